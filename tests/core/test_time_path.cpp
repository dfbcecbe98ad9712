// The CVODE time path itself: energy conservation (rebound speed = impact speed, e back to
// zero at separation, U(δ_max) = ½ m v0²), a consistent history, restarts at every switch,
// reuse of the workspace, threads, option validation, and failures reported as a status with
// CVODE's message (a step limit), never as an exception or a wrong number.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "test_helpers.hpp"

using namespace covopt;
using covopt::test::AddVariant;
using covopt::test::CheckPeaksAgainstExact;
using covopt::test::NamedScene;
using covopt::test::PaperScene;
using covopt::test::RelativeError;

namespace {

/// δ where the robot-on-bone segment (phase 3) begins: t2, or t1 without a covering [m].
double FullCompressionSwitch(const ImpactModel& model) {
  return model.segment(model.segment_count() - 1).start_m;
}

/// `scene` with the impact speed at which the exact δ_max is the full-compression switch
/// times (1 + relative): ½ m v0² = U(t2 (1 + relative)).
Scene GrazingScene(Scene scene, double relative) {
  const ImpactModel model = ImpactModel::FromScene(scene);
  const double target = FullCompressionSwitch(model) * (1.0 + relative);
  scene.robot.speed_m_per_s =
      std::sqrt(2.0 * model.StateAt(target).potential_energy_J / model.effective_mass_kg());
  return scene;
}

/// The exact path's result for `model`, the reference of the grazing tests. δ_max may round
/// exactly onto the start of its segment (δ_max == t2 to the bit); the exact duration is finite
/// there too (tests/core/test_exact_path.cpp, "delta_max landing exactly on a switch").
ImpactResult ExactReference(const ImpactModel& model) {
  ImpactResult exact = SolveExact(model);
  REQUIRE(std::isfinite(*exact.contact_duration_s));
  REQUIRE(std::isfinite(*exact.time_of_max_compression_s));
  return exact;
}

/// Every peak, the duration, the rebound speed and the time of the peak within `limit`
/// (relative) of the exact path.
void CheckAgainstExact(const ImpactResult& result, const ImpactResult& exact, double limit) {
  CheckPeaksAgainstExact(result, exact, limit);
  CHECK(RelativeError(*result.time_of_max_compression_s, *exact.time_of_max_compression_s) <
        limit);
}

}  // namespace

TEST_CASE("Energy is conserved: rebound speed equals impact speed", "[time]") {
  const double thickness = GENERATE(0.0, 0.002, 0.015);
  const ImpactModel model = ImpactModel::FromScene(PaperScene(thickness, 27.6e6, 0.22));
  TimeIntegrationOptions options;
  options.record_history = true;
  const ImpactResult result = SimulateImpact(model, options);
  REQUIRE(result.ok());
  CHECK(RelativeError(*result.rebound_speed_m_per_s, 2.0) < 1e-6);
  const ContactState at_max = model.StateAt(result.peaks.max_penetration_m);
  CHECK(RelativeError(at_max.potential_energy_J, model.impact_energy_J()) < 1e-6);
  // e is a function of δ alone: the integrated e returns to 0 at separation.
  CHECK(std::abs(result.history.back().energy_density_J_per_m2) <
        1e-6 * result.peaks.max_energy_density_J_per_m2);
}

TEST_CASE("The history is ordered, physical and consistent with the law", "[time]") {
  const ImpactModel model = ImpactModel::FromScene(PaperScene(0.015, 27.6e6, 0.22));
  TimeIntegrationOptions options;
  options.record_history = true;
  const ImpactResult result = SimulateImpact(model, options);
  REQUIRE(result.ok());
  REQUIRE(result.history.size() > 20);
  CHECK(result.history.front().time_s == 0.0);
  CHECK(result.history.back().time_s == Approx(*result.contact_duration_s).epsilon(1e-15));
  double previous_time = -1.0;
  double max_penetration = 0.0;
  for (const HistorySample& sample : result.history) {
    CHECK(sample.time_s > previous_time);
    previous_time = sample.time_s;
    CHECK(sample.penetration_m >= -1e-9 * result.peaks.max_penetration_m);
    CHECK(sample.force_N == model.StateAt(sample.penetration_m).force_N);
    const double e_law = model.StateAt(sample.penetration_m).energy_density_J_per_m2;
    CHECK(std::abs(sample.energy_density_J_per_m2 - e_law) <
          1e-6 * result.peaks.max_energy_density_J_per_m2);
    max_penetration = std::max(max_penetration, sample.penetration_m);
  }
  CHECK(max_penetration == result.peaks.max_penetration_m);
}

TEST_CASE("The integrator restarts at each switch crossed, both ways", "[time]") {
  const auto restarts = [](double thickness) {
    const ImpactModel model = ImpactModel::FromScene(PaperScene(thickness, 27.6e6, 0.22));
    return SimulateImpact(model).statistics.restarts;
  };
  CHECK(restarts(0.0) == 2);    // bare robot reaches bone: 1 -> 3 -> 1
  CHECK(restarts(0.03) == 2);   // thick covering: 1 -> 2 -> 1
  CHECK(restarts(0.002) == 4);  // thin covering bottoms out: 1 -> 2 -> 3 -> 2 -> 1
  Scene slow = PaperScene(0.0);
  slow.robot.speed_m_per_s = 0.05;
  CHECK(SimulateImpact(ImpactModel::FromScene(slow)).statistics.restarts == 0);
}

TEST_CASE("Statistics are reported", "[time]") {
  const ImpactResult result = SimulateImpact(ImpactModel::FromScene(PaperScene(0.015)));
  CHECK(result.method == ComputationMethod::kArkodeErk54);  // the default
  CHECK(result.statistics.steps > 10);
  CHECK(result.statistics.rhs_evaluations >= 6 * result.statistics.steps);  // 7 stages, FSAL
  CHECK(result.statistics.root_evaluations > 0);
  CHECK(result.statistics.jacobian_evaluations == 0);  // explicit: no Jacobian
  TimeIntegrationOptions adams;
  adams.method = ComputationMethod::kCvodeAdams;
  const ImpactResult fixed_point = SimulateImpact(ImpactModel::FromScene(PaperScene(0.015)), adams);
  CHECK(fixed_point.method == ComputationMethod::kCvodeAdams);
  CHECK(fixed_point.statistics.jacobian_evaluations == 0);  // Adams: fixed point, no Jacobian
  CHECK(fixed_point.statistics.nonlinear_iterations > 0);
  TimeIntegrationOptions bdf;
  bdf.method = ComputationMethod::kCvodeBdf;
  const ImpactResult newton = SimulateImpact(ImpactModel::FromScene(PaperScene(0.015)), bdf);
  CHECK(newton.method == ComputationMethod::kCvodeBdf);
  CHECK(newton.statistics.jacobian_evaluations > 0);
}

TEST_CASE("A reused workspace gives bit-identical results", "[time]") {
  TimeIntegrator integrator;
  const ImpactModel a = ImpactModel::FromScene(PaperScene(0.015));
  const ImpactModel b = ImpactModel::FromScene(PaperScene(0.0));
  const ImpactResult first = integrator.Simulate(a);
  (void)integrator.Simulate(b);
  TimeIntegrationOptions bdf;
  bdf.method = ComputationMethod::kCvodeBdf;
  (void)integrator.Simulate(b, bdf);
  const ImpactResult again = integrator.Simulate(a);
  CHECK(again.peaks.max_penetration_m == first.peaks.max_penetration_m);
  CHECK(*again.contact_duration_s == *first.contact_duration_s);
  CHECK(again.statistics.steps == first.statistics.steps);
}

TEST_CASE("Threads with their own workspaces agree with a single thread", "[time]") {
  const ImpactModel model = ImpactModel::FromScene(PaperScene(0.015));
  const ImpactResult reference = SimulateImpact(model);
  double results[2] = {0, 0};
  std::thread t0([&] { results[0] = *SimulateImpact(model).contact_duration_s; });
  std::thread t1([&] { results[1] = *SimulateImpact(model).contact_duration_s; });
  t0.join();
  t1.join();
  CHECK(results[0] == *reference.contact_duration_s);
  CHECK(results[1] == *reference.contact_duration_s);
}

TEST_CASE("A step limit is a status with a message, not an exception", "[time][failure]") {
  const ImpactModel model = ImpactModel::FromScene(PaperScene(0.015));
  TimeIntegrationOptions options;
  options.max_steps = 10;
  ImpactResult result;
  REQUIRE_NOTHROW(result = SimulateImpact(model, options));
  CHECK(result.status == SolveStatus::kStepLimit);
  CHECK_FALSE(result.ok());
  CHECK_FALSE(result.contact_duration_s.has_value());
  CHECK_THAT(result.message, Catch::Contains("step limit"));
  // The workspace is still usable afterwards.
  CHECK(SimulateImpact(model).ok());
}

TEST_CASE("Out-of-range options are rejected naming the option", "[time]") {
  const ImpactModel model = ImpactModel::FromScene(PaperScene(0.015));
  TimeIntegrationOptions options;
  options.relative_tolerance = 0.5;
  CHECK_THROWS_WITH(SimulateImpact(model, options), "relative_tolerance must be in [1e-14, 1e-2] (got 0.5)");
  options = {};
  options.absolute_tolerance = -1;
  CHECK_THROWS_WITH(SimulateImpact(model, options),
                    "absolute_tolerance must be in (0, 1e-2], or 0 for the relative tolerance (got -1)");
  options = {};
  options.max_steps = 0;
  CHECK_THROWS_WITH(SimulateImpact(model, options), "max_steps must be >= 10 (got 0)");
  options = {};
  options.method = ComputationMethod::kExact;
  CHECK_THROWS_WITH(SimulateImpact(model, options), Catch::StartsWith("method must be a time integrator (cvode-adams, ") &&
                                                        Catch::EndsWith(") (got exact)"));
  // The same check, with the caller's prefix, behind the sweep and optim's oracles.
  options = {};
  options.history_max_interval_s = -1;
  CHECK_THROWS_WITH(ValidateTimeIntegrationOptions(options, "time_path."),
                    "time_path.history_max_interval_s must be finite and >= 0 s (got -1)");
}

TEST_CASE("Without restarts the kinks cost accuracy but the run still completes", "[time]") {
  const ImpactModel model = ImpactModel::FromScene(PaperScene(0.002, 27.6e6, 0.22));
  TimeIntegrationOptions options;
  options.restart_at_phase_switches = false;
  const ImpactResult through = SimulateImpact(model, options);
  REQUIRE(through.ok());
  CHECK(through.statistics.restarts == 0);
  const ImpactResult exact = SolveExact(model);
  CHECK(RelativeError(through.peaks.max_penetration_m, exact.peaks.max_penetration_m) < 1e-4);
}

TEST_CASE("Dense output fills the history to the requested spacing", "[time]") {
  const ImpactModel model = ImpactModel::FromScene(PaperScene(0.015, 27.6e6, 0.22));
  const double duration = *SolveExact(model).contact_duration_s;
  TimeIntegrationOptions options;
  options.record_history = true;
  options.history_max_interval_s = duration / 300.0;
  const ImpactResult result = SimulateImpact(model, options);
  REQUIRE(result.ok());
  CHECK(result.history.size() >= 300);
  for (std::size_t i = 1; i < result.history.size(); ++i) {
    const HistorySample& sample = result.history[i];
    CHECK(sample.time_s > result.history[i - 1].time_s);
    CHECK(sample.time_s - result.history[i - 1].time_s <= options.history_max_interval_s * (1 + 1e-9));
    // Interpolated states stay on the law: e(δ) from the state matches the law's e.
    CHECK(std::abs(sample.energy_density_J_per_m2 -
                   model.StateAt(sample.penetration_m).energy_density_J_per_m2) <
          1e-5 * result.peaks.max_energy_density_J_per_m2);
  }
  options.history_max_interval_s = -1.0;
  CHECK_THROWS_WITH(SimulateImpact(model, options), Catch::Contains("history_max_interval_s"));
}

TEST_CASE("Each phase's unloading ends on its series: duration, symmetry and rebound", "[time]") {
  // Unloading toward a phase start (x -> 0, where the law's derivatives are singular) stops
  // where the phase's opening ended and finishes on the opening's series run backwards; the
  // motion is conservative, so the result must be the loading run in reverse.
  Scene scene = PaperScene(GENERATE(0.0, 0.002, 0.015, 0.05), 27.6e6, 0.22);
  scene.robot.speed_m_per_s = GENERATE(0.5, 2.0, 5.0);
  scene.model.thresholds = GENERATE(ThresholdReading::kCumulative, ThresholdReading::kLiteral);
  const ImpactModel model = ImpactModel::FromScene(scene);
  const ImpactResult exact = SolveExact(model);
  const ImpactResult result = SimulateImpact(model);
  REQUIRE(result.ok());
  CHECK(RelativeError(*result.contact_duration_s, *exact.contact_duration_s) < 1e-7);
  CHECK(RelativeError(*result.contact_duration_s, 2.0 * *result.time_of_max_compression_s) < 1e-7);
  CHECK(RelativeError(*result.rebound_speed_m_per_s, scene.robot.speed_m_per_s) < 1e-7);
}

TEST_CASE("Grazing the full-compression switch", "[time][grazing]") {
  // δ_max a hair above (or at, or below) the switch to the robot-on-bone phase: the designs
  // that the bracketed search's bisection on the full-compression boundary produces. The
  // integrator reaches the switch with almost no speed left; restarted in phase 3, δ = t2 + x
  // rounded back to t2 and the lower switch's root function was 0 from the restart on.
  // Before the grazing turn (time_integration.cpp, GrazingTurnAtSwitch) 35 of these 1800 runs
  // failed, on every scene: CVODE Adams (33) and BDF (2), with CV_ILL_INPUT ("Root found at
  // and very near t") but one CV_CONV_FAILURE, at offsets from -1e-6 to +1e-6, each within
  // 10 rtol of the switch; ERK 5(4) ran away (t = 1e149) and ERK 8(7) hit its step limit on
  // the optimiser's designs of the next test. Every integrator must now succeed and agree
  // with the exact path.
  std::vector<NamedScene> scenes;
  const Scene paper = PaperScene(0.015, 27.6e6, 0.22);
  auto add = [&](std::string name, auto&& edit) { AddVariant(scenes, paper, std::move(name), edit); };
  add("paper scene, 15 mm of 27.6 MPa", [](Scene&) {});
  add("4 mm of 1 GPa (the optimiser's stiff corner)", [](Scene& s) {
    s.covering = {999109940.49841368, 0.25, 0.0039910199699451044};
  });
  add("40 mm of 1 MPa", [](Scene& s) { s.covering = {1e6, 0.25, 0.04}; });
  add("no covering (the switch is t1)", [](Scene& s) { s.covering.thickness_m = 0.0; });
  add("literal thresholds", [](Scene& s) { s.model.thresholds = ThresholdReading::kLiteral; });

  TimeIntegrator integrator;
  for (const NamedScene& named : scenes) {
    for (const double relative : {-1e-6, -1e-10, -1e-14, 0.0, 1e-16, 1e-15, 1e-14, 1e-13, 1e-12,
                                  1e-11, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6}) {
      const ImpactModel model = ImpactModel::FromScene(GrazingScene(named.scene, relative));
      const ImpactResult exact = ExactReference(model);
      REQUIRE(std::isfinite(*exact.contact_duration_s));
      for (const double rtol : {1e-6, 1e-8, 1e-10}) {
        for (const ComputationMethod method : TimeIntegrationMethods()) {
          TimeIntegrationOptions options;
          options.method = method;
          options.relative_tolerance = rtol;
          const ImpactResult result = integrator.Simulate(model, options);
          INFO(named.name << ", δ_max at the switch x (1 + " << relative << "), "
                          << ToString(method) << ", rtol " << rtol << ": " << result.message);
          CHECK(result.ok());  // every failing combination listed, not only the first
          if (!result.ok()) continue;
          // ERK 6(5) (a 3rd-order table in SUNDIALS 6.4.1) and ERK 8(7) (events located on
          // the interpolant) miss 100 rtol on these scenes whether or not δ_max grazes the
          // switch (docs/numerics.md, findings 5 and 6; measured at 0.5-5 m/s without grazing:
          // up to 230 and 140 rtol at rtol 1e-6, 740 and 890 rtol at 1e-8): for them only the
          // status and a bound against gross errors (a turn or a return lost) are checked.
          const bool known_inaccurate = method == ComputationMethod::kArkodeErk65 ||
                                        method == ComputationMethod::kArkodeErk87;
          CheckAgainstExact(result, exact, (known_inaccurate ? 1e4 : 100.0) * rtol);
          // Within the tolerance of the switch either phase is a right reading; further out
          // the phase at the peak is the exact path's.
          if (std::abs(relative) > 1e3 * rtol) {
            CHECK(result.peaks.phase_at_max == exact.peaks.phase_at_max);
            CHECK(result.peaks.fully_compressed == exact.peaks.fully_compressed);
          }
        }
      }
    }
  }
}

TEST_CASE("Grazing the full-compression switch: the optimiser's failed designs",
          "[time][grazing]") {
  // The designs docs/numerics.md reported from `covopt optimize --oracle time-path` (2 m/s,
  // paper scene otherwise), with the integrator and tolerance each failed with; with this
  // history the ERK 5(4) runaway threw std::bad_alloc.
  struct Design {
    double modulus_Pa, thickness_m;
    ComputationMethod method;
    double rtol;
  };
  for (const Design& d : {Design{999109940.49841368, 0.0039910199699451044,  // CV_ILL_INPUT
                                 ComputationMethod::kCvodeAdams, 1e-9},
                          Design{700153201.49938297, 0.0044343416939057597,  // t = 1.2e149
                                 ComputationMethod::kArkodeErk54, 1e-5},
                          Design{353344091.8939957, 0.0054741874391763604,  // step limit
                                 ComputationMethod::kArkodeErk87, 1e-4}}) {
    const ImpactModel model = ImpactModel::FromScene(PaperScene(d.thickness_m, d.modulus_Pa, 0.25));
    const ImpactResult exact = ExactReference(model);
    TimeIntegrationOptions options;
    options.method = d.method;
    options.relative_tolerance = d.rtol;
    options.record_history = true;
    options.history_max_interval_s = *exact.contact_duration_s / 300.0;
    const ImpactResult result = SimulateImpact(model, options);
    INFO(ToString(d.method) << ", rtol " << d.rtol << ", E_c " << d.modulus_Pa << " Pa: "
                            << result.message);
    CHECK(result.ok());
    if (!result.ok()) continue;
    CHECK(RelativeError(FullCompressionSwitch(model), exact.peaks.max_penetration_m) < 1e-5);
    CheckAgainstExact(result, exact, 100.0 * d.rtol);
    // The history runs through the turn in order, to the requested spacing, and holds δ_max.
    double previous_time = -1.0;
    double max_penetration = 0.0;
    for (const HistorySample& sample : result.history) {
      CHECK(sample.time_s > previous_time);
      CHECK(sample.time_s - std::max(previous_time, 0.0) <=
            options.history_max_interval_s * (1 + 1e-9));
      previous_time = sample.time_s;
      max_penetration = std::max(max_penetration, sample.penetration_m);
    }
    CHECK(max_penetration == result.peaks.max_penetration_m);
    CHECK(result.history.back().time_s == *result.contact_duration_s);
  }
}
