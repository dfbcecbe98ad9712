"""covopt.materials() and covopt.material(name) against `covopt materials list|show --json`,
the unknown-name message, and the compressive-strength keys."""

import pytest

import covopt
from conftest import without_provenance


def test_materials_is_the_cli_list(cli_json):
    assert [m.to_dict() for m in covopt.materials()] == cli_json("materials", "list", "--json")


def test_material_is_the_cli_show(cli_json):
    name = covopt.materials()[0].name
    assert covopt.material(name).to_dict() == cli_json("materials", "show", name, "--json")


def test_material_ignores_case():
    first = covopt.materials()[0]
    assert without_provenance(covopt.material(first.name.upper())) == first


def test_every_material_has_the_documented_keys_in_si():
    keys = ["name", "family", "youngs_modulus_Pa", "poisson_ratio", "density_kg_per_m3",
            "modulus_basis", "source", "note", "crush_behaviour", "compressive_strength_Pa",
            "strength_method", "strength_source", "defined_at", "compressive_curve", "stress_at_25_Pa",
            "curve_energy_density_J_per_m3", "curve_source", "curve_rate", "curve_rate_per_s", "recovers",
            "rate_factor", "stress_at_25_band_Pa", "curve_shape"]
    for m in covopt.materials():
        assert list(m.to_dict()) == keys
        assert 1e3 <= m.youngs_modulus_Pa <= 1e12
        assert m.poisson_ratio is None or -1 < m.poisson_ratio <= 0.5


def test_an_unknown_name_is_a_value_error_with_the_clis_suggestions(cli):
    with pytest.raises(ValueError) as error:
        covopt.material("polystyrene").to_dict()
    message = str(error.value)
    assert message.startswith("no material 'polystyrene' in the catalog; did you mean ")
    code, out, err = cli("materials", "show", "polystyrene")
    assert code == 2 and out == ""
    assert message in err


def test_a_material_sets_the_covering_of_a_simulation():
    m = covopt.material("polystyrene foam 48.3")
    covering = covopt.simulate(covopt.Scene(material=m.name)).scene.covering
    assert covering.youngs_modulus_Pa == m.youngs_modulus_Pa
    assert covering.material == m.name


def test_every_material_states_its_crush_behaviour():
    materials = covopt.materials()
    assert len(materials) >= 45
    for m in materials:
        assert m.crush_behaviour in ("crushes", "does-not-crush", "unknown")
        if m.crush_behaviour == "crushes":
            assert m.compressive_strength_Pa > 0
            assert m.strength_method and m.strength_source
        else:
            assert m.compressive_strength_Pa is None
        if m.crush_behaviour == "does-not-crush":
            assert m.strength_method and m.strength_source
        if m.crush_behaviour == "unknown":
            assert m.strength_method is None and m.strength_source is None


def test_the_strength_agrees_with_the_cli(cli_json):
    m = covopt.material("XPS Foamular 250")
    shown = cli_json("materials", "show", "XPS Foamular 250", "--json")
    assert m.compressive_strength_Pa == shown["compressive_strength_Pa"]
    assert m.compressive_strength_Pa == pytest.approx(25 * 6894.757)
    assert m.strength_method == shown["strength_method"]
    assert covopt.material("silicone Sylgard 184").crush_behaviour == "does-not-crush"
