// `covopt audit`: every surface point of every link, every exposed body region (and the head),
// along a trajectory (docs/model.md §14). Per link, distinct radius of curvature and region the
// energy admitted at the binding limit, E* = ½ μ v_max², is computed once (MaxSafeSpeed at a
// fixed robot, μ = m_H); a point-sample then costs its kinematics and one square root per
// region, v_max(m) = sqrt(2 E* (1/m + 1/m_H)).
#include "covopt/optim/audit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <covopt/core/number_format.hpp>
#include <covopt/core/poisson_ratio.hpp>
#include <covopt/robot/link_kinematics.hpp>

#include "robust_internal.hpp"
#include "validation_internal.hpp"

namespace covopt::optim {
namespace {

using internal::Number;
using internal::Require;

constexpr double kInf = std::numeric_limits<double>::infinity();
/// The impact models' speed range [m/s]: below the lowest a point is at rest (as
/// CheckTrajectory), above the highest MaxSafeSpeed answers its ceiling.
constexpr double kModelMinSpeed_m_per_s = 1e-6;
constexpr double kModelMaxSpeed_m_per_s = 100.0;

/// One (covering, radius, region) limit, mass-free: the energy at the binding limit.
struct EnergyLimit {
  /// E* = ½ μ v_max² [J] (μ at the reference mass); 0: no safe speed.
  double energy_J = 0.0;
  /// Safe up to the model's 100 m/s at the reference mass, hence at every mass (μ <= m_H).
  bool ceiling = false;
  BodyLimitKind binding = BodyLimitKind::kNone;
  LimitingCriterion head_criterion = LimitingCriterion::kNone;
};

/// A braked limit at one mass (the time path).
struct BrakedLimit {
  double max_safe_speed_m_per_s = 0.0;  ///< [m/s]; 0: no safe speed
  BodyLimitKind binding = BodyLimitKind::kNone;
  LimitingCriterion head_criterion = LimitingCriterion::kNone;
  bool failed = false;  ///< the time path failed: no answer
  std::string message;
};

BodyLimitKind FromHead(LimitingCriterion criterion) noexcept {
  switch (criterion) {
    case LimitingCriterion::kLaceration:
    case LimitingCriterion::kContusion: return BodyLimitKind::kPressure;
    case LimitingCriterion::kFullCompression: return BodyLimitKind::kFullCompression;
    case LimitingCriterion::kCrush: return BodyLimitKind::kCrush;
    case LimitingCriterion::kFracture: return BodyLimitKind::kForce;  // the bone's fracture force
    case LimitingCriterion::kNone: break;
  }
  return BodyLimitKind::kNone;
}

/// v_max(m) [m/s] from a limit: sqrt(2 E* (1/m + 1/m_H)), capped at the model's ceiling.
inline double MaxSpeed(const EnergyLimit& limit, double inverse_mass_sum) noexcept {
  if (limit.ceiling) return kModelMaxSpeed_m_per_s;
  return std::min(kModelMaxSpeed_m_per_s, std::sqrt(2.0 * limit.energy_J * inverse_mass_sum));
}

/// The regions judged: the body regions, then the head.
class RegionLimits {
 public:
  explicit RegionLimits(const AuditSetup& setup) : setup_(setup) {
    for (const materials::BodyLimits& limits : setup.regions) {
      names_.push_back(limits.region->name + " (" + limits.area->name + ")");
      inverse_body_mass_.push_back(1.0 / limits.effective_mass_kg());
    }
    if (setup.head) {
      names_.push_back("head (Park et al. 2011)");
      inverse_body_mass_.push_back(1.0 / setup.head->head.mass_kg);
    }
  }
  std::size_t size() const noexcept { return names_.size(); }
  const std::vector<std::string>& names() const noexcept { return names_; }
  /// 1/m_H of region r [1/kg].
  double inverse_body_mass(std::size_t r) const noexcept { return inverse_body_mass_[r]; }
  bool is_head(std::size_t r) const noexcept { return setup_.head && r + 1 == names_.size(); }

  /// E* of region r for `covering` on a surface of radius `radius_m`: MaxSafeSpeed at a fixed
  /// robot (the largest μ, m_H: the lowest v_max, so the ceiling is met last).
  EnergyLimit Limit(const AuditCovering& covering, double radius_m, std::size_t r) const {
    const RegionSpeed speed = Speed(covering, radius_m, r, kFixed, /*braked=*/false);
    EnergyLimit out;
    out.binding = speed.binding;
    out.head_criterion = speed.head_criterion;
    switch (speed.status) {
      case SpeedLimitStatus::kSafeUpToSearchLimit:
        out.ceiling = true;
        out.binding = BodyLimitKind::kNone;
        out.head_criterion = LimitingCriterion::kNone;
        break;
      case SpeedLimitStatus::kLimited:
        out.energy_J = 0.5 * speed.max_safe_speed_m_per_s * speed.max_safe_speed_m_per_s / inverse_body_mass_[r];
        break;
      case SpeedLimitStatus::kNoSafeValue: break;  // E* = 0
      case SpeedLimitStatus::kEvaluationFailed:
        throw std::invalid_argument(names_[r] + ": the exact path could not judge it: " + speed.message);
    }
    return out;
  }

  /// The braked robot's largest safe speed against region r at mass `mass_kg` (the time path,
  /// bracketed: MaxSafeSpeed on a braking scene), for the branch and bound of §14.4.
  BrakedLimit Braked(const AuditCovering& covering, double radius_m, std::size_t r, double mass_kg) const {
    const RegionSpeed speed = Speed(covering, radius_m, r, mass_kg, /*braked=*/true);
    BrakedLimit out;
    out.binding = speed.binding;
    out.head_criterion = speed.head_criterion;
    out.max_safe_speed_m_per_s = speed.max_safe_speed_m_per_s;
    if (speed.status == SpeedLimitStatus::kSafeUpToSearchLimit) {
      out.max_safe_speed_m_per_s = kModelMaxSpeed_m_per_s;
      out.binding = BodyLimitKind::kNone;
      out.head_criterion = LimitingCriterion::kNone;
    } else if (speed.status == SpeedLimitStatus::kEvaluationFailed) {
      out.failed = true;
      out.message = speed.message;
    }
    return out;
  }

 private:
  /// One MaxSafeSpeed answer against region r, body region or head.
  struct RegionSpeed {
    SpeedLimitStatus status = SpeedLimitStatus::kLimited;
    double max_safe_speed_m_per_s = 0.0;
    BodyLimitKind binding = BodyLimitKind::kNone;
    LimitingCriterion head_criterion = LimitingCriterion::kNone;
    std::string message;
  };

  /// MaxSafeSpeed against region r with `covering` on radius `radius_m` at mass `mass_kg`:
  /// the closed form (a body region) or the exact path (the head) unbraked; the time path with
  /// the setup's braking when `braked`.
  RegionSpeed Speed(const AuditCovering& covering, double radius_m, std::size_t r, double mass_kg,
                    bool braked) const {
    const DesignRule& rule = setup_.rule;
    const bool covered = covering.covering.thickness_m > 0.0;
    const double delay = braked ? setup_.reaction_delay_s : 0.0;
    const double braking = braked ? setup_.braking_m_per_s2 : 0.0;
    RegionSpeed out;
    if (!is_head(r)) {
      BodyContactScene scene;
      scene.robot_mass_kg = mass_kg;
      scene.speed_m_per_s = 1.0;
      scene.robot_radius_m = radius_m;
      scene.covering = covering.covering;
      scene.contact_area_m2 = setup_.contact_area_m2;
      scene.reaction_delay_s = delay;
      scene.braking_m_per_s2 = braking;
      const BodyRegionSpeedLimit limit =
          MaxSafeSpeed(scene, setup_.regions[r], BodyRegionOptions{rule, covered ? covering.material : std::nullopt});
      out.status = limit.status;
      out.max_safe_speed_m_per_s = limit.max_safe_speed_m_per_s;
      out.binding = limit.limited_by;
      if (limit.status == SpeedLimitStatus::kEvaluationFailed) out.message = limit.message;
      return out;
    }
    // The head: Park et al.'s model; unbraked, U(δ_lim) does not depend on the mass.
    const std::optional<CandidateMaterial>& material = covering.material;
    if (covered && material && material->crush_behaviour == materials::CrushBehaviour::kUnknown &&
        rule.refuses_unknown_strength()) {
      out.status = SpeedLimitStatus::kNoSafeValue;  // refused at every speed, as a body region refuses it
      out.binding = BodyLimitKind::kCrush;
      out.head_criterion = LimitingCriterion::kCrush;
      return out;
    }
    Scene scene = *setup_.head;
    scene.robot.mass_kg = mass_kg;
    scene.robot.speed_m_per_s = 1.0;
    scene.robot.radius_m = radius_m;
    scene.robot.reaction_delay_s = delay;
    scene.robot.braking_m_per_s2 = braking;
    scene.covering = covering.covering;
    SpeedLimitOptions options = HeadOptions(covering);
    if (!braked) options.oracle.choice = OracleChoice::kExact;
    const SpeedLimit limit = MaxSafeSpeed(scene, options);
    out.status = limit.status;
    out.max_safe_speed_m_per_s = limit.max_safe_speed_m_per_s;
    out.head_criterion = limit.limited_by;
    out.binding = FromHead(limit.limited_by);
    if (limit.status == SpeedLimitStatus::kEvaluationFailed) out.message = limit.message;
    return out;
  }

  /// The head's criteria under the rule, with the covering's strength where it crushes.
  SpeedLimitOptions HeadOptions(const AuditCovering& covering) const {
    const DesignRule& rule = setup_.rule;
    SpeedLimitOptions options;
    options.allow_full_compression = !rule.compression_counts();
    options.safety_factor = rule.safety_factor;
    options.allow_crushing = rule.crushing_allowed;
    const std::optional<CandidateMaterial>& material = covering.material;
    if (covering.covering.thickness_m > 0.0 && material &&
        material->crush_behaviour == materials::CrushBehaviour::kCrushes) {
      options.covering_compressive_strength_Pa = material->compressive_strength_Pa;
    }
    return options;
  }

  const AuditSetup& setup_;
  std::vector<std::string> names_;
  std::vector<double> inverse_body_mass_;
};

/// A surface link, its covering and its limits per distinct radius and region.
struct LinkPlan {
  std::size_t chain_index = 0;
  const robot::LinkSurface* surface = nullptr;
  AuditCovering covering;
  std::vector<double> radii;                 ///< distinct radii judged at [m]
  std::vector<std::uint32_t> point_radius;   ///< per point: index into radii
  std::vector<double> surface_radii;         ///< per radius: the surface's own (kFlat kept)
  std::vector<EnergyLimit> limits;           ///< radii × regions
};

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
  internal::ValidateThicknessScan(d.min_thickness_m, d.max_thickness_m, d.thickness_scan_points,
                                  d.thickness_resolution_m, d.thickness_step_m, "design.");
  for (const CandidateMaterial& m : d.materials) internal::ValidateCandidateMaterial(m, "design material ");
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

/// The radii of a link's points as judged with `covering`: the surface's, a flat point's
/// replaced by flat_face_radius_m when covered. Throws for a covered flat point without one.
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

void PlanLimits(const RegionLimits& regions, LinkPlan& plan) {
  plan.limits.resize(plan.radii.size() * regions.size());
  for (std::size_t k = 0; k < plan.radii.size(); ++k) {
    for (std::size_t r = 0; r < regions.size(); ++r) {
      plan.limits[k * regions.size() + r] = regions.Limit(plan.covering, plan.radii[k], r);
    }
  }
}

std::string SampleWhere(const robot::JointTrajectory& t, std::size_t i) {
  if (i < t.line_numbers.size()) return t.source_name + ":" + std::to_string(t.line_numbers[i]);
  return "trajectory sample " + std::to_string(i + 1);
}

std::string Millimetres(double m) { return FormatSignificant(m * 1e3, 4) + " mm"; }

/// The pass over the trajectory: cells, the per-sample rows, and (for the design) each link's
/// energy demand per radius and region.
struct Pass {
  std::vector<AuditCell> cells;
  std::vector<double> ratio_over_time;
  std::vector<double> time_s;
  /// Per link: radii × regions, max over its moving point-samples of ½ μ v² [J].
  std::vector<std::vector<double>> demand_J;
  std::size_t sample_count = 0;
};

/// Visits every moving point-sample of the trajectory: per sample Update, then
/// on_point(sample, link, point, motion) for every moving point of every link, then
/// on_sample(sample, time). Checks the times (non-decreasing, finite) and the samples' sizes.
template <class OnPoint, class OnSample>
void Walk(const AuditSetup& setup, const robot::JointTrajectory& trajectory, const std::vector<LinkPlan>& plans,
          const OnPoint& on_point, const OnSample& on_sample) {
  robot::ChainSampleKinematics kin(setup.chain, setup.motion);
  double previous_time = -kInf;
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    const double t = trajectory.time_s[i];
    if (!std::isfinite(t) || t < previous_time) {
      throw std::invalid_argument(SampleWhere(trajectory, i) + ": time " + FormatShortest(t) +
                                  " s goes backwards or is not finite");
    }
    previous_time = t;
    if (i >= trajectory.positions.size() || i >= trajectory.velocities.size()) {
      throw std::invalid_argument(SampleWhere(trajectory, i) +
                                  ": the trajectory has fewer positions or velocities than times");
    }
    kin.Update(trajectory.positions[i], trajectory.velocities[i], SampleWhere(trajectory, i));
    for (std::size_t l = 0; l < plans.size(); ++l) {
      const LinkPlan& plan = plans[l];
      const std::vector<robot::SurfacePoint>& points = plan.surface->points;
      for (std::size_t p = 0; p < points.size(); ++p) {
        const robot::PointMotion m = kin.Point(plan.chain_index, points[p].position_m);
        if (!m.moving || !(m.speed_m_per_s >= kModelMinSpeed_m_per_s)) continue;
        on_point(i, l, p, m);
      }
    }
    on_sample(i, t);
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
  const auto on_point = [&](std::size_t i, std::size_t l, std::size_t p, const robot::PointMotion& m) {
    if (i != current_sample) {  // the first moving point of sample i: its time
      current_sample = i;
      current_time = trajectory.time_s[i];
    }
    const LinkPlan& plan = plans[l];
    const double v = m.speed_m_per_s;
    const double inverse_mass = 1.0 / m.reflected_mass_kg;  // 0 for a fixed direction
    const EnergyLimit* limits = &plan.limits[plan.point_radius[p] * n_regions];
    double* point_demand = demand ? pass.demand_J[l].data() + plan.point_radius[p] * n_regions : nullptr;
    AuditCell* row = &pass.cells[l * n_regions];
    double& worst = link_ratio[l];
    for (std::size_t r = 0; r < n_regions; ++r) {
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

/// What the branch and bound of a braking robot reports.
struct BrakingOutcome {
  std::size_t evaluations = 0;             ///< braked limits computed (time path)
  std::size_t fixed_direction_points = 0;  ///< point-samples along a fixed direction: unbraked
  std::size_t non_monotone_cells = 0;      ///< cells whose braked limit rose with the mass
  std::optional<std::string> failure;      ///< the first time-path failure
};

/// A braking robot (docs/model.md §14.4): replaces every cell's unbraked governing
/// point-sample by the braked one, exactly, judging as few point-samples braked as it can.
/// Two upper bounds of a point-sample's braked ratio v/(SF v_b(m)): its unbraked ratio
/// (braking only takes energy out), and v/(SF v_b(m')) for any mass m' >= m judged braked at the
/// same radius (a heavier robot is no safer: v_b does not rise with the mass; where a cell's
/// judged masses contradict that, only the first bound is used there, and a warning says so).
/// Per cell: the braked ratio at the unbraked governing point-sample is a lower bound; a second
/// pass collects the point-samples whose unbraked ratio exceeds it; then, best bound first, a
/// point-sample is judged braked until the best bound is a judged ratio.
BrakingOutcome ApplyBraking(const AuditSetup& setup, const robot::JointTrajectory& trajectory,
                            const RegionLimits& regions, const std::vector<LinkPlan>& plans,
                            std::vector<AuditCell>& cells) {
  const std::size_t n_regions = regions.size();
  const double sf = setup.rule.safety_factor;
  BrakingOutcome outcome;
  struct Judged {
    double max_safe_speed_m_per_s = 0.0;
    BodyLimitKind binding = BodyLimitKind::kNone;
    LimitingCriterion head_criterion = LimitingCriterion::kNone;
  };
  using Key = std::pair<std::uint32_t, double>;  // (radius index, mass [kg])
  struct Candidate {
    double unbraked_ratio = 0.0;
    std::uint32_t radius = 0;
    AuditCell cell;  ///< the point-sample, with its unbraked v_max, ratio and binding
  };

  // 1. Each cell's unbraked governing point-sample is the first candidate.
  std::vector<std::vector<Candidate>> candidates(cells.size());
  std::vector<double> lower_bound(cells.size(), 0.0);
  std::vector<std::map<Key, Judged>> judged(cells.size());
  std::vector<bool> monotone(cells.size(), true);
  // The braked limit of cell k at (radius, mass), judged once; nullptr when the time path failed.
  const auto judge = [&](std::size_t k, std::uint32_t radius, double mass) -> const Judged* {
    std::map<Key, Judged>& known = judged[k];
    const Key key{radius, mass};
    if (const auto it = known.find(key); it != known.end()) return &it->second;
    ++outcome.evaluations;
    const LinkPlan& plan = plans[cells[k].link];
    const BrakedLimit b = regions.Braked(plan.covering, plan.radii[radius], cells[k].region, mass);
    if (b.failed) {
      if (!outcome.failure) outcome.failure = b.message;
      return nullptr;
    }
    const auto it = known.emplace(key, Judged{b.max_safe_speed_m_per_s, b.binding, b.head_criterion}).first;
    // v_b must not rise with the mass (at one radius): check the neighbours.
    const auto rises = [](const Judged& lighter, const Judged& heavier) {
      return heavier.max_safe_speed_m_per_s > lighter.max_safe_speed_m_per_s * (1.0 + 1e-9);
    };
    if (it != known.begin() && std::prev(it)->first.first == radius && rises(std::prev(it)->second, it->second)) {
      monotone[k] = false;
    }
    if (std::next(it) != known.end() && std::next(it)->first.first == radius && rises(it->second, std::next(it)->second)) {
      monotone[k] = false;
    }
    return &it->second;
  };
  for (std::size_t k = 0; k < cells.size(); ++k) {
    if (!cells[k].sample) continue;
    const LinkPlan& plan = plans[cells[k].link];
    Candidate first{cells[k].governing_ratio, plan.point_radius[cells[k].point], cells[k]};
    const double mass = cells[k].reflected_mass_kg;
    if (std::isfinite(mass)) {
      const Judged* j = judge(k, first.radius, mass);
      if (!j) return outcome;
      lower_bound[k] = cells[k].speed_m_per_s / (sf * j->max_safe_speed_m_per_s);
    } else {
      lower_bound[k] = cells[k].governing_ratio;  // a fixed direction cannot brake
    }
    candidates[k].push_back(std::move(first));
  }

  // 2. Every other point-sample whose unbraked ratio exceeds its cell's lower bound.
  std::vector<double> inverse_body_mass(n_regions);
  for (std::size_t r = 0; r < n_regions; ++r) inverse_body_mass[r] = regions.inverse_body_mass(r);
  const auto on_point = [&](std::size_t i, std::size_t l, std::size_t p, const robot::PointMotion& m) {
    const LinkPlan& plan = plans[l];
    const double v = m.speed_m_per_s;
    const EnergyLimit* limits = &plan.limits[plan.point_radius[p] * n_regions];
    for (std::size_t r = 0; r < n_regions; ++r) {
      const std::size_t k = l * n_regions + r;
      if (!cells[k].sample || (i == *cells[k].sample && p == cells[k].point)) continue;  // judged in 1.
      const double v_max = MaxSpeed(limits[r], 1.0 / m.reflected_mass_kg + inverse_body_mass[r]);
      const double ratio = v / (sf * v_max);
      if (!(ratio > lower_bound[k])) continue;
      Candidate c{ratio, plan.point_radius[p], cells[k]};
      c.cell.governing_ratio = ratio;
      c.cell.speed_scale = v_max / v;
      c.cell.max_safe_speed_m_per_s = v_max;
      c.cell.binding = v_max < kModelMaxSpeed_m_per_s ? limits[r].binding : BodyLimitKind::kNone;
      c.cell.head_criterion = v_max < kModelMaxSpeed_m_per_s ? limits[r].head_criterion : LimitingCriterion::kNone;
      c.cell.sample = i;
      c.cell.time_s = trajectory.time_s[i];
      c.cell.point = p;
      c.cell.point_in_link_m = plan.surface->points[p].position_m;
      c.cell.point_in_base_m = m.position_m;
      c.cell.speed_m_per_s = v;
      c.cell.reflected_mass_kg = m.reflected_mass_kg;
      candidates[k].push_back(std::move(c));
    }
  };
  Walk(setup, trajectory, plans, on_point, [](std::size_t, double) {});

  // 3. Per cell, best bound first.
  for (std::size_t k = 0; k < cells.size(); ++k) {
    std::vector<Candidate>& list = candidates[k];
    if (list.empty()) continue;
    // A coarse mass grid per radius (4 per decade over the candidates' masses) tightens every
    // bound at the cost of a few braked limits, when there are many candidates.
    if (list.size() > 16) {
      std::map<std::uint32_t, std::pair<double, double>> range;  // radius -> lightest, heaviest
      for (const Candidate& c : list) {
        const double m = c.cell.reflected_mass_kg;
        if (!std::isfinite(m)) continue;
        auto [it, inserted] = range.try_emplace(c.radius, m, m);
        if (!inserted) it->second = {std::min(it->second.first, m), std::max(it->second.second, m)};
      }
      for (const auto& [radius, masses] : range) {
        const int steps = static_cast<int>(std::ceil(4.0 * std::log10(masses.second / masses.first)));
        for (int j = 0; j <= steps; ++j) {
          const double m = j == steps ? masses.second : masses.first * std::pow(10.0, j / 4.0);
          if (!judge(k, radius, m)) return outcome;
        }
      }
    }
    // The bound of candidate c, and whether it is its judged braked ratio.
    const auto bound = [&](const Candidate& c) -> std::pair<double, bool> {
      const double m = c.cell.reflected_mass_kg;
      if (!std::isfinite(m)) return {c.unbraked_ratio, true};
      const std::map<Key, Judged>& known = judged[k];
      const auto it = known.lower_bound(Key{c.radius, m});
      if (it == known.end() || it->first.first != c.radius) return {c.unbraked_ratio, false};
      const double ratio = c.cell.speed_m_per_s / (sf * it->second.max_safe_speed_m_per_s);
      if (it->first.second == m) return {ratio, true};
      if (!monotone[k]) return {c.unbraked_ratio, false};
      return {std::min(c.unbraked_ratio, ratio), false};
    };
    // Max-heap on the bound; ties: the earlier point-sample first.
    using Entry = std::pair<double, std::size_t>;
    const auto lower = [](const Entry& a, const Entry& b) {
      return a.first < b.first || (a.first == b.first && a.second > b.second);
    };
    std::priority_queue<Entry, std::vector<Entry>, decltype(lower)> heap(lower);
    const auto fill = [&] {
      while (!heap.empty()) heap.pop();
      for (std::size_t i = 0; i < list.size(); ++i) heap.emplace(bound(list[i]).first, i);
    };
    fill();
    while (true) {
      const auto [top, i] = heap.top();
      heap.pop();
      const auto [now, exact] = bound(list[i]);
      if (now < top) {  // tightened since it was pushed
        heap.emplace(now, i);
        continue;
      }
      if (exact) {  // no other bound is higher: this is the cell's braked governing ratio
        Candidate& c = list[i];
        if (!std::isfinite(c.cell.reflected_mass_kg)) {
          ++outcome.fixed_direction_points;
        } else {
          const Judged& j = judged[k].at(Key{c.radius, c.cell.reflected_mass_kg});
          c.cell.max_safe_speed_m_per_s = j.max_safe_speed_m_per_s;
          c.cell.governing_ratio = now;
          c.cell.speed_scale = j.max_safe_speed_m_per_s / c.cell.speed_m_per_s;
          c.cell.binding = j.binding;
          c.cell.head_criterion = j.head_criterion;
        }
        cells[k] = c.cell;
        break;
      }
      const bool was_monotone = monotone[k];
      if (!judge(k, list[i].radius, list[i].cell.reflected_mass_kg)) return outcome;
      if (was_monotone && !monotone[k]) {
        fill();  // the mass bounds no longer hold: every key back to what stands without them
      } else {
        heap.emplace(bound(list[i]).first, i);
      }
    }
    if (!monotone[k]) ++outcome.non_monotone_cells;
  }
  return outcome;
}

/// The per-link design: the thinnest thickness per material with E* >= the link's demand for
/// every radius and region it meets, rounded up to the step.
struct DesignTry {
  std::optional<double> thickness_m;
  std::string why_not;
};

DesignTry DesignMaterial(const AuditSetup& setup, const AuditDesignOptions& d, const RegionLimits& regions,
                         const LinkPlan& plan, const std::vector<double>& demand, const CandidateMaterial& material) {
  DesignTry out;
  if (material.crush_behaviour == materials::CrushBehaviour::kUnknown && setup.rule.refuses_unknown_strength()) {
    out.why_not = material.name + ": compressive strength unknown (refused by the rule)";
    return out;
  }
  const std::size_t n_regions = regions.size();
  // The (radius, region) pairs the link meets, the most demanding first.
  std::vector<std::size_t> pairs;
  for (std::size_t k = 0; k < demand.size(); ++k) {
    if (demand[k] > 0.0) pairs.push_back(k);
  }
  std::sort(pairs.begin(), pairs.end(), [&](std::size_t a, std::size_t b) { return demand[a] > demand[b]; });
  std::size_t last_failed = 0;  // checked first next time (the pair that binds stays the same)
  auto admissible = [&](double b) {
    AuditCovering covering{CoveringSpec{material.youngs_modulus_Pa, material.poisson_ratio, b}, material};
    auto ok = [&](std::size_t k) {
      const EnergyLimit limit = regions.Limit(covering, plan.radii[k / n_regions], k % n_regions);
      return limit.ceiling || limit.energy_J >= demand[k];
    };
    if (!pairs.empty() && !ok(pairs[last_failed])) return false;
    for (std::size_t j = 0; j < pairs.size(); ++j) {
      if (j == last_failed) continue;
      if (!ok(pairs[j])) {
        last_failed = j;
        return false;
      }
    }
    return true;
  };
  DesignSpace space;  // only its thickness range is read
  space.min_thickness_m = d.min_thickness_m;
  space.max_thickness_m = d.max_thickness_m;
  std::optional<double> thickness =
      internal::ThinnestAdmissibleThickness(space, d.thickness_scan_points, d.thickness_resolution_m, admissible);
  if (!thickness) {
    out.why_not = material.name + ": not safe at any thickness in " + Millimetres(d.min_thickness_m) + " .. " +
                  Millimetres(d.max_thickness_m);
    return out;
  }
  if (d.thickness_step_m > 0.0) {
    std::optional<double> beyond_max;
    const std::optional<double> stock = internal::FirstAdmissibleStock(
        *thickness, d.thickness_step_m, d.max_thickness_m, [](double b) { return b; }, admissible, beyond_max);
    if (stock) thickness = *stock;  // else the exact thinnest (no stock thickness within the range)
  }
  out.thickness_m = thickness;
  return out;
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
    std::string line = "ISO/TS 15066:2016 Table A.2, transient: " + std::to_string(setup.regions.size()) +
                       " body-region area" + (setup.regions.size() == 1 ? "" : "s") + "; criteria: force, pressure";
    if (rule.compression_counts()) line += ", the covering not fully compressed";
    if (!rule.crushing_allowed) line += ", the covering not crushed where its strength is known";
    line += "; safety factor " + FormatSignificant(rule.safety_factor) + " on each";
    scope.push_back(line);
    scope.push_back(
        "The covering: a Hertz layer on the robot's surface in series with the region's spring (ISO/TS 15066:2016 "
        "Annex A's model; the covering is covopt's extension, the standard has none); its peak pressure is also its "
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
  scope.push_back(
      "Each surface point at each sample: its velocity and the reflected mass along it (rigid links, no rotor "
      "inertia); every point of a link wears the link's covering on the point's radius of curvature.");
  return scope;
}

}  // namespace

AuditResult Audit(const AuditSetup& setup, const robot::JointTrajectory& trajectory, const AuditOptions& options) {
  ValidateSetup(setup);
  ValidateDesign(options.design);
  Require(trajectory.size() > 0, "trajectory: no samples");
  const RegionLimits regions(setup);
  const robot::ChainSampleKinematics names(setup.chain, setup.motion);

  AuditResult result;
  result.regions = regions.names();
  std::vector<LinkPlan> plans;
  plans.reserve(setup.surface.links.size());
  for (const robot::LinkSurface& link : setup.surface.links) {
    const std::optional<std::size_t> index = names.LinkIndex(link.link);
    if (!index) {
      std::string links;
      for (const std::string& name : names.link_names()) links += (links.empty() ? "" : ", ") + name;
      throw std::invalid_argument("surface: link '" + link.link + "' is not on the chain (links: " + links + ")");
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

  const bool design = !options.design.materials.empty();
  Pass pass = RunPass(setup, trajectory, regions, plans, options, design);
  result.cells = std::move(pass.cells);
  const bool brakes = setup.braking_m_per_s2 > 0.0;
  if (brakes) {
    const BrakingOutcome braking = ApplyBraking(setup, trajectory, regions, plans, result.cells);
    if (braking.failure) {
      result.ratio_over_time = std::move(pass.ratio_over_time);
      result.time_s = std::move(pass.time_s);
      result.sample_count = pass.sample_count;
      result.status = TrajectoryCheckStatus::kEvaluationFailed;
      result.safe_speed_scale = 0.0;
      result.message = "evaluation failed: the time path of the braking robot did not answer (" + *braking.failure +
                       "); no verdict";
      result.scope = Scope(setup);
      return result;
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
  }
  result.ratio_over_time = std::move(pass.ratio_over_time);
  result.time_s = std::move(pass.time_s);
  result.sample_count = pass.sample_count;

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
    result.message = "at rest: no surface point moves";
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
  result.scope = Scope(setup);
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

  if (!design) return result;

  // The per-link design, then a second audit with every designed link at its covering.
  const AuditDesignOptions& d = options.design;
  if (brakes) {
    result.warnings.push_back(
        "braking: the per-link design is the unbraked robot's (conservative: braking only takes energy out); its "
        "re-check is braked");
  }
  AuditSetup recheck = setup;
  std::vector<std::size_t> designed;
  for (std::size_t l = 0; l < plans.size(); ++l) {
    AuditLinkDesign ld;
    ld.link = l;
    const std::vector<double>& demand = pass.demand_J[l];
    if (std::none_of(demand.begin(), demand.end(), [](double e) { return e > 0.0; })) {
      ld.message = "the link never moves: no covering needed";
      result.link_designs.push_back(std::move(ld));
      continue;
    }
    LinkPlan plan;
    plan.chain_index = plans[l].chain_index;
    plan.surface = plans[l].surface;
    try {
      PlanRadii(setup, *plan.surface, /*covered=*/true, plan);
    } catch (const std::invalid_argument& e) {
      ld.message = std::string("no design: ") + e.what();
      result.link_designs.push_back(std::move(ld));
      continue;
    }
    // The demand was accumulated on the audited covering's radii; map it onto the covered ones.
    std::vector<double> covered_demand(plan.radii.size() * regions.size(), 0.0);
    for (std::size_t p = 0; p < plan.point_radius.size(); ++p) {
      const std::size_t from = plans[l].point_radius[p], to = plan.point_radius[p];
      for (std::size_t r = 0; r < regions.size(); ++r) {
        double& e = covered_demand[to * regions.size() + r];
        e = std::max(e, demand[from * regions.size() + r]);
      }
    }
    std::vector<std::string> why_not;
    for (const CandidateMaterial& material : d.materials) {
      const DesignTry t = DesignMaterial(setup, d, regions, plan, covered_demand, material);
      if (!t.thickness_m) {
        why_not.push_back(t.why_not);
        continue;
      }
      if (!ld.thickness_m || *t.thickness_m < *ld.thickness_m) {  // ties: catalog order
        ld.thickness_m = t.thickness_m;
        ld.material = material;
      }
    }
    if (!ld.material) {
      ld.message = "no material in " + Millimetres(d.min_thickness_m) + " .. " + Millimetres(d.max_thickness_m) +
                   " makes the link safe at full speed";
      for (const std::string& w : why_not) ld.message += "; " + w;
    } else {
      recheck.link_coverings[result.links[l]] = AuditCovering{
          CoveringSpec{ld.material->youngs_modulus_Pa, ld.material->poisson_ratio, *ld.thickness_m}, ld.material};
      designed.push_back(l);
    }
    result.link_designs.push_back(std::move(ld));
  }
  if (!designed.empty()) {
    AuditOptions again;
    again.keep_ratio_over_time = false;
    const AuditResult checked = Audit(recheck, trajectory, again);
    const double sf = setup.rule.safety_factor;
    for (std::size_t l : designed) {
      AuditLinkDesign& ld = result.link_designs[l];
      ld.governing_ratio = 0.0;
      for (std::size_t r = 0; r < checked.regions.size(); ++r) {
        ld.governing_ratio = std::max(ld.governing_ratio, checked.cell(l, r).governing_ratio);
      }
      const bool safe = sf * ld.governing_ratio <= 1.0;
      ld.message = ld.material->name + " at " + Millimetres(*ld.thickness_m) + ": " +
                   (safe ? "safe at full speed" : "NOT safe at full speed when checked again") +
                   " (governing ratio " + FormatSignificant(ld.governing_ratio, 4) + ")";
      if (!safe) {
        result.warnings.push_back("link '" + result.links[l] + "': the designed covering failed its re-check");
      }
    }
  }
  return result;
}

}  // namespace covopt::optim
