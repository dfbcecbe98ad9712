"""covopt.Scene (keywords read once, read-only attributes in SI, replace, repr, to_dict) and the
typed results (attributes, repr, to_dict() = the CLI's --json object)."""

import math

import pytest

import covopt


def test_a_scene_reads_its_keywords_once_into_si_attributes():
    scene = covopt.Scene(robot_mass="10kg", speed=1.5, covering_thickness="20mm", robot_radius="flat")
    assert (scene.robot_mass, scene.speed, scene.covering_thickness) == (10.0, 1.5, 0.02)
    assert scene.robot_radius == math.inf
    assert scene.head_mass == covopt.Scene().head_mass  # the paper's scene where unset
    assert scene.material is None and scene.thresholds == "cumulative" and scene.safety_factor == 1.0
    assert scene.covering_law == "auto" and covopt.Scene(covering_law="foam").covering_law == "foam"
    assert repr(scene) == "Scene(robot_mass='10kg', speed=1.5, covering_thickness='20mm', robot_radius='flat')"
    assert scene.to_dict()["robot"]["mass_kg"] == 10.0 and scene.to_dict()["robot"]["radius_m"] == "flat"


def test_replace_makes_a_changed_copy_and_none_unsets():
    scene = covopt.Scene(material="polystyrene foam 48.3", speed=2.0)
    faster = scene.replace(speed=3.0)
    assert (scene.speed, faster.speed, faster.material) == (2.0, 3.0, "polystyrene foam 48.3")
    assert scene.replace(material=None, covering_modulus="5MPa").covering_modulus == 5e6
    with pytest.raises(ValueError, match="give either material or covering_modulus"):
        scene.replace(covering_modulus="5MPa")


def test_a_scene_is_read_only_and_refuses_unknown_keywords_and_bad_values():
    scene = covopt.Scene()
    with pytest.raises(AttributeError):
        scene.speed = 2.0
    with pytest.raises(TypeError, match="unexpected keyword argument 'robot_mas'"):
        covopt.Scene(robot_mas=10)
    with pytest.raises(ValueError, match="robot_radius 40: a bare number is in metres"):
        covopt.Scene(robot_radius=40)
    with pytest.raises(TypeError, match="expected a covopt.Scene"):
        covopt.simulate({"speed": 2.0})


def test_results_are_attributes_with_the_cli_keys():
    result = covopt.simulate(covopt.Scene(speed=2.0))
    assert isinstance(result, covopt.Simulation) and isinstance(result, covopt.Result)
    assert result.contusion.ratio == result.to_dict()["contusion"]["ratio"]
    assert dir(result) == sorted(result.to_dict())
    # repr is the result summary's first line (the library's), its state word first.
    assert repr(result).startswith(f"Simulation({result.summary.state.upper()}, margin ")
    assert "head (frontal)" in repr(result)
    with pytest.raises(AttributeError, match="has no attribute 'peak_force'; it has: "):
        result.peak_force
    with pytest.raises(AttributeError, match="read-only"):
        result.safe = True
    copy = result.to_dict()
    copy["safe"] = "edited"
    assert result.safe in (True, False)  # to_dict() is a copy


def test_an_object_keyed_by_scene_flag_stays_a_dict():
    worst = covopt.worst_case(covopt.Scene(covering_thickness="15mm"), ranges={"head_mass": ("3.7kg",
                                                                                             "5.8kg")})
    assert isinstance(worst.worst_case.inputs, dict)
    assert set(worst.worst_case.inputs) == {"head-mass"}
