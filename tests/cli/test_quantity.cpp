// The command line reads values with the library's parser (covopt/core/quantity.hpp, tested
// in tests/core/test_quantity.cpp) through cli/quantity.hpp, which turns its errors into the
// CLI's InputError (exit 2). These tests check that forwarding, that the scene flags, scene
// files and limit flags use the named specs with their plausible ranges, and the regressions
// of issue 10 through the real command line: `--robot-radius 40` and `--covering-thickness
// 15` are refused as 40 m and 15 m, `40mm` and `40m` are taken as written; and that
// cli/README.md's table of plausible ranges is the named specs'.

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "errors.hpp"
#include "quantity.hpp"
#include "scene_fields.hpp"

using covopt::cli::InputError;
using covopt::cli::ParseQuantity;
using covopt::cli::QuantityKind;
using covopt::cli::QuantitySpec;
using covopt::cli::testing::Run;
using Catch::Matchers::Contains;
namespace specs = covopt::quantity_specs;

TEST_CASE("the CLI's ParseQuantity is the library's, throwing InputError", "[quantity]") {
  CHECK(ParseQuantity("15 mm", specs::kCoveringThickness, "--covering-thickness") == 0.015);
  CHECK_THROWS_AS(ParseQuantity("2kg", specs::kSpeed, "--speed"), InputError);
  for (const auto& [text, spec] : {std::pair{"2kg", specs::kSpeed},
                                   std::pair{"40", specs::kRobotRadius},
                                   std::pair{"nan", specs::kHeadMass}}) {
    std::string library;
    try {
      covopt::ParseQuantity(text, spec, "--flag");
    } catch (const std::invalid_argument& e) {
      library = e.what();
    }
    CAPTURE(text);
    REQUIRE_FALSE(library.empty());
    CHECK_THROWS_WITH(ParseQuantity(text, spec, "--flag"), library);
  }
}

TEST_CASE("every scene field reads bare numbers with its named spec", "[quantity]") {
  const std::vector<std::pair<std::string, const QuantitySpec*>> expected = {
      {"robot.mass", &specs::kRobotMass},           {"robot.speed", &specs::kSpeed},
      {"robot.radius", &specs::kRobotRadius},       {"robot.modulus", &specs::kRobotModulus},
      {"robot.poisson", &specs::kPoissonRatio},     {"covering.modulus", &specs::kCoveringModulus},
      {"covering.poisson", &specs::kPoissonRatio},  {"covering.thickness", &specs::kCoveringThickness},
      {"head.mass", &specs::kHeadMass},             {"head.radius", &specs::kHeadRadius},
      {"scalp.modulus", &specs::kScalpModulus},     {"scalp.poisson", &specs::kPoissonRatio},
      {"scalp.thickness", &specs::kScalpThickness}, {"skull.modulus", &specs::kSkullModulus},
      {"skull.poisson", &specs::kPoissonRatio},     {"model.damping", &specs::kContactDamping},
      {"robot.reaction_delay", &specs::kReactionDelay}, {"robot.braking", &specs::kBraking},
      {"head.torso_mass", &specs::kTorsoMass},      {"head.neck_stiffness", &specs::kNeckStiffness},
      {"head.neck_damping", &specs::kNeckDamping},
  };
  const auto fields = covopt::cli::SceneFields();
  REQUIRE(fields.size() == expected.size());
  for (std::size_t i = 0; i < fields.size(); ++i) {
    CAPTURE(expected[i].first);
    CHECK(fields[i].dotted_name() == expected[i].first);
    CHECK(fields[i].spec.kind == expected[i].second->kind);
    CHECK(fields[i].spec.plausible_min == expected[i].second->plausible_min);
    CHECK(fields[i].spec.plausible_max == expected[i].second->plausible_max);
    CHECK(fields[i].spec.what == expected[i].second->what);
  }
  const auto limits = covopt::cli::LimitFields();
  REQUIRE(limits.size() == 3);
  CHECK(limits[0].dotted_name() == "limits.laceration");
  CHECK(limits[0].spec.what == specs::kLacerationLimit.what);
  CHECK(limits[1].dotted_name() == "limits.contusion");
  CHECK(limits[1].spec.kind == QuantityKind::kEnergyDensity);
  CHECK(limits[2].dotted_name() == "limits.safety_factor");
}

TEST_CASE("limits must be positive and the safety factor in [1, 100]", "[quantity]") {
  const auto limits = covopt::cli::LimitFields();
  using covopt::cli::CheckLimitValue;
  CHECK_NOTHROW(CheckLimitValue(limits[0], 1e6, "--laceration-limit", "'1MPa'"));
  CHECK_THROWS_WITH(CheckLimitValue(limits[0], 0.0, "--laceration-limit", "'0'"),
                    "--laceration-limit must be in [1000, 1e+13] Pa (got '0')");
  CHECK_THROWS_WITH(CheckLimitValue(limits[1], -1.0, "limits.contusion", "-1"),
                    "limits.contusion must be in [1, 1e+13] J/m2 (got -1)");
  CHECK_NOTHROW(CheckLimitValue(limits[2], 1.0, "--safety-factor", "'1'"));
  CHECK_NOTHROW(CheckLimitValue(limits[2], 100.0, "--safety-factor", "'100'"));
  CHECK_THROWS_WITH(CheckLimitValue(limits[2], 0.99, "--safety-factor", "'0.99'"),
                    "--safety-factor must be in [1, 100] (got '0.99')");
  CHECK_THROWS_AS(CheckLimitValue(limits[2], 101.0, "limits.safety_factor", "101"), InputError);
}

TEST_CASE("a bare robot radius or covering thickness in mm is refused on the command line",
          "[quantity][run]") {
  // Issue 10: --robot-radius 40 silently meant 40 m and turned an unsafe robot into "no
  // covering needed"; --covering-thickness 15 was 15 m.
  for (const std::string command : {"simulate", "sweep"}) {
    std::vector<std::string> args = {command, "--robot-radius", "40"};
    if (command == "sweep") args.insert(args.end(), {"--x", "speed=1..2:3"});
    const auto run = Run(args);
    CAPTURE(command);
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK(run.err == "covopt " + command +
                         ": error: --robot-radius 40: a bare number is in metres (40 m); write "
                         "40mm or 40m\n");
  }
  const auto thick = Run({"simulate", "--covering-thickness", "15"});
  CHECK(thick.exit_code == 2);
  CHECK(thick.err == "covopt simulate: error: --covering-thickness 15: a bare number is in "
                     "metres (15 m); write 15mm or 15m\n");
}

TEST_CASE("with a unit, the same numbers are taken as written", "[quantity][run]") {
  const auto mm = Run({"simulate", "--robot-radius", "40mm", "--json"});
  REQUIRE(mm.exit_code == 0);
  CHECK(nlohmann::json::parse(mm.out)["scene"]["robot"]["radius_m"].get<double>() == 0.04);
  // 40 m is within the model's range: the user said so.
  const auto m = Run({"simulate", "--robot-radius", "40m", "--json"});
  REQUIRE(m.exit_code == 0);
  CHECK(nlohmann::json::parse(m.out)["scene"]["robot"]["radius_m"].get<double>() == 40.0);
  // 15 m of covering is not: the model's own range answers.
  const auto thick = Run({"simulate", "--covering-thickness", "15m"});
  CHECK(thick.exit_code == 2);
  CHECK_THAT(thick.err, Contains("covering.thickness must be 0 (no covering) or in [0.0001, 1] m"));
  // A plausible bare number is SI.
  const auto bare = Run({"simulate", "--robot-radius", "0.04", "--json"});
  REQUIRE(bare.exit_code == 0);
  CHECK(nlohmann::json::parse(bare.out)["scene"]["robot"]["radius_m"].get<double>() == 0.04);
}

TEST_CASE("a sub-unit value reaches the JSON without float noise", "[quantity][run]") {
  const auto run = Run({"simulate", "--covering-thickness", "18mm", "--json"});
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("\"thickness_m\": 0.018,") || Contains("\"thickness_m\": 0.018\n"));
  CHECK_THAT(run.out, !Contains("0.018000000000000002"));
}

TEST_CASE("cli/README.md documents every plausible range as the named specs have it",
          "[quantity]") {
  std::ifstream in(COVOPT_CLI_EXAMPLES_DIR "/../README.md");
  REQUIRE(in);
  std::stringstream text;
  text << in.rdbuf();
  const std::string readme = text.str();
  for (const QuantitySpec* spec : specs::kWithPlausibleRange) {
    CAPTURE(spec->what);
    const std::size_t row = readme.find("\n| " + std::string(spec->what) + " | ");
    REQUIRE(row != std::string::npos);
    const std::string line = readme.substr(row + 1, readme.find('\n', row + 1) - row - 1);
    std::string likely;
    for (const std::string_view unit : spec->likely_units) {
      if (unit.empty()) continue;
      if (!likely.empty()) likely += ", ";
      likely += unit;
    }
    CHECK_THAT(line, Contains("| " + covopt::FormatQuantity(spec->plausible_min, spec->kind) +
                              " to " + covopt::FormatQuantity(spec->plausible_max, spec->kind) +
                              " | " + likely + " |"));
  }
}
