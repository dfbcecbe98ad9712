/// @file sweep_bindings.cpp
/// covopt.sweep(x, y, scene, threads=None): a grid of impacts (covopt::Sweep) as numpy arrays,
/// the columns of `covopt sweep --csv` (python/covopt/__init__.py documents it).

#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/core/sweep.hpp"
#include "bounded.hpp"
#include "scene_keywords.hpp"

namespace py = pybind11;

namespace covopt::python {
namespace {

std::string Repr(const py::handle& value) { return py::repr(value).cast<std::string>(); }

}  // namespace

/// One sweep axis from Python: (quantity, values); the quantity is a CLI scene flag without
/// dashes, underscores allowed ("robot_mass" = "robot-mass"); values are SI numbers, or
/// "fixed"/"flat" for +inf.
SweepAxis ReadAxis(const py::handle& axis, const char* keyword) {
  const auto fail = [&](const std::string& problem) {
    throw std::invalid_argument(std::string(keyword) + ": " + problem + " (got " + Repr(axis) + ")");
  };
  if (!py::isinstance<py::sequence>(axis) || py::isinstance<py::str>(axis) || py::len(axis) != 2) {
    fail("expected (quantity, values), e.g. (\"speed\", [0.5, 1.0, 2.0])");
  }
  const py::sequence pair = py::reinterpret_borrow<py::sequence>(axis);
  if (!py::isinstance<py::str>(pair[0])) fail("the quantity must be a name such as \"speed\"");
  SweepAxis result;
  result.quantity = pair[0].cast<std::string>();
  for (char& c : result.quantity) c = c == '_' ? '-' : c;
  py::object values = pair[1];
  if (py::isinstance<py::str>(values)) fail("the values must be a sequence of numbers");
  if (!py::isinstance<py::iterable>(values)) fail("the values must be a sequence of numbers");
  ForEachBounded(values, kMaxSweepAxisValues, std::string(keyword) + " (" + result.quantity + ")",
                 [&](const py::handle value) {
    if (py::isinstance<py::str>(value)) {
      const std::string word = value.cast<std::string>();
      if (word != "fixed" && word != "flat") fail("a value is a number in SI, 'fixed' or 'flat' (not '" + word + "')");
      result.values.push_back(kFixed);
    } else if (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value) ||
               py::hasattr(value, "__float__")) {
      result.values.push_back(py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>());
    } else {
      fail("a value is a number in SI, 'fixed' or 'flat' (not " + Repr(value) + ")");
    }
  });
  return result;
}

namespace {

/// covopt.sweep(x, y, scene, threads=None): see python/covopt/__init__.py.
py::dict SweepGrid(const py::object& x, const py::object& y, const SceneInputs& inputs, const py::object& threads_) {
  SweepSpec spec;
  spec.scene = inputs.scene;
  spec.limits = inputs.limits;
  spec.safety_factor = inputs.safety_factor;
  spec.x = ReadAxis(x, "x");
  if (!y.is_none()) spec.y = ReadAxis(y, "y");
  SweepOptions options;
  if (!threads_.is_none()) {
    if (!py::isinstance<py::int_>(threads_) || threads_.cast<long long>() < 0) {
      throw std::invalid_argument("threads: expected an integer >= 0, 0 = all cores (got " + Repr(threads_) + ")");
    }
    options.threads = threads_.cast<unsigned>();
  }

  // The arrays, a[i, j] at x[i], y[j]; invalid points are NaN (numbers) or False (flags),
  // allocated only for a grid within the library's caps.
  CheckSweepSize(spec.x.values.size(), spec.y ? std::optional(spec.y->values.size()) : std::nullopt);
  const std::size_t nx = spec.x.values.size();
  const std::size_t ny = spec.y ? spec.y->values.size() : 0;
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(nx)};
  if (spec.y) shape.push_back(static_cast<py::ssize_t>(ny));
  struct Column {
    const char* name;
    double (*number)(const SweepRow&);  ///< for a float column
    bool (*flag)(const SweepRow&);      ///< for a bool column
  };
  // clang-format off
  static const Column kColumns[] = {
    {"max_penetration_m", [](const SweepRow& r) { return r.peaks.max_penetration_m; }, nullptr},
    {"peak_force_N", [](const SweepRow& r) { return r.peaks.peak_force_N; }, nullptr},
    {"contact_duration_s", [](const SweepRow& r) { return r.contact_duration_s.value_or(std::numeric_limits<double>::quiet_NaN()); }, nullptr},
    {"time_of_max_compression_s", [](const SweepRow& r) { return r.time_of_max_compression_s.value_or(std::numeric_limits<double>::quiet_NaN()); }, nullptr},
    {"max_compressive_stress_Pa", [](const SweepRow& r) { return r.peaks.max_compressive_stress_Pa; }, nullptr},
    {"max_tensile_stress_Pa", [](const SweepRow& r) { return r.peaks.max_tensile_stress_Pa; }, nullptr},
    {"max_energy_density_J_per_m2", [](const SweepRow& r) { return r.peaks.max_energy_density_J_per_m2; }, nullptr},
    {"rebound_speed_m_per_s", [](const SweepRow& r) { return r.rebound_speed_m_per_s; }, nullptr},
    {"phase_at_max", [](const SweepRow& r) { return static_cast<double>(PhaseNumber(r.peaks.phase_at_max)); }, nullptr},
    {"laceration_ratio", [](const SweepRow& r) { return r.assessment.laceration.ratio; }, nullptr},
    {"contusion_ratio", [](const SweepRow& r) { return r.assessment.contusion.ratio; }, nullptr},
    {"worst_ratio", [](const SweepRow& r) { return r.worst_ratio; }, nullptr},
    {"compression_ratio", [](const SweepRow& r) { return r.compression_ratio; }, nullptr},
    {"valid", nullptr, [](const SweepRow& r) { return r.valid; }},
    {"scalp_fully_compressed", nullptr, [](const SweepRow& r) { return r.valid && r.peaks.scalp_fully_compressed; }},
    {"fully_compressed", nullptr, [](const SweepRow& r) { return r.valid && r.peaks.fully_compressed; }},
    {"safe", nullptr, [](const SweepRow& r) { return r.valid && r.assessment.safe(); }},
    {"admissible", nullptr, [](const SweepRow& r) { return r.valid && r.admissible; }},
  };
  // clang-format on
  py::dict arrays;
  std::vector<double*> numbers;
  std::vector<bool*> flags;
  for (const Column& column : kColumns) {
    if (column.number) {
      py::array_t<double> array(shape);
      numbers.push_back(array.mutable_data());
      arrays[column.name] = array;
    } else {
      py::array_t<bool> array(shape);
      flags.push_back(array.mutable_data());
      arrays[column.name] = array;
    }
  }
  SweepResult result;
  {
    py::gil_scoped_release release;  // the consumer writes into the arrays' buffers only
    result = Sweep(spec, options, [&](std::span<const SweepRow> rows) {
      for (const SweepRow& row : rows) {
        std::size_t n = 0, f = 0;
        for (const Column& column : kColumns) {
          if (column.number) {
            numbers[n++][row.index] =
                row.valid ? column.number(row) : std::numeric_limits<double>::quiet_NaN();
          } else {
            flags[f++][row.index] = column.flag(row);
          }
        }
      }
    });
  }
  if (!result.ok()) {
    RaiseComputationError("no point of the sweep is a valid scene: " + result.message,
                          std::string(ToString(result.status)));
  }
  py::dict out;
  out["x"] = py::array_t<double>(static_cast<py::ssize_t>(nx), spec.x.values.data());
  out["x_quantity"] = spec.x.quantity;
  if (spec.y) {
    out["y"] = py::array_t<double>(static_cast<py::ssize_t>(ny), spec.y->values.data());
    out["y_quantity"] = spec.y->quantity;
  }
  for (const auto& item : arrays) out[item.first] = item.second;
  out["status"] = std::string(ToString(result.status));
  out["message"] = result.message;
  out["brief_report"] = result.BriefReport();
  return out;
}

}  // namespace

void BindSweep(py::module_& m) {
  m.def("sweep", &SweepGrid, py::arg("x"), py::arg("y"), py::arg("scene"), py::arg("threads"));
}

}  // namespace covopt::python
