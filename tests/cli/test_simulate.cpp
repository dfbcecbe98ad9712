// `covopt simulate` end to end, run in-process through RunCli. These tests check the exit
// codes (0 done, 2 bad input with nothing on stdout, help and version 0), that the table and
// the JSON carry the library's own numbers (compared with covopt::SolveExact and
// covopt::SimulateImpact on the same Scene, never with printed numbers), that the time path
// agrees with the exact one, that units on flags reach the Scene, and that every bad input
// is named on stderr.

#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/core.hpp"

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using Catch::Matchers::Contains;
using Json = nlohmann::json;

namespace {

covopt::ImpactResult Exact(const covopt::Scene& scene) {
  return covopt::SolveExact(covopt::ImpactModel::FromScene(scene));
}

/// Checks that `json` reports `result` exactly (the JSON numbers round-trip).
void CheckReports(const Json& json, const covopt::ImpactResult& result) {
  const covopt::ImpactPeaks& p = result.peaks;
  CHECK(json["max_penetration_m"].get<double>() == p.max_penetration_m);
  CHECK(json["peak_force_N"].get<double>() == p.peak_force_N);
  CHECK(json["max_compressive_stress_Pa"].get<double>() == p.max_compressive_stress_Pa);
  CHECK(json["max_tensile_stress_Pa"].get<double>() == p.max_tensile_stress_Pa);
  CHECK(json["max_energy_density_J_per_m2"].get<double>() == p.max_energy_density_J_per_m2);
  REQUIRE(result.contact_duration_s.has_value());
  CHECK(json["contact_duration_s"].get<double>() == *result.contact_duration_s);
  REQUIRE(result.rebound_speed_m_per_s.has_value());
  CHECK(json["rebound_speed_m_per_s"].get<double>() == *result.rebound_speed_m_per_s);
  CHECK(json["phase_at_max"].get<int>() == covopt::PhaseNumber(p.phase_at_max));
  CHECK(json["fully_compressed"].get<bool>() == p.fully_compressed);

  const covopt::InjuryAssessment verdicts = covopt::Assess(p);
  CHECK(json["laceration"]["value_Pa"].get<double>() == verdicts.laceration.value);
  CHECK(json["laceration"]["limit_Pa"].get<double>() == verdicts.laceration.limit);
  CHECK(json["laceration"]["ratio"].get<double>() == verdicts.laceration.ratio);
  CHECK(json["laceration"]["safe"].get<bool>() == verdicts.laceration.safe);
  CHECK(json["contusion"]["value_J_per_m2"].get<double>() == verdicts.contusion.value);
  CHECK(json["contusion"]["limit_J_per_m2"].get<double>() == verdicts.contusion.limit);
  CHECK(json["contusion"]["ratio"].get<double>() == verdicts.contusion.ratio);
  CHECK(json["contusion"]["safe"].get<bool>() == verdicts.contusion.safe);
  // The computation's warnings, besides the one about the input (the default covering assumed).
  std::size_t input_warnings = 0;
  for (const Json& w : json["warnings"]) input_warnings += w.get<std::string>().rfind("no covering given", 0) == 0;
  CHECK(json["warnings"].size() - input_warnings == result.warnings.size());
}

/// Bad input: exit 2, nothing on stdout, and stderr names what was wrong.
void CheckBadInput(const std::vector<std::string>& args, const std::string& named) {
  const CliRun run = Run(args);
  CAPTURE(args, run.err);
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Contains(named));
}

}  // namespace

TEST_CASE("the default scene prints a table with peaks and verdicts and exits 0", "[run]") {
  const CliRun run = Run({"simulate"});
  REQUIRE(run.exit_code == 0);
  CHECK(run.err.empty());
  for (const char* line : {"Scene", "robot 10 kg at 2 m/s", "max penetration", "peak force",
                           "contact duration", "max compressive stress", "max tensile stress",
                           "max energy density", "rebound speed", "phase at max",
                           "fully compressed", "laceration", "contusion", "limit 1 MPa",
                           "limit 2.52 J/cm²", "Method  exact", "Warnings"}) {
    CHECK_THAT(run.out, Contains(line));
  }
  // The verdict words follow the library's assessment.
  const auto verdicts = covopt::Assess(Exact(covopt::Scene{}).peaks);
  CHECK_THAT(run.out, Contains(std::string("contusion    ") +
                               (verdicts.contusion.safe ? "SAFE" : "UNSAFE")));
  CHECK_THAT(run.out, Contains(std::string("laceration   ") +
                               (verdicts.laceration.safe ? "SAFE" : "UNSAFE")));
}

TEST_CASE("simulate --json has every documented key", "[run][json]") {
  const CliRun run = Run({"simulate", "--json"});
  REQUIRE(run.exit_code == 0);
  const Json json = Json::parse(run.out);
  for (const char* key :
       {"max_penetration_m", "peak_force_N", "contact_duration_s", "max_compressive_stress_Pa",
        "max_tensile_stress_Pa", "max_energy_density_J_per_m2", "rebound_speed_m_per_s",
        "laceration", "contusion", "phase_at_max", "phase_at_max_name", "fully_compressed",
        "method", "solver", "scene", "warnings"}) {
    CAPTURE(key);
    CHECK(json.contains(key));
  }
  for (const char* key : {"value_Pa", "limit_Pa", "ratio", "safe"}) {
    CHECK(json["laceration"].contains(key));
  }
  for (const char* key : {"value_J_per_m2", "limit_J_per_m2", "ratio", "safe"}) {
    CHECK(json["contusion"].contains(key));
  }
  for (const char* key : {"status", "message", "steps", "rhs_evaluations", "root_evaluations",
                          "jacobian_evaluations", "nonlinear_iterations", "error_test_failures",
                          "convergence_failures", "restarts"}) {
    CHECK(json["solver"].contains(key));
  }
  for (const char* table : {"robot", "covering", "head", "scalp", "skull", "model"}) {
    CHECK(json["scene"].contains(table));
  }
  CHECK(json["method"] == "exact");
  CHECK(json["solver"]["status"] == "success");
  CHECK(json["solver"]["steps"] == 0);
  CHECK(json["scene"]["model"]["thresholds"] == "cumulative");
  CHECK(json["warnings"].is_array());
}

TEST_CASE("simulate --json reports exactly what SolveExact computes for the same scene", "[run][json]") {
  SECTION("the paper's scene") {
    const Json json = Json::parse(Run({"simulate", "--json"}).out);
    CheckReports(json, Exact({}));
    // Its covering is the default, assumed: said, as speed-limit says it (optim::SceneInputWarnings).
    REQUIRE(!json["warnings"].empty());
    CHECK(json["warnings"][0].get<std::string>().rfind("no covering given: the default is assumed", 0) == 0);
  }
  SECTION("a scene given with units on every kind of flag") {
    covopt::Scene scene;
    scene.robot.mass_kg = 4.0;
    scene.robot.speed_m_per_s = 1.5;
    scene.robot.radius_m = 0.04;
    scene.covering.youngs_modulus_Pa = 5e6;
    scene.covering.poisson_ratio = 0.3;
    scene.covering.thickness_m = 0.01;
    scene.head.radius_m = 0.09;
    const CliRun run = Run({"simulate", "--json", "--robot-mass", "4000g", "--speed", "5.4 km/h",
                            "--robot-radius", "4cm", "--covering-modulus", "5MPa",
                            "--covering-poisson", "0.3", "--covering-thickness", "10 mm",
                            "--head-radius", "0.09"});
    REQUIRE(run.exit_code == 0);
    const Json json = Json::parse(run.out);
    CHECK(json["scene"]["robot"]["mass_kg"].get<double>() == Approx(4.0));
    CHECK(json["scene"]["robot"]["speed_m_per_s"].get<double>() == Approx(1.5));
    // Rebuild the scene from what the CLI resolved, then compare bit for bit.
    scene.robot.mass_kg = json["scene"]["robot"]["mass_kg"].get<double>();
    scene.robot.speed_m_per_s = json["scene"]["robot"]["speed_m_per_s"].get<double>();
    scene.robot.radius_m = json["scene"]["robot"]["radius_m"].get<double>();
    scene.covering.youngs_modulus_Pa = json["scene"]["covering"]["youngs_modulus_Pa"].get<double>();
    scene.covering.thickness_m = json["scene"]["covering"]["thickness_m"].get<double>();
    CheckReports(json, Exact(scene));
  }
  SECTION("no covering, a flat robot, a fixed head, literal thresholds") {
    covopt::Scene scene;
    scene.covering.thickness_m = 0.0;
    scene.robot.radius_m = covopt::kFlat;
    scene.head.mass_kg = covopt::kFixed;
    scene.robot.speed_m_per_s = 0.5;
    scene.model.thresholds = covopt::ThresholdReading::kLiteral;
    const CliRun run = Run({"simulate", "--json", "--covering-thickness", "0", "--robot-radius",
                            "flat", "--head-mass", "fixed", "--speed", "0.5",
                            "--thresholds", "literal"});
    REQUIRE(run.exit_code == 0);
    const Json json = Json::parse(run.out);
    CHECK(json["scene"]["robot"]["radius_m"] == "flat");
    CHECK(json["scene"]["head"]["mass_kg"] == "fixed");
    CHECK(json["scene"]["model"]["thresholds"] == "literal");
    CheckReports(json, Exact(scene));
  }
}

TEST_CASE("a covering modulus given without a covering is reported as ignored", "[run]") {
  const CliRun run = Run({"simulate", "--json", "--covering-thickness", "0",
                          "--covering-modulus", "1GPa"});
  REQUIRE(run.exit_code == 0);
  const Json json = Json::parse(run.out);
  REQUIRE(json["warnings"].size() == 1);
  CHECK_THAT(json["warnings"][0].get<std::string>(),
             Contains("covering.modulus") && Contains("--covering-modulus '1GPa'") &&
                 Contains("ignored"));
  // The default covering modulus, not set by the user, is not worth a warning.
  CHECK(Json::parse(Run({"simulate", "--json", "--covering-thickness", "0"}).out)["warnings"]
            .empty());
}

TEST_CASE("the JSON never contains NaN or Infinity", "[run][json]") {
  const CliRun run = Run({"simulate", "--json", "--robot-mass", "fixed", "--robot-radius", "flat"});
  REQUIRE(run.exit_code == 0);
  for (const char* word : {"NaN", "nan", "Infinity", "inf"}) {
    CHECK_THAT(covopt::cli::testing::WithoutProvenance(run.out), !Contains(word));  // "provenance" has a "nan"
  }
  CHECK(Json::parse(run.out)["scene"]["robot"]["mass_kg"] == "fixed");
}

TEST_CASE("simulate --method cvode agrees with the exact path to 1e-6", "[run][cvode]") {
  const Json exact = Json::parse(Run({"simulate", "--json"}).out);
  for (const char* family : {"adams", "bdf"}) {
    CAPTURE(family);
    const CliRun run = Run({"simulate", "--json", "--method", "cvode", "--cvode-method", family});
    REQUIRE(run.exit_code == 0);
    const Json cvode = Json::parse(run.out);
    CHECK(cvode["method"] == std::string("cvode-") + family);
    CHECK(cvode["solver"]["status"] == "success");
    CHECK(cvode["solver"]["steps"].get<long>() > 0);
    CHECK(cvode["solver"]["rhs_evaluations"].get<long>() > 0);
    for (const char* key : {"max_penetration_m", "peak_force_N", "contact_duration_s",
                            "max_compressive_stress_Pa", "max_tensile_stress_Pa",
                            "max_energy_density_J_per_m2", "rebound_speed_m_per_s"}) {
      CAPTURE(key);
      CHECK(cvode[key].get<double>() == Approx(exact[key].get<double>()).epsilon(1e-6));
    }
    CHECK(cvode["phase_at_max"] == exact["phase_at_max"]);
  }
}

TEST_CASE("simulate --method cvode reports what SimulateImpact computes with the same options",
          "[run][cvode]") {
  const CliRun run = Run({"simulate", "--json", "--method", "cvode", "--rtol", "1e-8", "--atol",
                          "1e-9", "--cvode-method", "bdf"});
  REQUIRE(run.exit_code == 0);
  covopt::TimeIntegrationOptions options;
  options.method = covopt::ComputationMethod::kCvodeBdf;
  options.relative_tolerance = 1e-8;
  options.absolute_tolerance = 1e-9;
  const auto result = covopt::SimulateImpact(covopt::ImpactModel::FromScene({}), options);
  const Json json = Json::parse(run.out);
  CheckReports(json, result);
  CHECK(json["solver"]["steps"].get<long>() == result.statistics.steps);
  CHECK(json["solver"]["relative_tolerance"].get<double>() == 1e-8);
  CHECK(json["solver"]["absolute_tolerance"].get<double>() == 1e-9);
}

TEST_CASE("the table shows the method and solver statistics for cvode", "[run][cvode]") {
  const CliRun run = Run({"simulate", "--method", "cvode"});
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("Method  cvode-adams") && Contains("Solver  success") &&
                          Contains("steps") && Contains("rhs evaluations"));
}

TEST_CASE("a failed computation exits 1 with the status and the solver's message",
          "[run][errors]") {
  for (const bool json : {false, true}) {  // neither the table nor the JSON is printed
    std::vector<std::string> args{"simulate", "--method", "cvode", "--max-steps", "10"};
    if (json) args.push_back("--json");
    const CliRun run = Run(args);
    CAPTURE(json, run.err);
    CHECK(run.exit_code == 1);
    CHECK(run.out.empty());
    // The library's own words for what happened.
    covopt::TimeIntegrationOptions options;
    options.max_steps = 10;
    const auto result = covopt::SimulateImpact(covopt::ImpactModel::FromScene({}), options);
    REQUIRE_FALSE(result.ok());
    CHECK_THAT(run.err, Contains(std::string(covopt::ToString(result.status))) &&
                            Contains(result.message));
  }
  CheckBadInput({"simulate", "--method", "cvode", "--max-steps", "3"}, "max_steps");
}

TEST_CASE("out-of-range values are bad input naming the field", "[run][errors]") {
  CheckBadInput({"simulate", "--robot-mass", "-10kg"}, "robot.mass");
  CheckBadInput({"simulate", "--robot-mass", "-10kg"}, "--robot-mass");
  CheckBadInput({"simulate", "--speed", "0"}, "robot.speed");
  CheckBadInput({"simulate", "--covering-poisson", "0.6"}, "covering.poisson");
  CheckBadInput({"simulate", "--robot-mass", "fixed", "--head-mass", "fixed"}, "both fixed");
  CheckBadInput({"simulate", "--scalp-thickness", "9cm"}, "scalp.thickness");
}

TEST_CASE("unparsable values are bad input naming the flag", "[run][errors]") {
  CheckBadInput({"simulate", "--speed", "2kg"}, "--speed: unit 'kg' is not a speed");
  CheckBadInput({"simulate", "--speed", "inf"}, "--speed: not a finite number");
  CheckBadInput({"simulate", "--robot-mass", "nan"}, "--robot-mass: not a finite number");
  CheckBadInput({"simulate", "--head-radius", "flat"}, "--head-radius");
  CheckBadInput({"simulate", "--speed", "fixed"}, "--speed");
  CheckBadInput({"simulate", "--covering-thickness", ""}, "--covering-thickness: empty value");
  CheckBadInput({"simulate", "--skull-poisson", "0.2GPa"}, "--skull-poisson");
}

TEST_CASE("command-line mistakes are bad input with exit code 2, not CLI11's", "[run][errors]") {
  CheckBadInput({"simulate", "--bogus"}, "--bogus");
  CheckBadInput({"simulate", "--speed"}, "--speed");
  CheckBadInput({"simulate", "--method", "rk4"}, "--method");
  CheckBadInput({"simulate", "--thresholds", "strict"}, "--thresholds");
  CheckBadInput({"simulate", "--cvode-method", "euler"}, "--cvode-method");
  CheckBadInput({"simulate", "--speed", "1", "--speed", "2"}, "--speed");
  CheckBadInput({"frobnicate"}, "frobnicate");
}

TEST_CASE("options that do not combine are bad input", "[run][errors]") {
  CheckBadInput({"simulate", "--method", "exact", "--history", "h.csv"}, "--history");
  CheckBadInput({"simulate", "--method", "exact", "--plot", "p.png"}, "--plot");
  CheckBadInput({"simulate", "--rtol", "1e-8"}, "--rtol applies to the time path only");
  CheckBadInput({"simulate", "--cvode-method", "bdf"}, "--cvode-method");
  CheckBadInput({"simulate", "--plot", "chart.jpg"}, "*.png or *.svg");
}

TEST_CASE("integrator tolerances are checked by the library and reported as bad input",
          "[run][errors]") {
  CheckBadInput({"simulate", "--method", "cvode", "--rtol", "0.5"}, "rtol");
  CheckBadInput({"simulate", "--method", "cvode", "--atol", "1"}, "atol");
  CheckBadInput({"simulate", "--method", "cvode", "--atol", "0"}, "--atol");
  CheckBadInput({"simulate", "--method", "cvode", "--rtol", "1e-8 m"}, "--rtol");
}

TEST_CASE("help and version exit 0 and a missing subcommand is a usage error", "[run]") {
  const CliRun help = Run({"--help"});
  CHECK(help.exit_code == 0);
  CHECK_THAT(help.out, Contains("simulate"));

  const CliRun sub_help = Run({"simulate", "--help"});
  CHECK(sub_help.exit_code == 0);
  for (const char* flag : {"--robot-mass", "--speed", "--covering-thickness", "--scene",
                           "--method", "--json", "--history", "--plot", "Exit codes"}) {
    CHECK_THAT(sub_help.out, Contains(flag));
  }
  CHECK_THAT(sub_help.out, Contains("(default 27.6 MPa)"));  // defaults come from Scene{}

  const CliRun version = Run({"--version"});
  CHECK(version.exit_code == 0);
  CHECK_THAT(version.out, Contains("covopt "));

  const CliRun none = Run({});
  CHECK(none.exit_code == 2);
  CHECK(none.out.empty());
  CHECK_THAT(none.err, Contains("simulate") && Contains("no subcommand"));
}

TEST_CASE("simulate --json gives the stable code of every model warning beside its message", "[run][json]") {
  const CliRun thin_stiff = Run({"simulate", "--json", "--covering-thickness", "0.5mm", "--covering-modulus", "1GPa"});
  REQUIRE(thin_stiff.exit_code == 0);
  const Json j = Json::parse(thin_stiff.out);
  REQUIRE(j["warning_codes"].is_array());
  const std::vector<std::string> codes = j["warning_codes"].get<std::vector<std::string>>();
  CHECK(codes == std::vector<std::string>{"covering-stiffer-than-scalp", "fully-compressed"});
  const CliRun plain = Run({"simulate", "--json"});
  CHECK(Json::parse(plain.out)["warning_codes"].empty());
}
