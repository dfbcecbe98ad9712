// Where a result's inputs came from (covopt/report/input_sources.hpp): the JSON path of every
// scene field checked against the scene's JSON writer (SceneJsonPath, simulation_json.hpp), the
// source of a field (given, catalog, scene file, default) and the "input_sources" object
// appended to a result's JSON (only the paths it has, its own text kept).
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "covopt/core/scene.hpp"
#include "covopt/core/scene_fields.hpp"
#include "covopt/report/input_sources.hpp"
#include "covopt/report/simulation_json.hpp"

namespace {

using covopt::Scene;
using covopt::report::InputOrigins;
using covopt::report::SceneJsonPath;
using Json = nlohmann::json;

/// The dotted paths ("robot.mass_kg") of the leaves whose values differ between two objects.
void Differences(const Json& a, const Json& b, const std::string& prefix, std::vector<std::string>& paths) {
  if (a.is_object() && b.is_object()) {
    for (const auto& [key, value] : a.items()) {
      Differences(value, b.contains(key) ? b[key] : Json(), prefix.empty() ? key : prefix + "." + key, paths);
    }
  } else if (a != b) {
    paths.push_back(prefix);
  }
}

/// The paths SceneJson writes differently for `changed` than for the default scene, each with
/// the "scene." prefix of the results.
std::vector<std::string> ChangedPaths(const Scene& changed) {
  std::vector<std::string> paths;
  Differences(Json::parse(covopt::report::SceneJson(changed)), Json::parse(covopt::report::SceneJson(Scene{})), "",
              paths);
  for (std::string& path : paths) path = "scene." + path;
  return paths;
}

}  // namespace

TEST_CASE("SceneJsonPath: every scene field's path is where the scene's JSON writer puts it", "[input_sources]") {
  for (const covopt::SceneField& field : covopt::SceneFields()) {
    Scene scene;
    field.field(scene) = 12345.5;  // a value no default has
    CAPTURE(field.dotted_name());
    const std::optional<std::string> path = SceneJsonPath(field.dotted_name());
    REQUIRE(path);
    CHECK(ChangedPaths(scene) == std::vector<std::string>{*path});
  }
  Scene scene;
  scene.covering.law = covopt::CoveringLaw::kFoam;
  CHECK(ChangedPaths(scene) == std::vector<std::string>{*SceneJsonPath("covering.law")});
  scene = {};
  scene.head.area = covopt::HeadArea::kNasal;
  CHECK(ChangedPaths(scene) == std::vector<std::string>{*SceneJsonPath("head.area")});
  scene = {};
  scene.model.thresholds = covopt::ThresholdReading::kLiteral;
  CHECK(ChangedPaths(scene) == std::vector<std::string>{*SceneJsonPath("model.thresholds")});
  CHECK(SceneJsonPath("robot.mass") == "scene.robot.mass_kg");
  CHECK(SceneJsonPath("covering.material") == "scene.covering.material");
  for (const char* unknown : {"robot.law", "head.modulus", "mass", "limits.laceration", ""}) {
    CAPTURE(unknown);
    CHECK_FALSE(SceneJsonPath(unknown));
  }
}

TEST_CASE("InputSource: given, then catalog, then the scene file, else default", "[input_sources]") {
  InputOrigins origins;
  origins.given = {{"robot.mass", "flag --robot-mass"}, {"covering.material", "flag --material"}};
  origins.scene_file = "cell4.toml";
  origins.from_scene_file = {"robot.mass", "head.mass", "covering.modulus"};
  origins.from_catalog = {"covering.modulus", "covering.poisson"};
  CHECK(covopt::report::InputSource(origins, "robot.mass") == "flag --robot-mass");
  CHECK(covopt::report::InputSource(origins, "covering.modulus") == "catalog");
  CHECK(covopt::report::InputSource(origins, "head.mass") == "scene file cell4.toml");
  CHECK(covopt::report::InputSource(origins, "robot.speed") == "default");
}

TEST_CASE("WithInputSources: the paths the result has, appended last, the result's text kept", "[input_sources]") {
  InputOrigins origins;
  origins.given = {{"robot.speed", "keyword speed"}, {"limits.safety_factor", "keyword safety_factor"}};
  origins.scene_file = "s.toml";
  origins.from_scene_file = {"limits.laceration"};
  Json result;
  result["scene"] = Json::parse(covopt::report::SceneJson(Scene{}));
  result["scene"]["robot"].erase("mass_kg");  // as a trajectory's: each sample's own
  result["safety_factor"] = 1.5;
  result["limits"] = {{"laceration_Pa", 1e6}, {"contusion_J_per_m2", 25200}, {"derated_laceration_Pa", 666666.0}};
  std::string text = result.dump(2);
  const std::string factor = "\"safety_factor\": 1.5,";
  REQUIRE(text.find(factor) != std::string::npos);
  text.replace(text.find(factor), factor.size(), "\"safety_factor\": 1.50,");  // the writer's number text is kept
  const std::string with = covopt::report::WithInputSources(text, origins);
  CHECK(with.substr(0, with.find("\"input_sources\"")).find("\"safety_factor\": 1.50,") != std::string::npos);
  const Json sources = Json::parse(with)["input_sources"];
  CHECK(with.find("\"input_sources\"") > with.find("\"derated_laceration_Pa\""));  // the last key
  CHECK(sources["scene.robot.speed_m_per_s"] == "keyword speed");
  CHECK(sources["safety_factor"] == "keyword safety_factor");
  CHECK(sources["limits.laceration_Pa"] == "scene file s.toml");
  CHECK(sources["limits.contusion_J_per_m2"] == "default");
  CHECK(sources["scene.head.mass_kg"] == "default");
  CHECK(sources["scene.model.thresholds"] == "default");
  CHECK_FALSE(sources.contains("scene.robot.mass_kg"));   // not in the result
  CHECK_FALSE(sources.contains("scene.covering.material"));
  CHECK_FALSE(sources.contains("limits.derated_laceration_Pa"));  // derived, not an input
  CHECK_FALSE(sources.contains("laceration.limit_Pa"));
  // One line stays one line.
  const std::string one_line = covopt::report::WithInputSources(R"({"safety_factor":2})", origins);
  CHECK(one_line == R"({"safety_factor":2,"input_sources":{"safety_factor":"keyword safety_factor"}})");
  CHECK_THROWS_AS(covopt::report::WithInputSources("[1]", origins), std::invalid_argument);
  CHECK_THROWS_AS(covopt::report::WithInputSources("{", origins), std::invalid_argument);
}
