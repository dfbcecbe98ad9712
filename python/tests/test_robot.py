"""covopt.reflected_mass and covopt.contact_motion: the dicts are the CLI's ``covopt robot
--json`` object for the same inputs; a file and urdf_text= give the same answer; the planar
test arm's closed-form mass; the stretched arm's "fixed" direction; a trajectory from a CSV
file equals the same trajectory as a dict and gives |J q̇| of the closed form; bad input
raises ValueError naming what is wrong.
"""

import math
import os
import pathlib

import numpy as np
import pytest

import covopt
from conftest import without_provenance

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
PLANAR = ROOT / "tests" / "robot" / "data" / "planar_2link.urdf"  # l1 = 1, l2 = 0.8 m
FR3 = ROOT / "robot" / "models" / "franka_fr3.urdf"
FR3_READY = [0.0, -math.pi / 4, 0.0, -3 * math.pi / 4, 0.0, math.pi / 2, math.pi / 4]


@pytest.mark.parametrize("direction, flags", [((1.0, 0.0, 0.0), ["--direction", "1,0,0"]),
                                              (None, [])])
def test_reflected_mass_returns_the_cli_json_object(cli_json, direction, flags):
    got = covopt.reflected_mass(str(FR3), "fr3_link8", FR3_READY, point=(0.0, 0.0, 0.05),
                                direction=direction).to_dict()
    joints = ",".join(repr(q) for q in FR3_READY)
    expected = cli_json("robot", "--urdf", str(FR3), "--tip", "fr3_link8", f"--joints={joints}",
                        "--point", "0,0,0.05", "--json", *flags)
    assert got == expected
    if direction is None:
        assert got["reflected_mass_kg"] is None and got["direction"] is None


def test_a_file_and_urdf_text_agree_and_paths_may_be_pathlike():
    from_file = covopt.reflected_mass(PLANAR, "tool", [0.3, 1.2], direction=(1, 2, 0)).to_dict()
    from_text = covopt.reflected_mass(None, "tool", [0.3, 1.2], direction=(1, 2, 0),
                                      urdf_text=PLANAR.read_text()).to_dict()
    assert without_provenance(from_file) == without_provenance(from_text)  # the text is no input file


def test_the_planar_arm_has_its_closed_form_mass_and_a_fixed_stretched_direction():
    q1, q2 = 0.3, 1.2
    c2 = math.cos(q2)
    m = np.array([[0.1 + 0.05 + 2 * 0.25 + 1.5 * (1 + 0.16 + 2 * 0.4 * c2),
                   0.05 + 1.5 * (0.16 + 0.4 * c2)],
                  [0.05 + 1.5 * (0.16 + 0.4 * c2), 0.05 + 1.5 * 0.16]])
    s1, c1, s12, c12 = math.sin(q1), math.cos(q1), math.sin(q1 + q2), math.cos(q1 + q2)
    jac = np.array([[-s1 - 0.8 * s12, -0.8 * s12], [c1 + 0.8 * c12, 0.8 * c12]])
    u = np.array([0.6, 0.8])
    expected = 1.0 / (u @ jac @ np.linalg.solve(m, jac.T) @ u)
    got = covopt.reflected_mass(PLANAR, "tool", [q1, q2], direction=(0.6, 0.8, 0.0))
    assert got.reflected_mass_kg == pytest.approx(expected, rel=1e-12)
    assert got.max_reflected_mass_kg == "fixed"  # out of the plane
    stretched = covopt.reflected_mass(PLANAR, "tool", np.array([0.5, 0.0]), direction=(math.cos(0.5),
                                                                                       math.sin(0.5), 0.0))
    assert stretched.reflected_mass_kg == "fixed"
    assert any("infinite (fixed)" in w for w in stretched.warnings)


def test_contact_motion_from_a_csv_file_equals_the_dict_and_the_closed_form(tmp_path):
    rows = [(0.0, 0.3, 1.2, 0.5, -0.8), (0.1, 0.35, 1.1, 0.0, 0.0), (0.2, 0.4, 0.0, 1.0, 0.0)]
    csv = tmp_path / "trajectory.csv"
    csv.write_text("time_s,q1,q2,qd1,qd2\n" + "".join(",".join(map(repr, r)) + "\n" for r in rows))
    from_file = covopt.contact_motion(PLANAR, "tool", csv).to_dict()
    from_dict = covopt.contact_motion(PLANAR, "tool", {
        "time_s": [r[0] for r in rows],
        "positions": np.array([r[1:3] for r in rows]),
        "velocities": np.array([r[3:5] for r in rows])}).to_dict()
    assert without_provenance(from_file) == without_provenance(from_dict)  # the dict is no input file
    samples = from_file["samples"]
    assert [s["time_s"] for s in samples] == [0.0, 0.1, 0.2]
    assert samples[1]["moving"] is False and samples[1]["direction"] is None
    # Stretched arm turning at 1 rad/s about the shoulder: the tip moves at 1.8 m/s.
    assert samples[2]["speed_m_per_s"] == pytest.approx(1.8, rel=1e-12)
    along = covopt.reflected_mass(PLANAR, "tool", [0.3, 1.2], direction=samples[0]["direction"])
    assert samples[0]["reflected_mass_kg"] == pytest.approx(along.reflected_mass_kg, rel=1e-12)


@pytest.mark.parametrize("kwargs, words", [
    (dict(urdf="/nonexistent.urdf", tip="tool", joints=[0, 0]), "no such URDF file"),
    (dict(urdf=None, tip="tool", joints=[0, 0]), "exactly one of them"),
    (dict(urdf=None, tip="a", joints=[0], urdf_text="<robot"), "urdf_text: malformed URDF"),
    (dict(urdf=PLANAR, tip="hand", joints=[0, 0]), "tip link 'hand' is not in the URDF"),
    # A name with a line break or a NUL is echoed escaped: the message stays one line, whole.
    (dict(urdf=PLANAR, tip="ha\nnd\0x", joints=[0, 0]), "tip link 'ha\\nnd\\0x' is not in the URDF"),
    (dict(urdf=PLANAR, tip="link1", joints=[0], base="link2"), "not an ancestor"),
    (dict(urdf=PLANAR, tip="tool", joints=[0, 0, 0]), "3 values given"),
    (dict(urdf=PLANAR, tip="tool", joints=[0, math.nan]), "joints[1]: must be a finite number"),
    (dict(urdf=PLANAR, tip="tool", joints=[0, "30deg"]), "joints[1]: expected a number"),
    (dict(urdf=PLANAR, tip="tool", joints=[0, 0], direction=(0, 0, 0)), "non-zero vector"),
    (dict(urdf=PLANAR, tip="tool", joints=[0, 0], direction=(1, 0)), "direction: expected 3 components"),
    (dict(urdf=PLANAR, tip="tool", joints=[0, 0], point=(0.1, 0)), "point: expected 3 components"),
])
def test_bad_input_raises_value_error(kwargs, words):
    with pytest.raises(ValueError) as error:
        covopt.reflected_mass(**kwargs).to_dict()
    assert words in str(error.value)


def test_bad_trajectories_raise_value_error(tmp_path):
    backwards = tmp_path / "backwards.csv"
    backwards.write_text("t,q1,q2,qd1,qd2\n1,0,0,0,0\n0,0,0,0,0\n")
    with pytest.raises(ValueError, match="time goes backwards"):
        covopt.contact_motion(PLANAR, "tool", backwards).to_dict()
    with pytest.raises(ValueError, match="4 columns, expected 5"):
        short = tmp_path / "short.csv"
        short.write_text("t,q1,q2,qd1,qd2\n0,0,0,0\n")
        covopt.contact_motion(PLANAR, "tool", short).to_dict()
    with pytest.raises(ValueError, match="missing key 'velocities'"):
        covopt.contact_motion(PLANAR, "tool", {"time_s": [0], "positions": [[0, 0]]}).to_dict()


@pytest.mark.parametrize("kwargs, words", [
    # Degrees given as radians: beyond a full turn.
    (dict(urdf=FR3, tip="fr3_link8", joints=[0, -90, 90, -90, -90, 0, 0]),
     "joints: joint 2 (fr3_joint2): -90 rad is not allowed (within a full turn"),
    # FR3 joint 4 at +90 degrees: outside the URDF's [-3.0421, -0.1518] rad.
    (dict(urdf=FR3, tip="fr3_link8", joints=[0, 0, 0, math.pi / 2, 0, 1.57, 0]),
     "outside the URDF's limits [-3.0421, -0.1518] rad of joint 'fr3_joint4'"),
    (dict(urdf=PLANAR, tip="tool", joints=[0, 10**400]), "joints[1]: must be a finite number"),
    (dict(urdf=PLANAR, tip="tool", joints=np.zeros((2, 2))), "joints[0]: expected a number"),
    (dict(urdf=PLANAR, tip="tool", joints=[[0, 0]]), "joints[0]: expected a number"),
    (dict(urdf=PLANAR, tip="tool", joints=[0, 0], point=(1e308, 0, 0)), "point: component 1 = 1e+308 m"),
    (dict(urdf=PLANAR, tip="link2", base="link2", joints=[]), "has no movable joint"),
    (dict(urdf="/dev/zero", tip="tool", joints=[0, 0]), "larger than 16 MiB"),
    (dict(urdf=None, tip="b", joints=[0, 0], urdf_text=(
        "<robot name='c'><link name='base'/><link name='a'/><link name='b'/>"
        "<joint name='j1' type='continuous'><parent link='base'/><child link='a'/></joint>"
        "<joint name='j2' type='continuous'><parent link='a'/><child link='b'/></joint>"
        "<joint name='j3' type='fixed'><parent link='b'/><child link='a'/></joint></robot>")),
     "link 'a' has two parents"),
    (dict(urdf=None, tip="arm", joints=[0], urdf_text=(
        "<robot name='r'><link name='base'/><joint name='j1' type='continuous'><parent link='base'/>"
        "<child link='arm'/><axis xyz='0 0 1'/></joint><link name='arm'><inertial><mass value='2'/>"
        "<inertia ixx='0.01' ixy='0' ixz='0' iyy='0.1' iyz='0' izz='-0.1'/></inertial></link></robot>")),
     "link 'arm': <inertia> smallest principal moment = -0.1"),
])
def test_inputs_that_once_gave_wrong_answers_raise_value_error(kwargs, words):
    with pytest.raises(ValueError) as error:
        covopt.reflected_mass(**kwargs).to_dict()
    assert words in str(error.value)


def test_ignore_joint_limits_answers_with_a_warning():
    joints = [0, 0, 0, math.pi / 2, 0, 1.57, 0]
    got = covopt.reflected_mass(FR3, "fr3_link8", joints, direction=(1, 0, 0), ignore_joint_limits=True)
    assert any("were not checked" in w for w in got.warnings)
    checked = covopt.reflected_mass(FR3, "fr3_link8", FR3_READY, direction=(1, 0, 0))
    assert not any("were not checked" in w for w in checked.warnings)


def test_a_huge_direction_is_normalised_not_none():
    got = covopt.reflected_mass(PLANAR, "tool", [0.3, 1.2], direction=(1e308, 1e308, 0))
    assert got.direction == pytest.approx([math.sqrt(0.5), math.sqrt(0.5), 0])
    assert isinstance(got.reflected_mass_kg, float)


def test_trajectory_inputs_that_once_gave_wrong_answers(tmp_path):
    headerless = tmp_path / "headerless.csv"
    headerless.write_text("0,0,0,1.5,0\n0.1,0.1,0,0.1,0\n")
    motion = covopt.contact_motion(PLANAR, "tool", headerless)
    assert len(motion.samples) == 2
    assert motion.samples[0].speed_m_per_s == pytest.approx(1.8 * 1.5)
    assert any("no header line" in w for w in motion.warnings)
    degrees = tmp_path / "degrees.csv"
    degrees.write_text("t,q1,q2,qd1,qd2\n0,0,-90,0,0\n")
    with pytest.raises(ValueError,
                       match=r"degrees.csv:2, column 3 \(q2 \[rad\], joint 'elbow'\): -90 rad"):
        covopt.contact_motion(PLANAR, "tool", degrees).to_dict()
    hexfloat = tmp_path / "hex.csv"
    hexfloat.write_text("t,q1,q2,qd1,qd2\n0,0x1p3,0,0,0\n")
    with pytest.raises(ValueError, match="in decimal"):
        covopt.contact_motion(PLANAR, "tool", hexfloat).to_dict()
    with pytest.raises(ValueError, match="larger than 64 MiB"):
        covopt.contact_motion(PLANAR, "tool", "/dev/zero").to_dict()
    with pytest.raises(ValueError, match="unknown key 'velocity'"):
        covopt.contact_motion(PLANAR, "tool", {"time_s": [0], "positions": [[0, 0]],
                                               "velocities": [[0, 0]], "velocity": [[1, 1]]}).to_dict()
    too_fast = {"time_s": [0], "positions": [[0, 0]], "velocities": [[2.5, 0]]}
    with pytest.raises(ValueError, match="trajectory sample 1, qd1 \\(joint 'shoulder'\\): 2.5 rad/s"):
        covopt.contact_motion(PLANAR, "tool", too_fast).to_dict()
    ignored = covopt.contact_motion(PLANAR, "tool", too_fast, ignore_joint_limits=True)
    assert any("were not checked" in w for w in ignored.warnings)
