"""The reflected mass of a URDF chain, checked twice.

First the independent numpy reference (robot_reference.py: xml.etree, 4x4 transforms, the
joint-space inertia summed from the links' masses and inertias) against closed forms: a
planar 2-link arm (M, J_v, reflected mass, its singular stretched pose, a contact-point
offset, an inertia tensor in a turned frame), the same arm behind a fixed joint with a
turned origin, and a cart with a pendulum (prismatic and continuous joints). Its Jacobians
are checked against finite differences of its own forward kinematics, its M against the
kinetic energy of the links moving at numerically differentiated velocities, and the
shipped cobot models (robot/models) against the manufacturers' Denavit-Hartenberg tables.

Then covopt.reflected_mass (urdfdom + Orocos KDL) against that reference on both shipped
cobots at their named and at random configurations (fixed seed), several contact points
and directions, and on the test arms: masses to 1e-9 relative, directions to 1e-9, the
contact point to 1e-12 m; and covopt.contact_motion along the example FR3 trajectory
(velocity, speed, mass along the motion). Points on inner links (ChainSampleKinematics, C++
only) are checked by the C++ tests against tests/robot/data/link_points_numpy.txt, which the
last test here recomputes from the reference."""

import math
import os

import numpy as np
import pytest

import covopt
import robot_reference as ref

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, "data")
MODELS = os.path.join(HERE, os.pardir, os.pardir, "robot", "models")
FR3 = os.path.join(MODELS, "franka_fr3.urdf")
UR5E = os.path.join(MODELS, "ur5e.urdf")
PLANAR = os.path.join(DATA, "planar_2link.urdf")
PLANAR_MOUNTED = os.path.join(DATA, "planar_2link_mounted.urdf")
CART_PENDULUM = os.path.join(DATA, "cart_pendulum.urdf")

PI = math.pi
FR3_READY = [0.0, -PI / 4, 0.0, -3 * PI / 4, 0.0, PI / 2, PI / 4]
UR5E_READY = [0.0, -PI / 2, PI / 2, -PI / 2, -PI / 2, 0.0]
UR5E_UPRIGHT = [0.0, -PI / 2, 0.0, -PI / 2, 0.0, 0.0]  # singular at tool0

# The planar arm's numbers (python/tests/data/planar_2link.urdf).
L1, L2, M1, M2, LC1, LC2, I1, I2 = 0.5, 0.4, 3.0, 2.0, 0.25, 0.2, 0.07, 0.03


def planar_inertia(q2):
    c2 = math.cos(q2)
    m11 = M1 * LC1**2 + I1 + M2 * (L1**2 + LC2**2 + 2 * L1 * LC2 * c2) + I2
    m12 = M2 * (LC2**2 + L1 * LC2 * c2) + I2
    m22 = M2 * LC2**2 + I2
    return np.array([[m11, m12], [m12, m22]])


def planar_jacobian(q1, q2, length2=L2):
    s1, c1 = math.sin(q1), math.cos(q1)
    s12, c12 = math.sin(q1 + q2), math.cos(q1 + q2)
    return np.array([[-L1 * s1 - length2 * s12, -length2 * s12],
                     [L1 * c1 + length2 * c12, length2 * c12]])


def planar_reflected_mass(q1, q2, u_xy, length2=L2):
    j = planar_jacobian(q1, q2, length2)
    u = np.asarray(u_xy, dtype=float) / np.linalg.norm(u_xy)
    return 1.0 / (u @ j @ np.linalg.solve(planar_inertia(q2), j.T) @ u)


# ---------------------------------------------------------------- the reference itself

@pytest.mark.parametrize("q", [(0.0, 0.3), (0.7, -1.2), (-2.0, 2.5), (1.1, PI / 2)])
def test_reference_inertia_and_jacobian_of_the_planar_arm_are_the_closed_forms(q):
    model = ref.read_urdf(PLANAR)
    m = ref.joint_space_inertia(model, "world", "tool", q)
    np.testing.assert_allclose(m, planar_inertia(q[1]), rtol=1e-13, atol=1e-15)
    jv, p = ref.contact_jacobian(model, "world", "tool", q)
    np.testing.assert_allclose(jv[:2], planar_jacobian(*q), rtol=1e-13, atol=1e-15)
    np.testing.assert_array_equal(jv[2], 0.0)
    np.testing.assert_allclose(p[:2], [L1 * math.cos(q[0]) + L2 * math.cos(q[0] + q[1]),
                                       L1 * math.sin(q[0]) + L2 * math.sin(q[0] + q[1])],
                               atol=1e-15)


@pytest.mark.parametrize("q", [(0.0, 0.3), (0.7, -1.2), (-2.0, 2.5)])
def test_reference_reflected_mass_of_the_planar_arm_is_the_closed_form(q):
    for angle in np.linspace(0.0, PI, 7):
        u = (math.cos(angle), math.sin(angle), 0.0)
        r = ref.reflected_mass(PLANAR, "tool", q, direction=u)
        assert r["reflected_mass_kg"] == pytest.approx(planar_reflected_mass(*q, u[:2]),
                                                       rel=1e-12)
    # Out of the plane the arm cannot move: infinite, and that is the largest.
    r = ref.reflected_mass(PLANAR, "tool", q, direction=(0.0, 0.0, 1.0))
    assert r["reflected_mass_kg"] == math.inf
    assert r["max_reflected_mass_kg"] == math.inf
    assert abs(r["max_direction"][2]) == pytest.approx(1.0)
    # The smallest is the in-plane 2x2 problem's.
    j = planar_jacobian(*q)
    lam = np.linalg.eigvalsh(j @ np.linalg.solve(planar_inertia(q[1]), j.T))
    assert r["min_reflected_mass_kg"] == pytest.approx(1.0 / lam[-1], rel=1e-12)


def test_reference_stretched_planar_arm_is_fixed_along_the_arm_and_finite_across():
    q = (0.4, 0.0)
    along = (math.cos(0.4), math.sin(0.4), 0.0)
    across = (-math.sin(0.4), math.cos(0.4), 0.0)
    assert ref.reflected_mass(PLANAR, "tool", q, direction=along)["reflected_mass_kg"] == math.inf
    r = ref.reflected_mass(PLANAR, "tool", q, direction=across)
    assert r["reflected_mass_kg"] == pytest.approx(planar_reflected_mass(*q, across[:2]),
                                                   rel=1e-12)
    assert r["min_reflected_mass_kg"] == pytest.approx(r["reflected_mass_kg"], rel=1e-12)


def test_reference_contact_point_offset_is_a_longer_last_link():
    # The tool frame is link 2's turned +pi/2 about z: tool -y is link 2 +x.
    q, d = (0.3, 0.9), 0.15
    u = (0.6, -0.8, 0.0)
    r = ref.reflected_mass(PLANAR, "tool", q, point=(0.0, -d, 0.0), direction=u)
    assert r["reflected_mass_kg"] == pytest.approx(
        planar_reflected_mass(*q, u[:2], length2=L2 + d), rel=1e-12)
    np.testing.assert_allclose(
        r["contact_point_m"][:2],
        [L1 * math.cos(0.3) + (L2 + d) * math.cos(1.2), L1 * math.sin(0.3) + (L2 + d) * math.sin(1.2)],
        atol=1e-15)


def test_reference_counts_links_beyond_the_tip_as_payload_locked_at_zero():
    # Tip link1: link 2 rides on it, straight (elbow held at 0), a rigid body of link 1.
    q1 = 0.6
    m11 = M1 * LC1**2 + I1 + M2 * (L1 + LC2)**2 + I2
    across = (-math.sin(q1), math.cos(q1), 0.0)
    r = ref.reflected_mass(PLANAR, "link1", [q1], point=(L1, 0.0, 0.0), direction=across)
    assert r["joint_names"] == ["shoulder"]
    assert r["locked_joint_names"] == ["elbow"]
    np.testing.assert_allclose(r["joint_space_inertia"], [[m11]], rtol=1e-13)
    assert r["reflected_mass_kg"] == pytest.approx(m11 / L1**2, rel=1e-12)


def test_reference_arm_behind_a_turned_fixed_joint_turns_its_directions():
    mount = ref.rotation_from_rpy(PI / 2, 0.0, 0.3)
    q = (0.7, -1.2)
    for u_local in [(1.0, 0.0, 0.0), (0.6, 0.8, 0.0), (0.0, 0.0, 1.0), (0.3, -0.2, 0.5)]:
        flat = ref.reflected_mass(PLANAR, "tool", q, direction=u_local)
        mounted = ref.reflected_mass(PLANAR_MOUNTED, "tool", q, direction=mount @ u_local)
        assert mounted["reflected_mass_kg"] == pytest.approx(flat["reflected_mass_kg"], rel=1e-12)
    np.testing.assert_allclose(mounted["contact_point_m"],
                               [0.1, -0.2, 0.3] + mount @ flat["contact_point_m"], atol=1e-15)
    # The stand's 50 kg is on the base side of every joint: it does not count.
    np.testing.assert_allclose(ref.joint_space_inertia(ref.read_urdf(PLANAR_MOUNTED), "world",
                                                       "tool", q),
                               planar_inertia(q[1]), rtol=1e-13)


@pytest.mark.parametrize("theta", [0.0, 0.7, -2.2])
def test_reference_cart_pendulum_with_prismatic_and_continuous_joints_is_the_closed_form(theta):
    mc, mp, r, ip, length = 5.0, 1.5, 0.3, 0.02, 0.6
    s, c = math.sin(theta), math.cos(theta)
    m = np.array([[mc + mp, -mp * r * s], [-mp * r * s, mp * r**2 + ip]])
    j = np.array([[1.0, -length * s], [0.0, length * c]])
    model = ref.read_urdf(CART_PENDULUM)
    q = (0.25, theta)
    np.testing.assert_allclose(ref.joint_space_inertia(model, "rail", "tip", q), m, rtol=1e-13)
    for u in [(1.0, 0.0), (0.0, 1.0), (0.6, 0.8)]:
        expected = 1.0 / (np.array(u) @ j @ np.linalg.solve(m, j.T) @ np.array(u))
        got = ref.reflected_mass(CART_PENDULUM, "tip", q, direction=(*u, 0.0))
        assert got["reflected_mass_kg"] == pytest.approx(expected, rel=1e-12)
    if theta == 0.0:  # along the rail the whole 6.5 kg moves; across, the pendulum's inertia
        assert ref.reflected_mass(CART_PENDULUM, "tip", q, direction=(1, 0, 0))[
            "reflected_mass_kg"] == pytest.approx(mc + mp, rel=1e-12)


@pytest.mark.parametrize("urdf, base, tip, n", [(FR3, "base", "fr3_link8", 7),
                                                (UR5E, "base_link", "tool0", 6)],
                         ids=["fr3", "ur5e"])
def test_reference_jacobians_are_finite_differences_of_its_kinematics(urdf, base, tip, n):
    model = ref.read_urdf(urdf)
    rng = np.random.default_rng(12)
    point = np.array([0.03, -0.02, 0.05])
    for _ in range(3):
        q = rng.uniform(-2.0, 2.0, n)
        jv, _ = ref.contact_jacobian(model, base, tip, q, point)
        h = 1e-6
        numeric = np.empty((3, n))
        for k in range(n):
            dq = np.zeros(n)
            dq[k] = h
            numeric[:, k] = (ref.contact_jacobian(model, base, tip, q + dq, point)[1]
                             - ref.contact_jacobian(model, base, tip, q - dq, point)[1]) / (2 * h)
        np.testing.assert_allclose(jv, numeric, atol=1e-8)
        m = ref.joint_space_inertia(model, base, tip, q)
        np.testing.assert_allclose(m, m.T, atol=1e-15)
        assert np.linalg.eigvalsh(m)[0] > 0.0


def _kinetic_energy_by_finite_differences(model, base, tip, q, qdot, h=1e-6):
    """Sum over links of (m v^2 + w^T I w) / 2, v and w from central differences of poses."""
    before = ref.forward_kinematics(model, base, tip, q - h * qdot).link_frames
    after = ref.forward_kinematics(model, base, tip, q + h * qdot).link_frames
    now = ref.forward_kinematics(model, base, tip, q).link_frames
    energy = 0.0
    for link, frame in now.items():
        inertial = model.links.get(link)
        if link == base or inertial is None:
            continue
        com_before, com_after, com_now = (f @ inertial.frame for f in (before[link],
                                                                      after[link], frame))
        v = (com_after[:3, 3] - com_before[:3, 3]) / (2 * h)
        w_hat = (com_after[:3, :3] - com_before[:3, :3]) / (2 * h) @ com_now[:3, :3].T
        w = 0.5 * np.array([w_hat[2, 1] - w_hat[1, 2], w_hat[0, 2] - w_hat[2, 0],
                            w_hat[1, 0] - w_hat[0, 1]])
        r = com_now[:3, :3]
        energy += 0.5 * (inertial.mass_kg * v @ v + w @ r @ inertial.tensor_kg_m2 @ r.T @ w)
    return energy


@pytest.mark.parametrize("urdf, base, tip, n", [(FR3, "base", "fr3_link8", 7),
                                                (UR5E, "base_link", "tool0", 6),
                                                (CART_PENDULUM, "rail", "tip", 2)],
                         ids=["fr3", "ur5e", "cart-pendulum"])
def test_reference_inertia_matrix_is_the_kinetic_energy_of_the_moving_links(urdf, base, tip, n):
    # M from the Jacobian sum against M from link velocities differentiated numerically:
    # q_dot^T M q_dot = 2 T(q, q_dot), polarised for the off-diagonal terms.
    model = ref.read_urdf(urdf)
    q = np.random.default_rng(5).uniform(-1.5, 1.5, n)
    m = ref.joint_space_inertia(model, base, tip, q)
    eye = np.eye(n)
    diagonal = [2 * _kinetic_energy_by_finite_differences(model, base, tip, q, eye[i])
                for i in range(n)]
    numeric = np.diag(diagonal)
    for i in range(n):
        for j in range(i + 1, n):
            both = 2 * _kinetic_energy_by_finite_differences(model, base, tip, q, eye[i] + eye[j])
            numeric[i, j] = numeric[j, i] = 0.5 * (both - diagonal[i] - diagonal[j])
    np.testing.assert_allclose(numeric, m, rtol=1e-6, atol=1e-8 * np.abs(m).max())


def _craig(a, alpha, d, theta):
    return (ref.transform(ref.rotation_from_rpy(alpha, 0, 0), [a, 0, 0])
            @ ref.transform(ref.rotation_from_rpy(0, 0, theta), [0, 0, d]))


def _standard_dh(d, a, alpha, theta):
    return (ref.transform(ref.rotation_from_rpy(0, 0, theta), [0, 0, d])
            @ ref.transform(ref.rotation_from_rpy(alpha, 0, 0), [a, 0, 0]))


def test_shipped_fr3_flange_is_where_franka_dh_table_puts_it():
    # Craig convention (a_{i-1}, alpha_{i-1}, d_i), Franka's FCI documentation.
    table = [(0, 0, 0.333), (0, -PI / 2, 0), (0, PI / 2, 0.316), (0.0825, PI / 2, 0),
             (-0.0825, -PI / 2, 0.384), (0, PI / 2, 0), (0.088, PI / 2, 0)]
    model = ref.read_urdf(FR3)
    rng = np.random.default_rng(3)
    for q in [FR3_READY] + [rng.uniform(-2.5, 2.5, 7) for _ in range(5)]:
        t = np.eye(4)
        for (a, alpha, d), theta in zip(table, q):
            t = t @ _craig(a, alpha, d, theta)
        t = t @ _craig(0, 0, 0.107, 0)
        np.testing.assert_allclose(ref.forward_kinematics(model, "base", "fr3_link8", q).tip_frame,
                                   t, atol=1e-14)


def test_shipped_ur5e_wrist_3_is_where_the_ur_dh_table_puts_it():
    # Standard DH (d_i, a_i, alpha_i), UR's article; base_link is UR's base turned pi about z.
    table = [(0.1625, 0, PI / 2), (0, -0.425, 0), (0, -0.3922, 0), (0.1333, 0, PI / 2),
             (0.0997, 0, -PI / 2), (0.0996, 0, 0)]
    model = ref.read_urdf(UR5E)
    rng = np.random.default_rng(4)
    for q in [UR5E_READY] + [rng.uniform(-PI, PI, 6) for _ in range(5)]:
        t = ref.transform(ref.rotation_from_rpy(0, 0, PI), [0, 0, 0])
        for (d, a, alpha), theta in zip(table, q):
            t = t @ _standard_dh(d, a, alpha, theta)
        state = ref.forward_kinematics(model, "base_link", "tool0", q)
        np.testing.assert_allclose(state.link_frames["wrist_3_link"], t, atol=1e-14)
        np.testing.assert_allclose(state.tip_frame[:3, 3], t[:3, 3], atol=1e-14)


def test_reference_ur5e_upright_pose_moves_tool0_along_one_axis_only():
    r = ref.reflected_mass(UR5E, "tool0", UR5E_UPRIGHT, direction=(0.0, 1.0, 0.0))
    assert r["reflected_mass_kg"] == math.inf
    assert r["max_reflected_mass_kg"] == math.inf
    assert math.isfinite(r["min_reflected_mass_kg"])
    assert abs(r["min_direction"][0]) == pytest.approx(1.0, abs=1e-12)


# ------------------------------------------------------- covopt against the reference

def _mass(value):
    """covopt writes an infinite mass as "fixed"."""
    return math.inf if value == "fixed" else float(value)


def _assert_same_mass(got, expected):
    got = _mass(got)
    if math.isinf(expected):
        assert math.isinf(got), f"covopt {got} kg, reference infinite"
    else:
        assert got == pytest.approx(expected, rel=1e-9)


def _assert_same_axis(got, expected):
    """Unit directions equal up to sign."""
    got = np.asarray(got, dtype=float)
    assert np.linalg.norm(got) == pytest.approx(1.0, abs=1e-12)
    assert abs(float(got @ expected)) == pytest.approx(1.0, abs=1e-9)


def _eigenvalue_gaps_are_clear(reference):
    """Directions are comparable only for well separated eigenvalues."""
    a = reference["contact_jacobian"] @ np.linalg.solve(reference["joint_space_inertia"],
                                                        reference["contact_jacobian"].T)
    lam = np.linalg.eigvalsh(0.5 * (a + a.T))
    return min(lam[1] - lam[0], lam[2] - lam[1]) > 1e-6 * lam[2]


def _compare(urdf, tip, q, point, direction, base=None):
    expected = ref.reflected_mass(urdf, tip, q, base=base, point=point, direction=direction)
    got = covopt.reflected_mass(urdf, tip, list(q), base=base, point=tuple(point),
                                direction=tuple(direction)).to_dict()
    assert list(got["joint_names"]) == expected["joint_names"]
    np.testing.assert_allclose(got["contact_point_m"], expected["contact_point_m"], rtol=1e-12,
                               atol=1e-12)
    _assert_same_mass(got["reflected_mass_kg"], expected["reflected_mass_kg"])
    _assert_same_mass(got["max_reflected_mass_kg"], expected["max_reflected_mass_kg"])
    _assert_same_mass(got["min_reflected_mass_kg"], expected["min_reflected_mass_kg"])
    if _eigenvalue_gaps_are_clear(expected):
        _assert_same_axis(got["max_direction"], expected["max_direction"])
        _assert_same_axis(got["min_direction"], expected["min_direction"])
    return got, expected


def _cobot_cases():
    rng = np.random.default_rng(20261123)
    fr3_lower = np.array([-2.7437, -1.7837, -2.9007, -3.0421, -2.8065, 0.5445, -3.0159])
    fr3_upper = np.array([2.7437, 1.7837, 2.9007, -0.1518, 2.8065, 4.5169, 3.0159])
    cases = [("fr3-ready", FR3, "fr3_link8", FR3_READY),
             ("ur5e-ready", UR5E, "tool0", UR5E_READY)]
    for k in range(4):
        cases.append((f"fr3-random{k}", FR3, "fr3_link8",
                      list(rng.uniform(fr3_lower + 0.1, fr3_upper - 0.1))))
        cases.append((f"ur5e-random{k}", UR5E, "tool0", list(rng.uniform(-PI, PI, 6))))
    return cases


COBOT_CASES = _cobot_cases()
POINTS = [(0.0, 0.0, 0.0), (0.02, -0.035, 0.06)]
DIRECTIONS = [(1.0, 0.0, 0.0), (0.0, 0.0, -1.0), (0.3, -0.5, 0.8)]


@pytest.mark.parametrize("name, urdf, tip, q", COBOT_CASES, ids=[c[0] for c in COBOT_CASES])
def test_covopt_reflected_mass_of_the_shipped_cobots_agrees_with_the_reference(name, urdf, tip, q):
    for point in POINTS:
        for direction in DIRECTIONS:
            _compare(urdf, tip, q, point, direction)


def test_covopt_agrees_on_an_inner_link_and_a_base_other_than_the_root():
    # Tip fr3_link4: links 5 to 8 ride on it with joints 5 to 7 held at 0, in both.
    got, expected = _compare(FR3, "fr3_link4", FR3_READY[:4], (0.0, 0.05, 0.0), (0.0, 1.0, 0.0))
    assert expected["locked_joint_names"] == ["fr3_joint5", "fr3_joint6", "fr3_joint7"]
    assert any(all(name in w for name in expected["locked_joint_names"])
               for w in got["warnings"])
    _compare(PLANAR, "link1", [0.6], (L1, 0.0, 0.0), (0.0, 1.0, 0.0))
    _compare(UR5E, "tool0", UR5E_READY, (0.0, 0.0, 0.1), (1.0, 1.0, 0.0),
             base="base_link_inertia")


def test_covopt_agrees_on_the_test_arms_closed_forms():
    for q in [(0.0, 0.3), (0.7, -1.2), (-2.0, 2.5)]:
        got, _ = _compare(PLANAR, "tool", q, (0.0, -0.1, 0.0), (0.6, 0.8, 0.0))
        assert _mass(got["max_reflected_mass_kg"]) == math.inf  # out of the plane
        _compare(PLANAR_MOUNTED, "tool", q, (0.0, 0.0, 0.0),
                 tuple(ref.rotation_from_rpy(PI / 2, 0.0, 0.3) @ [0.6, 0.8, 0.0]))
    for theta in [0.0, 0.7, -2.2]:
        _compare(CART_PENDULUM, "tip", (0.25, theta), (0.0, 0.0, 0.0), (0.6, 0.8, 0.0))


def test_covopt_calls_singular_directions_fixed_with_a_warning():
    got, _ = _compare(PLANAR, "tool", (0.4, 0.0), (0.0, 0.0, 0.0),
                      (math.cos(0.4), math.sin(0.4), 0.0))
    assert got["reflected_mass_kg"] == "fixed" and got["max_reflected_mass_kg"] == "fixed"
    assert got["warnings"]
    got, _ = _compare(UR5E, "tool0", UR5E_UPRIGHT, (0.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    assert got["reflected_mass_kg"] == "fixed"
    assert got["warnings"]


def test_covopt_contact_motion_along_the_example_trajectory_agrees_with_the_reference():
    # robot/models/franka_fr3_pick.csv: per sample the point's velocity J_v q_dot, its speed,
    # and the reflected mass along the motion (at rest: the largest over all directions).
    csv = os.path.join(MODELS, "franka_fr3_pick.csv")
    with open(csv, encoding="utf-8") as lines:
        data = [line for line in lines if line.strip() and not line.startswith("#")]
    rows = np.array([[float(x) for x in line.split(",")] for line in data[1:]])  # no header
    point = (0.0, 0.0, 0.05)
    got = covopt.contact_motion(FR3, "fr3_link8", csv, point=point)
    assert list(got.joint_names) == [f"fr3_joint{k}" for k in range(1, 8)]
    assert len(got.samples) == len(rows)
    model = ref.read_urdf(FR3)
    for row, sample in zip(rows, got.samples):
        q, qdot = row[1:8], row[8:15]
        jv, p = ref.contact_jacobian(model, "base", "fr3_link8", q, point)
        velocity = jv @ qdot
        speed = float(np.linalg.norm(velocity))
        assert sample.time_s == row[0]
        np.testing.assert_allclose(sample.contact_point_m, p, atol=1e-12)
        np.testing.assert_allclose(sample.velocity_m_per_s, velocity, rtol=1e-9, atol=1e-13)
        assert sample.speed_m_per_s == pytest.approx(speed, rel=1e-9, abs=1e-13)
        if speed > 1e-6:
            expected = ref.reflected_mass(model, "fr3_link8", q, point=point, direction=velocity)
            _assert_same_mass(sample.reflected_mass_kg, expected["reflected_mass_kg"])
        elif not sample.moving:
            expected = ref.reflected_mass(model, "fr3_link8", q, point=point)
            _assert_same_mass(sample.reflected_mass_kg, expected["max_reflected_mass_kg"])


def test_link_points_file_is_what_the_numpy_reference_gives():
    """tests/robot/data/link_points_numpy.txt (the numbers the C++ ChainSampleKinematics test
    holds covopt to, points on several links of both cobots) is still the reference's: every
    row recomputed here, the velocity also against finite differences of the reference's own
    positions."""
    path = os.path.join(HERE, os.pardir, os.pardir, "tests", "robot", "data", "link_points_numpy.txt")
    with open(path) as f:
        stored = [line.split() for line in f if line.strip() and not line.startswith("#")]
    expected = ref.link_point_rows(MODELS)
    assert len(stored) == len(expected) == 99
    models = {}
    for row, want in zip(stored, expected):
        assert row[:4] == [str(x) for x in want[:4]]
        np.testing.assert_allclose([float(x) for x in row[4:]], want[4:], rtol=1e-12, atol=1e-15)
        urdf, tip, link, n = want[0], want[1], want[2], want[3]
        model = models.setdefault(urdf, ref.read_urdf(os.path.join(MODELS, urdf)))
        q, qd, point = (np.array(want[4:4 + n]), np.array(want[4 + n:4 + 2 * n]),
                        want[4 + 2 * n:7 + 2 * n])
        h = 1e-6
        ahead, _, _ = ref.link_point_motion(model, model.root(), tip, q + h * qd, qd, link, point)
        behind, _, _ = ref.link_point_motion(model, model.root(), tip, q - h * qd, qd, link, point)
        np.testing.assert_allclose((ahead - behind) / (2 * h), want[10 + 2 * n:13 + 2 * n], atol=1e-8)
    # Every joint free: on a link before the tip the mass is at most the one with the outer
    # joints locked where they are, 1/(u' J_k (M_kk)^-1 J_k' u), since (M^-1)_kk >= (M_kk)^-1
    # (a Schur complement); strictly below it where the outer joints couple.
    fr3 = models["franka_fr3.urdf"]
    below = 0
    for want in expected:
        if want[0] == "franka_fr3.urdf" and want[2] == "fr3_link4" and want[-1] > 0:
            n = want[3]
            q = np.array(want[4:4 + n])
            v = np.array(want[10 + 2 * n:13 + 2 * n])
            u = v / np.linalg.norm(v)
            state = ref.forward_kinematics(fr3, fr3.root(), "fr3_link8", q)
            jv, _ = ref.point_jacobians(state, "fr3_link4", np.array(want[7 + 2 * n:10 + 2 * n]))
            m = ref.joint_space_inertia(fr3, fr3.root(), "fr3_link8", q)
            locked = 1.0 / (u @ jv[:, :4] @ np.linalg.solve(m[:4, :4], jv[:, :4].T) @ u)
            assert want[-1] <= locked * (1 + 1e-12)
            below += want[-1] < 0.99 * locked
    assert below >= 3
