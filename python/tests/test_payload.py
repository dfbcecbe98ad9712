"""The payload keywords (payload_mass, payload_com, payload_inertia) and ISO/TS 15066's
fallback (covopt.iso_robot_mass): the FR3 with an offset tool against the independent numpy
reference (robot_reference.py, the tool one more rigid body on the flange); to_dict equal to
``covopt robot --json`` with the same --payload-* flags, and to ``covopt robot --trajectory
--json`` for check_trajectory; a zero payload changes nothing; a non-physical payload raises
ValueError naming the keyword; iso_robot_mass is M/2 + m_L exactly, and a scene with it answers
as the CLI's --robot-moving-mass but for the CLI's warning that says where the mass came from.
"""

import math
import pathlib

import numpy as np
import pytest

import covopt
from conftest import without_provenance
import robot_reference as ref

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
PLANAR = ROOT / "tests" / "robot" / "data" / "planar_2link.urdf"
FR3 = ROOT / "robot" / "models" / "franka_fr3.urdf"
PICK = ROOT / "robot" / "models" / "franka_fr3_pick.csv"
FR3_READY = [0.0, -math.pi / 4, 0.0, -3 * math.pi / 4, 0.0, math.pi / 2, math.pi / 4]
TOOL = dict(payload_mass=1.5, payload_com=(0.01, -0.02, 0.08),
            payload_inertia=(0.004, 0.005, 0.002, 0.0005, 0.0, -0.0003))
TOOL_FLAGS = ["--payload-mass", "1.5", "--payload-com", "0.01,-0.02,0.08",
              "--payload-inertia", "0.004,0.005,0.002,0.0005,0,-0.0003"]


def tensor(ixx, iyy, izz, ixy, ixz, iyz):
    return np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])


@pytest.mark.parametrize("direction", [(1.0, 0.0, 0.0), (0.3, -0.5, 0.8)])
def test_the_fr3_with_a_tool_matches_the_numpy_reference(direction):
    got = covopt.reflected_mass(str(FR3), "fr3_link8", FR3_READY, point=(0.0, 0.0, 0.05),
                                direction=direction, **TOOL)
    expected = ref.reflected_mass(str(FR3), "fr3_link8", FR3_READY, point=(0.0, 0.0, 0.05),
                                  direction=direction,
                                  payload=(1.5, TOOL["payload_com"], tensor(*TOOL["payload_inertia"])))
    bare = ref.reflected_mass(str(FR3), "fr3_link8", FR3_READY, point=(0.0, 0.0, 0.05), direction=direction)
    assert got.reflected_mass_kg == pytest.approx(expected["reflected_mass_kg"], rel=1e-9)
    assert got.min_reflected_mass_kg == pytest.approx(expected["min_reflected_mass_kg"], rel=1e-9)
    assert got.max_reflected_mass_kg == pytest.approx(expected["max_reflected_mass_kg"], rel=1e-9)
    without = got.payload.without_payload
    assert without.reflected_mass_kg == pytest.approx(bare["reflected_mass_kg"], rel=1e-9)
    assert got.reflected_mass_kg > without.reflected_mass_kg  # the tool raises the mass
    assert got.payload.mass_kg == 1.5
    assert got.payload.center_of_mass_m == list(TOOL["payload_com"])
    assert np.array(got.payload.inertia_kg_m2) == pytest.approx(tensor(*TOOL["payload_inertia"]), abs=0)


@pytest.mark.parametrize("direction, flags", [((1.0, 0.0, 0.0), ["--direction", "1,0,0"]), (None, [])])
def test_reflected_mass_with_a_payload_is_the_cli_json(cli_json, direction, flags):
    got = covopt.reflected_mass(str(FR3), "fr3_link8", FR3_READY, direction=direction, **TOOL).to_dict()
    joints = ",".join(repr(q) for q in FR3_READY)
    assert got == cli_json("robot", "--urdf", str(FR3), "--tip", "fr3_link8", f"--joints={joints}", "--json",
                           *TOOL_FLAGS, *flags)
    assert got["payload"]["without_payload"]["max_reflected_mass_kg"] < got["max_reflected_mass_kg"]


def test_check_trajectory_with_a_payload_is_the_cli_json(cli_json):
    got = covopt.check_trajectory(FR3, "fr3_link8", PICK, **TOOL).to_dict()
    expected = cli_json("robot", "--urdf", str(FR3), "--tip", "fr3_link8", "--trajectory", str(PICK), "--json",
                        *TOOL_FLAGS)
    # The CLI's own input warnings (the default covering) are the CLI's; the rest is the same.
    cli_warnings = expected.pop("warnings")
    assert set(got.pop("warnings")) <= set(cli_warnings)
    assert got == expected
    bare = covopt.check_trajectory(FR3, "fr3_link8", PICK)
    assert got["safe_speed_scale"] < bare.safe_speed_scale
    regions = covopt.check_trajectory(FR3, "fr3_link8", PICK, body_region="chest", contact_area=1e-4, **TOOL)
    bare_regions = covopt.check_trajectory(FR3, "fr3_link8", PICK, body_region="chest", contact_area=1e-4)
    assert regions.to_dict() != bare_regions.to_dict()


def test_contact_motion_with_a_payload_raises_every_moving_sample():
    bare = covopt.contact_motion(FR3, "fr3_link8", PICK).to_dict()["samples"]
    loaded = covopt.contact_motion(FR3, "fr3_link8", PICK, **TOOL).to_dict()["samples"]
    moving = [(b, l) for b, l in zip(bare, loaded) if b["moving"]]
    assert len(moving) > 50
    for b, l in moving:
        assert l["reflected_mass_kg"] > b["reflected_mass_kg"]
        assert l["speed_m_per_s"] == b["speed_m_per_s"]


def test_a_zero_payload_changes_nothing():
    bare = without_provenance(covopt.reflected_mass(PLANAR, "tool", [0.3, 1.2], direction=(1, 2, 0)))
    assert bare["payload"] is None
    for zero in [dict(payload_mass=0.0), dict(payload_mass=0, payload_com=(0, 0, 0), payload_inertia=(0,) * 6)]:
        assert without_provenance(covopt.reflected_mass(PLANAR, "tool", [0.3, 1.2], direction=(1, 2, 0), **zero)) == bare
    assert (without_provenance(covopt.contact_motion(FR3, "fr3_link8", PICK, payload_mass=0))
            == without_provenance(covopt.contact_motion(FR3, "fr3_link8", PICK)))


@pytest.mark.parametrize("keywords, words", [
    (dict(payload_mass=1, payload_inertia=(-0.01, 0.02, 0.02, 0, 0, 0)),
     ["payload_inertia", "smallest principal moment = -0.01", ">= 0 kg m²"]),
    (dict(payload_mass=1, payload_inertia=(0.01, 0.01, 0.03, 0, 0, 0)),
     ["payload_inertia", "largest principal moment = 0.03", "triangle inequality"]),
    (dict(payload_mass=1, payload_inertia=(math.nan, 0.02, 0.02, 0, 0, 0)),
     ["payload_inertia[0]", "finite"]),
    (dict(payload_mass=1, payload_inertia=(0.01, 0.02, 0.02)), ["payload_inertia", "expected 6", "got 3"]),
    (dict(payload_mass=-1), ["payload_mass", "mass = -1", "[0, 1e4] kg"]),
    (dict(payload_mass=math.inf), ["payload_mass", "finite"]),
    (dict(payload_mass=1, payload_com=(20, 0, 0)), ["payload_com", "centre of mass x = 20", "±10 m"]),
    (dict(payload_com=(0, 0, 0.1)), ["payload_com needs payload_mass"]),
    (dict(payload_mass=0, payload_inertia=(0.01, 0.01, 0.01, 0, 0, 0)), ["payload_inertia", "without a mass"]),
])
def test_a_non_physical_payload_raises_value_error_naming_the_keyword(keywords, words):
    with pytest.raises(ValueError) as raised:
        covopt.reflected_mass(PLANAR, "tool", [0.3, 1.2], **keywords)
    for word in words:
        assert word in str(raised.value)
    with pytest.raises(ValueError):
        covopt.check_trajectory(FR3, "fr3_link8", PICK, **keywords)


def test_iso_robot_mass_is_half_the_moving_mass_plus_the_payload(cli_json):
    assert covopt.iso_robot_mass(30.0, 2.5) == 30.0 / 2 + 2.5
    assert covopt.iso_robot_mass(30) == 15.0
    got = covopt.simulate(covopt.Scene(robot_mass=covopt.iso_robot_mass(30, 2.5))).to_dict()
    expected = cli_json("simulate", "--json", "--robot-moving-mass", "30", "--payload-mass", "2.5")
    assert expected["warnings"][0].startswith("robot mass 17.5 kg: ISO/TS 15066")
    expected["warnings"].pop(0)
    # The CLI's result also names the robot model behind its mass; the library's was given a mass.
    model = expected.pop("robot_model")
    assert (model["source"], model["moving_mass_kg"], model["payload_mass_kg"]) == ("iso-estimate", 30.0, 2.5)
    assert "M/2 + m_L, M = 30 kg" in expected["summary"]["robot"]["motion"]
    assert expected["summary"]["robot"]["reflected_mass_kg"] == 17.5
    expected["summary"]["robot"] = got["summary"]["robot"]
    assert got == expected
    for bad, word in [((0.0, 1.0), "moving_mass"), ((-5.0, 1.0), "moving_mass"), ((2e6, 0.0), "moving_mass"),
                      ((30.0, -1.0), "payload_mass"), ((30.0, math.nan), "payload_mass"), (("30kg", 1.0), "moving_mass")]:
        with pytest.raises(ValueError, match=word):
            covopt.iso_robot_mass(*bad)
