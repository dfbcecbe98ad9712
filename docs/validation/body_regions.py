#!/usr/bin/env python3
"""An independent implementation of covopt's body-region model (docs/model.md section 13).

It does not call covopt: it re-derives every number from the equations, with a different
root finder (bisection on the force instead of Newton in F^(1/3)) and a fixed-step RK4 time
path, so that its output can be used as check numbers for the library's tests.

Run it with the Python 3 standard library only (no numpy needed):

    python3 docs/validation/body_regions.py > docs/validation/body_regions.txt

Part 1 prints the check numbers of docs/model.md section 13; part 2 prints the comparison with
Svarny et al. 2022 of docs/validation.md section 5. SI units throughout; the printout converts
to mm, N/mm, MPa where it says so.
"""

import math

TRAVEL_FRACTION = 0.8  # the covering is fully compressed at 0.8 of its thickness


class Contact:
    """A robot (mass m_R, optional covering on a surface of radius R_r) against a body region
    (spring k_H, mass m_H; m_H = None means clamped, i.e. infinite)."""

    def __init__(self, robot_mass, body_k, body_mass=None, modulus=0.0, poisson=0.0,
                 thickness=0.0, robot_radius=None):
        self.mu = robot_mass if body_mass is None else 1.0 / (1.0 / robot_mass + 1.0 / body_mass)
        self.k = body_k
        self.covered = thickness > 0.0
        if self.covered:
            self.Rc = robot_radius + thickness
            self.Kc = 4.0 / 3.0 * modulus / (1.0 - poisson ** 2) * math.sqrt(self.Rc)
            self.travel = TRAVEL_FRACTION * thickness
            self.Fb = self.Kc * self.travel ** 1.5
        else:
            self.Fb = math.inf

    # --- the force law and the energy stored at a contact force F -------------------------
    def covering_deflection(self, F):
        if not self.covered:
            return 0.0
        return (min(F, self.Fb) / self.Kc) ** (2.0 / 3.0)

    def covering_energy(self, F):
        # W_c = integral of F d(delta_c) with delta_c = (F/K_c)^(2/3): (2/5) K_c^(-2/3) F^(5/3)
        if not self.covered:
            return 0.0
        return 0.4 * self.Kc ** (-2.0 / 3.0) * min(F, self.Fb) ** (5.0 / 3.0)

    def energy(self, F):
        return F * F / (2.0 * self.k) + self.covering_energy(F)

    # --- exact path: the root of energy(F) = 1/2 mu v^2, by bisection (independent of the
    # library's Newton iteration) ----------------------------------------------------------
    def force_at_energy(self, E):
        lo, hi = 0.0, 1.0
        while self.energy(hi) < E:
            hi *= 2.0
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if self.energy(mid) < E:
                lo = mid
            else:
                hi = mid
            if hi - lo <= 4e-16 * hi:
                break
        return 0.5 * (lo + hi)

    def peak_force(self, v):
        return self.force_at_energy(0.5 * self.mu * v * v)

    def contact_radius(self, F):
        if not self.covered:
            return 0.0
        return math.sqrt(self.Rc * self.covering_deflection(F))

    def pressure(self, F, area=None):
        """Hertz peak pressure 3F/(2 pi a^2) with a covering; F/A bare (None without an area)."""
        if not self.covered:
            return None if area is None else F / area
        return 3.0 * F / (2.0 * math.pi * self.contact_radius(F) ** 2)

    def speed_at_force(self, F):
        return math.sqrt(2.0 * self.energy(F) / self.mu)

    # --- the force at which each limit is reached (the speed limit is then closed form) ----
    def limit_forces(self, F_lim, p_lim, sf=1.0):
        out = {"force": F_lim / sf}
        if self.covered:
            p = p_lim / sf
            # below F_b: p = 3 F^(1/3) K_c^(2/3) / (2 pi R_c)  ->  F = (2 pi R_c p / 3)^3 / K_c^2
            F = (2.0 * math.pi * self.Rc * p / 3.0) ** 3 / self.Kc ** 2
            if F > self.Fb:
                # above F_b the contact radius is fixed: p = 3F / (2 pi R_c 0.8 b_c)
                F = p * 2.0 * math.pi * self.Rc * self.travel / 3.0
            out["pressure"] = F
            # compression: SF * delta_c / (0.8 b_c) <= 1
            out["compression"] = self.Kc * (self.travel / sf) ** 1.5
        return out

    def speed_limit(self, F_lim, p_lim, sf=1.0):
        speeds = {name: self.speed_at_force(F) for name, F in self.limit_forces(F_lim, p_lim, sf).items()}
        binding = min(speeds, key=speeds.get)
        return speeds[binding], binding, speeds

    # --- time path: RK4 on (delta_c, v) until the covering bottoms out, then on (delta_b, v);
    # v is the approach rate; mu v' = -F. Stops at v = 0 (the peak). ------------------------
    def time_path_peak(self, v0, steps_per_ms=200):
        mu, k = self.mu, self.k
        if self.covered:
            Kc = self.Kc

            def rhs_c(y):  # y = (delta_c, v); approach = delta_c + F/k, F = K_c delta_c^1.5
                dc, v = y
                dc = max(dc, 0.0)
                F = Kc * dc ** 1.5
                ddc = v / (1.0 + 1.5 * Kc * math.sqrt(dc) / k)
                return (ddc, -F / mu)
        else:
            rhs_c = None

        def rhs_b(y):  # y = (delta_b, v); F = k delta_b
            db, v = y
            return (v, -k * db / mu)

        def rk4(f, y, h):
            k1 = f(y)
            k2 = f((y[0] + 0.5 * h * k1[0], y[1] + 0.5 * h * k1[1]))
            k3 = f((y[0] + 0.5 * h * k2[0], y[1] + 0.5 * h * k2[1]))
            k4 = f((y[0] + h * k3[0], y[1] + h * k3[1]))
            return (y[0] + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]),
                    y[1] + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]))

        def run(f, y, stop):
            """Steps until stop(y) changes sign; the last step is bisected onto the event."""
            h = 1e-3 / steps_per_ms
            while True:
                y_new = rk4(f, y, h)
                if stop(y_new) <= 0.0:
                    lo, hi = 0.0, h
                    for _ in range(100):
                        mid = 0.5 * (lo + hi)
                        if stop(rk4(f, y, mid)) > 0.0:
                            lo = mid
                        else:
                            hi = mid
                    return rk4(f, y, hi)
                y = y_new

        if self.covered:
            travel = self.travel
            # stop at the peak (v = 0) or at the bottoming out, whichever comes first
            y = run(rhs_c, (0.0, v0), lambda y: min(y[1], travel - y[0]))
            if y[1] > 1e-12 * v0:  # bottomed out with speed left: the body spring alone
                y = run(rhs_b, (self.Fb / k, y[1]), lambda y: y[1])
                return k * y[0]
            return self.Kc * y[0] ** 1.5
        y = run(rhs_b, (0.0, v0), lambda y: y[1])
        return k * y[0]


def mm(x):
    return x * 1e3


def report_contact(title, c, v, F_lim, p_lim, sf=1.0, time_path=True):
    F = c.peak_force(v)
    print(f"-- {title}")
    print(f"   mu = {c.mu:.9g} kg, k_H = {c.k / 1e3:g} N/mm, E = 1/2 mu v^2 = {0.5 * c.mu * v * v:.9g} J at v = {v} m/s")
    if c.covered:
        print(f"   K_c = {c.Kc:.9g} N/m^1.5, R_c = {mm(c.Rc):g} mm, travel 0.8 b_c = {mm(c.travel):g} mm, F_b = {c.Fb:.9g} N")
    p = c.pressure(F)
    dc = c.covering_deflection(F)
    line = f"   F_max = {F:.9g} N"
    if p is not None:
        line += f", p_max = {p / 1e6:.9g} MPa ({p / 1e4:.5g} N/cm^2)"
    if c.covered:
        line += (f", delta_c = {mm(dc):.9g} mm, compression ratio = {dc / c.travel:.9g}, "
                 f"a = {mm(c.contact_radius(F)):.9g} mm, fully compressed = {F > c.Fb}")
    print(line)
    print(f"   body deflection F/k = {mm(F / c.k):.9g} mm, energy in body {F * F / (2 * c.k):.9g} J, in covering {c.covering_energy(F):.9g} J")
    if time_path:
        Ft = c.time_path_peak(v)
        print(f"   time path (RK4): F_max = {Ft:.9g} N, relative difference {abs(Ft / F - 1):.1e}")
    vmax, binding, speeds = c.speed_limit(F_lim, p_lim, sf)
    forces = c.limit_forces(F_lim, p_lim, sf)
    detail = ", ".join(f"{n} {speeds[n]:.9g} m/s (F* {forces[n]:.9g} N)" for n in speeds)
    print(f"   limits F_lim {F_lim:g} N, p_lim {p_lim / 1e4:g} N/cm^2, SF {sf:g}: {detail}")
    print(f"   v_max = {vmax:.9g} m/s, limited by {binding}")
    return vmax


def part1():
    print("== Part 1: check numbers for docs/model.md section 13 (robot 10 kg)")
    chest = dict(body_k=25e3, body_mass=40.0)  # ISO/TS 15066 Table A.3
    # transient chest (sternum): 2 x 140 N, 2 x 120 N/cm^2; clamped: 140 N, 120 N/cm^2
    Ft, pt, Fq, pq = 280.0, 2.4e6, 140.0, 1.2e6

    bare = Contact(10.0, **chest)
    print("-- C0 bare chest, transient: Annex A")
    print(f"   mu = {bare.mu:g} kg, v_max = F_lim / sqrt(mu k) = {Ft / math.sqrt(bare.mu * bare.k):.9g} m/s,"
          f" F at 0.25 m/s = v sqrt(mu k) = {0.25 * math.sqrt(bare.mu * bare.k):.9g} N")
    print(f"   the same through the energy balance: v_max = {bare.speed_at_force(Ft):.9g} m/s,"
          f" F at 0.25 m/s = {bare.peak_force(0.25):.9g} N")
    barec = Contact(10.0, body_k=25e3)
    print(f"   clamped (mu = m_R = 10 kg, 140 N): v_max = {Fq / math.sqrt(barec.mu * barec.k):.9g} m/s")

    pu10 = Contact(10.0, **chest, modulus=0.5e6, poisson=0.3, thickness=10e-3, robot_radius=40e-3)
    report_contact("C1 PU foam E 0.5 MPa, nu 0.3, b_c 10 mm, R_r 40 mm; chest transient", pu10, 0.25, Ft, pt)
    report_contact("C1 at 1 m/s (past F_b: the body spring alone)", pu10, 1.0, Ft, pt)
    report_contact("C1 with safety factor 2", pu10, 0.25, Ft, pt, sf=2.0, time_path=False)
    pu20 = Contact(10.0, **chest, modulus=0.5e6, poisson=0.3, thickness=20e-3, robot_radius=40e-3)
    report_contact("C2 PU foam E 0.5 MPa, nu 0.3, b_c 20 mm, R_r 40 mm; chest transient", pu20, 0.25, Ft, pt)
    ps = Contact(10.0, **chest, modulus=27.6e6, poisson=0.25, thickness=5e-3, robot_radius=15e-3)
    report_contact("C3 polystyrene E 27.6 MPa, nu 0.25, b_c 5 mm, R_r 15 mm; chest transient", ps, 0.25, Ft, pt)
    pu20q = Contact(10.0, body_k=25e3, modulus=0.5e6, poisson=0.3, thickness=20e-3, robot_radius=40e-3)
    report_contact("C4 = C2 clamped (m_H infinite; 140 N, 120 N/cm^2)", pu20q, 0.25, Fq, pq)
    # hands/fingers: k_H 75 N/mm, m_H 0.6 kg; 2 x 140 N; lowest area back of the hand (non-dominant)
    # 190 N/cm^2, transient 380 N/cm^2
    hand = Contact(10.0, body_k=75e3, body_mass=0.6)
    print(f"-- C5 bare hand, transient: mu = {hand.mu:.9g} kg, v_max = {280.0 / math.sqrt(hand.mu * hand.k):.9g} m/s")
    pu20h = Contact(10.0, body_k=75e3, body_mass=0.6, modulus=0.5e6, poisson=0.3, thickness=20e-3,
                    robot_radius=40e-3)
    report_contact("C5 the covering of C2 on the hand (back of the hand, non-dominant), transient", pu20h, 0.25,
                   280.0, 3.8e6)
    print()


def part2():
    print("== Part 2: Svarny et al. 2022 (RCIM 78:102363) beside the model")
    print("   Measured (abstract): passive skin lowered transient impact forces by about 40 %;")
    print("   up to 4x the ISO/TS 15066 velocity met the force limits in some cases.")
    print("   Not found in the sources read: the device's spring, the pad's thickness and stiffness,")
    print("   the speeds, the robots' effective masses. Everything below is parametric in them.")
    print()
    print("-- S1 the covering deflection the model needs for a 40 % cut, whatever the pad's modulus")
    print("   (at a bare peak force F0 on a spring k: F = 0.6 F0, delta_c = (5/4)(F0^2 - F^2)/(k F) = 4/3 F0/k)")
    print("   k [N/mm]  F0 [N]  bare delta_b [mm]  covering delta_c [mm]  thickness >= delta_c/0.8 [mm]")
    for k in (10e3, 25e3, 75e3):
        for F0 in (100.0, 200.0, 300.0):
            F = 0.6 * F0
            dc = 1.25 * (F0 * F0 - F * F) / (k * F)
            print(f"   {k / 1e3:8g}  {F0:6g}  {mm(F0 / k):17.4g}  {mm(dc):21.4g}  {mm(dc / TRAVEL_FRACTION):29.4g}")
    print()
    print("-- S2 the pad stiffness K_c that gives 40 % at a reference bare force F0_ref, and what the")
    print("   same pad then gives at other speeds (the bare force scales with v: F0 = F0_ref v/v_ref).")
    print("   Travel taken as ample (no bottoming out). E* = E_c/(1 - nu^2) = 3 K_c / (4 sqrt(R_c)),")
    print("   shown for R_c = 60 mm (R_r 40 mm + b_c 20 mm) and, in brackets, for R_c 30 and 120 mm.")
    for k in (10e3, 25e3, 75e3):
        F0r = 200.0
        F = 0.6 * F0r
        # (F0^2 - F^2)/(2k) = (2/5) K_c^(-2/3) F^(5/3)  ->  K_c
        Kc = (0.4 * F ** (5.0 / 3.0) * 2.0 * k / (F0r * F0r - F * F)) ** 1.5
        Es = [3.0 * Kc / (4.0 * math.sqrt(R)) for R in (60e-3, 30e-3, 120e-3)]
        ratios = []
        for s in (0.25, 0.5, 1.0, 1.5, 2.0):
            F0 = F0r * s
            E = F0 * F0 / (2 * k)
            # the covered contact with the fitted K_c and unlimited travel
            lo, hi = 0.0, F0
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                if mid * mid / (2 * k) + 0.4 * Kc ** (-2.0 / 3.0) * mid ** (5.0 / 3.0) < E:
                    lo = mid
                else:
                    hi = mid
            Fc = 0.5 * (lo + hi)
            dc = (Fc / Kc) ** (2.0 / 3.0)
            ratios.append(f"v/v_ref {s:g}: F0 {F0:g} N -> {Fc:.4g} N ({100 * (1 - Fc / F0):.1f} % less, delta_c {mm(dc):.3g} mm)")
        print(f"   k {k / 1e3:g} N/mm, F0_ref {F0r:g} N: K_c = {Kc:.4g} N/m^1.5, E* = {Es[0] / 1e6:.3g} MPa"
              f" [{Es[1] / 1e6:.3g}, {Es[2] / 1e6:.3g}]")
        for r in ratios:
            print("      " + r)
    print()
    print("-- S3 predicted force reduction at a bare force of 200 N for pads of given modulus and")
    print("   thickness (nu 0.3, R_r 40 mm); '*' marks a pad that bottoms out (F_max > F_b).")
    mods = (0.05e6, 0.1e6, 0.2e6, 0.5e6, 1e6, 2e6)
    print("   k [N/mm]  b_c [mm]  " + "  ".join(f"E_c {m / 1e6:g} MPa" for m in mods))
    for k in (10e3, 25e3, 75e3):
        for b in (10e-3, 20e-3, 30e-3):
            cells = []
            for m in mods:
                c = Contact(1.0, body_k=k, modulus=m, poisson=0.3, thickness=b, robot_radius=40e-3)
                E = 200.0 ** 2 / (2 * k)
                F = c.force_at_energy(E)
                cells.append(f"{100 * (1 - F / 200.0):5.1f} %{'*' if F > c.Fb else ' '}")
            print(f"   {k / 1e3:8g}  {mm(b):8g}  " + "  ".join(f"{x:>14}" for x in cells))
    print()
    print("-- S4 the speed gain at a force limit: v_cov/v_bare = sqrt(1 + 0.8 delta_c(F_lim)/delta_b(F_lim))")
    print("   (no bottoming out); the covering deflection a gain needs, as a multiple of F_lim/k:")
    for g in (1.25, 1.5, 2.0, 4.0):
        need = (g * g - 1.0) / 0.8
        print(f"   gain {g:g}: delta_c = {need:.4g} F_lim/k;"
              f" hand 280 N on 75 N/mm: {mm(need * 280 / 75e3):.3g} mm (thickness >= {mm(need * 280 / 75e3 / 0.8):.3g} mm)")
    print("   the pads of S2 (40 % at a bare 200 N) at a force limit of 280 N, no bottoming out:")
    for k in (10e3, 25e3, 75e3):
        F, F0r = 120.0, 200.0
        Kc = (0.4 * F ** (5.0 / 3.0) * 2.0 * k / (F0r * F0r - F * F)) ** 1.5
        dc, db = (280.0 / Kc) ** (2.0 / 3.0), 280.0 / k
        print(f"   k {k / 1e3:g} N/mm: delta_c {mm(dc):.3g} mm, delta_b {mm(db):.3g} mm, gain {math.sqrt(1 + 0.8 * dc / db):.3f}")


if __name__ == "__main__":
    part1()
    part2()
