// The exact path: energy balance U(δ_max) = ½ m v0², single-layer Hertz known answers
// (δ_max closed form and the contact time 2 δ_max/v0 · B(1/p, 1/2)/p, p = n + 1; the classic
// 2.9432 δ_max/v0 for n = 1.5), and the duration quadrature against an independent
// brute-force integration on multi-phase scenes.
#include <catch2/catch.hpp>

#include <cmath>

#include "test_helpers.hpp"

using namespace covopt;
using covopt::test::PaperScene;
using covopt::test::RelativeError;
using covopt::test::SetEveryExponent;

namespace {

/// Contact time of a single power law F = K x^n:  T = 2 δ_max/v0 ∫₀¹ du/sqrt(1 - u^p).
double SingleLawDuration(double delta_max, double speed, double exponent) {
  const double p = exponent + 1.0;
  return 2.0 * delta_max / speed * std::beta(1.0 / p, 0.5) / p;
}

/// Independent check of the duration: T/2 = ∫₀^δmax dδ / v(δ) by the substitution
/// δ = δ_max (1 - w²) and a composite midpoint rule with many points (slow but simple).
double BruteForceDuration(const ImpactModel& model, double delta_max) {
  const int intervals = 400000;
  const double energy = model.StateAt(delta_max).potential_energy_J;
  double sum = 0.0;
  for (int k = 0; k < intervals; ++k) {
    const double w = (k + 0.5) / intervals;
    const double delta = delta_max * (1.0 - w * w);
    const double gap = energy - model.StateAt(delta).potential_energy_J;
    sum += 2.0 * delta_max * w / std::sqrt(2.0 * gap / model.effective_mass_kg());
  }
  return 2.0 * sum / intervals;
}

}  // namespace

TEST_CASE("delta_max satisfies the energy balance to rounding", "[exact]") {
  const double thickness = GENERATE(0.0, 0.001, 0.005, 0.015, 0.03);
  const double modulus = GENERATE(0.2e6, 27.6e6, 1e9);
  const double speed = GENERATE(0.05, 2.0, 8.0);
  Scene scene = PaperScene(thickness, modulus, 0.25);
  scene.robot.speed_m_per_s = speed;
  const ImpactModel model = ImpactModel::FromScene(scene);
  const ImpactPeaks peaks = ExactPeaks(model);
  const ContactState at_max = model.StateAt(peaks.max_penetration_m);
  CHECK(RelativeError(at_max.potential_energy_J, model.impact_energy_J()) < 1e-13);
  CHECK(peaks.peak_force_N == at_max.force_N);
  CHECK(peaks.max_tensile_stress_Pa ==
        Approx(peaks.max_compressive_stress_Pa * (1 - 2 * 0.42) / 3).epsilon(1e-15));
}

TEST_CASE("delta_max satisfies the energy balance for every exponent and both readings",
          "[exact]") {
  // The energy balance is solved by Halley steps from the power term's own root; the
  // literal reading puts phase 3's origin before its start (x0 > 0) and the exponents span
  // the allowed [1, 5], so every branch of the solver is met.
  const ThresholdReading reading = GENERATE(ThresholdReading::kCumulative, ThresholdReading::kLiteral);
  const double exponent = GENERATE(1.0, 1.5, 2.65, 4.0, 5.0);
  const double thickness = GENERATE(0.0, 0.002, 0.015);
  const double speed = GENERATE(0.05, 2.0, 8.0);
  Scene scene = PaperScene(thickness, 27.6e6, 0.25);
  scene.robot.speed_m_per_s = speed;
  scene.model.thresholds = reading;
  SetEveryExponent(scene, exponent);
  const ImpactModel model = ImpactModel::FromScene(scene);
  const ImpactPeaks peaks = ExactPeaks(model);
  const ContactState at_max = model.StateAt(peaks.max_penetration_m);
  CAPTURE(reading == ThresholdReading::kLiteral, exponent, thickness, speed);
  CHECK(RelativeError(at_max.potential_energy_J, model.impact_energy_J()) < 1e-13);
}

TEST_CASE("A slow impact that stays in phase 1 matches single-layer Hertz", "[exact][hertz]") {
  Scene scene = PaperScene(0.0);
  scene.robot.speed_m_per_s = 0.1;
  const ImpactModel model = ImpactModel::FromScene(scene);
  const ImpactResult result = SolveExact(model);
  REQUIRE(result.peaks.phase_at_max == Phase::kRobotOnScalp);
  const double n = 1.65;
  const double k = model.segment(0).stiffness;
  const double delta_max = std::pow((n + 1) * model.impact_energy_J() / k, 1 / (n + 1));
  CHECK(RelativeError(result.peaks.max_penetration_m, delta_max) < 1e-14);
  CHECK(RelativeError(*result.contact_duration_s, SingleLawDuration(delta_max, 0.1, n)) < 1e-12);
  CHECK(*result.rebound_speed_m_per_s == 0.1);
}

TEST_CASE("Classic Hertz (n = 1.5): delta_max = (5 m v^2 / 4K)^(2/5), T = 2.9432 delta_max / v",
          "[exact][hertz]") {
  Scene scene = PaperScene(0.0);
  scene.model.exponent_covering_scalp = 1.5;
  scene.robot.speed_m_per_s = 0.2;
  scene.head.mass_kg = kFixed;  // m = m_r
  const ImpactModel model = ImpactModel::FromScene(scene);
  const ImpactResult result = SolveExact(model);
  REQUIRE(result.peaks.phase_at_max == Phase::kRobotOnScalp);
  // K = 4/3 E* sqrt(R) with the robot-scalp pair.
  const double e_star = 1 / ((1 - 0.3 * 0.3) / 70e9 + (1 - 0.42 * 0.42) / 16.7e6);
  const double radius = 1 / (1 / 0.015 + 1 / 0.08);
  const double k = 4.0 / 3.0 * e_star * std::sqrt(radius);
  const double delta_max = std::pow(5.0 * 10.0 * 0.2 * 0.2 / (4.0 * k), 0.4);
  CHECK(RelativeError(result.peaks.max_penetration_m, delta_max) < 1e-13);
  CHECK(*result.contact_duration_s / (delta_max / 0.2) == Approx(2.9432).epsilon(1e-4));
}

TEST_CASE("The duration quadrature agrees with brute-force integration across phases",
          "[exact]") {
  const double thickness = GENERATE(0.0, 0.002, 0.015, 0.03);
  const ImpactModel model = ImpactModel::FromScene(PaperScene(thickness, 27.6e6, 0.22));
  const ImpactPeaks peaks = ExactPeaks(model);
  const double quadrature = ExactContactDuration(model, peaks);
  const double brute = BruteForceDuration(model, peaks.max_penetration_m);
  INFO("thickness " << thickness << " quadrature " << quadrature << " brute " << brute);
  CHECK(RelativeError(quadrature, brute) < 1e-7);  // limited by the midpoint rule
}

TEST_CASE("delta_max just past a phase switch keeps the duration smooth", "[exact]") {
  // Speeds around the one that ends exactly at t1: the duration must vary continuously.
  const ImpactModel reference = ImpactModel::FromScene(PaperScene(0.0));
  const double u1 = reference.segment(1).energy_at_start_J;
  const double critical_speed = std::sqrt(2 * u1 / reference.effective_mass_kg());
  double previous = 0.0;
  for (double factor : {1 - 1e-6, 1 - 1e-12, 1.0, 1 + 1e-12, 1 + 1e-6}) {
    Scene scene = PaperScene(0.0);
    scene.robot.speed_m_per_s = critical_speed * factor;
    const ImpactModel model = ImpactModel::FromScene(scene);
    const ImpactResult result = SolveExact(model);
    const double duration = *result.contact_duration_s;
    if (previous > 0) CHECK(RelativeError(duration, previous) < 1e-5);
    previous = duration;
  }
}

TEST_CASE("delta_max landing exactly on a switch gives a finite, continuous duration", "[exact]") {
  // A soft thick covering fully compressed at 2.017 m/s: at this speed δ_max rounds exactly onto
  // t2, the top segment's start, where the duration quadrature's first piece is empty (it was
  // 0/0: "contact duration -nan ms").
  Scene scene = PaperScene(0.0);
  scene.covering.youngs_modulus_Pa = 1e6;
  scene.covering.thickness_m = 0.040;
  scene.covering.poisson_ratio = 0.25;
  scene.robot.speed_m_per_s = 2.0173746111141204;
  const ImpactModel model = ImpactModel::FromScene(scene);
  const ImpactResult result = SolveExact(model);
  REQUIRE(result.peaks.max_penetration_m == model.segment(model.segment_count() - 1).start_m);
  REQUIRE(result.contact_duration_s.has_value());
  const double duration = *result.contact_duration_s;
  CHECK(std::isfinite(duration));
  CHECK(RelativeError(duration, BruteForceDuration(model, result.peaks.max_penetration_m)) < 1e-5);
  // Every speed within 64 ulps either side of it: finite, and continuous across the switch.
  double speed = scene.robot.speed_m_per_s;
  for (int k = 0; k < 64; ++k) speed = std::nextafter(speed, 0.0);
  for (int k = 0; k <= 128; ++k, speed = std::nextafter(speed, 10.0)) {
    scene.robot.speed_m_per_s = speed;
    const ImpactResult near = SolveExact(ImpactModel::FromScene(scene));
    INFO("speed " << speed);
    REQUIRE(std::isfinite(*near.contact_duration_s));
    CHECK(RelativeError(*near.contact_duration_s, duration) < 1e-9);
  }
}

TEST_CASE("Fully compressed thin coverings reach phase 3 and say so", "[exact]") {
  const ImpactResult thin = SolveExact(ImpactModel::FromScene(PaperScene(0.002, 27.6e6, 0.22)));
  CHECK(thin.peaks.phase_at_max == Phase::kRobotOnBone);
  CHECK(thin.peaks.fully_compressed);
  CHECK_FALSE(thin.warnings.empty());
  const ImpactResult thick = SolveExact(ImpactModel::FromScene(PaperScene(0.03, 27.6e6, 0.22)));
  CHECK(thick.peaks.phase_at_max == Phase::kCoveringOnBone);
  CHECK_FALSE(thick.peaks.fully_compressed);
}

TEST_CASE("A sharp robot edge is reported outside Hertz validity", "[exact]") {
  Scene scene = PaperScene(0.0);
  scene.robot.radius_m = 0.0005;
  const ImpactResult result = SolveExact(ImpactModel::FromScene(scene));
  REQUIRE_FALSE(result.warnings.empty());
  CHECK_THAT(result.warnings.front().message, Catch::Contains("Hertz validity"));
}
