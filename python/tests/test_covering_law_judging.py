"""The judging calls and the covering's law (issue 35): keep_travel=True is --keep-travel, the
results name the law and its validity as the CLI's JSON does, a foam used up is reported at its
own speed and does not limit, and a fully compressed Hertz covering is limited by law-validity."""

import pytest

import covopt
from calls import call

VN600 = "vinyl-nitrile foam VN600"

CASES = [
    ({"material": VN600, "covering_thickness": "10mm", "robot_mass": 10.0},
     ["--material", VN600, "--covering-thickness", "10mm", "--robot-mass", "10kg"]),
    ({"material": VN600, "covering_thickness": "10mm", "robot_mass": 10.0, "keep_travel": True},
     ["--material", VN600, "--covering-thickness", "10mm", "--robot-mass", "10kg", "--keep-travel"]),
    ({"covering_modulus": "5.884MPa", "covering_poisson": 0.3, "covering_thickness": "20mm", "robot_mass": 1.0},
     ["--covering-modulus", "5.884MPa", "--covering-poisson", "0.3", "--covering-thickness", "20mm",
      "--robot-mass", "1kg"]),
]


@pytest.mark.parametrize("kwargs,flags", CASES)
def test_speed_limit_rows_carry_the_law_as_the_cli_does(cli_json, kwargs, flags):
    ours = call(covopt.speed_limit, **kwargs)
    theirs = cli_json("speed-limit", "--json", *flags)
    assert ours["rows"] == theirs["rows"]
    assert ours["criterion"] == theirs["criterion"]
    row = ours["rows"][0]
    assert row["covering_law"] in ("foam", "hertz")
    assert set(row["validity"]) == {"within", "note"}


def test_a_foam_used_up_is_reported_not_a_limit():
    scene = covopt.Scene(material=VN600, covering_thickness=0.01, robot_mass=10.0)
    judged = covopt.max_safe_speed(scene)
    kept = covopt.max_safe_speed(scene, keep_travel=True)
    assert judged.covering_law == "foam"
    assert judged.limited_by in ("laceration", "contusion", "fracture")
    assert judged.covering_used_up_m_per_s < judged.max_safe_speed_m_per_s
    assert kept.limited_by == "full-compression"
    assert kept.max_safe_speed_m_per_s <= judged.covering_used_up_m_per_s * (1 + 1e-12)
    # simulate between the two: used up, within its law, safe; unsafe only with keep_travel.
    v = 0.5 * (judged.covering_used_up_m_per_s + judged.max_safe_speed_m_per_s)
    at = covopt.simulate(scene.replace(speed=v)).to_dict()
    assert at["fully_compressed"] and at["validity"]["within"] and at["safe"]
    assert not covopt.simulate(scene.replace(speed=v), keep_travel=True).to_dict()["safe"]


def test_a_fully_compressed_hertz_covering_is_limited_by_law_validity():
    scene = covopt.Scene(covering_modulus="5.884MPa", covering_poisson=0.3, covering_thickness="20mm",
                         robot_mass=1.0)
    judged = covopt.max_safe_speed(scene)
    kept = covopt.max_safe_speed(scene, keep_travel=True)
    assert judged.limited_by == "law-validity"
    assert kept.limited_by == "full-compression"
    assert judged.max_safe_speed_m_per_s == pytest.approx(kept.max_safe_speed_m_per_s, rel=1e-12)
    paper = covopt.max_safe_speed(scene, allow_full_compression=True)
    assert paper.max_safe_speed_m_per_s > judged.max_safe_speed_m_per_s


def test_sweep_takes_keep_travel_with_a_body_region_only():
    scene = covopt.Scene(material=VN600, covering_thickness=0.01, robot_mass=8.0)
    speeds = ("speed", [0.5, 1.0, 2.0, 4.0])
    judged = covopt.sweep(speeds, scene=scene, body_region="chest")
    kept = covopt.sweep(speeds, scene=scene, body_region="chest", keep_travel=True)
    # The travel rule only removes admissible points (a foam used up is within its law).
    assert all(k <= j for k, j in zip(kept.to_dict()["admissible"], judged.to_dict()["admissible"]))
    assert sum(kept.to_dict()["admissible"]) < sum(judged.to_dict()["admissible"])
    with pytest.raises(ValueError, match="keep_travel applies with body_region"):
        covopt.sweep(speeds, scene=scene, keep_travel=True)
