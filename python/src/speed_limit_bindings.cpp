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
#include "covopt/core/sweep.hpp"
#include "covopt/optim/speed_limit.hpp"
#include "covopt/optim/speed_limit_table.hpp"
#include "covopt/report/speed_limit_json.hpp"
#include "bounded.hpp"
#include "report_charts.hpp"
#include "scene_keywords.hpp"

namespace py = pybind11;

namespace covopt::python {

optim::SpeedLimitOptions SpeedLimitOptionsFrom(const SceneInputs& inputs, const py::kwargs& kwargs) {
  optim::SpeedLimitOptions options;
  options.limits = inputs.limits;
  options.safety_factor = inputs.safety_factor;
  options.allow_full_compression = Flag(kwargs, "allow_full_compression");
  options.keep_travel = Flag(kwargs, "keep_travel");
  options.allow_crushing = Flag(kwargs, "allow_crushing");
  options.covering_compressive_strength_Pa = inputs.CrushCheck().compressive_strength_Pa;
  options.oracle = ReadOracleKeywords(kwargs, inputs.scene);
  return options;
}

namespace {

using optim::SpeedLimitQuantity;
using optim::SpeedLimitRow;

/// One value or a list of values of a scene quantity: at most kMaxSweepAxisValues, as the
/// CLI's --robot-mass / --speed lists.
std::vector<double> ReadValues(const py::handle& value, const QuantitySpec& spec, const char* keyword) {
  std::vector<double> values;
  if (!py::isinstance<py::str>(value) && py::isinstance<py::iterable>(value)) {
    ForEachBounded(value, kMaxSweepAxisValues, keyword,
                   [&](const py::handle item) { values.push_back(ReadSceneQuantity(item, spec, keyword)); });
    if (values.empty()) throw std::invalid_argument(std::string(keyword) + ": no values (got an empty list)");
    return values;
  }
  return {ReadSceneQuantity(value, spec, keyword)};
}

/// The rows computed by the library (optim::SpeedLimitTable); bad scenes raise ValueError
/// naming the keyword, and a failed search, as the CLI's exit 1, a ComputationError.
std::vector<SpeedLimitRow> Compute(SpeedLimitQuantity quantity, std::span<const optim::SpeedLimitCovering> coverings,
                                   std::span<const double> values, const SceneInputs& inputs) {
  std::vector<SpeedLimitRow> rows;
  try {
    py::gil_scoped_release release;
    rows = optim::SpeedLimitTable(quantity, coverings, values);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(inputs.Attributed(e.what()));
  }
  if (const SpeedLimitRow* failed = optim::FirstFailedRow(quantity, rows)) {
    RaiseComputationError(optim::RowMessage(quantity, *failed), "evaluation-failed");
  }
  return rows;
}

/// The one row as a dict: the row's keys, and message and brief_report.
py::dict OneLimit(SpeedLimitQuantity quantity, const SceneInputs& inputs, const py::kwargs& kwargs,
                  const char* function) {
  const bool by_speed = quantity == SpeedLimitQuantity::kSpeed;
  const char* solved = by_speed ? "speed" : "robot_mass";
  if (inputs.Gave(solved)) {
    throw std::invalid_argument(std::string(function) + "() computes " + (by_speed ? "the speed" : "the robot mass") +
                                "; drop " + solved + " from the scene");
  }
  const optim::SpeedLimitOptions options = SpeedLimitOptionsFrom(inputs, kwargs);
  const double value = by_speed ? inputs.scene.robot.mass_kg : inputs.scene.robot.speed_m_per_s;
  const optim::SpeedLimitCovering covering{inputs.scene, inputs.covering_material, options};
  const SpeedLimitRow row = Compute(quantity, {&covering, 1}, {&value, 1}, inputs).front();
  const std::vector<std::string> notes = InputAndCrushWarnings(inputs);  // as the CLI's
  const py::dict table = JsonToPython(report::SpeedLimitJson(quantity, inputs.scene, options, {&row, 1}, notes, -1));
  py::dict result = py::list(table["rows"])[0].cast<py::dict>();
  result["message"] = by_speed ? row.speed_limit.message : row.mass_limit.message;
  result["brief_report"] = by_speed ? row.speed_limit.BriefReport() : row.mass_limit.BriefReport();
  result["warnings"] = table["warnings"];
  return result;
}

py::dict MaxSafeSpeed(const SceneInputs& scene, const py::kwargs& kwargs) {
  return OneLimit(SpeedLimitQuantity::kSpeed, scene, kwargs, "max_safe_speed");
}
py::dict MaxSafeMass(const SceneInputs& scene, const py::kwargs& kwargs) {
  return OneLimit(SpeedLimitQuantity::kMass, scene, kwargs, "max_safe_mass");
}

/// covopt.speed_limit(scene, solve_for=, values=, materials=, ...): the dict of `covopt speed-limit --json`.
py::dict SpeedLimitTable(const SceneInputs& scene, const py::kwargs& kwargs) {
  SpeedLimitQuantity quantity = SpeedLimitQuantity::kSpeed;
  if (const auto v = Option(kwargs, "solve_for")) {
    const std::string text = py::str(*v).cast<std::string>();
    if (text == "mass") quantity = SpeedLimitQuantity::kMass;
    else if (text != "speed") throw std::invalid_argument("solve_for: expected 'speed' or 'mass' (got '" + text + "')");
  }
  const bool by_speed = quantity == SpeedLimitQuantity::kSpeed;
  const char* solved = by_speed ? "speed" : "robot_mass";
  if (scene.Gave(solved)) {
    throw std::invalid_argument(std::string("speed_limit(solve_for='") + (by_speed ? "speed" : "mass") +
                                "') computes " + (by_speed ? "the speed" : "the robot mass") + "; drop " + solved +
                                " from the scene" + (by_speed ? " (or give solve_for='mass')" : ""));
  }
  // The materials, one block of rows each (a name or a list of names).
  std::vector<std::optional<std::string>> names;
  if (const auto v = Option(kwargs, "materials")) {
    if (py::isinstance<py::str>(*v)) {
      names.emplace_back(v->cast<std::string>());
    } else if (py::isinstance<py::iterable>(*v)) {
      ForEachBounded(*v, kMaxSweepAxisValues, "materials", [&](const py::handle item) {
        if (!py::isinstance<py::str>(item)) {
          throw std::invalid_argument("materials: expected a name or a list of names (got " +
                                      py::repr(*v).cast<std::string>() + ")");
        }
        names.emplace_back(item.cast<std::string>());
      });
    }
    if (names.empty()) throw std::invalid_argument("materials: expected a name or a list of names (got an empty list)");
  } else {
    names.emplace_back();
  }
  const QuantitySpec& spec = by_speed ? quantity_specs::kRobotMass : quantity_specs::kSpeed;
  const std::vector<double> values =
      Option(kwargs, "values") ? ReadValues(*Option(kwargs, "values"), spec, "values")
                               : std::vector<double>{by_speed ? scene.scene.robot.mass_kg : scene.scene.robot.speed_m_per_s};

  std::vector<optim::SpeedLimitCovering> coverings;
  optim::SpeedLimitOptions options;
  std::vector<std::string> notes;  // the covering notes the CLI prints as warnings
  for (const std::optional<std::string>& name : names) {
    py::dict change;
    if (name) change["material"] = *name;
    const SceneInputs inputs = scene.With(change);
    options = SpeedLimitOptionsFrom(inputs, kwargs);
    for (std::string& note : InputAndCrushWarnings(inputs)) {
      if (std::find(notes.begin(), notes.end(), note) == notes.end()) notes.push_back(std::move(note));
    }
    coverings.push_back({inputs.scene, inputs.covering_material, options});
  }
  const std::vector<SpeedLimitRow> rows = Compute(quantity, coverings, values, scene);
  // The table's criterion covers every material: crushing where a strength is known (as the CLI's).
  options.covering_compressive_strength_Pa = 0.0;
  py::dict table = JsonToPython(report::SpeedLimitJson(quantity, coverings.front().scene, options, rows, notes, -1));
  if (!by_speed) return table;  // the chart draws the max safe speed over the mass, as the CLI's --plot
  chart::SpeedLimitChartInput input{{}, values, options};
  for (const optim::SpeedLimitCovering& c : coverings) input.coverings.push_back({c.scene, c.material});
  return WithReportCharts(std::move(table), [input = std::move(input)] { return std::vector{chart::SpeedLimitChart(input)}; });
}

}  // namespace

void BindSpeedLimit(py::module_& m) {
  m.def("max_safe_speed", &MaxSafeSpeed);
  m.def("max_safe_mass", &MaxSafeMass);
  m.def("speed_limit", &SpeedLimitTable);
}

}  // namespace covopt::python
