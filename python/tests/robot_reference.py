"""An independent reference for the reflected mass of a URDF chain, in plain numpy.

It shares nothing with covopt's C++ robot library (no urdfdom, no Orocos KDL): the URDF is
read with xml.etree, the kinematics are products of 4x4 transforms, and the joint-space
inertia matrix is summed link by link from the links' own masses and inertias,

    M(q) = sum_i ( m_i J_vi^T J_vi + J_wi^T R_i I_i R_i^T J_wi ),

with J_vi the linear Jacobian of link i's centre of mass, J_wi its angular Jacobian and
R_i I_i R_i^T its inertia tensor about the centre of mass in the base frame. The reflected
mass at a contact point along a unit direction u (base frame) is

    m_u = 1 / (u^T J_v M^-1 J_v^T u),

J_v the 3 x n linear Jacobian of the contact point; its largest and smallest values over
all directions are 1/lambda_min and 1/lambda_max of the 3 x 3 matrix J_v M^-1 J_v^T, along
the matching eigenvectors. A direction the chain cannot move the point in (lambda = 0) has
an infinite reflected mass.

Conventions (the URDF specification's): a joint's <origin xyz rpy> places the joint frame
in the parent link's frame, rpy = fixed-axis roll about x, pitch about y, yaw about z
(R = Rz(yaw) Ry(pitch) Rx(roll)); the axis is in the joint frame and is normalised; the child
link's frame is the joint frame moved by the joint (a rotation q about the axis, or a
translation q along it). An <inertial> <origin> places the centre of mass and the frame the
inertia tensor is written in. Only the links on the chain base -> tip count (the base link's
own mass does not move) and the links that hang off them (beyond the tip, or side branches),
rigidly, with any movable joint among those held at position 0 (covopt's documented rule);
joint rotor inertia is not modelled (URDF has no field for it).

Used by test_robot_crosscheck.py; not part of the covopt package.
"""

import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

import numpy as np

MOVABLE_JOINT_TYPES = ("revolute", "continuous", "prismatic")
SUPPORTED_JOINT_TYPES = MOVABLE_JOINT_TYPES + ("fixed",)

# u^T A u (or an eigenvalue of A) at or below this times A's largest eigenvalue: the chain
# cannot move the point that way, an infinite mass (the rule covopt documents, 1e-9).
SINGULAR_EIGENVALUE_RATIO = 1e-9


def rotation_from_rpy(roll, pitch, yaw):
    """R = Rz(yaw) Ry(pitch) Rx(roll), the URDF convention."""
    cr, sr = math.cos(roll), math.sin(roll)
    cp, sp = math.cos(pitch), math.sin(pitch)
    cy, sy = math.cos(yaw), math.sin(yaw)
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return rz @ ry @ rx


def rotation_about_axis(axis, angle):
    """Rodrigues' formula for a unit axis."""
    x, y, z = axis
    k = np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * (k @ k)


def transform(rotation, translation):
    t = np.eye(4)
    t[:3, :3] = rotation
    t[:3, 3] = translation
    return t


def _floats(text, count, what):
    values = [float(v) for v in text.split()]
    if len(values) != count:
        raise ValueError(f"{what}: expected {count} numbers, got {text!r}")
    return values


def _origin(element):
    """The 4x4 transform of an <origin> child of `element` (identity when absent)."""
    origin = element.find("origin") if element is not None else None
    if origin is None:
        return np.eye(4)
    xyz = _floats(origin.get("xyz", "0 0 0"), 3, "origin xyz")
    rpy = _floats(origin.get("rpy", "0 0 0"), 3, "origin rpy")
    return transform(rotation_from_rpy(*rpy), xyz)


@dataclass
class Inertial:
    mass_kg: float
    frame: np.ndarray  # 4x4: centre of mass and the tensor's axes, in the link frame
    tensor_kg_m2: np.ndarray  # 3x3 about the centre of mass, in `frame`'s axes


@dataclass
class Joint:
    name: str
    type: str
    parent: str
    child: str
    origin: np.ndarray  # 4x4, the joint frame in the parent link's frame
    axis: np.ndarray = field(default_factory=lambda: np.array([1.0, 0.0, 0.0]))


@dataclass
class UrdfModel:
    name: str
    links: dict  # link name -> Inertial or None
    joints: dict  # joint name -> Joint
    parent_joint: dict  # child link name -> Joint
    child_joints: dict  # parent link name -> [Joint]

    def root(self):
        roots = [name for name in self.links if name not in self.parent_joint]
        if len(roots) != 1:
            raise ValueError(f"the URDF has {len(roots)} root links: {roots}")
        return roots[0]

    def chain(self, base, tip):
        """The joints from base to tip, in order."""
        for link in (base, tip):
            if link not in self.links:
                raise ValueError(f"no link named {link!r}")
        joints = []
        link = tip
        while link != base:
            joint = self.parent_joint.get(link)
            if joint is None:
                raise ValueError(f"link {base!r} is not an ancestor of {tip!r}")
            joints.append(joint)
            link = joint.parent
        joints.reverse()
        for joint in joints:
            if joint.type not in SUPPORTED_JOINT_TYPES:
                raise ValueError(f"joint {joint.name!r} has unsupported type {joint.type!r}")
        return joints


def read_urdf(path):
    """Parse a URDF file into links (with their inertials) and joints."""
    robot = ET.parse(path).getroot()
    links = {}
    for link in robot.findall("link"):
        inertial = link.find("inertial")
        if inertial is None:
            links[link.get("name")] = None
            continue
        mass = float(inertial.find("mass").get("value"))
        i = inertial.find("inertia")
        ixx, ixy, ixz, iyy, iyz, izz = (float(i.get(k, "0"))
                                        for k in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"))
        tensor = np.array([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
        links[link.get("name")] = Inertial(mass, _origin(inertial), tensor)
    joints = {}
    parent_joint = {}
    child_joints = {}
    for j in robot.findall("joint"):
        axis_element = j.find("axis")
        axis = np.array(_floats(axis_element.get("xyz"), 3, "axis xyz")
                        if axis_element is not None else [1.0, 0.0, 0.0])
        axis = axis / np.linalg.norm(axis)
        joint = Joint(j.get("name"), j.get("type"), j.find("parent").get("link"),
                      j.find("child").get("link"), _origin(j), axis)
        joints[joint.name] = joint
        parent_joint[joint.child] = joint
        child_joints.setdefault(joint.parent, []).append(joint)
    return UrdfModel(robot.get("name"), links, joints, parent_joint, child_joints)


@dataclass
class ChainState:
    """Kinematics of a chain at one configuration, everything in the base frame."""
    joint_names: list
    link_frames: dict  # link name -> 4x4 pose
    axes: list  # per movable joint: unit axis
    axis_points: list  # per movable joint: a point on the axis
    prismatic: list  # per movable joint: True if prismatic
    movable_before: dict  # link name -> number of movable joints between base and the link
    tip_frame: np.ndarray
    locked_joint_names: list  # movable joints off the chain, held at 0


def forward_kinematics(model, base, tip, q):
    joints = model.chain(base, tip)
    movable = [j for j in joints if j.type in MOVABLE_JOINT_TYPES]
    q = np.asarray(q, dtype=float)
    if q.shape != (len(movable),):
        raise ValueError(f"{len(movable)} joint values needed, got {q.shape}")
    frames = {base: np.eye(4)}
    axes, points, prismatic, before = [], [], [], {base: 0}
    k = 0
    for joint in joints:
        joint_frame = frames[joint.parent] @ joint.origin
        if joint.type == "fixed":
            motion = np.eye(4)
        else:
            axes.append(joint_frame[:3, :3] @ joint.axis)
            points.append(joint_frame[:3, 3].copy())
            if joint.type == "prismatic":
                prismatic.append(True)
                motion = transform(np.eye(3), joint.axis * q[k])
            else:
                prismatic.append(False)
                motion = transform(rotation_about_axis(joint.axis, q[k]), np.zeros(3))
            k += 1
        frames[joint.child] = joint_frame @ motion
        before[joint.child] = k
    # Links off the chain hanging from a chain link after the base move with that link.
    on_chain = set(frames)
    locked = []
    pending = [link for link in frames if link != base]
    while pending:
        link = pending.pop()
        for joint in model.child_joints.get(link, []):
            if joint.child in on_chain:
                continue
            if joint.type in MOVABLE_JOINT_TYPES:
                locked.append(joint.name)
            frames[joint.child] = frames[link] @ joint.origin
            before[joint.child] = before[link]
            pending.append(joint.child)
    return ChainState([j.name for j in movable], frames, axes, points, prismatic, before,
                      frames[tip], sorted(locked))


def point_jacobians(state, link, point_in_base):
    """(J_v, J_w): the 3 x n linear and angular Jacobians of a point fixed to `link`."""
    n = len(state.axes)
    jv = np.zeros((3, n))
    jw = np.zeros((3, n))
    for k in range(state.movable_before[link]):
        if state.prismatic[k]:
            jv[:, k] = state.axes[k]
        else:
            jv[:, k] = np.cross(state.axes[k], point_in_base - state.axis_points[k])
            jw[:, k] = state.axes[k]
    return jv, jw


def joint_space_inertia(model, base, tip, q):
    """M(q), n x n, summed over the links after the base."""
    state = forward_kinematics(model, base, tip, q)
    n = len(state.axes)
    m = np.zeros((n, n))
    for link, frame in state.link_frames.items():
        inertial = model.links.get(link)
        if link == base or inertial is None:
            continue
        com_frame = frame @ inertial.frame
        jv, jw = point_jacobians(state, link, com_frame[:3, 3])
        r = com_frame[:3, :3]
        m += inertial.mass_kg * jv.T @ jv + jw.T @ (r @ inertial.tensor_kg_m2 @ r.T) @ jw
    return m


def contact_jacobian(model, base, tip, q, point=(0.0, 0.0, 0.0)):
    """(J_v, contact point in the base frame) for a point given in the tip link's frame."""
    state = forward_kinematics(model, base, tip, q)
    p = (state.tip_frame @ np.append(np.asarray(point, dtype=float), 1.0))[:3]
    jv, _ = point_jacobians(state, tip, p)
    return jv, p


def reflected_mass(urdf, tip, joints, base=None, point=(0.0, 0.0, 0.0), direction=None):
    """The reference answer with the keys of covopt.reflected_mass (math.inf for "fixed")."""
    model = read_urdf(urdf) if isinstance(urdf, str) else urdf
    base = base or model.root()
    state = forward_kinematics(model, base, tip, joints)
    m = joint_space_inertia(model, base, tip, joints)
    jv, p = contact_jacobian(model, base, tip, joints, point)
    a = jv @ np.linalg.solve(m, jv.T)
    a = 0.5 * (a + a.T)
    eigenvalues, eigenvectors = np.linalg.eigh(a)  # ascending
    lam_max = eigenvalues[-1]

    def mass_of(lam):
        if lam_max <= 0.0 or lam <= SINGULAR_EIGENVALUE_RATIO * lam_max:
            return math.inf
        return 1.0 / lam

    result = {
        "max_reflected_mass_kg": mass_of(eigenvalues[0]),
        "min_reflected_mass_kg": mass_of(eigenvalues[-1]),
        "max_direction": eigenvectors[:, 0],
        "min_direction": eigenvectors[:, -1],
        "contact_point_m": p,
        "joint_names": state.joint_names,
        "locked_joint_names": state.locked_joint_names,
        "joint_space_inertia": m,
        "contact_jacobian": jv,
    }
    if direction is not None:
        u = np.asarray(direction, dtype=float)
        u = u / np.linalg.norm(u)
        result["direction"] = u
        result["reflected_mass_kg"] = mass_of(float(u @ a @ u))
    return result


def link_point_motion(model, base, tip, q, qd, link, point):
    """A point fixed to any link of the chain base -> tip (or hanging off it) at a sample
    (q, q_dot): (position [m], velocity [m/s], reflected mass along the velocity [kg]), base
    frame. The mass uses the whole chain's M(q), every joint free: J_v has zero columns for
    the joints beyond the link. A point at rest (|v| <= 1e-9 m/s) has mass 0 (not computed),
    as covopt's ChainSampleKinematics."""
    state = forward_kinematics(model, base, tip, q)
    p = (state.link_frames[link] @ np.append(np.asarray(point, dtype=float), 1.0))[:3]
    jv, _ = point_jacobians(state, link, p)
    v = jv @ np.asarray(qd, dtype=float)
    speed = float(np.linalg.norm(v))
    if speed <= 1e-9:
        return p, v, 0.0
    u = v / speed
    m = joint_space_inertia(model, base, tip, q)
    return p, v, 1.0 / float(u @ jv @ np.linalg.solve(m, jv.T) @ u)


# The points of tests/robot/data/link_points_numpy.txt: (URDF file name in robot/models, tip,
# links, seed). Each link gets three points (its origin and two off it) at the named
# configuration ("ready") and at two random samples inside the joint limits.
LINK_POINT_CASES = [
    ("franka_fr3.urdf", "fr3_link8", ["fr3_link0", "fr3_link2", "fr3_link4", "fr3_link6", "fr3_link8"], 2505),
    ("ur5e.urdf", "tool0", ["base_link_inertia", "shoulder_link", "upper_arm_link", "forearm_link",
                            "wrist_2_link", "tool0"], 2506),
]
LINK_POINTS = [(0.0, 0.0, 0.0), (0.08, -0.03, 0.05), (-0.04, 0.1, -0.06)]
READY = {"franka_fr3.urdf": [0.0, -math.pi / 4, 0.0, -3 * math.pi / 4, 0.0, math.pi / 2, math.pi / 4],
         "ur5e.urdf": [0.0, -math.pi / 2, math.pi / 2, -math.pi / 2, -math.pi / 2, 0.0]}


def link_point_rows(models_dir):
    """The rows of tests/robot/data/link_points_numpy.txt, as lists of values: urdf, tip,
    link, n, q (n), q_dot (n), point (3), then position (3), velocity (3), reflected mass."""
    import os
    rows = []
    for urdf, tip, links, seed in LINK_POINT_CASES:
        path = os.path.join(models_dir, urdf)
        model = read_urdf(path)
        root = ET.parse(path).getroot()
        limits = {}
        for j in root.findall("joint"):
            limit = j.find("limit")
            if limit is not None:
                limits[j.get("name")] = (float(limit.get("lower")), float(limit.get("upper")),
                                         float(limit.get("velocity")))
        base = model.root()
        movable = [j.name for j in model.chain(base, tip) if j.type in MOVABLE_JOINT_TYPES]
        rng = np.random.default_rng(seed)
        samples = [(np.array(READY[urdf]), np.array([0.3 * (-1) ** k for k in range(len(movable))]))]
        for _ in range(2):
            lo = np.array([max(limits[j][0], -3.0) + 0.05 for j in movable])
            hi = np.array([min(limits[j][1], 3.0) - 0.05 for j in movable])
            speed = np.array([0.5 * limits[j][2] for j in movable])
            samples.append((rng.uniform(lo, hi), rng.uniform(-speed, speed)))
        for q, qd in samples:
            for link in links:
                for point in LINK_POINTS:
                    p, v, mass = link_point_motion(model, base, tip, q, qd, link, point)
                    rows.append([urdf, tip, link, len(movable), *q, *qd, *point, *p, *v, mass])
    return rows
