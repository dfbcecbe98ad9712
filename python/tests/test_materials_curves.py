"""Compressive curves in Python: covopt.Material's curve attributes against the CLI's JSON,
covopt.Catalog with users' files (the same keys; errors as ValueError with file:line:column),
Catalog.find(stress_at_25=...) against `covopt materials find --stress-at-25`, and bad input."""

import pytest

import covopt

VN600 = "vinyl-nitrile foam VN600"

USER_CATALOG = """[[material]]
name = "my sponge"
family = "foam"
youngs_modulus_Pa = "200 kPa"
modulus_basis = "compressive"
source = "a datasheet"
compressive_curve = [[0.1, "30 kPa"], ["25%", "45 kPa"], [0.5, "120 kPa"]]
curve_source = "read off the datasheet"
curve_rate = "20 1/s"
recovers = false
rate_factor = [1, 2.5]
"""


def test_a_material_exposes_its_curve_as_the_cli_prints_it(cli_json):
    m = covopt.material(VN600)
    shown = cli_json("materials", "show", VN600, "--json")
    assert m.compressive_curve == [tuple(p) for p in shown["compressive_curve"]]
    assert len(m.compressive_curve) == 199
    assert all(isinstance(p, tuple) and len(p) == 2 for p in m.compressive_curve)
    assert m.curve_source == shown["curve_source"] and "10.18126/6h74-leb4" in m.curve_source
    assert m.curve_rate == "quasi-static"
    assert m.recovers is True
    assert m.rate_factor == (1.0, 4.0)
    assert m.stress_at_25_Pa == pytest.approx(57273.05, rel=1e-5)
    # W at the last point: an independent trapezoid sum over the points from the origin.
    points = [(0.0, 0.0)] + m.compressive_curve
    w = sum(0.5 * (s0 + s1) * (e1 - e0) for (e0, s0), (e1, s1) in zip(points, points[1:]))
    assert m.curve_energy_density_J_per_m3 == pytest.approx(w, rel=1e-12)


def test_a_material_without_a_curve_has_none():
    m = covopt.material("polystyrene foam 27.6")
    assert m.compressive_curve is None
    assert m.rate_factor is None and m.recovers is None and m.curve_source is None
    assert m.stress_at_25_Pa is None


def test_a_band_carries_its_range_and_shape():
    m = covopt.material("neoprene sponge D1056 2C3")
    low, high = m.stress_at_25_band_Pa
    assert low <= m.stress_at_25_Pa <= high
    assert m.curve_shape.startswith("VN600 (NIST), scaled")


def test_catalog_loads_users_files_with_the_same_keys(tmp_path):
    path = tmp_path / "mine.toml"
    path.write_text(USER_CATALOG)
    catalog = covopt.Catalog(path)
    assert len(catalog) == len(covopt.materials()) + 1
    mine = catalog.material("MY SPONGE")
    assert mine.compressive_curve == [(0.1, 30e3), (0.25, 45e3), (0.5, 120e3)]
    assert mine.curve_rate == "20 1/s" and mine.curve_rate_per_s == 20.0
    assert mine.recovers is False
    assert mine.rate_factor == (1.0, 2.5)
    only = covopt.Catalog(path, no_builtin=True)
    assert [m.name for m in only.materials()] == ["my sponge"]


def test_catalog_find_stress_at_25_is_the_clis(cli_json, tmp_path):
    catalog = covopt.Catalog()
    found = catalog.find(stress_at_25=(30e3, 80e3))
    assert [m.to_dict() for m in found] == cli_json("materials", "find", "--stress-at-25", "30kPa..80kPa", "--json")
    assert all(30e3 <= m.stress_at_25_Pa <= 80e3 for m in found)
    without = [m for m in covopt.materials() if m.stress_at_25_Pa is None]
    assert found.excluded_for_want_of_curve == len(without)
    # Open ends and has_curve.
    assert len(catalog.find(stress_at_25=(None, 80e3))) >= len(found)
    curves = catalog.find(has_curve=True)
    assert all(m.compressive_curve for m in curves)
    assert len(curves) >= 12
    assert [m.name for m in catalog.find(has_curve=True, family="padding")] == [
        m.name for m in curves if m.family == "padding"]


@pytest.mark.parametrize("bad", [(80e3, 30e3), (-1, 10), ("30kPa", "80kPa"), (1, 2, 3), "30kPa..80kPa",
                                 (float("nan"), 1), (True, 2)])
def test_catalog_find_refuses_a_bad_range(bad):
    with pytest.raises(ValueError, match=r"stress_at_25 must be \(low_Pa, high_Pa\)"):
        covopt.Catalog().find(stress_at_25=bad)


def test_a_bad_user_catalog_is_a_value_error_at_file_line_column(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(USER_CATALOG.replace('["25%", "45 kPa"]', '["25%", "20 kPa"]'))
    with pytest.raises(ValueError) as error:
        covopt.Catalog(path)
    assert str(error.value).startswith(f"catalog: {path}:7:")
    assert "compressive_curve point 2: stress 20000 Pa falls below the previous point's 30000 Pa" in str(error.value)
    shape_less = tmp_path / "band.toml"
    shape_less.write_text(USER_CATALOG + 'stress_at_25_band = ["40 kPa", "50 kPa"]\n')
    with pytest.raises(ValueError, match="curve_shape is required with a stress_at_25_band"):
        covopt.Catalog(shape_less)
    with pytest.raises(TypeError):
        covopt.Catalog(42)
