/// @file measure_bindings.cpp
/// covopt.predict_measurement (python/covopt/__init__.py documents it): what a biofidelic
/// force-measuring device reads beside the body model, as `covopt measure --json`
/// (optim/measurement.hpp). The robot and covering come from the covopt.Scene, the region from
/// body_region (as covopt.simulate), the device from device, or device_spring with device_pad,
/// or the region's own pair.

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "body_region_inputs.hpp"
#include "covopt/core/measuring_device.hpp"
#include "covopt/optim/measurement.hpp"
#include "covopt/report/measurement_json.hpp"
#include "scene_keywords.hpp"

namespace py = pybind11;

namespace covopt::python {
namespace {

/// A keyword given as text, or as a number written out (device_pad=70 is "70").
std::optional<std::string> Text(const py::kwargs& kwargs, const char* name) {
  const auto v = Option(kwargs, name);
  if (!v) return std::nullopt;
  if (py::isinstance<py::str>(*v)) return v->cast<std::string>();
  if (py::isinstance<py::int_>(*v) || py::isinstance<py::float_>(*v)) return py::str(*v).cast<std::string>();
  throw std::invalid_argument(std::string(name) + ": expected text (got " + py::repr(*v).cast<std::string>() + ")");
}

py::object PredictMeasurement(const SceneInputs& inputs, const py::kwargs& kwargs) {
  const OneRegionContact c = ReadOneRegionContact(inputs, kwargs, "predict_measurement");
  DeviceChoice choice{.preset = Text(kwargs, "device"), .spring_N_per_m = std::nullopt, .pad = Text(kwargs, "device_pad"),
                      .pad_thickness_m = std::nullopt};
  if (const auto v = Option(kwargs, "device_spring")) {
    choice.spring_N_per_m = ReadSceneQuantity(*v, kDeviceSpringSpec, "device_spring");
  }
  if (const auto v = Option(kwargs, "device_pad_thickness")) {
    choice.pad_thickness_m = ReadSceneQuantity(*v, kPadThicknessSpec, "device_pad_thickness");
  }
  const MeasuringDevice device = ResolveDevice(choice, c.limits.region->name);
  optim::MeasurementPrediction prediction;
  try {
    py::gil_scoped_release release;
    prediction = optim::PredictMeasurement(c.scene, c.limits, device, c.judge);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(inputs.Attributed(e.what()));
  }
  std::vector<std::string> warnings = c.warnings;
  warnings.insert(warnings.end(), prediction.warnings.begin(), prediction.warnings.end());
  return JsonToPython(report::MeasurementJson(c.scene, c.material, prediction, inputs.safety_factor, warnings));
}

}  // namespace

void BindMeasure(py::module_& m) { m.def("predict_measurement", &PredictMeasurement); }

}  // namespace covopt::python
