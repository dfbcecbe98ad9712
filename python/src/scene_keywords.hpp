#pragma once
/// @file scene_keywords.hpp
/// covopt.Scene (defined in module.cpp): the scene, its limits and safety factor, read once
/// from the keywords robot_mass, speed, ..., material, thresholds, laceration_limit,
/// contusion_limit, safety_factor; every scene-taking call takes one. Also the small readers
/// the binding files share.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <pybind11/pybind11.h>

#include "covopt/core/quantity.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/core/sweep.hpp"
#include "covopt/materials/catalog.hpp"
#include "covopt/optim/covering_design.hpp"
#include "covopt/optim/oracle.hpp"
#include "covopt/optim/speed_limit.hpp"
#include "covopt/report/simulation_json.hpp"

namespace covopt::python {

/// covopt.Scene: what the scene keywords describe, and the keywords as given (for messages
/// that name them). Immutable; Scene.replace(**keywords) makes a changed copy.
struct SceneInputs {
  Scene scene;                                   ///< Scene{} with the keywords applied
  std::optional<std::string> covering_material;  ///< the catalog name, if material= was given
  bool covering_poisson_assumed = false;         ///< the material's ν is unknown: 0.25 used
  InjuryLimits limits;
  double safety_factor = 1.0;  ///< [-], in [1, 100]
  pybind11::dict given;        ///< keyword -> the value as the caller gave it

  /// The keyword was given (and not None).
  bool Gave(const char* keyword) const { return given.contains(keyword); }
  /// Scene.replace(**changes): the keywords given with `changes` applied (None unsets), read anew.
  SceneInputs With(const pybind11::dict& changes) const;
  /// A library message naming scene fields ("robot.mass must be ...") with the keywords given
  /// for them: "... (robot.mass is robot_mass=-10.0)".
  std::string Attributed(const std::string& message) const;
  /// The crush check of the covering (optim::CrushCheckFor): the built-in catalog material's
  /// strength, and the notes the CLI prints for the same input.
  optim::CoveringCrushCheck CrushCheck() const;
  /// Judges a report as the CLI's simulate does: its injury verdicts against `limits` with
  /// report.safety_factor, the crush verdict when the covering is a built-in material of
  /// known strength, and the scope (what the verdict covers).
  /// `keep_travel`: the covering's travel rule counts as a limit (keep_travel=True).
  void Judge(report::SimulationReport& report, bool keep_travel = false) const;
};

/// Reads the scene keywords (the scene itself is checked later, by the library).
/// @throws pybind11::type_error for an unknown keyword; std::invalid_argument naming the
/// keyword, the value and what is allowed.
SceneInputs ReadScene(const pybind11::kwargs& keywords);

/// `kwargs[name]` unless absent or None.
std::optional<pybind11::object> Option(const pybind11::dict& kwargs, const char* name);
/// A bool keyword: True or False (Python's or numpy's bool).
/// @throws std::invalid_argument "design: expected True or False (got 'yes')" for anything else.
bool Bool(const pybind11::handle& value, const char* name);
/// Bool(kwargs[name]), false when absent or None.
bool Flag(const pybind11::dict& kwargs, const char* name);

/// A Python value as SI: a number (SI; math.inf where the spec allows "fixed" or "flat"), or
/// a string read with the CLI's unit parser. @throws std::invalid_argument naming `keyword`.
double ReadSceneQuantity(const pybind11::handle& value, const QuantitySpec& spec, std::string_view keyword);

/// oracle= ('auto', 'exact', 'time-path'), method= (the time path's integrator, or 'exact'),
/// rtol= and max_steps= (an int >= 10) as optimize() and speed_limit() take them, checked against `scene` (oracle='exact'
/// on a braking or neck scene is refused with the library's message).
/// @throws std::invalid_argument naming the keyword, the value and what is allowed.
optim::OracleOptions ReadOracleKeywords(const pybind11::kwargs& kwargs, const Scene& scene);

/// The warnings `covopt simulate` adds about its inputs, naming the keywords where the CLI
/// names its flags (module.cpp).
std::vector<std::string> InputWarnings(const SceneInputs& inputs);

/// InputWarnings(inputs), then the covering's crush notes not among them (the default covering
/// is in both): the warnings the CLI's speed-limit, robot --trajectory and audit print.
std::vector<std::string> InputAndCrushWarnings(const SceneInputs& inputs);

/// One sweep axis from Python, (quantity, values), for `keyword` ("x" or "y") (module.cpp).
/// @throws std::invalid_argument naming the keyword.
SweepAxis ReadAxis(const pybind11::handle& axis, const char* keyword);

/// covopt.max_safe_speed's options: the scene's limits and safety factor,
/// allow_full_compression=, allow_crushing=, the covering's crush strength and the oracle
/// keywords (speed_limit_bindings.cpp).
optim::SpeedLimitOptions SpeedLimitOptionsFrom(const SceneInputs& inputs, const pybind11::kwargs& kwargs);

/// The field of a Scene keyword ("robot.mass" for robot_mass); empty when it is none.
std::string_view FieldOfKeyword(std::string_view keyword);

/// Solve's option messages name time_path.*: here they are the keywords rtol, atol, max_steps.
std::string SolveKeywords(std::string message);

/// optimize's candidates: the built-in catalog and the catalog files (catalog=; only those with
/// no_builtin=True), filtered by materials= and families= (module.cpp).
std::vector<optim::CandidateMaterial> Candidates(const pybind11::kwargs& kwargs);

/// The built-in catalog (unless no_builtin) and the catalog files added to it, in order; a bad
/// file is ValueError "catalog: file:line:column: ..." (catalog_bindings.cpp).
materials::Catalog LoadCatalogFiles(const std::vector<std::string>& files, bool no_builtin);

/// json.loads(text).
pybind11::object JsonToPython(const std::string& text);

/// Raises covopt.ComputationError(message, status): a computation that ran on valid input and
/// failed (`status`: the library's status name, e.g. "step-limit", "evaluation-failed").
[[noreturn]] void RaiseComputationError(const std::string& message, const std::string& status);

}  // namespace covopt::python
