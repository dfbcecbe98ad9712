// `covopt audit`: every surface point of every link, every exposed body region (and the head),
// along a trajectory (docs/model.md §14). Per link, distinct radius of curvature and region the
// energy admitted at the binding limit, E* = ½ μ v_max², is computed once (MaxSafeSpeed at a
// fixed robot, μ = m_H); a point-sample then costs its kinematics and one square root per
// region, v_max(m) = sqrt(2 E* (1/m + 1/m_H)).
#include "covopt/audit/audit.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <covopt/core/number_format.hpp>
#include <covopt/core/poisson_ratio.hpp>

#include "audit_internal.hpp"
#include "validation_internal.hpp"

namespace covopt::audit {
using namespace detail;
namespace {

using optim::internal::Number;
using optim::internal::Require;

std::string LinkName(const robot::LinkSurface& link) { return "'" + link.link + "'"; }

void ValidateCovering(const AuditCovering& c, const std::string& where) {
  const CoveringSpec& s = c.covering;
  Require(std::isfinite(s.thickness_m) && s.thickness_m >= 0.0 && s.thickness_m <= 1.0,
          where + ".covering.thickness_m must be in [0, 1] m (0: bare) (got " + Number(s.thickness_m) + ")");
  if (s.thickness_m == 0.0) return;
  Require(std::isfinite(s.youngs_modulus_Pa) && s.youngs_modulus_Pa > 0.0 && s.youngs_modulus_Pa <= 1e13,
          where + ".covering.youngs_modulus_Pa must be in (0, 1e13] Pa (got " + Number(s.youngs_modulus_Pa) + ")");
  Require(IsPoissonRatio(s.poisson_ratio), where + ".covering.poisson_ratio must be in " +
                                                std::string(kPoissonRatioRange) + " (got " + Number(s.poisson_ratio) + ")");
}

void ValidateDesign(const AuditDesignOptions& d) {
  if (d.materials.empty()) return;
  optim::internal::ValidateThicknessScan(d.min_thickness_m, d.max_thickness_m, d.thickness_scan_points,
                                  d.thickness_resolution_m, d.thickness_step_m, "design.");
  for (const CandidateMaterial& m : d.materials) optim::internal::ValidateCandidateMaterial(m, "design material ");
}

void ValidateSetup(const AuditSetup& s) {
  Require(!s.regions.empty() || s.head.has_value(), "regions: no body region to judge and no head");
  Require(!s.surface.links.empty(), "surface: no link has a surface (no collision geometry on the chain)");
  for (std::size_t i = 0; i < s.regions.size(); ++i) {
    const materials::BodyLimits& limits = s.regions[i];
    Require(limits.region != nullptr && limits.area != nullptr,
            "regions[" + std::to_string(i) + "]: no body region and area given");
    Require(limits.contact == ContactType::kTransient,
            "regions[" + std::to_string(i) + "]: " + limits.region->name + " (" + limits.area->name +
                ") is clamped (quasi-static); an audit judges the free (transient) impacts of a motion");
  }
  if (s.head) {
    const Scene& h = *s.head;
    Require(!h.is_damped(), "head: model.damping_s_per_m must be 0 in an audit (got " +
                                Number(h.model.damping_s_per_m) +
                                "): its energy invariant needs the conservative head model");
    Require(!h.head.has_neck(), "head: head.torso_mass_kg must be 0 in an audit (got " + Number(h.head.torso_mass_kg) +
                                    "): its energy invariant needs a free head without a neck");
    Require(std::isfinite(h.head.mass_kg) && h.head.mass_kg > 0.0,
            "head: head.mass_kg must be finite and > 0 kg in an audit (got " + Number(h.head.mass_kg) +
                "): a fixed head is a clamped contact, and an audit judges free impacts");
    Require(h.robot.braking_m_per_s2 == 0.0 && h.robot.reaction_delay_s == 0.0,
            "head: robot.braking_m_per_s2 and robot.reaction_delay_s must be 0 in the head scene (got " +
                Number(h.robot.braking_m_per_s2) + " m/s², " + Number(h.robot.reaction_delay_s) +
                " s): the audit's braking is AuditSetup::braking_m_per_s2 and reaction_delay_s, for every region");
  }
  Require(std::isfinite(s.contact_area_m2) && s.contact_area_m2 >= 0.0 && s.contact_area_m2 <= 1.0,
          "contact_area_m2 must be in [0, 1] m² (0: not given) (got " + Number(s.contact_area_m2) + ")");
  Require(!s.flat_face_radius_m || (std::isfinite(*s.flat_face_radius_m) && *s.flat_face_radius_m > 0.0 &&
                                    *s.flat_face_radius_m <= 100.0),
          "flat_face_radius_m must be in (0, 100] m (got " + Number(s.flat_face_radius_m.value_or(0.0)) + ")");
  Require(std::isfinite(s.reaction_delay_s) && s.reaction_delay_s >= 0.0 && s.reaction_delay_s <= 10.0,
          "reaction_delay_s must be in [0, 10] s (got " + Number(s.reaction_delay_s) + ")");
  Require(std::isfinite(s.braking_m_per_s2) && s.braking_m_per_s2 >= 0.0 && s.braking_m_per_s2 <= 1e4,
          "braking_m_per_s2 must be in [0, 1e4] m/s² (got " + Number(s.braking_m_per_s2) + ")");
  Require(std::isfinite(s.rule.safety_factor) && s.rule.safety_factor >= 1.0 && s.rule.safety_factor <= 100.0,
          "rule.safety_factor must be in [1, 100] (got " + Number(s.rule.safety_factor) + ")");
  ValidateCovering(s.covering, "covering");
  std::set<std::string> surface_links;
  for (const robot::LinkSurface& link : s.surface.links) surface_links.insert(link.link);
  for (const auto& [name, covering] : s.link_coverings) {
    if (!surface_links.count(name)) {
      std::string links;
      for (const robot::LinkSurface& link : s.surface.links) links += (links.empty() ? "" : ", ") + link.link;
      throw std::invalid_argument("link_coverings: '" + name + "' is not a link of the surface (links: " + links +
                                  ")");
    }
    ValidateCovering(covering, "link_coverings['" + name + "']");
  }
}

const AuditCovering& CoveringOf(const AuditSetup& setup, const std::string& link) {
  const auto it = setup.link_coverings.find(link);
  return it == setup.link_coverings.end() ? setup.covering : it->second;
}

/// Where a covered flat point is, for the refusal.
std::string FlatPointWhere(const robot::LinkSurface& link, const robot::SurfacePoint& p) {
  std::string where = "link " + LinkName(link) + " has flat points";
  if (p.shape_index < link.shapes.size()) {
    const robot::SurfaceShape& shape = link.shapes[p.shape_index];
    where += " (" + std::string(robot::ToString(shape.type)) +
             (shape.origin.empty() ? std::string() : ", " + shape.origin) + ")";
  }
  return where;
}

void PlanLimits(const RegionLimits& regions, LinkPlan& plan) {
  plan.limits.resize(plan.radii.size() * regions.size());
  for (std::size_t k = 0; k < plan.radii.size(); ++k) {
    for (std::size_t r = 0; r < regions.size(); ++r) {
      plan.limits[k * regions.size() + r] = regions.Limit(plan.covering, plan.radii[k], r);
    }
  }
}

Pass RunPass(const AuditSetup& setup, const robot::JointTrajectory& trajectory, const RegionLimits& regions,
             const std::vector<LinkPlan>& plans, const AuditOptions& options, bool demand) {
  const std::size_t n_links = plans.size(), n_regions = regions.size();
  const double sf = setup.rule.safety_factor;
  Pass pass;
  pass.cells.resize(n_links * n_regions);
  for (std::size_t l = 0; l < n_links; ++l) {
    for (std::size_t r = 0; r < n_regions; ++r) {
      AuditCell& c = pass.cells[l * n_regions + r];
      c.link = l;
      c.region = r;
      c.speed_scale = kInf;
    }
  }
  if (demand) {
    pass.demand_J.resize(n_links);
    for (std::size_t l = 0; l < n_links; ++l) pass.demand_J[l].assign(plans[l].radii.size() * n_regions, 0.0);
  }
  std::vector<double> inverse_body_mass(n_regions);
  for (std::size_t r = 0; r < n_regions; ++r) inverse_body_mass[r] = regions.inverse_body_mass(r);
  std::vector<double> link_ratio(n_links, 0.0);
  std::vector<std::size_t> link_region(n_links, 0);
  if (options.keep_ratio_over_time) {
    pass.ratio_over_time.reserve(trajectory.size() * n_links);
    pass.time_s.reserve(trajectory.size());
  }
  double current_time = 0.0;
  std::size_t current_sample = trajectory.size();
  const Exposure& exposure = regions.exposure();
  std::vector<std::uint8_t> exposed(n_regions, 1);
  pass.link_moves.assign(n_links, 0);
  const auto on_point = [&](std::size_t i, std::size_t l, std::size_t p, const robot::PointMotion& m) {
    if (i != current_sample) {  // the first moving point of sample i: its time
      current_sample = i;
      current_time = trajectory.time_s[i];
    }
    pass.link_moves[l] = 1;
    if (!exposure.everywhere() && !exposure.At(m.position_m, exposed)) return;  // in no zone: not judged
    const LinkPlan& plan = plans[l];
    const double v = m.speed_m_per_s;
    const double inverse_mass = 1.0 / m.reflected_mass_kg;  // 0 for a fixed direction
    const EnergyLimit* limits = &plan.limits[plan.point_radius[p] * n_regions];
    double* point_demand = demand ? pass.demand_J[l].data() + plan.point_radius[p] * n_regions : nullptr;
    AuditCell* row = &pass.cells[l * n_regions];
    double& worst = link_ratio[l];
    for (std::size_t r = 0; r < n_regions; ++r) {
      if (!exposed[r]) continue;
      const double inverse_mass_sum = inverse_mass + inverse_body_mass[r];  // 1/μ
      const double v_max = MaxSpeed(limits[r], inverse_mass_sum);
      const double ratio = v / (sf * v_max);
      if (ratio > worst) {
        worst = ratio;
        link_region[l] = r;
      }
      if (point_demand) point_demand[r] = std::max(point_demand[r], 0.5 * v * v / inverse_mass_sum);
      AuditCell& c = row[r];
      if (c.sample && !(ratio > c.governing_ratio)) continue;
      c.governing_ratio = ratio;
      c.speed_scale = v_max / v;
      c.binding = v_max < kModelMaxSpeed_m_per_s ? limits[r].binding : BodyLimitKind::kNone;
      c.head_criterion = v_max < kModelMaxSpeed_m_per_s ? limits[r].head_criterion : LimitingCriterion::kNone;
      c.sample = i;
      c.time_s = current_time;
      c.point = p;
      c.point_in_link_m = plan.surface->points[p].position_m;
      c.point_in_base_m = m.position_m;
      c.speed_m_per_s = v;
      c.reflected_mass_kg = m.reflected_mass_kg;
      c.max_safe_speed_m_per_s = v_max;
    }
  };
  const auto on_sample = [&](std::size_t i, double t) {
    if (options.keep_ratio_over_time) {
      pass.ratio_over_time.insert(pass.ratio_over_time.end(), link_ratio.begin(), link_ratio.end());
      pass.time_s.push_back(t);
    }
    if (options.on_sample) options.on_sample(AuditSampleRow{i, t, link_ratio, link_region});
    std::fill(link_ratio.begin(), link_ratio.end(), 0.0);
    std::fill(link_region.begin(), link_region.end(), 0);
  };
  Walk(setup, trajectory, plans, on_point, on_sample);
  pass.sample_count = trajectory.size();
  return pass;
}

std::string CellWhere(const AuditResult& r, const AuditCell& c) {
  return r.links[c.link] + ", " + r.regions[c.region] + ", " +
         std::string(c.binding_name()) +
         ", t = " + FormatSignificant(c.time_s, 4) + " s";
}

std::vector<std::string> Scope(const AuditSetup& setup) {
  std::vector<std::string> scope;
  const DesignRule& rule = setup.rule;
  if (!setup.regions.empty()) {
    std::string line = setup.regions.front().Citation() + ", transient: " + std::to_string(setup.regions.size()) +
                       " body-region area" + (setup.regions.size() == 1 ? "" : "s") + "; criteria: force, pressure";
    if (rule.compression_counts()) line += ", the covering not fully compressed";
    if (!rule.crushing_allowed) line += ", the covering not crushed where its strength is known";
    line += "; safety factor " + FormatSignificant(rule.safety_factor) + " on each";
    scope.push_back(line);
    scope.push_back(
        "The covering: a Hertz layer on the robot's surface in series with the region's spring (" +
        materials::BuiltInEdition() +
        "'s model; the covering is covopt's extension, the standard has none); its peak pressure is also its "
        "compressive stress for the crush check.");
  }
  if (setup.head) {
    for (std::string& line : HeadVerdictScope(rule)) scope.push_back("Head (Park et al. 2011): " + line);
  }
  if (setup.braking_m_per_s2 > 0.0) {
    scope.push_back("The robot brakes " + FormatSignificant(setup.reaction_delay_s) + " s after first contact at " +
                    FormatSignificant(setup.braking_m_per_s2) +
                    " m/s² (docs/model.md §10.2): the governing ratios are the braked robot's, on the time path");
  }
  if (!setup.exposure_zones.empty()) {
    scope.push_back("Exposure zones (" + std::to_string(setup.exposure_zones.size()) +
                    ", boxes in the base frame, faces inside): a point-sample is judged against a region only where a "
                    "zone exposes that region; cells no zone exposes are not judged");
    for (const ExposureZone& z : setup.exposure_zones) {
      std::string regions;
      for (const std::string& r : z.regions) regions += (regions.empty() ? "" : ", ") + r;
      std::string box;
      for (int k = 0; k < 3; ++k) {
        box += std::string(k ? ", " : "") + "xyz"[k] + " " + FormatSignificant(z.min_m[k]) + " .. " +
               FormatSignificant(z.max_m[k]) + " m";
      }
      scope.push_back("Exposure zone '" + z.name + "' (" + box + "): " + regions);
    }
  }
  scope.push_back(
      "Each surface point at each sample: its velocity and the reflected mass along it (rigid links, no rotor "
      "inertia); every point of a link wears the link's covering on the point's radius of curvature.");
  return scope;
}

}  // namespace

namespace detail {

std::string Millimetres(double m) { return FormatSignificant(m * 1e3, 4) + " mm"; }

std::string SampleWhere(const robot::JointTrajectory& t, std::size_t i) {
  if (i < t.line_numbers.size()) return t.source_name + ":" + std::to_string(t.line_numbers[i]);
  return "trajectory sample " + std::to_string(i + 1);
}

void PlanRadii(const AuditSetup& setup, const robot::LinkSurface& link, bool covered, LinkPlan& plan) {
  plan.radii.clear();
  plan.surface_radii.clear();
  plan.point_radius.assign(link.points.size(), 0);
  for (std::size_t p = 0; p < link.points.size(); ++p) {
    const double surface_radius = link.points[p].radius_of_curvature_m;
    double radius = surface_radius;
    if (covered && !std::isfinite(surface_radius)) {
      if (!setup.flat_face_radius_m) {
        throw std::invalid_argument(
            "flat_face_radius_m: " + FlatPointWhere(link, link.points[p]) +
            " and a covering; the covering's Hertz contact needs a finite radius: give the radius to judge flat "
            "points at (flat_face_radius_m), or describe the link in a surface file");
      }
      radius = *setup.flat_face_radius_m;
    }
    const auto it = std::find(plan.radii.begin(), plan.radii.end(), radius);
    plan.point_radius[p] = static_cast<std::uint32_t>(it - plan.radii.begin());
    if (it == plan.radii.end()) {
      plan.radii.push_back(radius);
      plan.surface_radii.push_back(surface_radius);
    }
  }
}

/// The surface's links, each with its covering and its limits per distinct radius and region;
/// their names and point counts into `result`.
std::vector<LinkPlan> PlanLinks(const AuditSetup& setup, const RegionLimits& regions, AuditResult& result) {
  const robot::ChainSampleKinematics names(setup.chain, setup.motion);
  std::vector<LinkPlan> plans;
  plans.reserve(setup.surface.links.size());
  for (const robot::LinkSurface& link : setup.surface.links) {
    const std::optional<std::size_t> index = names.LinkIndex(link.carrier());  // the tool: the tip link
    if (!index) {
      std::string links;
      for (const std::string& name : names.link_names()) links += (links.empty() ? "" : ", ") + name;
      throw std::invalid_argument("surface: link '" + link.carrier() + "' is not on the chain (links: " + links + ")");
    }
    LinkPlan plan;
    plan.chain_index = *index;
    plan.surface = &link;
    plan.covering = CoveringOf(setup, link.link);
    const bool covered = plan.covering.covering.thickness_m > 0.0;
    BodyContactScene as_judged;
    as_judged.covering = plan.covering.covering;
    as_judged.contact_area_m2 = setup.contact_area_m2;
    if (!setup.regions.empty() && BareRobotLacksContactArea(as_judged)) {
      throw std::invalid_argument(
          "contact_area_m2: link '" + link.link +
          "' is bare (no covering) and no contact area is given: its pressure cannot be judged (a verdict on the "
          "force alone is not a verdict); give the bare robot's contact area (> 0 m²) or a covering");
    }
    PlanRadii(setup, link, covered, plan);
    try {
      PlanLimits(regions, plan);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument("link '" + link.link + "': " + e.what());
    }
    result.links.push_back(link.link);
    result.link_point_counts.push_back(link.points.size());
    plans.push_back(std::move(plan));
  }
  return plans;
}

}  // namespace detail

namespace {

/// A braking robot: the braked cells and their warnings. false: the time path failed, and
/// `result` says so (no verdict).
bool Brake(const AuditSetup& setup, const robot::JointTrajectory& trajectory, const RegionLimits& regions,
           const std::vector<LinkPlan>& plans, AuditResult& result) {
  const BrakingOutcome braking = ApplyBraking(setup, trajectory, regions, plans, result.cells);
  if (braking.failure) {
    result.status = TrajectoryCheckStatus::kEvaluationFailed;
    result.safe_speed_scale = 0.0;
    result.message = "evaluation failed: the time path of the braking robot did not answer (" + *braking.failure +
                     "); no verdict";
    result.scope = Scope(setup);
    return false;
  }
  result.warnings.push_back(
      "braking: the cells are the braked robot's (" + std::to_string(braking.evaluations) +
      " braked limits on the time path); the per-sample ratios (heat map, streamed rows) are the unbraked "
      "bounds");
  if (braking.non_monotone_cells > 0) {
    result.warnings.push_back("braking: in " + std::to_string(braking.non_monotone_cells) +
                              " cells the braked limit rose with the reflected mass somewhere; there only the "
                              "unbraked bound pruned the search (the result is exact either way)");
  }
  if (braking.fixed_direction_points > 0) {
    result.warnings.push_back("braking: " + std::to_string(braking.fixed_direction_points) +
                              " point-samples move along a direction the chain cannot move in (an infinite "
                              "reflected mass): they are judged unbraked");
  }
  return true;
}

/// The cells the exposure zones leave out: AuditCell::not_judged, the count and the warning.
void MarkNotJudged(const AuditSetup& setup, const RegionLimits& regions, const Pass& pass, AuditResult& result) {
  result.exposure_zones = setup.exposure_zones;
  const Exposure& exposure = regions.exposure();
  if (exposure.everywhere()) return;
  for (AuditCell& c : result.cells) {
    if (c.sample) continue;
    if (!exposure.Anywhere(c.region)) {
      c.not_judged = "no exposure zone exposes the region";
    } else if (pass.link_moves[c.link]) {
      c.not_judged = "the link's moving points never enter a zone exposing the region";
    } else {
      continue;  // the link never moves
    }
    ++result.not_judged_cells;
  }
  if (result.not_judged_cells > 0) {
    result.warnings.push_back(std::to_string(result.not_judged_cells) + " of " + std::to_string(result.cells.size()) +
                              " link × region cells are not judged: the exposure zones (" +
                              std::to_string(setup.exposure_zones.size()) +
                              ") expose their region nowhere the link moves; a risk assessment must confirm that a "
                              "person cannot present those regions there");
  }
}

/// The safe speed scale, the cell that sets it, the status and the message.
void SetLimitingCell(AuditResult& result) {
  result.safe_speed_scale = kInf;
  for (std::size_t k = 0; k < result.cells.size(); ++k) {
    const AuditCell& c = result.cells[k];
    if (!c.sample) continue;
    if (!result.limiting_cell || c.speed_scale < result.safe_speed_scale) {
      result.safe_speed_scale = c.speed_scale;
      result.limiting_cell = k;
    }
  }
  if (!result.limiting_cell) {
    result.status = TrajectoryCheckStatus::kAtRest;
    result.message = result.not_judged_cells > 0
                         ? "not judged: no moving surface point lies in an exposure zone that exposes a judged region"
                         : "at rest: no surface point moves";
  } else {
    const AuditCell& c = result.cells[*result.limiting_cell];
    const std::string scale = FormatSignificant(result.safe_speed_scale, 4);
    if (result.safe_speed_scale >= 1.0) {
      result.status = TrajectoryCheckStatus::kSafe;
      result.message = "safe: the program may run up to " + scale + "× (" + CellWhere(result, c) + ")";
    } else {
      result.status = TrajectoryCheckStatus::kUnsafe;
      result.message = "unsafe: slow the program to " + scale + "× (" + CellWhere(result, c) + ")";
    }
  }
}

/// The surface's and the trajectory's warnings, the flat faces judged at a radius, the cells
/// at the model's ceiling.
void AddWarnings(const AuditSetup& setup, const robot::JointTrajectory& trajectory, const std::vector<LinkPlan>& plans,
                 AuditResult& result) {
  result.warnings.insert(result.warnings.begin(), setup.surface.warnings.begin(), setup.surface.warnings.end());
  for (const std::string& w : trajectory.warnings) result.warnings.push_back(w);
  if (setup.flat_face_radius_m) {
    for (const LinkPlan& plan : plans) {
      for (std::size_t k = 0; k < plan.radii.size(); ++k) {
        if (std::isfinite(plan.surface_radii[k]) || !std::isfinite(plan.radii[k])) continue;
        result.warnings.push_back("link '" + plan.surface->link + "': its flat points are judged at a radius of " +
                                  Millimetres(*setup.flat_face_radius_m) +
                                  " (flat_face_radius_m): the covering's contact on a flat face is not modelled");
        break;
      }
    }
  }
  for (const AuditCell& c : result.cells) {
    if (c.sample && c.max_safe_speed_m_per_s >= kModelMaxSpeed_m_per_s) {
      result.warnings.push_back(
          "some cells are safe up to the model's 100 m/s: their ratios and scales are bounds (the true limit lies "
          "above)");
      break;
    }
  }
}

}  // namespace

std::vector<std::string> AuditRegionNames(const AuditSetup& setup) {
  std::vector<std::string> names;
  for (const materials::BodyLimits& limits : setup.regions) {
    names.push_back(limits.region->name + " (" + limits.area->name + ")");
  }
  if (setup.head) names.emplace_back("head (Park et al. 2011)");
  return names;
}

AuditResult Audit(const AuditSetup& setup, const robot::JointTrajectory& trajectory, const AuditOptions& options) {
  ValidateSetup(setup);
  ValidateDesign(options.design);
  Require(trajectory.size() > 0, "trajectory: no samples");
  const RegionLimits regions(setup);

  AuditResult result;
  result.regions = regions.names();
  const std::vector<LinkPlan> plans = PlanLinks(setup, regions, result);

  const bool design = !options.design.materials.empty();
  Pass pass = RunPass(setup, trajectory, regions, plans, options, design);
  result.cells = std::move(pass.cells);
  result.ratio_over_time = std::move(pass.ratio_over_time);
  result.time_s = std::move(pass.time_s);
  result.sample_count = pass.sample_count;
  MarkNotJudged(setup, regions, pass, result);
  if (setup.braking_m_per_s2 > 0.0 && !Brake(setup, trajectory, regions, plans, result)) return result;

  SetLimitingCell(result);
  result.scope = Scope(setup);
  AddWarnings(setup, trajectory, plans, result);
  if (design) DesignLinks(setup, trajectory, options, regions, plans, pass, result);
  return result;
}

}  // namespace covopt::audit
