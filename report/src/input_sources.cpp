#include "covopt/report/input_sources.hpp"

#include <algorithm>
#include <stdexcept>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

#include "append_key.hpp"
#include "covopt/core/scene_fields.hpp"
#include "covopt/report/simulation_json.hpp"

namespace covopt::report {
namespace {

using Json = nlohmann::ordered_json;

/// The fields that are not Scene fields, and where results other than the scene object show
/// inputs (a field's paths are tried in order; every one present is listed).
constexpr std::pair<std::string_view, std::string_view> kOtherPaths[] = {
    {"limits.safety_factor", "safety_factor"},
    {"limits.safety_factor", "laceration.safety_factor"},
    {"limits.safety_factor", "contusion.safety_factor"},
    {"limits.safety_factor", "fracture.safety_factor"},
    {"limits.safety_factor", "verdict.safety_factor"},
    {"limits.laceration", "limits.laceration_Pa"},
    {"limits.laceration", "laceration.limit_Pa"},
    {"limits.contusion", "limits.contusion_J_per_m2"},
    {"limits.contusion", "contusion.limit_J_per_m2"},
    {"robot.reaction_delay", "reaction_delay_s"},
    {"robot.braking", "braking_m_per_s2"},
};

constexpr std::string_view kChoices[] = {"covering.material", "covering.law", "head.area", "model.thresholds"};

/// The value at a dotted path ("scene.robot.mass_kg"), or null when there is none.
const Json* At(const Json& object, std::string_view path) {
  const Json* node = &object;
  while (!path.empty()) {
    const std::size_t dot = path.find('.');
    const std::string key(path.substr(0, dot));
    if (!node->is_object() || !node->contains(key)) return nullptr;
    node = &(*node)[key];
    path = dot == std::string_view::npos ? std::string_view() : path.substr(dot + 1);
  }
  return node;
}

bool Contains(const std::vector<std::string>& fields, const std::string& field) {
  return std::find(fields.begin(), fields.end(), field) != fields.end();
}

}  // namespace

std::string InputSource(const InputOrigins& origins, const std::string& field) {
  if (const auto given = origins.given.find(field); given != origins.given.end()) return given->second;
  if (Contains(origins.from_catalog, field)) return "catalog";
  if (Contains(origins.from_scene_file, field)) return "scene file " + origins.scene_file;
  return "default";
}

namespace {

/// The "input_sources" object of `result_json`.
Json SourcesObject(const std::string& result_json, const InputOrigins& origins) {
  Json result;
  try {
    result = Json::parse(result_json);
  } catch (const Json::parse_error&) {
    throw std::invalid_argument("input sources: the result's text is not a JSON object");
  }
  if (!result.is_object()) throw std::invalid_argument("input sources: the result's text is not a JSON object");
  std::vector<std::pair<std::string, std::string>> paths;  // (JSON path, field)
  for (const SceneField& field : SceneFields()) {
    const std::string name = field.dotted_name();
    if (const auto path = SceneJsonPath(name)) paths.emplace_back(*path, name);
  }
  for (const std::string_view choice : kChoices) {
    if (const auto path = SceneJsonPath(choice)) paths.emplace_back(*path, std::string(choice));
  }
  for (const auto& [field, path] : kOtherPaths) paths.emplace_back(std::string(path), std::string(field));
  Json sources = Json::object();
  for (const auto& [path, field] : paths) {
    const Json* value = At(result, path);
    if (value == nullptr || value->is_structured()) continue;
    sources[path] = InputSource(origins, field);
  }
  return sources;
}

}  // namespace

std::string InputSourcesJson(const std::string& result_json, const InputOrigins& origins, int indent) {
  return SourcesObject(result_json, origins).dump(indent);
}

std::string WithInputSources(const std::string& result_json, const InputOrigins& origins) {
  return internal::AppendKey(result_json, "input_sources", SourcesObject(result_json, origins), "WithInputSources");
}

}  // namespace covopt::report
