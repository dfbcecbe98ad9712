// The literal threshold reading (docs/model.md §4): where the paper's eq. (2) and (4), read
// literally, make the force or the stress DROP at a switch, the reported F_max and σ_c,max
// are the largest over the loading branch 0..δ_max, not the values at δ_max, on both paths;
// without a covering the literal if-chain takes phase 3's law from δ = 0. e_A,max stays
// e(δ_max). The default cumulative reading is unchanged: its peaks are exactly the law at
// δ_max (its F and σ are non-decreasing).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "test_helpers.hpp"

using namespace covopt;
using covopt::test::AddVariant;
using covopt::test::NamedScene;
using covopt::test::PaperScene;
using covopt::test::RelativeError;

namespace {

/// Hertz stiffness of eq. (3), written out here independently of the library.
double Hertz(double e1, double nu1, double e2, double nu2, double curvature) {
  return 4.0 / 3.0 / ((1 - nu1 * nu1) / e1 + (1 - nu2 * nu2) / e2) / std::sqrt(curvature);
}

/// A scene whose literal law drops at t1: a 10 mm scalp under a 6.5 mm, 100 MPa covering
/// (0.8 b_c = 5.2 mm < 0.8 b_s = 8 mm, so phase 3 takes over at 8 mm measured from 5.2 mm),
/// hit at 1.5 m/s so that δ_max lies just beyond the drop.
Scene DropScene() {
  Scene scene = PaperScene(0.0065, 100e6, 0.25);
  scene.scalp.thickness_m = 0.010;
  scene.robot.speed_m_per_s = 1.5;
  scene.model.thresholds = ThresholdReading::kLiteral;
  return scene;
}

/// The largest F and σ_c and the last e of the law sampled densely over [0, δ_max].
struct Sampled {
  double force_N = 0.0, stress_Pa = 0.0, energy_density = 0.0;
};
Sampled SampleLoading(const ImpactModel& model, double delta_max) {
  Sampled s;
  constexpr int kSamples = 200000;
  double previous_density = 0.0;
  for (int k = 1; k <= kSamples; ++k) {
    const ContactState state = model.StateAt(delta_max * k / kSamples);
    s.force_N = std::max(s.force_N, state.force_N);
    s.stress_Pa = std::max(s.stress_Pa, state.compressive_stress_Pa);
    CHECK(state.energy_density_J_per_m2 >= previous_density);  // e never decreases
    previous_density = state.energy_density_J_per_m2;
  }
  s.energy_density = previous_density;
  return s;
}

/// The speed that takes a model to penetration δ [m]: U(δ) = ½ m v².
double SpeedReaching(const Scene& scene, double delta) {
  const ImpactModel model = ImpactModel::FromScene(scene);
  return std::sqrt(2.0 * model.StateAt(delta).potential_energy_J / model.effective_mass_kg());
}

std::vector<NamedScene> LiteralScenes() {
  std::vector<NamedScene> scenes;
  const Scene literal = [] {
    Scene s = PaperScene(0.015, 27.6e6, 0.22);
    s.model.thresholds = ThresholdReading::kLiteral;
    return s;
  }();
  auto add = [&](std::string name, auto&& edit) { AddVariant(scenes, literal, std::move(name), edit); };
  add("paper scene, well ordered", [](Scene&) {});
  add("force drop just passed", [](Scene& s) { s = DropScene(); });
  add("force drop, faster", [](Scene& s) {
    s = DropScene();
    s.robot.speed_m_per_s = 1.6;
  });
  add("ill ordered, 1 mm, 2 m/s (jumps up)", [](Scene& s) { s.covering.thickness_m = 0.001; });
  add("no covering, 2 m/s", [](Scene& s) { s.covering.thickness_m = 0.0; });
  add("no covering, stress drop just passed", [](Scene& s) {
    s.covering.thickness_m = 0.0;
    s.robot.speed_m_per_s = 0.35;
  });
  add("no covering, flat robot, slow", [](Scene& s) {
    s.covering.thickness_m = 0.0;
    s.robot.radius_m = kFlat;
    s.robot.speed_m_per_s = 0.3;
  });
  return scenes;
}

}  // namespace

TEST_CASE("Literal reading: a force drop at t1 reports the largest force over the contact",
          "[literal][regression]") {
  const Scene scene = DropScene();
  const ImpactModel model = ImpactModel::FromScene(scene);
  REQUIRE(model.segment_count() == 2);
  const double t1 = 0.008;
  const ImpactPeaks peaks = ExactPeaks(model);
  REQUIRE(peaks.max_penetration_m > t1);  // past the drop
  REQUIRE(peaks.max_penetration_m < 0.0090);

  // Before the fix the exact path reported F(δ_max) ≈ 762 N; the force reached ≈ 1026 N at
  // t1, K_cs t1^1.65 with K_cs of eq. (3a) for the covering (R_c = 21.5 mm) on the scalp.
  const double k_cs = Hertz(100e6, 0.25, 16.7e6, 0.42, 1 / 0.0215 + 1 / 0.08);
  const double force_at_t1 = k_cs * std::pow(t1, 1.65);
  const double force_at_max = model.StateAt(peaks.max_penetration_m).force_N;
  CHECK(force_at_max == Approx(762.0).margin(0.5));
  CHECK(force_at_t1 == Approx(1025.6).margin(0.5));
  CHECK(peaks.peak_force_N == Approx(force_at_t1).epsilon(1e-12));
  CHECK(peaks.peak_force_N > force_at_max + 250.0);
  // The stress rises again beyond its own drop and peaks at δ_max in this scene.
  CHECK(peaks.max_compressive_stress_Pa ==
        model.StateAt(peaks.max_penetration_m).compressive_stress_Pa);
  CHECK(peaks.max_tensile_stress_Pa == model.TensileFromCompressive(peaks.max_compressive_stress_Pa));
  // Still "fully compressed": δ_max lies in the robot-on-bone segment, which starts at t1.
  CHECK(peaks.fully_compressed);
  CHECK(peaks.full_compression_penetration_m == Approx(t1).epsilon(1e-15));

  // The time path reports the same maximum (it passed t1 by root finding).
  const ImpactResult simulated = SimulateImpact(model);
  REQUIRE(simulated.ok());
  CHECK(RelativeError(simulated.peaks.peak_force_N, force_at_t1) < 1e-12);
}

TEST_CASE("Literal reading without a covering follows the if-chain: phase 3 from δ = 0",
          "[literal][law]") {
  Scene scene = PaperScene(0.0);
  scene.model.thresholds = ThresholdReading::kLiteral;
  const ImpactModel model = ImpactModel::FromScene(scene);
  REQUIRE(model.segment_count() == 2);
  const double t1 = 0.0024;
  const ForceLawSegment& bone = model.segment(1);
  CHECK(bone.phase == Phase::kRobotOnBone);
  CHECK(bone.start_m == Approx(t1).epsilon(1e-15));
  CHECK(bone.origin_m == 0.0);
  CHECK(bone.force_offset_N == 0.0);
  CHECK(bone.stress_offset_Pa == 0.0);

  // F = K_rb δ^2.65 above t1, with K_rb of eq. (3c): 107 N at t1, down from 144.5 N.
  const double k_rb = Hertz(70e9, 0.3, 6.5e9, 0.22, 1 / 0.015 + 1 / 0.077);
  for (double delta : {0.0025, 0.004, 0.01}) {
    CHECK(model.StateAt(delta).force_N == Approx(k_rb * std::pow(delta, 2.65)).epsilon(1e-12));
  }
  const ContactState below = model.StateInSegment(0, t1);
  const ContactState above = model.StateInSegment(1, t1);
  CHECK(below.force_N == Approx(144.5113).epsilon(1e-6));  // docs/model.md's bare-robot F1
  CHECK(above.force_N == Approx(k_rb * std::pow(t1, 2.65)).epsilon(1e-12));
  CHECK(above.force_N < below.force_N - 30.0);
  CHECK(above.compressive_stress_Pa < below.compressive_stress_Pa);
  // U and e, integrals of F and σ, stay continuous.
  CHECK(above.potential_energy_J == Approx(below.potential_energy_J).epsilon(1e-14));
  CHECK(above.energy_density_J_per_m2 == Approx(below.energy_density_J_per_m2).epsilon(1e-14));

  // Just past t1 (δ_max = 1.05 t1) both F and σ at δ_max are below their values at t1:
  // the peaks are the phase-1 values at t1 (F1 = 144.5113 N, σ1 = 2.276011 MPa).
  scene.robot.speed_m_per_s = SpeedReaching(scene, 1.05 * t1);
  const ImpactModel slow = ImpactModel::FromScene(scene);
  const ImpactPeaks peaks = ExactPeaks(slow);
  REQUIRE(peaks.max_penetration_m == Approx(1.05 * t1).epsilon(1e-12));
  REQUIRE(slow.StateAt(peaks.max_penetration_m).force_N < 144.0);
  CHECK(peaks.peak_force_N == Approx(144.5113).epsilon(1e-6));
  CHECK(peaks.max_compressive_stress_Pa == Approx(2.276011e6).epsilon(1e-6));
  CHECK(peaks.max_energy_density_J_per_m2 ==
        slow.StateAt(peaks.max_penetration_m).energy_density_J_per_m2);
  CHECK(peaks.phase_at_max == Phase::kRobotOnBone);
  CHECK(peaks.fully_compressed);
}

TEST_CASE("Literal reading: both paths report the largest F and σ over the contact",
          "[literal][agree]") {
  for (const NamedScene& named : LiteralScenes()) {
    INFO(named.name);
    const ImpactModel model = ImpactModel::FromScene(named.scene);
    const ImpactResult exact = SolveExact(model);
    const Sampled sampled = SampleLoading(model, exact.peaks.max_penetration_m);
    // The maximum is at least every sample, and no sample misses it by more than the
    // sampling step lets the law move.
    // (1e-14: the last sample is δ_max up to rounding.)
    CHECK(exact.peaks.peak_force_N >= sampled.force_N * (1 - 1e-14));
    CHECK(RelativeError(exact.peaks.peak_force_N, sampled.force_N) < 1e-4);
    CHECK(exact.peaks.max_compressive_stress_Pa >= sampled.stress_Pa * (1 - 1e-14));
    CHECK(RelativeError(exact.peaks.max_compressive_stress_Pa, sampled.stress_Pa) < 1e-3);
    CHECK(exact.peaks.max_energy_density_J_per_m2 == Approx(sampled.energy_density).epsilon(1e-14));

    for (ComputationMethod method : {ComputationMethod::kArkodeErk54, ComputationMethod::kCvodeBdf}) {
      TimeIntegrationOptions options;
      options.method = method;
      options.relative_tolerance = 1e-10;
      const ImpactResult simulated = SimulateImpact(model, options);
      INFO(ToString(method) << ": " << simulated.message);
      REQUIRE(simulated.ok());
      CHECK(simulated.peaks.phase_at_max == exact.peaks.phase_at_max);
      CHECK(RelativeError(simulated.peaks.peak_force_N, exact.peaks.peak_force_N) < 1e-7);
      CHECK(RelativeError(simulated.peaks.max_compressive_stress_Pa,
                          exact.peaks.max_compressive_stress_Pa) < 1e-7);
      CHECK(RelativeError(simulated.peaks.max_energy_density_J_per_m2,
                          exact.peaks.max_energy_density_J_per_m2) < 1e-7);
      CHECK(RelativeError(*simulated.contact_duration_s, *exact.contact_duration_s) < 1e-7);
    }
  }
}

TEST_CASE("The cumulative reading's peaks are exactly the law at δ_max, on both paths",
          "[cumulative][regression]") {
  std::vector<NamedScene> scenes;
  const Scene base = PaperScene(0.015, 27.6e6, 0.22);
  auto add = [&](std::string name, auto&& edit) { AddVariant(scenes, base, std::move(name), edit); };
  add("paper scene", [](Scene&) {});
  add("no covering", [](Scene& s) { s.covering.thickness_m = 0; });
  add("thin, fully compressed", [](Scene& s) { s.covering.thickness_m = 0.002; });
  add("slow, phase 1", [](Scene& s) { s.robot.speed_m_per_s = 0.05; });
  add("stiff thin covering", [](Scene& s) { s.covering = {1e9, 0.25, 0.0005}; });
  add("flat robot, fixed head", [](Scene& s) {
    s.robot.radius_m = kFlat;
    s.head.mass_kg = kFixed;
  });
  for (const NamedScene& named : scenes) {
    INFO(named.name);
    const ImpactModel model = ImpactModel::FromScene(named.scene);
    const ImpactPeaks peaks = ExactPeaks(model);
    // Bit for bit: the value of the law at δ_max, in the segment the energy balance chose.
    const std::size_t segment = model.SegmentIndexAt(peaks.max_penetration_m);
    const ContactState at_max = model.StateInSegment(segment, peaks.max_penetration_m);
    CHECK(peaks.peak_force_N == at_max.force_N);
    CHECK(peaks.max_compressive_stress_Pa == at_max.compressive_stress_Pa);
    CHECK(peaks.max_tensile_stress_Pa == model.TensileFromCompressive(at_max.compressive_stress_Pa));
    CHECK(peaks.max_energy_density_J_per_m2 == at_max.energy_density_J_per_m2);
    // F and σ never decrease along the cumulative law, switches included.
    for (std::size_t j = 0; j + 1 < model.segment_count(); ++j) {
      const double end = model.segment(j).end_m;
      CHECK(model.StateInSegment(j + 1, end).force_N >= model.StateInSegment(j, end).force_N);
      CHECK(model.StateInSegment(j + 1, end).compressive_stress_Pa >=
            model.StateInSegment(j, end).compressive_stress_Pa);
    }
    const ImpactResult simulated = SimulateImpact(model);
    REQUIRE(simulated.ok());
    const ContactState simulated_at_max = model.StateAt(simulated.peaks.max_penetration_m);
    CHECK(simulated.peaks.peak_force_N == simulated_at_max.force_N);
    CHECK(simulated.peaks.max_compressive_stress_Pa == simulated_at_max.compressive_stress_Pa);
  }
}

TEST_CASE("full_compression_penetration_m is where the robot-on-bone segment begins",
          "[peaks]") {
  const auto start = [](Scene scene) {
    return ExactPeaks(ImpactModel::FromScene(scene)).full_compression_penetration_m;
  };
  CHECK(start(PaperScene(0.015)) == Approx(0.0024 + 0.012).epsilon(1e-14));  // t1 + 0.8 b_c
  CHECK(start(PaperScene(0.0)) == Approx(0.0024).epsilon(1e-14));            // t1
  Scene literal = PaperScene(0.015);
  literal.model.thresholds = ThresholdReading::kLiteral;
  CHECK(start(literal) == Approx(0.012).epsilon(1e-14));  // 0.8 b_c
  literal.covering.thickness_m = 0.001;
  CHECK(start(literal) == Approx(0.0024).epsilon(1e-14));  // ill ordered: t1
  // fully_compressed is exactly "δ_max beyond it".
  for (double thickness : {0.002, 0.0128, 0.015, 0.03}) {
    const ImpactPeaks peaks = ExactPeaks(ImpactModel::FromScene(PaperScene(thickness)));
    CHECK(peaks.fully_compressed == (peaks.max_penetration_m > peaks.full_compression_penetration_m));
  }
}

namespace {

/// U [J] and e [J/m²] of the law at δ [m] in long double, from the segment holding δ, with
/// x^k - x0^k = x0^k expm1(k log1p((δ - start)/x0)) past a literal start (origin < start):
/// no cancellation however close δ is to the start.
struct ReferenceIntegrals {
  long double energy_J = 0.0L;
  long double density_J_per_m2 = 0.0L;
};
ReferenceIntegrals IntegralsAt(const ImpactModel& model, double delta) {
  const ForceLawSegment& seg = model.segment(model.SegmentIndexAt(delta));
  const long double n = seg.exponent;
  const long double past_start = static_cast<long double>(delta) - seg.start_m;
  const long double x0 = static_cast<long double>(seg.start_m) - seg.origin_m;
  const long double x = static_cast<long double>(delta) - seg.origin_m;
  auto power_difference = [&](long double k) {  // x^k - x0^k
    return x0 > 0.0L ? std::pow(x0, k) * std::expm1(k * std::log1p(past_start / x0))
                     : std::pow(x, k);
  };
  const long double kc = 3.0 / (2.0 * std::numbers::pi) * seg.stiffness * seg.curvature_per_m;
  ReferenceIntegrals integrals;
  integrals.energy_J = seg.energy_at_start_J + seg.force_offset_N * past_start +
                       seg.stiffness * power_difference(n + 1.0L) / (n + 1.0L);
  integrals.density_J_per_m2 = seg.energy_density_at_start_J_per_m2 +
                               seg.stress_offset_Pa * past_start + kc * power_difference(n) / n;
  return integrals;
}

/// Literal scenes whose robot-on-bone law starts before its switch (origin < start): the
/// force jumps there, up or down.
std::vector<NamedScene> IllOrderedLiteralScenes() {
  std::vector<NamedScene> scenes;
  const Scene literal = [] {
    Scene s = PaperScene(0.0);
    s.model.thresholds = ThresholdReading::kLiteral;
    return s;
  }();
  auto add = [&](std::string name, auto&& edit) {
    AddVariant(scenes, literal, std::move(name), edit);
  };
  add("no covering (F drops at t1)", [](Scene&) {});
  add("no covering, flat robot", [](Scene& s) { s.robot.radius_m = kFlat; });
  add("no covering, n_cs 3, n_rb 1.2 (F jumps 1.6e7-fold)", [](Scene& s) {
    s.model.exponent_covering_scalp = 3.0;
    s.model.exponent_robot_bone = 1.2;
  });
  add("1 mm covering (F jumps up)", [](Scene& s) { s.covering = {27.6e6, 0.22, 0.001}; });
  add("6.5 mm, 100 MPa covering on a 10 mm scalp (F drops)", [](Scene& s) { s = DropScene(); });
  return scenes;
}

/// The robot-on-bone segment of a literal model (its last).
const ForceLawSegment& LastSegment(const ImpactModel& model) {
  return model.segment(model.segment_count() - 1);
}

}  // namespace

TEST_CASE("Literal reading: U and e just past a switch whose law starts before it are exact",
          "[literal][law][regression]") {
  // U = U(start) + F_off d + K/p (x^p - x0^p) and e alike: the difference of the powers,
  // each of order K x0^p, cancelled (U off by 4e-8 and e by 1e-8 where F jumps 1.6e7-fold).
  for (const NamedScene& named : IllOrderedLiteralScenes()) {
    const ImpactModel model = ImpactModel::FromScene(named.scene);
    const ForceLawSegment& bone = LastSegment(model);
    REQUIRE(bone.origin_m < bone.start_m);
    for (int j = 0; j <= 45; ++j) {
      const double delta = bone.start_m * (1.0 + std::pow(10.0, -j / 3.0));
      INFO(named.name << ", δ = start (1 + 10^-" << j / 3.0 << ")");
      const ContactState state = model.StateAt(delta);
      const ReferenceIntegrals reference = IntegralsAt(model, delta);
      CHECK(std::abs(state.potential_energy_J - reference.energy_J) <= 4e-16L * reference.energy_J);
      CHECK(std::abs(state.energy_density_J_per_m2 - reference.density_J_per_m2) <=
            4e-16L * reference.density_J_per_m2);
    }
  }
}

TEST_CASE("Literal reading: delta_max just past a jumped switch is within an ulp of the "
          "energy balance, damped or not",
          "[literal][exact][regression]") {
  // U(δ_max) = E (undamped: ½ m v0²; damped: m φ(d v0)/d², docs/model.md §10.1). Just past
  // the switch U rises by F(δ) per metre with F the jumped force, so no double δ_max does
  // better than E between U at δ_max's two neighbours: that is the check (where F jumps
  // 1.6e7-fold one ulp of δ_max moves U by 1.2e-8 of E). The energy balance solved in the
  // local penetration x lost the distance past the switch to the rounding of
  // x0 = start - origin and missed by up to 8 ulps (U off by 4.5e-8 there).
  const double damping = GENERATE(0.0, 0.2, 5.0);
  const long double damping_ld = damping;
  for (const NamedScene& named : IllOrderedLiteralScenes()) {
    const ImpactModel bare = ImpactModel::FromScene(named.scene);
    const double switch_energy = LastSegment(bare).energy_at_start_J;
    const double mass = bare.effective_mass_kg();
    for (int j = 0; j <= 48; ++j) {
      const long double target = switch_energy * (1.0L + std::pow(10.0L, -j / 3.0L));
      // The speed storing `target` at δ_max: φ(w)/d² = target/m, φ(w) = w - ln(1 + w), by
      // bisection in long double (undamped: ½ v0²).
      long double speed = std::sqrt(2.0L * target / mass);
      if (damping > 0.0) {
        long double low = 0.0L, high = 2.0L * speed + 1.0L;
        for (int k = 0; k < 200; ++k) {
          const long double mid = 0.5L * (low + high);
          const long double w = damping_ld * mid;
          (mass * (w - std::log1p(w)) / (damping_ld * damping_ld) < target ? low : high) = mid;
        }
        speed = low;
      }
      Scene scene = named.scene;
      scene.robot.speed_m_per_s = static_cast<double>(speed);
      scene.model.damping_s_per_m = damping;
      const ImpactModel model = ImpactModel::FromScene(scene);
      const long double w0 = damping_ld * scene.robot.speed_m_per_s;
      const long double energy = damping > 0.0
                                     ? mass * (w0 - std::log1p(w0)) / (damping_ld * damping_ld)
                                     : static_cast<long double>(model.impact_energy_J());
      const double delta_max = ExactPeaks(model).max_penetration_m;
      INFO(named.name << ", d = " << damping << " s/m, E = U(switch) (1 + 10^-" << j / 3.0 << ")");
      // The slack: U(start) is stored rounded (one eps of E), and the damped E = m φ(d v0)/d²
      // is computed by the library to about 1e-15.
      const long double slack = (damping > 0.0 ? 2e-15L : 2.3e-16L) * energy;
      const long double below = IntegralsAt(model, std::nextafter(delta_max, 0.0)).energy_J;
      const long double above = IntegralsAt(model, std::nextafter(delta_max, 1.0)).energy_J;
      auto residual_in_eps = [&](long double u) {  // (U - E)/E in units of 1e-16
        return static_cast<double>((u - energy) / energy * 1e16L);
      };
      CAPTURE(residual_in_eps(below), residual_in_eps(IntegralsAt(model, delta_max).energy_J),
              residual_in_eps(above));
      CHECK(below <= energy + slack);
      CHECK(above >= energy - slack);
    }
  }
}
