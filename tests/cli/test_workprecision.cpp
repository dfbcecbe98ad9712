// `covopt workprecision`: the study's shape (the exact path first, one point per method,
// restart choice and tolerance), its physics (errors are measured against the exact path and
// shrink as the tolerance tightens; the exact path costs less than any integration), the
// CSV and JSON it writes, its bad input, and that it prints what the library's
// covopt::MeasureWorkPrecision measures (the CLI only parses and prints).
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_support.hpp"
#include "covopt/core/work_precision.hpp"
#include "errors.hpp"
#include "plot.hpp"
#include "workprecision.hpp"

using namespace covopt::cli::testing;
using Catch::Matchers::Contains;

namespace {

std::size_t CountFields(const std::string& line) {
  return static_cast<std::size_t>(std::count(line.begin(), line.end(), ',')) + 1;
}

}  // namespace

TEST_CASE("workprecision --json measures each method against the exact path", "[workprecision]") {
  TempDir dir;
  const auto csv = dir / "wp.csv";
  const CliRun run = Run({"workprecision", "--methods", "cvode-adams,arkode-erk54", "--tolerances",
                          "1e-4,1e-8", "--restart", "on", "--repeats", "1", "--json", "--csv",
                          csv.string()});
  CAPTURE(run.err);
  REQUIRE(run.exit_code == 0);
  const auto json = nlohmann::json::parse(run.out);
  const auto& points = json["points"];
  REQUIRE(points.size() == 5);  // exact + 2 methods x 2 tolerances
  CHECK(points[0]["method"] == "exact");
  CHECK(points[0]["worst_error"] == 0.0);
  const double exact_seconds = points[0]["seconds_per_impact"];
  CHECK(exact_seconds > 0.0);
  for (std::size_t i = 1; i < points.size(); i += 2) {
    const auto& loose = points[i];
    const auto& tight = points[i + 1];
    CAPTURE(loose.dump(), tight.dump());
    CHECK(loose["method"] == tight["method"]);
    CHECK(loose["relative_tolerance"] == 1e-4);
    CHECK(tight["relative_tolerance"] == 1e-8);
    CHECK(loose["status"] == "success");
    CHECK(tight["status"] == "success");
    // The tolerance buys accuracy, and costs steps.
    CHECK(tight["worst_error"].get<double>() < loose["worst_error"].get<double>());
    CHECK(tight["worst_error"].get<double>() < 1e-6);
    CHECK(tight["steps"].get<long>() > loose["steps"].get<long>());
    // The worst error is the largest of the five.
    for (const char* key : {"error_max_penetration", "error_peak_force",
                            "error_max_compressive_stress", "error_max_energy_density",
                            "error_contact_duration"}) {
      CHECK(tight[key].get<double>() <= tight["worst_error"].get<double>());
    }
    CHECK(tight["energy_residual"].get<double>() >= 0.0);
    // The exact path is cheaper than any integration of the same impact.
    CHECK(tight["seconds_per_impact"].get<double>() > exact_seconds);
  }
  CHECK(json["cheapest_reaching_error"]["1e-06"]["worst_error"].get<double>() <= 1e-6);

  const std::vector<std::string> lines = SplitLines(ReadFile(csv));
  REQUIRE(lines.size() == 6);  // header + 5 rows
  CHECK_THAT(lines[0], Contains("worst_error") && Contains("seconds_per_impact"));
  for (const std::string& line : lines) CHECK(CountFields(line) == CountFields(lines[0]));
  CHECK_THAT(lines[1], Contains("exact,"));
}

TEST_CASE("workprecision without restarts adds a second series per method", "[workprecision]") {
  const CliRun run = Run({"workprecision", "--methods", "arkode-erk87", "--tolerances", "1e-9",
                          "--repeats", "1"});
  CAPTURE(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("arkode-erk87 ") && Contains("arkode-erk87, no restart"));
  // Fehlberg 8(7) through the kinks loses its order: the table says it.
  CHECK_THAT(run.out, Contains("Not keeping the tolerance") && Contains("arkode-erk87, no restart ("));
}

TEST_CASE("workprecision reads a decade ladder of tolerances", "[workprecision]") {
  using covopt::cli::ParseToleranceLadder;
  const std::vector<double> down = ParseToleranceLadder("1e-3..1e-6");
  REQUIRE(down.size() == 4);
  CHECK(down.front() == Approx(1e-3));
  CHECK(down.back() == Approx(1e-6));
  CHECK(ParseToleranceLadder("1e-12..1e-3").size() == 10);
  CHECK(ParseToleranceLadder("1e-5").size() == 1);
  CHECK(ParseToleranceLadder("1e-4,3e-7,1e-9").size() == 3);
  CHECK_THROWS_AS(ParseToleranceLadder("1e-20..1e-3"), covopt::cli::InputError);
  CHECK_THROWS_AS(ParseToleranceLadder("1e-4,,1e-6"), covopt::cli::InputError);
  CHECK_THROWS_AS(ParseToleranceLadder("0.5"), covopt::cli::InputError);
}

TEST_CASE("workprecision bad input is exit 2 naming the flag", "[workprecision][errors]") {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"workprecision", "--methods", "rk4"},
        std::vector<std::string>{"workprecision", "--methods", "exact"},
        std::vector<std::string>{"workprecision", "--tolerances", "1e-20"},
        std::vector<std::string>{"workprecision", "--tolerances", "fast"},
        std::vector<std::string>{"workprecision", "--plot", "chart.pdf"},
        std::vector<std::string>{"workprecision", "--robot-mass", "-1kg"}}) {
    const CliRun run = Run(args);
    CAPTURE(args, run.err);
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK_THAT(run.err, Contains(args[1].substr(0, 8)) || Contains("robot.mass"));
  }
}

TEST_CASE("workprecision draws both charts with gnuplot", "[workprecision][plot]") {
  if (!covopt::cli::FindOnPath("gnuplot")) {
    WARN("gnuplot is not on PATH; skipping the chart test");
    return;
  }
  TempDir dir;
  const auto work = dir / "work.svg";
  const auto promise = dir / "promise.png";
  const CliRun run = Run({"workprecision", "--methods", "arkode-erk54", "--tolerances", "1e-4,1e-6",
                          "--repeats", "1", "--plot", work.string(), "--tolerance-plot",
                          promise.string()});
  CAPTURE(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(ReadFile(work), Contains("<svg") && Contains("arkode-erk54"));
  CHECK(ReadFile(promise).substr(0, 4) == std::string("\x89PNG", 4));
}

TEST_CASE("workprecision --json prints what the library's study measures", "[workprecision]") {
  const CliRun run = Run({"workprecision", "--methods", "cvode-bdf,arkode-erk32", "--tolerances",
                          "1e-5,1e-7", "--restart", "off", "--repeats", "1", "--json"});
  CAPTURE(run.err);
  REQUIRE(run.exit_code == 0);
  const auto json = nlohmann::json::parse(run.out);

  covopt::WorkPrecisionOptions options;
  options.methods = {covopt::ComputationMethod::kCvodeBdf, covopt::ComputationMethod::kArkodeErk32};
  options.relative_tolerances = {1e-5, 1e-7};
  options.restart = covopt::RestartSeries::kOff;
  options.repetitions = 1;
  // The CLI's default scene is the library's default scene.
  const covopt::WorkPrecisionResult study = covopt::MeasureWorkPrecision(covopt::Scene{}, options);
  REQUIRE(study.status == covopt::WorkPrecisionStatus::kSuccess);
  REQUIRE(json["points"].size() == study.points.size());
  for (std::size_t i = 0; i < study.points.size(); ++i) {
    const auto& printed = json["points"][i];
    const covopt::WorkPrecisionPoint& measured = study.points[i];
    CAPTURE(i, printed.dump());
    CHECK(printed["method"] == std::string(covopt::ToString(measured.method)));
    CHECK(printed["restart_at_phase_switches"] == measured.restart);
    // Integration is deterministic: the same run gives the same numbers to the last bit.
    CHECK(printed["worst_error"].get<double>() == measured.worst_error);
    CHECK(printed["error_peak_force"].get<double>() == measured.error_peak_force);
    CHECK(printed["steps"].get<long>() == measured.statistics.steps);
    CHECK(printed["rhs_evaluations"].get<long>() == measured.statistics.rhs_evaluations);
  }
  // The cheapest run per target is chosen by time, which differs between the two runs;
  // each printed choice must reach its target.
  for (const auto& [target, best] : json["cheapest_reaching_error"].items()) {
    CAPTURE(target);
    if (!best.is_null()) CHECK(best["worst_error"].get<double>() <= std::stod(target));
  }
}
