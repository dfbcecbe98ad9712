// The body-region contact's exact path (docs/model.md §13): the bare robot is ISO/TS 15066
// Annex A exactly, the energy balance holds at the computed peak, an independent bisection on
// the balance written out here finds the same force, the Hertz pressure equals the textbook
// sphere-on-flat peak pressure, the trends the model must show (a softer covering lowers the
// force until it bottoms out, clamped is stricter than transient), and bad scenes are refused
// naming the field.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include <covopt/core/body_contact.hpp>

namespace {

using covopt::BodyContactModel;
using covopt::BodyContactScene;
using covopt::ContactType;

BodyContactScene Chest(double robot_mass_kg, double speed_m_per_s) {
  BodyContactScene s;
  s.robot_mass_kg = robot_mass_kg;
  s.speed_m_per_s = speed_m_per_s;
  s.body_stiffness_N_per_m = 25e3;  // chest, Table A.3
  s.body_mass_kg = 40.0;
  return s;
}

BodyContactScene Covered(double modulus_Pa, double thickness_m, double radius_m, double speed) {
  BodyContactScene s = Chest(10.0, speed);
  s.robot_radius_m = radius_m;
  s.covering = {modulus_Pa, 0.3, thickness_m};
  return s;
}

/// The stored energy written out independently of the library [J].
double StoredEnergy(const BodyContactScene& s, double force_N) {
  const double e_star = s.covering.youngs_modulus_Pa / (1.0 - std::pow(s.covering.poisson_ratio, 2));
  const double k_c = 4.0 / 3.0 * e_star * std::sqrt(s.robot_radius_m + s.covering.thickness_m);
  const double f_b = k_c * std::pow(0.8 * s.covering.thickness_m, 1.5);
  const double f = std::min(force_N, f_b);
  return force_N * force_N / (2.0 * s.body_stiffness_N_per_m) +
         0.4 * std::pow(k_c, -2.0 / 3.0) * std::pow(f, 5.0 / 3.0);
}

double BisectForce(const BodyContactScene& s, double energy_J) {
  double lo = 0.0;
  double hi = 1.0;
  while (StoredEnergy(s, hi) < energy_J) hi *= 2.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (StoredEnergy(s, mid) < energy_J ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

TEST_CASE("the bare robot's peak force is ISO/TS 15066 Annex A's v sqrt(mu k) exactly", "[body_contact]") {
  const double speed = GENERATE(0.1, 0.626099, 1.5);
  const double robot_mass = GENERATE(2.0, 10.0, 80.0);
  const BodyContactScene scene = Chest(robot_mass, speed);
  const covopt::BodyContactResult r = covopt::Solve(scene);
  const double mu = 1.0 / (1.0 / robot_mass + 1.0 / 40.0);
  CHECK(r.reduced_mass_kg == Approx(mu).epsilon(1e-15));
  CHECK(r.peak_force_N == Approx(speed * std::sqrt(mu * 25e3)).epsilon(1e-14));
  // E = F²/(2k) = ½ μ v².
  CHECK(r.body_energy_J == Approx(0.5 * mu * speed * speed).epsilon(1e-14));
  CHECK(r.covering_energy_J == Approx(0.0).margin(1e-15));
  CHECK_FALSE(r.peak_pressure_Pa.has_value());  // no contact area given: not evaluated
  REQUIRE(r.contact_duration_s.has_value());
  CHECK(*r.contact_duration_s == Approx(std::numbers::pi * std::sqrt(mu / 25e3)).epsilon(1e-14));
}

TEST_CASE("the annex's check number: 280 N on the chest is reached at 0.626099 m/s by a 10 kg robot", "[body_contact]") {
  const covopt::BodyContactResult r = covopt::Solve(Chest(10.0, 0.626099));
  CHECK(r.peak_force_N == Approx(280.0).epsilon(1e-6));
}

TEST_CASE("the bare robot's pressure is the force over the given contact area", "[body_contact]") {
  BodyContactScene s = Chest(10.0, 0.5);
  s.contact_area_m2 = 1e-4;  // 1 cm²
  const covopt::BodyContactResult r = covopt::Solve(s);
  REQUIRE(r.peak_pressure_Pa.has_value());
  CHECK(*r.peak_pressure_Pa == Approx(r.peak_force_N / 1e-4).epsilon(1e-15));
}

TEST_CASE("with a covering the energy balance holds at the peak, as an independent bisection finds it", "[body_contact]") {
  const double modulus = GENERATE(0.05e6, 0.5e6, 5e6, 27.6e6, 1e9);
  const double thickness = GENERATE(1e-3, 5e-3, 20e-3);
  const double speed = GENERATE(0.05, 0.5, 3.0);
  const BodyContactScene s = Covered(modulus, thickness, 0.04, speed);
  const BodyContactModel model = BodyContactModel::FromScene(s);
  const covopt::BodyContactResult r = covopt::Solve(model);
  INFO("E " << modulus << " b " << thickness << " v " << speed);
  CHECK(model.EnergyAtForce(r.peak_force_N) == Approx(r.energy_transferred_J).epsilon(1e-13));
  CHECK(StoredEnergy(s, r.peak_force_N) == Approx(r.energy_transferred_J).epsilon(1e-12));
  CHECK(r.peak_force_N == Approx(BisectForce(s, r.energy_transferred_J)).epsilon(1e-12));
  CHECK(r.body_energy_J + r.covering_energy_J == Approx(r.energy_transferred_J).epsilon(1e-13));
  CHECK(r.max_approach_m == Approx(model.ApproachAtForce(r.peak_force_N)).epsilon(1e-15));
  CHECK(r.fully_compressed == (r.peak_force_N > model.bottom_out_force_N()));
  CHECK(r.compression_ratio <= 1.0);
  CHECK(r.compression_ratio > 0.0);
}

TEST_CASE("the covering's pressure is the textbook Hertz sphere-on-flat peak pressure", "[body_contact]") {
  // p0 = (6 F E*² / (π³ R²))^(1/3) for a sphere of radius R and reduced modulus E* on a rigid flat.
  const double modulus = GENERATE(0.5e6, 27.6e6);
  const BodyContactScene s = Covered(modulus, 10e-3, 0.04, 0.3);
  const covopt::BodyContactResult r = covopt::Solve(s);
  REQUIRE_FALSE(r.fully_compressed);
  const double e_star = modulus / (1.0 - 0.09);
  const double radius = 0.05;
  const double p0 = std::cbrt(6.0 * r.peak_force_N * e_star * e_star /
                              (std::pow(std::numbers::pi, 3) * radius * radius));
  REQUIRE(r.peak_pressure_Pa.has_value());
  CHECK(*r.peak_pressure_Pa == Approx(p0).epsilon(1e-12));
  CHECK(r.contact_radius_m == Approx(std::cbrt(0.75 * r.peak_force_N * radius / e_star)).epsilon(1e-12));
}

TEST_CASE("a softer covering lowers the peak force below the bare robot's until it bottoms out", "[body_contact]") {
  const double bare = covopt::Solve(Chest(10.0, 1.0)).peak_force_N;
  double previous = bare;
  for (const double modulus : {1e9, 1e8, 1e7, 1e6}) {
    const covopt::BodyContactResult r = covopt::Solve(Covered(modulus, 20e-3, 0.04, 1.0));
    INFO("E " << modulus);
    REQUIRE_FALSE(r.fully_compressed);
    CHECK(r.peak_force_N < previous);
    previous = r.peak_force_N;
  }
  // Much softer: the covering bottoms out and the force rises again toward the bare value
  // (the covering's stored energy is capped at 2/5 F_b (0.8 b_c)).
  const covopt::BodyContactResult crushed = covopt::Solve(Covered(1e3, 20e-3, 0.04, 1.0));
  CHECK(crushed.fully_compressed);
  CHECK(crushed.compression_ratio == 1.0);
  CHECK(crushed.peak_force_N > previous);
  CHECK(crushed.peak_force_N < bare);
}

TEST_CASE("clamped contact gives a larger force than transient for the same robot", "[body_contact]") {
  const double modulus = GENERATE(0.0, 1e6);
  BodyContactScene s = modulus > 0.0 ? Covered(modulus, 10e-3, 0.04, 0.4) : Chest(10.0, 0.4);
  const double transient = covopt::Solve(s).peak_force_N;
  s.contact = ContactType::kClamped;
  const covopt::BodyContactResult clamped = covopt::Solve(s);
  CHECK(clamped.reduced_mass_kg == 10.0);
  CHECK(clamped.peak_force_N > transient);
}

TEST_CASE("a fixed robot against a free region: the region's mass alone", "[body_contact]") {
  BodyContactScene s = Chest(covopt::kFixed, 0.3);
  CHECK(covopt::Solve(s).reduced_mass_kg == 40.0);
}

TEST_CASE("bad body-contact scenes are refused naming the field and the range", "[body_contact]") {
  auto refused = [](const BodyContactScene& s, const std::string& fragment) {
    try {
      (void)BodyContactModel::FromScene(s);
    } catch (const std::invalid_argument& e) {
      INFO(e.what());
      CHECK(std::string(e.what()).find(fragment) != std::string::npos);
      return;
    }
    FAIL("accepted a bad scene, expected: " << fragment);
  };
  BodyContactScene flat = Chest(10.0, 0.5);
  flat.covering.thickness_m = 5e-3;
  refused(flat, "robot.radius: a covering needs the radius");
  BodyContactScene nan_mass = Chest(std::nan(""), 0.5);
  refused(nan_mass, "robot.mass must be in [0.001, 1e+06] kg");
  refused(Chest(10.0, 0.0), "robot.speed must be in [1e-06, 100] m/s");
  BodyContactScene both_fixed = Chest(covopt::kFixed, 0.5);
  both_fixed.contact = ContactType::kClamped;
  refused(both_fixed, "both be immovable");
  BodyContactScene fixed_body = Chest(10.0, 0.5);
  fixed_body.body_mass_kg = covopt::kFixed;
  refused(fixed_body, "contact clamped");
  BodyContactScene area = Chest(10.0, 0.5);
  area.contact_area_m2 = -1.0;
  refused(area, "contact_area must be 0 (not given) or in [1e-06, 1] m2");
  BodyContactScene spring = Chest(10.0, 0.5);
  spring.body_stiffness_N_per_m = 0.0;
  refused(spring, "body.stiffness must be in (0, 1e+09] N/m");
}

TEST_CASE("the exact path refuses a history, which needs the time path", "[body_contact]") {
  covopt::SolveOptions options;
  options.path = covopt::PathChoice::kExact;
  options.record_history = true;
  CHECK_THROWS_WITH(covopt::Solve(Chest(10.0, 0.5), options),
                    Catch::Contains("a history needs the time path"));
}

TEST_CASE("the check numbers of docs/model.md §13, computed by docs/validation/body_regions.py", "[body_contact]") {
  // Robot 10 kg at 0.25 m/s, transient. The script solves the balance by bisection (not the
  // library's Newton iteration) and prints 9 digits.
  struct Check {
    double modulus_Pa, poisson, thickness_m, radius_m, stiffness_N_per_m, body_mass_kg;
    double covering_stiffness, bottom_out_force_N, force_N, pressure_Pa, deflection_m;
  };
  const Check check = GENERATE(
      Check{0.5e6, 0.3, 10e-3, 0.04, 25e3, 40.0, 163814.504, 117.216117, 68.9529000, 0.117234957e6, 5.61651328e-3},
      Check{0.5e6, 0.3, 20e-3, 0.04, 25e3, 40.0, 179449.798, 363.180856, 70.394744, 0.104535916e6, 5.35876658e-3},
      Check{27.6e6, 0.25, 5e-3, 0.015, 25e3, 40.0, 5551259.64, 1404.36995, 104.932384, 3.53027819e6, 0.709597373e-3},
      Check{0.5e6, 0.3, 20e-3, 0.04, 75e3, 0.6, 179449.798, 363.180856, 17.9911007, 0.0663393732e6, 2.15812456e-3});
  BodyContactScene s = Covered(check.modulus_Pa, check.thickness_m, check.radius_m, 0.25);
  s.covering.poisson_ratio = check.poisson;
  s.body_stiffness_N_per_m = check.stiffness_N_per_m;
  s.body_mass_kg = check.body_mass_kg;
  const BodyContactModel model = BodyContactModel::FromScene(s);
  CHECK(model.covering_stiffness() == Approx(check.covering_stiffness).epsilon(1e-8));
  CHECK(model.bottom_out_force_N() == Approx(check.bottom_out_force_N).epsilon(1e-8));
  const covopt::BodyContactResult r = covopt::Solve(model);
  CHECK(r.peak_force_N == Approx(check.force_N).epsilon(1e-8));
  REQUIRE(r.peak_pressure_Pa.has_value());
  CHECK(*r.peak_pressure_Pa == Approx(check.pressure_Pa).epsilon(1e-8));
  CHECK(r.covering_deflection_m == Approx(check.deflection_m).epsilon(1e-8));
}
