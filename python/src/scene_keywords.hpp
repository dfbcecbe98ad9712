#pragma once
/// @file scene_keywords.hpp
/// The scene keywords every scene-taking Python call shares (robot_mass, speed, ...,
/// material, thresholds, laceration_limit, contusion_limit, safety_factor), read as
/// covopt.simulate reads them; defined in module.cpp, for the other binding files.

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include <pybind11/pybind11.h>

#include "covopt/core/quantity.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/optim/oracle.hpp"
#include "covopt/optim/speed_limit.hpp"
#include "covopt/report/simulation_json.hpp"

namespace covopt::python {

/// What the scene keywords describe.
struct SceneKeywordInputs {
  Scene scene;                                   ///< Scene{} with the keywords applied
  std::optional<std::string> covering_material;  ///< the catalog name, if material= was given
  bool covering_poisson_assumed = false;         ///< the material's ν is unknown: 0.25 used
  InjuryLimits limits;
  double safety_factor = 1.0;  ///< [-], in [1, 100]
};

/// Refuses a keyword that is neither a scene keyword nor one of `own` ("FUNCTION() got an
/// unknown keyword 'X'"), then reads the scene keywords (the scene itself is checked later,
/// by the library).
/// @throws std::invalid_argument naming the keyword, the value and what is allowed.
SceneKeywordInputs ReadSceneKeywords(const pybind11::kwargs& kwargs, const char* function,
                                     std::initializer_list<const char*> own);

/// A Python value as SI: a number (SI; math.inf where the spec allows "fixed" or "flat"), or
/// a string read with the CLI's unit parser. @throws std::invalid_argument naming `keyword`.
double ReadSceneQuantity(const pybind11::handle& value, const QuantitySpec& spec, std::string_view keyword);

/// A library message naming scene fields, with the keywords the caller gave for them.
std::string AttributeSceneError(const std::string& message, const pybind11::kwargs& given);

/// oracle= ('auto', 'exact', 'time-path'), method= (the time path's integrator, or 'exact'),
/// rtol= and max_steps= (an int >= 10) as optimize() and speed_limit() take them, checked against `scene` (oracle='exact'
/// on a braking or neck scene is refused with the library's message).
/// @throws std::invalid_argument naming the keyword, the value and what is allowed.
optim::OracleOptions ReadOracleKeywords(const pybind11::kwargs& kwargs, const Scene& scene);

/// The crush check of the covering the keywords describe (optim::CrushCheckFor): the built-in
/// catalog material's strength, and the notes the CLI prints for the same input.
optim::CoveringCrushCheck CrushCheckOf(const SceneKeywordInputs& inputs, const pybind11::kwargs& kwargs);

/// Judges a simulation report as the CLI's simulate does: its injury verdicts against
/// `limits` with report.safety_factor, the crush verdict when report.covering_material is a
/// built-in material of known strength, and the scope (what the verdict covers).
void JudgeReport(report::SimulationReport& report, const InjuryLimits& limits, const pybind11::kwargs& kwargs);

/// json.loads(text).
pybind11::object JsonToPython(const std::string& text);

/// Raises covopt.ComputationError(message, status): a computation that ran on valid input and
/// failed (`status`: the library's status name, e.g. "step-limit", "evaluation-failed").
[[noreturn]] void RaiseComputationError(const std::string& message, const std::string& status);

}  // namespace covopt::python
