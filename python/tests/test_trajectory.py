"""covopt.check_trajectory: the dict is the CLI's ``covopt robot --trajectory --json`` object
for the same inputs (scene keywords as the scene flags); a CSV file and the same trajectory
as a dict of arrays give the same answer; the trajectory sped up by its safe_speed_scale is
exactly at the limit (scale 1, safe), a hair faster is unsafe, half as fast has twice the
scale; every moving sample's verdict is covopt.simulate's at its speed and reflected mass; a
point at rest; bad input raises ValueError (or TypeError for a keyword the function does not
take) naming what is wrong.
"""

import math
import pathlib

import numpy as np
import pytest

import covopt
from conftest import without_provenance
from calls import call

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
FR3 = ROOT / "robot" / "models" / "franka_fr3.urdf"
PICK = ROOT / "robot" / "models" / "franka_fr3_pick.csv"
PLANAR = ROOT / "tests" / "robot" / "data" / "planar_2link.urdf"


def pick_arrays():
    """The shipped trajectory as (time_s, positions, velocities) arrays."""
    table = np.loadtxt(PICK, delimiter=",", comments="#", skiprows=4)
    return table[:, 0], table[:, 1:8], table[:, 8:15]


def write_trajectory(path, time_s, positions, velocities):
    rows = np.column_stack([time_s, positions, velocities])
    header = "time_s," + ",".join(f"q{i}" for i in range(1,
                                                         8)) + "," + ",".join(f"qd{i}" for i in range(1,
                                                                                                      8))
    path.write_text(header + "\n" + "\n".join(",".join(repr(float(x)) for x in row) for row in rows) + "\n")
    return path


@pytest.mark.parametrize("kwargs, flags", [
    ({}, []),
    ({"covering_thickness": 0.0}, ["--covering-thickness", "0"]),
    ({"material": "XPS Foamular 250", "allow_full_compression": True},
     ["--material", "XPS Foamular 250", "--allow-full-compression"]),
    ({"point": (0.0, 0.0, 0.1), "head_mass": "fixed", "laceration_limit": "2MPa"},
     ["--point", "0,0,0.1", "--head-mass", "fixed", "--laceration-limit", "2MPa"]),
])
def test_check_trajectory_returns_the_cli_json_object(cli_json, kwargs, flags):
    got = call(covopt.check_trajectory, str(FR3), "fr3_link8", str(PICK), **kwargs)
    expected = cli_json("robot", "--urdf", str(FR3), "--tip", "fr3_link8", "--trajectory", str(PICK),
                        "--json", *flags)
    # The same warnings, the assumed ν and the default covering included (the library's).
    assert got.pop("warnings") == expected.pop("warnings")
    assert got == expected
    assert got["sample_count"] == 101 and len(got["samples"]) == 101
    assert got["joint_names"] == [f"fr3_joint{i}" for i in range(1, 8)]


def test_a_file_and_a_dict_of_arrays_agree():
    time_s, positions, velocities = pick_arrays()
    from_file = covopt.check_trajectory(FR3, "fr3_link8", PICK).to_dict()
    from_dict = covopt.check_trajectory(FR3, "fr3_link8", {"time_s": time_s, "positions": positions,
                                                           "velocities": velocities}).to_dict()
    assert without_provenance(from_file) == without_provenance(from_dict)  # the dict is no input file
    from_text = covopt.check_trajectory(None, "fr3_link8", PICK, urdf_text=FR3.read_text()).to_dict()
    assert without_provenance(from_text) == without_provenance(from_file)  # the text is no input file


def test_the_safe_speed_scale_is_exact(tmp_path):
    time_s, positions, velocities = pick_arrays()
    check = covopt.check_trajectory(FR3, "fr3_link8", PICK).to_dict()
    k = check["safe_speed_scale"]
    assert check["status"] == "safe" and k > 1.0
    worst = check["worst_sample"]
    assert worst == {"index": worst["index"], **check["samples"][worst["index"]]}
    assert all(s["speed_scale"] >= k for s in check["samples"] if s["moving"])

    # Sped up k times the move exceeds FR3's joint velocity limits: the covering's limit is
    # what is checked here, so the URDF's limits are set aside.
    at_limit = covopt.check_trajectory(FR3, "fr3_link8", write_trajectory(tmp_path / "at.csv", time_s,
                                                                          positions, velocities * k), ignore_joint_limits=True)
    assert at_limit.safe_speed_scale == pytest.approx(1.0, abs=1e-9)
    assert at_limit.status == "safe"
    beyond = covopt.check_trajectory(FR3, "fr3_link8", {"time_s": time_s, "positions": positions,
                           "velocities": velocities * k * (1 + 1e-6)}, ignore_joint_limits=True)
    assert beyond.status == "unsafe" and beyond.unsafe_sample_count >= 1
    half = covopt.check_trajectory(FR3, "fr3_link8", {"time_s": time_s, "positions": positions,
                                                      "velocities": velocities * 0.5})
    assert half.safe_speed_scale == pytest.approx(2 * k, rel=1e-12)


def test_every_verdict_is_simulate_at_the_sample_speed_and_mass():
    check = covopt.check_trajectory(FR3, "fr3_link8", PICK,
                                    scene=covopt.Scene(covering_thickness="10mm")).to_dict()
    for sample in check["samples"][::10]:
        if not sample["moving"]:
            assert sample["laceration_ratio"] == 0.0 and sample["speed_scale"] is None
            continue
        impact = covopt.simulate(covopt.Scene(robot_mass=sample["reflected_mass_kg"],
                                              speed=sample["speed_m_per_s"], covering_thickness=0.01))
        assert sample["laceration_ratio"] == pytest.approx(impact.laceration.ratio, rel=1e-12)
        assert sample["contusion_ratio"] == pytest.approx(impact.contusion.ratio, rel=1e-12)
        limit = covopt.max_safe_speed(covopt.Scene(robot_mass=sample["reflected_mass_kg"],
                                                   covering_thickness=0.01))
        assert sample["max_safe_speed_m_per_s"] == limit.max_safe_speed_m_per_s
        assert sample["speed_scale"] == pytest.approx(
            limit.max_safe_speed_m_per_s / sample["speed_m_per_s"], rel=1e-15)


def test_a_point_at_rest_has_nothing_to_judge():
    still = {"time_s": [0.0, 0.5], "positions": [[0.3, 1.2], [0.3, 1.2]], "velocities": [[0, 0], [0, 0]]}
    check = covopt.check_trajectory(PLANAR, "tool", still)
    assert check.status == "at-rest"
    assert check.safe_speed_scale is None and check.worst_sample is None
    assert all(not s.moving for s in check.samples)


@pytest.mark.parametrize("kwargs, words", [
    ({"trajectory": "no-such-file.csv"}, "no such trajectory file"),
    ({"trajectory": {"time_s": [0.0, -1.0], "positions": [[0.0] * 7] * 2,
                     "velocities": [[0.0] * 7] * 2}},
     "time goes backwards"),
    ({"trajectory": {"time_s": [0.0], "positions": [[0.0] * 6], "velocities": [[0.0] * 7]}},
     "positions"),
    ({"trajectory": {"time_s": [0.0], "positions": [[0.0] * 7], "velocities": [[math.nan] + [0.0] * 6]}},
     "finite"),
    ({"trajectory": {"time_s": [0.0], "positions": [[0.0, -0.78, 0, -2.35, 0, 1.57, 0.78]],
                     "velocities": [[1000.0] + [0.0] * 6]}, "ignore_joint_limits": True}, "in [0, 100] m/s"),
    ({"trajectory": {"time_s": [0.0], "positions": [[0.0, -0.78, 0, -2.35, 0, 1.57, 0.78]],
                     "velocities": [[1000.0] + [0.0] * 6]}},
     "1000 rad/s is not allowed (outside the URDF's velocity limit [-2.62, 2.62] rad/s of joint 'fr3_joint1'"),
    ({"trajectory": {"time_s": [0.0], "positions": [[0.0] * 7], "velocities": [[0.0] * 7]}},
     "outside the URDF's limits [-3.0421, -0.1518] rad of joint 'fr3_joint4'"),
    ({"covering_thickness": -0.001}, "covering_thickness"),
    ({"material": "no such foam"}, "no such foam"),
    ({"safety_factor": 0.5}, "safety_factor"),
    ({"tip": "no_such_link"}, "no_such_link"),
])
def test_bad_input_raises_value_error(kwargs, words):
    arguments = {"urdf": FR3, "tip": "fr3_link8", "trajectory": PICK, **kwargs}
    with pytest.raises(ValueError) as error:
        call(covopt.check_trajectory, **arguments)
    assert words in str(error.value)


def test_the_robot_mass_and_speed_are_not_keywords():
    for keyword in ("robot_mass", "speed"):
        with pytest.raises(ValueError, match=f"drop {keyword} from the scene"):
            covopt.check_trajectory(FR3, "fr3_link8", PICK, scene=covopt.Scene(**{keyword: 1.0}))


def test_a_trajectory_without_a_header_keeps_its_first_row(tmp_path):
    rows = ("0,0,-0.78,0,-2.35,0,1.57,0.78,2.5,0,0,0,0,0,0\n"
            "0.1,0,-0.78,0,-2.35,0,1.57,0.78,0.1,0,0,0,0,0,0\n")
    headerless = tmp_path / "headerless.csv"
    headerless.write_text(rows)
    with_header = tmp_path / "header.csv"
    with_header.write_text("t,q1,q2,q3,q4,q5,q6,q7,qd1,qd2,qd3,qd4,qd5,qd6,qd7\n" + rows)
    a = covopt.check_trajectory(FR3, "fr3_link8", headerless)
    b = covopt.check_trajectory(FR3, "fr3_link8", with_header)
    assert a.sample_count == 2 and a.worst_sample.index == 0
    assert a.safe_speed_scale == b.safe_speed_scale
    assert any("no header line" in w for w in a.warnings)
    assert not any("no header line" in w for w in b.warnings)


def test_check_trajectory_ignore_joint_limits_warns():
    beyond = {"time_s": [0.0], "positions": [[0.0, -0.78, 0, 1.57, 0, 1.57, 0.78]],
              "velocities": [[0.5] + [0.0] * 6]}
    check = covopt.check_trajectory(FR3, "fr3_link8", beyond, ignore_joint_limits=True)
    assert any("were not checked" in w for w in check.warnings)
