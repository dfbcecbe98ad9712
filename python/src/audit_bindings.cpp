/// @file audit_bindings.cpp
/// covopt.audit: the whole robot along its motion, as `covopt audit --json` (the dict is
/// report::AuditJson, the CLI's). The keywords every command shares are read here as the other
/// functions read them: the robot as covopt.contact_motion (robot_inputs.hpp), the covering for
/// all links, the head and the limits from a covopt.Scene, the regions as
/// covopt.simulate(body_region=...) (body_region_inputs.hpp); the audit itself is assembled by
/// covopt::audit::AssembleAudit, the call `covopt audit` makes. See python/covopt/_audit.py for
/// the documentation.

#include <array>
#include <map>
#include <sstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "body_region_inputs.hpp"
#include "covopt/audit/assemble.hpp"
#include "covopt/audit/audit.hpp"
#include "covopt/report/audit_json.hpp"
#include "covopt/report/output_file.hpp"
#include "covopt/report/retime_json.hpp"
#include "covopt/audit/retime.hpp"
#include "covopt/audit/retime_inputs.hpp"
#include "covopt/chart/retime_charts.hpp"
#include "covopt/robot/trajectory.hpp"
#include "covopt/robot/payload.hpp"
#include "covopt/robot/surface.hpp"
#include "covopt/scene_file/link_coverings.hpp"
#include "covopt/chart/region_charts.hpp"
#include "report_charts.hpp"
#include "robot_inputs.hpp"
#include "scene_keywords.hpp"

namespace py = pybind11;

namespace covopt::python {
namespace {

std::string Path(const py::handle& value) {
  return py::str(py::module_::import("os").attr("fspath")(value)).cast<std::string>();
}

/// A length keyword [m] (a number in m, or a string with its unit), > 0.
std::optional<double> Length(const py::kwargs& kwargs, const char* keyword) {
  const auto v = Option(kwargs, keyword);
  if (!v) return std::nullopt;
  static constexpr QuantitySpec kLength{QuantityKind::kLength, false, false, 0.0, 1000.0, {"mm", "cm"}, "length"};
  const double value = ReadSceneQuantity(*v, kLength, keyword);
  if (!(value > 0.0)) throw std::invalid_argument(std::string(keyword) + ": must be a length > 0");
  return value;
}

std::vector<std::string> Names(const py::kwargs& kwargs, const char* keyword) {
  std::vector<std::string> names;
  if (const auto v = Option(kwargs, keyword)) {
    if (py::isinstance<py::str>(*v)) {
      names.push_back(v->cast<std::string>());
    } else {
      for (const py::handle item : *v) names.push_back(py::str(item).cast<std::string>());
    }
  }
  return names;
}

/// payload_mass= (kg, or "500g"), payload_com= (x, y, z) [m], payload_inertia= (ixx, iyy, izz,
/// ixy, ixz, iyz) [kg m²], as the CLI's --payload-* flags.
robot::Payload ReadPayload(const py::kwargs& kwargs) {
  robot::Payload payload;
  const auto mass = Option(kwargs, "payload_mass");
  if (!mass) {
    if (Option(kwargs, "payload_com") || Option(kwargs, "payload_inertia")) {
      throw std::invalid_argument("payload_com and payload_inertia need payload_mass (the payload's mass in kg)");
    }
    return payload;
  }
  static constexpr QuantitySpec kMass{QuantityKind::kMass, false, false, 0.0, robot::kMaxPayloadMassKg, {"g", ""},
                                      "payload mass"};
  payload.mass_kg = ReadSceneQuantity(*mass, kMass, "payload_mass");
  if (const auto com = Option(kwargs, "payload_com")) payload.center_of_mass_m = Triple(*com, "payload_com");
  if (const auto inertia = Option(kwargs, "payload_inertia")) payload.inertia_kg_m2 = PayloadInertia(*inertia);
  robot::CheckPayload(payload, robot::PayloadInputNames{"payload_mass", "payload_com", "payload_inertia"});
  return payload;
}

/// link_coverings=: a link-covering file (str or os.PathLike, read by the library), or a dict
/// {link: {material or modulus (and poisson), thickness}} with the file's keys and values.
std::variant<std::string, std::vector<scene_file::LinkCoveringEntry>> ReadLinkCoverings(const py::object& value) {
  if (!py::isinstance<py::dict>(value)) {
    if (!py::isinstance<py::str>(value) && !py::hasattr(value, "__fspath__")) {
      throw std::invalid_argument("link_coverings: expected a link-covering file (a path) or a dict {link: {material "
                                  "or modulus (and poisson), thickness}} (got " +
                                  py::repr(value).cast<std::string>() + ")");
    }
    return Path(value);
  }
  std::vector<scene_file::LinkCoveringEntry> entries;
  for (const auto& [key, item] : value.cast<py::dict>()) {
    scene_file::LinkCoveringEntry entry;
    entry.link = py::str(key).cast<std::string>();
    if (auto problem = scene_file::NameProblem("link name", entry.link)) {
      throw std::invalid_argument("link_coverings: " + *problem);
    }
    entry.where = "link_coverings['" + entry.link + "']";
    if (!py::isinstance<py::dict>(item)) {
      throw std::invalid_argument(entry.where + ": expected a dict of material or modulus (and poisson), thickness (got " +
                                  py::repr(item).cast<std::string>() + ")");
    }
    const py::dict fields = item.cast<py::dict>();
    for (const auto& [name, _] : fields) {
      const std::string k = py::str(name).cast<std::string>();
      if (k != "material" && k != "modulus" && k != "poisson" && k != "thickness") {
        throw std::invalid_argument(entry.where + ": unknown key '" + k +
                                    "' (a link takes material or modulus (and poisson), thickness)");
      }
    }
    if (!fields.contains("thickness")) throw std::invalid_argument(entry.where + ": needs thickness");
    entry.thickness_m = ReadSceneQuantity(fields["thickness"], quantity_specs::kCoveringThickness,
                                          entry.where + " thickness");
    if (fields.contains("material")) {
      if (!py::isinstance<py::str>(fields["material"])) {
        throw std::invalid_argument(entry.where + " material: expected a catalog name (a string), got " +
                                    py::repr(fields["material"]).cast<std::string>());
      }
      entry.material = fields["material"].cast<std::string>();
      if (auto problem = scene_file::NameProblem("material name", *entry.material)) {
        throw std::invalid_argument(entry.where + " material: " + *problem);
      }
    }
    if (fields.contains("modulus")) {
      if (entry.material) throw std::invalid_argument(entry.where + ": give either material or modulus, not both");
      entry.modulus_Pa = ReadSceneQuantity(fields["modulus"], quantity_specs::kCoveringModulus, entry.where + " modulus");
    }
    if (fields.contains("poisson")) {
      if (!entry.modulus_Pa) throw std::invalid_argument(entry.where + ": poisson is given with modulus only");
      entry.poisson_ratio = ReadSceneQuantity(fields["poisson"], quantity_specs::kPoissonRatio, entry.where + " poisson");
    }
    if (auto problem = scene_file::CheckLinkCovering(entry)) {
      throw std::invalid_argument(entry.where + " " + problem->message);  // the file's ranges
    }
    if (entry.thickness_m > 0.0 && !entry.material && !entry.modulus_Pa) {
      throw std::invalid_argument(entry.where + ": a covering needs material or modulus (thickness 0: bare)");
    }
    entries.push_back(std::move(entry));
  }
  return entries;
}

/// The design's keywords.
void SetDesignKeywords(const py::kwargs& kwargs, audit::AuditInputs& in) {
  in.design = Flag(kwargs, "design");
  in.design_materials = Names(kwargs, "materials");
  in.families = Names(kwargs, "families");
  in.allow_unknown_strength = Flag(kwargs, "allow_unknown_strength");
  if (const auto v = Option(kwargs, "max_thickness")) {
    in.max_thickness_m = ReadSceneQuantity(*v, quantity_specs::kCoveringThickness, "max_thickness");
  }
  if (const auto v = Option(kwargs, "thickness_step")) {
    in.thickness_step_m = ReadSceneQuantity(*v, quantity_specs::kThicknessStep, "thickness_step");
  }
}

/// exposure=: an exposure file (a path), or a list of zones as dicts {name, min_m, max_m, regions}.
std::variant<std::string, std::vector<audit::ExposureZone>> Exposure(const py::handle& value) {
  if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__")) return Path(value);
  std::vector<audit::ExposureZone> zones;
  std::size_t index = 0;
  for (const py::handle item : value) {
    const std::string where = "exposure[" + std::to_string(index++) + "]";
    if (!py::isinstance<py::dict>(item)) throw std::invalid_argument(where + ": expected a dict (name, min_m, max_m, regions)");
    const py::dict zone = py::reinterpret_borrow<py::dict>(item);
    for (const auto& [key, unused] : zone) {
      const std::string k = py::str(key).cast<std::string>();
      if (k != "name" && k != "min_m" && k != "max_m" && k != "regions") {
        throw std::invalid_argument(where + ": unknown key '" + k + "' (a zone takes name, min_m, max_m, regions)");
      }
    }
    const auto corner = [&](const char* key) {
      if (!zone.contains(key)) throw std::invalid_argument(where + ": " + key + " is required ([x, y, z] in m)");
      const std::vector<double> v = zone[key].cast<std::vector<double>>();
      if (v.size() != 3) throw std::invalid_argument(where + ": " + key + ": expected [x, y, z] in m");
      return Eigen::Vector3d(v[0], v[1], v[2]);
    };
    audit::ExposureZone z{.name = zone.contains("name") ? py::str(zone["name"]).cast<std::string>() : std::string(),
                          .min_m = corner("min_m"),
                          .max_m = corner("max_m"),
                          .regions = {},
                          .origin = where};
    if (zone.contains("regions")) {
      const py::object regions = zone["regions"];
      if (py::isinstance<py::str>(regions)) z.regions.push_back(regions.cast<std::string>());
      else for (const py::handle r : regions) z.regions.push_back(py::str(r).cast<std::string>());
    }
    zones.push_back(std::move(z));
  }
  return zones;
}

/// The audit assembled from its keywords (covopt::audit::AssembleAudit), as covopt.audit and
/// covopt.retime both take them.
audit::AssembledAudit AssembleFromKeywords(const py::object& urdf, const std::string& tip, const py::object& trajectory,
                                           const std::optional<std::string>& base,
                                           const std::optional<std::string>& urdf_text, const SceneInputs& inputs,
                                           const py::kwargs& kwargs) {
  py::kwargs region_kwargs = kwargs;
  if (!Option(region_kwargs, "body_region")) region_kwargs["body_region"] = audit::kDefaultBodyRegions;
  const BodyRegionSelection regions = SelectBodyRegions(inputs, region_kwargs);

  // The library's input names are Python's keywords (AuditFieldNames' defaults).
  audit::AuditInputs in(Chain(urdf, urdf_text, tip, base).WithPayload(ReadPayload(kwargs)),
                        urdf_text ? std::string() : Path(urdf));
  in.urdf_text = urdf_text;
  if (const auto spacing = Length(kwargs, "surface_spacing")) in.surface.spacing_m = *spacing;
  in.surface.box_edge_radius_m = Length(kwargs, "box_edge_radius");
  if (const auto file = Option(kwargs, "surface_file")) in.surface.surface_file = Path(*file);
  in.flat_face_radius_m = Length(kwargs, "flat_face_radius");
  in.reflected_mass = ReflectedMassOptions(Flag(kwargs, "ignore_joint_limits"));
  if (py::isinstance<py::dict>(trajectory)) {
    in.trajectory = Trajectory(trajectory, in.chain.joint_count());
  } else {
    in.trajectory = Path(trajectory);
  }
  in.scene = inputs.scene;
  for (const auto& [keyword, field] : {std::pair{"robot_mass", "robot.mass"}, std::pair{"speed", "robot.speed"},
                                       std::pair{"robot_radius", "robot.radius"}}) {
    if (inputs.Gave(keyword)) in.given_robot_inputs.emplace(field, py::str(inputs.given[keyword]).cast<std::string>());
  }
  in.regions = regions.limits;
  in.contact = regions.contact;
  in.contact_area_m2 = regions.contact_area_m2;
  in.head = regions.head;
  in.judge = regions.judge;
  if (const auto value = Option(kwargs, "link_coverings")) in.link_coverings = ReadLinkCoverings(*value);
  // The tool, the payload and the exposure zones.
  in.tool_surface = Names(kwargs, "tool_surface");
  in.payload_surface = Names(kwargs, "payload_surface");
  if (const auto value = Option(kwargs, "exposure")) in.exposure = Exposure(*value);
  SetDesignKeywords(kwargs, in);
  if (const auto keep = Option(kwargs, "keep_ratio_over_time")) in.keep_ratio_over_time = Bool(*keep, "keep_ratio_over_time");
  in.scene_warnings = InputAndCrushWarnings(inputs);
  audit::AssembledAudit assembled = audit::AssembleAudit(in);
  assembled.setup.keep_travel = Flag(kwargs, "keep_travel");
  return assembled;
}

py::object Audit(const py::object& urdf, const std::string& tip, const py::object& trajectory,
                 const std::optional<std::string>& base, const std::optional<std::string>& urdf_text,
                 const SceneInputs& inputs, const py::kwargs& kwargs) {
  const audit::AssembledAudit assembled = AssembleFromKeywords(urdf, tip, trajectory, base, urdf_text, inputs, kwargs);
  audit::AuditResult result;
  try {
    py::gil_scoped_release release;
    result = audit::Audit(assembled.setup, assembled.trajectory, assembled.options);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(inputs.Attributed(e.what()));
  }
  py::dict d = JsonToPython(report::AuditJson(assembled.setup, result, assembled.input_warnings, -1));
  // The link x region map always; the map over time needs keep_ratio_over_time=True.
  return WithReportCharts(std::move(d), [result, sf = assembled.setup.rule.safety_factor,
                                         name = TrajectoryName(trajectory)] {
    std::vector charts{chart::AuditRegionMap(result, sf)};
    if (!result.ratio_over_time.empty()) charts.push_back(chart::AuditHeatMap(result, sf, name));
    return charts;
  });
}

/// A joint limit keyword: one number for every joint, or a sequence of one per joint.
std::optional<Eigen::VectorXd> JointLimits(const py::kwargs& kwargs, const char* keyword, std::size_t joints,
                                           double max, bool allow_infinite) {
  const auto v = Option(kwargs, keyword);
  if (!v) return std::nullopt;
  std::vector<double> values;
  const auto number = [&](const py::handle& item) {
    if (py::isinstance<py::str>(item) || py::isinstance<py::bool_>(item)) throw py::cast_error("not a number");
    return item.cast<double>();
  };
  try {
    if (!py::isinstance<py::str>(*v) && py::hasattr(*v, "__iter__")) {
      for (const py::handle item : *v) values.push_back(number(item));
    } else {
      values.push_back(number(*v));
    }
  } catch (const py::cast_error&) {
    throw std::invalid_argument(std::string(keyword) + ": expected a number (SI: rad/s, rad/s²) or one per joint (got " +
                                py::repr(*v).cast<std::string>() + ")");
  }
  return audit::JointLimitVector(values, joints, keyword, max, allow_infinite);
}

/// thickness=: a sweep spec ("0..40mm:9") or a sequence of lengths.
std::vector<double> Thicknesses(const py::object& value) {
  if (py::isinstance<py::str>(value)) return audit::ThicknessGrid(value.cast<std::string>(), "thickness");
  if (!py::hasattr(value, "__iter__")) {
    throw std::invalid_argument("thickness: expected a sweep (\"0..40mm:9\") or a list of lengths (got " +
                                py::repr(value).cast<std::string>() + ")");
  }
  std::string spec;
  for (const py::handle item : value) {
    spec += (spec.empty() ? "" : ",") + py::str(item).cast<std::string>();
  }
  return audit::ThicknessGrid(spec, "thickness");
}

py::object Retime(const py::object& urdf, const std::string& tip, const py::object& trajectory,
                  const std::optional<std::string>& base, const std::optional<std::string>& urdf_text,
                  const SceneInputs& inputs, const py::kwargs& given) {
  // materials= is the sweep's here; the per-link design's materials are design_materials=.
  py::kwargs kwargs;
  for (const auto& [key, value] : given) {
    const std::string k = py::str(key).cast<std::string>();
    if (k == "materials" || k == "joint_accel_limit" || k == "joint_speed_limit" || k == "max_speed_scale" ||
        k == "thickness") {
      continue;
    }
    kwargs[py::str(k == "design_materials" ? "materials" : k)] = value;
  }
  kwargs["keep_ratio_over_time"] = false;
  const audit::AssembledAudit assembled = AssembleFromKeywords(urdf, tip, trajectory, base, urdf_text, inputs, kwargs);
  const std::size_t joints = assembled.setup.chain.joint_count();
  audit::RetimeOptions options;
  options.joint_acceleration_limits =
      JointLimits(given, "joint_accel_limit", joints, audit::kMaxJointAccelerationLimit, false);
  if (!options.joint_acceleration_limits) {
    throw std::invalid_argument("joint_accel_limit is required (the URDF gives no acceleration limit): one number in "
                                "rad/s² for every joint, or one per joint");
  }
  options.joint_speed_limits = JointLimits(given, "joint_speed_limit", joints, audit::kMaxJointSpeedLimit, true);
  if (const auto v = Option(given, "max_speed_scale")) {
    if (!py::isinstance<py::int_>(*v) && !py::isinstance<py::float_>(*v)) {
      throw std::invalid_argument("max_speed_scale: expected a number in (0, 100] (got " + py::repr(*v).cast<std::string>() + ")");
    }
    options.max_speed_scale = v->cast<double>();
  }
  std::optional<report::RetimeSweep> sweep;
  if (const auto v = Option(given, "thickness")) {
    sweep.emplace();
    sweep->thicknesses_m = Thicknesses(*v);
    sweep->designs = audit::CycleTimeDesigns(assembled, materials::Catalog::BuiltIn(), Names(given, "materials"),
                                             Flag(given, "design"), "materials");
  } else if (Option(given, "materials")) {
    throw std::invalid_argument("materials: the sweep's materials need thickness= (the thicknesses to sweep)");
  }
  audit::RetimeResult result;
  try {
    py::gil_scoped_release release;
    result = audit::Retime(assembled.setup, assembled.trajectory, options);
    if (sweep) {
      sweep->points = audit::CycleTimeAgainstThickness(assembled.setup, assembled.trajectory, options, sweep->designs,
                                                       sweep->thicknesses_m);
    }
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(inputs.Attributed(e.what()));
  }
  const bool answer = result.status == audit::RetimeStatus::kSafe || result.status == audit::RetimeStatus::kAtRest;
  if (const auto file = Option(given, "output"); file && answer) {
    std::ostringstream csv;
    robot::WriteJointTrajectory(csv, result.trajectory, assembled.setup.chain.joint_names());
    report::WriteFileAtomically(Path(*file), csv.str());
  }
  py::dict d = JsonToPython(
      report::RetimeJson(assembled.setup, result, options, sweep ? &*sweep : nullptr, assembled.input_warnings, -1));
  return WithReportCharts(std::move(d), [result, sweep, name = TrajectoryName(trajectory)] {
    std::vector<chart::GnuplotChart> charts;
    if (!result.path_speed.empty()) charts.push_back(chart::RetimeSpeedChart(result, name));
    if (sweep && !sweep->points.empty()) charts.push_back(chart::CycleTimeChart(*sweep, result.original_cycle_time_s));
    return charts;
  });
}

}  // namespace

void BindAudit(py::module_& m) {
  m.def("audit", &Audit, py::arg("urdf"), py::arg("tip"), py::arg("trajectory"), py::arg("base"),
        py::arg("urdf_text"), py::arg("scene"));
  m.def("retime", &Retime, py::arg("urdf"), py::arg("tip"), py::arg("trajectory"), py::arg("base"),
        py::arg("urdf_text"), py::arg("scene"));
}

}  // namespace covopt::python
