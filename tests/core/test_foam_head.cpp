// The foam law on the head (docs/model.md §16): the foam phase against an independent brute-force
// computation (the pressure σ(w(r)/h) integrated over the contact, the energy by quadrature, δ_max
// by bisection), the used-up layer against the bare robot's chain from the stop, exact path
// against time path, the law's choice and refusals, and the covering never reading worse than
// the bare robot.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "covopt/core.hpp"

namespace {

using covopt::CompressiveCurve;
using covopt::CoveringLaw;
using covopt::ImpactModel;
using covopt::ImpactPeaks;
using covopt::Scene;
using covopt::StrainStressPoint;

constexpr double kPi = std::numbers::pi;

/// NIST's quasi-static VN600 vinyl-nitrile curve (strain, Pa).
std::vector<StrainStressPoint> Vn600Points(double scale = 1.0) {
  std::vector<StrainStressPoint> points{
      {0.02, 14.3e3}, {0.05, 22.0e3}, {0.10, 30.2e3}, {0.15, 37.4e3}, {0.20, 45.9e3}, {0.25, 57.3e3},
      {0.30, 72.2e3}, {0.35, 91.6e3}, {0.40, 118.0e3}, {0.45, 153.2e3}, {0.49, 189.5e3}};
  for (StrainStressPoint& p : points) p.stress_Pa *= scale;
  return points;
}

std::shared_ptr<const CompressiveCurve> Vn600(double scale = 1.0) {
  return std::make_shared<const CompressiveCurve>(CompressiveCurve::FromPoints(Vn600Points(scale)));
}

/// The paper's scene (10 kg robot, R_r 15 mm, free 4.5 kg head) wearing `thickness` of a foam.
Scene FoamScene(double thickness_m, double speed_m_per_s, std::shared_ptr<const CompressiveCurve> curve = Vn600()) {
  Scene scene;
  scene.robot.speed_m_per_s = speed_m_per_s;
  scene.covering = covopt::CoveringSpec{
      .youngs_modulus_Pa = 1e6, .poisson_ratio = 0.0, .thickness_m = thickness_m, .compressive_curve = std::move(curve)};
  return scene;
}

double EffectiveMass(const Scene& s) { return 1.0 / (1.0 / s.robot.mass_kg + 1.0 / s.head.mass_kg); }

/// The test's own σ(ε): linear interpolation through (0, 0) and the points, written here.
double StressOf(const std::vector<StrainStressPoint>& points, double strain) {
  double e0 = 0.0, s0 = 0.0;
  for (const StrainStressPoint& p : points) {
    if (strain <= p.strain) return s0 + (p.stress_Pa - s0) * (strain - e0) / (p.strain - e0);
    e0 = p.strain;
    s0 = p.stress_Pa;
  }
  return s0;
}

/// Brute force of the foundation: F(d) = ∫₀^a σ(w(r)/h) 2π r dr with w = d − r²/(2R), a² = 2Rd
/// (midpoint rule in r), and U(d) = ∫₀^d F (midpoint rule).
struct BruteForceFoam {
  std::vector<StrainStressPoint> points;
  double h = 0.0, relative_radius = 0.0;
  double Force(double d) const {
    const double a = std::sqrt(2.0 * relative_radius * d);
    constexpr int kCells = 1000;
    double sum = 0.0;
    for (int i = 0; i < kCells; ++i) {
      const double r = (i + 0.5) * a / kCells;
      sum += StressOf(points, (d - r * r / (2.0 * relative_radius)) / h) * 2.0 * kPi * r;
    }
    return sum * a / kCells;
  }
  double Energy(double d) const {
    constexpr int kCells = 400;
    double sum = 0.0;
    for (int i = 0; i < kCells; ++i) sum += Force((i + 0.5) * d / kCells);
    return sum * d / kCells;
  }
  /// δ with U(δ) = energy, by bisection on [0, upper].
  double PenetrationAt(double energy, double upper) const {
    double lo = 0.0, hi = upper;
    for (int i = 0; i < 45; ++i) {
      const double mid = 0.5 * (lo + hi);
      (Energy(mid) < energy ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }
};

/// Hertz stiffness 4/3 ((1-ν1²)/E1 + (1-ν2²)/E2)⁻¹ c^(-1/2), written here.
double Hertz(double e1, double nu1, double e2, double nu2, double curvature) {
  return 4.0 / 3.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2) / std::sqrt(curvature);
}

covopt::TimeIntegrationOptions TimePath(covopt::ComputationMethod method, double rtol) {
  covopt::TimeIntegrationOptions options;
  options.method = method;
  options.relative_tolerance = rtol;
  options.record_history = true;
  return options;
}

}  // namespace

TEST_CASE("foam head: the foam phase agrees with the pressure integrated over the contact", "[foam_head]") {
  for (double h : {0.005, 0.02, 0.04}) {
    for (double v : {0.1, 0.3, 0.6}) {
      const Scene scene = FoamScene(h, v);
      const ImpactModel model = ImpactModel::FromScene(scene);
      REQUIRE(model.is_foam());
      const ImpactPeaks peaks = covopt::ExactPeaks(model);
      if (peaks.fully_compressed) continue;  // the bottomed cases have their own test
      CAPTURE(h, v);
      const double relative_radius = 1.0 / (1.0 / (0.015 + h) + 1.0 / 0.08);
      const BruteForceFoam brute{Vn600Points(), h, relative_radius};
      const double energy = 0.5 * EffectiveMass(scene) * v * v;
      const double delta = brute.PenetrationAt(energy, 0.49 * h);
      const double strain = delta / h;
      CHECK(peaks.max_penetration_m == Approx(delta).epsilon(2e-5));
      CHECK(peaks.peak_force_N == Approx(brute.Force(delta)).epsilon(5e-5));
      CHECK(peaks.max_compressive_stress_Pa == Approx(StressOf(Vn600Points(), strain)).epsilon(5e-5));
      // e = ∫ σ(δ/h) dδ and σ_t = (1 − 2ν_t) F/(2π a²), a² = 2 R δ.
      double e = 0.0;
      for (int i = 0; i < 20000; ++i) e += StressOf(Vn600Points(), (i + 0.5) * delta / 20000 / h);
      e *= delta / 20000;
      CHECK(peaks.max_energy_density_J_per_m2 == Approx(e).epsilon(5e-5));
      const double tensile = (1.0 - 2.0 * 0.42) * brute.Force(delta) / (2.0 * kPi * 2.0 * relative_radius * delta);
      CHECK(peaks.max_tensile_stress_Pa == Approx(tensile).epsilon(5e-5));
      CHECK(peaks.covering_strain_at_peak == Approx(strain).epsilon(2e-5));
      CHECK(peaks.covering_law == CoveringLaw::kFoam);
      CHECK(peaks.energy_past_stop_J == 0.0);
      const covopt::CoveringValidity validity = covopt::CoveringLawValidity(model, peaks);
      CHECK(validity.within);
      CHECK(validity.note.find("within the measured curve") != std::string::npos);
    }
  }
}

TEST_CASE("foam head: a used-up layer is a rigid stop and the bare robot's chain carries on", "[foam_head]") {
  // 5 mm of VN600 stores A h V(0.49) ≈ 0.05 J; 2 m/s brings 6.2 J: most of it passes the stop.
  for (double v : {0.5, 2.0, 4.0}) {
    const Scene scene = FoamScene(0.005, v);
    const ImpactModel model = ImpactModel::FromScene(scene);
    const ImpactPeaks peaks = covopt::ExactPeaks(model);
    CAPTURE(v);
    REQUIRE(peaks.fully_compressed);
    const double h = 0.005, stop = 0.49 * h;
    const double relative_radius = 1.0 / (1.0 / (0.015 + h) + 1.0 / 0.08);
    const BruteForceFoam brute{Vn600Points(), h, relative_radius};
    const double force_stop = brute.Force(stop), energy_stop = brute.Energy(stop);
    const double energy = 0.5 * EffectiveMass(scene) * v * v;
    CHECK(model.foam_stop_penetration_m() == Approx(stop).epsilon(1e-14));
    CHECK(peaks.energy_past_stop_J == Approx(energy - energy_stop).epsilon(1e-4));
    // Past the stop: the bare robot's chain (K1 x^1.65 on the scalp to t1, then F1 + K3 x^2.65 on
    // bone) continued from the y_s at which it carries F_stop; by bisection.
    const double k1 = Hertz(70e9, 0.3, 16.7e6, 0.42, 1.0 / 0.015 + 1.0 / 0.08);
    const double k3 = Hertz(70e9, 0.3, 6.5e9, 0.22, 1.0 / 0.015 + 1.0 / 0.077);
    const double t1 = 0.8 * 0.003;
    auto bare_force = [&](double y) {
      return k1 * std::pow(std::min(y, t1), 1.65) + k3 * std::pow(std::max(y - t1, 0.0), 2.65);
    };
    auto bare_energy = [&](double y) {
      const double y1 = std::min(y, t1), y3 = std::max(y - t1, 0.0);
      return k1 * std::pow(y1, 2.65) / 2.65 + k1 * std::pow(y1, 1.65) * y3 + k3 * std::pow(y3, 3.65) / 3.65;
    };
    auto bisect = [](auto f, double target) {
      double lo = 0.0, hi = 0.1;
      for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) < target ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi);
    };
    const double y_s = bisect(bare_force, force_stop);
    const double y = bisect(bare_energy, energy - energy_stop + bare_energy(y_s));
    CHECK(peaks.max_penetration_m == Approx(stop + y - y_s).epsilon(1e-5));
    CHECK(peaks.peak_force_N == Approx(bare_force(y)).epsilon(1e-4));
    CHECK(peaks.covering_strain_at_peak == Approx(0.49).epsilon(1e-14));
    CHECK(peaks.scalp_fully_compressed == (y > t1));
    const covopt::CoveringValidity validity = covopt::CoveringLawValidity(model, peaks);
    CHECK(validity.within);  // the stop is modelled: within the law, and the note says so
    CHECK(validity.note.find("used up") != std::string::npos);
    const covopt::ImpactResult exact = covopt::SolveExact(model);
    CHECK(exact.validity.within);
    bool warned = false;
    for (const covopt::ValidityWarning& w : exact.warnings) warned |= w.code == covopt::ValidityCode::kFullyCompressed;
    CHECK(warned);
  }
}

TEST_CASE("foam head: exact path and time path agree, within the curve and used up", "[foam_head]") {
  using covopt::ComputationMethod;
  struct Case {
    double h, v;
  };
  for (const Case c : {Case{0.02, 0.3}, Case{0.04, 1.0}, Case{0.01, 1.0}, Case{0.005, 2.0}}) {
    const ImpactModel model = ImpactModel::FromScene(FoamScene(c.h, c.v));
    const covopt::ImpactResult exact = covopt::SolveExact(model);
    for (ComputationMethod method : {ComputationMethod::kCvodeAdams, ComputationMethod::kCvodeBdf,
                                     ComputationMethod::kArkodeErk54, ComputationMethod::kArkodeEsdirk54}) {
      CAPTURE(c.h, c.v, covopt::ToString(method));
      const double rtol = 1e-8;
      const covopt::ImpactResult timed = covopt::SimulateImpact(model, TimePath(method, rtol));
      REQUIRE(timed.ok());
      const double tol = 1e-5;  // 1000 rtol: the peaks' error follows the energy residual (docs/numerics.md)
      CHECK(timed.peaks.max_penetration_m == Approx(exact.peaks.max_penetration_m).epsilon(tol));
      CHECK(timed.peaks.peak_force_N == Approx(exact.peaks.peak_force_N).epsilon(tol));
      CHECK(timed.peaks.max_compressive_stress_Pa == Approx(exact.peaks.max_compressive_stress_Pa).epsilon(tol));
      CHECK(timed.peaks.max_tensile_stress_Pa == Approx(exact.peaks.max_tensile_stress_Pa).epsilon(tol));
      CHECK(timed.peaks.max_energy_density_J_per_m2 == Approx(exact.peaks.max_energy_density_J_per_m2).epsilon(tol));
      CHECK(*timed.contact_duration_s == Approx(*exact.contact_duration_s).epsilon(tol));
      CHECK(timed.validity.within == exact.validity.within);
      CHECK(*timed.energy_residual < 1e-6);
      // The history: F never exceeds its peak, and the foam's stress is the curve's.
      for (const covopt::HistorySample& sample : timed.history) {
        CHECK(sample.force_N <= exact.peaks.peak_force_N * (1.0 + 1e-6));
      }
    }
  }
}

TEST_CASE("foam head: the exact duration converges onto a brute-force quadrature of 2 ∫ dδ / v", "[foam_head]") {
  for (double v : {0.3, 1.0}) {
    const Scene scene = FoamScene(0.02, v);
    const ImpactModel model = ImpactModel::FromScene(scene);
    const covopt::ImpactResult exact = covopt::SolveExact(model);
    const double m = EffectiveMass(scene), dmax = exact.peaks.max_penetration_m;
    // δ = δ_max (1 − u²): T = 2 ∫₀¹ 2 δ_max u du / sqrt(2 (U(δ_max) − U(δ)) / m), midpoint in u.
    const double energy = 0.5 * m * v * v;
    constexpr int kCells = 200000;
    double sum = 0.0;
    for (int i = 0; i < kCells; ++i) {
      const double u = (i + 0.5) / kCells;
      const double gap = energy - model.StateAt(dmax * (1.0 - u * u)).potential_energy_J;
      sum += 2.0 * dmax * u / std::sqrt(2.0 * gap / m);
    }
    CAPTURE(v);
    CHECK(*exact.contact_duration_s == Approx(2.0 * sum / kCells).epsilon(1e-8));
  }
}

TEST_CASE("foam head: the law follows covering.law and the curve", "[foam_head]") {
  Scene foam = FoamScene(0.02, 1.0);
  CHECK(ImpactModel::FromScene(foam).covering_law() == CoveringLaw::kFoam);
  foam.covering.law = CoveringLaw::kFoam;
  CHECK(ImpactModel::FromScene(foam).is_foam());

  // hertz with a curve: today's law, bit for bit.
  Scene hertz = foam;
  hertz.covering.law = CoveringLaw::kHertz;
  Scene plain = hertz;
  plain.covering.compressive_curve = nullptr;
  plain.covering.law = CoveringLaw::kAuto;
  const covopt::ImpactResult a = covopt::SolveExact(ImpactModel::FromScene(hertz));
  const covopt::ImpactResult b = covopt::SolveExact(ImpactModel::FromScene(plain));
  CHECK(a.peaks.covering_law == CoveringLaw::kHertz);
  CHECK(a.peaks.max_penetration_m == b.peaks.max_penetration_m);
  CHECK(a.peaks.peak_force_N == b.peaks.peak_force_N);
  CHECK(a.peaks.max_tensile_stress_Pa == b.peaks.max_tensile_stress_Pa);
  CHECK(a.peaks.max_energy_density_J_per_m2 == b.peaks.max_energy_density_J_per_m2);
  CHECK(*a.contact_duration_s == *b.contact_duration_s);
  CHECK(a.validity.note.rfind("hertz law", 0) == 0);

  // foam without a curve: refused, naming covering.law.
  Scene no_curve = plain;
  no_curve.covering.law = CoveringLaw::kFoam;
  CHECK_THROWS_WITH(ImpactModel::FromScene(no_curve), Catch::Contains("covering.law"));

  // What the foam law does not model is refused, naming the field.
  Scene damped = foam;
  damped.model.damping_s_per_m = 0.1;
  CHECK_THROWS_WITH(ImpactModel::FromScene(damped), Catch::Contains("model.damping"));
  Scene braking = foam;
  braking.robot.braking_m_per_s2 = 10.0;
  braking.robot.reaction_delay_s = 0.01;
  CHECK_THROWS_WITH(ImpactModel::FromScene(braking), Catch::Contains("robot.braking"));
  Scene literal = foam;
  literal.model.thresholds = covopt::ThresholdReading::kLiteral;
  CHECK_THROWS_WITH(ImpactModel::FromScene(literal), Catch::Contains("model.thresholds"));
  covopt::TimeIntegrationOptions extended;
  extended.force_extended_dynamics = true;
  CHECK_THROWS_AS(covopt::SimulateImpact(ImpactModel::FromScene(foam), extended), std::invalid_argument);
  CHECK_THROWS_WITH(covopt::ExactPeakSensitivities(ImpactModel::FromScene(foam), covopt::ExactPeaks(ImpactModel::FromScene(foam))),
                    Catch::Contains("foam law"));

  // No covering: the bare robot, whatever the law says.
  Scene bare = foam;
  bare.covering.thickness_m = 0.0;
  CHECK_FALSE(ImpactModel::FromScene(bare).is_foam());
  CHECK(covopt::CoveringLawValidity(ImpactModel::FromScene(bare), covopt::ExactPeaks(ImpactModel::FromScene(bare))).within);
}

TEST_CASE("foam head: a covering never reads worse than the bare robot on the same contact", "[foam_head]") {
  // Curves from a tenth to ten times VN600, 3-40 mm, on robot radii 5 mm to flat, 2-40 kg,
  // 0.1-5 m/s. A layer that is softer than the bare contact at its stop (it stores at least
  // the energy the bare robot stores when it carries the same force) gives peaks F, σ_t, e at
  // most the bare robot's, within its curve and used up (checked at 40 forces up to the stop). A layer stiffer than that (ten times
  // VN600 on a thin layer: 1.9 MPa at 49 %, against the scalp's soft Hertz contact) reads
  // worse on force: the fracture criterion says so, and the grid must meet such cases too.
  int used_up = 0, within = 0, stiffer = 0;
  for (double scale : {0.1, 1.0, 10.0}) {
    const auto curve = Vn600(scale);
    for (double h : {0.003, 0.01, 0.04}) {
      for (double radius : {0.005, 0.015, 0.05, covopt::kFlat}) {
        for (double mass : {2.0, 10.0, 40.0}) {
          Scene covered = FoamScene(h, 1.0, curve);
          covered.robot.radius_m = radius;
          covered.robot.mass_kg = mass;
          Scene bare = covered;
          bare.covering.thickness_m = 0.0;
          const ImpactModel covered_model = ImpactModel::FromScene(covered);
          const ImpactModel bare_model = ImpactModel::FromScene(bare);
          // Softer: at every force the layer carries up to its stop, it stores at least the bare
          // robot's energy at that force (the bare penetration by bisection).
          bool softer = true;
          for (int k = 1; k <= 40; ++k) {
            const covopt::ContactState layer =
                covered_model.StateAt(covered_model.foam_stop_penetration_m() * k / 40.0);
            double lo = 0.0, hi = 0.1;
            for (int i = 0; i < 200; ++i) {
              const double mid = 0.5 * (lo + hi);
              (bare_model.StateAt(mid).force_N < layer.force_N ? lo : hi) = mid;
            }
            softer = softer && bare_model.StateAt(lo).potential_energy_J <= layer.potential_energy_J;
          }
          stiffer += softer ? 0 : 1;
          for (double v : {0.1, 0.5, 1.5, 5.0}) {
            covered.robot.speed_m_per_s = bare.robot.speed_m_per_s = v;
            const ImpactPeaks c = covopt::ExactPeaks(ImpactModel::FromScene(covered));
            const ImpactPeaks b = covopt::ExactPeaks(ImpactModel::FromScene(bare));
            (c.fully_compressed ? used_up : within) += 1;
            if (!softer) continue;
            CAPTURE(scale, h, radius, mass, v);
            CHECK(c.peak_force_N <= b.peak_force_N);
            CHECK(c.max_tensile_stress_Pa <= b.max_tensile_stress_Pa);
            CHECK(c.max_energy_density_J_per_m2 <= b.max_energy_density_J_per_m2);
          }
        }
      }
    }
  }
  CHECK(used_up > 50);  // both regimes are covered by the grid
  CHECK(within > 50);
  CHECK(stiffer > 0);
  CHECK(stiffer <= 36);  // only the ten-times curve (36 contacts) is stiffer than the bare contact
}

TEST_CASE("foam head: a thicker layer of the same foam never lowers the force-limited speed", "[foam_head]") {
  // The largest v with F_max <= F_lim (bisection on v: F_max grows with v), per thickness.
  auto force_limited_speed = [](double h, double force_limit_N) {
    double lo = 1e-3, hi = 20.0;
    for (int i = 0; i < 60; ++i) {
      const double mid = std::sqrt(lo * hi);
      const ImpactPeaks p = covopt::ExactPeaks(ImpactModel::FromScene(FoamScene(h, mid)));
      (p.peak_force_N <= force_limit_N ? lo : hi) = mid;
    }
    return lo;
  };
  for (double limit : {20.0, 200.0, 2000.0}) {
    double previous = 0.0;
    for (double h : {0.002, 0.005, 0.01, 0.02, 0.04, 0.08}) {
      const double v = force_limited_speed(h, limit);
      CAPTURE(limit, h, v);
      CHECK(v >= previous * (1.0 - 1e-9));
      previous = v;
    }
  }
}

TEST_CASE("foam head: the curve's V inverse and its drop without cancellation", "[foam_head][curve]") {
  const CompressiveCurve curve = CompressiveCurve::FromPoints(Vn600Points());
  for (double e : {1e-7, 0.001, 0.02, 0.0333, 0.1, 0.25, 0.4, 0.48999, 0.49}) {
    CAPTURE(e);
    const auto back = curve.StrainAtSecondIntegral(curve.SecondIntegralAt(e));
    REQUIRE(back);
    CHECK(*back == Approx(e).epsilon(1e-12));
  }
  CHECK_FALSE(curve.StrainAtSecondIntegral(curve.total_second_integral_J_per_m3() * 1.000001));
  CHECK_FALSE(curve.StrainAtSecondIntegral(-1.0));
  // The drop V(ε) − V(ε − γ) against long-double subtraction, down to gaps of 1e-14 of ε.
  for (double e : {0.013, 0.2, 0.49}) {
    for (double gap : {1e-14, 1e-9, 1e-4, 0.01, 0.1}) {
      if (gap > e) continue;
      // V on this piece, in long double, from the test's own σ: ∫∫ by the exact cubic.
      const double lower = e - gap;
      const long double exact =
          static_cast<long double>(curve.EnergyDensityAt(lower)) * gap +
          static_cast<long double>(StressOf(Vn600Points(), lower)) * gap * gap / 2 +
          static_cast<long double>(curve.SlopeAt(e)) * gap * gap * gap / 6;
      CAPTURE(e, gap);
      if (lower >= (e == 0.013 ? 0.0 : e == 0.2 ? 0.15 : 0.45)) {  // the gap inside e's piece
        CHECK(curve.SecondIntegralDrop(e, gap) == Approx(static_cast<double>(exact)).epsilon(1e-12));
      }
      CHECK(curve.SecondIntegralDrop(e, gap) ==
            Approx(curve.SecondIntegralAt(e) - curve.SecondIntegralAt(lower)).epsilon(1e-6).margin(1e-12));
    }
  }
  CHECK(curve.SlopeAt(0.22) == Approx((57.3e3 - 45.9e3) / 0.05));
  CHECK(curve.SlopeAt(0.01) == Approx(14.3e3 / 0.02));
}

TEST_CASE("foam head: the warnings say near the curve's end, and used up with the energy past the stop", "[foam_head]") {
  auto codes = [](const covopt::ImpactResult& r) {
    std::vector<covopt::ValidityCode> out;
    for (const covopt::ValidityWarning& w : r.warnings) out.push_back(w.code);
    return out;
  };
  auto has = [](const std::vector<covopt::ValidityCode>& v, covopt::ValidityCode c) {
    return std::find(v.begin(), v.end(), c) != v.end();
  };
  Scene scene = FoamScene(0.02, 1.0);
  const ImpactModel probe = ImpactModel::FromScene(scene);
  // The speed that takes the layer to strain 0.48 (within 5 % of its last 0.49), and 0.40.
  for (double strain : {0.40, 0.48}) {
    const double energy = probe.StateAt(strain * 0.02).potential_energy_J;
    scene.robot.speed_m_per_s = std::sqrt(2.0 * energy / EffectiveMass(scene));
    const covopt::ImpactResult r = covopt::SolveExact(ImpactModel::FromScene(scene));
    CAPTURE(strain);
    CHECK(r.peaks.covering_strain_at_peak == Approx(strain).epsilon(1e-9));
    CHECK(has(codes(r), covopt::ValidityCode::kNearFullCompression) == (strain > 0.95 * 0.49));
    CHECK_FALSE(has(codes(r), covopt::ValidityCode::kFullyCompressed));
    CHECK(r.validity.within);
  }
  scene.robot.speed_m_per_s = 1.0;
  const covopt::ImpactResult used_up = covopt::SolveExact(ImpactModel::FromScene(scene));
  CHECK(has(codes(used_up), covopt::ValidityCode::kFullyCompressed));
  CHECK_FALSE(has(codes(used_up), covopt::ValidityCode::kNearFullCompression));
  CHECK_FALSE(has(codes(used_up), covopt::ValidityCode::kCoveringStifferThanScalp));
  CHECK(used_up.validity.note.find(" J of the ") != std::string::npos);
}
