#!/usr/bin/env python3
"""Writes robot/models/ur5e_surface.toml: capsules enclosing the UR5e's collision meshes, the
surface file (robot/README.md, "Surface files") of robot/models/ur5e.urdf, whose links have no
collision geometry of their own.

Source: Universal Robots' ROS 2 description, github.com/UniversalRobots/
Universal_Robots_ROS2_Description at commit 2221ec0 (release 2.4.5), BSD-3-Clause
(Copyright Universal Robots A/S and contributors): the binary STL collision meshes
meshes/ur5e/collision/{shoulder,upperarm,forearm,wrist1,wrist2,wrist3}.stl, placed in each
link's frame by the <collision><origin> of urdf/ur_macro.xacro with the offsets of
config/ur5e/physical_parameters.yaml (shoulder_offset 0.138 m, elbow_offset 0.007 m) and
config/ur5e/visual_parameters.yaml (visual_offset of wrist 1, 2, 3: -0.127, -0.0997,
-0.0989 m); MESH_PLACEMENT below copies them. The meshes themselves are not in covopt: get
them from that repository at that commit and give their directory.

The fit. Each link's capsules have axes chosen from the arm's build (MESH_PLACEMENT's
neighbours, AXES below): the joint housings turn about the joint axes (z of the link frame,
and the next joint's axis), the upper arm's and forearm's tubes run along x at the
shoulder/elbow offset. The mesh triangles are covered with points (a barycentric grid of
FIT_SPACING_M, 2 mm; the corners included); every point goes to the nearest axis line; each
capsule's radius is the largest distance of its points from its axis, and its end points are
the shortest segment on that line within which every one of its points lies within the
radius: for a point at axial position t and distance d, a <= t + sqrt(r^2 - d^2) and
b >= t - sqrt(r^2 - d^2). So every grid point is inside (or on) a capsule, and, capsules
being convex, every grid cell whose corners share a capsule: the capsules enclose the meshes,
as Franka's capsules enclose its arm. Radii are rounded up and end points out to 0.1 mm.
The script then checks the corners, edge midpoints and centroid of every mesh triangle
against the rounded capsules and writes the largest distance of any of them outside into the
file's header (0 when all are inside).

    /usr/bin/python3 scripts/fit-ur5e-capsules.py MESH_DIR [OUTPUT.toml]

MESH_DIR: the repository's meshes/ur5e/collision at 2221ec0. OUTPUT: default
robot/models/ur5e_surface.toml. numpy only; the same meshes give the same file.
"""

import math
import pathlib
import sys

import numpy as np

SOURCE = ("github.com/UniversalRobots/Universal_Robots_ROS2_Description, commit 2221ec0 "
          "(2.4.5), BSD-3-Clause, Copyright Universal Robots A/S and contributors")
PI = math.pi

# link -> (mesh file, collision origin xyz, rpy) from urdf/ur_macro.xacro at 2221ec0.
MESH_PLACEMENT = {
    "shoulder_link": ("shoulder.stl", (0.0, 0.0, 0.0), (0.0, 0.0, PI)),
    "upper_arm_link": ("upperarm.stl", (0.0, 0.0, 0.138), (PI / 2, 0.0, -PI / 2)),
    "forearm_link": ("forearm.stl", (0.0, 0.0, 0.007), (PI / 2, 0.0, -PI / 2)),
    "wrist_1_link": ("wrist1.stl", (0.0, 0.0, -0.127), (PI / 2, 0.0, 0.0)),
    "wrist_2_link": ("wrist2.stl", (0.0, 0.0, -0.0997), (0.0, 0.0, 0.0)),
    "wrist_3_link": ("wrist3.stl", (0.0, 0.0, -0.0989), (PI / 2, 0.0, 0.0)),
}

# link -> [(what, a point on the axis, axis direction)], link frame (robot/models/ur5e.urdf):
# z of each link frame is its joint's axis; the next joint's axis is y of the shoulder and
# wrist links (the joint origins' rpy of +-pi/2 about x); the tubes run along x at the
# shoulder (0.138 m) and elbow (0.007 m) offsets; the elbow and wrist 1 axes are at
# x = -0.425 m and x = -0.3922 m of the upper arm and forearm.
AXES = {
    "shoulder_link": [("shoulder pan housing (joint 1 axis)", (0, 0, 0), (0, 0, 1)),
                      ("shoulder lift housing (joint 2 axis)", (0, 0, 0), (0, 1, 0))],
    "upper_arm_link": [("shoulder housing (joint 2 axis)", (0, 0, 0), (0, 0, 1)),
                       ("upper arm tube", (0, 0, 0.138), (1, 0, 0)),
                       ("elbow housing (joint 3 axis)", (-0.425, 0, 0), (0, 0, 1))],
    "forearm_link": [("elbow housing (joint 3 axis)", (0, 0, 0), (0, 0, 1)),
                     ("forearm tube", (0, 0, 0.007), (1, 0, 0)),
                     ("wrist 1 housing (joint 4 axis)", (-0.3922, 0, 0), (0, 0, 1))],
    "wrist_1_link": [("wrist 1 housing (joint 4 axis)", (0, 0, 0), (0, 0, 1)),
                     ("wrist 2 housing (joint 5 axis)", (0, 0, 0), (0, 1, 0))],
    "wrist_2_link": [("wrist 2 housing (joint 5 axis)", (0, 0, 0), (0, 0, 1)),
                     ("wrist 3 housing (joint 6 axis)", (0, 0, 0), (0, 1, 0))],
    "wrist_3_link": [("flange disc (joint 6 axis)", (0, 0, 0), (0, 0, 1))],
}

ROUND_M = 1e-4  # radii rounded up, end points out, to 0.1 mm
FIT_SPACING_M = 2e-3  # the grid of points on each mesh triangle that the capsules enclose


def rotation_from_rpy(roll, pitch, yaw):
    """R = Rz(yaw) Ry(pitch) Rx(roll), the URDF convention."""
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch),
                              math.cos(yaw), math.sin(yaw))
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return rz @ ry @ rx


def read_binary_stl(path):
    """The triangles of a binary STL, shape (n, 3, 3) [file units: metres for these meshes]."""
    data = pathlib.Path(path).read_bytes()
    count = int.from_bytes(data[80:84], "little")
    if len(data) != 84 + 50 * count:
        raise ValueError(f"{path}: not a binary STL of {count} triangles ({len(data)} bytes)")
    record = np.dtype([("normal", "<f4", 3), ("vertices", "<f4", (3, 3)), ("attribute", "<u2")])
    return np.frombuffer(data[84:], dtype=record, count=count)["vertices"].astype(float)


def surface_points(triangles, spacing_m):
    """Points on every triangle: a barycentric grid whose cells' edges are at most spacing_m
    (each triangle's corners included)."""
    chunks = []
    longest = np.max(np.linalg.norm(triangles - np.roll(triangles, 1, axis=1), axis=2), axis=1)
    divisions = np.maximum(1, np.ceil(longest / spacing_m)).astype(int)
    for k in np.unique(divisions):
        grid = np.array([(i, j, k - i - j) for i in range(k + 1) for j in range(k + 1 - i)], float) / k
        chunks.append(np.einsum("gc,tcx->tgx", grid, triangles[divisions == k]).reshape(-1, 3))
    return np.unique(np.concatenate(chunks), axis=0)


def axial_and_radial(points, origin, direction):
    """Each point's position t along the axis line and its distance d from it."""
    relative = points - origin
    t = relative @ direction
    d = np.linalg.norm(relative - np.outer(t, direction), axis=1)
    return t, d


def fit_capsule(points, origin, direction):
    """The enclosing capsule on the given axis line: (a, b, r), a and b on the line."""
    t, d = axial_and_radial(points, origin, direction)
    r = math.ceil(d.max() / ROUND_M) * ROUND_M + ROUND_M  # the rounding of the ends below
    reach = np.sqrt(np.maximum(r * r - d * d, 0.0))
    lo, hi = (t + reach).min(), (t - reach).max()
    if lo > hi:  # every point within r of one point of the line: a sphere
        lo = hi = 0.5 * (lo + hi)
    lo = math.floor(lo / ROUND_M) * ROUND_M
    hi = math.ceil(hi / ROUND_M) * ROUND_M
    return origin + lo * direction, origin + hi * direction, r


def distance_outside(points, capsules):
    """max over points of min over capsules of (distance to the segment - radius) [m]."""
    best = np.full(len(points), np.inf)
    for a, b, r in capsules:
        ab = b - a
        length2 = ab @ ab
        s = np.zeros(len(points)) if length2 == 0 else np.clip((points - a) @ ab / length2, 0.0, 1.0)
        best = np.minimum(best, np.linalg.norm(points - (a + np.outer(s, ab)), axis=1) - r)
    return best.max()


def number(x):
    text = f"{x:.4f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__)
    mesh_dir = pathlib.Path(sys.argv[1])
    output = pathlib.Path(sys.argv[2]) if len(sys.argv) == 3 else (
        pathlib.Path(__file__).resolve().parent.parent / "robot" / "models" / "ur5e_surface.toml")
    blocks = []
    worst = 0.0
    for link, (mesh, xyz, rpy) in MESH_PLACEMENT.items():
        triangles = read_binary_stl(mesh_dir / mesh) @ rotation_from_rpy(*rpy).T + np.array(xyz)
        vertices = surface_points(triangles, FIT_SPACING_M)
        axes = [(what, np.array(p, float), np.array(u, float) / np.linalg.norm(u)) for what, p, u in AXES[link]]
        distances = np.stack([axial_and_radial(vertices, p, u)[1] for _, p, u in axes])
        nearest = distances.argmin(axis=0)
        capsules, lines = [], []
        for k, (what, p, u) in enumerate(axes):
            a, b, r = fit_capsule(vertices[nearest == k], p, u)
            capsules.append((a, b, r))
            lines.append(f"  {{ from_m = [{', '.join(number(x) for x in a)}], "
                         f"to_m = [{', '.join(number(x) for x in b)}], radius_m = {number(r)} }},"
                         f"  # {what}")
        # Corners, edge midpoints and centroids of every triangle.
        checks = np.concatenate([triangles.reshape(-1, 3),
                                 0.5 * (triangles + np.roll(triangles, 1, axis=1)).reshape(-1, 3),
                                 triangles.mean(axis=1)])
        outside = distance_outside(checks, capsules)
        worst = max(worst, outside)
        low, high = vertices.min(axis=0), vertices.max(axis=0)
        blocks.append(
            f"# {link}: meshes/ur5e/collision/{mesh}, {len(triangles)} triangles, at xyz "
            f"({', '.join(number(x) for x in xyz)}) rpy ({', '.join(f'{x:.6g}' for x in rpy)}); mesh box "
            f"[{', '.join(number(x) for x in low)}] .. [{', '.join(number(x) for x in high)}] m;\n"
            f"# largest distance of a triangle point outside the capsules: {max(outside, 0.0) * 1e3:.2f} mm\n"
            f"[[link]]\nname = \"{link}\"\nsegments = [\n" + "\n".join(lines) + "\n]\n")
        print(f"{link}: {len(capsules)} capsules, radii "
              f"{', '.join(number(r) for _, _, r in capsules)} m; outside at most {max(outside, 0.0) * 1e3:.2f} mm")
    header = (
        "# The UR5e's surface for covopt (robot/models/ur5e.urdf has no collision geometry):\n"
        "# capsules enclosing Universal Robots' collision meshes, per moving link, in the link\n"
        "# frames of ur5e.urdf (the ROS description's). Lengths in metres.\n"
        f"# Source: {SOURCE}:\n"
        "# meshes/ur5e/collision/*.stl placed by urdf/ur_macro.xacro's <collision><origin> (offsets\n"
        "# from config/ur5e/physical_parameters.yaml and visual_parameters.yaml).\n"
        "# Fitted by scripts/fit-ur5e-capsules.py (numpy): axes from the arm's build (joint axes,\n"
        "# tube axes); points every 2 mm on the mesh triangles, each to its nearest axis; radius =\n"
        "# its points' largest distance from the axis, the shortest ends enclosing them; rounded\n"
        "# up/out to 0.1 mm. The largest distance of any triangle corner, edge midpoint or centroid\n"
        f"# outside the capsules is {max(worst, 0.0) * 1e3:.2f} mm.\n"
        "# UR's collision meshes are coarse hulls, not the arm's skin: the upper arm's is the hull of\n"
        "# its two joint housings (0.12 m wide, 0.15 m deep along the joint axes, all along the arm),\n"
        "# and flat-capped housings become hemispheres. So these capsules enclose the arm with room\n"
        "# to spare, and their radii (0.044-0.095 m) are larger than the housings' own (0.060 m at\n"
        "# the shoulder and elbow, 0.039 m at the wrists, in the same meshes): a larger radius of\n"
        "# curvature gives a lower contact pressure, so check the radius of a real contact by hand.\n"
        "# base_link_inertia (the base) does not move; flange and tool0 have no mesh (no tool).\n"
        "# Regenerate: /usr/bin/python3 scripts/fit-ur5e-capsules.py <meshes/ur5e/collision>\n\n")
    output.write_text(header + "\n".join(blocks))
    print(f"wrote {output}")


if __name__ == "__main__":
    main()
