"""The physical floors from Python (docs/guide/inputs-and-errors.md, "Physical floors"): a
length, area, mass, time or modulus below its floor is a ValueError naming the keyword, never
an answer; and, as a property, scenes drawn over each keyword's whole range give finite
numbers or a ValueError. A denormal robot_radius once gave max_safe_speed 100 m/s
("safe-up-to-search-limit")."""
import math
import random

import pytest

import covopt


def test_denormal_radius_is_a_value_error_naming_robot_radius():
    scene = covopt.Scene(robot_radius=5e-324, covering_thickness=0, robot_mass=10)
    for call, given in ((covopt.max_safe_speed, scene), (covopt.max_safe_mass, scene.replace(robot_mass=None)),
                        (covopt.simulate, scene)):
        with pytest.raises(ValueError, match=r"robot_radius") as error:
            call(given)
        assert "[0.0001, 100] m" in str(error.value)
        assert "5e-324" in str(error.value)


@pytest.mark.parametrize("keywords,words", [
    ({"reaction_delay": "1e-300s", "braking": "1e4m/s2"}, "robot.reaction_delay must be 0 (brake at contact) or in [1e-06, 10] s"),
    ({"torso_mass": 5e-324, "neck_stiffness": 1e4}, "head.torso_mass must be in [0.001, 1e+06] kg"),
    ({"covering_thickness": "0.05mm"}, "covering.thickness must be 0 (no covering) or in [0.0001, 1] m"),
    ({"covering_modulus": "5e-324Pa"}, "covering.modulus must be in [1000, 1e+13] Pa"),
    ({"laceration_limit": "5e-324Pa"}, "laceration_limit must be in [1000, 1e+13] Pa"),
])
def test_below_a_floor_is_a_value_error(keywords, words):
    with pytest.raises(ValueError) as error:
        covopt.simulate(covopt.Scene(**keywords))
    assert words in str(error.value)


def test_contact_area_floor():
    bare = covopt.Scene(covering_thickness=0)
    with pytest.raises(ValueError, match=r"contact_area must be in \[1 mm², 1 m²\]"):
        covopt.simulate(bare, body_region="chest", contact_area="1e-300m2")
    r = covopt.simulate(bare, body_region="chest", contact_area="1mm2")
    assert math.isfinite(r.peak_force_N)


def finite_numbers(value):
    """Every number in a result's dict, nested."""
    if isinstance(value, dict):
        for v in value.values():
            yield from finite_numbers(v)
    elif isinstance(value, list):
        for v in value:
            yield from finite_numbers(v)
    elif isinstance(value, float):
        yield value


def log_uniform(rng, low, high):
    u = rng.random()
    if u < 0.05:
        return low
    if u < 0.08:
        return high
    if u < 0.12:
        return low * (1 + 1e-9)
    if u < 0.14:
        return 5e-324
    return math.exp(rng.uniform(math.log(low), math.log(high)))


def test_property_every_accepted_scene_gives_finite_numbers():
    rng = random.Random(33)
    taken = refused = 0
    for _ in range(300):
        keywords = {
            "robot_mass": f"{log_uniform(rng, 1e-3, 1e6)!r}kg",
            "speed": f"{log_uniform(rng, 1e-6, 100.0)!r}m/s",
            "robot_radius": f"{log_uniform(rng, 1e-4, 100.0)!r}m",
            "covering_thickness": 0 if rng.random() < 0.2 else f"{log_uniform(rng, 1e-4, 1.0)!r}m",
            "covering_modulus": f"{log_uniform(rng, 1e3, 1e13)!r}Pa",
            "head_mass": f"{log_uniform(rng, 1e-3, 1e6)!r}kg",
        }
        try:
            scene = covopt.Scene(**keywords)
            result = covopt.simulate(scene).to_dict()
            limit = covopt.max_safe_speed(scene.replace(speed=None)).to_dict()
        except ValueError:
            refused += 1
            continue
        taken += 1
        for number in list(finite_numbers(result)) + list(finite_numbers(limit)):
            assert math.isfinite(number), keywords
        # A NaN reaches JSON as null: the numbers that must be there are.
        for key in ("max_penetration_m", "peak_force_N", "max_compressive_stress_Pa", "max_energy_density_J_per_m2",
                    "contact_duration_s"):
            assert isinstance(result[key], float) and math.isfinite(result[key]), (key, keywords)
        for key in ("laceration", "contusion"):
            assert math.isfinite(result[key]["ratio"]), (key, keywords)
        for key in ("laceration_ratio", "contusion_ratio", "compression_ratio"):
            assert limit[key] is None or math.isfinite(limit[key]), (key, keywords)
    assert taken > 100
    assert refused > 10
