// Scene files are TOML with the tables and keys of the scene flags. These tests check that a
// good file sets exactly the values it names (numbers in SI, strings with units, fixed and
// flat), that the shipped example is the paper's scene, that flags override the file, and
// that every kind of bad file (unknown table or key, wrong type, non-finite number, TOML
// syntax error, missing file) is an InputError that says where, and leaves the scene alone.

#include <string>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/core/scene.hpp"
#include "errors.hpp"
#include "scene_file.hpp"

using covopt::Scene;
using covopt::cli::ApplySceneFile;
using covopt::cli::ApplySceneToml;
using covopt::cli::InputError;
using covopt::cli::testing::Run;
using covopt::cli::testing::TempDir;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

/// The message ApplySceneToml throws for `text`, or "" if it accepts it.
std::string ErrorFor(const std::string& text) {
  Scene scene;
  try {
    ApplySceneToml(text, "scene.toml", scene);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

bool SameScene(const Scene& a, const Scene& b) {
  return a.robot.mass_kg == b.robot.mass_kg && a.robot.speed_m_per_s == b.robot.speed_m_per_s &&
         a.robot.radius_m == b.robot.radius_m &&
         a.robot.youngs_modulus_Pa == b.robot.youngs_modulus_Pa &&
         a.robot.poisson_ratio == b.robot.poisson_ratio &&
         a.covering.youngs_modulus_Pa == b.covering.youngs_modulus_Pa &&
         a.covering.poisson_ratio == b.covering.poisson_ratio &&
         a.covering.thickness_m == b.covering.thickness_m && a.head.mass_kg == b.head.mass_kg &&
         a.head.radius_m == b.head.radius_m &&
         a.scalp.youngs_modulus_Pa == b.scalp.youngs_modulus_Pa &&
         a.scalp.poisson_ratio == b.scalp.poisson_ratio &&
         a.scalp.thickness_m == b.scalp.thickness_m &&
         a.skull.youngs_modulus_Pa == b.skull.youngs_modulus_Pa &&
         a.skull.poisson_ratio == b.skull.poisson_ratio &&
         a.model.thresholds == b.model.thresholds;
}

}  // namespace

TEST_CASE("a scene file sets the values it names and nothing else", "[scene_file]") {
  Scene scene;
  const auto set = ApplySceneToml(R"(
[robot]
mass = 7.5            # a number is SI
speed = "250 mm/s"    # a string carries a unit
radius = "flat"
[covering]
thickness = 0
[head]
mass = "fixed"
[model]
thresholds = "literal"
)",
                                  "scene.toml", scene);
  CHECK(scene.robot.mass_kg == 7.5);
  CHECK(scene.robot.speed_m_per_s == Approx(0.25));
  CHECK(scene.robot.radius_m == covopt::kFlat);
  CHECK(scene.covering.thickness_m == 0.0);
  CHECK(scene.head.mass_kg == covopt::kFixed);
  CHECK(scene.model.thresholds == covopt::ThresholdReading::kLiteral);
  CHECK(set.size() == 6);

  // Everything else keeps its default.
  const Scene defaults;
  CHECK(scene.robot.youngs_modulus_Pa == defaults.robot.youngs_modulus_Pa);
  CHECK(scene.covering.youngs_modulus_Pa == defaults.covering.youngs_modulus_Pa);
  CHECK(scene.head.radius_m == defaults.head.radius_m);
  CHECK(scene.scalp.thickness_m == defaults.scalp.thickness_m);
  CHECK(scene.skull.poisson_ratio == defaults.skull.poisson_ratio);
}

TEST_CASE("an integer is read as a number", "[scene_file]") {
  Scene scene;
  ApplySceneToml("[robot]\nmass = 12\n", "scene.toml", scene);
  CHECK(scene.robot.mass_kg == 12.0);
}

TEST_CASE("the shipped example file is the paper's scene, which is the default", "[scene_file]") {
  Scene scene;
  scene.robot.mass_kg = 1.0;  // so that the file must set it back
  const auto set = ApplySceneFile(COVOPT_CLI_EXAMPLES_DIR "/paper_scene.toml", scene);
  CHECK(SameScene(scene, Scene{}));
  CHECK(set.size() == 16);  // every field
}

TEST_CASE("an unknown key is named with its location and a did-you-mean", "[scene_file]") {
  const std::string message = ErrorFor("[robot]\nmas = 10\n");
  CHECK_THAT(message, StartsWith("scene.toml:2:1: unknown key 'robot.mas'"));
  CHECK_THAT(message, Contains("did you mean 'robot.mass'?"));

  CHECK_THAT(ErrorFor("[covering]\nthicknes = \"15mm\"\n"),
             Contains("did you mean 'covering.thickness'?"));
  // Far from every key: list the keys of the table instead.
  CHECK_THAT(ErrorFor("[skull]\ncolour = 1\n"),
             Contains("unknown key 'skull.colour'") && Contains("[skull] takes modulus, poisson"));
}

TEST_CASE("an unknown table is named with a did-you-mean", "[scene_file]") {
  CHECK_THAT(ErrorFor("[robt]\nmass = 10\n"),
             StartsWith("scene.toml:1:2: unknown table 'robt'") && Contains("did you mean 'robot'?"));
  // A field outside any table.
  CHECK_THAT(ErrorFor("speed = 2\n"),
             Contains("unknown table 'speed'") && Contains("put 'speed' under a table such as [robot]"));
}

TEST_CASE("a value of the wrong type is named with its location", "[scene_file]") {
  CHECK_THAT(ErrorFor("[robot]\nmass = true\n"),
             StartsWith("scene.toml:2:8: robot.mass: expected a number (SI) or a string with a unit") &&
                 Contains("got a boolean"));
  CHECK_THAT(ErrorFor("[head]\nradius = [1, 2]\n"), Contains("head.radius") && Contains("an array"));
  CHECK_THAT(ErrorFor("robot = 3\n"), Contains("'robot' must be a table"));
  CHECK_THAT(ErrorFor("[model]\nthresholds = 1\n"),
             Contains("model.thresholds") && Contains("expected a string"));
  CHECK_THAT(ErrorFor("[model]\nthresholds = \"strict\"\n"),
             Contains("model.thresholds: expected 'cumulative' or 'literal' (got 'strict')"));
}

TEST_CASE("a bad value in a string is reported like a bad flag, with the location",
          "[scene_file]") {
  CHECK(ErrorFor("[robot]\nspeed = \"2kg\"\n") ==
        "scene.toml:2:9: robot.speed: unit 'kg' is not a speed; use m/s, mm/s, cm/s or km/h "
        "(got '2kg')");
  CHECK_THAT(ErrorFor("[head]\nradius = \"flat\"\n"), Contains("head.radius"));
}

TEST_CASE("non-finite TOML numbers are rejected", "[scene_file]") {
  CHECK_THAT(ErrorFor("[robot]\nspeed = inf\n"), Contains("robot.speed: not a finite number"));
  CHECK_THAT(ErrorFor("[robot]\nspeed = nan\n"), Contains("robot.speed: not a finite number"));
}

TEST_CASE("a TOML syntax error reports file:line:column", "[scene_file]") {
  CHECK_THAT(ErrorFor("[robot]\nmass = = 10\n"), StartsWith("scene.toml:2:") &&
                                                     Contains("TOML syntax error"));
  CHECK_THAT(ErrorFor("[robot\n"), StartsWith("scene.toml:1:") && Contains("TOML syntax error"));
}

TEST_CASE("a bad file leaves the scene unchanged", "[scene_file]") {
  Scene scene;
  CHECK_THROWS_AS(ApplySceneToml("[robot]\nmass = 3\nspeed = \"x\"\n", "scene.toml", scene),
                  InputError);
  CHECK(SameScene(scene, Scene{}));
}

TEST_CASE("a missing or unreadable scene file is an input error naming it", "[scene_file]") {
  TempDir dir;
  Scene scene;
  CHECK_THROWS_WITH(ApplySceneFile(dir / "nope.toml", scene),
                    Contains("cannot read scene file") && Contains("nope.toml") &&
                        Contains("No such file"));
  CHECK_THROWS_WITH(ApplySceneFile(dir.path(), scene), Contains("is a directory"));
}

TEST_CASE("covopt simulate reads --scene and lets flags override it", "[scene_file][run]") {
  TempDir dir;
  const auto file = dir.Write("scene.toml", "[robot]\nmass = \"5kg\"\nspeed = \"1 m/s\"\n");
  const auto run = Run({"simulate", "--scene", file.string(), "--speed", "1.5m/s", "--json"});
  REQUIRE(run.exit_code == 0);
  const auto json = nlohmann::json::parse(run.out);
  CHECK(json["scene"]["robot"]["mass_kg"] == 5.0);          // from the file
  CHECK(json["scene"]["robot"]["speed_m_per_s"] == 1.5);    // the flag wins
  CHECK(json["scene"]["head"]["mass_kg"] == Scene{}.head.mass_kg);  // the default
}

TEST_CASE("covopt simulate reports a bad scene file as bad input", "[scene_file][run]") {
  TempDir dir;
  const auto file = dir.Write("bad.toml", "[robot]\nmas = 10\n");
  const auto run = Run({"simulate", "--scene", file.string()});
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Contains("bad.toml:2:1") && Contains("did you mean 'robot.mass'?"));

  const auto missing = Run({"simulate", "--scene", (dir / "missing.toml").string()});
  CHECK(missing.exit_code == 2);
  CHECK(missing.out.empty());
  CHECK_THAT(missing.err, Contains("missing.toml"));
}

TEST_CASE("a range error in a scene file says which file set the value", "[scene_file][run]") {
  TempDir dir;
  const auto file = dir.Write("thin.toml", "[scalp]\nthickness = \"9cm\"\n");
  const auto run = Run({"simulate", "--scene", file.string()});
  CHECK(run.exit_code == 2);
  CHECK_THAT(run.err, Contains("scalp.thickness") && Contains("thin.toml"));
}
