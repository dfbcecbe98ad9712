"""covopt.body_regions() and covopt.body_region_limits(): ISO/TS 15066's table from Python,
the same objects as ``covopt body-regions list --json``; the limits as the library computes
them (transient twice the quasi-static ones, clamped m_H infinite), and bad names and the
forbidden transient contacts as ValueError with the library's message."""

import json
import math
import os
import shutil
import subprocess

import pytest

import covopt

# ISO/TS 15066:2016 Table A.2/A.3: region -> (F_qs N, k N/mm, m_H kg, {area: p_qs N/cm²}).
# A transcription independent of the data file, for a few regions.
EXPECTED = {
    "chest": (140, 25, 40, {"sternum": 120, "pectoral-muscle": 170}),
    "face": (65, 75, 4.4, {"masticatory-muscle": 110}),
    "lower-legs": (130, 60, 75, {"middle-of-shin": 220, "calf-muscle": 210}),
}


def _cli():
    candidate = os.environ.get("COVOPT_CLI")
    if candidate:
        return candidate
    here = os.path.dirname(os.path.abspath(covopt.__file__))
    built = os.path.join(here, "..", "..", "cli", "covopt")
    return built if os.path.exists(built) else shutil.which("covopt")


def test_the_table_has_12_regions_and_29_areas_numbered_in_order():
    regions = covopt.body_regions()
    assert len(regions) == 12
    numbers = [area.number for region in regions for area in region.areas]
    assert numbers == list(range(1, 30))
    for region in regions:
        assert len(region.sources) >= 2
        assert region.default_area == min(region.areas, key=lambda a: a.quasi_static_pressure_Pa).name


def test_values_in_si_units():
    by_name = {region.name: region for region in covopt.body_regions()}
    for name, (force, k, mass, areas) in EXPECTED.items():
        region = by_name[name]
        assert region.quasi_static_force_N == force
        assert region.stiffness_N_per_m == k * 1e3
        assert region.effective_mass_kg == mass
        assert {a.name: a.quasi_static_pressure_Pa for a in region.areas} == {
            a: p * 1e4 for a, p in areas.items()}
    assert by_name["face"].transient_permitted is False
    assert by_name["face"].transient_force_N is None
    assert by_name["chest"].transient_force_N == 280


def test_the_same_objects_as_the_cli_json():
    cli = _cli()
    if cli is None:
        pytest.fail("no covopt binary: set COVOPT_CLI")
    out = subprocess.run([cli, "body-regions", "list", "--json"], check=True,
                         capture_output=True, text=True).stdout
    assert [region.to_dict() for region in covopt.body_regions()] == json.loads(out)


def test_limits_transient_is_twice_clamped():
    transient = covopt.body_region_limits("chest")
    assert transient.area == "sternum"
    assert transient.contact == "transient"
    assert transient.force_N == 280
    assert transient.pressure_Pa == 240e4
    assert transient.effective_mass_kg == 40
    assert transient.stiffness_N_per_m == 25e3
    assert transient.describe == ("ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M, transient "
                                  "(2× quasi-static), chest (sternum): 280 N, 240 N/cm²")
    clamped = covopt.body_region_limits("Chest", "pectoral_muscle", contact="clamped")
    assert clamped.area == "pectoral-muscle"
    assert clamped.force_N == 140
    assert clamped.pressure_Pa == 170e4
    assert math.isinf(clamped.effective_mass_kg)
    assert clamped.describe.startswith("ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M, quasi-static, chest")
    assert covopt.body_region_limits("chest", contact="quasi-static").contact == "clamped"


def test_transient_contact_with_the_face_is_refused_naming_a32():
    for region in ("face", "skull/forehead"):
        with pytest.raises(ValueError, match=r"ISO/TS 15066:2016 A\.3\.2 \(= ISO 10218-2:2025 Annex M\) does not permit transient"):
            covopt.body_region_limits(region)
        assert covopt.body_region_limits(region, contact="clamped").force_N > 0


def test_bad_names_raise_value_error_with_the_choices():
    with pytest.raises(ValueError, match=r"did you mean 'chest'\? \(regions: skull-forehead, face"):
        covopt.body_region_limits("chset")
    with pytest.raises(ValueError, match=r"\(areas of chest: sternum, pectoral-muscle\)"):
        covopt.body_region_limits("chest", "sternun")
    with pytest.raises(ValueError, match=r"contact: expected 'transient' or 'clamped' \(got 'soft'\)"):
        covopt.body_region_limits("chest", contact="soft")
