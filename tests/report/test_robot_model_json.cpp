// covopt::report::WithRobotModel (report/robot_model_json.hpp): the robot model behind a robot
// mass becomes the result's "robot_model" input and its summary's robot, so the report shows
// the URDF, the joints and the reflected mass as inputs and on its first page.

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "covopt/core/result_summary.hpp"
#include "covopt/report/robot_model_json.hpp"
#include "covopt/report/summary_json.hpp"

namespace {

using covopt::report::RobotModelInputs;
using covopt::report::WithRobotModel;
using Json = nlohmann::json;

RobotModelInputs Fr3() {
  return {.source = "urdf",
          .urdf_file = "models/fr3.urdf",
          .base_link = "fr3_link0",
          .tip_link = "fr3_link8",
          .joint_names = {"fr3_joint1", "fr3_joint2"},
          .joint_positions = {0.0, -0.5},
          .contact_point_m = {0.5, 0.0, 0.6},
          .direction = {1.0, 0.0, 0.0},
          .payload_mass_kg = 0.5,
          .reflected_mass_kg = 1.84993};
}

std::string WithSummary() {
  covopt::ResultSummary summary;
  summary.command = "speed-limit";
  summary.kind = covopt::ResultSummary::Kind::kLimits;
  summary.limits.push_back({.target = "head", .quantity = "max safe speed", .unit = "m/s", .value = 0.8});
  summary.Finish();
  return R"({"solve_for": "speed", "summary": )" + covopt::report::SummaryJson(summary) + "}";
}

}  // namespace

TEST_CASE("WithRobotModel adds the URDF, its joints and the reflected mass as an input and to the summary",
          "[report][robot_model]") {
  const Json j = Json::parse(WithRobotModel(WithSummary(), Fr3()));
  const Json& model = j.at("robot_model");
  CHECK(model.at("source") == "urdf");
  CHECK(model.at("urdf_file") == "models/fr3.urdf");
  CHECK(model.at("tip_link") == "fr3_link8");
  CHECK(model.at("joint_names") == Json({"fr3_joint1", "fr3_joint2"}));
  CHECK(model.at("joint_positions") == Json({0.0, -0.5}));
  CHECK(model.at("moving_mass_kg").is_null());
  CHECK(model.at("reflected_mass_kg") == 1.84993);
  CHECK(j.at("solve_for") == "speed");  // the result's own keys stay

  const covopt::ResultSummary summary = covopt::report::SummaryFromJson(j.dump());
  CHECK(summary.robot.model_file == "models/fr3.urdf");
  CHECK(summary.robot.joints == std::vector<std::string>{"fr3_joint1", "fr3_joint2"});
  CHECK(summary.robot.reflected_mass_kg == 1.84993);
  CHECK(summary.robot.payload_kg == 0.5);
  CHECK_THAT(summary.robot.motion, Catch::Contains("fr3_joint2 = -0.5"));
}

TEST_CASE("WithRobotModel: ISO/TS 15066's estimate names M, a fixed robot reads fixed, a non-object is refused",
          "[report][robot_model]") {
  RobotModelInputs iso{.source = "iso-estimate", .moving_mass_kg = 30.0, .payload_mass_kg = 2.0, .reflected_mass_kg = 17.0};
  const Json j = Json::parse(WithRobotModel(WithSummary(), iso));
  CHECK(j.at("robot_model").at("urdf_file").is_null());
  CHECK(j.at("robot_model").at("moving_mass_kg") == 30.0);
  const covopt::ResultSummary summary = covopt::report::SummaryFromJson(j.dump());
  CHECK(summary.robot.model_file.empty());
  CHECK_THAT(summary.robot.motion, Catch::Contains("M/2 + m_L, M = 30 kg"));

  RobotModelInputs fixed = Fr3();
  fixed.reflected_mass_kg = std::numeric_limits<double>::infinity();
  CHECK(Json::parse(WithRobotModel("{}", fixed)).at("robot_model").at("reflected_mass_kg") == "fixed");
  CHECK_FALSE(Json::parse(WithRobotModel("{}", fixed)).contains("summary"));  // none added where none was

  CHECK_THROWS_AS(WithRobotModel("[1, 2]", Fr3()), std::invalid_argument);
  CHECK_THROWS_AS(WithRobotModel("not json", Fr3()), std::invalid_argument);
}

TEST_CASE("WithRobotModel: the robot model's values get their sources, the object right before input_sources",
          "[report][robot_model]") {
  const std::string result = R"({"solve_for": "speed", "input_sources": {"scene.head.mass_kg": "default"},
                                 "provenance": {"software": "covopt"}})";
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(WithRobotModel(result, Fr3()));
  std::vector<std::string> keys;
  for (const auto& item : j.items()) keys.push_back(item.key());
  CHECK(keys == std::vector<std::string>{"solve_for", "robot_model", "input_sources", "provenance"});
  const auto& sources = j.at("input_sources");
  CHECK(sources.at("scene.head.mass_kg") == "default");  // the others kept
  CHECK(sources.at("robot_model.urdf_file") == "flag --urdf");
  CHECK(sources.at("robot_model.joint_positions.1") == "flag --joints");
  CHECK(sources.at("robot_model.direction.0") == "flag --direction");
  CHECK(sources.at("robot_model.joint_names.1") == "flag --urdf");
  CHECK(sources.at("robot_model.reflected_mass_kg") == "flag --urdf");
  CHECK(sources.at("robot_model.payload_mass_kg") == "flag --payload-mass");
  CHECK_FALSE(sources.contains("robot_model.moving_mass_kg"));  // null for a URDF: no value, no source
  RobotModelInputs iso{.source = "iso-estimate", .moving_mass_kg = 30.0, .reflected_mass_kg = 15.0};
  const nlohmann::json k = nlohmann::json::parse(WithRobotModel(result, iso));
  CHECK(k.at("input_sources").at("robot_model.moving_mass_kg") == "flag --robot-moving-mass");
  CHECK(k.at("input_sources").at("robot_model.payload_mass_kg") == "default");
}
