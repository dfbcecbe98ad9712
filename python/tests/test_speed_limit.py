"""covopt.max_safe_speed, covopt.max_safe_mass and covopt.speed_limit: the same dict as
`covopt speed-limit --json` (both come from covopt::report::SpeedLimitJson), limits that are
what covopt.simulate finds safe just below and unsafe just above, and bad input."""

import math
import re

import pytest

import covopt
from conftest import same_provenance
from calls import call

CASES = [
    ({}, []),
    ({"values": [0.5, 5.0, math.inf]}, ["--robot-mass", "0.5kg,5kg,fixed"]),
    ({"robot_mass": 20.0, "covering_thickness": "20mm", "material": "polystyrene foam 27.6",
      "safety_factor": 1.5}, ["--robot-mass", "20kg", "--covering-thickness", "20mm",
                              "--material", "polystyrene foam 27.6", "--safety-factor", "1.5"]),
    ({"covering_thickness": 0.01, "covering_modulus": 2e6, "allow_full_compression": True},
     ["--covering-thickness", "10mm", "--covering-modulus", "2MPa", "--allow-full-compression"]),
    ({"solve_for": "mass", "values": [0.5, 2.0, 3.0]},
     ["--solve-for", "mass", "--speed", "0.5m/s,2m/s,3m/s"]),
    ({"materials": ["polystyrene foam 27.6", "polystyrene foam 48.3"], "covering_thickness": "25mm"},
     ["--material", "polystyrene foam 27.6", "--material", "polystyrene foam 48.3",
      "--covering-thickness", "25mm"]),
    ({"materials": ["XPS Foamular 250", "EPS geofoam EPS39"], "covering_thickness": "16mm"},
     ["--material", "XPS Foamular 250", "--material", "EPS geofoam EPS39", "--covering-thickness",
      "16mm"]),
    ({"material": "XPS Foamular 250", "covering_thickness": "16mm", "allow_crushing": True},
     ["--material", "XPS Foamular 250", "--covering-thickness", "16mm", "--allow-crushing"]),
]


def test_a_crushing_material_limits_the_speed_where_its_strength_is_reached():
    crush = covopt.max_safe_speed(covopt.Scene(material="XPS Foamular 250", covering_thickness=0.016))
    assert crush.limited_by == "crush"
    liner = covopt.max_safe_speed(covopt.Scene(material="XPS Foamular 250", covering_thickness=0.016),
                                  allow_crushing=True)
    assert liner.limited_by != "crush"
    assert liner.max_safe_speed_m_per_s > 10 * crush.max_safe_speed_m_per_s
    # No covering given: the assumed default is said, as the CLI says it.
    assumed = covopt.max_safe_speed()
    assert assumed.warnings[0].startswith("no covering given")


@pytest.mark.parametrize("kwargs,flags", CASES)
def test_speed_limit_returns_the_cli_json_object(cli_json, kwargs, flags):
    ours = call(covopt.speed_limit, **kwargs)
    theirs = cli_json("speed-limit", "--json", *flags)
    assert list(ours) == list(theirs)
    assert {k: v for k, v in ours.items() if k not in ("warnings", "input_sources", "provenance")} == \
        {k: v for k, v in theirs.items() if k not in ("warnings", "input_sources", "provenance")}
    assert same_provenance(ours["provenance"], theirs["provenance"])
    # The same warnings (a safety factor, an assumed ν: the library's), the input named each its way.
    assert unsourced(ours["warnings"]) == unsourced(theirs["warnings"])


def unsourced(warnings):
    """The warnings without where an input came from ("(from --safety-factor '2')" in the CLI,
    "(from safety_factor=2)" in Python)."""
    return [re.sub(r" \(from [^)]*\)", "", w) for w in warnings]


def safe(result):
    """simulate's verdict under the default criterion: safe and, with a covering, not fully
    compressed (for the bare robot the ratios alone count)."""
    covered = result["scene"]["covering"]["thickness_m"] > 0
    return result["safe"] and not (covered and result["fully_compressed"])


@pytest.mark.parametrize("scene", [{}, {"robot_mass": 3.0, "covering_thickness": 0},
                                   {"covering_thickness": "8mm", "covering_modulus": "2MPa"},
                                   {"head_mass": "fixed", "robot_radius": "flat"}])
def test_the_max_safe_speed_is_the_edge_of_what_simulate_calls_safe(scene):
    scene = covopt.Scene(**scene)
    limit = covopt.max_safe_speed(scene)
    assert limit.status == "limited"
    v = limit.max_safe_speed_m_per_s
    assert safe(covopt.simulate(scene.replace(speed=v * (1 - 1e-9))).to_dict())
    assert not safe(covopt.simulate(scene.replace(speed=v * (1 + 1e-6))).to_dict())
    at = covopt.simulate(scene.replace(speed=v))
    assert at.laceration.ratio == limit.laceration_ratio
    assert at.contusion.ratio == limit.contusion_ratio


def test_the_max_safe_mass_and_speed_describe_one_boundary():
    v = covopt.max_safe_speed(covopt.Scene(robot_mass=7.0)).max_safe_speed_m_per_s
    m = covopt.max_safe_mass(covopt.Scene(speed=v))
    assert m.max_safe_mass_kg == pytest.approx(7.0, rel=1e-9)
    assert m.limited_by == "contusion"
    assert covopt.max_safe_mass(covopt.Scene(speed=0.3)).max_safe_mass_kg == "fixed"
    assert "fixed robot" in covopt.max_safe_mass(covopt.Scene(speed=0.3)).message


def test_edges_are_answers():
    top = covopt.max_safe_speed(covopt.Scene(robot_mass="1g", covering_thickness=0,
                                             laceration_limit="1GPa", contusion_limit="1000J/cm2"))
    assert top.max_safe_speed_m_per_s == 100.0
    assert top.limited_by == "none"
    none = covopt.max_safe_speed(covopt.Scene(laceration_limit="1kPa", safety_factor=100))
    assert none.max_safe_speed_m_per_s is None
    assert none.status == "no-safe-value"


@pytest.mark.parametrize("function,kwargs,words", [
    (covopt.max_safe_speed, {"robot_mass": -1.0}, "robot_mass"),
    (covopt.max_safe_speed, {"safety_factor": 0.5}, "safety_factor"),
    (covopt.max_safe_mass, {"speed": "2kg"}, "speed"),
    (covopt.speed_limit, {"speed": 2.0}, "speed"),
    (covopt.speed_limit, {"solve_for": "weight"}, "solve_for"),
    (covopt.speed_limit, {"values": [1.0, "x"]}, "values"),
    (covopt.speed_limit, {"values": []}, "values"),
    (covopt.speed_limit, {"materials": "no such foam"}, "no such foam"),
])
def test_bad_input_raises_value_error_naming_the_keyword(function, kwargs, words):
    with pytest.raises(ValueError, match=words):
        call(function, **kwargs)
