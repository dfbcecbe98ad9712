// A robot's reflected mass and a contact point's motion as JSON text (covopt robot --json,
// covopt.reflected_mass(), covopt.contact_motion()).
#include "covopt/report/robot_json.hpp"

#include <cmath>
#include <vector>

#include <nlohmann/json.hpp>

namespace covopt::report {
namespace {

using nlohmann::ordered_json;

/// A mass [kg]: a number, or "fixed" when infinite (the robot cannot move that way).
ordered_json Mass(double mass_kg) {
  return std::isfinite(mass_kg) ? ordered_json(mass_kg) : ordered_json("fixed");
}

ordered_json Vector(const Eigen::Vector3d& v) { return ordered_json::array({v[0], v[1], v[2]}); }

std::vector<std::string> Warnings(std::span<const std::string> input_warnings,
                                  const std::vector<std::string>& own) {
  std::vector<std::string> warnings(input_warnings.begin(), input_warnings.end());
  warnings.insert(warnings.end(), own.begin(), own.end());
  return warnings;
}

}  // namespace

std::string RobotJson(const robot::ReflectedMassResult& result, std::span<const std::string> input_warnings,
                      int indent, const std::optional<RobotPayload>& payload) {
  ordered_json j;
  j["reflected_mass_kg"] = result.reflected_mass_kg ? Mass(*result.reflected_mass_kg) : ordered_json(nullptr);
  j["direction"] = result.direction ? Vector(*result.direction) : ordered_json(nullptr);
  j["max_reflected_mass_kg"] = Mass(result.max_reflected_mass_kg);
  j["max_direction"] = Vector(result.max_direction);
  j["min_reflected_mass_kg"] = Mass(result.min_reflected_mass_kg);
  j["min_direction"] = Vector(result.min_direction);
  j["contact_point_m"] = Vector(result.contact_point_m);
  j["joint_names"] = result.joint_names;
  j["payload"] = nullptr;
  if (payload) {
    const Eigen::Matrix3d& inertia = payload->payload.inertia_kg_m2;
    ordered_json rows = ordered_json::array();
    for (int r = 0; r < 3; ++r) rows.push_back(Vector(inertia.row(r).transpose()));
    const robot::ReflectedMassResult& bare = payload->without_payload;
    j["payload"] = {{"mass_kg", payload->payload.mass_kg},
                    {"center_of_mass_m", Vector(payload->payload.center_of_mass_m)},
                    {"inertia_kg_m2", rows},
                    {"without_payload",
                     {{"reflected_mass_kg", bare.reflected_mass_kg ? Mass(*bare.reflected_mass_kg) : ordered_json(nullptr)},
                      {"max_reflected_mass_kg", Mass(bare.max_reflected_mass_kg)},
                      {"min_reflected_mass_kg", Mass(bare.min_reflected_mass_kg)}}}};
  }
  j["status"] = robot::ToString(result.status);
  j["message"] = result.message;
  j["warnings"] = Warnings(input_warnings, result.warnings);
  return j.dump(indent);
}

std::string ContactMotionJson(const robot::ContactMotionResult& result,
                              std::span<const std::string> input_warnings, int indent) {
  ordered_json samples = ordered_json::array();
  for (const robot::ContactMotionSample& s : result.samples) {
    samples.push_back({{"time_s", s.time_s},
                       {"speed_m_per_s", s.speed_m_per_s},
                       {"moving", s.moving},
                       {"direction", s.moving ? Vector(s.direction) : ordered_json(nullptr)},
                       {"velocity_m_per_s", Vector(s.velocity_m_per_s)},
                       {"contact_point_m", Vector(s.contact_point_m)},
                       {"reflected_mass_kg", Mass(s.reflected_mass_kg)}});
  }
  ordered_json j;
  j["samples"] = samples;
  j["joint_names"] = result.joint_names;
  j["status"] = robot::ToString(result.status);
  j["message"] = result.message;
  j["warnings"] = Warnings(input_warnings, result.warnings);
  return j.dump(indent);
}

}  // namespace covopt::report
