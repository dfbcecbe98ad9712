#!/usr/bin/env python3
"""The foam law against measured data (docs/validation.md §6): every number of that section.

Run after building:  python3 docs/validation/foam_validation.py [path/to/covopt]
(output: docs/validation/foam_validation.txt). It calls only the covopt CLI (`materials show`,
`simulate --json`) and computes its own references with numpy from the catalog's points: the
energy integrals W(ε) = ∫σ dε by the trapezoid rule (exact for a piecewise-linear curve), and a
body region with a foam layer, a Shore-A pad and a spring in series by its own energy balance
(bisection on the force), independent of covopt's code. python/tests/test_validation_foam.py
imports this file and holds its numbers.
"""

import json
import math
import os
import pathlib
import subprocess
import sys

import numpy as np

VN600 = "vinyl-nitrile foam VN600"
# The design notes' 11 rounded points of the NIST VN600 record and the six of their first
# estimate (strain, stress Pa): what a coarse reading of the published curve gives.
VN600_ELEVEN = [(0.02, 14.3e3), (0.05, 22.0e3), (0.10, 30.2e3), (0.15, 37.4e3), (0.20, 45.9e3),
                (0.25, 57.3e3), (0.30, 72.2e3), (0.35, 91.6e3), (0.40, 118.0e3), (0.45, 153.2e3),
                (0.49, 189.5e3)]
VN600_SIX = [(0.02, 14.3e3), (0.05, 22.0e3), (0.10, 30.2e3), (0.25, 57.3e3), (0.40, 118.0e3),
             (0.49, 189.5e3)]
# ISO/TS 15066 Table A.3 regions whose spring constants are those of measuring devices'
# springs (DGUV FB HM-080 pairs: 10, 25, 75 N/mm among them).
SPRINGS = {"abdomen": 10e3, "chest": 25e3, "hands-fingers": 75e3}
ROBOT_MASS_KG = 10.0
ROBOT_RADIUS_M = 0.040


def covopt_binary():
    if len(sys.argv) > 1 and __name__ == "__main__":
        return sys.argv[1]
    if os.environ.get("COVOPT_CLI"):
        return os.environ["COVOPT_CLI"]
    return str(pathlib.Path(__file__).resolve().parents[2] / "build" / "cli" / "covopt")


def run_json(*args):
    done = subprocess.run([covopt_binary(), *args], capture_output=True, text=True, check=True)
    return json.loads(done.stdout)


def curve_points(material=VN600):
    """The catalog's curve (strain, stress Pa) with the origin in front."""
    shown = run_json("materials", "show", material, "--json")
    return [(0.0, 0.0)] + [tuple(p) for p in shown["compressive_curve"]], shown


def energy_density(points, strain):
    """W(strain) = ∫0^strain σ dε [J/m³] of a piecewise-linear curve through `points`
    (with the origin), by the trapezoid rule on the points and the end (exact for such a curve)."""
    e = np.array([p[0] for p in points])
    s = np.array([p[1] for p in points])
    if points[0][0] > 0.0:
        e, s = np.concatenate(([0.0], e)), np.concatenate(([0.0], s))
    inside = e < strain
    grid = np.concatenate((e[inside], [strain]))
    return float(np.trapezoid(np.interp(grid, e, s), grid)) if hasattr(np, "trapezoid") else \
        float(np.trapz(np.interp(grid, e, s), grid))


class FoamLayer:
    """A foam layer of thickness h on a curved face R_c (docs/model.md §15.2), tabulated densely:
    F(d) = 2π R_c h W(d/h), U(d) = 2π R_c h² V(d/h); past the curve's end a rigid stop."""

    def __init__(self, points, thickness_m, outer_radius_m, samples=200001):
        e = np.array([p[0] for p in points])
        s = np.array([p[1] for p in points])
        self.strain = np.unique(np.concatenate((np.linspace(0.0, e[-1], samples), e)))
        sigma = np.interp(self.strain, e, s)
        w = np.concatenate(([0.0], np.cumsum(0.5 * (sigma[1:] + sigma[:-1]) * np.diff(self.strain))))
        # V = ∫W: W is piecewise quadratic; Simpson on each interval with the midpoint's W exact.
        mid = 0.5 * (self.strain[1:] + self.strain[:-1])
        sigma_mid = np.interp(mid, e, s)
        w_mid = w[:-1] + 0.5 * (sigma[:-1] + sigma_mid) * (mid - self.strain[:-1])
        v = np.concatenate(([0.0], np.cumsum(np.diff(self.strain) / 6.0 * (w[:-1] + 4.0 * w_mid + w[1:]))))
        self.force = 2.0 * math.pi * outer_radius_m * thickness_m * w
        self.energy = 2.0 * math.pi * outer_radius_m * thickness_m ** 2 * v

    def energy_at_force(self, force_n):
        if force_n >= self.force[-1]:
            return float(self.energy[-1])
        return float(np.interp(force_n, self.force, self.energy))


def hertz_pad_energy(force_n, modulus_pa, poisson, radius_m):
    """A Hertz layer (sphere R on a half-space) at force F: δ = (F/K)^(2/3), U = 2/5 F δ."""
    k = 4.0 / 3.0 * modulus_pa / (1.0 - poisson ** 2) * math.sqrt(radius_m)
    return 0.4 * force_n * (force_n / k) ** (2.0 / 3.0)


def series_force(energy_j, spring_n_per_m, elements):
    """The peak force of elements in series with a spring at impact energy E: each element's
    energy at a force F adds up (the same F goes through all); U(F) = E by bisection."""
    def total(force):
        return force * force / (2.0 * spring_n_per_m) + sum(element(force) for element in elements)
    low, high = 0.0, math.sqrt(2.0 * spring_n_per_m * energy_j)  # the bare spring bounds it
    for _ in range(200):
        mid = 0.5 * (low + high)
        low, high = (mid, high) if total(mid) < energy_j else (low, mid)
    return 0.5 * (low + high)


def region_simulate(region, speed, thickness_mm, material=VN600, law="foam", radius_m=ROBOT_RADIUS_M,
                    contact="transient"):
    args = ["simulate", "--json", "--body-region", region, "--contact", contact,
            "--robot-mass", f"{ROBOT_MASS_KG}kg", "--robot-radius", f"{radius_m * 1e3}mm",
            "--speed", f"{speed}m/s", "--covering-thickness", f"{thickness_mm}mm"]
    if thickness_mm > 0:
        args += ["--material", material, "--covering-law", law]
    else:
        args += ["--contact-area", "1m2"]  # the bare robot's pressure is not compared here
    return run_json(*args)["regions"][0]


def region_mass(region):
    return {"abdomen": 40.0, "chest": 40.0, "hands-fingers": 0.6}[region]


def reduced_mass(region):
    return 1.0 / (1.0 / ROBOT_MASS_KG + 1.0 / region_mass(region))


def speed_for_bare_force(region, force_n):
    """Annex A: F0 = v sqrt(mu k)."""
    return force_n / math.sqrt(reduced_mass(region) * SPRINGS[region])


def vn600_integrals():
    points, shown = curve_points()
    return {
        "record_W25": energy_density(points, 0.25), "record_W49": energy_density(points, 0.49),
        "record_W_end": energy_density(points, points[-1][0]), "catalog_W_end": shown["curve_energy_density_J_per_m3"],
        "eleven_W25": energy_density(VN600_ELEVEN, 0.25), "eleven_W49": energy_density(VN600_ELEVEN, 0.49),
        "six_W25": energy_density(VN600_SIX, 0.25), "six_W49": energy_density(VN600_SIX, 0.49),
        "points": len(points) - 1,
    }


def reduction(region, force_n, thickness_mm):
    """1 − F_covered/F_bare at the speed where the bare robot gives force_n, and the covered row."""
    v = speed_for_bare_force(region, force_n)
    bare = region_simulate(region, v, 0)["peak_force_N"]
    row = region_simulate(region, v, thickness_mm)
    return 1.0 - row["peak_force_N"] / bare, row


def independent_foam_force(region, force_n, thickness_mm, rate_factor=1.0):
    """The peak force of a VN600 layer (its stresses times rate_factor) by the script's own balance."""
    points, _ = curve_points()
    points = [(e, rate_factor * s) for e, s in points]
    layer = FoamLayer(points, thickness_mm * 1e-3, ROBOT_RADIUS_M + thickness_mm * 1e-3)
    energy = force_n ** 2 / (2.0 * SPRINGS[region])
    return series_force(energy, SPRINGS[region], [layer.energy_at_force])


def shore_a_modulus(shore):
    """The catalog's correlation for solid rubber (Ruess): log10(E/MPa) = 0.0235 ShA − 0.6403."""
    return 10 ** (0.0235 * shore - 0.6403) * 1e6


def pad_compression(force_n, shore, radius_m):
    """The pad's Hertz compression δ = (F/K)^(2/3) and contact radius a = sqrt(R δ) at force F."""
    modulus = shore_a_modulus(shore)
    k = 4.0 / 3.0 * modulus / (1.0 - 0.49 ** 2) * math.sqrt(radius_m)
    deflection = (force_n / k) ** (2.0 / 3.0)
    return deflection, math.sqrt(radius_m * deflection)


def device_reading(spring, force_n, pad_shore, pad_mm, foam_mm):
    """What a device (spring + Shore-A pad, bonded on its face) reads for a robot of radius R_r,
    bare or with a VN600 layer, at the impact energy where the bare spring alone reads force_n."""
    energy = force_n ** 2 / (2.0 * spring)
    elements = []
    if pad_mm > 0:
        elements.append(lambda f: hertz_pad_energy(f, shore_a_modulus(pad_shore), 0.49, ROBOT_RADIUS_M + foam_mm * 1e-3))
    if foam_mm > 0:
        points, _ = curve_points()
        layer = FoamLayer(points, foam_mm * 1e-3, ROBOT_RADIUS_M + foam_mm * 1e-3)
        elements.append(layer.energy_at_force)
    return series_force(energy, spring, elements)


def report():
    lines = []
    w = vn600_integrals()
    lines.append(f"VN600: {w['points']} points; W(25 %) = {w['record_W25']:.1f} J/m3, W(49 %) = {w['record_W49']:.1f} J/m3, "
                 f"W(end) = {w['record_W_end']:.1f} (catalog {w['catalog_W_end']:.1f})")
    lines.append(f"  11 rounded points: W(25 %) = {w['eleven_W25']:.1f}, W(49 %) = {w['eleven_W49']:.1f}")
    lines.append(f"  6 points: W(25 %) = {w['six_W25']:.1f}, W(49 %) = {w['six_W49']:.1f}")
    lines.append("Force reduction 1 - F_cov/F_bare, VN600 on R_r 40 mm, 10 kg, transient (covopt | independent):")
    for region in SPRINGS:
        for force in (100.0, 200.0, 300.0):
            cells = []
            for mm in (5, 10, 20, 40):
                r, row = reduction(region, force, mm)
                ind = 1.0 - independent_foam_force(region, force, mm) / force
                cells.append(f"{mm} mm {100 * r:5.1f} % | {100 * ind:5.1f} %{' used up' if row['fully_compressed'] else ''}")
            lines.append(f"  {region:14s} k {SPRINGS[region] / 1e3:4.0f} N/mm, bare {force:.0f} N: " + "; ".join(cells))
    for factor in (1.0, 2.0, 4.0):
        cells = [f"{mm} mm {100 * (1 - independent_foam_force('hands-fingers', 200.0, mm, factor) / 200.0):5.1f} %"
                 for mm in (10, 20, 40)]
        lines.append(f"  hands-fingers at 200 N, VN600 stresses x {factor:.0f} (rate factor): " + "; ".join(cells))
    lines.append("Device readings (spring + Shore-A pad in series, R_r 40 mm), at bare-spring force 200 N:")
    for spring in (10e3, 25e3, 75e3):
        foam_only = device_reading(spring, 200.0, 0, 0, 20)
        for shore in (10, 30, 70):
            bare = device_reading(spring, 200.0, shore, 1, 0)
            covered = device_reading(spring, 200.0, shore, 1, 20)
            deflection, radius = pad_compression(bare, shore, ROBOT_RADIUS_M)
            lines.append(f"  k {spring / 1e3:3.0f} N/mm, ShA {shore:2d} (E {shore_a_modulus(shore) / 1e6:.2f} MPa): bare robot {bare:6.1f} N "
                         f"(pad compressed {deflection * 1e3:4.1f} mm, contact radius {radius * 1e3:4.1f} mm), "
                         f"20 mm VN600 {covered:6.1f} N: reduction {100 * (1 - covered / bare):5.1f} % "
                         f"(without the pad: {foam_only:6.1f} N, {100 * (1 - foam_only / 200.0):5.1f} %)")
    return "\n".join(lines)


if __name__ == "__main__":
    text = report()
    print(text)
    (pathlib.Path(__file__).parent / "foam_validation.txt").write_text(text + "\n")
