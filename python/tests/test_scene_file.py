"""covopt.load_scene(path) reads scene files with the library's reader, the one behind
``covopt simulate --scene``: the Scene it returns gives the CLI's result, and a bad file
raises ValueError with the CLI's message (file:line:column, the key, what is allowed)."""

import os

import pytest

import covopt
from conftest import without_provenance

EXAMPLE = os.path.join(os.path.dirname(__file__), "..", "..", "cli", "examples", "paper_scene.toml")


def write(tmp_path, text, name="scene.toml"):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def test_the_shipped_example_is_the_papers_scene():
    scene = covopt.load_scene(EXAMPLE)
    assert (scene.robot_mass, scene.speed, scene.robot_radius, scene.covering_thickness) == (10.0, 2.0,
                                                                                             0.015, 0.015)
    assert scene.thresholds == "cumulative" and scene.safety_factor == 1.0
    from_file, default = without_provenance(covopt.simulate(scene)), without_provenance(covopt.simulate())
    # The same scene; only the default's covering is assumed, and said so.
    assert from_file.pop("warnings") == [] and default.pop("warnings")[0].startswith("no covering given")
    assert from_file == default


def test_only_what_the_file_sets_with_fixed_flat_and_extras(tmp_path):
    path = write(tmp_path, '[robot]\nspeed = "250 mm/s"\nradius = "flat"\n[head]\nmass = "fixed"\n'
                           '[covering]\nmaterial = "EPS geofoam EPS39"\n[limits]\nsafety_factor = 2\n')
    assert repr(covopt.load_scene(path)) == ("Scene(head_mass=inf, robot_radius=inf, speed=0.25, "
                                             "material='EPS geofoam EPS39', safety_factor=2.0)")


def test_a_unit_that_is_implausible_bare_stays_readable(tmp_path):
    scene = covopt.load_scene(write(tmp_path, '[robot]\nradius = "2m"\n'))
    assert repr(scene) == "Scene(robot_radius='2.0m')"
    assert covopt.simulate(scene).scene.robot.radius_m == 2.0


def test_ranges_are_returned_for_the_robust_calls(tmp_path):
    scene = covopt.load_scene(write(tmp_path, '[head]\nmass = "3.7kg..5.8kg"\n'))
    assert scene.ranges == {"head_mass": (3.7, 5.8)}
    assert covopt.worst_case(scene).worst_case.inputs == \
        covopt.worst_case(ranges={"head_mass": ("3.7kg", "5.8kg")}).worst_case.inputs
    with pytest.raises(ValueError, match="the scene has ranges"):
        covopt.simulate(scene)


def test_the_result_is_the_clis_for_the_same_file(tmp_path, cli_json):
    path = write(tmp_path, '[robot]\nmass = "7.5 kg"\nspeed = 1.2\n[covering]\nthickness = "20mm"\n'
                           '[limits]\nlaceration = "0.8 MPa"\n')
    # The CLI names the scene file among its inputs; a Scene does not remember its file.
    assert without_provenance(covopt.simulate(covopt.load_scene(path))) == \
        without_provenance(cli_json("simulate", "--scene", path, "--json"))


@pytest.mark.parametrize("text", ['[robot]\nmas = 10\n', '[robot]\nradius = 40\n', '[robt]\n',
                                  '[limits]\nsafety_factor = 0.5\n', '[robot]\nmass = = 1\n'])
def test_a_bad_file_raises_the_clis_message(tmp_path, cli, text):
    path = write(tmp_path, text)
    with pytest.raises(ValueError) as error:
        covopt.load_scene(path)
    assert str(error.value).startswith(path + ":")
    code, out, err = cli("simulate", "--scene", path)
    assert code == 2 and out == ""
    assert err == f"covopt simulate: error: {error.value}\n"


def test_a_missing_file_names_it(tmp_path):
    with pytest.raises(ValueError, match="cannot read scene file .*nope.toml"):
        covopt.load_scene(tmp_path / "nope.toml")
