"""The ISO/TS 15066 body regions in Python: covopt.simulate, speed_limit and optimize with
body_region= (docs/model.md §13), checked against Annex A's formula, an independent numpy
computation of the model, physical trends and the library's refusals."""

import math

import numpy as np
import pytest

import covopt

Scene = covopt.Scene
BARE = {"covering_thickness": 0}
# A covering given by its modulus: no catalog material, so no crush check.
COVERED = {"covering_modulus": "5MPa", "covering_poisson": 0.3, "covering_thickness": "20mm",
           "robot_radius": "50mm"}


def limits(region, area=None, contact="transient"):
    return covopt.body_region_limits(region, area, contact)


def reduced_mass(robot_mass, body_mass):
    return 1.0 / (1.0 / robot_mass + (0.0 if body_mass in ("fixed", math.inf) else 1.0 / body_mass))


def test_bare_robot_is_annex_a_exactly():
    # F = v sqrt(mu k): chest k_H = 25 N/mm, m_H = 40 kg (Table A.3), and every other region;
    # a contact area of 1 m² keeps the pressure (F/A) far below its limit.
    for robot_mass, speed in ((10.0, 0.5), (3.0, 1.7), (25.0, 0.25)):
        r = covopt.simulate(Scene(robot_mass=robot_mass, speed=speed, **BARE), body_region="chest", contact_area="1m2")
        assert r.peak_force_N == pytest.approx(speed * math.sqrt(reduced_mass(robot_mass, 40.0) * 25e3),
                                               rel=1e-14)
        assert r.compression_ratio == 0.0 and r.peak_pressure_Pa == pytest.approx(r.peak_force_N, rel=1e-15)
        assert r.governing == "force" and r.force.ratio == pytest.approx(r.peak_force_N / 280, rel=1e-14)
    for contact in ("transient", "clamped"):
        for row in covopt.speed_limit(Scene(robot_mass=10, **BARE), body_region="all", contact=contact,
                                      contact_area="1m2"):
            if row.region == "head":
                continue
            lim = limits(row.region, row.area, contact)
            r = covopt.simulate(Scene(robot_mass=10, speed=0.8, **BARE), body_region=row.region,
                                body_area=row.area, contact=contact, contact_area="1m2")
            mu = reduced_mass(10.0, lim.effective_mass_kg)
            assert r.reduced_mass_kg == pytest.approx(mu, rel=1e-15)
            assert r.peak_force_N == pytest.approx(0.8 * math.sqrt(mu * lim.stiffness_N_per_m), rel=1e-14)
            assert r.force.ratio == pytest.approx(r.peak_force_N / r.force.limit_N, rel=1e-14)
            # and v_max = F_lim / sqrt(mu k), limited by force with a large contact area
            assert row.bare_max_speed_m_per_s == pytest.approx(
                row.force_limit_N / math.sqrt(mu * lim.stiffness_N_per_m), rel=1e-12)
            assert row.bare_limited_by == "force" and row.covered_max_speed_m_per_s is None and row.gain is None


def test_bare_chest_speed_limit():
    row, = covopt.speed_limit(Scene(robot_mass=10, **BARE), body_region="chest", contact_area="1m2")
    assert (row.region, row.area, row.contact) == ("chest", "sternum", "transient")
    assert (row.force_limit_N, row.pressure_limit_Pa) == (280.0, 2.4e6)
    assert row.bare_max_speed_m_per_s == pytest.approx(280 / math.sqrt(8 * 25e3), rel=1e-14)
    assert row.bare_max_speed_m_per_s == pytest.approx(0.626099, abs=5e-7)
    assert "chest (sternum): 280 N, 240 N/cm²" in row.criteria


def test_energy_balance_and_hertz_pressure():
    r = covopt.simulate(Scene(robot_mass=10, speed=0.6, **COVERED), body_region="hands-fingers")
    lim = limits("hands-fingers", r.area)
    mu = reduced_mass(10.0, lim.effective_mass_kg)
    assert r.energy_transferred_J == pytest.approx(0.5 * mu * 0.6 ** 2, rel=1e-14)
    body_energy = r.peak_force_N ** 2 / (2 * lim.stiffness_N_per_m)
    assert r.body_deflection_m == pytest.approx(r.peak_force_N / lim.stiffness_N_per_m, rel=1e-12)
    k_c = 4 / 3 * 5e6 / (1 - 0.3 ** 2) * math.sqrt(0.05 + 0.02)
    covering_energy = 0.4 * k_c ** (-2 / 3) * r.peak_force_N ** (5 / 3)
    assert body_energy + covering_energy == pytest.approx(r.energy_transferred_J, rel=1e-12)
    a2 = 0.07 * (r.peak_force_N / k_c) ** (2 / 3)
    assert r.contact_radius_m ** 2 == pytest.approx(a2, rel=1e-12)
    assert r.peak_pressure_Pa == pytest.approx(3 * r.peak_force_N / (2 * math.pi * a2), rel=1e-12)
    assert r.compression_ratio == pytest.approx((r.peak_force_N / k_c) ** (2 / 3) / (0.8 * 0.02), rel=1e-12)
    assert r.pressure.ratio == pytest.approx(r.peak_pressure_Pa / r.pressure.limit_Pa, rel=1e-14)
    worst = max(r.force.ratio, r.pressure.ratio, r.compression_ratio)
    assert r.governing_ratio == pytest.approx(worst, rel=1e-15)
    assert r.admissible == (worst <= 1.0) and r.margin == pytest.approx(1 - worst, abs=1e-15)


def model_speed_limit(row, robot_mass, modulus, poisson, thickness, radius, safety_factor=1.0):
    """An independent numpy computation of the covered speed limit (docs/model.md §13):
    1/2 mu v^2 = F^2/(2k) + 0.4 K_c^(-2/3) min(F, F_b)^(5/3) at the least of the forces where
    the force, the Hertz pressure or the covering's travel reaches its limit / SF."""
    lim = limits(row.region, row.area, row.contact)
    mu = reduced_mass(robot_mass, lim.effective_mass_kg)
    k = lim.stiffness_N_per_m
    r_c = radius + thickness
    k_c = 4.0 / 3.0 * modulus / (1.0 - poisson ** 2) * np.sqrt(r_c)
    f_b = k_c * (0.8 * thickness) ** 1.5
    # p = 3 F / (2 pi a^2), a^2 = R_c (F/K_c)^(2/3)  =>  F = (2 pi R_c p / 3)^3 / K_c^2
    f_pressure = (2 * np.pi * r_c * row.pressure_limit_Pa / safety_factor / 3) ** 3 / k_c ** 2
    f_travel = k_c * (0.8 * thickness / safety_factor) ** 1.5
    forces = np.array([row.force_limit_N / safety_factor, f_pressure, f_travel])
    energy = forces ** 2 / (2 * k) + 0.4 * k_c ** (-2 / 3) * np.minimum(forces, f_b) ** (5 / 3)
    speeds = np.sqrt(2 * energy / mu)
    return speeds.min(), ("force", "pressure", "full-compression")[int(speeds.argmin())]


@pytest.mark.parametrize("modulus, thickness, radius, safety_factor", [
    (5e6, 0.02, 0.05, 1.0), (50e6, 0.02, 0.05, 1.0), (0.3e6, 0.01, 0.03, 1.0), (2e6, 0.005, 0.1, 1.5)])
@pytest.mark.parametrize("contact", ["transient", "clamped"])
def test_covered_speed_limit_matches_an_independent_computation(modulus, thickness, radius, safety_factor,
                                                                 contact):
    scene = Scene(robot_mass=12, covering_modulus=modulus, covering_poisson=0.3, covering_thickness=thickness,
                  robot_radius=radius, safety_factor=safety_factor)
    # keep_travel: the travel rule as a limit (the independent computation's full-compression limit).
    table = covopt.speed_limit(scene, body_region="all", contact=contact, keep_travel=True)
    assert len(table) == (27 if contact == "transient" else 29)  # 26 areas and the head; 29 areas
    for row in table:
        if row.region == "head":
            continue
        expected, kind = model_speed_limit(row, 12.0, modulus, 0.3, thickness, radius, safety_factor)
        assert row.covered_max_speed_m_per_s == pytest.approx(expected, rel=1e-9), row.criteria
        assert row.covered_limited_by == kind
        assert row.gain == pytest.approx(row.covered_max_speed_m_per_s / row.bare_max_speed_m_per_s, rel=1e-15)


def test_every_limit_kind_binds_somewhere():
    kinds = {row.covered_limited_by
             for modulus, thickness in ((5e6, 0.02), (50e6, 0.02), (0.3e6, 0.01))
             for row in covopt.speed_limit(Scene(robot_mass=12, covering_modulus=modulus,
                                                 covering_thickness=thickness, robot_radius=0.05),
                                           body_region="all", contact="clamped", keep_travel=True)}
    assert kinds == {"force", "pressure", "full-compression"}


def test_clamped_is_stricter_than_transient():
    for scene in (Scene(robot_mass=10, **BARE), Scene(robot_mass=10, **COVERED)):
        transient = {(r.region, r.area): r for r in covopt.speed_limit(scene, body_region="all", contact_area="1cm2")}
        clamped = {(r.region, r.area): r for r in covopt.speed_limit(scene, body_region="all", contact="clamped",
                                                                     contact_area="1cm2")}
        assert set(clamped) - set(transient) == {("skull-forehead", a) for a in ("forehead", "temple")} | {
            ("face", "masticatory-muscle")}
        assert ("head", None) in transient and ("head", None) not in clamped
        for key, row in clamped.items():
            if key in transient:
                for side in ("bare_max_speed_m_per_s", "covered_max_speed_m_per_s"):
                    if getattr(row, side) is not None:
                        assert getattr(row, side) < getattr(transient[key], side), key


def test_a_softer_covering_raises_the_covered_limit_until_pressure_binds():
    found = []
    for modulus in (200e6, 50e6, 20e6, 10e6, 5e6, 2e6, 1e6):
        row, = covopt.speed_limit(Scene(robot_mass=10, covering_modulus=modulus, covering_thickness="20mm",
                                        robot_radius="50mm"), body_region="chest")
        found.append((row.covered_max_speed_m_per_s, row.covered_limited_by, row.bare_max_speed_m_per_s))
    speeds = [v for v, _, _ in found]
    assert speeds == sorted(speeds) and len(set(speeds)) == len(speeds)
    assert found[0][1] == "pressure" and found[-1][1] == "force"
    assert found[-1][0] > found[-1][2]  # the soft covering beats the bare robot (force alone); the stiff one does not
    assert found[0][0] < found[0][2]


def test_the_head_row_is_park_et_al_s_max_safe_speed():
    scene = Scene(robot_mass=10, material="elastomer Shore A50", covering_thickness="10mm", robot_radius="30mm")
    head = list(covopt.speed_limit(scene, body_region="all"))[-1]
    assert (head.region, head.criteria, head.force_limit_N) == ("head", "skin injury, Park et al. 2011", None)
    covered = covopt.max_safe_speed(scene)
    bare = covopt.max_safe_speed(scene.replace(covering_thickness=0, material=None))
    assert head.covered_max_speed_m_per_s == covered.max_safe_speed_m_per_s
    assert head.bare_max_speed_m_per_s == bare.max_safe_speed_m_per_s
    assert head.gain == pytest.approx(covered.max_safe_speed_m_per_s / bare.max_safe_speed_m_per_s, rel=1e-15)


def test_design_for_body_regions():
    scene = Scene(robot_mass=10, speed=0.7, robot_radius="30mm")
    design = covopt.optimize(scene, body_region=["chest", "hands-fingers", "head"])
    assert isinstance(design, covopt.BodyRegionDesign)
    assert not design.bare_robot.safe and design.bare_robot.regions[0].force.ratio > 1  # chest: 1.118 bare
    best = design.recommendation
    assert best.admissible and all(j.admissible for j in best.regions)
    assert max(best.head.laceration_ratio, best.head.contusion_ratio) <= 1
    assert "Recommended" in design.message and best.material in design.message
    for region in ("chest", "hands-fingers"):  # the same verdict from simulate
        at = Scene(robot_mass=10, speed=0.7, robot_radius="30mm", material=best.material,
                   covering_thickness=best.thickness_m)
        assert covopt.simulate(at, body_region=region).admissible
    # half a millimetre thinner (the rounding step) fails a region or the head
    thinner = at.replace(covering_thickness=best.thickness_m - 0.5e-3)
    head = covopt.simulate(thinner)
    assert not (all(covopt.simulate(thinner, body_region=r).admissible for r in ("chest", "hands-fingers"))
                and head.safe and not head.fully_compressed)


def test_results_are_typed_and_give_their_dicts():
    r = covopt.simulate(Scene(robot_mass=10, speed=0.5, **COVERED), body_region="chest", contact="clamped")
    assert isinstance(r, covopt.BodyContact) and isinstance(r, covopt.Result)
    d = r.to_dict()
    assert d["regions"][0]["peak_force_N"] == r.peak_force_N and d["regions"][0]["force"]["ratio"] == r.force.ratio
    assert d["scene"]["covering"]["youngs_modulus_Pa"] == 5e6 and d["scene"]["contact"] == "clamped"
    assert r.criteria.startswith("ISO/TS 15066:2016") and "quasi-static" in r.criteria
    assert r.safe == r.admissible and "time_path" not in d and "history" not in d
    table = covopt.speed_limit(Scene(robot_mass=10, **COVERED), body_region=["chest", "pelvis"])
    assert isinstance(table, covopt.BodyRegionSpeedLimitTable)
    assert [row.region for row in table] == ["chest", "pelvis"] and table[1].area == "pelvic-bone"
    assert table.to_dict()["rows"][0]["bare_max_speed_m_per_s"] == table[0].bare_max_speed_m_per_s
    assert any("no contact_area" in w for w in table.warnings)  # the bare column: the force's alone


def test_contact_area_gives_the_bare_robot_s_pressure():
    r = covopt.simulate(Scene(robot_mass=10, speed=0.5, **BARE), body_region="chest", contact_area=1e-4)
    assert r.peak_pressure_Pa == pytest.approx(r.peak_force_N / 1e-4, rel=1e-15)
    for area in (1e-4, "1cm2", "100mm2", "1 cm2"):  # a string is read with its unit, as the CLI's
        row, = covopt.speed_limit(Scene(robot_mass=10, **BARE), body_region="chest", contact_area=area)
        # 1 cm²: 240 N/cm² binds before 280 N
        assert row.bare_limited_by == "pressure"
        assert row.bare_max_speed_m_per_s == pytest.approx(240 / math.sqrt(8 * 25e3), rel=1e-12)


@pytest.mark.parametrize("call", [
    lambda: covopt.simulate(Scene(robot_mass=10, speed=0.5, **BARE), body_region="chest"),
    lambda: covopt.speed_limit(Scene(robot_mass=10, **BARE), body_region=["chest", "pelvis"]),
    lambda: covopt.sweep(("speed", [0.2, 0.4]), scene=Scene(**BARE), body_region="chest"),
])
def test_the_bare_robot_s_own_verdict_needs_its_contact_area(call):
    with pytest.raises(ValueError, match="contact_area is needed for the bare robot on chest"):
        call()


def test_with_a_covering_the_bare_column_is_the_force_s_alone_with_a_warning():
    row, = covopt.speed_limit(Scene(robot_mass=10, **COVERED), body_region="chest")
    assert row.bare_limited_by == "force"
    assert row.bare_max_speed_m_per_s == pytest.approx(280 / math.sqrt(8 * 25e3), rel=1e-12)
    with_area, = covopt.speed_limit(Scene(robot_mass=10, **COVERED), body_region="chest", contact_area="1cm2")
    assert with_area.bare_limited_by == "pressure" and with_area.covered_max_speed_m_per_s == row.covered_max_speed_m_per_s


@pytest.mark.parametrize("call, message", [
    (lambda: covopt.simulate(Scene(**BARE), body_region="chset", contact_area=1e-4),
     "body region 'chset' is not in ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M; did you mean 'chest'?"),
    (lambda: covopt.simulate(Scene(**BARE), body_region="face", contact_area=1e-4),
     "ISO/TS 15066:2016 A.3.2 (= ISO 10218-2:2025 Annex M) does not permit transient contact with the face; use contact='clamped', or "
     "judge the head with Park et al.'s skin model (body_region='head')"),
    (lambda: covopt.speed_limit(Scene(**BARE), body_region="chest", body_area="palm"),
     "body area 'palm' is not an area of 'chest'"),
    (lambda: covopt.simulate(Scene(robot_radius="flat"), body_region="chest"),
     "robot.radius: a covering needs the radius of the robot surface under it"),
    (lambda: covopt.simulate(Scene(robot_mass="fixed", **BARE), body_region="chest", contact="clamped",
                             contact_area=1e-4),
     "robot.mass: a clamped contact needs a robot that moves"),
    (lambda: covopt.simulate(Scene(), body_region="chest", contact="sideways"),
     "contact: expected 'transient' or 'clamped' (got 'sideways')"),
    (lambda: covopt.simulate(Scene(head_mass=4.0), body_region="chest"),
     "head_mass: body_region='chest' does not read it"),
    (lambda: covopt.simulate(Scene(), contact="clamped"), "contact applies to an ISO/TS 15066 body region"),
    (lambda: covopt.simulate(Scene(), body_region="chest", contact_area="5m2"),
     "contact_area must be in [1 mm², 1 m²]"),
    (lambda: covopt.simulate(Scene(), body_region="chest", contact_area="1 parsec"), "contact_area"),
    (lambda: covopt.simulate(Scene(), body_region="chest", contact_area=[1e-4]), "contact_area: expected a number"),
    (lambda: covopt.simulate(Scene(robot_mass=10, speed=0.5, **BARE), body_region="chest"),
     "contact_area is needed for the bare robot on chest"),
    (lambda: covopt.speed_limit(Scene(speed=1.0), body_region="chest"), "drop speed from the scene"),
    (lambda: covopt.simulate(Scene(), body_region="all"), "body_region: simulate takes one region"),
    (lambda: covopt.optimize(Scene(covering_thickness="5mm"), body_region="chest"),
     "covering_thickness: the covering is what optimize designs"),
])
def test_bad_input_raises_value_error_with_the_message(call, message):
    with pytest.raises(ValueError) as error:
        call()
    assert message in str(error.value)
    assert "\n" not in str(error.value)
