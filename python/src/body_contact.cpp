/// @file body_contact.cpp
/// The ISO/TS 15066 body regions in Python (docs/model.md §13): covopt.simulate,
/// covopt.speed_limit and covopt.optimize with body_region= (python/covopt/_body_regions.py
/// documents them), over core's BodyContactScene/Solve, materials' BodyRegionTable and
/// optim's JudgeBodyContact, MaxSafeSpeed, BodyRegionSpeedLimitTable and DesignForBodyRegions.
///
/// The robot and its covering come from a covopt.Scene (robot_mass, speed, robot_radius, the
/// covering keywords or material, safety_factor); the region from the keywords body_region,
/// body_area, contact and contact_area, named as the CLI's --body-region, --body-area,
/// --contact and --contact-area. A scene keyword the body-region model does not read (the
/// head's, the skull's, damping, braking, the robot's modulus) is refused, never ignored.
/// The dicts are built here; their keys carry their units. Bad input raises ValueError with
/// the library's one-line message (flags named as keywords).

#include <cctype>
#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "covopt/core/body_contact.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/solve.hpp"
#include "covopt/materials/body_regions.hpp"
#include "covopt/materials/catalog.hpp"
#include "covopt/optim/body_region_check.hpp"
#include "covopt/optim/design.hpp"
#include "scene_keywords.hpp"

namespace py = pybind11;

namespace covopt::python {
namespace {

using materials::BodyLimits;
using materials::BodyRegionTable;

std::string Repr(const py::handle& value) { return py::repr(value).cast<std::string>(); }

/// The library's messages name the CLI's flags; here they are keywords:
/// "--contact clamped" -> "contact='clamped'", "--body-region head" -> "body_region='head'".
std::string AsKeywords(std::string message) {
  for (const std::string_view flag : {"--body-region", "--body-area", "--contact-area", "--contact"}) {
    std::string keyword(flag.substr(2));
    for (char& c : keyword) c = c == '-' ? '_' : c;
    for (std::size_t at = message.find(flag); at != std::string::npos; at = message.find(flag, at)) {
      const std::size_t end = at + flag.size();
      if (end < message.size() && (std::isalnum(static_cast<unsigned char>(message[end])) || message[end] == '-')) {
        at = end;  // a longer flag (--contact-area when looking for --contact)
        continue;
      }
      std::size_t value_end = end;
      if (end < message.size() && message[end] == ' ') {
        value_end = end + 1;
        while (value_end < message.size() &&
               (std::isalnum(static_cast<unsigned char>(message[value_end])) || message[value_end] == '-')) {
          ++value_end;
        }
      }
      const std::string value = message.substr(end + 1, value_end > end + 1 ? value_end - end - 1 : 0);
      const std::string replacement = value.empty() || value == "NAME" || value == "A"
                                          ? keyword
                                          : keyword + "='" + value + "'";
      message.replace(at, (value.empty() ? end : value_end) - at, replacement);
      at += replacement.size();
    }
  }
  return message;
}

/// Runs `f`, re-raising the library's std::invalid_argument with keywords for flags.
template <typename F>
auto Keyworded(F&& f) {
  try {
    return f();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(AsKeywords(e.what()));
  }
}

/// The scene keywords the body-region model reads; every other one given is refused.
const char* const kReadKeywords[] = {"robot_mass",         "speed",    "robot_radius", "covering_modulus",
                                     "covering_poisson",   "material", "safety_factor", "covering_thickness",
                                     "ranges"};

/// body_region as given, for messages: "chest", "['chest', 'face']".
std::string RegionText(const py::kwargs& kwargs) {
  const py::object value = kwargs["body_region"];
  return py::isinstance<py::str>(value) ? value.cast<std::string>() : Repr(value);
}

/// Refuses the scene keywords the body-region model does not read (`region`: body_region).
void RefuseHeadKeywords(const SceneInputs& inputs, const std::string& region) {
  for (const auto& item : inputs.given) {
    const std::string keyword = py::str(item.first).cast<std::string>();
    bool read = false;
    for (const char* k : kReadKeywords) read = read || keyword == k;
    if (!read) {
      throw std::invalid_argument(
          keyword + ": body_region=" + (region.front() == '[' ? region : "'" + region + "'") +
          " does not read it (ISO/TS 15066's model takes robot_mass, speed, robot_radius, the covering and "
          "safety_factor; the region's spring and mass are Table A.3's); drop it, or judge the head with "
          "body_region='head'");
    }
  }
  if (Option(inputs.given, "ranges") && py::len(inputs.given["ranges"]) > 0) {
    throw std::invalid_argument("ranges: the scene has ranges, a population; a body region takes one scene");
  }
}

/// contact=: "transient" (default), "clamped" (or "quasi-static").
ContactType ReadContact(const py::kwargs& kwargs) {
  const auto v = Option(kwargs, "contact");
  if (!v) return ContactType::kTransient;
  const std::string text = py::str(*v).cast<std::string>();
  const auto contact = ParseContactType(text);
  if (!contact) throw std::invalid_argument("contact: expected 'transient' or 'clamped' (got " + Repr(*v) + ")");
  return *contact;
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

/// What body_region, body_area and contact name: the ISO regions' limits and whether the head
/// (Park et al.'s skin model) is among them. "all" is every region the contact permits, and
/// the head when transient.
struct RegionChoice {
  std::vector<BodyLimits> limits;
  bool head = false;
  bool all = false;
  ContactType contact = ContactType::kTransient;
};

bool IsHead(std::string name) {
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return name == "head";
}

RegionChoice ReadRegions(const py::kwargs& kwargs) {
  RegionChoice choice;
  choice.contact = ReadContact(kwargs);
  const std::vector<std::string> names = ReadRegionNames(kwargs);
  const auto area = Option(kwargs, "body_area");
  const std::string area_name = area ? py::str(*area).cast<std::string>() : std::string();
  if (area && names.size() != 1) {
    throw std::invalid_argument("body_area: names an area of one region; give one body_region with it (got " +
                                std::to_string(names.size()) + " regions)");
  }
  const BodyRegionTable& table = BodyRegionTable::BuiltIn();
  for (const std::string& name : names) {
    if (name == "all") {
      if (area) throw std::invalid_argument("body_area: body_region='all' takes every area; drop body_area");
      choice.all = true;
      for (BodyLimits& limits : table.AllLimits(choice.contact)) choice.limits.push_back(std::move(limits));
      choice.head = choice.head || choice.contact == ContactType::kTransient;
    } else if (IsHead(name)) {
      if (area) throw std::invalid_argument("body_area: the head is judged by Park et al.'s skin model, not by area");
      if (choice.contact != ContactType::kTransient) {
        throw std::invalid_argument("contact='clamped': the head's skin model (Park et al. 2011) is a transient "
                                    "impact; for the clamped head use body_region='skull-forehead' or 'face'");
      }
      choice.head = true;
    } else {
      choice.limits.push_back(Keyworded([&] { return table.Limits(name, area_name, choice.contact); }));
    }
  }
  return choice;
}

/// contact_area= [m²]: a number in (0, 1] m².
double ReadContactArea(const py::kwargs& kwargs) {
  const auto v = Option(kwargs, "contact_area");
  if (!v) return 0.0;
  if (py::isinstance<py::bool_>(*v) || !(py::isinstance<py::float_>(*v) || py::isinstance<py::int_>(*v))) {
    throw std::invalid_argument("contact_area: expected a number in m2 (got " + Repr(*v) + ")");
  }
  const double area = py::float_(*v).cast<double>();
  if (!(area > 0.0 && area <= 1.0)) {
    throw std::invalid_argument("contact_area must be in (0, 1] m2 (1 cm2 is 1e-4) (got " + Repr(*v) + ")");
  }
  return area;
}

/// The robot and covering of `inputs` with the contact's keywords (the region's k_H and m_H are
/// set by optim::WithRegion).
BodyContactScene ContactScene(const SceneInputs& inputs, const py::kwargs& kwargs, ContactType contact) {
  BodyContactScene scene;
  scene.robot_mass_kg = inputs.scene.robot.mass_kg;
  scene.speed_m_per_s = inputs.scene.robot.speed_m_per_s;
  scene.robot_radius_m = inputs.scene.robot.radius_m;
  scene.covering = inputs.scene.covering;
  scene.contact = contact;
  scene.contact_area_m2 = ReadContactArea(kwargs);
  return scene;
}

/// How a contact is judged: the safety factor, allow_full_compression, allow_crushing and the
/// catalog material of the covering (its crush behaviour), if material= was given.
optim::BodyRegionOptions JudgeOptions(const SceneInputs& inputs, const py::kwargs& kwargs) {
  optim::BodyRegionOptions options;
  options.rule.safety_factor = inputs.safety_factor;
  options.rule.criterion = Flag(kwargs, "allow_full_compression") ? optim::DesignCriterion::kPaper
                                                                   : optim::DesignCriterion::kNoFullCompression;
  options.rule.crushing_allowed = Flag(kwargs, "allow_crushing");
  options.rule.unknown_strength_allowed = Flag(kwargs, "allow_unknown_strength");
  if (inputs.covering_material && inputs.scene.covering.thickness_m > 0.0) {
    const std::vector<std::string> name{*inputs.covering_material};
    options.material = optim::SelectCandidates(materials::Catalog::BuiltIn(), name).front();
  }
  return options;
}

py::object OrNone(const std::optional<double>& value) {
  return value ? py::object(py::float_(*value)) : py::object(py::none());
}

py::object MassOrFixed(double mass_kg) {
  return std::isinf(mass_kg) ? py::object(py::str("fixed")) : py::object(py::float_(mass_kg));
}

/// The limits' keys: region, area, contact, force_limit_N, pressure_limit_Pa and the region's
/// Table A.3 values.
void PutLimits(py::dict& d, const BodyLimits& limits) {
  d["region"] = limits.region->name;
  d["region_title"] = limits.region->title;
  d["area"] = limits.area->name;
  d["area_title"] = limits.area->title;
  d["contact"] = std::string(ToString(limits.contact));
  d["force_limit_N"] = limits.force_N;
  d["pressure_limit_Pa"] = limits.pressure_Pa;
  d["stiffness_N_per_m"] = limits.stiffness_N_per_m();
  d["effective_mass_kg"] = MassOrFixed(limits.effective_mass_kg());
}

py::dict SceneDict(const BodyContactScene& scene, const SceneInputs& inputs) {
  py::dict d;
  d["robot_mass_kg"] = MassOrFixed(scene.robot_mass_kg);
  d["speed_m_per_s"] = scene.speed_m_per_s;
  d["robot_radius_m"] = std::isinf(scene.robot_radius_m) ? py::object(py::str("flat")) : py::float_(scene.robot_radius_m);
  py::dict covering;
  covering["thickness_m"] = scene.covering.thickness_m;
  if (scene.has_covering()) {
    covering["youngs_modulus_Pa"] = scene.covering.youngs_modulus_Pa;
    covering["poisson_ratio"] = scene.covering.poisson_ratio;
    covering["material"] = inputs.covering_material ? py::object(py::str(*inputs.covering_material)) : py::none();
  }
  d["covering"] = covering;
  d["contact_area_m2"] = scene.contact_area_m2 > 0.0 ? py::object(py::float_(scene.contact_area_m2)) : py::none();
  d["safety_factor"] = inputs.safety_factor;
  return d;
}

py::dict ContactDict(const BodyContactResult& r) {
  py::dict d;
  d["method"] = r.method;
  d["reduced_mass_kg"] = r.reduced_mass_kg;
  d["energy_transferred_J"] = r.energy_transferred_J;
  d["peak_force_N"] = r.peak_force_N;
  d["peak_pressure_Pa"] = OrNone(r.peak_pressure_Pa);
  d["contact_radius_m"] = r.contact_radius_m;
  d["covering_deflection_m"] = r.covering_deflection_m;
  d["body_deflection_m"] = r.body_deflection_m;
  d["max_approach_m"] = r.max_approach_m;
  d["body_energy_J"] = r.body_energy_J;
  d["covering_energy_J"] = r.covering_energy_J;
  d["compression_ratio"] = r.compression_ratio;
  d["fully_compressed"] = r.fully_compressed;
  d["contact_duration_s"] = OrNone(r.contact_duration_s);
  d["rebound_speed_m_per_s"] = r.rebound_speed_m_per_s;
  return d;
}

/// A judgement: the limits, the contact's peaks, the ratios and the verdict.
py::dict JudgementDict(const optim::BodyRegionJudgement& j) {
  py::dict d;
  PutLimits(d, j.limits);
  for (const auto& item : ContactDict(j.contact)) d[item.first] = item.second;
  py::dict ratios;
  ratios["force"] = j.force_ratio;
  ratios["pressure"] = OrNone(j.pressure_ratio);
  ratios["compression"] = j.compression_ratio;
  ratios["crush"] = j.crush_check == optim::CrushCheck::kChecked ? py::object(py::float_(j.crush_ratio)) : py::none();
  d["ratios"] = ratios;
  d["crush_check"] = std::string(optim::ToString(j.crush_check));
  d["governing"] = std::string(optim::ToString(j.governing));
  d["governing_ratio"] = j.governing_ratio;
  d["admissible"] = j.admissible;
  d["margin"] = j.margin;
  d["scope"] = j.scope;
  return d;
}

/// The solver options of simulate: method= None (the exact path; the time path with
/// history=True), "exact", or "time-path"/"cvode"/an integrator name; rtol=, atol=,
/// max_steps= for the time path.
SolveOptions ReadPath(const py::kwargs& kwargs) {
  SolveOptions options;
  options.record_history = Flag(kwargs, "history");
  if (const auto v = Option(kwargs, "method")) {
    const std::string method = py::str(*v).cast<std::string>();
    const auto named = method == "cvode" ? std::optional(ComputationMethod::kCvodeAdams) : ParseComputationMethod(method);
    if (method == "exact") {
      options.path = PathChoice::kExact;
    } else if (method == "time-path") {
      options.path = PathChoice::kTimePath;  // the default integrator
    } else if (named && *named != ComputationMethod::kExact) {
      options.path = PathChoice::kTimePath;
      options.time_path.method = *named;
    } else {
      std::string names;
      for (const ComputationMethod m : TimeIntegrationMethods()) names += ", " + std::string(ToString(m));
      throw std::invalid_argument("method: expected exact, time-path, cvode" + names + " (got '" + method + "')");
    }
  }
  const bool time_path = options.path == PathChoice::kTimePath || options.record_history;
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

/// Solve's option messages name time_path.*: here they are the keywords.
std::string OptionKeywords(std::string message) {
  for (const auto& [field, keyword] : {std::pair{"time_path.relative_tolerance", "rtol"},
                                       {"time_path.absolute_tolerance", "atol"}, {"time_path.max_steps", "max_steps"}}) {
    if (message.rfind(field, 0) == 0) message = keyword + message.substr(std::string_view(field).size());
  }
  return message;
}

/// One region the call judges (simulate and sweep take one region, not the head or "all").
BodyLimits OneRegion(const py::kwargs& kwargs, const char* function) {
  const RegionChoice choice = ReadRegions(kwargs);
  if (choice.all || choice.limits.size() != 1 || choice.head) {
    throw std::invalid_argument(std::string("body_region: ") + function +
                                " takes one region (got " + Repr(kwargs["body_region"]) +
                                "); speed_limit and optimize take several or 'all'");
  }
  return choice.limits.front();
}

/// covopt.simulate(scene, body_region=..., ...): one contact, judged.
py::dict Simulate(const SceneInputs& inputs, const py::kwargs& kwargs) {
  const BodyLimits limits = OneRegion(kwargs, "simulate");
  RefuseHeadKeywords(inputs, limits.region->name);
  const SolveOptions options = ReadPath(kwargs);
  const optim::BodyRegionOptions judge = JudgeOptions(inputs, kwargs);
  const BodyContactScene scene = optim::WithRegion(ContactScene(inputs, kwargs, limits.contact), limits);
  optim::BodyRegionJudgement judgement;
  BodyContactResult contact;
  try {
    py::gil_scoped_release release;
    judgement = optim::JudgeBodyContact(scene, limits, judge);
    contact = options.path == PathChoice::kAuto && !options.record_history ? judgement.contact
                                                                           : Solve(scene, options);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(inputs.Attributed(OptionKeywords(AsKeywords(e.what()))));
  }
  if (!contact.ok()) {
    RaiseComputationError("the computation failed: " + std::string(ToString(contact.status)) + ": " + contact.message,
                          std::string(ToString(contact.status)));
  }
  py::dict d = JudgementDict(judgement);
  for (const auto& item : ContactDict(contact)) d[item.first] = item.second;  // the path asked for
  d["scene"] = SceneDict(scene, inputs);
  py::list warnings;
  if (scene.has_covering() && scene.contact_area_m2 > 0.0) {
    warnings.append("contact_area is not read with a covering: the pressure is the covering's Hertz pressure");
  }
  d["warnings"] = warnings;
  if (options.record_history) {
    py::dict columns;
    const auto column = [&](const char* name, double (*field)(const BodyContactSample&)) {
      py::array_t<double> array(static_cast<py::ssize_t>(contact.history.size()));
      double* data = array.mutable_data();
      for (std::size_t i = 0; i < contact.history.size(); ++i) data[i] = field(contact.history[i]);
      columns[name] = array;
    };
    column("time_s", [](const BodyContactSample& s) { return s.time_s; });
    column("approach_m", [](const BodyContactSample& s) { return s.approach_m; });
    column("approach_rate_m_per_s", [](const BodyContactSample& s) { return s.approach_rate_m_per_s; });
    column("force_N", [](const BodyContactSample& s) { return s.force_N; });
    d["history"] = columns;
  }
  return d;
}

py::dict LimitDict(const optim::BodyRegionSpeedLimit& limit) {
  py::dict d;
  d["max_safe_speed_m_per_s"] = limit.status == optim::SpeedLimitStatus::kNoSafeValue
                                    ? py::object(py::none())
                                    : py::object(py::float_(limit.max_safe_speed_m_per_s));
  d["limited_by"] = std::string(optim::ToString(limit.limited_by));
  d["status"] = std::string(optim::ToString(limit.status));
  d["message"] = limit.message;
  return d;
}

/// covopt.speed_limit(scene, body_region=...): one row per area (and the head's, computed by
/// covopt/_body_regions.py with covopt.max_safe_speed).
py::dict SpeedLimitTable(const SceneInputs& inputs, const py::kwargs& kwargs) {
  const RegionChoice choice = ReadRegions(kwargs);
  if (!choice.head) RefuseHeadKeywords(inputs, RegionText(kwargs));
  if (inputs.Gave("speed")) {
    throw std::invalid_argument("speed_limit() computes the speed; drop speed from the scene");
  }
  const optim::BodyRegionOptions options = JudgeOptions(inputs, kwargs);
  const BodyContactScene scene = ContactScene(inputs, kwargs, choice.contact);
  std::vector<optim::BodyRegionSpeedLimitRow> rows;
  try {
    py::gil_scoped_release release;
    rows = optim::BodyRegionSpeedLimitTable(scene, choice.limits, options);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(inputs.Attributed(AsKeywords(e.what())));
  }
  py::list out;
  for (const optim::BodyRegionSpeedLimitRow& row : rows) {
    py::dict d;
    PutLimits(d, row.limits);
    d["scope"] = row.limits.Describe();
    d["bare"] = LimitDict(row.bare);
    d["covered"] = row.covered ? py::object(LimitDict(*row.covered)) : py::object(py::none());
    d["gain"] = OrNone(row.gain());
    out.append(d);
  }
  py::dict table;
  table["contact"] = std::string(ToString(choice.contact));
  table["safety_factor"] = inputs.safety_factor;
  py::list criteria;  // the limits counted (a row's scope says which apply to its area)
  criteria.append("force");
  criteria.append("pressure");
  if (options.rule.compression_counts()) criteria.append("full-compression");
  if (!options.rule.crushing_allowed) criteria.append("crush");
  table["criteria"] = criteria;
  table["scene"] = SceneDict(scene, inputs);
  table["rows"] = out;
  table["head"] = choice.head;  // covopt/_body_regions.py appends the head's row
  return table;
}

/// covopt.optimize(scene, body_region=[...]): the covering for every region at the scene's speed.
py::dict Design(const SceneInputs& inputs, const py::kwargs& kwargs) {
  for (const char* k : {"covering_modulus", "covering_thickness", "covering_poisson", "material"}) {
    if (inputs.Gave(k)) {
      throw std::invalid_argument(std::string(k) + ": the covering is what optimize designs; give materials= "
                                  "or families= to choose candidates");
    }
  }
  const RegionChoice choice = ReadRegions(kwargs);
  optim::BodyRegionDesignRequest request;
  request.scene = ContactScene(inputs, kwargs, choice.contact);
  request.regions = choice.limits;
  if (choice.head) {
    request.head = inputs.scene;  // the head's own keywords apply to its skin model
  } else {
    RefuseHeadKeywords(inputs, RegionText(kwargs));
  }
  const auto names = [&](const char* keyword) {
    std::vector<std::string> list;
    if (const auto v = Option(kwargs, keyword)) {
      if (py::isinstance<py::str>(*v)) {
        list.push_back(v->cast<std::string>());
      } else {
        for (const py::handle item : *v) list.push_back(py::str(item).cast<std::string>());
      }
    }
    return list;
  };
  const std::vector<std::string> material_names = names("materials");
  const std::vector<std::string> families = names("families");
  try {
    request.materials = optim::SelectCandidates(materials::Catalog::BuiltIn(), material_names, families);
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    throw std::invalid_argument((what.rfind("no family", 0) == 0 ? "families: " : "materials: ") + what);
  }
  request.rule = JudgeOptions(inputs, kwargs).rule;
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
  const auto head_dict = [](const optim::DesignScore& s, double safety_factor) {
    py::dict d;
    d["laceration_ratio"] = s.laceration_ratio;
    d["contusion_ratio"] = s.contusion_ratio;
    d["compression_ratio"] = s.compression_ratio;
    d["safe"] = s.safe(safety_factor);
    return d;
  };
  const double sf = request.rule.safety_factor;
  py::dict d;
  d["message"] = result.message;
  d["speed_m_per_s"] = request.scene.speed_m_per_s;
  py::list bare;
  for (const auto& j : result.bare_robot) bare.append(JudgementDict(j));
  d["bare_robot"] = bare;
  d["bare_head"] = result.bare_head ? py::object(head_dict(*result.bare_head, sf)) : py::object(py::none());
  d["bare_robot_safe"] = result.bare_robot_safe;
  py::list candidates;
  for (const optim::BodyRegionDesignCandidate& c : result.candidates) {
    py::dict cd;
    cd["material"] = c.material.name;
    cd["family"] = c.material.family;
    cd["thickness_m"] = OrNone(c.thickness_m);
    cd["admissible"] = c.admissible();
    cd["governing_ratio"] = c.governing_ratio;
    cd["governing_where"] = c.governing_where;
    py::list regions;
    for (const auto& j : c.regions) regions.append(JudgementDict(j));
    cd["regions"] = regions;
    cd["head"] = c.head ? py::object(head_dict(*c.head, sf)) : py::object(py::none());
    candidates.append(cd);
  }
  d["candidates"] = candidates;
  d["recommendation"] = result.recommendation ? py::object(candidates[*result.recommendation]) : py::object(py::none());
  d["scope"] = py::cast(result.scope);
  d["warnings"] = py::cast(result.warnings);
  d["safety_factor"] = sf;
  return d;
}

}  // namespace

void RegisterBodyContact(py::module_& m) {
  m.def("simulate_body_region", &Simulate);
  m.def("body_region_speed_limit", &SpeedLimitTable);
  m.def("design_for_body_regions", &Design);
}

}  // namespace covopt::python
