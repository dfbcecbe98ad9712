// The body-region contact with a foam covering (docs/model.md §15): the law is chosen from the
// covering (auto/foam/hertz), the exact path agrees with an independent reference written out
// here (the pressure of every column integrated over the contact, the columns' energy likewise,
// and bisection on the energy balance), on curved and flat faces, transient and clamped, within
// the curve and used up; the time path agrees with the exact path; a covering never reads worse
// than the bare robot; thicker foam never lowers the force-limited speed; the round check numbers of model.md §15.7.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <covopt/core/body_contact.hpp>
#include <covopt/core/compressive_curve.hpp>

namespace {

using covopt::BodyContactModel;
using covopt::BodyContactResult;
using covopt::BodyContactScene;
using covopt::CompressiveCurve;
using covopt::ContactType;
using covopt::CoveringLaw;
using covopt::StrainStressPoint;

/// VN600 vinyl-nitrile (NIST foam_db, quasi-static): the eleven rounded points of model.md §15.7 [kPa].
std::shared_ptr<const CompressiveCurve> Vn600() {
  static const std::vector<StrainStressPoint> kPoints{
      {0.02, 14.3e3}, {0.05, 22.0e3}, {0.10, 30.2e3},  {0.15, 37.4e3},  {0.20, 45.9e3}, {0.25, 57.3e3},
      {0.30, 72.2e3}, {0.35, 91.6e3}, {0.40, 118.0e3}, {0.45, 153.2e3}, {0.49, 189.5e3}};
  static const auto curve = std::make_shared<const CompressiveCurve>(CompressiveCurve::FromPoints(kPoints));
  return curve;
}
/// The six points the round check numbers of model.md §15.7 were computed with (2/5/10/25/40/49 %).
std::shared_ptr<const CompressiveCurve> Vn600SixPoints() {
  static const std::vector<StrainStressPoint> kPoints{{0.02, 14.3e3}, {0.05, 22.0e3},  {0.10, 30.2e3},
                                                      {0.25, 57.3e3}, {0.40, 118.0e3}, {0.49, 189.5e3}};
  static const auto curve = std::make_shared<const CompressiveCurve>(CompressiveCurve::FromPoints(kPoints));
  return curve;
}
/// A stiff foam with a plateau (a flat face's force is then constant over a range of d).
std::shared_ptr<const CompressiveCurve> PlateauFoam() {
  static const std::vector<StrainStressPoint> kPoints{{0.05, 400e3}, {0.6, 400e3}, {0.8, 3e6}};
  static const auto curve = std::make_shared<const CompressiveCurve>(CompressiveCurve::FromPoints(kPoints));
  return curve;
}

/// The hand (Table A.3: 75 N/mm, 0.6 kg), a 10 kg robot, transient.
BodyContactScene Hand(double speed, double radius_m, double thickness_m,
                      std::shared_ptr<const CompressiveCurve> curve = Vn600()) {
  BodyContactScene s;
  s.robot_mass_kg = 10.0;
  s.speed_m_per_s = speed;
  s.robot_radius_m = radius_m;
  s.body_stiffness_N_per_m = 75e3;
  s.body_mass_kg = 0.6;
  s.covering = covopt::CoveringSpec{.youngs_modulus_Pa = 1e6, .poisson_ratio = 0.3, .thickness_m = thickness_m};
  s.covering.compressive_curve = std::move(curve);
  return s;
}

// ---- The independent reference -------------------------------------------------------------

/// σ(ε) by linear interpolation through (0, 0) and the points, flat past the last [Pa].
double Stress(const CompressiveCurve& c, double e) {
  double e0 = 0.0, s0 = 0.0;
  for (const StrainStressPoint& p : c.points()) {
    if (e <= p.strain) return s0 + (p.stress_Pa - s0) * (std::max(e, 0.0) - e0) / (p.strain - e0);
    e0 = p.strain;
    s0 = p.stress_Pa;
  }
  return s0;
}
/// W(ε) by the trapezoid rule on the pieces (exact for a linear piece) [J/m³].
double EnergyDensity(const CompressiveCurve& c, double e) {
  double w = 0.0, e0 = 0.0;
  for (const StrainStressPoint& p : c.points()) {
    const double e1 = std::min(e, p.strain);
    if (e1 <= e0) break;
    w += 0.5 * (Stress(c, e0) + Stress(c, e1)) * (e1 - e0);
    e0 = p.strain;
  }
  return w;
}
/// Composite Simpson of f over [a, b] with n (even) intervals.
template <typename F>
double Simpson(F f, double a, double b, int n = 4000) {
  const double step = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(a + i * step);
  return sum * step / 3.0;
}

/// The foam's force and stored energy at compression d, from the columns: on a curved face each
/// column at radius r is compressed by w(r) = d - r²/(2 R_c) (strain w/h), pushes with σ(w/h)
/// and stores h W(w/h) per unit area; on a flat face every column has w = d over the area A.
struct Foam {
  const BodyContactScene& s;
  double Force(double d) const {
    const CompressiveCurve& c = *s.covering.compressive_curve;
    const double h = s.covering.thickness_m;
    if (std::isinf(s.robot_radius_m)) return s.contact_area_m2 * Stress(c, d / h);
    const double rc = s.robot_radius_m + h;
    return Simpson([&](double r) { return Stress(c, (d - r * r / (2.0 * rc)) / h) * 2.0 * std::numbers::pi * r; }, 0.0,
                   std::sqrt(2.0 * rc * d));
  }
  double Energy(double d) const {
    const CompressiveCurve& c = *s.covering.compressive_curve;
    const double h = s.covering.thickness_m;
    if (std::isinf(s.robot_radius_m)) return s.contact_area_m2 * h * EnergyDensity(c, d / h);
    const double rc = s.robot_radius_m + h;
    return Simpson(
        [&](double r) { return h * EnergyDensity(c, (d - r * r / (2.0 * rc)) / h) * 2.0 * std::numbers::pi * r; },
        0.0, std::sqrt(2.0 * rc * d));
  }
  double Stored(double d) const {
    const double f = Force(d);
    return Energy(d) + f * f / (2.0 * s.body_stiffness_N_per_m);
  }
  double EndDeflection() const { return s.covering.compressive_curve->last_strain() * s.covering.thickness_m; }
  /// The peak force of the energy balance: bisection on d within the curve, the stop past it.
  double PeakForce() const {
    const double mu = s.contact == ContactType::kClamped ? s.robot_mass_kg
                                                         : 1.0 / (1.0 / s.robot_mass_kg + 1.0 / s.body_mass_kg);
    const double energy = 0.5 * mu * s.speed_m_per_s * s.speed_m_per_s;
    const double end = EndDeflection();
    if (energy >= Stored(end)) return std::sqrt(2.0 * s.body_stiffness_N_per_m * (energy - Energy(end)));
    double lo = 0.0, hi = end;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      (Stored(mid) < energy ? lo : hi) = mid;
    }
    return Force(0.5 * (lo + hi));
  }
};

double Mu(const BodyContactScene& s) {
  return s.contact == ContactType::kClamped ? s.robot_mass_kg : 1.0 / (1.0 / s.robot_mass_kg + 1.0 / s.body_mass_kg);
}

}  // namespace

TEST_CASE("Foam body contact: the law follows the covering (auto, foam, hertz), bad combinations refused",
          "[body_contact][foam]") {
  BodyContactScene foam = Hand(1.0, 0.015, 0.02);
  CHECK(BodyContactModel::FromScene(foam).foam());
  const BodyContactResult r = covopt::Solve(foam);
  REQUIRE(r.covering_law);
  CHECK(*r.covering_law == CoveringLaw::kFoam);

  // kHertz with a curve: bit-identical to the same covering without one.
  BodyContactScene hertz = foam;
  hertz.covering.law = CoveringLaw::kHertz;
  BodyContactScene plain = foam;
  plain.covering.compressive_curve.reset();
  const BodyContactResult a = covopt::Solve(hertz), b = covopt::Solve(plain);
  CHECK(a.peak_force_N == b.peak_force_N);
  CHECK(a.peak_pressure_Pa == b.peak_pressure_Pa);
  CHECK(a.covering_deflection_m == b.covering_deflection_m);
  CHECK(*a.covering_law == CoveringLaw::kHertz);
  CHECK(*b.covering_law == CoveringLaw::kHertz);

  BodyContactScene no_curve = plain;
  no_curve.covering.law = CoveringLaw::kFoam;
  CHECK_THROWS_WITH(BodyContactModel::FromScene(no_curve), Catch::Contains("covering.law"));

  BodyContactScene flat = foam;
  flat.robot_radius_m = covopt::kFlat;
  CHECK_THROWS_WITH(BodyContactModel::FromScene(flat), Catch::Contains("contact_area"));
  flat.contact_area_m2 = 4e-4;
  CHECK_NOTHROW(BodyContactModel::FromScene(flat));
  // The foam law reads no modulus: a covering given by its curve alone is accepted.
  flat.covering.youngs_modulus_Pa = 0.0;
  CHECK_NOTHROW(BodyContactModel::FromScene(flat));
  // Bare: no law.
  BodyContactScene bare = foam;
  bare.covering.thickness_m = 0.0;
  CHECK_FALSE(covopt::Solve(bare).covering_law.has_value());
}

TEST_CASE("Foam body contact: the exact path agrees with the columns integrated and bisection on the balance",
          "[body_contact][foam]") {
  struct Case {
    double radius_m;
    double area_m2;
    ContactType contact;
    double thickness_m;
  };
  const Case cases[] = {
      {0.015, 0.0, ContactType::kTransient, 0.04}, {0.015, 0.0, ContactType::kClamped, 0.02},
      {0.05, 2e-4, ContactType::kTransient, 0.01}, {covopt::kFlat, 4e-4, ContactType::kTransient, 0.02},
      {covopt::kFlat, 1e-3, ContactType::kClamped, 0.01},
  };
  for (const Case& c : cases) {
    for (double speed : {0.05, 0.3, 0.8, 1.5, 3.0}) {
      BodyContactScene s = Hand(speed, c.radius_m, c.thickness_m);
      s.contact_area_m2 = c.area_m2;
      s.contact = c.contact;
      const BodyContactResult r = covopt::Solve(s);
      const Foam reference{s};
      INFO("radius " << c.radius_m << " thickness " << c.thickness_m << " speed " << speed << " "
                     << covopt::ToString(c.contact));
      CHECK(r.peak_force_N == Approx(reference.PeakForce()).epsilon(1e-7));
      // The energy balance at the computed peak, and the fields.
      CHECK(r.body_energy_J + r.covering_energy_J == Approx(0.5 * Mu(s) * speed * speed).epsilon(1e-12));
      CHECK(r.peak_strain == Approx(r.covering_deflection_m / c.thickness_m).epsilon(1e-15));
      if (r.fully_compressed) {
        CHECK(r.covering_deflection_m == Approx(reference.EndDeflection()).epsilon(1e-15));
        CHECK(r.energy_past_stop_J > 0.0);
        CHECK(r.compression_ratio == 1.0);
      } else {
        CHECK(r.covering_energy_J == Approx(reference.Energy(r.covering_deflection_m)).epsilon(1e-7));
        CHECK(r.energy_past_stop_J == 0.0);
        CHECK(r.compression_ratio < 1.0);
      }
      if (std::isinf(c.radius_m)) {
        CHECK(*r.peak_pressure_Pa == Approx(r.peak_force_N / c.area_m2).epsilon(1e-14));
      } else if (!r.fully_compressed) {
        CHECK(*r.peak_pressure_Pa == Approx(Stress(*s.covering.compressive_curve, r.peak_strain)).epsilon(1e-12));
        CHECK(r.contact_radius_m ==
              Approx(std::sqrt(2.0 * (c.radius_m + c.thickness_m) * r.covering_deflection_m)).epsilon(1e-14));
      } else if (c.area_m2 > 0.0) {
        // Past the stop on a curved face: σ_end plus the bare robot's rule for the rest.
        const BodyContactModel m = BodyContactModel::FromScene(s);
        CHECK(r.pressure_past_stop);
        CHECK(*r.peak_pressure_Pa == Approx(189.5e3 + (r.peak_force_N - m.bottom_out_force_N()) / c.area_m2));
      } else {
        CHECK_FALSE(r.peak_pressure_Pa.has_value());
        CHECK(r.pressure_past_stop);
      }
      CHECK(r.validity.within);
      CHECK_FALSE(r.validity.note.empty());
    }
  }
}

TEST_CASE("Foam body contact: a plateau of the curve on a flat face (force constant over a range of d)",
          "[body_contact][foam]") {
  BodyContactScene s = Hand(0.2, covopt::kFlat, 0.02, PlateauFoam());
  s.contact_area_m2 = 5e-4;  // F = 200 N on the plateau
  const BodyContactModel m = BodyContactModel::FromScene(s);
  // The last compression with 200 N is the plateau's end (0.6 h): the largest energy.
  CHECK(m.CoveringDeflectionAtForce(200.0) == Approx(0.6 * 0.02).epsilon(1e-14));
  CHECK(m.EnergyAtForce(200.0) == Approx(m.EnergyAtDeflection(0.6 * 0.02)).epsilon(1e-14));
  for (double speed : {0.2, 0.5, 1.0, 2.0}) {
    s.speed_m_per_s = speed;
    const Foam reference{s};
    CHECK(covopt::Solve(s).peak_force_N == Approx(reference.PeakForce()).epsilon(1e-9));
  }
}

TEST_CASE("Foam body contact: the time path agrees with the exact path, within the curve and used up",
          "[body_contact][foam][time_path]") {
  covopt::SolveOptions time;
  time.path = covopt::PathChoice::kTimePath;
  time.time_path.relative_tolerance = 1e-10;
  struct Case {
    double radius_m;
    double area_m2;
    ContactType contact;
    double speed;  // 0.3: within the curve; 2.5: used up (10 mm)
  };
  const Case cases[] = {
      {0.015, 0.0, ContactType::kTransient, 0.3},    {0.015, 0.0, ContactType::kTransient, 2.5},
      {0.015, 2e-4, ContactType::kClamped, 0.1},     {0.015, 2e-4, ContactType::kClamped, 1.0},
      {covopt::kFlat, 4e-4, ContactType::kTransient, 0.3}, {covopt::kFlat, 4e-4, ContactType::kClamped, 2.5},
  };
  for (const Case& c : cases) {
    BodyContactScene s = Hand(c.speed, c.radius_m, 0.01);
    s.contact_area_m2 = c.area_m2;
    s.contact = c.contact;
    const BodyContactResult exact = covopt::Solve(s);
    const BodyContactResult path = covopt::Solve(s, time);
    INFO("radius " << c.radius_m << " speed " << c.speed << " " << covopt::ToString(c.contact));
    REQUIRE(path.ok());
    CHECK(path.fully_compressed == exact.fully_compressed);
    // The time path keeps its tolerance (1e-10): it restarts at every point of the curve.
    CHECK(path.peak_force_N == Approx(exact.peak_force_N).epsilon(1e-8));
    CHECK(path.covering_deflection_m == Approx(exact.covering_deflection_m).epsilon(1e-8));
    CHECK(path.max_approach_m == Approx(exact.max_approach_m).epsilon(1e-8));
    CHECK(path.warnings.empty());
    CHECK(*path.covering_law == CoveringLaw::kFoam);
    CHECK(path.rebound_speed_m_per_s == Approx(c.speed).epsilon(1e-8));
    CHECK(*path.energy_residual < 1e-8);
  }
}

TEST_CASE("Foam body contact: a braking robot (time path only) lowers the peak", "[body_contact][foam][time_path]") {
  BodyContactScene s = Hand(1.5, 0.015, 0.02);
  const BodyContactResult unbraked = covopt::Solve(s);
  s.reaction_delay_s = 0.002;
  s.braking_m_per_s2 = 200.0;
  const BodyContactResult braked = covopt::Solve(s);
  REQUIRE(braked.ok());
  CHECK(braked.method.find("time path") != std::string::npos);
  CHECK(braked.peak_force_N < unbraked.peak_force_N);
  CHECK(*braked.energy_residual < 1e-6);  // 100 rtol: the time path's own tolerance check
  CHECK(braked.warnings.empty());
  covopt::SolveOptions exact;
  exact.path = covopt::PathChoice::kExact;
  CHECK_THROWS_AS(covopt::Solve(s, exact), std::invalid_argument);
}

TEST_CASE("Foam body contact: a covering never reads worse than the bare robot", "[body_contact][foam]") {
  const std::shared_ptr<const CompressiveCurve> curves[] = {
      Vn600(), PlateauFoam(), std::make_shared<const CompressiveCurve>(Vn600()->Scaled(40.0))};
  for (const auto& curve : curves) {
    for (double radius : {0.005, 0.02, 0.1, covopt::kFlat}) {
      for (double thickness : {0.002, 0.01, 0.03}) {
        for (double speed : {0.05, 0.25, 1.0, 2.5}) {
          for (ContactType contact : {ContactType::kTransient, ContactType::kClamped}) {
            BodyContactScene s = Hand(speed, radius, thickness, curve);
            s.contact = contact;
            s.contact_area_m2 = 2e-4;
            BodyContactScene bare = s;
            bare.covering.thickness_m = 0.0;
            const BodyContactResult covered = covopt::Solve(s), naked = covopt::Solve(bare);
            INFO("radius " << radius << " thickness " << thickness << " speed " << speed);
            CHECK(covered.peak_force_N <= naked.peak_force_N);
            if (std::isinf(radius)) CHECK(*covered.peak_pressure_Pa <= *naked.peak_pressure_Pa);
          }
        }
      }
    }
  }
}

TEST_CASE("Foam body contact: thicker foam never lowers the force-limited speed", "[body_contact][foam]") {
  for (double radius : {0.005, 0.015, 0.05, covopt::kFlat}) {
    double previous = 0.0;
    for (double thickness = 0.001; thickness <= 0.08; thickness *= 1.25) {
      BodyContactScene s = Hand(1.0, radius, thickness);
      s.contact_area_m2 = 4e-4;
      const double speed = BodyContactModel::FromScene(s).SpeedAtPeakForce(280.0);
      INFO("radius " << radius << " thickness " << thickness);
      CHECK(speed >= previous);
      previous = speed;
    }
  }
}

TEST_CASE("Foam body contact: the round check numbers (VN600, hand, 10 kg, R_r 15 mm, transient)",
          "[body_contact][foam]") {
  // 280 N: the hand's transient force limit (2 x 140 N, Table A.2).
  const double bare = BodyContactModel::FromScene(Hand(1.0, 0.015, 0.0)).SpeedAtPeakForce(280.0);
  CHECK(bare == Approx(1.35895).epsilon(1e-5));
  // With the six points of the round numbers: 2.67 m/s (40 mm), used up at 0.62 m/s and force-limited
  // at 1.47 m/s (10 mm), 1.89 m/s (20 mm).
  auto model = [](double thickness, std::shared_ptr<const CompressiveCurve> curve) {
    return BodyContactModel::FromScene(Hand(1.0, 0.015, thickness, std::move(curve)));
  };
  auto used_up = [](const BodyContactModel& m) { return std::sqrt(2.0 * m.bottom_out_energy_J() / m.reduced_mass_kg()); };
  CHECK(model(0.04, Vn600SixPoints()).SpeedAtPeakForce(280.0) == Approx(2.6727).epsilon(2e-4));
  CHECK(used_up(model(0.01, Vn600SixPoints())) == Approx(0.6154).epsilon(2e-4));
  CHECK(model(0.01, Vn600SixPoints()).SpeedAtPeakForce(280.0) == Approx(1.4670).epsilon(2e-4));
  CHECK(model(0.02, Vn600SixPoints()).SpeedAtPeakForce(280.0) == Approx(1.8859).epsilon(2e-4));
  // The eleven points: the same against the reference of this file (bisection on d for 280 N).
  for (double thickness : {0.01, 0.02, 0.04}) {
    const BodyContactScene s = Hand(1.0, 0.015, thickness);
    const Foam reference{s};
    const double end = reference.EndDeflection();
    double energy = reference.Energy(end) + 280.0 * 280.0 / (2.0 * 75e3);
    if (reference.Force(end) > 280.0) {
      double lo = 0.0, hi = end;
      for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        (reference.Force(mid) < 280.0 ? lo : hi) = mid;
      }
      energy = reference.Stored(0.5 * (lo + hi));
    }
    const BodyContactModel m = model(thickness, Vn600());
    CHECK(m.SpeedAtPeakForce(280.0) == Approx(std::sqrt(2.0 * energy / Mu(s))).epsilon(1e-7));
    CHECK(used_up(m) == Approx(std::sqrt(2.0 * reference.Stored(end) / Mu(s))).epsilon(1e-7));
  }
  CHECK(model(0.04, Vn600()).SpeedAtPeakForce(280.0) == Approx(2.6935).epsilon(2e-4));
  CHECK(used_up(model(0.01, Vn600())) == Approx(0.6045).epsilon(2e-4));
  CHECK(model(0.01, Vn600()).SpeedAtPeakForce(280.0) == Approx(1.4638).epsilon(2e-4));
  CHECK(model(0.02, Vn600()).SpeedAtPeakForce(280.0) == Approx(1.8720).epsilon(2e-4));
}
