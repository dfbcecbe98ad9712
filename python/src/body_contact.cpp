/// @file body_contact.cpp
/// The ISO/TS 15066 body regions in Python (docs/model.md §13): covopt.simulate,
/// covopt.speed_limit and covopt.optimize with body_region= (python/covopt/_body_regions.py
/// documents them), over core's BodyContactScene/Solve, materials' BodyRegionTable and
/// optim's JudgeBodyContact, MaxSafeSpeed, BodyRegionSpeedLimitTable and DesignForBodyRegions.
///
/// The robot and its covering come from a covopt.Scene (robot_mass, speed, robot_radius, the
/// covering keywords or material, safety_factor, reaction_delay and braking); the region from
/// the keywords body_region, body_area, contact and contact_area, named as the CLI's
/// --body-region, --body-area, --contact and --contact-area. A scene keyword the body-region
/// model does not read (the head's, the skull's, damping, the robot's modulus) is refused,
/// never ignored. A braking robot is judged on the time path (docs/model.md §13.10).
/// The dicts are built here; their keys carry their units. Bad input raises ValueError with
/// the library's one-line message (flags named as keywords).

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "covopt/chart/region_charts.hpp"
#include "covopt/core/body_contact.hpp"
#include "covopt/core/physical_floors.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/quantity.hpp"
#include "covopt/core/solve.hpp"
#include "covopt/materials/body_regions.hpp"
#include "covopt/materials/catalog.hpp"
#include "covopt/optim/body_region_check.hpp"
#include "covopt/optim/body_region_sweep.hpp"
#include "covopt/optim/body_region_trajectory.hpp"
#include "covopt/optim/design.hpp"
#include "covopt/optim/speed_limit.hpp"
#include "covopt/optim/target_speed_limits.hpp"
#include "covopt/optim/trajectory_check.hpp"
#include "covopt/report/body_contact_json.hpp"
#include "covopt/report/body_region_sweep_output.hpp"
#include "covopt/robot/trajectory.hpp"
#include "covopt/scene_file/integrators.hpp"
#include "covopt/scene_file/scene_inputs.hpp"
#include "covopt/scene_file/spelling.hpp"
#include "covopt/scene_file/targets.hpp"
#include "body_region_inputs.hpp"
#include "report_charts.hpp"
#include "robot_inputs.hpp"
#include "scene_keywords.hpp"

namespace py = pybind11;

namespace covopt::python {
namespace {

using materials::BodyLimits;
using materials::BodyRegionTable;

std::string Repr(const py::handle& value) { return py::repr(value).cast<std::string>(); }

}  // namespace

std::string AsKeywords(std::string_view message) {
  static constexpr scene_file::FieldSpelling kKeywords[] = {
      {"body.region", "body_region"},
      {"body.area", "body_area"},
      {"body.contact", "contact"},
      {"body.contact_area", "contact_area"},
      {"body.limits", "limits"},
      {"head.mass", "head_mass"},  // "give head.mass=fixed" for a head held still
  };
  return scene_file::Respell(message, kKeywords, scene_file::ValueStyle::kKeyword);
}

namespace {

/// Runs `f`, re-raising the library's std::invalid_argument with keywords for flags.
template <typename F>
auto Keyworded(F&& f) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(AsKeywords(e.what()));
  }
}


/// body_region as given, for messages: "chest", "['chest', 'face']".
std::string RegionText(const py::kwargs& kwargs) {
  const py::object value = kwargs["body_region"];
  return py::isinstance<py::str>(value) ? value.cast<std::string>() : Repr(value);
}

/// Refuses the scene keywords the body-region model does not read (`region`: body_region).
void RefuseHeadKeywords(const SceneInputs& inputs, const std::string& region) {
  for (const auto& item : inputs.given) {
    const std::string keyword = py::str(item.first).cast<std::string>();
    if (keyword != "ranges" && !scene_file::BodyRegionReads(FieldOfKeyword(keyword))) {
      throw std::invalid_argument(
          keyword + ": body_region=" + (region.front() == '[' ? region : "'" + region + "'") +
          " does not read it (ISO/TS 15066's model takes robot_mass, speed, robot_radius, the covering, "
          "reaction_delay, braking and safety_factor; the region's spring and mass are Table A.3's); drop it, or "
          "judge the head with "
          "body_region='head'");
    }
  }
  if (Option(inputs.given, "ranges") && py::len(inputs.given["ranges"]) > 0) {
    throw std::invalid_argument("ranges: the scene has ranges, a population; a body region takes one scene");
  }
}

/// body_region=: a name, "all" or a list of names; body_area= (one region only).
std::vector<std::string> ReadRegionNames(const py::kwargs& kwargs) {
  const py::object value = *Option(kwargs, "body_region");
  std::vector<std::string> names;
  if (py::isinstance<py::str>(value)) {
    names.push_back(value.cast<std::string>());
  } else if (py::isinstance<py::iterable>(value)) {
    for (const py::handle item : value) {
      if (!py::isinstance<py::str>(item)) {
        throw std::invalid_argument("body_region: expected a region name or a list of names (got " + Repr(value) + ")");
      }
      names.push_back(item.cast<std::string>());
    }
  }
  if (names.empty()) {
    throw std::invalid_argument("body_region: expected a region name or a list of names (got " + Repr(value) + ")");
  }
  return names;
}

/// body_region=, body_area=, contact= and contact_area= resolved by the library
/// (scene_file::ResolveTargets: case, "all", "head", duplicates), its messages and notes
/// spelled as keywords. contact_area= is a number in m² or a string with its unit ("1cm2").
materials::ContactTargets ReadTargets(const py::kwargs& kwargs) {
  scene_file::TargetRequest request;
  request.names = ReadRegionNames(kwargs);
  if (const auto v = Option(kwargs, "body_area")) request.area = py::str(*v).cast<std::string>();
  if (const auto v = Option(kwargs, "contact")) request.contact = py::str(*v).cast<std::string>();
  if (const auto v = Option(kwargs, "contact_area")) {
    if (py::isinstance<py::bool_>(*v) ||
        !(py::isinstance<py::float_>(*v) || py::isinstance<py::int_>(*v) || py::isinstance<py::str>(*v))) {
      throw std::invalid_argument(
          "contact_area: expected a number in m2 or a string with its unit, e.g. '1cm2' (got " + Repr(*v) + ")");
    }
    request.contact_area_m2 = ReadSceneQuantity(*v, quantity_specs::kContactArea, "contact_area");
    request.contact_area_shown = py::str(*v).cast<std::string>();
  }
  request.limits = LimitsPath(kwargs);
  materials::ContactTargets targets = Keyworded([&] { return *scene_file::ResolveTargets(request); });
  for (std::string& note : targets.notes) note = AsKeywords(note);
  return targets;
}

/// The library's bare-robot contact-area policy (scene_file::RequireBareRobotContactArea).
void RequireBareContactArea(const materials::ContactTargets& targets, const BodyContactScene& scene) {
  Keyworded([&] { scene_file::RequireBareRobotContactArea(targets, scene); });
}

/// How a contact is judged, as the CLI's BodyRegionOptionsOf: the safety factor,
/// allow_full_compression, allow_crushing, and the catalog material of the covering (its crush
/// behaviour) if material= was given; a material of unknown strength is judged without the
/// crush check (the crush notes say so), unless `unknown_strength` says otherwise.
optim::BodyRegionOptions JudgeOptions(const SceneInputs& inputs, const py::kwargs& kwargs,
                                      std::optional<bool> unknown_strength = std::nullopt) {
  return optim::BodyRegionOptionsOf(
      inputs.safety_factor, Flag(kwargs, "allow_full_compression"), Flag(kwargs, "allow_crushing"),
      unknown_strength.value_or(!inputs.CrushCheck().notes.empty()),
      inputs.covering_material ? materials::Catalog::BuiltIn().Find(*inputs.covering_material) : nullptr,
      Flag(kwargs, "keep_travel"));
}

std::optional<std::string> MaterialName(const SceneInputs& inputs) {
  if (inputs.covering_material && inputs.scene.covering.thickness_m > 0.0) return inputs.covering_material;
  return std::nullopt;
}

/// The solver options of simulate: method= None or "exact" (the exact path), or
/// "time-path"/"cvode"/an integrator name (the time path, besides the exact path's verdict);
/// rtol=, atol=, max_steps= for the time path; history=True runs the time path.
SolveOptions ReadPath(const py::kwargs& kwargs) {
  SolveOptions options;
  options.record_history = Flag(kwargs, "history");
  if (const auto v = Option(kwargs, "method")) {
    const std::string method = py::str(*v).cast<std::string>();
    if (method == "exact") {
      options.path = PathChoice::kExact;
    } else if (method == "time-path") {
      options.path = PathChoice::kTimePath;  // the default integrator
    } else if (const auto named = scene_file::ParseIntegrator(method)) {
      options.path = PathChoice::kTimePath;
      options.time_path.method = *named;
    } else {
      throw std::invalid_argument("method: expected exact, time-path, cvode, " + scene_file::IntegratorNames() +
                                  " (got '" + method + "')");
    }
  }
  if (options.record_history && options.path == PathChoice::kExact) {
    throw std::invalid_argument("history=True needs the time path; drop method='exact'");
  }
  if (options.record_history) options.path = PathChoice::kTimePath;
  const bool time_path = options.path == PathChoice::kTimePath;
  for (const char* k : {"rtol", "atol", "max_steps"}) {
    if (Option(kwargs, k) && !time_path) {
      throw std::invalid_argument(std::string(k) + " applies to the time path only; give method='time-path' or "
                                  "an integrator, or history=True");
    }
  }
  if (const auto v = Option(kwargs, "rtol")) options.time_path.relative_tolerance = py::float_(*v).cast<double>();
  if (const auto v = Option(kwargs, "atol")) options.time_path.absolute_tolerance = py::float_(*v).cast<double>();
  if (const auto v = Option(kwargs, "max_steps")) {
    if (!py::isinstance<py::int_>(*v) || py::isinstance<py::bool_>(*v)) {
      throw std::invalid_argument("max_steps: expected an integer (got " + Repr(*v) + ")");
    }
    options.time_path.max_steps = v->cast<long>();
  }
  return options;
}

/// One region the call judges (simulate and sweep take one region, not the head or "all").
materials::ContactTargets OneRegion(const py::kwargs& kwargs, const char* function) {
  materials::ContactTargets targets = ReadTargets(kwargs);
  if (targets.targets.size() != 1 || targets.has_head()) {
    throw std::invalid_argument(std::string("body_region: ") + function +
                                " takes one region (got " + Repr(kwargs["body_region"]) +
                                "); speed_limit and optimize take several or 'all'");
  }
  return targets;
}

/// "contact_area 1 cm² is the bare robot's; ..." (the CLI's ContactAreaNote, naming the keyword).
std::vector<std::string> ContactWarnings(const SceneInputs& inputs, const materials::ContactTargets& targets,
                                         const BodyContactScene& scene) {
  std::vector<std::string> warnings = InputWarnings(inputs);
  warnings.insert(warnings.end(), targets.notes.begin(), targets.notes.end());
  if (const auto note = scene_file::ContactAreaNote(targets, scene)) warnings.push_back(AsKeywords(*note));
  return warnings;
}

/// The input warnings and the targets' notes, without the default covering's: optimize
/// designs the covering (and the contact area is the bare robot's, judged as such).
std::vector<std::string> DesignWarnings(const SceneInputs& inputs, const materials::ContactTargets& targets) {
  std::vector<std::string> warnings = InputWarnings(inputs);
  std::erase(warnings, optim::DefaultCoveringNote(inputs.scene));
  warnings.insert(warnings.end(), targets.notes.begin(), targets.notes.end());
  return warnings;
}

/// covopt.simulate(scene, body_region=..., ...): one contact, judged; the dict is `covopt
/// simulate --body-region --json`'s, with time_path (and history) when the time path ran.
py::dict Simulate(const SceneInputs& inputs, const py::kwargs& kwargs) {
  const materials::ContactTargets targets = OneRegion(kwargs, "simulate");
  const BodyLimits& limits = *targets.targets.front().limits;
  RefuseHeadKeywords(inputs, limits.region->name);
  const SolveOptions options = ReadPath(kwargs);
  const optim::BodyRegionOptions judge = JudgeOptions(inputs, kwargs);
  const BodyContactScene scene = scene_file::BodyContactSceneOf(inputs.scene, targets);
  RequireBareContactArea(targets, scene);
  std::vector<optim::BodyRegionJudgement> judgements;
  std::optional<BodyContactResult> timed;
  try {
    py::gil_scoped_release release;
    // A braking robot has only the time path: method='exact' is refused (by Solve), and its
    // verdict is the time path's, with the integrator and tolerances given.
    if (scene.robot_brakes() && options.path == PathChoice::kExact) {
      (void)Solve(optim::WithRegion(scene, limits), options);
    }
    judgements.push_back(optim::JudgeBodyContact(scene, limits, judge, options.time_path));
    if (options.path == PathChoice::kTimePath) timed = Solve(optim::WithRegion(scene, limits), options);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(inputs.Attributed(SolveKeywords(AsKeywords(e.what()))));
  }
  for (const BodyContactResult* c : {&judgements.front().contact, timed ? &*timed : nullptr}) {
    if (c && !c->ok()) {
      RaiseComputationError("the time path failed on " + limits.region->name + " (" +
                                std::string(ToString(c->status)) + "): " + c->message,
                            std::string(ToString(c->status)));
    }
  }
  std::vector<std::string> warnings = ContactWarnings(inputs, targets, scene);
  for (std::string& w : report::TimePathWarnings(judgements.front(), timed ? &*timed : nullptr)) {
    warnings.push_back(std::move(w));
  }
  py::dict d = JsonToPython(report::BodyContactSimulationJson(scene, MaterialName(inputs), judgements,
                                                              inputs.safety_factor, std::nullopt, warnings));
  if (timed) d["time_path"] = JsonToPython(report::BodyContactTimePathJson(*timed));
  if (options.record_history) {
    py::dict columns;
    for (const report::HistoryColumn& c : report::BodyContactHistoryColumns(timed->history)) {
      columns[py::str(std::string(c.name))] = py::array_t<double>(static_cast<py::ssize_t>(c.values.size()), c.values.data());
    }
    d["history"] = columns;
  }
  return WithReportCharts(std::move(d), [scene, judgements, judge, material = MaterialName(inputs)] {
    return chart::BodyRegionSimulationCharts(scene, judgements, judge, material);
  });
}

/// covopt.speed_limit(scene, body_region=..., values=None): `covopt speed-limit --body-region
/// --json`'s object: one row per area (and the head's) per robot mass in values (default the
/// scene's).
py::dict SpeedLimitTable(const SceneInputs& inputs, const py::kwargs& kwargs) {
  const materials::ContactTargets targets = ReadTargets(kwargs);
  if (!targets.has_head()) RefuseHeadKeywords(inputs, RegionText(kwargs));
  if (inputs.Gave("speed")) {
    throw std::invalid_argument("speed_limit() computes the speed; drop speed from the scene");
  }
  std::vector<double> masses{inputs.scene.robot.mass_kg};
  if (const auto v = Option(kwargs, "values")) {
    masses.clear();
    if (py::isinstance<py::str>(*v) || !py::isinstance<py::iterable>(*v)) {
      masses.push_back(ReadSceneQuantity(*v, quantity_specs::kRobotMass, "values"));
    } else {
      for (const py::handle item : *v) masses.push_back(ReadSceneQuantity(item, quantity_specs::kRobotMass, "values"));
    }
    if (masses.empty()) throw std::invalid_argument("values: no robot masses (got an empty list)");
  }
  const optim::BodyRegionOptions options = JudgeOptions(inputs, kwargs);
  const BodyContactScene scene = scene_file::BodyContactSceneOf(inputs.scene, targets);
  RequireBareContactArea(targets, scene);
  const optim::TargetSpeedLimitRequest request{inputs.scene, scene, masses, options,
                                               SpeedLimitOptionsFrom(inputs, kwargs), TimeIntegrationOptions{}};
  optim::TargetSpeedLimits table;
  try {
    py::gil_scoped_release release;
    table = optim::TargetSpeedLimitTable(request, targets);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(inputs.Attributed(AsKeywords(e.what())));
  }
  if (!table.failure.empty()) RaiseComputationError(table.failure, "evaluation-failed");
  std::vector<report::BodyRegionTableRow> rows;
  for (const optim::TargetSpeedLimit& row : table.rows) rows.push_back(report::TableRow(row, MaterialName(inputs).value_or("")));
  std::vector<std::string> warnings = InputWarnings(inputs);
  warnings.insert(warnings.end(), targets.notes.begin(), targets.notes.end());
  if (const auto note = scene_file::BarePressureNote(targets)) warnings.push_back(AsKeywords(*note));
  return WithReportCharts(
      JsonToPython(report::BodyRegionSpeedLimitJson(scene, MaterialName(inputs),
                                                    optim::BodyRegionCriterion(optim::JudgedRule(options), targets.has_head(), targets.Citation()),
                                                    options.rule.safety_factor, rows, warnings)),
      [rows] { return std::vector{chart::BodyRegionSpeedChart(rows)}; });
}

/// covopt.optimize(scene, body_region=[...]): the covering for every region at the scene's
/// speed, as `covopt optimize --body-region --json`.
py::dict Design(const SceneInputs& inputs, const py::kwargs& kwargs) {
  for (const char* k : {"covering_modulus", "covering_thickness", "covering_poisson", "material"}) {
    if (inputs.Gave(k)) {
      throw std::invalid_argument(std::string(k) + ": the covering is what optimize designs; give materials= "
                                  "or families= to choose candidates");
    }
  }
  const materials::ContactTargets targets = ReadTargets(kwargs);
  optim::BodyRegionDesignRequest request;
  request.scene = scene_file::BodyContactSceneOf(inputs.scene, targets);
  request.regions = targets.IsoLimits();
  if (targets.has_head()) {
    request.head = inputs.scene;  // the head's own keywords apply to its skin model
    request.head->covering.law = CoveringLaw::kAuto;  // the design's law (below), not the designed covering's
  } else {
    RefuseHeadKeywords(inputs, RegionText(kwargs));
  }
  request.materials = Candidates(kwargs);
  request.covering_law = inputs.scene.covering.law;
  if (!Option(kwargs, "materials")) optim::KeepCandidatesForLaw(request.materials, request.covering_law);
  request.rule = JudgeOptions(inputs, kwargs, Flag(kwargs, "allow_unknown_strength")).rule;
  if (const auto v = Option(kwargs, "max_thickness")) {
    request.max_thickness_m = ReadSceneQuantity(*v, quantity_specs::kCoveringThickness, "max_thickness");
  }
  if (const auto v = Option(kwargs, "thickness_step")) {
    request.thickness_step_m = ReadSceneQuantity(*v, quantity_specs::kThicknessStep, "thickness_step");
  }
  optim::BodyRegionDesignResult result;
  try {
    py::gil_scoped_release release;
    result = optim::DesignForBodyRegions(request);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(inputs.Attributed(AsKeywords(e.what())));
  }
  py::dict d = JsonToPython(report::BodyRegionDesignJson(request, result,
                                                        optim::BodyRegionCriterion(request.rule, targets.has_head(), targets.Citation()),
                                                        DesignWarnings(inputs, targets)));
  return WithReportCharts(std::move(d), [request, result] { return chart::BodyRegionDesignCharts(request, result); });
}

/// covopt.check_trajectory(..., body_region=...): every sample against the ISO regions named
/// (optim::CheckTrajectoryForBodyRegions) and the head, if named, by its own check, as `covopt
/// robot --trajectory --body-region --json`.
py::dict CheckTrajectory(const py::object& urdf, const std::string& tip, const py::object& trajectory,
                         const std::optional<std::string>& base, const py::object& point,
                         const std::optional<std::string>& urdf_text, bool ignore_joint_limits,
                         const py::tuple& payload, const SceneInputs& inputs, const py::kwargs& kwargs) {
  RefuseSampleKeywords(inputs);
  const materials::ContactTargets targets = ReadTargets(kwargs);
  const std::vector<BodyLimits> iso = targets.IsoLimits();
  if (!targets.has_head()) RefuseHeadKeywords(inputs, RegionText(kwargs));
  const optim::BodyRegionOptions options = JudgeOptions(inputs, kwargs);
  const BodyContactScene scene = scene_file::BodyContactSceneOf(inputs.scene, targets);
  RequireBareContactArea(targets, scene);

  const robot::ContactMotionResult motion =
      ReadContactMotion(urdf, tip, trajectory, base, point, urdf_text, ignore_joint_limits, PayloadFrom(payload));
  const optim::TrajectoryCheckOptions head_options = TrajectoryCheckOptionsFrom(inputs, kwargs);
  std::optional<optim::BodyRegionTrajectoryCheck> check;
  std::optional<optim::TrajectoryCheck> head;
  try {
    py::gil_scoped_release release;
    const std::vector<optim::MotionSample> samples = optim::MotionSamples(motion.samples);
    if (!iso.empty()) check = optim::CheckTrajectoryForBodyRegions(scene, iso, samples, options);
    if (targets.has_head()) head = optim::CheckTrajectory(inputs.scene, samples, head_options);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(inputs.Attributed(AsKeywords(e.what())));
  }
  std::optional<report::HeadTrajectorySummary> head_summary;
  if (head) {
    if (head->status == optim::TrajectoryCheckStatus::kEvaluationFailed) {
      RaiseComputationError(head->message, std::string(optim::ToString(head->status)));
    }
    head_summary = report::HeadTrajectorySummary{std::string(optim::ToString(head->status)), head->safe_speed_scale,
                                                 head->message};
  }
  std::vector<std::string> warnings = InputAndCrushWarnings(inputs);
  warnings.insert(warnings.end(), motion.warnings.begin(), motion.warnings.end());
  warnings.insert(warnings.end(), targets.notes.begin(), targets.notes.end());
  const optim::BodyRegionTrajectoryCheck checked = check ? *check : optim::BodyRegionTrajectoryCheck{};
  return WithReportCharts(
      JsonToPython(report::BodyRegionTrajectoryJson(checked, iso, scene, head_summary,
                                                    optim::BodyRegionCriterion(optim::JudgedRule(options), targets.has_head(), targets.Citation()),
                                                    optim::JudgedRule(options).safety_factor, warnings)),
      [checked, iso, sf = options.rule.safety_factor] { return chart::BodyRegionTrajectoryCharts(checked, iso, sf); });
}

/// covopt.sweep(x, y, scene=..., body_region=...): one region's verdict over the grid
/// (optim::SweepBodyRegion), as numpy arrays a[i, j] at x[i], y[j] (the columns of `covopt
/// sweep --body-region --csv`); an invalid point is NaN / False, with its message in errors.
py::dict Sweep(const py::object& x, const py::object& y, const SceneInputs& inputs, const py::kwargs& kwargs) {
  const materials::ContactTargets targets = OneRegion(kwargs, "sweep");
  const BodyLimits& limits = *targets.targets.front().limits;
  RefuseHeadKeywords(inputs, limits.region->name);
  const SweepAxis x_axis = ReadAxis(x, "x");
  const std::optional<SweepAxis> y_axis = y.is_none() ? std::nullopt : std::optional(ReadAxis(y, "y"));
  const optim::BodyRegionOptions options = JudgeOptions(inputs, kwargs);
  const BodyContactScene scene = scene_file::BodyContactSceneOf(inputs.scene, targets);
  RequireBareContactArea(targets, scene);
  std::vector<optim::BodyRegionSweepPoint> grid;
  try {
    py::gil_scoped_release release;
    grid = optim::SweepBodyRegion(scene, x_axis, y_axis, limits, options);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(inputs.Attributed(e.what()));
  }
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(x_axis.values.size())};
  if (y_axis) shape.push_back(static_cast<py::ssize_t>(y_axis->values.size()));
  const report::BodyRegionSweepColumns table = report::BodyRegionSweepColumnsOf(grid, limits);
  py::dict out;
  out["x"] = py::array_t<double>(static_cast<py::ssize_t>(x_axis.values.size()), x_axis.values.data());
  out["x_quantity"] = x_axis.quantity;
  if (y_axis) {
    out["y"] = py::array_t<double>(static_cast<py::ssize_t>(y_axis->values.size()), y_axis->values.data());
    out["y_quantity"] = y_axis->quantity;
  }
  for (const report::BodyRegionSweepColumn& column : table.columns) {
    py::array_t<double> array(shape);
    std::copy(column.values.begin(), column.values.end(), array.mutable_data());
    out[py::str(std::string(column.name))] = column.flag ? py::object(array.attr("astype")(py::dtype::of<bool>())) : array;
  }
  py::array_t<bool> valid(shape);
  std::copy(table.valid.begin(), table.valid.end(), valid.mutable_data());
  out["valid"] = valid;
  out["governing"] = table.governing;  // flat, reshaped to the grid by covopt/_body_regions.py
  out["error"] = table.errors;
  out["region"] = limits.region->name;
  out["area"] = limits.area->name;
  out["contact"] = std::string(ToString(limits.contact));
  out["scope"] = limits.Describe();
  out["message"] = table.message;
  return out;
}

}  // namespace

std::optional<std::string> LimitsPath(const py::dict& kwargs) {
  const auto v = Option(kwargs, "limits");
  if (!v) return std::nullopt;
  if (!py::isinstance<py::str>(*v) && !py::hasattr(*v, "__fspath__")) {
    throw std::invalid_argument("limits: expected the path of a body-region table file (a str or os.PathLike), got " +
                                Repr(*v));
  }
  return py::module_::import("os").attr("fspath")(*v).cast<std::string>();
}

BodyRegionSelection SelectBodyRegions(const SceneInputs& inputs, const py::kwargs& kwargs) {
  const materials::ContactTargets targets = ReadTargets(kwargs);
  return BodyRegionSelection{targets.IsoLimits(), targets.has_head(), targets.contact, targets.contact_area_m2,
                             JudgeOptions(inputs, kwargs)};
}

OneRegionContact ReadOneRegionContact(const SceneInputs& inputs, const py::kwargs& kwargs, const char* function) {
  const materials::ContactTargets targets = OneRegion(kwargs, function);
  const BodyLimits& limits = *targets.targets.front().limits;
  RefuseHeadKeywords(inputs, limits.region->name);
  const BodyContactScene scene = scene_file::BodyContactSceneOf(inputs.scene, targets);
  RequireBareContactArea(targets, scene);
  return {limits, scene, JudgeOptions(inputs, kwargs), MaterialName(inputs), ContactWarnings(inputs, targets, scene)};
}

void RegisterBodyContact(py::module_& m) {
  m.def("simulate_body_region", &Simulate);
  m.def("body_region_speed_limit", &SpeedLimitTable);
  m.def("design_for_body_regions", &Design);
  m.def("check_trajectory_body_region", &CheckTrajectory, py::arg("urdf"), py::arg("tip"), py::arg("trajectory"),
        py::arg("base"), py::arg("point"), py::arg("urdf_text"), py::arg("ignore_joint_limits"), py::arg("payload"),
        py::arg("scene"));
  m.def("sweep_body_region", &Sweep, py::arg("x"), py::arg("y"), py::arg("scene"));
}

}  // namespace covopt::python
