// Where numerical methods fail (docs/numerics.md, "Stability where methods fail"): scenes and
// settings found by experiment to break integrators or silently cost accuracy, each turned
// into what covopt must do there: the right answer, or a clear failure status or warning,
// never a wrong number reported as a clean success. The exact path is the reference.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "covopt/core/physical_floors.hpp"
#include "test_helpers.hpp"

using namespace covopt;
using covopt::test::AddVariant;
using covopt::test::NamedScene;
using covopt::test::PaperScene;
using covopt::test::RelativeError;

namespace {

/// The scenes where methods were seen to struggle.
std::vector<NamedScene> StressScenes() {
  std::vector<NamedScene> scenes;
  const Scene base = PaperScene(0.015, 27.6e6, 0.25);
  auto add = [&](std::string name, auto&& edit) { AddVariant(scenes, base, std::move(name), edit); };
  add("paper scene", [](Scene&) {});
  add("bare robot on bone", [](Scene& s) { s.covering.thickness_m = 0; });
  add("0.5 mm of 1 GPa, bottomed out", [](Scene& s) { s.covering = {1e9, 0.25, 0.5e-3}; });
  // The thinnest covering (the floor, 0.1 mm) at the top speed: phase 2 lasts under a microsecond.
  add("0.1 mm covering at 100 m/s: phase 2 lasts < 1 us", [](Scene& s) {
    s.covering = {1e9, 0.25, kMinLayerThickness_m};
    s.robot.speed_m_per_s = 100.0;
  });
  add("0.1 MPa, 50 mm: a long soft contact", [](Scene& s) { s.covering = {0.1e6, 0.25, 0.05}; });
  add("0.01 m/s", [](Scene& s) { s.robot.speed_m_per_s = 0.01; });
  add("10 m/s", [](Scene& s) { s.robot.speed_m_per_s = 10.0; });
  add("0.1 kg robot", [](Scene& s) { s.robot.mass_kg = 0.1; });
  add("1000 kg robot", [](Scene& s) { s.robot.mass_kg = 1000.0; });
  add("flat bare robot on a fixed head", [](Scene& s) {
    s.robot.radius_m = kFlat;
    s.covering.thickness_m = 0;
    s.head.mass_kg = kFixed;
  });
  add("flat robot on a 10 m head (nearly flat on flat)", [](Scene& s) {
    s.robot.radius_m = kFlat;
    s.head.radius_m = 10.0;
  });
  add("literal thresholds, 2 mm: the force jumps", [](Scene& s) {
    s.covering.thickness_m = 0.002;
    s.model.thresholds = ThresholdReading::kLiteral;
  });
  return scenes;
}

double WorstError(const ImpactResult& simulated, const ImpactResult& exact) {
  return std::max({RelativeError(simulated.peaks.max_penetration_m, exact.peaks.max_penetration_m),
                   RelativeError(simulated.peaks.peak_force_N, exact.peaks.peak_force_N),
                   RelativeError(simulated.peaks.max_compressive_stress_Pa,
                                 exact.peaks.max_compressive_stress_Pa),
                   RelativeError(simulated.peaks.max_energy_density_J_per_m2,
                                 exact.peaks.max_energy_density_J_per_m2),
                   RelativeError(*simulated.contact_duration_s, *exact.contact_duration_s),
                   RelativeError(*simulated.rebound_speed_m_per_s,
                                 *exact.rebound_speed_m_per_s)});
}

bool HasWarning(const ImpactResult& result, const std::string& text) {
  return std::any_of(result.warnings.begin(), result.warnings.end(),
                     [&](const ValidityWarning& w) { return w.message.find(text) != std::string::npos; });
}

}  // namespace

TEST_CASE("Every time-path result is within 100 x rtol of the exact path, or says it is not",
          "[numerics]") {
  TimeIntegrator integrator;
  for (const NamedScene& named : StressScenes()) {
    const ImpactModel model = ImpactModel::FromScene(named.scene);
    const ImpactResult exact = SolveExact(model);
    for (const ComputationMethod method : TimeIntegrationMethods()) {
      for (const bool restart : {true, false}) {
        for (const double rtol : {1e-5, 1e-8, 1e-11}) {
          TimeIntegrationOptions options;
          options.method = method;
          options.relative_tolerance = rtol;
          options.restart_at_phase_switches = restart;
          const ImpactResult result = integrator.Simulate(model, options);
          INFO(named.name << ", " << ToString(method) << (restart ? "" : ", no restart")
                          << ", rtol " << rtol << ": " << result.message);
          if (!result.ok()) {
            // A failure is a status with the integrator's words, never a number.
            CHECK(!result.message.empty());
            CHECK(result.raw_code != 0);
            CHECK(!result.energy_residual.has_value());
            continue;
          }
          REQUIRE(result.energy_residual.has_value());
          const double error = WorstError(result, exact);
          CHECK(std::isfinite(error));
          const bool flagged = HasWarning(result, "did not keep its tolerance");
          if (!restart) CHECK(HasWarning(result, "C0 kinks"));
          if (restart) {
            INFO("worst error " << error << ", energy residual " << *result.energy_residual);
            CHECK((error <= std::max(100.0 * rtol, 1e-9) || flagged));
          }
          // The self-check is no false alarm: when it fires, the peaks really are off by
          // more than the tolerance.
          if (flagged) CHECK(error > rtol);
        }
      }
    }
  }
}

TEST_CASE("The well-behaved integrators keep their tolerance on every stress scene",
          "[numerics]") {
  // CVODE Adams/BDF, ARKODE ERK 3(2), Dormand-Prince 5(4) (the default) and both DIRKs,
  // restarted at the switches: no warning, and errors within 100 x rtol at rtol 1e-8.
  TimeIntegrator integrator;
  for (const ComputationMethod method :
       {ComputationMethod::kCvodeAdams, ComputationMethod::kCvodeBdf, ComputationMethod::kArkodeErk32,
        ComputationMethod::kArkodeErk54, ComputationMethod::kArkodeSdirk43,
        ComputationMethod::kArkodeEsdirk54}) {
    for (const NamedScene& named : StressScenes()) {
      const ImpactModel model = ImpactModel::FromScene(named.scene);
      TimeIntegrationOptions options;
      options.method = method;
      const ImpactResult result = integrator.Simulate(model, options);
      INFO(named.name << ", " << ToString(method) << ": " << result.message);
      REQUIRE(result.ok());
      CHECK_FALSE(HasWarning(result, "did not keep its tolerance"));
      CHECK(WorstError(result, SolveExact(model)) <= 100.0 * options.relative_tolerance);
    }
  }
}

TEST_CASE("Without the restart at the kinks a high-order method loses its order", "[numerics]") {
  // Fehlberg 8(7) straight through the C0 kinks at rtol 1e-9: the local error test does not
  // see them; the error grows by orders of magnitude and the result says why.
  const ImpactModel model = ImpactModel::FromScene(PaperScene(0.015, 27.6e6, 0.25));
  const ImpactResult exact = SolveExact(model);
  TimeIntegrationOptions options;
  options.method = ComputationMethod::kArkodeErk87;
  options.relative_tolerance = 1e-9;
  const ImpactResult restarted = SimulateImpact(model, options);
  options.restart_at_phase_switches = false;
  const ImpactResult through = SimulateImpact(model, options);
  REQUIRE(restarted.ok());
  REQUIRE(through.ok());
  CHECK(WorstError(through, exact) > 100.0 * WorstError(restarted, exact));
  CHECK(WorstError(through, exact) > 1000.0 * options.relative_tolerance);
  CHECK(HasWarning(through, "C0 kinks"));
  CHECK(HasWarning(through, "did not keep its tolerance"));
}

TEST_CASE("An explicit method at a tight tolerance stops at the step limit with a status",
          "[numerics]") {
  // Bogacki-Shampine 3(2) needs ~17 000 steps at rtol 1e-12 on the paper scene.
  TimeIntegrationOptions options;
  options.method = ComputationMethod::kArkodeErk32;
  options.relative_tolerance = 1e-12;
  options.max_steps = 2000;
  const ImpactResult result = SimulateImpact(ImpactModel::FromScene(PaperScene(0.015)), options);
  CHECK(result.status == SolveStatus::kStepLimit);
  CHECK_FALSE(result.ok());
  CHECK(result.message.find("step limit") != std::string::npos);
  CHECK_FALSE(result.contact_duration_s.has_value());
  CHECK_FALSE(result.energy_residual.has_value());
}

TEST_CASE("Contact starts at delta = 0 without a spurious separation event at t0",
          "[numerics]") {
  // δ = 0 at t = 0 is a root of the separation function; only its downward crossing counts.
  for (const ComputationMethod method : TimeIntegrationMethods()) {
    for (const double speed : {0.01, 2.0, 10.0}) {
      Scene scene = PaperScene(0.015);
      scene.robot.speed_m_per_s = speed;
      const ImpactModel model = ImpactModel::FromScene(scene);
      TimeIntegrationOptions options;
      options.method = method;
      options.record_history = true;
      const ImpactResult result = SimulateImpact(model, options);
      INFO(ToString(method) << " at " << speed << " m/s: " << result.message);
      REQUIRE(result.ok());
      REQUIRE(result.history.size() > 10);
      CHECK(result.history.front().time_s == 0.0);
      CHECK(result.history.front().penetration_m == 0.0);
      CHECK(RelativeError(*result.contact_duration_s, *SolveExact(model).contact_duration_s) < 1e-4);
    }
  }
}

TEST_CASE("An overshooting step never takes the pow of a negative base", "[numerics]") {
  // Each phase's formula is evaluated beyond its ends while a step overshoots a switch;
  // the phase-local penetration is clamped at 0, so every value stays finite.
  for (const double thickness : {0.0, 0.002, 0.015}) {
    const ImpactModel model = ImpactModel::FromScene(PaperScene(thickness));
    for (std::size_t i = 0; i < model.segment_count(); ++i) {
      const double start = model.segment(i).start_m;
      for (const double delta : {start - 1e-3, start - 1e-15, start, start + 1e-15, start + 0.05}) {
        const ContactState state = model.StateInSegment(i, delta);
        INFO("segment " << i << ", delta " << delta);
        CHECK(std::isfinite(state.force_N));
        CHECK(std::isfinite(state.compressive_stress_Pa));
        CHECK(std::isfinite(state.energy_density_J_per_m2));
        CHECK(std::isfinite(state.potential_energy_J));
        CHECK(std::isfinite(state.stiffness_N_per_m));
      }
    }
  }
}

TEST_CASE("A phase lasting under a microsecond is entered and left, not stepped over", "[numerics]") {
  // The thinnest covering (the floor, 0.1 mm) at 100 m/s: phase 2 (covering on bone) spans
  // 80 um of penetration, under a microsecond. (A 1 um covering, a few ns, is below the floor.)
  Scene scene = PaperScene(kMinLayerThickness_m, 1e9, 0.25);
  scene.robot.speed_m_per_s = 100.0;
  const ImpactModel model = ImpactModel::FromScene(scene);
  REQUIRE(SolveExact(model).peaks.phase_at_max == Phase::kRobotOnBone);
  for (const ComputationMethod method : TimeIntegrationMethods()) {
    TimeIntegrationOptions options;
    options.method = method;
    const ImpactResult result = SimulateImpact(model, options);
    INFO(ToString(method) << ": " << result.message);
    REQUIRE(result.ok());
    CHECK(result.statistics.restarts == 4);  // 1 -> 2 -> 3 -> 2 -> 1
    CHECK(result.peaks.phase_at_max == Phase::kRobotOnBone);
  }
}

TEST_CASE("Flat on flat has no Hertz contact and is refused by name", "[numerics]") {
  Scene scene = PaperScene(0.015);
  scene.robot.radius_m = kFlat;
  scene.head.radius_m = kFlat;
  CHECK_THROWS_WITH(ImpactModel::FromScene(scene), Catch::Contains("head.radius"));
}

TEST_CASE("A maximum grazing a switch is right even when the crossing is not seen", "[numerics]") {
  // δ_max a hair (1e-9 relative) above t1 or t2: δ crosses the switch up and back inside one
  // step, where rootfinding (signs at the step ends) cannot see it; the excursion is then
  // integrated with the lower phase's law continued, whose force differs by K x^n with
  // x ~ 1e-9 t. The peaks stay within the tolerance; the phase flag may read the lower phase.
  for (const std::size_t segment : {std::size_t{1}, std::size_t{2}}) {
    for (const double excess : {1e-3, 1e-9, 0.0}) {
      Scene scene = PaperScene(0.015, 27.6e6, 0.25);
      const ImpactModel base = ImpactModel::FromScene(scene);
      const double threshold = base.segment(segment).start_m;
      const double energy = base.StateAt(threshold * (1.0 + excess)).potential_energy_J;
      scene.robot.speed_m_per_s = std::sqrt(2.0 * energy / base.effective_mass_kg());
      const ImpactModel model = ImpactModel::FromScene(scene);
      const ImpactResult exact = SolveExact(model);
      for (const ComputationMethod method :
           {ComputationMethod::kArkodeErk54, ComputationMethod::kCvodeAdams}) {
        TimeIntegrationOptions options;
        options.method = method;
        const ImpactResult result = SimulateImpact(model, options);
        INFO(ToString(method) << ", switch " << segment << ", excess " << excess << ": "
                              << result.message);
        REQUIRE(result.ok());
        CHECK(WorstError(result, exact) <= 100.0 * options.relative_tolerance);
        const int phase_gap = static_cast<int>(exact.peaks.phase_at_max) % 10 -
                              static_cast<int>(result.peaks.phase_at_max) % 10;
        CHECK((phase_gap == 0 || (excess < 1e-6 && phase_gap == 1)));
      }
    }
  }
}

namespace {

/// The scenes of the ERK 6(5) / ERK 8(7) limit and of the σ_c-at-t1 limit (docs/numerics.md,
/// "Measured limits"): a covering on scalp, a stiff thin covering (the optimiser's corner),
/// a thick soft one, the bare robot, the literal thresholds and a bottomed-out fixed head.
std::vector<NamedScene> LimitScenes() {
  std::vector<NamedScene> scenes;
  const Scene base = PaperScene(0.015, 27.6e6, 0.22);
  auto add = [&](std::string name, auto&& edit) { AddVariant(scenes, base, std::move(name), edit); };
  add("paper scene, 15 mm of 27.6 MPa", [](Scene&) {});
  add("4 mm of 1 GPa", [](Scene& s) { s.covering = {999109940.49841368, 0.25, 0.0039910199699451044}; });
  add("40 mm of 1 MPa", [](Scene& s) { s.covering = {1e6, 0.25, 0.04}; });
  add("no covering", [](Scene& s) { s.covering.thickness_m = 0.0; });
  add("literal thresholds", [](Scene& s) { s.model.thresholds = ThresholdReading::kLiteral; });
  add("2 mm of 200 MPa, fixed head", [](Scene& s) {
    s.covering = {200e6, 0.25, 0.002};
    s.head.mass_kg = kFixed;
  });
  return scenes;
}

/// The worst relative error of the peaks but σ_c (and σ_t, which follows it), the duration and
/// the rebound speed against the exact path.
double WorstErrorButStress(const ImpactResult& simulated, const ImpactResult& exact) {
  return std::max({RelativeError(simulated.peaks.max_penetration_m, exact.peaks.max_penetration_m),
                   RelativeError(simulated.peaks.peak_force_N, exact.peaks.peak_force_N),
                   RelativeError(simulated.peaks.max_energy_density_J_per_m2,
                                 exact.peaks.max_energy_density_J_per_m2),
                   RelativeError(*simulated.contact_duration_s, *exact.contact_duration_s),
                   RelativeError(*simulated.rebound_speed_m_per_s, *exact.rebound_speed_m_per_s)});
}

}  // namespace

TEST_CASE("ERK 6(5) and ERK 8(7) stay within their measured limits", "[numerics][limits]") {
  // SUNDIALS 6.4.1's ARKODE_VERNER_8_5_6 converges at order 3 (finding 5), and Fehlberg 8(7)
  // locates its events on a degree-5 interpolant (finding 6): neither keeps 100 rtol. Measured
  // over these 6 scenes x 8 speeds (0.05-8 m/s), δ-only and extended path: the worst of the
  // five peaks, T and the rebound speed reached 232 rtol (ERK 6(5)) and 140 rtol (ERK 8(7)) at
  // rtol 1e-6, 902 and 974 rtol at 1e-8. The limits docs/numerics.md states are asserted with
  // a margin of about 1.3x, so that the test fails if either gets worse.
  struct Limit {
    ComputationMethod method;
    double rtol, bound;  // bound in units of rtol
  };
  const Limit limits[] = {{ComputationMethod::kArkodeErk65, 1e-6, 300.0},
                          {ComputationMethod::kArkodeErk65, 1e-8, 1200.0},
                          {ComputationMethod::kArkodeErk87, 1e-6, 200.0},
                          {ComputationMethod::kArkodeErk87, 1e-8, 1300.0}};
  TimeIntegrator integrator;
  for (const NamedScene& named : LimitScenes()) {
    for (const double speed : {0.05, 0.2, 0.5, 1.0, 2.0, 3.0, 5.0, 8.0}) {
      Scene scene = named.scene;
      scene.robot.speed_m_per_s = speed;
      const ImpactModel model = ImpactModel::FromScene(scene);
      const ImpactResult exact = SolveExact(model);
      for (const Limit& limit : limits) {
        for (const bool extended : {false, true}) {
          TimeIntegrationOptions options;
          options.method = limit.method;
          options.relative_tolerance = limit.rtol;
          options.force_extended_dynamics = extended;
          const ImpactResult result = integrator.Simulate(model, options);
          INFO(named.name << " at " << speed << " m/s, " << ToString(limit.method) << ", rtol "
                          << limit.rtol << (extended ? ", extended path" : "") << ": " << result.message);
          REQUIRE(result.ok());
          const double error = WorstError(result, exact);
          CHECK(error <= limit.bound * limit.rtol);
          // The self-check (energy residual) fell short of the error by at most 1.63x on this
          // scan (one result 101 rtol off without the warning, its residual 97 rtol): beyond
          // 200 rtol every result says it did not keep its tolerance.
          if (error > 200.0 * limit.rtol) CHECK(HasWarning(result, "did not keep its tolerance"));
        }
      }
    }
  }
}

TEST_CASE("The peak contact stress grazing t1 is as accurate as delta_max allows", "[numerics][limits]") {
  // Just above t1 (the covering on bone, n = 1.8), σ_c = σ_1 + k x^0.8 has an unbounded slope in
  // δ: an error ε in δ_max moves σ_c by up to k (ε δ_max)^0.8, far more than ε. The stated limit
  // (docs/numerics.md): σ_c,max is within max(100 rtol, the change of σ_c over 100 rtol of
  // δ_max) of the exact path, every other peak, T and the rebound within 100 rtol. Measured over
  // these scenes x 67 offsets of δ_max from t1 (±1e-14 .. ±5e-4 relative) x rtol 1e-4 .. 1e-10,
  // δ-only and extended path: σ_c's error reached 1.2e4 rtol (CVODE BDF) but never more than 0.22
  // of that change for the six well-behaved methods.
  TimeIntegrator integrator;
  double largest_stress_error = 0.0;  // in units of rtol
  for (const NamedScene& named : LimitScenes()) {
    const double t1 = ImpactModel::FromScene(named.scene).segment(1).start_m;
    for (const double relative : {-1e-6, -1e-9, 0.0, 1e-12, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6}) {
      const ImpactModel model = ImpactModel::FromScene(test::WithMaxPenetration(named.scene, t1 * (1.0 + relative)));
      const ImpactResult exact = SolveExact(model);
      for (const double rtol : {1e-6, 1e-8}) {
        const double stress_bound = std::max(100.0, test::StressChangeOver(model, exact.peaks, 100.0 * rtol) / rtol);
        for (const ComputationMethod method :
             {ComputationMethod::kCvodeAdams, ComputationMethod::kCvodeBdf, ComputationMethod::kArkodeErk32,
              ComputationMethod::kArkodeErk54, ComputationMethod::kArkodeSdirk43,
              ComputationMethod::kArkodeEsdirk54}) {
          for (const bool extended : {false, true}) {
            TimeIntegrationOptions options;
            options.method = method;
            options.relative_tolerance = rtol;
            options.force_extended_dynamics = extended;
            const ImpactResult result = integrator.Simulate(model, options);
            INFO(named.name << ", δ_max at t1 x (1 + " << relative << "), " << ToString(method) << ", rtol "
                            << rtol << (extended ? ", extended path" : "") << ": " << result.message);
            REQUIRE(result.ok());
            CHECK(WorstErrorButStress(result, exact) <= 100.0 * rtol);
            const double stress_error =
                RelativeError(result.peaks.max_compressive_stress_Pa, exact.peaks.max_compressive_stress_Pa) / rtol;
            CHECK(stress_error <= stress_bound);
            largest_stress_error = std::max(largest_stress_error, stress_error);
          }
        }
      }
    }
  }
  // The limit is real: 100 rtol alone would not hold for σ_c here.
  CHECK(largest_stress_error > 100.0);
}
