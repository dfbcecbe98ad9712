"""Writes a small "plant" of FR3 programs for the audit_cluster.py example: the shipped pick
move (robot/models/franka_fr3_pick.csv) and variants of it, run slower (every time stretched
by a factor, every joint velocity divided by it) or shifted (a constant offset on joint 1 or
joint 4, velocities unchanged), each within the FR3's joint limits.

    python3 python/examples/make_fr3_programs.py [FOLDER]   (default: python/examples/fr3_programs)
"""

import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
PICK = ROOT / "robot" / "models" / "franka_fr3_pick.csv"
JOINTS = 7

# name: (time stretch, {joint index (0-based): offset [rad]})
VARIANTS = {
    "pick": (1.0, {}),
    "pick_slow": (1.5, {}),
    "pick_left": (1.0, {0: 0.4}),
    "pick_right": (1.0, {0: -0.4}),
    "pick_low_slow": (1.25, {3: -0.2}),
}


def read(path):
    rows = []
    for line in pathlib.Path(path).read_text().splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        try:
            rows.append([float(x) for x in line.split(",")])
        except ValueError:
            continue  # the header
    return rows


def variant(rows, stretch, offsets):
    out = []
    for row in rows:
        t, q, qd = row[0], row[1:1 + JOINTS], row[1 + JOINTS:1 + 2 * JOINTS]
        q = [x + offsets.get(i, 0.0) for i, x in enumerate(q)]
        out.append([t * stretch] + q + [x / stretch for x in qd])
    return out


def main(folder=None):
    folder = pathlib.Path(folder) if folder else pathlib.Path(__file__).resolve().parent / "fr3_programs"
    folder.mkdir(parents=True, exist_ok=True)
    rows = read(PICK)
    header = "time_s," + ",".join(f"q_fr3_joint{i}" for i in range(1, JOINTS + 1)) + "," + \
        ",".join(f"qd_fr3_joint{i}" for i in range(1, JOINTS + 1))
    paths = []
    for name, (stretch, offsets) in VARIANTS.items():
        lines = [f"# {name}: the FR3 pick move (robot/models/franka_fr3_pick.csv), time x {stretch:g}, "
                 f"joint offsets {offsets or 'none'} [rad]; written by python/examples/make_fr3_programs.py", header]
        lines += [",".join(repr(x) for x in row) for row in variant(rows, stretch, offsets)]
        path = folder / f"{name}.csv"
        path.write_text("\n".join(lines) + "\n")
        paths.append(path)
    return paths


if __name__ == "__main__":
    for p in main(sys.argv[1] if len(sys.argv) > 1 else None):
        print(p)
