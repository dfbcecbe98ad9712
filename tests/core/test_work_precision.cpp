// The work-precision study as a library call (covopt::MeasureWorkPrecision): the exact path is
// the first point and the reference (error 0); the default method's errors shrink as the
// tolerance tightens; the worst error is the largest of the five; integrating straight through
// the force law's kinks is less accurate than restarting at them; the summary (cheapest run per
// target, series keeping their tolerance) agrees with the points; a failed integration is data;
// progress reaches the total; bad options are rejected naming the field, the value and the
// allowed range.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "covopt/core/time_integration.hpp"
#include "covopt/core/work_precision.hpp"
#include "test_helpers.hpp"

namespace {

using covopt::ComputationMethod;
using covopt::RestartSeries;
using covopt::WorkPrecisionOptions;
using covopt::WorkPrecisionPoint;
using covopt::WorkPrecisionResult;
using covopt::WorkPrecisionStatus;

/// The paper's scene with its 15 mm covering of 27.6 MPa: the impact crosses the force law's
/// phase switches, where the law is only C⁰.
covopt::Scene CoveredPaperScene() { return covopt::test::PaperScene(0.015); }

/// One method, one timed run per point: the tests check accuracy, never time.
WorkPrecisionOptions QuickOptions(ComputationMethod method, std::vector<double> tolerances,
                                  RestartSeries restart) {
  WorkPrecisionOptions options;
  options.methods = {method};
  options.relative_tolerances = std::move(tolerances);
  options.restart = restart;
  options.repetitions = 1;
  return options;
}

}  // namespace

TEST_CASE("work-precision: the default method's errors shrink as the tolerance tightens",
          "[work_precision]") {
  const ComputationMethod default_method = covopt::TimeIntegrationOptions{}.method;
  const WorkPrecisionResult study = covopt::MeasureWorkPrecision(
      CoveredPaperScene(),
      QuickOptions(default_method, {1e-4, 1e-6, 1e-8, 1e-10}, RestartSeries::kOn));
  INFO(study.BriefReport());
  REQUIRE(study.status == WorkPrecisionStatus::kSuccess);
  REQUIRE(study.points.size() == 5);  // the exact path + 4 tolerances
  CHECK(study.points[0].method == ComputationMethod::kExact);
  CHECK(study.points[0].worst_error == 0.0);
  for (std::size_t i = 1; i + 1 < study.points.size(); ++i) {
    const WorkPrecisionPoint& loose = study.points[i];
    const WorkPrecisionPoint& tight = study.points[i + 1];
    CAPTURE(loose.relative_tolerance, loose.worst_error, tight.worst_error);
    CHECK(loose.method == default_method);
    CHECK(tight.relative_tolerance < loose.relative_tolerance);
    // Two decades of tolerance buy accuracy and cost steps.
    CHECK(tight.worst_error < loose.worst_error);
    CHECK(tight.statistics.steps > loose.statistics.steps);
  }
  // With the restarts the method keeps its promise: the error stays near the tolerance.
  for (std::size_t i = 1; i < study.points.size(); ++i) {
    CHECK(study.points[i].worst_error <= 100.0 * study.points[i].relative_tolerance);
  }
  REQUIRE(study.series.size() == 1);
  CHECK(study.series[0].kept_tolerance);
  CHECK(study.series[0].failures == 0);
}

TEST_CASE("work-precision: the worst error is the largest of the five relative errors",
          "[work_precision]") {
  const WorkPrecisionResult study = covopt::MeasureWorkPrecision(
      CoveredPaperScene(), QuickOptions(ComputationMethod::kCvodeAdams, {1e-3, 1e-5, 1e-7},
                                        RestartSeries::kBoth));
  REQUIRE(study.IsUsable());
  REQUIRE(study.points.size() == 7);  // the exact path + 2 series x 3 tolerances
  for (const WorkPrecisionPoint& p : study.points) {
    CAPTURE(covopt::ToString(p.method), p.restart, p.relative_tolerance);
    REQUIRE(p.ok());
    const double largest = std::max({p.error_max_penetration, p.error_peak_force,
                                     p.error_max_compressive_stress, p.error_max_energy_density,
                                     p.error_contact_duration});
    CHECK(p.worst_error == largest);
    CHECK(p.worst_error >= 0.0);
    CHECK(p.timed_runs == 1);
    CHECK(p.seconds_per_impact > 0.0);
  }
  // The restart series comes first, then the one without.
  CHECK(study.points[1].restart);
  CHECK_FALSE(study.points[4].restart);
  REQUIRE(study.series.size() == 2);
  CHECK(study.series[0].restart);
  CHECK_FALSE(study.series[1].restart);
}

TEST_CASE("work-precision: integrating through the kinks is less accurate than restarting",
          "[work_precision]") {
  // At tight tolerances the error of a run without restarts is set by the C⁰ kinks at the
  // phase switches, not by the tolerance.
  const WorkPrecisionResult study = covopt::MeasureWorkPrecision(
      CoveredPaperScene(),
      QuickOptions(ComputationMethod::kArkodeErk87, {1e-8, 1e-10}, RestartSeries::kBoth));
  REQUIRE(study.status == WorkPrecisionStatus::kSuccess);
  REQUIRE(study.points.size() == 5);
  for (std::size_t i = 1; i <= 2; ++i) {
    const WorkPrecisionPoint& restarted = study.points[i];
    const WorkPrecisionPoint& straight = study.points[i + 2];
    CAPTURE(restarted.relative_tolerance, restarted.worst_error, straight.worst_error);
    REQUIRE(restarted.relative_tolerance == straight.relative_tolerance);
    CHECK(restarted.restart);
    CHECK_FALSE(straight.restart);
    CHECK(straight.worst_error > restarted.worst_error);
  }
  // Fehlberg 8(7) loses its order at the kinks: that series does not keep its tolerance.
  REQUIRE(study.series.size() == 2);
  CHECK(study.series[0].kept_tolerance);
  CHECK_FALSE(study.series[1].kept_tolerance);
  CHECK(study.series[1].worst_error_to_tolerance > study.kept_tolerance_ratio);
}

TEST_CASE("work-precision: the cheapest run per target is the cheapest that reaches it",
          "[work_precision]") {
  WorkPrecisionOptions options = QuickOptions(ComputationMethod::kArkodeErk54,
                                              {1e-3, 1e-6, 1e-9}, RestartSeries::kBoth);
  options.methods.push_back(ComputationMethod::kCvodeBdf);
  options.error_targets = {1e-3, 1e-7, 1e-30};
  const WorkPrecisionResult study = covopt::MeasureWorkPrecision(CoveredPaperScene(), options);
  REQUIRE(study.IsUsable());
  REQUIRE(study.points.size() == 13);  // the exact path + 2 methods x 2 series x 3 tolerances
  REQUIRE(study.cheapest.size() == 3);
  for (const covopt::CheapestRun& run : study.cheapest) {
    CAPTURE(run.target_error);
    CHECK(study.CheapestReaching(run.target_error) ==
          (run.point ? &study.points[*run.point] : nullptr));
    if (!run.point) continue;
    const WorkPrecisionPoint& best = study.points[*run.point];
    CHECK(best.method != ComputationMethod::kExact);
    CHECK(best.worst_error <= run.target_error);
    for (const WorkPrecisionPoint& p : study.points) {
      if (p.method == ComputationMethod::kExact || !p.ok() || !(p.worst_error <= run.target_error))
        continue;
      CHECK(best.seconds_per_impact <= p.seconds_per_impact);
    }
  }
  CHECK(study.cheapest[0].point.has_value());
  // No integration is exact to 1e-30: only the exact path is, and it is no candidate.
  CHECK_FALSE(study.cheapest[2].point.has_value());
  CHECK_THAT(study.BriefReport(), Catch::Matchers::Contains("12 integrations in 4 series"));
}

TEST_CASE("work-precision: a failed integration is a point with its status, not an error",
          "[work_precision][errors]") {
  WorkPrecisionOptions options =
      QuickOptions(ComputationMethod::kArkodeErk54, {1e-4, 1e-10}, RestartSeries::kOn);
  // Enough steps for rtol 1e-4 (16 on this scene), far too few for 1e-10 (about 180).
  options.max_steps_per_run = 60;
  const WorkPrecisionResult study = covopt::MeasureWorkPrecision(CoveredPaperScene(), options);
  INFO(study.BriefReport());
  CHECK(study.status == WorkPrecisionStatus::kSomeRunsFailed);
  CHECK(study.IsUsable());
  REQUIRE(study.points.size() == 3);
  const WorkPrecisionPoint& reached = study.points[1];
  const WorkPrecisionPoint& failed = study.points[2];
  CHECK(reached.ok());
  CHECK(failed.status == covopt::SolveStatus::kStepLimit);
  CHECK_FALSE(failed.message.empty());
  // A failed run has no errors: NaN, never a misleading 0.
  CHECK(std::isnan(failed.worst_error));
  CHECK(std::isnan(failed.error_max_penetration));
  CHECK(std::isnan(failed.error_contact_duration));
  REQUIRE(study.series.size() == 1);
  CHECK(study.series[0].failures == 1);
  CHECK_FALSE(study.series[0].kept_tolerance);
  // Only the run that succeeded can be the cheapest.
  for (const covopt::CheapestRun& run : study.cheapest) {
    if (run.point) CHECK(*run.point == 1);
  }
  CHECK_THAT(study.BriefReport(), Catch::Matchers::Contains("1 failed"));
}

TEST_CASE("work-precision: progress reaches the total, one call per run", "[work_precision]") {
  WorkPrecisionOptions options =
      QuickOptions(ComputationMethod::kCvodeAdams, {1e-4, 1e-6}, RestartSeries::kBoth);
  std::vector<std::size_t> completed;
  std::size_t total = 0;
  options.progress = [&](const covopt::WorkPrecisionProgress& progress) {
    completed.push_back(progress.completed_runs);
    total = progress.total_runs;
  };
  const WorkPrecisionResult study = covopt::MeasureWorkPrecision(CoveredPaperScene(), options);
  REQUIRE(study.IsUsable());
  CHECK(total == 5);  // the exact path + 1 method x 2 series x 2 tolerances
  REQUIRE(completed.size() == total);
  for (std::size_t i = 0; i < completed.size(); ++i) CHECK(completed[i] == i + 1);
  CHECK(study.points.size() == total);
}

TEST_CASE("work-precision: bad options are rejected naming the field, value and range",
          "[work_precision][errors]") {
  const covopt::Scene scene = CoveredPaperScene();
  const auto rejects = [&](const WorkPrecisionOptions& options, const std::string& field,
                           const std::string& detail) {
    CAPTURE(field, detail);
    try {
      (void)covopt::MeasureWorkPrecision(scene, options);
      FAIL("accepted");
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      CAPTURE(message);
      CHECK(message.rfind(field, 0) == 0);
      CHECK(message.find(detail) != std::string::npos);
    }
  };
  const WorkPrecisionOptions good =
      QuickOptions(ComputationMethod::kArkodeErk54, {1e-6}, RestartSeries::kOn);
  WorkPrecisionOptions bad = good;
  bad.methods.clear();
  rejects(bad, "methods", "at least one");
  bad = good;
  bad.methods = {ComputationMethod::kExact};
  rejects(bad, "methods[0]", "(got exact)");
  bad = good;
  bad.methods = {ComputationMethod::kCvodeBdf, ComputationMethod::kCvodeBdf};
  rejects(bad, "methods[1]", "twice");
  bad = good;
  bad.relative_tolerances = {1e-6, 0.5};
  rejects(bad, "relative_tolerances[1]", "[1e-14, 1e-2] (got 0.5)");
  bad = good;
  bad.relative_tolerances = {std::numeric_limits<double>::quiet_NaN()};
  rejects(bad, "relative_tolerances[0]", "(got nan)");
  bad = good;
  bad.relative_tolerances.clear();
  rejects(bad, "relative_tolerances", "at least one");
  bad = good;
  bad.repetitions = -1;
  rejects(bad, "repetitions", "[0, 100000] (got -1)");
  bad = good;
  bad.timing_budget_s = 0.0;
  rejects(bad, "timing_budget_s", "(0, 60] s (got 0)");
  bad = good;
  bad.max_steps_per_run = 9;
  rejects(bad, "max_steps_per_run", ">= 10 (got 9)");
  bad = good;
  bad.error_targets = {1e-3, -1.0};
  rejects(bad, "error_targets[1]", "> 0 (got -1)");
  bad = good;
  bad.kept_tolerance_ratio = std::numeric_limits<double>::infinity();
  rejects(bad, "kept_tolerance_ratio", "(got inf)");
  bad = good;
  bad.restart = static_cast<RestartSeries>(7);
  rejects(bad, "restart", "(got 7)");

  // A bad scene is the scene's own message, naming its field.
  covopt::Scene bad_scene = scene;
  bad_scene.covering.thickness_m = -0.001;
  CHECK_THROWS_WITH(covopt::MeasureWorkPrecision(bad_scene, good),
                    Catch::Matchers::Contains("covering.thickness"));
}
