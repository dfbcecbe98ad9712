// Forced failures of the time path (issue 6): step limits and tolerances CVODE/ARKODE cannot
// or may not take. A failure must come back as a status with the integrator's own message,
// never as NaN peaks or an exception, and must leave the reusable workspace clean (the next
// run is bit-identical to one on a fresh workspace). Run under COVOPT_SANITIZE these also show
// that the failure paths free what they allocate.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <catch2/catch.hpp>

#include "covopt/core/exact.hpp"
#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/time_integration.hpp"

namespace {

using covopt::ComputationMethod;
using covopt::ImpactModel;
using covopt::ImpactResult;
using covopt::Scene;
using covopt::SolveStatus;
using covopt::TimeIntegrationOptions;
using covopt::TimeIntegrator;

constexpr ComputationMethod kTimeMethods[] = {
    ComputationMethod::kCvodeAdams,    ComputationMethod::kCvodeBdf,
    ComputationMethod::kArkodeErk32,   ComputationMethod::kArkodeErk54,
    ComputationMethod::kArkodeErk65,   ComputationMethod::kArkodeErk87,
    ComputationMethod::kArkodeSdirk43, ComputationMethod::kArkodeEsdirk54,
};

void CheckSameResult(const ImpactResult& a, const ImpactResult& b) {
  CHECK(a.status == b.status);
  CHECK(a.peaks.max_penetration_m == b.peaks.max_penetration_m);
  CHECK(a.peaks.peak_force_N == b.peaks.peak_force_N);
  CHECK(a.peaks.max_energy_density_J_per_m2 == b.peaks.max_energy_density_J_per_m2);
  CHECK(a.contact_duration_s == b.contact_duration_s);
  CHECK(a.statistics.steps == b.statistics.steps);
}

}  // namespace

TEST_CASE("a step limit is reported as step-limit with the integrator's message",
          "[time][faults]") {
  const ImpactModel model = ImpactModel::FromScene(Scene{});
  for (const ComputationMethod method : kTimeMethods) {
    CAPTURE(covopt::ToString(method));
    TimeIntegrationOptions options;
    options.method = method;
    options.max_steps = 10;
    options.record_history = true;
    TimeIntegrator integrator;
    const ImpactResult failed = integrator.Simulate(model, options);
    CHECK_FALSE(failed.ok());
    CHECK(failed.status == SolveStatus::kStepLimit);
    CHECK(covopt::ToString(failed.status) == std::string_view("step-limit"));
    CHECK_FALSE(failed.message.empty());
    CHECK(failed.statistics.steps <= 10 + 2);  // the limit, give or take the restart steps
    // No result pretends to be one: a failed run carries no contact duration.
    CHECK_FALSE(failed.contact_duration_s.has_value());

    // The same workspace, after the failure, gives exactly what a fresh one gives.
    options.max_steps = 200000;
    const ImpactResult after = integrator.Simulate(model, options);
    TimeIntegrator fresh;
    const ImpactResult reference = fresh.Simulate(model, options);
    REQUIRE(after.ok());
    CheckSameResult(after, reference);
    CHECK(std::isfinite(after.peaks.max_penetration_m));
  }
}

TEST_CASE("tolerances no integrator can meet are rejected before it runs", "[time][faults]") {
  const ImpactModel model = ImpactModel::FromScene(Scene{});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Bad {
    double rtol, atol;
    const char* field;
  };
  const char* const rtol = "relative_tolerance must be in [1e-14, 1e-2]";
  const char* const atol = "absolute_tolerance must be in (0, 1e-2], or 0";
  for (const Bad& bad : {Bad{1e-16, 0.0, rtol}, Bad{0.0, 0.0, rtol}, Bad{-1e-8, 0.0, rtol}, Bad{nan, 0.0, rtol},
                         Bad{1.0, 0.0, rtol}, Bad{1e-8, -1.0, atol}, Bad{1e-8, nan, atol}, Bad{1e-8, 1.0, atol}}) {
    CAPTURE(bad.rtol, bad.atol);
    TimeIntegrationOptions options;
    options.relative_tolerance = bad.rtol;
    options.absolute_tolerance = bad.atol;
    CHECK_THROWS_AS(covopt::SimulateImpact(model, options), std::invalid_argument);
    try {
      (void)covopt::SimulateImpact(model, options);
    } catch (const std::invalid_argument& e) {
      CHECK_THAT(e.what(), Catch::Matchers::Contains(bad.field));
    }
  }
  TimeIntegrationOptions options;
  options.max_steps = 9;
  CHECK_THROWS_WITH(covopt::SimulateImpact(model, options), "max_steps must be >= 10 (got 9)");
}

TEST_CASE("the tightest allowed tolerance either succeeds or fails with a status, never NaN",
          "[time][faults]") {
  // rtol 1e-14 with an absolute tolerance of 1e-300 asks for ~100 ulp per step: at the edge
  // of what double precision can deliver. Whatever the integrator does, it must say so.
  const ImpactModel model = ImpactModel::FromScene(Scene{});
  const ImpactResult exact = covopt::SolveExact(model);
  for (const ComputationMethod method :
       {ComputationMethod::kCvodeAdams, ComputationMethod::kCvodeBdf}) {
    CAPTURE(covopt::ToString(method));
    TimeIntegrationOptions options;
    options.method = method;
    options.relative_tolerance = 1e-14;
    options.absolute_tolerance = 1e-300;
    options.max_steps = 20000;
    const ImpactResult result = covopt::SimulateImpact(model, options);
    CAPTURE(covopt::ToString(result.status), result.message);
    if (result.ok()) {
      CHECK(result.peaks.max_penetration_m ==
            Approx(exact.peaks.max_penetration_m).epsilon(1e-9));
      REQUIRE(result.contact_duration_s.has_value());
      CHECK(std::isfinite(*result.contact_duration_s));
    } else {
      CHECK_FALSE(result.message.empty());
      CHECK_FALSE(result.contact_duration_s.has_value());
    }
  }
}

TEST_CASE("repeated failures and successes on one workspace stay consistent", "[time][faults]") {
  // Under ASan/LSan this is the leak check of the failure path: 200 failed runs.
  const ImpactModel model = ImpactModel::FromScene(Scene{});
  TimeIntegrator integrator;
  TimeIntegrationOptions failing;
  failing.max_steps = 10;
  TimeIntegrationOptions passing;
  const ImpactResult reference = integrator.Simulate(model, passing);
  REQUIRE(reference.ok());
  for (int i = 0; i < 100; ++i) {
    const ImpactResult failed = integrator.Simulate(model, failing);
    REQUIRE(failed.status == SolveStatus::kStepLimit);
  }
  CheckSameResult(integrator.Simulate(model, passing), reference);
  for (int i = 0; i < 100; ++i) {
    const ImpactResult failed = covopt::SimulateImpact(model, failing);
    REQUIRE(failed.status == SolveStatus::kStepLimit);
  }
  CheckSameResult(covopt::SimulateImpact(model, passing), reference);
}
