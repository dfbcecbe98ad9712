// `covopt speed-limit` run in-process: that every row is the library's answer for its scene
// (optim::MaxSafeSpeed / MaxSafeMass, to the bit), that lists and ranges of masses (or speeds)
// give one row each, that several --material give one block each, that --json, --csv and the
// table agree, that the edges are answers (safe up to 100 m/s with limited_by "none" and a
// warning; nothing safe: null), that --plot draws a chart (skipped without gnuplot) and a
// missing gnuplot is exit 1 with no file, and that bad input is exit 2 with one line on
// stderr and nothing on stdout.
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/materials/catalog.hpp"
#include "covopt/optim/speed_limit.hpp"
#include "plot.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::ReadFile;
using covopt::cli::testing::Run;
using covopt::cli::testing::ScopedEnv;
using covopt::cli::testing::SplitLines;
using covopt::cli::testing::TempDir;
using nlohmann::json;

json JsonOf(const CliRun& run) {
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  return json::parse(run.out);
}

/// `speed-limit` with each of `cases` is bad input: exit 2, nothing on stdout, one line on
/// stderr containing named[i].
void ExpectSpeedLimitRefusals(const std::vector<std::vector<std::string>>& cases,
                              const std::vector<std::string>& named) {
  for (std::size_t i = 0; i < cases.size(); ++i) {
    std::vector<std::string> args{"speed-limit"};
    args.insert(args.end(), cases[i].begin(), cases[i].end());
    const CliRun run = Run(args);
    INFO(fmt::format("{}", fmt::join(args, " ")) << " -> " << run.err);
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK(SplitLines(run.err).size() == 1);
    CHECK(run.err.find(named[i]) != std::string::npos);
  }
}

}  // namespace

TEST_CASE("speed-limit prints the library's max safe speed for the paper's scene", "[speed_limit]") {
  // --keep-travel: the library's default options (the travel rule kept), today's limits exactly.
  const CliRun run = Run({"speed-limit", "--keep-travel"});
  REQUIRE(run.exit_code == 0);
  CHECK(run.err.empty());
  const covopt::optim::SpeedLimit expected = covopt::optim::MaxSafeSpeed(covopt::Scene{});
  CHECK(run.out.find(fmt::format("{:.4g} m/s", expected.max_safe_speed_m_per_s)) != std::string::npos);
  CHECK(run.out.find("contusion") != std::string::npos);
  CHECK(run.out.find("Criterion  no laceration and no contusion (Park et al. 2011's skin limits), no fracture (the "
                     "peak force within the struck area's lowest published fracture force), the covering not "
                     "fully compressed") != std::string::npos);
  // No covering was given: the default one is assumed, and said so; so is the head's scope.
  CHECK(run.out.find("no covering given: the default is assumed") != std::string::npos);
  CHECK(run.out.find("A.3.2") != std::string::npos);
}

TEST_CASE("speed-limit --json: one row per mass of a range, each the library's answer to the bit", "[speed_limit]") {
  const json j = JsonOf(Run({"speed-limit", "--robot-mass", "0.5kg..50kg:log:5,fixed", "--covering-thickness",
                             "20mm", "--covering-modulus", "16MPa", "--keep-travel", "--json"}));
  CHECK(j["solve_for"] == "speed");
  CHECK(j["criterion"]["parts"] == json::array({"laceration", "contusion", "fracture", "full-compression", "crush", "law-validity"}));
  CHECK(j["search_limit"]["max_speed_m_per_s"] == 100.0);
  CHECK(j["scene"]["robot"].count("speed_m_per_s") == 0);
  CHECK(j["scene"]["robot"].count("mass_kg") == 0);  // the rows vary it
  CHECK(j["scene"]["covering"]["thickness_m"] == 0.02);
  const json& rows = j["rows"];
  REQUIRE(rows.size() == 6);
  CHECK(rows[5]["robot_mass_kg"] == "fixed");
  double previous = 1e300;
  for (const json& row : rows) {
    covopt::Scene scene;
    scene.covering.thickness_m = 0.02;
    scene.covering.youngs_modulus_Pa = 16e6;
    scene.robot.mass_kg = row["robot_mass_kg"].is_string() ? covopt::kFixed : row["robot_mass_kg"].get<double>();
    const covopt::optim::SpeedLimit expected = covopt::optim::MaxSafeSpeed(scene);
    CHECK(row["max_safe_speed_m_per_s"].get<double>() == expected.max_safe_speed_m_per_s);
    CHECK(row["limited_by"] == covopt::optim::ToString(expected.limited_by));
    CHECK(row["laceration_ratio"].get<double>() == expected.at_limit.laceration_ratio);
    CHECK(row["contusion_ratio"].get<double>() == expected.at_limit.contusion_ratio);
    CHECK(row["status"] == "limited");
    CHECK(row["material"].is_null());
    CHECK(row["max_safe_speed_m_per_s"].get<double>() < previous);  // heavier is slower
    previous = row["max_safe_speed_m_per_s"].get<double>();
  }
  REQUIRE(j["warnings"].size() == 1);  // a covering given by its modulus has no strength to check
  CHECK_THAT(j["warnings"][0].get<std::string>(), Catch::StartsWith("the covering is given by its modulus"));
}

TEST_CASE("speed-limit --solve-for mass: one row per speed, 'fixed' when even a fixed robot is safe",
          "[speed_limit]") {
  const json j = JsonOf(Run({"speed-limit", "--solve-for", "mass", "--speed", "0.5m/s,1.5m/s,2m/s", "--json"}));
  CHECK(j["solve_for"] == "mass");
  const json& rows = j["rows"];
  REQUIRE(rows.size() == 3);
  CHECK(rows[0]["max_safe_mass_kg"] == "fixed");
  CHECK(rows[0]["limited_by"] == "none");
  CHECK(rows[0]["status"] == "safe-up-to-search-limit");
  for (int i = 1; i < 3; ++i) {
    covopt::Scene scene;
    scene.robot.speed_m_per_s = rows[i]["speed_m_per_s"].get<double>();
    const covopt::optim::MassLimit expected = covopt::optim::MaxSafeMass(scene);
    CHECK(rows[i]["max_safe_mass_kg"].get<double>() == expected.max_safe_mass_kg);
    CHECK(rows[i]["limited_by"] == "contusion");
  }
  REQUIRE(j["warnings"].size() == 2);  // the assumed default covering, then the fixed robot
  CHECK(j["warnings"][1].get<std::string>().find("fixed robot") != std::string::npos);
}

TEST_CASE("speed-limit --csv writes the JSON rows' columns, and '-' prints them", "[speed_limit]") {
  const TempDir dir;
  const auto csv = dir / "limits.csv";
  const std::vector<std::string> args{"speed-limit", "--robot-mass", "2kg,10kg,fixed", "--material",
                                      "polystyrene foam 27.6"};
  std::vector<std::string> with_csv = args;
  with_csv.insert(with_csv.end(), {"--csv", csv.string()});
  const CliRun table = Run(with_csv);
  REQUIRE(table.exit_code == 0);
  CHECK(table.out.find("Wrote") != std::string::npos);
  std::vector<std::string> with_json = args;
  with_json.push_back("--json");
  const json j = JsonOf(Run(with_json));
  const std::vector<std::string> lines = SplitLines(ReadFile(csv));
  REQUIRE(lines.size() == 4);
  CHECK(lines[0] ==
        "material,robot_mass_kg,max_safe_speed_m_per_s,limited_by,laceration_ratio,contusion_ratio,"
        "fracture_ratio,compression_ratio,status,covering_law,within_law,covering_used_up_m_per_s");
  CHECK(lines[3].rfind("polystyrene foam 27.6,fixed,", 0) == 0);
  for (std::size_t i = 0; i < 3; ++i) {
    const json& row = j["rows"][i];
    CHECK(row["material"] == "polystyrene foam 27.6");
    const double speed = row["max_safe_speed_m_per_s"].get<double>();
    CHECK(lines[i + 1].find(fmt::format(",{},", speed)) != std::string::npos);
  }
  std::vector<std::string> to_stdout = args;
  to_stdout.insert(to_stdout.end(), {"--csv", "-"});
  const CliRun printed = Run(to_stdout);
  REQUIRE(printed.exit_code == 0);
  CHECK(printed.out == ReadFile(csv));

  // An unwritable target: exit 1, the message names the file, nothing left behind.
  std::vector<std::string> bad = args;
  bad.insert(bad.end(), {"--csv", (dir / "no-such-dir" / "x.csv").string()});
  const CliRun failed = Run(bad);
  CHECK(failed.exit_code == 1);
  CHECK(failed.err.find("x.csv") != std::string::npos);
}

TEST_CASE("speed-limit: several --material give one block of rows each", "[speed_limit]") {
  const json j = JsonOf(Run({"speed-limit", "--robot-mass", "1kg,10kg", "--covering-thickness", "20mm", "--material",
                             "XPS Foamular 250", "--material", "EPS geofoam EPS22", "--json"}));
  const json& rows = j["rows"];
  REQUIRE(rows.size() == 4);
  CHECK(rows[0]["material"] == "XPS Foamular 250");
  CHECK(rows[1]["material"] == "XPS Foamular 250");
  CHECK(rows[2]["material"] == "EPS geofoam EPS22");
  CHECK(rows[3]["robot_mass_kg"] == 10.0);
  CHECK(j["scene"]["covering"].count("youngs_modulus_Pa") == 0);  // each block has its own
  CHECK(j["scene"]["covering"]["thickness_m"] == 0.02);
  const auto& catalog = covopt::materials::Catalog::BuiltIn();
  covopt::Scene scene;
  scene.covering.thickness_m = 0.02;
  scene.covering.youngs_modulus_Pa = catalog.Find("EPS geofoam EPS22")->youngs_modulus_Pa;
  scene.robot.mass_kg = 10.0;
  // Each block judges crushing with its own material's strength (EPS22: 135 kPa, it binds).
  covopt::optim::SpeedLimitOptions options;
  options.covering_compressive_strength_Pa = *catalog.Find("EPS geofoam EPS22")->compressive_strength_Pa;
  CHECK(rows[3]["max_safe_speed_m_per_s"].get<double>() ==
        covopt::optim::MaxSafeSpeed(scene, options).max_safe_speed_m_per_s);
  CHECK(rows[3]["limited_by"] == "crush");
  const CliRun table = Run({"speed-limit", "--covering-thickness", "20mm", "--material", "XPS Foamular 250",
                            "--material", "EPS geofoam EPS22"});
  REQUIRE(table.exit_code == 0);
  CHECK(table.out.find("EPS geofoam EPS22") != std::string::npos);
}

TEST_CASE("speed-limit: safe up to 100 m/s says so, and nothing safe is null", "[speed_limit]") {
  const json safe = JsonOf(Run({"speed-limit", "--robot-mass", "1g", "--covering-thickness", "0",
                                "--laceration-limit", "1GPa", "--contusion-limit", "1000J/cm2", "--json"}));
  CHECK(safe["rows"][0]["max_safe_speed_m_per_s"] == 100.0);
  CHECK(safe["rows"][0]["limited_by"] == "none");
  REQUIRE(safe["warnings"].size() == 1);
  CHECK(safe["warnings"][0].get<std::string>().find("100 m/s") != std::string::npos);

  const json none = JsonOf(Run({"speed-limit", "--laceration-limit", "1kPa", "--safety-factor", "100", "--json"}));
  CHECK(none["rows"][0]["max_safe_speed_m_per_s"].is_null());
  CHECK(none["rows"][0]["status"] == "no-safe-value");
  CHECK(none["rows"][0]["limited_by"] == "laceration");
  const CliRun table = Run({"speed-limit", "--laceration-limit", "1kPa", "--safety-factor", "100"});
  REQUIRE(table.exit_code == 0);
  CHECK(table.out.find("none safe") != std::string::npos);
  CHECK(table.out.find("nan") == std::string::npos);
}

TEST_CASE("speed-limit reads the scene file, limits and the criterion as the other commands do", "[speed_limit]") {
  const std::string scene_file = std::string(COVOPT_CLI_EXAMPLES_DIR) + "/paper_scene.toml";
  const CliRun run = Run({"speed-limit", "--scene", scene_file, "--json"});
  REQUIRE(run.exit_code == 0);
  const json strict = JsonOf(Run({"speed-limit", "--covering-thickness", "10mm", "--covering-modulus", "2MPa",
                                  "--json"}));
  const json paper = JsonOf(Run({"speed-limit", "--covering-thickness", "10mm", "--covering-modulus", "2MPa",
                                 "--allow-full-compression", "--json"}));
  CHECK(strict["rows"][0]["limited_by"] == "law-validity");  // a Hertz covering's full compression
  CHECK(paper["criterion"]["parts"] == json::array({"laceration", "contusion", "fracture", "crush", "law-validity"}));
  CHECK(paper["rows"][0]["max_safe_speed_m_per_s"].get<double>() >
        strict["rows"][0]["max_safe_speed_m_per_s"].get<double>());
  const json derated = JsonOf(Run({"speed-limit", "--safety-factor", "2", "--json"}));
  CHECK(derated["rows"][0]["contusion_ratio"].get<double>() == Approx(0.5).epsilon(1e-12));
  CHECK(derated["safety_factor"] == 2.0);
}

TEST_CASE("speed-limit --plot draws the Safety-Map chart, and a missing gnuplot is exit 1", "[speed_limit][plot]") {
  const TempDir dir;
  const auto png = dir / "map.png";
  {
    const ScopedEnv no_path("PATH", dir.path().string());
    const CliRun missing = Run({"speed-limit", "--plot", png.string()});
    CHECK(missing.exit_code == 1);
    CHECK(missing.err.find("gnuplot") != std::string::npos);
    CHECK(!std::filesystem::exists(png));
  }
  if (!covopt::cli::FindOnPath("gnuplot")) {
    WARN("gnuplot is not on PATH; skipping the chart");
    return;
  }
  const CliRun run = Run({"speed-limit", "--material", "XPS Foamular 250", "--material", "EPS geofoam EPS22",
                          "--robot-mass", "1kg..100kg:log:4", "--plot", png.string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const std::string image = ReadFile(png);
  REQUIRE(image.size() > 8);
  CHECK(image.substr(1, 3) == "PNG");
}

TEST_CASE("speed-limit bad input: exit 2, one line naming the flag, nothing on stdout", "[speed_limit]") {
  const std::vector<std::vector<std::string>> cases = {
      {"--speed", "2m/s"},
      {"--solve-for", "mass", "--robot-mass", "3kg"},
      {"--solve-for", "weight"},
      {"--robot-mass", "2kg..1kg"},
      {"--robot-mass", "-3kg"},
      {"--robot-mass", "5kg,,3kg"},
      {"--robot-mass", "2e6kg"},
      {"--solve-for", "mass", "--speed", "0..2m/s"},
      {"--safety-factor", "0.5"},
      {"--laceration-limit", "-1MPa"},
      {"--material", "no such foam"},
      {"--material", "XPS Foamular 250", "--covering-modulus", "3MPa"},
      {"--plot", "chart.pdf"},
      {"--solve-for", "mass", "--plot", "chart.png"},
      {"--json", "--csv", "-"},
      {"--csv", ""},
      {"--covering-thickness", "-1mm"},
  };
  const std::vector<std::string> named = {"--speed", "--robot-mass", "--solve-for", "--robot-mass", "robot.mass",
                                          "--robot-mass", "robot.mass", "robot.speed", "--safety-factor",
                                          "--laceration-limit", "--material", "--material", "--plot", "--plot",
                                          "--csv", "--csv", "covering.thickness"};
  ExpectSpeedLimitRefusals(cases, named);
}

TEST_CASE("speed-limit --oracle: auto takes the exact path's solve on the paper's scene", "[speed_limit][oracle]") {
  const json j = JsonOf(Run({"speed-limit", "--json"}));
  CHECK(j["oracle"]["name"] == "exact");
  CHECK(j["oracle"]["search"] == "penetration-axis");
  CHECK(j["oracle"]["method"].is_null());
  CHECK_THAT(j["oracle"]["reason"].get<std::string>(), Catch::StartsWith("auto:"));
  REQUIRE(j["warnings"].size() == 1);  // the assumed default covering
  // --oracle exact says the same as auto here, to the bit.
  const json exact = JsonOf(Run({"speed-limit", "--json", "--oracle", "exact"}));
  CHECK(exact["oracle"]["name"] == "exact");
  CHECK(exact["rows"][0]["max_safe_speed_m_per_s"] == j["rows"][0]["max_safe_speed_m_per_s"]);
  // --rtol under auto on a scene the exact path answers: not used, and a warning says so.
  const json unused = JsonOf(Run({"speed-limit", "--json", "--rtol", "1e-6"}));
  CHECK(unused["oracle"]["name"] == "exact");
  REQUIRE(unused["warnings"].size() == 2);
  CHECK_THAT(unused["warnings"][1].get<std::string>(),
             Catch::Contains("--rtol is not used: auto chose the exact path") &&
                 Catch::Contains("--oracle time-path to search on the time path"));
}

TEST_CASE("speed-limit --oracle time-path brackets the limit on the time path and agrees with the exact path",
          "[speed_limit][oracle]") {
  const json exact = JsonOf(Run({"speed-limit", "--json"}));
  const json time = JsonOf(Run({"speed-limit", "--json", "--oracle", "time-path"}));
  CHECK(time["oracle"]["name"] == "time-path");
  CHECK(time["oracle"]["search"] == "bracketed-bisection");
  CHECK(time["oracle"]["method"] == "arkode-erk54");  // the library's default integrator
  CHECK(time["oracle"]["rtol"] == 1e-8);
  CHECK(time["oracle"]["failed_evaluations"] == 0);
  CHECK(time["oracle"]["evaluations"].get<long>() > 10);
  const double exact_speed = exact["rows"][0]["max_safe_speed_m_per_s"].get<double>();
  const double time_speed = time["rows"][0]["max_safe_speed_m_per_s"].get<double>();
  CHECK(time["rows"][0]["limited_by"] == exact["rows"][0]["limited_by"]);
  CHECK(std::abs(time_speed - exact_speed) <= 1e-6 * exact_speed);  // measured 5e-9 at rtol 1e-8

  // --method and --rtol reach the integrator, and the table says which oracle ran.
  const CliRun table = Run({"speed-limit", "--oracle", "time-path", "--method", "cvode", "--rtol", "1e-9"});
  INFO(table.err);
  REQUIRE(table.exit_code == 0);
  CHECK_THAT(table.out, Catch::Contains("Oracle     time path (cvode-adams, rtol 1e-09), a bracketed bisection"));
  CHECK_THAT(table.out, Catch::Contains(fmt::format("{:.4g} m/s", exact_speed)));
}

TEST_CASE("speed-limit --oracle, --method, --rtol: bad input exits 2 with one line naming the flag",
          "[speed_limit][oracle]") {
  const std::vector<std::vector<std::string>> cases = {
      {"--oracle", "foo"},
      {"--oracle", "exact", "--braking", "50m/s2"},
      {"--oracle", "exact", "--torso-mass", "30kg", "--neck-stiffness", "20kN/m"},
      {"--oracle", "time-path", "--method", "exact"},
      {"--oracle", "exact", "--method", "arkode-erk54"},
      {"--oracle", "exact", "--rtol", "1e-6"},
      {"--method", "rk4"},
      {"--oracle", "time-path", "--rtol", "0.5"},
      {"--oracle", "time-path", "--rtol", "abc"},
  };
  const std::vector<std::string> named = {"--oracle: expected auto, exact or time-path (got 'foo')",
                                          "--oracle exact: the exact path needs an energy integral; a scene with "
                                          "braking (--braking) has only the time path",
                                          "a neck (--torso-mass) has only the time path",
                                          "--method exact contradicts --oracle time-path",
                                          "--method arkode-erk54 applies to the time path",
                                          "--rtol applies to the time path",
                                          "--method: expected exact, cvode or one of",
                                          "--rtol must be in [1e-14, 1e-2] (got '0.5')",
                                          "--rtol"};
  ExpectSpeedLimitRefusals(cases, named);
  // On a braking scene auto takes the time path: no refusal, and the table says so.
  const CliRun braking = Run({"speed-limit", "--braking", "50m/s2"});
  INFO(braking.err);
  CHECK(braking.exit_code == 0);
  CHECK_THAT(braking.out, Catch::Contains("Oracle     time path"));
}
