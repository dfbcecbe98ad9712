"""The scene keywords beyond the conservative two-mass impact (docs/model.md §10) in Python.

damping, reaction_delay, braking, torso_mass, neck_stiffness and neck_damping are keywords of
every scene-taking wrapper; simulate chooses its path as the CLI's --method auto does (the
exact path with damping, the time path with braking or a neck) and gives the CLI's numbers;
the physics: damping dissipates (coefficient of restitution below 1, less the more damping),
braking lowers the peak force, a neck sits between a free head and a head carrying its torso.
The neck values here are test inputs, not published physiology.
"""

import inspect
import math

import pytest

import covopt
from calls import call

EXTENDED = ("damping", "reaction_delay", "braking", "torso_mass", "neck_stiffness", "neck_damping")
SCENE_WRAPPERS = (covopt.simulate, covopt.sweep, covopt.optimize, covopt.max_safe_speed,
                  covopt.max_safe_mass, covopt.speed_limit, covopt.check_trajectory)
NECK = {"torso_mass": "30kg", "neck_stiffness": "20kN/m", "neck_damping": "200N*s/m"}


@pytest.mark.parametrize("wrapper", SCENE_WRAPPERS, ids=lambda f: f.__name__)
def test_every_scene_taking_call_takes_a_scene_with_the_extended_keywords(wrapper):
    parameters = inspect.signature(wrapper).parameters
    assert parameters["scene"].default is None
    scene = covopt.Scene(**{name: 0.0 for name in EXTENDED})
    assert all(getattr(scene, name) == 0.0 for name in EXTENDED)
    assert "damping" in inspect.getdoc(covopt.Scene)


def test_damping_dissipates_on_the_exact_path_as_the_cli(cli_json):
    conservative = covopt.simulate()
    damped = covopt.simulate(covopt.Scene(damping="0.2s/m")).to_dict()
    assert damped["method"] == "exact"
    assert damped["scene"]["model"]["damping_s_per_m"] == 0.2
    assert 0.0 < damped["coefficient_of_restitution"] < 1.0
    assert damped["rebound_speed_m_per_s"] < conservative.rebound_speed_m_per_s
    more = covopt.simulate(covopt.Scene(damping=0.5))  # SI: s/m
    assert more.coefficient_of_restitution < damped["coefficient_of_restitution"]
    # The same object as the CLI's, number for number.
    assert damped == cli_json("simulate", "--damping", "0.2s/m", "--json")


def test_braking_lowers_the_peak_force_on_the_time_path():
    free = covopt.simulate(method="arkode-erk54")
    braked = covopt.simulate(covopt.Scene(braking="200m/s2"))  # from first contact: no reaction delay
    late = covopt.simulate(covopt.Scene(braking="200m/s2", reaction_delay="3ms"))
    assert braked.method == "arkode-erk54"  # auto: the time path's default integrator
    assert braked.scene.robot.braking_m_per_s2 == 200.0
    assert braked.peak_force_N < free.peak_force_N
    assert braked.max_penetration_m < free.max_penetration_m
    # Braking later removes less of the robot's momentum before the peak.
    assert braked.peak_force_N < late.peak_force_N <= free.peak_force_N * (1 + 1e-9)


def test_a_neck_lies_between_a_free_head_and_one_carrying_its_torso():
    free = covopt.simulate(method="arkode-erk54")
    neck = call(covopt.simulate, **NECK)
    heavy = covopt.simulate(covopt.Scene(head_mass=4.5 + 30.0), method="arkode-erk54")
    assert neck["method"] == "arkode-erk54"
    assert free.peak_force_N < neck["peak_force_N"] < heavy.peak_force_N
    assert neck["scene"]["head"]["torso_mass_kg"] == 30.0


def test_the_extended_keywords_reach_the_speed_limit_and_the_history():
    braked = covopt.max_safe_speed(covopt.Scene(braking="50m/s2"))
    assert braked.max_safe_speed_m_per_s > covopt.max_safe_speed().max_safe_speed_m_per_s
    assert braked.status == "limited"
    history = covopt.simulate(covopt.Scene(braking="200m/s2"), history=True).history
    assert len(history.time_s) >= 400  # spaced by a first run's contact duration
    assert max(history.force_N) > 0.0


@pytest.mark.parametrize("kwargs,named", [
    ({"damping": -0.1}, "damping"),
    ({"braking": "-5m/s2"}, "braking"),
    ({"neck_stiffness": "20kN/m"}, "neck"),  # a neck without a torso
    ({"braking": "200m/s2", "method": "exact"}, "method='exact'"),
    ({"damping": "0.2kg"}, "damping"),
])
def test_bad_extended_input_is_a_value_error_naming_it(kwargs, named):
    with pytest.raises(ValueError, match=".*" + named.replace("(", r"\(")):
        call(covopt.simulate, **kwargs)


def test_a_fixed_torso_is_accepted():
    result = covopt.simulate(covopt.Scene(torso_mass=math.inf, neck_stiffness="20kN/m"))
    assert result.peak_force_N > 0.0
