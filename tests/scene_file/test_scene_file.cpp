// covopt::scene_file reads scene files: TOML with the tables and keys of the scene flags. These
// tests check that a good file sets exactly the values it names (numbers in SI, strings with
// units, fixed and flat), that a bare number must be plausible as on the command line, that
// the shipped example is the paper's scene, that [limits], covering.material and ranges reach
// the extras, and that every kind of bad file (unknown table or key, wrong type, non-finite
// number, implausible bare number, bad limit, TOML syntax error, missing file) is a
// std::invalid_argument that says where, and leaves the scene alone. The CLI's use of the
// files (--scene) is tested in tests/cli/test_scene_file.cpp.

#include <filesystem>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include <catch2/catch.hpp>

#include "covopt/core/quantity.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/core/scene_fields.hpp"
#include "covopt/scene_file/scene_file.hpp"

using covopt::Scene;
using covopt::scene_file::ApplySceneFile;
using covopt::scene_file::ApplySceneToml;
using covopt::scene_file::SceneFileExtras;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

/// The message ApplySceneToml throws for `text`, or "" if it accepts it.
std::string ErrorFor(const std::string& text) {
  Scene scene;
  SceneFileExtras extras;
  try {
    ApplySceneToml(text, "scene.toml", scene, &extras);
  } catch (const std::invalid_argument& e) {
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
law = "hertz"
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
  CHECK(scene.covering.law == covopt::CoveringLaw::kHertz);
  CHECK(set.size() == 7);

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
  const auto set = ApplySceneFile(COVOPT_SCENE_EXAMPLES_DIR "/paper_scene.toml", scene, &extras);
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
        "scene.toml:2:14: limits.laceration must be in [1000, 1e+13] Pa (got '-1MPa')");
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
  CHECK_THAT(ErrorFor("[covering]\nlaw = 1\n"),
             Contains("covering.law: expected a string, \"auto\", \"foam\" or \"hertz\", got an integer"));
  CHECK_THAT(ErrorFor("[covering]\nlaw = \"soft\"\n"),
             Contains("covering.law: expected 'auto', 'foam' or 'hertz' (got 'soft')"));
  CHECK_THAT(ErrorFor("[covering]\nlaws = \"foam\"\n"), Contains("did you mean 'covering.law'?"));
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
                  std::invalid_argument);
  CHECK_THROWS_AS(ApplySceneToml("[limits]\nsafety_factor = 2\nlaceration = \"x\"\n",
                                 "scene.toml", scene, &extras),
                  std::invalid_argument);
  CHECK(SameScene(scene, Scene{}));
  CHECK(extras.safety_factor == 3.0);
  CHECK_FALSE(extras.laceration_limit_Pa.has_value());
}

TEST_CASE("a missing or unreadable scene file is an input error naming it", "[scene_file]") {
  const std::filesystem::path dir = std::filesystem::temp_directory_path();
  Scene scene;
  CHECK_THROWS_WITH(ApplySceneFile(dir / "covopt-no-such-scene-file.toml", scene),
                    Contains("cannot read scene file") && Contains("covopt-no-such-scene-file.toml") &&
                        Contains("No such file"));
  CHECK_THROWS_WITH(ApplySceneFile(dir, scene), Contains("is a directory"));
}

TEST_CASE("a range in a scene file is an uncertain input, refused where extras are not wanted",
          "[scene_file][range]") {
  Scene scene;
  SceneFileExtras extras;
  const auto set = ApplySceneToml("[head]\nmass = \"3.7kg..5.8kg\"\n", "scene.toml", scene, &extras);
  CHECK(set == std::vector<std::string>{"head.mass"});
  REQUIRE(extras.ranges.size() == 1);
  CHECK(extras.ranges[0].field == "head.mass");
  CHECK(extras.ranges[0].name == "head-mass");
  CHECK(extras.ranges[0].source == "scene.toml:2:8: head.mass");
  CHECK(extras.ranges[0].low == 3.7);
  CHECK(extras.ranges[0].high == 5.8);
  CHECK(scene.head.mass_kg == Scene{}.head.mass_kg);  // the scene keeps its value
  CHECK_THROWS_WITH(ApplySceneToml("[head]\nmass = \"3.7kg..5.8kg\"\n", "scene.toml", scene),
                    StartsWith("scene.toml:2:8: head.mass: a range (an uncertain input) is taken by"));
  CHECK_THAT(ErrorFor("[head]\nmass = \"fixed..5kg\"\n"),
             Contains("a range needs finite ends: a fixed body cannot be uncertain"));
  CHECK_THAT(ErrorFor("[head]\nmass = \"5kg..4kg\"\n"),
             Contains("the lower end is above the upper end"));
}

TEST_CASE("ParseQuantityRange reads closed and one-sided ranges in SI", "[scene_file][range]") {
  using covopt::scene_file::ParseQuantityRange;
  const auto& modulus = covopt::quantity_specs::kCoveringModulus;
  const auto both = ParseQuantityRange("10MPa..100 MPa", modulus, "--modulus");
  CHECK(both.min == 10e6);
  CHECK(both.max == 100e6);
  CHECK_FALSE(ParseQuantityRange(" 1GPa.. ", modulus, "--modulus").max.has_value());
  CHECK_THROWS_WITH(ParseQuantityRange("10..100MPa", modulus, "--modulus"),
                    "--modulus: give the unit on both ends, e.g. 10MPa..100MPa; a bare number is SI "
                    "(got '10..100MPa')");
  CHECK_THROWS_WITH(ParseQuantityRange("1MPa", modulus, "--strength", "100kPa..1MPa"),
                    Contains("e.g. 100kPa..1MPa"));
}

TEST_CASE("the [limits] fields are checked with one message for every front end", "[scene_file]") {
  const auto limits = covopt::scene_file::LimitFields();
  REQUIRE(limits.size() == 3);
  CHECK(limits[0].dotted_name() == "limits.laceration");
  CHECK(limits[2].name == "safety-factor");
  using covopt::scene_file::CheckLimitValue;
  CHECK_NOTHROW(CheckLimitValue(limits[2], 100.0, "limits.safety_factor", "100"));
  CHECK_THROWS_WITH(CheckLimitValue(limits[2], 0.5, "limits.safety_factor", "0.5"),
                    "limits.safety_factor must be in [1, 100] (got 0.5)");
  CHECK_THROWS_WITH(CheckLimitValue(limits[1], 0.0, "limits.contusion", "0"),
                    "limits.contusion must be in [1, 1e+13] J/m2 (got 0)");
  CHECK(covopt::scene_file::ParseThresholds("literal", "model.thresholds") ==
        covopt::ThresholdReading::kLiteral);
  CHECK(covopt::scene_file::ThresholdsName(covopt::ThresholdReading::kCumulative) == "cumulative");
}

TEST_CASE("[report] reaches the extras as settings named by where they are written", "[scene_file]") {
  Scene scene;
  SceneFileExtras extras;
  const auto set = ApplySceneToml(
      "[report]\nproject = \"Line 4\"\nmargin_threshold = 0.2\nappendix = \"full\"\nnote = \"\"\"a\nb\"\"\"\n",
      "scene.toml", scene, &extras);
  CHECK(SameScene(scene, Scene{}));
  // toml++ keeps a table's keys sorted.
  CHECK(set == std::vector<std::string>{"report.appendix", "report.margin_threshold", "report.note", "report.project"});
  REQUIRE(extras.report.size() == 4);
  CHECK(extras.report[0].key == "appendix");
  CHECK(std::get<std::string>(extras.report[0].value) == "full");
  CHECK(extras.report[0].name == "scene.toml:4:12: report.appendix");
  CHECK(std::get<double>(extras.report[1].value) == 0.2);
  CHECK(std::get<std::string>(extras.report[2].value) == "a\nb");
  CHECK(std::get<std::string>(extras.report[3].value) == "Line 4");
  // A threshold may be a string ("10%") or an integer; the values are read by the report.
  ApplySceneToml("[report]\nmargin_threshold = \"10%\"\n", "s.toml", scene, &extras);
  CHECK(std::get<std::string>(extras.report.back().value) == "10%");
  ApplySceneToml("[report]\nmargin_threshold = 0\n", "s.toml", scene, &extras);
  CHECK(std::get<double>(extras.report.back().value) == 0.0);
}

TEST_CASE("bad [report] keys and types are named with their location", "[scene_file]") {
  CHECK(ErrorFor("[report]\nprojet = \"x\"\n") == "scene.toml:2:1: unknown key 'report.projet'; did you mean 'report.project'?");
  CHECK_THAT(ErrorFor("[report]\ncolour = \"x\"\n"),
             Contains("[report] takes project, cell, assessor, note, margin_threshold, appendix"));
  CHECK(ErrorFor("[report]\nassessor = 3\n") == "scene.toml:2:12: report.assessor: expected a string, got an integer");
  CHECK_THAT(ErrorFor("[report]\nmargin_threshold = true\n"),
             Contains("report.margin_threshold: expected a share, 0.1 or \"10%\"") && Contains("a boolean"));
  CHECK_THAT(ErrorFor("report = 3\n"), Contains("'report' must be a table"));
  Scene scene;
  CHECK_THROWS_WITH(ApplySceneToml("[report]\nproject = \"x\"\n", "scene.toml", scene, nullptr),
                    "scene.toml:2:11: report.project is not read by this command; remove it");
}
