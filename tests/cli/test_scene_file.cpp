// Scene files are TOML with the tables and keys of the scene flags. These tests check that a
// good file sets exactly the values it names (numbers in SI, strings with units, fixed and
// flat), that a bare number must be plausible as on the command line, that the shipped
// example is the paper's scene, that flags override the file, that [limits] and
// covering.material reach simulate and sweep, and that every kind of bad file (unknown table
// or key, wrong type, non-finite number, implausible bare number, bad limit, TOML syntax
// error, missing file) is an InputError that says where, and leaves the scene alone.

#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/core/scene.hpp"
#include "errors.hpp"
#include "scene_file.hpp"

using covopt::Scene;
using covopt::cli::ApplySceneFile;
using covopt::cli::ApplySceneToml;
using covopt::cli::InputError;
using covopt::cli::SceneFileExtras;
using covopt::cli::testing::Run;
using covopt::cli::testing::TempDir;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

/// The message ApplySceneToml throws for `text`, or "" if it accepts it.
std::string ErrorFor(const std::string& text) {
  Scene scene;
  SceneFileExtras extras;
  try {
    ApplySceneToml(text, "scene.toml", scene, &extras);
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
  SceneFileExtras extras;
  const auto set = ApplySceneFile(COVOPT_CLI_EXAMPLES_DIR "/paper_scene.toml", scene, &extras);
  CHECK(SameScene(scene, Scene{}));
  CHECK(set.size() == 19);  // every field and the three limits
  const covopt::InjuryLimits limits;
  CHECK(extras.laceration_limit_Pa == limits.laceration_tensile_stress_Pa);
  CHECK(extras.contusion_limit_J_per_m2 == limits.contusion_energy_density_J_per_m2);
  CHECK(extras.safety_factor == 1.0);
  CHECK_FALSE(extras.covering_material.has_value());
}

TEST_CASE("a bare number in a scene file must be plausible, as on the command line",
          "[scene_file]") {
  CHECK(ErrorFor("[robot]\nradius = 40\n") ==
        "scene.toml:2:10: robot.radius 40: a bare number is in metres (40 m); write \"40mm\" "
        "or \"40m\"");
  CHECK(ErrorFor("[covering]\nthickness = 15\n") ==
        "scene.toml:2:13: covering.thickness 15: a bare number is in metres (15 m); write "
        "\"15mm\" or \"15m\"");
  CHECK(ErrorFor("[covering]\nmodulus = 27.6\n") ==
        "scene.toml:2:11: covering.modulus 27.6: a bare number is in pascals (27.6 Pa); write "
        "\"27.6MPa\" or \"27.6Pa\"");
  CHECK_THAT(ErrorFor("[head]\nmass = 4500\n"), Contains("write \"4500g\" or \"4500kg\""));
  // With a unit, or plausible in SI, the value is taken.
  Scene scene;
  ApplySceneToml("[robot]\nradius = \"40m\"\n[covering]\nthickness = 0.018\nmodulus = 27.6e6\n",
                 "scene.toml", scene);
  CHECK(scene.robot.radius_m == 40.0);
  CHECK(scene.covering.thickness_m == 0.018);
  CHECK(scene.covering.youngs_modulus_Pa == 27.6e6);
  ApplySceneToml("[covering]\nthickness = 0\n", "scene.toml", scene);  // no covering
  CHECK(scene.covering.thickness_m == 0.0);
}

TEST_CASE("[limits] sets the injury limits and the safety factor", "[scene_file]") {
  Scene scene;
  SceneFileExtras extras;
  const auto set = ApplySceneToml(
      "[limits]\nlaceration = \"0.8 MPa\"\ncontusion = \"2 J/cm2\"\nsafety_factor = 1.5\n",
      "scene.toml", scene, &extras);
  // toml++ keeps a table's keys sorted.
  CHECK(set == std::vector<std::string>{"limits.contusion", "limits.laceration",
                                        "limits.safety_factor"});
  CHECK(extras.laceration_limit_Pa == 0.8e6);
  CHECK(extras.contusion_limit_J_per_m2 == 20000.0);
  CHECK(extras.safety_factor == 1.5);
  CHECK(SameScene(scene, Scene{}));
  // Bare SI numbers, when plausible.
  ApplySceneToml("[limits]\nlaceration = 1e6\ncontusion = 25200\n", "scene.toml", scene, &extras);
  CHECK(extras.laceration_limit_Pa == 1e6);
  CHECK(extras.contusion_limit_J_per_m2 == 25200.0);
}

TEST_CASE("bad limits are named with their location", "[scene_file]") {
  CHECK(ErrorFor("[limits]\ncontusion = 2.52\n") ==
        "scene.toml:2:13: limits.contusion 2.52: a bare number is in joules per square metre "
        "(2.52 J/m2); write \"2.52J/cm2\" or \"2.52J/m2\"");
  CHECK(ErrorFor("[limits]\nlaceration = 1\n") ==
        "scene.toml:2:14: limits.laceration 1: a bare number is in pascals (1 Pa); write "
        "\"1MPa\" or \"1Pa\"");
  CHECK(ErrorFor("[limits]\nlaceration = \"-1MPa\"\n") ==
        "scene.toml:2:14: limits.laceration must be > 0 Pa (got '-1MPa')");
  CHECK(ErrorFor("[limits]\nsafety_factor = 0.5\n") ==
        "scene.toml:2:17: limits.safety_factor must be in [1, 100] (got 0.5)");
  CHECK_THAT(ErrorFor("[limits]\ncontusion = \"2.52 MPa\"\n"),
             Contains("scene.toml:2:13: limits.contusion: unit 'MPa' is not an energy density"));
  CHECK_THAT(ErrorFor("[limits]\nsafety_factor = true\n"),
             Contains("limits.safety_factor: expected a number") && Contains("a boolean"));
  CHECK_THAT(ErrorFor("[limits]\nlaceraton = \"1MPa\"\n"),
             Contains("unknown key 'limits.laceraton'") &&
                 Contains("did you mean 'limits.laceration'?"));
  CHECK_THAT(ErrorFor("safety_factor = 2\n"),
             Contains("unknown table 'safety_factor'") && Contains("put 'safety_factor' under [limits]"));
}

TEST_CASE("covering.material names a catalog material, not with modulus or poisson",
          "[scene_file]") {
  Scene scene;
  SceneFileExtras extras;
  const auto set = ApplySceneToml("[covering]\nmaterial = \"EPS geofoam EPS39\"\n", "scene.toml",
                                  scene, &extras);
  CHECK(set == std::vector<std::string>{"covering.material"});
  CHECK(extras.covering_material == "EPS geofoam EPS39");
  CHECK(extras.covering_material_where == "scene.toml:2:12");
  CHECK(SameScene(scene, Scene{}));  // looked up by the consumer

  CHECK(ErrorFor("[covering]\nmaterial = \"EPS geofoam EPS39\"\nmodulus = \"5MPa\"\n") ==
        "scene.toml:2:12: covering.material 'EPS geofoam EPS39' sets the covering's modulus and "
        "Poisson ratio; give either covering.material or covering.modulus, not both");
  CHECK_THAT(ErrorFor("[covering]\npoisson = 0.3\nmaterial = \"x\"\n"),
             Contains("covering.material or covering.poisson"));
  CHECK_THAT(ErrorFor("[covering]\nmaterial = 3\n"),
             Contains("covering.material: expected a string") && Contains("an integer"));
  CHECK_THAT(ErrorFor("[covering]\nmaterial = \" \"\n"), Contains("covering.material: empty name"));
}

TEST_CASE("[limits] and covering.material are refused where the caller does not read them",
          "[scene_file]") {
  Scene scene;
  CHECK_THROWS_WITH(ApplySceneToml("[limits]\nsafety_factor = 2\n", "scene.toml", scene),
                    "scene.toml:2:17: limits.safety_factor is not read by this command; remove it");
  CHECK_THROWS_WITH(ApplySceneToml("[covering]\nmaterial = \"x\"\n", "scene.toml", scene),
                    Contains("covering.material is not read by this command"));
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

TEST_CASE("a bad file leaves the scene and the extras unchanged", "[scene_file]") {
  Scene scene;
  SceneFileExtras extras;
  extras.safety_factor = 3.0;
  CHECK_THROWS_AS(ApplySceneToml("[robot]\nmass = 3\nspeed = \"x\"\n", "scene.toml", scene),
                  InputError);
  CHECK_THROWS_AS(ApplySceneToml("[limits]\nsafety_factor = 2\nlaceration = \"x\"\n",
                                 "scene.toml", scene, &extras),
                  InputError);
  CHECK(SameScene(scene, Scene{}));
  CHECK(extras.safety_factor == 3.0);
  CHECK_FALSE(extras.laceration_limit_Pa.has_value());
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

TEST_CASE("simulate judges against the scene file's limits, and flags override them",
          "[scene_file][run]") {
  TempDir dir;
  const auto file = dir.Write("limits.toml",
                              "[limits]\nlaceration = \"0.5 MPa\"\ncontusion = \"3 J/cm2\"\n");
  const auto run = Run({"simulate", "--scene", file.string(), "--json"});
  REQUIRE(run.exit_code == 0);
  const auto json = nlohmann::json::parse(run.out);
  CHECK(json["laceration"]["limit_Pa"] == 0.5e6);
  CHECK(json["contusion"]["limit_J_per_m2"] == 30000.0);
  const double stress = json["laceration"]["value_Pa"].get<double>();
  CHECK(json["laceration"]["ratio"].get<double>() == stress / 0.5e6);
  // The paper's scene: 2.90 J/cm² is unsafe against 2.52 J/cm², safe against 3 J/cm².
  CHECK(json["contusion"]["safe"] == true);

  const auto flag = Run({"simulate", "--scene", file.string(), "--laceration-limit", "2MPa",
                         "--contusion-limit", "25.2kJ/m2", "--json"});
  REQUIRE(flag.exit_code == 0);
  const auto flagged = nlohmann::json::parse(flag.out);
  CHECK(flagged["laceration"]["limit_Pa"] == 2e6);
  CHECK(flagged["contusion"]["limit_J_per_m2"] == 25200.0);
  CHECK(flagged["contusion"]["safe"] == false);

  const auto table = Run({"simulate", "--laceration-limit", "0.5MPa"});
  REQUIRE(table.exit_code == 0);
  CHECK_THAT(table.out, Contains("limit 0.5 MPa"));
}

TEST_CASE("a safety factor judges against the derated limits and says so", "[scene_file][run]") {
  TempDir dir;
  // The paper's scene with a 15 mm covering of E 13 MPa: laceration ratio ~0.2, contusion
  // ratio just below 1 — safe, but not with a factor of 1.2.
  const auto file = dir.Write("factor.toml", "[limits]\nsafety_factor = 1.2\n");
  const std::vector<std::string> scene = {"--covering-modulus", "10MPa"};
  std::vector<std::string> plain_args = {"simulate", "--json"};
  plain_args.insert(plain_args.end(), scene.begin(), scene.end());
  const auto plain = Run(plain_args);
  REQUIRE(plain.exit_code == 0);
  const auto p = nlohmann::json::parse(plain.out);
  const double contusion_ratio = p["contusion"]["ratio"].get<double>();
  REQUIRE(contusion_ratio < 1.0);
  REQUIRE(contusion_ratio * 1.2 > 1.0);
  CHECK(p["safe"] == true);
  CHECK(p["contusion"]["safety_factor"] == 1.0);
  CHECK(p["contusion"]["derated_limit_J_per_m2"] == 25200.0);

  std::vector<std::string> derated_args = {"simulate", "--json", "--scene", file.string()};
  derated_args.insert(derated_args.end(), scene.begin(), scene.end());
  const auto derated = Run(derated_args);
  REQUIRE(derated.exit_code == 0);
  const auto d = nlohmann::json::parse(derated.out);
  CHECK(d["contusion"]["ratio"].get<double>() == contusion_ratio);  // still value/limit
  CHECK(d["contusion"]["limit_J_per_m2"] == 25200.0);               // the limit stays
  CHECK(d["contusion"]["derated_limit_J_per_m2"].get<double>() == Approx(21000.0));
  CHECK(d["contusion"]["safety_factor"] == 1.2);
  CHECK(d["laceration"]["derated_limit_Pa"].get<double>() == Approx(1e6 / 1.2));
  CHECK(d["contusion"]["safe"] == false);
  CHECK(d["laceration"]["safe"] == true);
  CHECK(d["safe"] == false);
  CHECK_THAT(d["warnings"].dump(), Contains("safety factor 1.2 (from " + file.string()));

  // The flag overrides the file, and the table states the derated limits.
  std::vector<std::string> flag_args = {"simulate", "--scene", file.string(), "--safety-factor", "1"};
  flag_args.insert(flag_args.end(), scene.begin(), scene.end());
  CHECK_THAT(Run(flag_args).out, Contains("overall      SAFE"));
  std::vector<std::string> table_args = {"simulate", "--safety-factor", "1.2"};
  table_args.insert(table_args.end(), scene.begin(), scene.end());
  const auto table = Run(table_args);
  CHECK_THAT(table.out, Contains("overall      UNSAFE") &&
                            Contains("judged against its limit divided by 1.2") &&
                            Contains("2.1 J/cm²"));
}

TEST_CASE("covering.material in a scene file works like --material", "[scene_file][run]") {
  TempDir dir;
  const auto file = dir.Write("material.toml", "[covering]\nmaterial = \"polystyrene foam 48.3\"\n");
  const auto run = Run({"simulate", "--scene", file.string(), "--json"});
  REQUIRE(run.exit_code == 0);
  const auto json = nlohmann::json::parse(run.out);
  CHECK(json["scene"]["covering"]["youngs_modulus_Pa"] == 48.3e6);
  CHECK(json["scene"]["covering"]["poisson_ratio"] == 0.25);
  CHECK(json["scene"]["covering"]["material"] == "polystyrene foam 48.3");

  // --material overrides the file's material.
  const auto flag = Run({"simulate", "--scene", file.string(), "--material",
                         "polystyrene foam 27.6", "--json"});
  REQUIRE(flag.exit_code == 0);
  CHECK(nlohmann::json::parse(flag.out)["scene"]["covering"]["youngs_modulus_Pa"] == 27.6e6);

  // Setting E or ν on top of it would leave half a material.
  const auto clash = Run({"simulate", "--scene", file.string(), "--covering-modulus", "5MPa"});
  CHECK(clash.exit_code == 2);
  CHECK_THAT(clash.err, Contains("covering.material 'polystyrene foam 48.3' (" + file.string() +
                                 ":2:12) sets the covering's modulus and Poisson ratio") &&
                            Contains("--covering-modulus"));

  const auto unknown = dir.Write("unknown.toml", "[covering]\nmaterial = \"polystyrene\"\n");
  const auto missing = Run({"simulate", "--scene", unknown.string()});
  CHECK(missing.exit_code == 2);
  CHECK_THAT(missing.err, Contains(unknown.string() + ":2:12: covering.material: no material "
                                                      "'polystyrene'"));

  // --catalog applies to the file's material too.
  const auto catalog = dir.Write("lab.toml",
                                 "[[material]]\nname = \"lab foam\"\nfamily = \"foam\"\n"
                                 "youngs_modulus_Pa = \"12MPa\"\nmodulus_basis = \"compressive\"\n"
                                 "source = \"test\"\n");
  const auto lab = dir.Write("lab_scene.toml", "[covering]\nmaterial = \"lab foam\"\n");
  const auto with_catalog = Run({"simulate", "--scene", lab.string(), "--catalog",
                                 catalog.string(), "--json"});
  REQUIRE(with_catalog.exit_code == 0);
  CHECK(nlohmann::json::parse(with_catalog.out)["scene"]["covering"]["youngs_modulus_Pa"] == 12e6);
}

TEST_CASE("sweep reads the limits and the file's material", "[scene_file][run]") {
  TempDir dir;
  const auto file = dir.Write("sweep.toml", "[covering]\nmaterial = \"polystyrene foam 48.3\"\n"
                                            "[limits]\nlaceration = \"0.5MPa\"\n");
  const auto run = Run({"sweep", "--scene", file.string(), "--x", "speed=1m/s,2m/s", "--csv", "-",
                        "--contusion-limit", "3J/cm2"});
  REQUIRE(run.exit_code == 0);
  const auto reference = Run({"simulate", "--material", "polystyrene foam 48.3",
                              "--laceration-limit", "0.5MPa", "--contusion-limit", "3J/cm2",
                              "--json"});
  REQUIRE(reference.exit_code == 0);
  const auto json = nlohmann::json::parse(reference.out);
  // The 2 m/s row carries simulate's ratios against the same limits.
  CHECK_THAT(run.out, Contains(fmt::format("{}", json["laceration"]["ratio"].get<double>())) &&
                          Contains(fmt::format("{}", json["contusion"]["ratio"].get<double>())));
}
