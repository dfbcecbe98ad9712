/// @file module.cpp
/// covopt._covopt: the pybind11 extension behind `import covopt` (python/covopt/__init__.py).
///
/// covopt.Scene holds a scene read from keywords named as the CLI's scene flags with
/// underscores. A scene value is a number in SI (math.inf for a fixed mass or a flat robot),
/// or a string read as the CLI reads a flag ("15mm", "fixed", "flat"). A number, like a bare
/// number on the command line, must be plausible for its quantity (robot_radius=40 is
/// refused: 40 m; write "40mm", or "40m" if meant). Every call takes a Scene and its own
/// options. Results are the CLI's JSON objects, built by covopt::report and loaded by
/// json.loads (covopt/_results.py makes them attribute objects), so their keys and numbers
/// are those of `covopt simulate --json` and `covopt materials ... --json`. Bad input raises
/// ValueError with the library's message; a failed computation raises
/// covopt.ComputationError (with .status). The computation runs without the GIL.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <optional>
#include <stdexcept>
#include <thread>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "covopt/optim/design_map.hpp"
#include "covopt/optim/verdicts.hpp"
#include "covopt/core/physical_floors.hpp"
#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/quantity.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/core/solve.hpp"
#include "covopt/core/sweep.hpp"
#include "covopt/core/time_integration.hpp"
#include "covopt/materials/catalog.hpp"
#include "covopt/materials/material.hpp"
#include "covopt/optim/design.hpp"
#include "covopt/optim/input_warnings.hpp"
#include "covopt/report/design_json.hpp"
#include "covopt/report/history_csv.hpp"
#include "covopt/report/materials_json.hpp"
#include "covopt/report/simulation_json.hpp"
#include "covopt/core/scene_fields.hpp"
#include "covopt/scene_file/fields.hpp"
#include "covopt/scene_file/integrators.hpp"
#include "covopt/scene_file/scene_inputs.hpp"
#include "covopt/scene_file/spelling.hpp"
#include "bounded.hpp"
#include "report_charts.hpp"
#include "scene_keywords.hpp"

namespace py = pybind11;

namespace covopt::python {
namespace {

namespace specs = covopt::quantity_specs;

/// The Scene keywords and the fields they name: the library's table of the scene inputs
/// (scene_file::SceneInputSpellings), "robot_mass" for robot.mass.
std::span<const scene_file::FieldSpelling> SceneKeywords() {
  return scene_file::SceneInputSpellings(scene_file::ValueStyle::kKeyword);
}


std::string Repr(const py::handle& value) { return py::repr(value).cast<std::string>(); }

/// A number as a person would type it: 40.0 as "40", 0.25 as "0.25".
std::string AsTyped(const py::handle& number) {
  if (py::isinstance<py::float_>(number)) {
    const double value = number.cast<double>();
    if (value == std::floor(value) && std::abs(value) < 1e15) {
      return std::to_string(static_cast<long long>(value));
    }
  }
  return py::str(number).cast<std::string>();
}

}  // namespace

namespace {

/// A Python number as SI, `keyword` named in messages: not a bool, within a double, finite
/// (or math.inf where the spec allows "fixed" or "flat"). Not checked for plausibility.
double NumberOf(const py::handle& value, const QuantitySpec& spec, std::string_view keyword) {
  if (py::isinstance<py::bool_>(value) ||
      !(py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value))) {
    throw std::invalid_argument(std::string(keyword) + ": expected a number in SI (" +
                                std::string(SiUnit(spec.kind)) + ") or a string with a unit (got " +
                                Repr(value) + ")");
  }
  // An int beyond a double (10**400) is no number the model takes: pybind11's cast would
  // fail with "Unable to cast"; Python's float() raises OverflowError.
  double number = 0.0;
  try {
    number = py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>();
  } catch (const py::error_already_set&) {
    const std::string typed = AsTyped(value);
    throw std::invalid_argument(std::string(keyword) + ": " +
                                (typed.size() > 40 ? typed.substr(0, 20) + "... (" + std::to_string(typed.size()) +
                                                         " digits)"
                                                   : typed) +
                                " is beyond a double; expected a number in SI (" + std::string(SiUnit(spec.kind)) +
                                ")");
  }
  if (std::isinf(number) && number > 0 && (spec.allow_fixed || spec.allow_flat)) return number;
  if (!std::isfinite(number)) {
    throw std::invalid_argument(
        std::string(keyword) + " must be finite" +
        (spec.allow_fixed ? " (or math.inf / 'fixed' for a fixed body)"
         : spec.allow_flat ? " (or math.inf / 'flat' for a flat surface)"
                           : "") +
        " (got " + Repr(value) + ")");
  }
  return number;
}

}  // namespace

double ReadSceneQuantity(const py::handle& value, const QuantitySpec& spec, std::string_view keyword) {
  if (py::isinstance<py::str>(value)) {
    return ParseQuantity(value.cast<std::string>(), spec, keyword);
  }
  const double number = NumberOf(value, spec, keyword);
  // A number has no unit, as a bare number on the command line: an implausible one is the
  // classic slip (robot_radius=40 meant in mm) and refused with the spellings to use.
  CheckBareNumber(number, AsTyped(value), spec, keyword, "'");
  return number;
}

std::optional<py::object> Option(const py::dict& kwargs, const char* name) {
  if (!kwargs.contains(name)) return std::nullopt;
  py::object value = kwargs[name];
  if (value.is_none()) return std::nullopt;
  return value;
}

bool Bool(const py::handle& value, const char* name) {
  if (py::isinstance<py::bool_>(value)) return value.cast<bool>();
  // numpy's bool (np.True_, a 0-d boolean array) is a bool too; "yes", 1 or a list are not.
  if (py::hasattr(value, "dtype") && py::hasattr(value, "ndim") && value.attr("ndim").cast<int>() == 0 &&
      py::str(value.attr("dtype").attr("kind")).cast<std::string>() == "b") {
    return PyObject_IsTrue(value.ptr()) == 1;
  }
  std::string shown = py::repr(value).cast<std::string>();
  if (shown.size() > 40) {
    shown.resize(40);
    shown += "...";  // appended: GCC 12's LTO warns on substr(...) + "..." (robot_bindings.cpp)
  }
  throw std::invalid_argument(std::string(name) + ": expected True or False (got " + shown + ")");
}

bool Flag(const py::dict& kwargs, const char* name) {
  const auto value = Option(kwargs, name);
  return value && Bool(*value, name);
}

namespace {

const materials::Catalog& BuiltInCatalog() { return materials::Catalog::BuiltIn(); }

const materials::Material& FindMaterial(std::string_view name) {
  const materials::Material* m = BuiltInCatalog().Find(name);
  if (m == nullptr) throw std::invalid_argument(BuiltInCatalog().MissingMaterialMessage(name));
  return *m;
}

/// Raises covopt.ComputationError for a failed impact computation.
[[noreturn]] void RaiseImpactFailure(const ImpactResult& result) {
  RaiseComputationError("the computation failed: " + std::string(ToString(result.status)) + " (" +
                            std::string(ToString(result.method)) + ", code " + std::to_string(result.raw_code) +
                            ")" + (result.message.empty() ? "" : ": " + result.message),
                        std::string(ToString(result.status)));
}

/// max_steps=: an int (not a bool) >= 10.
long ReadMaxSteps(const py::handle& value) {
  if (!py::isinstance<py::int_>(value) || py::isinstance<py::bool_>(value)) {
    throw std::invalid_argument("max_steps: expected an integer (got " + Repr(value) + ")");
  }
  const long steps = value.cast<long>();
  if (steps < 10) throw std::invalid_argument("max_steps must be >= 10 (got " + std::to_string(steps) + ")");
  return steps;
}

/// The quantity a field holds; nullptr for a word (the material, the thresholds).
const QuantitySpec* SpecOf(std::string_view field) {
  if (const SceneField* scene_field = FindSceneField(field)) return &scene_field->spec;
  for (const scene_file::LimitField& limit : scene_file::LimitFields()) {
    if (limit.dotted_name() == field) return &limit.spec;
  }
  return nullptr;
}

}  // namespace

std::string_view FieldOfKeyword(std::string_view keyword) {
  for (const scene_file::FieldSpelling& k : SceneKeywords()) {
    if (k.name == keyword) return k.field;
  }
  return {};
}

std::string SolveKeywords(std::string message) {
  for (const auto& [field, keyword] : {std::pair{"time_path.relative_tolerance", "rtol"},
                                       {"time_path.absolute_tolerance", "atol"}, {"time_path.max_steps", "max_steps"}}) {
    if (message.rfind(field, 0) == 0) message = keyword + message.substr(std::string_view(field).size());
  }
  return message;
}

SceneInputs ReadScene(const py::kwargs& keywords) {
  SceneInputs inputs;
  for (const auto& item : keywords) {
    const std::string name = py::str(item.first).cast<std::string>();
    if (FieldOfKeyword(name).empty() && name != "ranges") {
      throw py::type_error("Scene() got an unexpected keyword argument '" + name + "'");
    }
    if (py::isinstance<py::str>(item.second) && item.second.cast<std::string>().find("..") != std::string::npos) {
      throw std::invalid_argument(name + "=" + Repr(item.second) + ": a range LO..HI describes a population, not "
                                  "one scene; give ranges={'" + name + "': " + Repr(item.second) +
                                  "} to covopt.worst_case, injury_probability or robust_optimize");
    }
    if (!item.second.is_none()) inputs.given[item.first] = item.second;
  }
  // The library's one resolution (scene_file::ApplySceneInputs), in the table's order; a
  // number is read here (Python's types), a string there with its unit.
  std::vector<scene_file::SceneInput> values;
  for (const scene_file::FieldSpelling& k : SceneKeywords()) {
    const auto value = Option(inputs.given, std::string(k.name).c_str());
    if (!value) continue;
    const QuantitySpec* spec = SpecOf(k.field);
    if (spec != nullptr && !py::isinstance<py::str>(*value)) {
      values.push_back({std::string(k.field), NumberOf(*value, *spec, k.name), AsTyped(*value)});
    } else {
      values.push_back({std::string(k.field), py::str(*value).cast<std::string>(), ""});
    }
  }
  scene_file::ResolvedScene resolved;
  try {
    scene_file::ApplySceneInputs(values, BuiltInCatalog(), resolved, "'");
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(scene_file::Respell(e.what(), SceneKeywords(), scene_file::ValueStyle::kKeyword));
  }
  inputs.scene = resolved.scene;
  inputs.limits = resolved.limits;
  inputs.safety_factor = resolved.safety_factor;
  if (const materials::Material* m = resolved.covering_material) {
    inputs.covering_material = m->name;
    inputs.covering_poisson_assumed = !m->poisson_ratio.has_value();
  }
  return inputs;
}

SceneInputs SceneInputs::With(const py::dict& changes) const {
  py::kwargs merged;
  for (const auto& item : given) merged[item.first] = item.second;
  for (const auto& item : changes) merged[item.first] = item.second;
  return ReadScene(merged);
}

std::string SceneInputs::Attributed(const std::string& message) const {
  std::string origins;
  for (const scene_file::FieldSpelling& k : SceneKeywords()) {
    const std::string keyword(k.name);
    if (FindSceneField(k.field) != nullptr && Gave(keyword.c_str()) && message.find(k.field) != std::string::npos) {
      origins += std::string(origins.empty() ? "" : "; ") + std::string(k.field) + " is " + keyword + "=" +
                 Repr(given[keyword.c_str()]);
    }
  }
  return origins.empty() ? message : message + " (" + origins + ")";
}

optim::CoveringCrushCheck SceneInputs::CrushCheck() const {
  bool covering_given = false;
  for (const char* keyword : {"covering_thickness", "covering_modulus", "covering_poisson", "material"}) {
    covering_given = covering_given || Gave(keyword);
  }
  const materials::Material* material = covering_material ? BuiltInCatalog().Find(*covering_material) : nullptr;
  return optim::CrushCheckFor(scene, material, covering_given);
}

void SceneInputs::Judge(report::SimulationReport& report, bool keep_travel) const {
  report.verdict =
      optim::SimulationVerdict(report.scene, report.result.peaks, limits, safety_factor, CrushCheck(), false, keep_travel);
}

/// The warnings `covopt simulate` adds about its inputs (optim::SceneInputWarnings, as the
/// CLI's): where the CLI names a flag or scene file as the source, these name the keyword,
/// "(from safety_factor=2)".
std::vector<std::string> InputWarnings(const SceneInputs& inputs) {
  const auto source_of = [&inputs](std::string_view field) -> std::optional<std::string> {
    const char* keyword = field == "limits.safety_factor" ? "safety_factor"
                          : field == "covering.material"  ? "material"
                          : field == "covering.modulus"   ? "covering_modulus"
                          : field == "covering.poisson"   ? "covering_poisson"
                          : field == "covering.thickness" ? "covering_thickness"
                                                          : nullptr;
    if (keyword == nullptr || !inputs.Gave(keyword)) return std::nullopt;
    return std::string(keyword) + "=" + Repr(inputs.given[keyword]);
  };
  const materials::Material* material =
      inputs.covering_material ? BuiltInCatalog().Find(*inputs.covering_material) : nullptr;
  return optim::SceneInputWarnings(inputs.scene, inputs.limits, inputs.safety_factor, material, source_of);
}

std::vector<std::string> InputAndCrushWarnings(const SceneInputs& inputs) {
  std::vector<std::string> warnings = InputWarnings(inputs);
  optim::AppendNewWarnings(warnings, inputs.CrushCheck().notes);
  return warnings;
}

namespace {

/// simulate's method=, rtol=, atol=, max_steps=, history= as Solve's options: the path
/// auto (the exact path where the scene has an energy integral and no history is asked for),
/// exact, or the time path with a named integrator.
SolveOptions ReadSolveOptions(const py::dict& kwargs, const Scene& scene) {
  const auto get = [&](const char* name) { return Option(kwargs, name); };
  SolveOptions options;
  options.record_history = Flag(kwargs, "history");
  if (const auto v = get("method")) {
    const std::string method = py::str(*v).cast<std::string>();
    if (method == "exact") {
      if (!scene.has_energy_integral()) {
        throw std::invalid_argument("method='exact': the exact path needs an energy integral; a scene with "
                                    "braking or a neck has only the time path; drop method (the default "
                                    "integrator runs then) or give a time-path method");
      }
      if (options.record_history) {
        throw std::invalid_argument("method='exact' computes no time history, which history=True "
                                    "needs; drop method (the default integrator runs then) or "
                                    "give a time-path method");
      }
      options.path = PathChoice::kExact;
    } else if (const auto named = scene_file::ParseIntegrator(method)) {
      options.path = PathChoice::kTimePath;
      options.time_path.method = *named;
    } else {
      throw std::invalid_argument("method: expected exact, cvode or one of " + scene_file::IntegratorNames() +
                                  " (got '" + method + "')");
    }
  }
  const bool time_path = ChoosePath(scene, options) == PathChoice::kTimePath;
  for (const char* k : {"rtol", "atol", "max_steps"}) {
    if (get(k) && !time_path) {
      throw std::invalid_argument(std::string(k) +
                                  " applies to the time path only; give method='cvode' or "
                                  "another integrator, or history=True");
    }
  }
  TimeIntegrationOptions& time = options.time_path;
  if (const auto v = get("rtol")) time.relative_tolerance = ReadSceneQuantity(*v, specs::kTolerance, "rtol");
  if (const auto v = get("atol")) {
    time.absolute_tolerance = ReadSceneQuantity(*v, specs::kTolerance, "atol");
    if (!(time.absolute_tolerance > 0.0)) {
      throw std::invalid_argument("atol must be > 0 (got " + Repr(*v) + ")");
    }
  }
  if (const auto v = get("max_steps")) time.max_steps = ReadMaxSteps(*v);
  return options;
}

/// The columns of `--history` as numpy arrays (the extended ones beyond the two-mass model).
py::dict HistoryColumns(const std::vector<HistorySample>& h, const ImpactModel& model) {
  py::dict columns;
  for (const report::HistoryColumn& c : report::ImpactHistoryColumns(model, h)) {
    columns[py::str(std::string(c.name))] = py::array_t<double>(static_cast<py::ssize_t>(c.values.size()), c.values.data());
  }
  return columns;
}

/// covopt.simulate(scene, method=, rtol=, atol=, max_steps=, history=): see covopt/__init__.py.
py::dict Simulate(const SceneInputs& inputs, const py::kwargs& kwargs) {
  const SolveOptions options = ReadSolveOptions(kwargs, inputs.scene);
  report::SimulationReport report;
  report.scene = inputs.scene;
  report.covering_material = inputs.covering_material;
  report.covering_poisson_assumed = inputs.covering_poisson_assumed;
  if (ChoosePath(inputs.scene, options) == PathChoice::kTimePath) report.time_options = options.time_path;
  std::optional<ImpactModel> model;
  try {
    model.emplace(ImpactModel::FromScene(report.scene));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(inputs.Attributed(e.what()));
  }
  try {
    py::gil_scoped_release release;
    report.result = Solve(*model, options);
  } catch (const std::invalid_argument& e) {  // an option out of range, named as the keyword
    throw std::invalid_argument(SolveKeywords(e.what()));
  }
  if (!report.result.ok()) RaiseImpactFailure(report.result);
  inputs.Judge(report, Flag(kwargs, "keep_travel"));
  report.input_warnings = InputWarnings(inputs);
  py::dict result = JsonToPython(report::SimulationJson(report, -1));
  if (options.record_history) result["history"] = HistoryColumns(report.result.history, *model);
  return WithReportCharts(std::move(result), [report] { return chart::SimulationCharts(report); });
}

/// A list of strings from a str or a sequence of them.
std::vector<std::string> ReadNames(const py::handle& value, const char* keyword) {
  std::vector<std::string> names;
  if (py::isinstance<py::str>(value)) return {value.cast<std::string>()};
  if (py::isinstance<py::iterable>(value)) {
    for (const py::handle item : value) {
      if (!py::isinstance<py::str>(item)) break;
      names.push_back(item.cast<std::string>());
    }
    if (names.size() == py::len(value)) return names;
  }
  throw std::invalid_argument(std::string(keyword) + ": expected a name or a list of names (got " +
                              Repr(value) + ")");
}

}  // namespace

/// oracle=, method=, rtol=, max_steps= as optimize() and speed_limit() take them (scene_keywords.hpp).
optim::OracleOptions ReadOracleKeywords(const py::kwargs& kwargs, const Scene& scene) {
  const auto get = [&](const char* name) { return Option(kwargs, name); };
  optim::OracleOptions oracle;
  if (const auto v = get("oracle")) {
    const std::string name = py::str(*v).cast<std::string>();
    const auto choice = optim::ParseOracleChoice(name);
    if (!choice) throw std::invalid_argument("oracle: expected 'auto', 'exact' or 'time-path' (got '" + name + "')");
    oracle.choice = *choice;
  }
  bool method_exact = false;
  if (const auto v = get("method")) {
    const std::string method = py::str(*v).cast<std::string>();
    if (method == "exact") {
      method_exact = true;
    } else if (const auto named = scene_file::ParseIntegrator(method)) {
      oracle.time_path.method = *named;
    } else {
      throw std::invalid_argument("method: expected exact, cvode or one of " + scene_file::IntegratorNames() +
                                  " (got '" + method + "')");
    }
  }
  if (method_exact) {
    if (oracle.choice == optim::OracleChoice::kTimePath) {
      throw std::invalid_argument("method='exact' contradicts oracle='time-path': the time path runs an integrator");
    }
    oracle.choice = optim::OracleChoice::kExact;
  }
  if (const auto v = get("rtol")) {
    if (oracle.choice == optim::OracleChoice::kExact) {
      throw std::invalid_argument("rtol applies to the time path; oracle='exact' runs none");
    }
    oracle.time_path.relative_tolerance = ReadSceneQuantity(*v, specs::kTolerance, "rtol");
    if (!(oracle.time_path.relative_tolerance >= 1e-14 && oracle.time_path.relative_tolerance <= 1e-2)) {
      throw std::invalid_argument("rtol must be in [1e-14, 1e-2] (got " + Repr(*v) + ")");
    }
  }
  if (oracle.choice == optim::OracleChoice::kExact && get("method") && !method_exact) {
    throw std::invalid_argument("method applies to the time path; oracle='exact' runs none");
  }
  if (const auto v = get("max_steps")) {
    if (oracle.choice == optim::OracleChoice::kExact) {
      throw std::invalid_argument("max_steps applies to the time path; oracle='exact' runs none");
    }
    oracle.time_path.max_steps = ReadMaxSteps(*v);
  }
  (void)optim::ChooseOracle(scene, oracle.choice);  // oracle='exact' on a braking/neck scene: its message
  return oracle;
}

std::vector<optim::CandidateMaterial> Candidates(const py::kwargs& kwargs) {
  const auto get = [&](const char* name) { return Option(kwargs, name); };
  const std::vector<std::string> files = get("catalog") ? ReadNames(*get("catalog"), "catalog") : std::vector<std::string>{};
  const materials::Catalog catalog = LoadCatalogFiles(files, Flag(kwargs, "no_builtin"));
  const std::vector<std::string> names = get("materials") ? ReadNames(*get("materials"), "materials") : std::vector<std::string>{};
  const std::vector<std::string> families = get("families") ? ReadNames(*get("families"), "families") : std::vector<std::string>{};
  try {
    return optim::SelectCandidates(catalog, names, families);
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    throw std::invalid_argument((what.rfind("no family", 0) == 0 ? "families: " : "materials: ") + what);
  }
}

namespace {

/// covopt.optimize(**scene, ...): see python/covopt/__init__.py.
py::dict Optimize(const SceneInputs& inputs, const py::kwargs& kwargs) {
  const auto get = [&](const char* name) { return Option(kwargs, name); };
  for (const char* k : {"covering_modulus", "covering_thickness", "material"}) {
    if (inputs.Gave(k)) {
      throw std::invalid_argument(std::string(k) +
                                  ": the covering is what optimize designs; give thickness= for the "
                                  "least injury at a thickness, materials= to choose candidates");
    }
  }
  if (inputs.Gave("covering_poisson")) {
    throw std::invalid_argument("covering_poisson: the covering is what optimize designs; give "
                                "optimize(covering_poisson=...) for the continuous design's");
  }
  optim::DesignRequest request;
  request.scene = inputs.scene;
  optim::DesignOptions& d = request.options;
  d.covering_law = inputs.scene.covering.law;  // auto: the foam law where a material has a curve
  request.scene.covering.law = CoveringLaw::kAuto;  // the design's law, not the designed covering's
  d.limits = inputs.limits;
  d.safety_factor = inputs.safety_factor;
  const auto read = [&](const char* keyword, const QuantitySpec& spec, double& into) {
    if (const auto v = get(keyword)) into = ReadSceneQuantity(*v, spec, keyword);
  };
  read("max_thickness", specs::kCoveringThickness, d.space.max_thickness_m);
  read("min_modulus", specs::kCoveringModulus, d.space.min_modulus_Pa);
  read("max_modulus", specs::kCoveringModulus, d.space.max_modulus_Pa);
  read("covering_poisson", specs::kPoissonRatio, d.covering_poisson_ratio);
  read("thickness_step", specs::kThicknessStep, d.thickness_step_m);
  const auto require = [](bool ok, const std::string& message) {
    if (!ok) throw std::invalid_argument(message);
  };
  const auto shown = [&](const char* keyword) { return get(keyword) ? Repr(*get(keyword)) : std::string(); };
  require(d.space.max_thickness_m > d.space.min_thickness_m && d.space.max_thickness_m <= 1.0,
          "max_thickness must be in (0.1 mm, 1 m] (got " + shown("max_thickness") + ")");
  require(d.space.min_modulus_Pa >= kMinModulus_Pa && d.space.max_modulus_Pa > d.space.min_modulus_Pa &&
              d.space.max_modulus_Pa <= 1e13,
          "min_modulus/max_modulus must satisfy 1000 <= min < max <= 1e13 Pa (got " +
              std::to_string(d.space.min_modulus_Pa) + " Pa, " + std::to_string(d.space.max_modulus_Pa) + " Pa)");
  require(d.covering_poisson_ratio > -1.0 && d.covering_poisson_ratio <= 0.5,
          "covering_poisson must be in (-1, 0.5] (got " + shown("covering_poisson") + ")");
  require(d.thickness_step_m >= 0.0 && d.thickness_step_m <= 0.01,
          "thickness_step must be in [0, 10 mm] (got " + shown("thickness_step") + ")");
  if (const auto v = get("thickness")) {
    request.thickness_m = ReadSceneQuantity(*v, specs::kCoveringThickness, "thickness");
    require(*request.thickness_m >= kMinLayerThickness_m && *request.thickness_m <= 1.0,
            "thickness must be in [0.1 mm, 1 m] (got " + Repr(*v) + "); for no covering use "
            "simulate(covering_thickness=0)");
  }
  d.allow_full_compression = Flag(kwargs, "allow_full_compression");
  d.allow_crushing = Flag(kwargs, "allow_crushing");
  d.allow_unknown_strength = Flag(kwargs, "allow_unknown_strength");
  if (const auto v = get("global_algorithm")) {
    const std::string g = py::str(*v).cast<std::string>();
    if (g == "direct-l") d.global_algorithm = optim::NloptAlgorithm::kDirectL;
    else if (g == "isres") d.global_algorithm = optim::NloptAlgorithm::kIsres;
    else if (g == "mlsl") d.global_algorithm = optim::NloptAlgorithm::kMlsl;
    else throw std::invalid_argument("global_algorithm: expected direct-l, isres or mlsl (got '" + g + "')");
  }
  const auto whole = [&](const char* keyword, long long low, long long high) {
    const py::object v = *get(keyword);
    if (!py::isinstance<py::int_>(v) || py::isinstance<py::bool_>(v) || v.cast<long double>() < low ||
        v.cast<long double>() > high) {
      throw std::invalid_argument(std::string(keyword) + " must be a whole number in [" +
                                  std::to_string(low) + ", " + std::to_string(high) + "] (got " + Repr(v) + ")");
    }
    return v.cast<long long>();
  };
  if (get("seed")) d.seed = static_cast<unsigned long>(whole("seed", 0, std::numeric_limits<long long>::max()));
  if (get("threads")) {  // 0 = every core, as sweep and the sampling take it
    const long long threads = whole("threads", 0, 256);
    d.threads = threads == 0 ? static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 256u))
                             : static_cast<int>(threads);
  }
  d.oracle = ReadOracleKeywords(kwargs, request.scene);

  request.materials = Candidates(kwargs);
  if (!get("materials")) optim::KeepCandidatesForLaw(request.materials, d.covering_law);
  (void)optim::KeepCandidatesTheSceneModels(request.materials, d.covering_law, request.scene);  // as the CLI

  optim::DesignResult result;
  {
    py::gil_scoped_release release;
    result = optim::Design(request);  // throws invalid_argument naming the field
  }
  if (!result.ok()) RaiseComputationError(result.message, std::string(optim::ToString(result.status)));
  return WithReportCharts(JsonToPython(report::DesignJson(request, result, {}, -1)), [request, result] {
    return std::vector{chart::DesignMapChart(optim::ComputeDesignMap(request, result))};
  });
}

py::list Materials() {
  std::vector<const materials::Material*> rows;
  for (const materials::Material& m : BuiltInCatalog().materials()) rows.push_back(&m);
  return JsonToPython(report::MaterialsJson(rows, -1));
}

py::dict Material(const std::string& name) {
  return JsonToPython(report::MaterialJson(FindMaterial(name), -1));
}

}  // namespace

py::object JsonToPython(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

void RaiseComputationError(const std::string& message, const std::string& status) {
  py::object error_type = py::module_::import("covopt._errors").attr("ComputationError");
  py::object error = error_type(message, status);
  PyErr_SetObject(error_type.ptr(), error.ptr());
  throw py::error_already_set();
}

namespace {

/// covopt.Scene: read-only attributes from the keyword table, replace(), to_dict(), repr.
void BindScene(py::module_& m) {
  py::class_<SceneInputs> scene(m, "Scene", R"(An impact scene, its injury limits and safety factor (SI).

Scene(**keywords): the keywords are the CLI's scene flags with underscores (--robot-mass is
robot_mass); unset values are the paper's scene. A value is an SI number or a string with a
unit ("15mm", "27.6MPa"); math.inf or "fixed" is an immovable body (robot_mass, head_mass,
torso_mass), math.inf or "flat" a flat robot (robot_radius). A bare number must be plausible
for its quantity: robot_radius=40 (40 m) is refused; write "40mm", or "40m" if meant.
Keywords: robot_mass [kg], speed [m/s], robot_radius [m], robot_modulus [Pa], robot_poisson,
covering_modulus [Pa], covering_poisson, covering_thickness [m] (0 = no covering), head_mass
[kg], head_radius [m], scalp_modulus [Pa], scalp_poisson, scalp_thickness [m], skull_modulus
[Pa], skull_poisson; beyond the conservative two-mass model (docs/model.md section 10; 0 = off):
damping [s/m] (Hunt-Crossley), reaction_delay [s] and braking [m/s2] (the robot brakes that long
after first contact), torso_mass [kg], neck_stiffness [N/m], neck_damping [N s/m] (the head on a
neck). material: a built-in catalog name (sets covering_modulus and covering_poisson);
thresholds: "cumulative" (default) or "literal"; head_area: the struck area ("frontal", ...);
covering_law: "auto" (default; today the Hertz law in every call), "foam" (a material's measured
compressive curve, simulate and speed limits; optimize not yet) or "hertz"; laceration_limit [Pa] (1e6), contusion_limit
[J/m2] (25200); safety_factor in [1, 100]: a verdict is safe when safety_factor x ratio <= 1.
Bad values raise ValueError naming the keyword; an unknown keyword TypeError.
ranges: {keyword: (low, high) or "LO..HI"}, a population for worst_case, injury_probability and
robust_optimize. Attributes: every keyword, in SI. replace(**keywords): a changed copy (None unsets).
to_dict(): the scene object of `covopt simulate --json`.)");
  scene.def(py::init(&ReadScene));
  for (const SceneField& field : SceneFields()) {
    std::string keyword(field.name);
    std::replace(keyword.begin(), keyword.end(), '-', '_');
    const std::string doc = field.dotted_name() + " [" + std::string(SiUnit(field.spec.kind)) + "]";
    const SceneField* f = &field;  // the library's table lives as long as the program
    scene.def_property_readonly(
        keyword.c_str(), [f](const SceneInputs& s) { return f->value(s.scene); }, doc.c_str());
  }
  scene.def_property_readonly("material", [](const SceneInputs& s) { return s.covering_material; })
      .def_property_readonly("thresholds", [](const SceneInputs& s) {
        return s.scene.model.thresholds == ThresholdReading::kLiteral ? "literal" : "cumulative";
      })
      .def_property_readonly("head_area", [](const SceneInputs& s) { return std::string(ToString(s.scene.head.area)); })
      .def_property_readonly("covering_law", [](const SceneInputs& s) { return std::string(ToString(s.scene.covering.law)); })
      .def_property_readonly("laceration_limit", [](const SceneInputs& s) { return s.limits.laceration_tensile_stress_Pa; })
      .def_property_readonly("contusion_limit", [](const SceneInputs& s) { return s.limits.contusion_energy_density_J_per_m2; })
      .def_property_readonly("safety_factor", [](const SceneInputs& s) { return s.safety_factor; })
      .def_property_readonly("ranges", [](const SceneInputs& s) { return Option(s.given, "ranges").value_or(py::dict()); })
      .def("replace", [](const SceneInputs& s, const py::kwargs& changes) { return s.With(changes); })
      // Pickled as its keywords (covopt.audit_many sends scenes to dask workers).
      .def(py::pickle([](const SceneInputs& s) { return py::dict(s.given); },
                      [](const py::dict& given) { return ReadScene(py::reinterpret_borrow<py::kwargs>(given)); }))
      .def("to_dict", [](const SceneInputs& s) { return JsonToPython(report::SceneJson(s.scene, -1)); })
      .def("__repr__", [](const SceneInputs& s) {
        std::string text;
        for (const auto& item : s.given) {
          if (!text.empty()) text += ", ";  // appended: GCC 12's LTO warns on "literal" + std::string
          text += py::str(item.first).cast<std::string>();
          text += "=";
          text += Repr(item.second);
        }
        return "Scene(" + text + ")";
      });
}

}  // namespace

void BindSpeedLimit(py::module_& m);  // speed_limit_bindings.cpp
void BindRobot(py::module_& m);       // robot_bindings.cpp
void BindTrajectory(py::module_& m);  // trajectory_bindings.cpp
void BindRobust(py::module_& m);      // robust_bindings.cpp
void BindSceneFile(py::module_& m);   // scene_file_bindings.cpp
void RegisterBodyRegions(py::module_& m);  // body_regions.cpp
void RegisterBodyContact(py::module_& m);  // body_contact.cpp
void BindAudit(py::module_& m);            // audit_bindings.cpp
void BindReport(py::module_& m);           // report_bindings.cpp
void BindSweep(py::module_& m);            // sweep_bindings.cpp
void BindCatalog(py::module_& m);          // catalog_bindings.cpp
void BindMeasure(py::module_& m);          // measure_bindings.cpp
}  // namespace covopt::python

PYBIND11_MODULE(_covopt, m) {
  m.doc() = "covopt's C++ library (use the covopt package, which documents it)";
  // std::invalid_argument becomes ValueError.
  covopt::python::BindScene(m);
  m.def("simulate", &covopt::python::Simulate);
  m.def("optimize", &covopt::python::Optimize);
  m.def("materials", &covopt::python::Materials);
  m.def("material", &covopt::python::Material, py::arg("name"));
  covopt::python::BindCatalog(m);
  covopt::python::BindMeasure(m);
  covopt::python::BindSpeedLimit(m);
  covopt::python::BindRobot(m);
  covopt::python::BindTrajectory(m);
  covopt::python::BindRobust(m);
  covopt::python::BindSceneFile(m);
  covopt::python::RegisterBodyRegions(m);
  covopt::python::RegisterBodyContact(m);
  covopt::python::BindAudit(m);
  covopt::python::BindReport(m);
  covopt::python::BindSweep(m);
}
