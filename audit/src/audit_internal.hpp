#pragma once
// Shared internals of the audit's sources (audit.cpp: the setup, the pass over the trajectory and
// the result; audit_braking.cpp: the braking robot's branch and bound; audit_design.cpp: the
// per-link design). Not installed.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <covopt/core/number_format.hpp>
#include <covopt/optim/speed_limit.hpp>
#include <covopt/robot/link_kinematics.hpp>

#include "covopt/audit/audit.hpp"

namespace covopt::audit::detail {

using namespace covopt::optim;  // the audit judges with optim's limits and rules

inline constexpr double kInf = std::numeric_limits<double>::infinity();
/// The impact models' speed range [m/s]: below the lowest a point is at rest (as
/// CheckTrajectory), above the highest MaxSafeSpeed answers its ceiling.
inline constexpr double kModelMinSpeed_m_per_s = 1e-6;
inline constexpr double kModelMaxSpeed_m_per_s = 100.0;

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

inline BodyLimitKind FromHead(LimitingCriterion criterion) noexcept {
  switch (criterion) {
    case LimitingCriterion::kLaceration:
    case LimitingCriterion::kContusion: return BodyLimitKind::kPressure;
    case LimitingCriterion::kFullCompression: return BodyLimitKind::kFullCompression;
    case LimitingCriterion::kCrush: return BodyLimitKind::kCrush;
    case LimitingCriterion::kFracture: return BodyLimitKind::kForce;  // the bone's fracture force
    case LimitingCriterion::kLawValidity: return BodyLimitKind::kLawValidity;
    case LimitingCriterion::kNone: break;
  }
  return BodyLimitKind::kNone;
}

/// v_max(m) [m/s] from a limit: sqrt(2 E* (1/m + 1/m_H)), capped at the model's ceiling.
inline double MaxSpeed(const EnergyLimit& limit, double inverse_mass_sum) noexcept {
  if (limit.ceiling) return kModelMaxSpeed_m_per_s;
  return std::min(kModelMaxSpeed_m_per_s, std::sqrt(2.0 * limit.energy_J * inverse_mass_sum));
}

/// The exposure zones of a setup (AuditSetup::exposure_zones), resolved against the regions an
/// audit judges: the one predicate "is region r exposed at this point" of every pass over the
/// trajectory (the audit's, the braking robot's search, the re-timing's per-sample limits).
/// A point on a box's face or edge counts as inside (min_m <= p <= max_m per axis).
class Exposure {
 public:
  /// @throws std::invalid_argument naming the zone (its origin) and the field: a non-finite
  ///         corner, min_m above max_m, no regions, a name that is no region, a zone named twice.
  Exposure(const AuditSetup& setup, const std::vector<std::string>& region_names);
  /// No zones: every region is exposed everywhere.
  bool everywhere() const noexcept { return zones_.empty(); }
  /// Whether any zone exposes region r (everywhere(): true).
  bool Anywhere(std::size_t r) const noexcept { return everywhere() || anywhere_[r] != 0; }
  /// The regions exposed at `p_m` (base frame) into `mask` (one entry per region, 1: exposed);
  /// false when none is.
  bool At(const Eigen::Vector3d& p_m, std::vector<std::uint8_t>& mask) const {
    mask.assign(n_regions_, everywhere() ? 1 : 0);
    if (everywhere()) return true;
    bool any = false;
    for (const Zone& z : zones_) {
      if (!((p_m.array() >= z.min_m.array()).all() && (p_m.array() <= z.max_m.array()).all())) continue;
      for (std::size_t r = 0; r < n_regions_; ++r) mask[r] |= z.regions[r];
      any = true;
    }
    return any;
  }
  /// Whether region r is exposed at `p_m` (base frame).
  bool Exposes(const Eigen::Vector3d& p_m, std::size_t r) const {
    if (everywhere()) return true;
    for (const Zone& z : zones_) {
      if (z.regions[r] && (p_m.array() >= z.min_m.array()).all() && (p_m.array() <= z.max_m.array()).all()) {
        return true;
      }
    }
    return false;
  }

 private:
  struct Zone {
    Eigen::Vector3d min_m, max_m;
    std::vector<std::uint8_t> regions;  ///< per judged region: 1 when the zone exposes it
  };
  std::size_t n_regions_ = 0;
  std::vector<Zone> zones_;
  std::vector<std::uint8_t> anywhere_;
};

/// The regions judged: the body regions, then the head.
class RegionLimits {
 public:
  explicit RegionLimits(const AuditSetup& setup)
      : setup_(setup), names_(AuditRegionNames(setup)), exposure_(setup, names_) {
    for (const materials::BodyLimits& limits : setup.regions) {
      inverse_body_mass_.push_back(1.0 / limits.effective_mass_kg());
    }
    if (setup.head) inverse_body_mass_.push_back(1.0 / setup.head->head.mass_kg);
  }
  std::size_t size() const noexcept { return names_.size(); }
  const std::vector<std::string>& names() const noexcept { return names_; }
  /// 1/m_H of region r [1/kg].
  double inverse_body_mass(std::size_t r) const noexcept { return inverse_body_mass_[r]; }
  bool is_head(std::size_t r) const noexcept { return setup_.head && r + 1 == names_.size(); }
  /// Where each region is exposed (AuditSetup::exposure_zones).
  const Exposure& exposure() const noexcept { return exposure_; }

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
          MaxSafeSpeed(scene, setup_.regions[r],
                       BodyRegionOptions{rule, covered ? covering.material : std::nullopt,
                                         setup_.keep_travel && rule.compression_counts()});
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
    options.keep_travel = setup_.keep_travel;
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
  Exposure exposure_;
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

std::string Millimetres(double m);
std::string SampleWhere(const robot::JointTrajectory& t, std::size_t i);

/// The radii of a link's points as judged with `covering`: the surface's, a flat point's
/// replaced by flat_face_radius_m when covered. Throws for a covered flat point without one.
void PlanRadii(const AuditSetup& setup, const robot::LinkSurface& link, bool covered, LinkPlan& plan);

/// The surface's links, each with its covering and its limits per distinct radius and region
/// (throws for a link off the chain, a bare link without a contact area, a covered flat point
/// without flat_face_radius_m); their names and point counts into `result` (audit.cpp).
std::vector<LinkPlan> PlanLinks(const AuditSetup& setup, const RegionLimits& regions, AuditResult& result);

/// The pass over the trajectory: cells, the per-sample rows, and (for the design) each link's
/// energy demand per radius and region.
struct Pass {
  std::vector<AuditCell> cells;
  std::vector<double> ratio_over_time;
  std::vector<double> time_s;
  /// Per link: radii × regions, max over its moving point-samples of ½ μ v² [J].
  std::vector<std::vector<double>> demand_J;
  std::vector<std::uint8_t> link_moves;  ///< per link: 1 when some point-sample of it moves
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

/// What the branch and bound of a braking robot reports.
struct BrakingOutcome {
  std::size_t evaluations = 0;             ///< braked limits computed (time path)
  std::size_t fixed_direction_points = 0;  ///< point-samples along a fixed direction: unbraked
  std::size_t non_monotone_cells = 0;      ///< cells whose braked limit rose with the mass
  std::optional<std::string> failure;      ///< the first time-path failure
};

/// A braking robot (docs/model.md §14.4): replaces every cell's unbraked governing
/// point-sample by the braked one, exactly (audit_braking.cpp).
BrakingOutcome ApplyBraking(const AuditSetup& setup, const robot::JointTrajectory& trajectory,
                            const RegionLimits& regions, const std::vector<LinkPlan>& plans,
                            std::vector<AuditCell>& cells);

/// The per-link design of options.design (audit_design.cpp): per link the thinnest catalog
/// covering for the demand `pass` collected, then a second audit with every designed link at
/// its covering; fills result.link_designs and its warnings.
void DesignLinks(const AuditSetup& setup, const robot::JointTrajectory& trajectory, const AuditOptions& options,
                 const RegionLimits& regions, const std::vector<LinkPlan>& plans, const Pass& pass,
                 AuditResult& result);

}  // namespace covopt::audit::detail
