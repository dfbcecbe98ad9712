"""docs/validation.md §6, the foam law against measured data: the numbers that section states,
computed by docs/validation/foam_validation.py (the covopt CLI and its own numpy references)
and held here, so that the report cannot drift from the code without a test failing."""

import importlib.util
import math
import os
import pathlib

import pytest

from conftest import covopt_binary

SCRIPT = pathlib.Path(__file__).resolve().parents[2] / "docs" / "validation" / "foam_validation.py"


@pytest.fixture(scope="module")
def fv():
    binary = covopt_binary()
    if not binary:
        pytest.fail("no covopt binary: set COVOPT_CLI or build the covopt target")
    os.environ.setdefault("COVOPT_CLI", binary)
    spec = importlib.util.spec_from_file_location("foam_validation", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_vn600_energy_integrals_from_the_record_and_from_published_points(fv):
    w = fv.vn600_integrals()
    assert w["points"] == 199
    # The 199-point record (trapezoid rule, exact for the piecewise-linear curve the law uses).
    assert w["record_W25"] == pytest.approx(8408.6, abs=0.1)
    assert w["record_W49"] == pytest.approx(34475.1, abs=0.1)
    # The catalog's own W at the curve's end (covopt's exact integral) is the same number.
    assert w["catalog_W_end"] == pytest.approx(w["record_W_end"], rel=1e-9)
    # The 11 rounded points read from the published curve, and the 6 of a first estimate:
    # coarse points overestimate the convex curve's integral (6 points: +1.7 % at 25 %).
    assert w["eleven_W25"] == pytest.approx(8345.0, abs=0.1)
    assert w["eleven_W49"] == pytest.approx(34551.5, abs=0.1)
    assert w["six_W25"] == pytest.approx(8555.0, abs=0.1)
    assert w["six_W49"] == pytest.approx(35540.0, abs=0.1)
    assert abs(w["eleven_W49"] / w["record_W49"] - 1) < 0.003
    assert w["six_W25"] > w["record_W25"] and w["six_W49"] > w["record_W49"]


@pytest.mark.parametrize("region", ["abdomen", "chest", "hands-fingers"])
def test_body_region_foam_force_equals_an_independent_energy_balance(fv, region):
    # covopt's exact path against the script's own tabulated F = 2 pi R_c h W, U = 2 pi R_c h^2 V
    # and bisection on U(F) + F^2/(2k) = E, within the curve and used up.
    for force in (100.0, 300.0):
        for mm in (5, 20, 40):
            reduction, row = fv.reduction(region, force, mm)
            independent = fv.independent_foam_force(region, force, mm)
            assert row["covering_law"] == "foam"
            assert row["peak_force_N"] == pytest.approx(independent, rel=1e-6)
            assert row["peak_force_N"] <= force * (1 + 1e-12)  # never worse than bare


def test_svarny_reduction_table_and_its_trends(fv):
    # VN600 on R_r 40 mm, 10 kg, transient, at the speed where the bare robot gives 200 N.
    expected = {("abdomen", 20): 0.133, ("chest", 20): 0.283, ("hands-fingers", 20): 0.543,
                ("hands-fingers", 10): 0.414, ("hands-fingers", 40): 0.579, ("chest", 40): 0.340}
    for (region, mm), value in expected.items():
        assert fv.reduction(region, 200.0, mm)[0] == pytest.approx(value, abs=5e-4)
    # The cut grows with the spring's stiffness and with thickness, and falls with the speed.
    assert fv.reduction("hands-fingers", 100.0, 20)[0] > fv.reduction("hands-fingers", 200.0, 20)[0] > \
        fv.reduction("hands-fingers", 300.0, 20)[0]
    # At an impact rate the curve is stiffer (VN600's rate factor [1, 4]): the cut shrinks.
    assert fv.independent_foam_force("hands-fingers", 200.0, 20, 4.0) == pytest.approx(200.0 * (1 - 0.374), abs=0.1)
    # A thin layer used up gives little: 5 mm at 300 N on the hand.
    reduction, row = fv.reduction("hands-fingers", 300.0, 5)
    assert row["fully_compressed"] and reduction < 0.05


def test_device_with_a_shore_a_pad_reads_less_than_its_bare_spring(fv):
    for spring in (10e3, 25e3, 75e3):
        foam_only = fv.device_reading(spring, 200.0, 0, 0, 20)
        previous = 0.0
        for shore in (10, 30, 70):
            bare = fv.device_reading(spring, 200.0, shore, 1, 0)
            covered = fv.device_reading(spring, 200.0, shore, 1, 20)
            # The pad is compliance in series: below the spring alone, rising with hardness.
            assert previous < bare < 200.0
            previous = bare
            # In series, the covered reading is below both the pad-only and the foam-only one.
            assert covered < min(bare, foam_only)
    # Hand spring with the red A70 pad: bare 164.9 N, with 20 mm VN600 85.7 N (-48 %).
    assert fv.device_reading(75e3, 200.0, 70, 1, 0) == pytest.approx(164.9, abs=0.05)
    assert fv.device_reading(75e3, 200.0, 70, 1, 20) == pytest.approx(85.7, abs=0.05)


def test_device_pad_as_covopt_hertz_covering_and_its_validity(fv):
    # The device's pad seen from the robot: a Hertz layer of E(ShA), nu 0.49 with R_c = 40 mm
    # (robot radius 40 mm - b, thickness b). covopt's force equals the script's series balance,
    # and the solid-elastomer limits of the Hertz law (strain <= 0.20, a_c <= b_c) say which
    # pads the law describes at 200 N on the hand's 75 N/mm.
    energy = 200.0 ** 2 / (2 * 75e3)
    speed = math.sqrt(2 * energy / fv.reduced_mass("hands-fingers"))
    for shore, within in ((70, True), (10, False)):
        modulus = fv.shore_a_modulus(shore)
        row = fv.run_json("simulate", "--json", "--body-region", "hands-fingers", "--robot-mass", "10kg",
                          "--robot-radius", "20mm", "--speed", f"{speed}m/s", "--covering-thickness", "20mm",
                          "--covering-modulus", f"{modulus}Pa", "--covering-poisson", "0.49")["regions"][0]
        independent = fv.series_force(energy, 75e3, [lambda f: fv.hertz_pad_energy(f, modulus, 0.49, 0.040)])
        assert row["peak_force_N"] == pytest.approx(independent, rel=1e-9)
        assert row["validity"]["within"] is within
        if not within:
            assert "solid elastomer (ν 0.49) under the Hertz law: peak strain" in row["validity"]["note"]
