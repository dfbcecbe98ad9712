// `covopt optimize --oracle`: the JSON's solver.oracle says which oracle ran and why (exact
// on the paper's scene, the time path when asked or when the scene brakes), the human report
// says it in one line, the time-path optimum equals the exact one to its tolerance, and bad
// input exits 2 with one message naming the flag: an unknown oracle, a tolerance out of range,
// --method exact against --oracle time-path, --oracle exact on a braking or neck scene, a
// --max-steps below 10 or with the exact path; a time path that fails (too few steps) exits 1
// with its status, never a limit or a design.
// `covopt speed-limit` on a braking scene names the time path; `covopt workprecision
// --design` measures the time-path optimum against the exact one.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"

using covopt::cli::testing::Run;
using nlohmann::json;

namespace {

/// Small searches: these tests check the plumbing, not the optimum's last digits.
const std::vector<std::string> kQuick = {"--material", "polystyrene foam 27.6", "--top", "1"};

std::vector<std::string> Args(std::vector<std::string> a, const std::vector<std::string>& b = kQuick) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

TEST_CASE("optimize reports the exact path as its oracle on the paper's scene", "[optimize][oracle]") {
  const auto run = Run(Args({"optimize", "--json"}));
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const json oracle = json::parse(run.out)["solver"]["oracle"];
  CHECK(oracle["name"] == "exact");
  CHECK(oracle["method"].is_null());
  CHECK(oracle["rtol"].is_null());
  CHECK(oracle["gradient"] == "analytic");
  CHECK(oracle["failed_evaluations"] == 0);
  CHECK_THAT(oracle["reason"].get<std::string>(), Catch::Contains("auto") && Catch::Contains("energy integral"));

  const auto text = Run(Args({"optimize"}));
  REQUIRE(text.exit_code == 0);
  CHECK_THAT(text.out, Catch::Contains("\nOracle  exact path, analytic gradients; auto: the conservative two-mass"));
  CHECK_THAT(text.out, Catch::Contains("exact-path evaluations"));
}

TEST_CASE("optimize --oracle time-path reproduces the exact optimum and says how it ran", "[optimize][oracle]") {
  const auto exact = Run({"optimize", "--json", "--top", "0"});
  const auto time =
      Run({"optimize", "--json", "--top", "0", "--oracle", "time-path", "--method", "arkode-erk87", "--rtol", "1e-9"});
  INFO(time.err);
  REQUIRE(exact.exit_code == 0);
  REQUIRE(time.exit_code == 0);
  const json a = json::parse(exact.out), b = json::parse(time.out);
  const json& oracle = b["solver"]["oracle"];
  CHECK(oracle["name"] == "time-path");
  CHECK(oracle["method"] == "arkode-erk87");
  CHECK(oracle["rtol"].get<double>() == 1e-9);
  CHECK(oracle["gradient"] == "cvodes-forward-sensitivities");
  CHECK_THAT(oracle["reason"].get<std::string>(), Catch::Contains("as asked"));
  CHECK(oracle["failed_evaluations"] == 0);
  const double b_exact = a["continuous_optimum"]["thickness_m"].get<double>();
  const double b_time = b["continuous_optimum"]["thickness_m"].get<double>();
  CHECK(std::abs(b_time / b_exact - 1.0) <= 1e-6);
  CHECK(b["recommendation"]["material"] == a["recommendation"]["material"]);
  CHECK(b["recommendation"]["thickness_m"] == a["recommendation"]["thickness_m"]);
}

TEST_CASE("optimize on a braking scene takes the time path under auto", "[optimize][oracle]") {
  const auto run = Run(Args({"optimize", "--json", "--braking", "50m/s2", "--reaction-delay", "2ms"}));
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const json oracle = json::parse(run.out)["solver"]["oracle"];
  CHECK(oracle["name"] == "time-path");
  CHECK(oracle["method"] == "arkode-erk54");
  CHECK(oracle["gradient"] == "central-difference");
  CHECK(oracle.contains("gradient_step_disagreement"));
  CHECK_THAT(oracle["reason"].get<std::string>(), Catch::Contains("auto") && Catch::Contains("brakes"));
  const auto text = Run(Args({"optimize", "--braking", "50m/s2", "--reaction-delay", "2ms"}));
  REQUIRE(text.exit_code == 0);
  CHECK_THAT(text.out, Catch::Contains("\nOracle  time path (arkode-erk54, rtol 1e-08), central-difference gradients; "
                                       "auto: the robot brakes"));
  CHECK_THAT(text.out, Catch::Contains("time-path evaluations"));
}

TEST_CASE("optimize warns when --method or --rtol is given but auto chose the exact path", "[optimize][oracle]") {
  const auto run = Run(Args({"optimize", "--rtol", "1e-6"}));
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.out, Catch::Contains("Warning: --rtol is not used: auto chose the exact path"));
}

TEST_CASE("optimize refuses bad oracle input with exit 2 and one message", "[optimize][oracle][bad-input]") {
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"--oracle", "foo"}, "--oracle: expected auto, exact or time-path (got 'foo')"},
      {{"--oracle", "time-path", "--rtol", "0"}, "--rtol must be in [1e-14, 1e-2] (got '0')"},
      {{"--oracle", "time-path", "--rtol", "0.5"}, "--rtol must be in [1e-14, 1e-2] (got '0.5')"},
      {{"--oracle", "time-path", "--method", "exact"}, "--method exact contradicts --oracle time-path"},
      {{"--oracle", "time-path", "--method", "rk4"}, "--method: expected exact, cvode or one of"},
      {{"--oracle", "exact", "--braking", "20m/s2"},
       "--oracle exact: the exact path needs an energy integral; a scene with braking (--braking) has only the time "
       "path; use --oracle auto or time-path"},
      {{"--oracle", "exact", "--torso-mass", "30kg", "--neck-stiffness", "20kN/m"},
       "--oracle exact: the exact path needs an energy integral; a scene with a neck (--torso-mass)"},
      {{"--oracle", "exact", "--method", "cvode-bdf"}, "--method cvode-bdf applies to the time path; --oracle exact "
                                                       "runs none"},
      {{"--oracle", "exact", "--rtol", "1e-6"}, "--rtol applies to the time path; --oracle exact runs none"},
      {{"--oracle", "time-path", "--max-steps", "5"}, "--max-steps must be >= 10 (got 5)"},
      {{"--oracle", "exact", "--max-steps", "1000"}, "--max-steps applies to the time path; --oracle exact runs none"},
      {{"--method", "exact", "--max-steps", "1000"}, "--max-steps applies to the time path; --method exact runs none"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"optimize"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto run = Run(args);
    INFO(c.message);
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK_THAT(run.err, Catch::StartsWith("covopt optimize: error: ") && Catch::Contains(c.message));
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  }
}

TEST_CASE("speed-limit on a braking scene names the time path and its bisection", "[speed-limit][oracle]") {
  const auto json_run = Run({"speed-limit", "--json", "--braking", "200m/s2", "--reaction-delay", "2ms"});
  INFO(json_run.err);
  REQUIRE(json_run.exit_code == 0);
  const json j = json::parse(json_run.out);
  CHECK(j["oracle"]["name"] == "time-path");
  CHECK(j["oracle"]["method"] == "arkode-erk54");
  CHECK(j["oracle"]["evaluations"].get<long>() > 10);
  CHECK_FALSE(j["oracle"].contains("gradient"));
  CHECK(j["oracle"]["search"] == "bracketed-bisection");
  const auto text = Run({"speed-limit", "--braking", "200m/s2", "--reaction-delay", "2ms"});
  REQUIRE(text.exit_code == 0);
  CHECK_THAT(text.out, Catch::Contains("Oracle     time path (arkode-erk54, rtol 1e-08), a bracketed bisection"));
  const auto paper = Run({"speed-limit", "--json"});
  REQUIRE(paper.exit_code == 0);
  CHECK(json::parse(paper.out)["oracle"]["name"] == "exact");
  CHECK(json::parse(paper.out)["oracle"]["search"] == "penetration-axis");
}

TEST_CASE("a time path that fails is reported with its status and exit 1, never as a limit or a design",
          "[speed-limit][optimize][oracle][failure]") {
  // 10 steps (--max-steps' smallest value) cannot carry a braked contact to separation.
  const auto limit = Run({"speed-limit", "--braking", "200m/s2", "--max-steps", "10"});
  CHECK(limit.exit_code == 1);
  CHECK(limit.out.empty());
  CHECK_THAT(limit.err, Catch::StartsWith("covopt speed-limit: error: no answer: the oracle failed at 1e-06 m/s") &&
                            Catch::Contains("step-limit"));
  CHECK(std::count(limit.err.begin(), limit.err.end(), '\n') == 1);
  const auto as_json = Run({"speed-limit", "--json", "--braking", "200m/s2", "--max-steps", "10"});
  CHECK(as_json.exit_code == 1);
  CHECK(as_json.out.empty());
  // The same limit with the default step limit is an answer: the failure is the step limit's.
  CHECK(Run({"speed-limit", "--braking", "200m/s2", "--max-steps", "200000"}).exit_code == 0);

  const auto design = Run(Args({"optimize", "--braking", "50m/s2", "--max-steps", "10"}));
  CHECK(design.exit_code == 1);
  CHECK(design.out.empty());
  CHECK_THAT(design.err, Catch::StartsWith("covopt optimize: error: ") && Catch::Contains("step-limit"));
}

TEST_CASE("optimize under auto: --max-steps on a scene the exact path answers is not used, a warning says so",
          "[speed-limit][optimize][oracle]") {
  const auto run = Run(Args({"optimize", "--max-steps", "1000", "--rtol", "1e-6"}));
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.out, Catch::Contains("Warning: --rtol and --max-steps are not used: auto chose the exact path"));
}

TEST_CASE("workprecision --design measures the time-path optimum against the exact one", "[workprecision][oracle]") {
  const auto run = Run({"workprecision", "--design", "--json", "--methods", "arkode-erk54", "--tolerances", "1e-6,1e-9"});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const json j = json::parse(run.out);
  CHECK(j["study"] == "design");
  REQUIRE(j["points"].size() == 3);
  CHECK(j["points"][0]["oracle"] == "exact");
  CHECK(j["points"][0]["method"].is_null());
  for (int i = 1; i <= 2; ++i) {
    const json& p = j["points"][i];
    CHECK(p["oracle"] == "time-path");
    CHECK(p["method"] == "arkode-erk54");
    CHECK(p["feasible"] == true);
    CHECK(p["error_thickness"].get<double>() <= 100 * p["relative_tolerance"].get<double>());
  }
  const auto bad = Run({"workprecision", "--design", "--restart", "off"});
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.err, Catch::Contains("--restart applies to the integrator study, not to --design"));
}
