"""covopt.sweep: numpy arrays with a[i, j] at x[i], y[j], each point the single simulation
of its scene; one axis gives 1-D arrays; invalid points are NaN and False; the same for
any number of threads; bad axes are ValueErrors."""

import math

import numpy as np
import pytest

import covopt


def test_each_point_is_the_simulation_of_its_scene():
    speeds = [0.5, 1.0, 2.0, 3.0]
    thicknesses = [0.0, 0.005, 0.015]
    grid = covopt.sweep(("speed", speeds), ("covering_thickness", thicknesses),
                        scene=covopt.Scene(robot_mass=20.0)).to_dict()
    assert grid["x_quantity"] == "speed" and grid["y_quantity"] == "covering-thickness"
    np.testing.assert_array_equal(grid["x"], speeds)
    np.testing.assert_array_equal(grid["y"], thicknesses)
    for i, speed in enumerate(speeds):
        for j, thickness in enumerate(thicknesses):
            one = covopt.simulate(covopt.Scene(speed=speed, covering_thickness=thickness,
                                               robot_mass=20.0))
            assert grid["peak_force_N"][i, j] == one.peak_force_N
            assert grid["max_energy_density_J_per_m2"][i, j] == one.max_energy_density_J_per_m2
            assert grid["contact_duration_s"][i, j] == one.contact_duration_s
            assert grid["laceration_ratio"][i, j] == one.laceration.ratio
            assert grid["contusion_ratio"][i, j] == one.contusion.ratio
            # The sweep's safe is the injury verdict; admissible also needs the covering's
            # design rules (not fully compressed), as simulate's safe does.
            assert grid["safe"][i, j] == one.verdict.injury_safe
            assert grid["admissible"][i, j] == one.safe
            assert grid["fully_compressed"][i, j] == one.fully_compressed
            assert grid["phase_at_max"][i, j] == one.phase_at_max


def test_shapes_and_types():
    grid = covopt.sweep(("speed", np.linspace(0.5, 3, 7)), ("robot_mass", [1, 10, 100,
                                                                           "fixed"])).to_dict()
    assert grid["worst_ratio"].shape == (7, 4)
    assert grid["worst_ratio"].dtype == np.float64
    assert grid["safe"].dtype == np.bool_
    np.testing.assert_array_equal(grid["worst_ratio"],
                                  np.maximum(grid["laceration_ratio"], grid["contusion_ratio"]))
    assert grid["y"][-1] == math.inf
    assert grid["status"] == "all-valid"
    line = covopt.sweep(("speed", [1.0, 2.0])).to_dict()
    assert line["peak_force_N"].shape == (2,) and "y" not in line
    # Faster impacts are harder: the force grows along every row.
    assert np.all(np.diff(grid["peak_force_N"], axis=0) > 0)


def test_the_same_for_any_number_of_threads():
    axes = (("speed", np.linspace(0.1, 4, 30)), ("covering_thickness", np.linspace(0, 0.03, 20)))
    one = covopt.sweep(*axes, threads=1).to_dict()
    many = covopt.sweep(*axes, threads=3).to_dict()
    for name in ("peak_force_N", "worst_ratio", "compression_ratio", "admissible"):
        np.testing.assert_array_equal(one[name], many[name])


def test_invalid_points_are_nan_and_false():
    grid = covopt.sweep(("head_radius", [0.08, 0.002]))
    assert list(grid.valid) == [True, False]
    assert math.isnan(grid.peak_force_N[1]) and not grid.safe[1]
    assert grid.status == "some-invalid" and "head" in grid.message
    with pytest.raises(covopt.ComputationError) as error:
        covopt.sweep(("head_radius", [0.002])).to_dict()
    assert error.value.status == "none-valid"


@pytest.mark.parametrize("x,words", [
    (("sped", [1.0]), ["no scene quantity 'sped'"]),
    (("speed", []), ["x.values: no values for speed"]),
    (("speed", [math.nan]), ["x.values[0]", "nan"]),
    ("speed", ["x: expected (quantity, values)"]),
    (("speed", [1.0, "fast"]), ["x: a value is a number in SI, 'fixed' or 'flat'", "fast"]),
])
def test_bad_axes_are_value_errors(x, words):
    with pytest.raises(ValueError) as error:
        covopt.sweep(x).to_dict()
    for word in words:
        assert word in str(error.value)


def test_scene_keywords_apply_as_in_simulate():
    grid = covopt.sweep(("speed", [2.0]), scene=covopt.Scene(material="polystyrene foam 48.3",
                                                             safety_factor=2.0))
    one = covopt.simulate(covopt.Scene(speed=2.0, material="polystyrene foam 48.3", safety_factor=2.0))
    assert grid.worst_ratio[0] == max(one.laceration.ratio, one.contusion.ratio)
    assert grid.safe[0] == one.safe
