#!/usr/bin/env python3
"""Writes tests/robot/data/link_points_numpy.txt: points on several links of the shipped FR3
and UR5e at several samples (q, q_dot), with their position, velocity and reflected mass
along the velocity from the independent numpy reference python/tests/robot_reference.py
(xml.etree, 4x4 transforms, M summed from the links' inertias; no KDL, no covopt). The C++
test tests/robot/test_link_kinematics.cpp holds covopt's ChainSampleKinematics to these rows;
python/tests/test_robot_crosscheck.py checks that the file is still what the reference gives.

    /usr/bin/python3 scripts/make-link-points-reference.py [OUTPUT]
"""

import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "python" / "tests"))
import robot_reference  # noqa: E402


def main():
    output = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "tests" / "robot" / "data" / "link_points_numpy.txt"
    lines = [
        "# Written by scripts/make-link-points-reference.py from python/tests/robot_reference.py (numpy).",
        "# One point per line, whitespace-separated: urdf (in robot/models) tip link n q1..qn qd1..qdn",
        "# point_in_link_m(3)  then the reference: position_m(3) velocity_m_per_s(3) reflected_mass_kg",
        "# (along the velocity, every joint free; 0 at rest). Base: the URDF's root link.",
    ]
    for row in robot_reference.link_point_rows(str(ROOT / "robot" / "models")):
        lines.append(" ".join(str(x) if isinstance(x, (str, int)) else repr(float(x)) for x in row))
    output.write_text("\n".join(lines) + "\n")
    print(f"wrote {output}: {len(lines) - 4} points")


if __name__ == "__main__":
    main()
