#include "covopt/report/robot_model_json.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "covopt/core/number_format.hpp"
#include "json_number.hpp"

namespace covopt::report {
namespace {

using Json = nlohmann::ordered_json;
using internal::Number;

Json Numbers(const std::vector<double>& values) {
  Json list = Json::array();
  for (const double v : values) list.push_back(Number(v));
  return list;
}

Json MassOrFixed(double mass_kg) { return std::isinf(mass_kg) ? Json("fixed") : Number(mass_kg); }

/// "configuration fr3_joint1 = 0 rad, fr3_joint2 = -0.5 rad, ..." (a joint whose name says
/// nothing of its type reads in its SI unit, rad or m, as given to the library).
std::string Configuration(const RobotModelInputs& model) {
  std::string text = "configuration ";
  for (std::size_t i = 0; i < model.joint_positions.size(); ++i) {
    if (i > 0) text += ", ";
    text += i < model.joint_names.size() ? model.joint_names[i] : fmt::format("q{}", i + 1);
    text += " = " + FormatShortest(model.joint_positions[i]);
  }
  return text + " (rad, or m for a prismatic joint)";
}

}  // namespace

std::string WithRobotModel(const std::string& json_object, const RobotModelInputs& model) {
  Json j = Json::parse(json_object, nullptr, false);
  if (!j.is_object()) throw std::invalid_argument("WithRobotModel: json_object is not a JSON object");
  const bool urdf = model.source == "urdf";
  j["robot_model"] = {{"source", model.source},
                      {"urdf_file", urdf ? Json(model.urdf_file) : Json(nullptr)},
                      {"base_link", urdf ? Json(model.base_link) : Json(nullptr)},
                      {"tip_link", urdf ? Json(model.tip_link) : Json(nullptr)},
                      {"joint_names", model.joint_names},
                      {"joint_positions", Numbers(model.joint_positions)},
                      {"contact_point_m", Numbers(model.contact_point_m)},
                      {"direction", Numbers(model.direction)},
                      {"moving_mass_kg", urdf ? Json(nullptr) : Number(model.moving_mass_kg)},
                      {"payload_mass_kg", Number(model.payload_mass_kg)},
                      {"reflected_mass_kg", MassOrFixed(model.reflected_mass_kg)}};
  // Where each of its values came from, when the result says where its inputs did: the flags of
  // the robot model. The object goes before "input_sources" (which stays the last key but the
  // provenance's).
  if (auto sources = j.find("input_sources"); sources != j.end() && sources->is_object()) {
    // The typed configuration by its own flags; what the model gives (masses, the contact point
    // in the base frame, the joints' names) by --urdf.
    const auto flag_of = [&](const std::string& key) -> std::string {
      if (!urdf) return "flag --robot-moving-mass";
      if (key == "joint_positions") return "flag --joints";
      if (key == "direction") return "flag --direction";
      if (key == "tip_link") return "flag --tip";
      return "flag --urdf";
    };
    for (const auto& [key, value] : j["robot_model"].items()) {
      if (value.is_primitive() && !value.is_null()) (*sources)["robot_model." + key] = flag_of(key);
      for (std::size_t i = 0; value.is_array() && i < value.size(); ++i) {
        (*sources)["robot_model." + key + "." + std::to_string(i)] = flag_of(key);
      }
    }
    (*sources)["robot_model.payload_mass_kg"] = model.payload_mass_kg > 0.0 ? "flag --payload-mass" : "default";
    Json reordered = Json::object();
    for (auto& [key, value] : j.items()) {
      if (key == "robot_model") continue;
      if (key == "input_sources") reordered["robot_model"] = std::move(j["robot_model"]);
      reordered[key] = std::move(value);
    }
    j = std::move(reordered);
  }
  if (auto summary = j.find("summary"); summary != j.end() && summary->is_object()) {
    Json& robot = (*summary)["robot"];
    robot["model_file"] = urdf ? model.urdf_file : std::string();
    robot["motion"] = urdf ? Configuration(model)
                           : fmt::format("ISO/TS 15066 estimate M/2 + m_L, M = {} kg",
                                         FormatShortest(model.moving_mass_kg));
    robot["joints"] = model.joint_names;
    robot["reflected_mass_kg"] = Number(model.reflected_mass_kg);
    robot["payload_kg"] = Number(model.payload_mass_kg);
  }
  return j.dump(2);
}

}  // namespace covopt::report
