// A TimeIntegrator is reused across runs (SimulateImpact keeps one per thread), so a run's
// output must not depend on what ran before it on the same integrator: the same scene gives
// the same peaks, times, energy residual, history and solver counters on a fresh integrator
// and after other scenes, other options and a failed run, for every method, on the δ-only
// path and on the extended one. (ARKODE's ReInit keeps the root-finding state of the previous
// run, which cost a reused integrator extra right-hand-side and root evaluations; see
// Stepper::BeginRun in core/src/stepper.hpp.)
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "test_helpers.hpp"

using namespace covopt;
using covopt::test::PaperScene;

namespace {

void RequireSameRun(const ImpactResult& again, const ImpactResult& fresh) {
  REQUIRE(fresh.ok());
  CHECK(again.status == fresh.status);
  CHECK(again.message == fresh.message);
  CHECK(again.raw_code == fresh.raw_code);
  CHECK(again.peaks.max_penetration_m == fresh.peaks.max_penetration_m);
  CHECK(again.peaks.peak_force_N == fresh.peaks.peak_force_N);
  CHECK(again.peaks.max_compressive_stress_Pa == fresh.peaks.max_compressive_stress_Pa);
  CHECK(again.peaks.max_energy_density_J_per_m2 == fresh.peaks.max_energy_density_J_per_m2);
  CHECK(again.contact_duration_s == fresh.contact_duration_s);
  CHECK(again.rebound_speed_m_per_s == fresh.rebound_speed_m_per_s);
  CHECK(again.coefficient_of_restitution == fresh.coefficient_of_restitution);
  CHECK(again.time_of_max_compression_s == fresh.time_of_max_compression_s);
  CHECK(again.energy_residual == fresh.energy_residual);
  CHECK(again.warnings.size() == fresh.warnings.size());
  const SolverStatistics& a = again.statistics;
  const SolverStatistics& f = fresh.statistics;
  CHECK(a.steps == f.steps);
  CHECK(a.rhs_evaluations == f.rhs_evaluations);
  CHECK(a.root_evaluations == f.root_evaluations);
  CHECK(a.jacobian_evaluations == f.jacobian_evaluations);
  CHECK(a.nonlinear_iterations == f.nonlinear_iterations);
  CHECK(a.error_test_failures == f.error_test_failures);
  CHECK(a.convergence_failures == f.convergence_failures);
  CHECK(a.restarts == f.restarts);
  REQUIRE(again.history.size() == fresh.history.size());
  for (std::size_t i = 0; i < fresh.history.size(); ++i) {
    CHECK(again.history[i].time_s == fresh.history[i].time_s);
    CHECK(again.history[i].penetration_m == fresh.history[i].penetration_m);
    CHECK(again.history[i].head_speed_m_per_s == fresh.history[i].head_speed_m_per_s);
    CHECK(again.history[i].dissipated_work_J == fresh.history[i].dissipated_work_J);
  }
}

Scene BrakingScene() {
  Scene scene = PaperScene(0.015);
  scene.robot.reaction_delay_s = 0.002;
  scene.robot.braking_m_per_s2 = 50.0;
  return scene;
}

Scene NeckScene() {
  Scene scene = PaperScene(0.005);
  scene.head.torso_mass_kg = 30.0;
  scene.head.neck_stiffness_N_per_m = 2e4;
  scene.head.neck_damping_N_s_per_m = 100.0;
  return scene;
}

Scene DampedScene() {
  Scene scene = PaperScene(0.0);
  scene.model.damping_s_per_m = 0.3;
  return scene;
}

}  // namespace

TEST_CASE("A reused integrator reports what a fresh one reports, counters included",
          "[time][reuse]") {
  const ComputationMethod method = GENERATE(from_range(TimeIntegrationMethods()));
  const bool extended = GENERATE(false, true);
  CAPTURE(std::string(ToString(method)), extended);

  Scene first = PaperScene(0.015);
  first.robot.speed_m_per_s = 3.0;  // the scene of the Python-against-CLI check
  if (extended) first = BrakingScene();
  const ImpactModel model = ImpactModel::FromScene(first);
  TimeIntegrationOptions options;
  options.method = method;
  options.record_history = true;

  TimeIntegrator integrator;
  const ImpactResult fresh = integrator.Simulate(model, options);

  // Other scenes, other options and a failure on the same integrator, on both paths.
  const std::vector<Scene> others{PaperScene(0.0), BrakingScene(), NeckScene(), DampedScene(),
                                  PaperScene(0.002, 1e6, 0.45)};
  for (const Scene& scene : others) {
    TimeIntegrationOptions other = options;
    other.record_history = false;
    other.relative_tolerance = 1e-6;
    (void)integrator.Simulate(ImpactModel::FromScene(scene), other);
    other.force_extended_dynamics = true;
    other.relative_tolerance = 1e-9;
    (void)integrator.Simulate(ImpactModel::FromScene(scene), other);
  }
  TimeIntegrationOptions failing = options;
  failing.max_steps = 10;
  REQUIRE_FALSE(integrator.Simulate(model, failing).ok());

  const ImpactResult again = integrator.Simulate(model, options);
  RequireSameRun(again, fresh);
  // And a second integrator in the same process, created after all of the above.
  TimeIntegrator another;
  RequireSameRun(another.Simulate(model, options), fresh);
}

TEST_CASE("The conservative scene on the extended path is as reproducible", "[time][reuse]") {
  const ComputationMethod method = GENERATE(from_range(TimeIntegrationMethods()));
  CAPTURE(std::string(ToString(method)));
  const ImpactModel model = ImpactModel::FromScene(PaperScene(0.015));
  TimeIntegrationOptions options;
  options.method = method;
  options.force_extended_dynamics = true;
  TimeIntegrator integrator;
  const ImpactResult fresh = integrator.Simulate(model, options);
  TimeIntegrationOptions conservative = options;
  conservative.force_extended_dynamics = false;
  (void)integrator.Simulate(model, conservative);
  (void)integrator.Simulate(ImpactModel::FromScene(NeckScene()), options);
  RequireSameRun(integrator.Simulate(model, options), fresh);
}
