"""A braking robot against the ISO/TS 15066 body regions (docs/model.md §13.10), in Python:
reaction_delay= and braking= in the scene take the time path; the bare robot's braked peak
against the closed form of a spring with a constant force added, the energy closed along the
history by numpy, the braked speed limits above the unbraked ones and equal to the CLI's,
and the refusals."""

import json
import math

import numpy as np
import pytest

import covopt

Scene = covopt.Scene
BARE = {"covering_thickness": 0}
COVERED = {"covering_modulus": "3MPa", "covering_poisson": 0.25, "covering_thickness": "10mm",
           "robot_radius": "20mm"}


def test_bare_braked_peak_is_the_closed_form_of_a_spring_with_a_constant_force():
    # Until t_d: d = (v0/w) sin wt; then d'' = -w² d - a while the robot moves forward (it does
    # up to the maximum), so d + a/w² oscillates: d_max = hypot(d_d + a/w², d'_d/w) - a/w².
    k, m_h = 25e3, 40.0  # chest, Table A.3
    for robot_mass, speed, delay, braking in ((10.0, 1.0, 0.0, 200.0), (5.0, 0.5, 0.004, 50.0),
                                              (20.0, 0.3, 0.01, 1000.0)):
        mu = 1.0 / (1.0 / robot_mass + 1.0 / m_h)
        w = math.sqrt(k / mu)
        offset = braking / w**2
        d_max = math.hypot(speed / w * math.sin(w * delay) + offset, speed * math.cos(w * delay) / w) - offset
        r = covopt.simulate(Scene(robot_mass=robot_mass, speed=speed, reaction_delay=delay, braking=braking, **BARE),
                            body_region="chest", contact_area="1cm2", method="time-path", rtol=1e-11)
        assert r.method == "time path (arkode-erk54, rtol 1e-11)"
        assert r.peak_force_N == pytest.approx(k * d_max, rel=1e-8)
        assert r.time_path.peak_force_N == r.peak_force_N
        assert r.to_dict()["scene"]["braking"] == {"reaction_delay_s": delay, "braking_m_per_s2": braking}
        unbraked = covopt.simulate(Scene(robot_mass=robot_mass, speed=speed, **BARE), body_region="chest",
                                   contact_area="1cm2")
        assert r.peak_force_N < unbraked.peak_force_N and r.governing_ratio < unbraked.governing_ratio


def test_the_energy_closes_along_a_braking_robot_s_history():
    # ½ m_R v_R² + ½ m_H (v_R - δ')² + F²/(2k) + W = ½ m_R v0² in the frame where the region
    # starts at rest (bare robot: the springs' energy is the body spring's).
    robot_mass, speed, k, m_h = 10.0, 1.0, 25e3, 40.0
    r = covopt.simulate(Scene(robot_mass=robot_mass, speed=speed, reaction_delay=0.005, braking=100.0, **BARE),
                        body_region="chest", contact_area="1cm2", history=True, rtol=1e-10)
    h = r.history
    v_r, rate, force, work = h.robot_speed_m_per_s, h.approach_rate_m_per_s, h.force_N, h.braking_work_J
    total = 0.5 * robot_mass * v_r**2 + 0.5 * m_h * (v_r - rate)**2 + force**2 / (2 * k) + work
    initial = 0.5 * robot_mass * speed**2
    assert np.max(np.abs(total - initial)) <= 100 * 1e-10 * initial
    assert work[-1] > 0 and np.all(np.diff(work) >= -1e-12 * initial)  # the brake only takes energy out
    assert np.isclose(force.max(), r.peak_force_N, rtol=1e-12)


def test_braked_speed_limits_are_above_the_unbraked_ones_and_the_cli_s(cli):
    braked = covopt.speed_limit(Scene(robot_mass=10, reaction_delay=0.005, braking=100, **COVERED),
                                body_region=["chest", "hands-fingers"], contact_area="1cm2")
    unbraked = covopt.speed_limit(Scene(robot_mass=10, **COVERED), body_region=["chest", "hands-fingers"],
                                  contact_area="1cm2")
    assert len(braked) == 2
    for b, u in zip(braked, unbraked):
        assert b.covered_status == "limited" and b.bare_status == "limited"
        assert b.covered_max_speed_m_per_s > u.covered_max_speed_m_per_s
        assert b.bare_max_speed_m_per_s > u.bare_max_speed_m_per_s
    code, out, err = cli("speed-limit", "--body-region", "chest,hands-fingers", "--contact-area", "1cm2",
                         "--robot-mass", "10", "--reaction-delay", "5ms", "--braking", "100m/s2",
                         "--covering-modulus", "3MPa", "--covering-poisson", "0.25", "--covering-thickness", "10mm",
                         "--robot-radius", "20mm", "--json")
    assert code == 0, err
    assert [row["covered_max_speed_m_per_s"] for row in json.loads(out)["rows"]] == \
        [row.covered_max_speed_m_per_s for row in braked]


def test_a_braking_robot_s_refusals_and_failures():
    with pytest.raises(ValueError, match="path exact"):
        covopt.simulate(Scene(braking=100, **COVERED), body_region="chest", method="exact")
    with pytest.raises(ValueError, match="robot.braking needs a robot that moves"):
        covopt.simulate(Scene(robot_mass="fixed", braking=100, **BARE), body_region="chest", contact_area="1cm2")
    with pytest.raises(ValueError, match=r"reaction_delay must be 0 \(brake at contact\) or in \[1e-06, 10\] s"):
        covopt.simulate(Scene(reaction_delay="20s", braking=100, **COVERED), body_region="chest")
    with pytest.raises(covopt.ComputationError) as error:
        covopt.simulate(Scene(braking=100, **COVERED), body_region="chest", method="time-path", max_steps=10)
    assert error.value.status == "step-limit"
