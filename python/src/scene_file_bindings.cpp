/// @file scene_file_bindings.cpp
/// covopt.load_scene(path): a scene file read by the library's reader
/// (covopt/scene_file/scene_file.hpp), the one `covopt simulate --scene` uses, with the same
/// errors (ValueError with the library's "file:line:column: ..." message). It returns the
/// keywords of covopt.Scene (covopt/__init__.py makes the Scene), holding only what the file
/// sets: each scene field by its keyword (`robot_mass`, SI float, math.inf for "fixed"/"flat"),
/// `thresholds` ("cumulative" or "literal"), `head_area` ("frontal", ...), `covering_law` ("auto", "foam"
/// or "hertz"), `material` (covering.material),
/// `laceration_limit`, `contusion_limit`, `safety_factor`, and `ranges` ({"head_mass": (low,
/// high)} in SI, as the robust calls take them) when the file writes ranges.

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "covopt/core/quantity.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/core/scene_fields.hpp"
#include "covopt/scene_file/scene_file.hpp"

namespace py = pybind11;

namespace covopt::python {
namespace {

/// "robot-mass" -> "robot_mass": the Python keyword of a field's name.
std::string Keyword(std::string_view name) {
  std::string keyword(name);
  for (char& c : keyword) {
    if (c == '-') c = '_';
  }
  return keyword;
}

/// The value a keyword takes for `value` [SI]: the float, or, where a bare number is not
/// plausible for the quantity (a file may write radius = "40m"), the number with its SI unit
/// ("40.0m"), which the keyword reads back as the same double.
py::object KeywordValue(double value, const QuantitySpec& spec) {
  if (std::isinf(value)) return py::float_(value);
  try {
    CheckBareNumber(value, "", spec, "", "'");
    return py::float_(value);
  } catch (const std::invalid_argument&) {
    return py::str(py::repr(py::float_(value)).cast<std::string>() + std::string(SiUnit(spec.kind)));
  }
}

py::dict LoadScene(const std::string& path) {
  Scene scene;
  scene_file::SceneFileExtras extras;
  const std::vector<std::string> set = scene_file::ApplySceneFile(path, scene, &extras);
  py::dict keywords;
  for (const std::string& name : set) {
    if (const SceneField* field = FindSceneField(name)) {
      if (std::any_of(extras.ranges.begin(), extras.ranges.end(),
                      [&](const scene_file::SceneRange& r) { return r.field == name; })) {
        continue;  // in ranges
      }
      keywords[py::str(Keyword(field->name))] = KeywordValue(field->value(scene), field->spec);
    }
  }
  if (std::find(set.begin(), set.end(), "model.thresholds") != set.end()) {
    keywords["thresholds"] = std::string(scene_file::ThresholdsName(scene.model.thresholds));
  }
  if (std::find(set.begin(), set.end(), "head.area") != set.end()) {
    keywords["head_area"] = std::string(ToString(scene.head.area));
  }
  if (std::find(set.begin(), set.end(), "covering.law") != set.end()) {
    keywords["covering_law"] = std::string(ToString(scene.covering.law));
  }
  if (extras.covering_material) keywords["material"] = *extras.covering_material;
  if (extras.laceration_limit_Pa) keywords["laceration_limit"] = *extras.laceration_limit_Pa;
  if (extras.contusion_limit_J_per_m2) keywords["contusion_limit"] = *extras.contusion_limit_J_per_m2;
  if (extras.safety_factor) keywords["safety_factor"] = *extras.safety_factor;
  if (!extras.ranges.empty()) {
    py::dict ranges;
    for (const scene_file::SceneRange& range : extras.ranges) {
      ranges[py::str(Keyword(range.name))] = py::make_tuple(range.low, range.high);
    }
    keywords["ranges"] = ranges;
  }
  return keywords;
}

}  // namespace

void BindSceneFile(py::module_& m) {
  m.def("load_scene", &LoadScene, py::arg("path"));
}

}  // namespace covopt::python
