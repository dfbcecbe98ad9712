#!/usr/bin/env python3
"""Speed-mass map of the paper's covering: the worst injury ratio over robot speed and mass.

One covopt.sweep (the exact path on every grid point, on all cores) gives the laceration and
contusion ratios (value / limit) of the paper's scene with its 15 mm covering over robot
speed [m/s] and reflected mass [kg]; the chart colours the worse of the two, draws the safe
boundary (ratio 1) and hatches where the covering is fully compressed at the peak.

    PYTHONPATH=build/python python3 python/examples/speed_mass_map.py speed_mass_map.png
"""

import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import covopt  # noqa: E402


def main(output="speed_mass_map.png"):
    speeds = np.linspace(0.25, 4.0, 200)     # m/s
    masses = np.geomspace(1.0, 50.0, 200)    # kg
    grid = covopt.sweep(("speed", speeds), ("robot_mass", masses))
    worst = grid.worst_ratio                 # worst[i, j] at speeds[i], masses[j]
    full = grid.fully_compressed.astype(float)

    fig, ax = plt.subplots(figsize=(7, 5))
    mesh = ax.pcolormesh(masses, speeds, worst, shading="auto", cmap="RdYlGn_r",
                         vmin=0, vmax=2)
    fig.colorbar(mesh, ax=ax, label="worst injury ratio (value / limit)")
    ax.contour(masses, speeds, worst, levels=[1.0], colors="k", linewidths=2)
    ax.contourf(masses, speeds, full, levels=[0.5, 1.5], colors="none", hatches=["//"])
    ax.set_xscale("log")
    ax.set_xlabel("robot reflected mass [kg]")
    ax.set_ylabel("impact speed [m/s]")
    ax.set_title("Paper's scene, 15 mm covering at 27.6 MPa:\n"
                 "safe below the black line; hatched = covering fully compressed")
    fig.tight_layout()
    fig.savefig(output, dpi=120)
    print(f"wrote {output}; {grid.brief_report}")


if __name__ == "__main__":
    main(*sys.argv[1:2])
