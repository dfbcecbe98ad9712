/// @file speed_limit_bindings.cpp
/// covopt.max_safe_speed, covopt.max_safe_mass and covopt.speed_limit: optim::MaxSafeSpeed /
/// MaxSafeMass with the scene keywords of covopt.simulate; the dicts are report::SpeedLimitJson
/// (covopt.speed_limit returns the object `covopt speed-limit --json` prints). See
/// python/covopt/__init__.py for the documentation.

#include <cmath>
#include <algorithm>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "covopt/core/quantity.hpp"
#include "covopt/optim/speed_limit.hpp"
#include "covopt/optim/speed_limit_table.hpp"
#include "covopt/report/speed_limit_json.hpp"
#include "scene_keywords.hpp"

namespace py = pybind11;

namespace covopt::python {
namespace {

using optim::SpeedLimitQuantity;
using optim::SpeedLimitRow;

/// `kwargs` without the keys in `drop`.
py::kwargs Without(const py::kwargs& kwargs, std::initializer_list<const char*> drop) {
  py::kwargs rest;
  for (const auto& item : kwargs) {
    const std::string key = py::str(item.first).cast<std::string>();
    bool dropped = false;
    for (const char* d : drop) dropped = dropped || key == d;
    if (!dropped) rest[item.first] = item.second;
  }
  return rest;
}

std::optional<py::object> Get(const py::kwargs& kwargs, const char* name) {
  if (!kwargs.contains(name)) return std::nullopt;
  py::object value = kwargs[name];
  if (value.is_none()) return std::nullopt;
  return value;
}

optim::SpeedLimitOptions OptionsFrom(const SceneKeywordInputs& inputs, const py::kwargs& kwargs) {
  optim::SpeedLimitOptions options;
  options.limits = inputs.limits;
  options.safety_factor = inputs.safety_factor;
  if (const auto v = Get(kwargs, "allow_full_compression")) options.allow_full_compression = py::bool_(*v).cast<bool>();
  if (const auto v = Get(kwargs, "allow_crushing")) options.allow_crushing = py::bool_(*v).cast<bool>();
  options.covering_compressive_strength_Pa = CrushCheckOf(inputs, kwargs).compressive_strength_Pa;
  options.oracle = ReadOracleKeywords(kwargs, inputs.scene);
  return options;
}

/// One value or a list of values of a scene quantity.
std::vector<double> ReadValues(const py::handle& value, const QuantitySpec& spec, const char* keyword) {
  std::vector<double> values;
  if (!py::isinstance<py::str>(value) && py::isinstance<py::iterable>(value)) {
    for (const py::handle item : value) values.push_back(ReadSceneQuantity(item, spec, keyword));
    if (values.empty()) throw std::invalid_argument(std::string(keyword) + ": no values (got an empty list)");
    return values;
  }
  return {ReadSceneQuantity(value, spec, keyword)};
}

/// The rows computed by the library (optim::SpeedLimitTable); bad scenes raise ValueError
/// naming the keyword, and a failed search, as the CLI's exit 1, a ComputationError.
std::vector<SpeedLimitRow> Compute(SpeedLimitQuantity quantity, std::span<const optim::SpeedLimitCovering> coverings,
                                   std::span<const double> values, const py::kwargs& kwargs) {
  std::vector<SpeedLimitRow> rows;
  try {
    py::gil_scoped_release release;
    rows = optim::SpeedLimitTable(quantity, coverings, values);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(AttributeSceneError(e.what(), kwargs));
  }
  if (const SpeedLimitRow* failed = optim::FirstFailedRow(quantity, rows)) {
    RaiseComputationError(optim::RowMessage(quantity, *failed), "evaluation-failed");
  }
  return rows;
}

/// The one row as a dict: the row's keys, and message and brief_report.
py::dict OneLimit(SpeedLimitQuantity quantity, const py::kwargs& kwargs, const char* function) {
  const bool by_speed = quantity == SpeedLimitQuantity::kSpeed;
  const char* solved = by_speed ? "speed" : "robot_mass";
  if (Get(kwargs, solved)) {
    throw std::invalid_argument(std::string(function) + "() computes " + (by_speed ? "the speed" : "the robot mass") +
                                "; drop " + solved);
  }
  const SceneKeywordInputs inputs = ReadSceneKeywords(kwargs, function, {"allow_full_compression", "allow_crushing", "oracle", "method", "rtol", "max_steps"});
  const optim::SpeedLimitOptions options = OptionsFrom(inputs, kwargs);
  const double value = by_speed ? inputs.scene.robot.mass_kg : inputs.scene.robot.speed_m_per_s;
  const optim::SpeedLimitCovering covering{inputs.scene, inputs.covering_material, options};
  const SpeedLimitRow row = Compute(quantity, {&covering, 1}, {&value, 1}, kwargs).front();
  const std::vector<std::string> notes = CrushCheckOf(inputs, kwargs).notes;
  const py::dict table = JsonToPython(report::SpeedLimitJson(quantity, inputs.scene, options, {&row, 1}, notes, -1));
  py::dict result = py::list(table["rows"])[0].cast<py::dict>();
  result["message"] = by_speed ? row.speed_limit.message : row.mass_limit.message;
  result["brief_report"] = by_speed ? row.speed_limit.BriefReport() : row.mass_limit.BriefReport();
  result["warnings"] = table["warnings"];
  return result;
}

py::dict MaxSafeSpeed(const py::kwargs& kwargs) { return OneLimit(SpeedLimitQuantity::kSpeed, kwargs, "max_safe_speed"); }
py::dict MaxSafeMass(const py::kwargs& kwargs) { return OneLimit(SpeedLimitQuantity::kMass, kwargs, "max_safe_mass"); }

/// covopt.speed_limit(**scene, solve_for=, materials=, ...): the dict of `covopt speed-limit --json`.
py::dict SpeedLimitTable(const py::kwargs& kwargs) {
  SpeedLimitQuantity quantity = SpeedLimitQuantity::kSpeed;
  if (const auto v = Get(kwargs, "solve_for")) {
    const std::string text = py::str(*v).cast<std::string>();
    if (text == "mass") quantity = SpeedLimitQuantity::kMass;
    else if (text != "speed") throw std::invalid_argument("solve_for: expected 'speed' or 'mass' (got '" + text + "')");
  }
  const bool by_speed = quantity == SpeedLimitQuantity::kSpeed;
  const char* solved = by_speed ? "speed" : "robot_mass";
  const char* varied = by_speed ? "robot_mass" : "speed";
  if (Get(kwargs, solved)) {
    throw std::invalid_argument(std::string("speed_limit(solve_for='") + (by_speed ? "speed" : "mass") +
                                "') computes " + (by_speed ? "the speed" : "the robot mass") + "; drop " + solved +
                                (by_speed ? " (or give solve_for='mass')" : ""));
  }
  // The materials, one block of rows each (a name or a list of names).
  std::vector<std::optional<std::string>> names;
  if (const auto v = Get(kwargs, "material")) {
    if (py::isinstance<py::str>(*v)) {
      names.emplace_back(v->cast<std::string>());
    } else if (py::isinstance<py::iterable>(*v)) {
      for (const py::handle item : *v) {
        if (!py::isinstance<py::str>(item)) {
          throw std::invalid_argument("material: expected a name or a list of names (got " +
                                      py::repr(*v).cast<std::string>() + ")");
        }
        names.emplace_back(item.cast<std::string>());
      }
    }
    if (names.empty()) throw std::invalid_argument("material: expected a name or a list of names (got an empty list)");
  } else {
    names.emplace_back();
  }
  const py::kwargs rest = Without(kwargs, {varied, "material", "solve_for"});
  const QuantitySpec& spec = by_speed ? quantity_specs::kRobotMass : quantity_specs::kSpeed;

  std::vector<optim::SpeedLimitCovering> coverings;
  std::vector<double> values;
  optim::SpeedLimitOptions options;
  std::vector<std::string> notes;  // the covering notes the CLI prints as warnings
  for (const std::optional<std::string>& name : names) {
    py::kwargs scene_kwargs = rest;
    if (name) scene_kwargs["material"] = *name;
    const SceneKeywordInputs inputs =
        ReadSceneKeywords(scene_kwargs, "speed_limit", {"allow_full_compression", "allow_crushing", "solve_for", "oracle", "method", "rtol", "max_steps"});
    options = OptionsFrom(inputs, scene_kwargs);
    for (std::string& note : CrushCheckOf(inputs, scene_kwargs).notes) {
      if (std::find(notes.begin(), notes.end(), note) == notes.end()) notes.push_back(std::move(note));
    }
    if (coverings.empty()) {
      values = Get(kwargs, varied) ? ReadValues(*Get(kwargs, varied), spec, varied)
                                   : std::vector<double>{by_speed ? inputs.scene.robot.mass_kg : inputs.scene.robot.speed_m_per_s};
    }
    coverings.push_back({inputs.scene, inputs.covering_material, options});
  }
  const std::vector<SpeedLimitRow> rows = Compute(quantity, coverings, values, kwargs);
  // The table's criterion covers every material: crushing where a strength is known (as the CLI's).
  options.covering_compressive_strength_Pa = 0.0;
  return JsonToPython(report::SpeedLimitJson(quantity, coverings.front().scene, options, rows, notes, -1));
}

}  // namespace

void BindSpeedLimit(py::module_& m) {
  m.def("max_safe_speed", &MaxSafeSpeed);
  m.def("max_safe_mass", &MaxSafeMass);
  m.def("speed_limit", &SpeedLimitTable);
}

}  // namespace covopt::python
