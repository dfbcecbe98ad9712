// The whole robot along its motion as JSON text and CSV (covopt audit --json/--csv,
// covopt.audit()).
#include "covopt/report/audit_json.hpp"

#include <array>
#include <cmath>

#include <covopt/core/number_format.hpp>
#include <nlohmann/json.hpp>

#include "covopt/optim/body_region_check.hpp"
#include "covopt/audit/summary.hpp"
#include "json_number.hpp"
#include "summary_object.hpp"

namespace covopt::report {
namespace {

using nlohmann::ordered_json;

constexpr std::array<std::string_view, 19> kCellColumns = {
    "link",              "region",            "governing_ratio",   "binding",
    "sample",            "time_s",            "point",             "point_in_link_x_m",
    "point_in_link_y_m", "point_in_link_z_m", "point_in_base_x_m", "point_in_base_y_m",
    "point_in_base_z_m", "speed_m_per_s",     "reflected_mass_kg", "max_safe_speed_m_per_s",
    "speed_scale",       "head_criterion",    "not_judged"};

ordered_json Vector(const Eigen::Vector3d& v) {
  return ordered_json::array({internal::Number(v[0]), internal::Number(v[1]), internal::Number(v[2])});
}

/// A cell with its point's coordinates split (the CSV's columns, in kCellColumns order).
ordered_json FlatCell(const audit::AuditResult& result, const audit::AuditCell& cell) {
  const bool moved = cell.sample.has_value();
  const auto when_moved = [moved](ordered_json value) { return moved ? std::move(value) : ordered_json(nullptr); };
  ordered_json j;
  j["link"] = result.links.at(cell.link);
  j["region"] = result.regions.at(cell.region);
  j["governing_ratio"] = internal::Number(cell.governing_ratio);
  j["binding"] = moved ? ordered_json(cell.binding_name()) : ordered_json(nullptr);
  j["sample"] = moved ? ordered_json(*cell.sample) : ordered_json(nullptr);
  j["time_s"] = when_moved(internal::Number(cell.time_s));
  j["point"] = when_moved(ordered_json(cell.point));
  const char* axes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    j[std::string("point_in_link_") + axes[i] + "_m"] = when_moved(internal::Number(cell.point_in_link_m[i]));
  }
  for (int i = 0; i < 3; ++i) {
    j[std::string("point_in_base_") + axes[i] + "_m"] = when_moved(internal::Number(cell.point_in_base_m[i]));
  }
  j["speed_m_per_s"] = when_moved(internal::Number(cell.speed_m_per_s));
  j["reflected_mass_kg"] = when_moved(internal::Number(cell.reflected_mass_kg));
  j["max_safe_speed_m_per_s"] = when_moved(internal::Number(cell.max_safe_speed_m_per_s));
  j["speed_scale"] = internal::Number(cell.speed_scale);  // +inf (never moves): null
  j["head_criterion"] = moved && cell.head_criterion != optim::LimitingCriterion::kNone
                            ? ordered_json(optim::ToString(cell.head_criterion))
                            : ordered_json(nullptr);
  j["not_judged"] = cell.not_judged.empty() ? ordered_json(nullptr) : ordered_json(cell.not_judged);
  return j;
}

/// The exposure zones judged with; null without zones.
ordered_json ZonesJson(const audit::AuditResult& result) {
  if (result.exposure_zones.empty()) return nullptr;
  ordered_json zones = ordered_json::array();
  for (const audit::ExposureZone& zone : result.exposure_zones) {
    zones.push_back(ordered_json{{"name", zone.name},
                                 {"min_m", Vector(zone.min_m)},
                                 {"max_m", Vector(zone.max_m)},
                                 {"regions", zone.regions},
                                 {"origin", zone.origin}});
  }
  return zones;
}

std::string CsvText(const ordered_json& value) {
  if (value.is_null()) return {};
  if (value.is_string()) return value.get<std::string>();
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  if (value.is_number_unsigned()) return std::to_string(value.get<std::size_t>());
  return FormatShortest(value.get<double>());
}

ordered_json CoveringJson(const std::string& link, const audit::AuditCovering& covering, const char* from) {
  ordered_json j;
  j["link"] = link;
  j["material"] = covering.material && covering.covering.thickness_m > 0.0 ? ordered_json(covering.material->name)
                                                                          : ordered_json(nullptr);
  j["modulus_Pa"] = internal::Number(covering.covering.youngs_modulus_Pa);
  j["poisson_ratio"] = internal::Number(covering.covering.poisson_ratio);
  j["thickness_m"] = internal::Number(covering.covering.thickness_m);
  // The law that describes it (a measured curve takes the foam law unless Hertz is
  // asked for); "" bare. Each cell's limit counts the law's validity ("law-validity").
  const CoveringSpec& spec = covering.covering;
  j["covering_law"] = !(spec.thickness_m > 0.0) ? "" : spec.compressive_curve && spec.law != CoveringLaw::kHertz ? "foam" : "hertz";
  j["from"] = from;
  return j;
}

/// The audited robot: its name, chain and payload (null without one).
ordered_json RobotJson(const robot::KinematicChain& chain) {
  ordered_json robot;
  robot["name"] = chain.robot_name();
  robot["base_link"] = chain.base_link();
  robot["tip_link"] = chain.tip_link();
  robot["joint_names"] = chain.joint_names();
  if (const robot::Payload& payload = chain.payload(); !payload.empty()) {
    ordered_json p;
    p["mass_kg"] = internal::Number(payload.mass_kg);
    p["center_of_mass_m"] = Vector(payload.center_of_mass_m);
    ordered_json inertia = ordered_json::array();
    for (int r = 0; r < 3; ++r) inertia.push_back(Vector(payload.inertia_kg_m2.row(r).transpose()));
    p["inertia_kg_m2"] = std::move(inertia);
    robot["payload"] = std::move(p);
  } else {
    robot["payload"] = nullptr;
  }
  return robot;
}

/// The surface judged: its spacing and each link's number of points.
ordered_json SurfaceJson(const robot::RobotSurface& surface_in) {
  ordered_json surface;
  surface["spacing_m"] = internal::Number(surface_in.spacing_m);
  ordered_json links = ordered_json::array();
  for (const robot::LinkSurface& link : surface_in.links) {
    links.push_back(ordered_json{{"name", link.link},
                                 {"point_count", link.points.size()},
                                 {"carried_by", link.frame_link.empty() ? ordered_json(nullptr) : ordered_json(link.frame_link)}});
  }
  surface["links"] = std::move(links);
  return surface;
}

}  // namespace

std::span<const std::string_view> AuditCellColumns() noexcept { return kCellColumns; }

std::vector<std::string> AuditCellCsvCells(const audit::AuditResult& result, const audit::AuditCell& cell) {
  const ordered_json flat = FlatCell(result, cell);
  std::vector<std::string> cells;
  for (const auto& [key, value] : flat.items()) cells.push_back(CsvText(value));
  return cells;
}

std::vector<std::string> AuditSampleColumns(std::span<const std::string> links) {
  std::vector<std::string> columns{"sample", "time_s"};
  for (const std::string& link : links) {
    columns.push_back(link + "_ratio");
    columns.push_back(link + "_region");
  }
  return columns;
}

std::vector<std::string> AuditSampleCsvCells(const audit::AuditSampleRow& row, std::span<const std::string> regions) {
  std::vector<std::string> cells{std::to_string(row.sample), FormatShortest(row.time_s)};
  for (std::size_t i = 0; i < row.link_ratio.size(); ++i) {
    const double ratio = row.link_ratio[i];
    cells.push_back(FormatShortest(ratio));
    const std::size_t region = i < row.link_region.size() ? row.link_region[i] : regions.size();
    cells.push_back(ratio > 0.0 && region < regions.size() ? regions[region] : std::string());
  }
  return cells;
}

std::string AuditJson(const audit::AuditSetup& setup, const audit::AuditResult& result,
                      std::span<const std::string> input_warnings, int indent) {
  const bool head = setup.head.has_value();
  ordered_json j;
  j["status"] = optim::ToString(result.status);
  j["message"] = result.message;
  j["summary"] = internal::SummaryObject(audit::SummarizeAudit(setup, result));
  j["safe_speed_scale"] = internal::Number(result.safe_speed_scale);
  if (result.limiting_cell && *result.limiting_cell < result.cells.size()) {
    const audit::AuditCell& cell = result.cells[*result.limiting_cell];
    ordered_json limiting;
    limiting["link"] = result.links.at(cell.link);
    limiting["region"] = result.regions.at(cell.region);
    limiting["binding"] = cell.binding_name();
    limiting["time_s"] = internal::Number(cell.time_s);
    limiting["governing_ratio"] = internal::Number(cell.governing_ratio);
    j["limiting"] = std::move(limiting);
  } else {
    j["limiting"] = nullptr;
  }
  j["criterion"] = optim::BodyRegionCriterion(setup.rule, head, setup.regions.empty() ? std::string() : setup.regions.front().Citation());
  j["safety_factor"] = internal::Number(setup.rule.safety_factor);
  j["contact_area_m2"] = setup.contact_area_m2 > 0.0 ? internal::Number(setup.contact_area_m2) : ordered_json(nullptr);
  j["reaction_delay_s"] = internal::Number(setup.reaction_delay_s);
  j["braking_m_per_s2"] = internal::Number(setup.braking_m_per_s2);

  j["robot"] = RobotJson(setup.chain);
  j["surface"] = SurfaceJson(setup.surface);
  j["sample_count"] = result.sample_count;
  j["regions"] = result.regions;
  j["scope"] = result.scope;
  j["exposure_zones"] = ZonesJson(result);
  j["not_judged_cells"] = result.not_judged_cells;

  ordered_json coverings = ordered_json::array();
  for (const std::string& link : result.links) {
    const auto own = setup.link_coverings.find(link);
    coverings.push_back(own != setup.link_coverings.end() ? CoveringJson(link, own->second, "link file")
                                                          : CoveringJson(link, setup.covering, "all links"));
  }
  j["coverings"] = std::move(coverings);

  ordered_json cells = ordered_json::array();
  for (const audit::AuditCell& cell : result.cells) {
    ordered_json flat = FlatCell(result, cell);
    // The point's coordinates as vectors in the JSON (the CSV splits them).
    const bool moved = cell.sample.has_value();
    ordered_json c;
    for (const auto& [key, value] : flat.items()) {
      if (key.rfind("point_in_", 0) == 0) {
        if (key == "point_in_link_x_m") c["point_in_link_m"] = moved ? Vector(cell.point_in_link_m) : ordered_json(nullptr);
        if (key == "point_in_base_x_m") c["point_in_base_m"] = moved ? Vector(cell.point_in_base_m) : ordered_json(nullptr);
        continue;
      }
      c[key] = value;
    }
    cells.push_back(std::move(c));
  }
  j["cells"] = std::move(cells);

  const std::size_t link_count = result.links.size();
  if (!result.ratio_over_time.empty() && link_count > 0) {
    ordered_json over_time;
    over_time["time_s"] = result.time_s;
    over_time["links"] = result.links;
    ordered_json rows = ordered_json::array();
    for (std::size_t s = 0; s * link_count < result.ratio_over_time.size(); ++s) {
      ordered_json row = ordered_json::array();
      for (std::size_t l = 0; l < link_count; ++l) row.push_back(internal::Number(result.ratio_over_time[s * link_count + l]));
      rows.push_back(std::move(row));
    }
    over_time["ratio"] = std::move(rows);
    j["ratio_over_time"] = std::move(over_time);
  } else {
    j["ratio_over_time"] = nullptr;
  }

  ordered_json designs = ordered_json::array();
  for (const audit::AuditLinkDesign& design : result.link_designs) {
    ordered_json d;
    d["link"] = result.links.at(design.link);
    d["material"] = design.material ? ordered_json(design.material->name) : ordered_json(nullptr);
    d["thickness_m"] = internal::Number(design.thickness_m);
    d["governing_ratio"] = internal::Number(design.governing_ratio);
    d["message"] = design.message;
    designs.push_back(std::move(d));
  }
  j["link_designs"] = std::move(designs);

  std::vector<std::string> warnings(input_warnings.begin(), input_warnings.end());
  warnings.insert(warnings.end(), result.warnings.begin(), result.warnings.end());
  j["warnings"] = std::move(warnings);
  return j.dump(indent);
}

}  // namespace covopt::report
