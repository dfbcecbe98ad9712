"""The history of a scene beyond the conservative two-mass impact (docs/model.md §10) in Python.

With damping, braking or a neck, covopt.simulate(history=True) adds the CLI's extra --history
columns: the bodies' speeds, the neck force and the work taken out of the moving bodies. They
equal the CLI's CSV number for number, and they are physical: δ' is the difference of the
speeds, the brake does no work before its delay and only takes energy out afterwards, and at
separation the kinetic energy lost is the work taken out. A conservative scene keeps the seven
columns. Every run here is a time-path run in the same process as other tests': that the numbers
still equal the CLI's fresh process is part of the check.
"""

import numpy as np
import pytest

import covopt
from calls import call

BRAKING = {"braking": "200m/s2", "reaction_delay": "2ms"}
BRAKING_FLAGS = ["--braking", "200m/s2", "--reaction-delay", "2ms"]
NECK = {"torso_mass": "30kg", "neck_stiffness": "20kN/m", "neck_damping": "200N*s/m"}
BASE = ["time_s", "penetration_m", "penetration_rate_m_per_s", "force_N", "compressive_stress_Pa",
        "tensile_stress_Pa", "energy_density_J_per_m2"]
EXTRA = ["robot_speed_m_per_s", "head_speed_m_per_s", "neck_force_N", "dissipated_work_J"]


def test_a_braking_history_has_the_bodies_speeds_and_the_brakes_work():
    result = call(covopt.simulate, history=True, **BRAKING)
    history = result["history"]
    assert list(history) == BASE + EXTRA
    samples = result["solver"]["history_samples"]
    assert samples >= 400
    for name in EXTRA:
        assert history[name].shape == (samples,)
        assert history[name].dtype == np.float64
    v0 = result["scene"]["robot"]["speed_m_per_s"]
    robot_kg = result["scene"]["robot"]["mass_kg"]
    head_kg = result["scene"]["head"]["mass_kg"]
    robot = history["robot_speed_m_per_s"]
    head = history["head_speed_m_per_s"]
    work = history["dissipated_work_J"]
    time = history["time_s"]

    assert robot[0] == v0 and head[0] == 0.0 and work[0] == 0.0
    np.testing.assert_allclose(robot - head, history["penetration_rate_m_per_s"],
                               rtol=0, atol=1e-12 * v0)
    assert np.all(history["neck_force_N"] == 0.0)  # no neck
    # Before the reaction delay the brake is off and nothing else dissipates.
    assert np.all(work[time < 0.002] == 0.0)
    assert np.any(time < 0.002) and np.any(time > 0.002)
    # Braking only takes energy out: W grows (to the dense output's rounding) and ends > 0.
    assert np.all(np.diff(work) >= -1e-9 * work[-1])
    assert work[-1] > 0.0
    # The robot slows under the brake and the contact force; the head is only pushed.
    assert robot[-1] < v0 and head[-1] > 0.0
    # At separation U = 0: the kinetic energy lost is the work taken out.
    impact_energy = 0.5 * robot_kg * head_kg / (robot_kg + head_kg) * v0 ** 2
    balance = 0.5 * robot_kg * (robot[-1] ** 2 - v0 ** 2) + 0.5 * head_kg * head[-1] ** 2 + work[-1]
    assert abs(balance) < 1e-6 * impact_energy


def test_a_braking_history_equals_the_cli_history_csv(cli, tmp_path):
    csv = tmp_path / "history.csv"
    code, _, err = cli("simulate", *BRAKING_FLAGS, "--history", str(csv))
    assert code == 0, err
    table = np.genfromtxt(csv, delimiter=",", names=True)
    history = call(covopt.simulate, history=True, **BRAKING)["history"]
    assert list(table.dtype.names) == list(history)
    for name in history:
        np.testing.assert_array_equal(history[name], table[name])


def test_a_neck_history_carries_the_neck_force():
    history = call(covopt.simulate, history=True, **NECK)["history"]
    assert list(history) == BASE + EXTRA
    assert history["neck_force_N"][0] == 0.0  # the neck starts relaxed
    assert history["neck_force_N"].max() > 0.0  # then the head pulls on the torso
    assert history["dissipated_work_J"][-1] > 0.0  # the neck damper


@pytest.mark.parametrize("kwargs", [{}, {"method": "cvode"}])
def test_a_conservative_history_keeps_seven_columns(kwargs):
    assert list(call(covopt.simulate, history=True, **kwargs)["history"]) == BASE
