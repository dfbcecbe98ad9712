// The CVODE time path itself: energy conservation (rebound speed = impact speed, e back to
// zero at separation, U(δ_max) = ½ m v0²), a consistent history, restarts at every switch,
// reuse of the workspace, threads, option validation, and failures reported as a status with
// CVODE's message (a step limit), never as an exception or a wrong number.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <thread>

#include "test_helpers.hpp"

using namespace covopt;
using covopt::test::PaperScene;
using covopt::test::RelativeError;

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
  CHECK_THROWS_WITH(SimulateImpact(model, options), Catch::Contains("rtol"));
  options = {};
  options.absolute_tolerance = -1;
  CHECK_THROWS_WITH(SimulateImpact(model, options), Catch::Contains("atol"));
  options = {};
  options.max_steps = 0;
  CHECK_THROWS_WITH(SimulateImpact(model, options), Catch::Contains("max_steps"));
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
