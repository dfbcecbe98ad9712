#pragma once
/// @file input_sources.hpp
/// Where each input of a result came from, written into the result's JSON by the CLI and Python
/// as its top-level "input_sources" object: {"<dotted JSON path of an input leaf>": source},
/// the source one of "flag --robot-mass", "keyword robot_mass" (Python), "scene file NAME.toml",
/// "catalog" (a covering's modulus and Poisson ratio from its catalog material) or "default".
///
/// The inputs listed: the scene's fields, choices and covering material where the result's JSON
/// has them ("scene.robot.mass_kg", SceneJsonPath), the safety factor ("safety_factor", or each
/// criterion's in simulate's "laceration.safety_factor" ...) and the injury limits
/// ("limits.laceration_Pa", or simulate's "laceration.limit_Pa"), and the reaction delay and
/// braking of an audit ("reaction_delay_s", "braking_m_per_s2"). A path the result does not
/// have is left out; other inputs are not listed (their source is not known here).

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace covopt::report {

/// What a front end knows about where its inputs came from. Fields by their dotted names: a
/// Scene field's ("robot.mass"), "covering.material", "covering.law", "head.area",
/// "model.thresholds", or a limit's ("limits.laceration", "limits.contusion",
/// "limits.safety_factor").
struct InputOrigins {
  /// The fields the user gave, each with the source it is shown with: "flag --robot-mass",
  /// "keyword robot_mass".
  std::map<std::string, std::string, std::less<>> given;
  /// The scene file's name as shown ("cell4.toml"; its path is in the provenance).
  std::string scene_file;
  /// The fields the scene file set (scene_file::ApplySceneFile's answer).
  std::vector<std::string> from_scene_file;
  /// The fields a catalog material set: "covering.modulus", "covering.poisson".
  std::vector<std::string> from_catalog;
};

/// The source of `field`: what `origins` gave it (given, then catalog, then the scene file),
/// else "default".
std::string InputSource(const InputOrigins& origins, const std::string& field);

/// The "input_sources" object of `result_json` (one JSON object): every listed input path the
/// result has (see above), mapped to InputSource of its field. `indent` as nlohmann's dump.
/// @throws std::invalid_argument when result_json is not a JSON object.
std::string InputSourcesJson(const std::string& result_json, const InputOrigins& origins, int indent = 2);

/// `result_json` (one JSON object, as the *Json functions print it, at any indent) with
/// "input_sources" (InputSourcesJson) appended as its last key, the result's own text kept.
/// @throws std::invalid_argument when result_json is not a JSON object.
std::string WithInputSources(const std::string& result_json, const InputOrigins& origins);

}  // namespace covopt::report
