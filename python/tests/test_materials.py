"""covopt.materials() and covopt.material(name) against `covopt materials list|show --json`,
and the unknown-name message."""

import pytest

import covopt


def test_materials_is_the_cli_list(cli_json):
    assert covopt.materials() == cli_json("materials", "list", "--json")


def test_material_is_the_cli_show(cli_json):
    name = covopt.materials()[0]["name"]
    assert covopt.material(name) == cli_json("materials", "show", name, "--json")


def test_material_ignores_case():
    first = covopt.materials()[0]
    assert covopt.material(first["name"].upper()) == first


def test_every_material_has_the_documented_keys_in_si():
    keys = ["name", "family", "youngs_modulus_Pa", "poisson_ratio", "density_kg_per_m3",
            "modulus_basis", "source", "note", "defined_at"]
    for m in covopt.materials():
        assert list(m) == keys
        assert 1e4 <= m["youngs_modulus_Pa"] <= 1e12
        assert m["poisson_ratio"] is None or -1 < m["poisson_ratio"] <= 0.5


def test_an_unknown_name_is_a_value_error_with_the_clis_suggestions(cli):
    with pytest.raises(ValueError) as error:
        covopt.material("polystyrene")
    message = str(error.value)
    assert message.startswith("no material 'polystyrene' in the catalog; did you mean ")
    code, out, err = cli("materials", "show", "polystyrene")
    assert code == 2 and out == ""
    assert message in err


def test_a_material_sets_the_covering_of_a_simulation():
    m = covopt.material("polystyrene foam 48.3")
    covering = covopt.simulate(material=m["name"])["scene"]["covering"]
    assert covering["youngs_modulus_Pa"] == m["youngs_modulus_Pa"]
    assert covering["material"] == m["name"]
