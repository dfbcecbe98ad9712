#pragma once
/// @file audit.hpp
/// `covopt audit`: the whole robot along its motion (docs/model.md §14). For every trajectory
/// sample and every surface point of every chain link (covopt/robot/surface.hpp):
///   - the point's velocity v and the reflected mass m along it (ChainSampleKinematics);
///   - every exposed body region, transient (ISO/TS 15066 Table A.2, docs/model.md §13), with
///     the link's covering on the point's radius of curvature, and optionally the head under
///     Park et al.'s criteria (the head model of scene.hpp);
///   - the ratio v / v_max(m), v_max the largest safe speed of that point against that region.
///
/// Why it is fast. In the conservative (unbraked) models the energy admitted at a region's
/// binding limit, E* = ½ μ v_max², does not depend on the robot's mass; only the reduced mass
/// μ = m m_H/(m + m_H) does. So per link, per distinct radius of curvature and per region
/// E* is computed once (MaxSafeSpeed), and a point-sample costs its kinematics and one square
/// root per region:  v_max(m) = sqrt(2 E*/μ(m)).
/// A braking robot (reaction_delay_s, braking_m_per_s2) has no such invariant; the unbraked
/// ratio is an upper bound of the braked one (braking only takes energy out), so the braked
/// ratio is computed on the time path only where the unbraked bound could govern
/// (branch and bound per link × region): the result is the braked governing ratio, exactly.
///
///     covopt::audit::AuditSetup setup{chain, surface};
///     setup.regions = table.AllLimits(covopt::ContactType::kTransient);
///     setup.head = covopt::Scene{};                         // the head under Park et al.
///     const auto result = covopt::audit::Audit(setup, trajectory);
///     result.safe_speed_scale;                              // min over links × regions

#include <cstddef>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <covopt/core/body_contact.hpp>
#include <covopt/core/scene.hpp>
#include <covopt/materials/body_regions.hpp>
#include <covopt/robot/kinematic_chain.hpp>
#include <covopt/robot/surface.hpp>
#include <covopt/robot/trajectory.hpp>

#include <covopt/optim/body_region_check.hpp>
#include <covopt/optim/covering_design.hpp>
#include <covopt/optim/trajectory_check.hpp>

namespace covopt::audit {

/// The covering of a link: a catalog material (its crush data then count) or a modulus.
struct AuditCovering {
  /// Modulus, Poisson ratio and thickness; thickness 0: the bare link.
  CoveringSpec covering{27.6e6, 0.25, 0.0};
  /// The catalog material, when it is one (its name, crush behaviour and strength).
  std::optional<optim::CandidateMaterial> material;
};

/// A zone of the cell and the body regions a person can present there (the risk assessment's
/// answer, `--exposure FILE.toml`): an axis-aligned box in the robot's base frame. A point-sample
/// is judged against a region only when the point lies in a zone that exposes that region; with
/// no zones (the default) every region is exposed everywhere. Cells that no zone exposes are
/// not judged, and the result says so.
struct ExposureZone {
  std::string name;                                  ///< "above the table"
  Eigen::Vector3d min_m = Eigen::Vector3d::Zero();   ///< the box's lower corner, base frame [m]
  Eigen::Vector3d max_m = Eigen::Vector3d::Zero();   ///< its upper corner [m], >= min_m
  /// The regions exposed there, as AuditRegionNames spells them ("chest (sternum)", "head (Park
  /// et al. 2011)"), or a region's name without its area ("lower-legs": all its areas), or
  /// "head" (Park et al.'s head), or "all". A name that is no body region of ISO/TS 15066's
  /// table and not the head is refused; a region of the table the audit does not judge (not in
  /// AuditSetup::regions) is left out (the same zone file serves an audit of fewer regions).
  std::vector<std::string> regions;
  /// Where it was read ("exposure.toml:12:1"), for messages.
  std::string origin;
};

/// What an audit judges. The chain, its surface and the exposed regions.
struct AuditSetup {
  /// The chain and its surface; the rest is set field by field (as in the example above).
  /// A constructor, so that `AuditSetup setup{chain, surface};` names every field it sets.
  AuditSetup(robot::KinematicChain chain_in, robot::RobotSurface surface_in)
      : chain(std::move(chain_in)), surface(std::move(surface_in)) {}
  /// Takes the robot's reaction (reaction_delay_s, braking_m_per_s2) from `scene` for every
  /// region and the head, and, when `judge_head`, the head from `scene` without it (the head
  /// scene itself must not brake: the brake is the setup's).
  void SetReactionAndHead(const Scene& scene, bool judge_head) {
    reaction_delay_s = scene.robot.reaction_delay_s;
    braking_m_per_s2 = scene.robot.braking_m_per_s2;
    head.reset();
    if (!judge_head) return;
    head = scene;
    head->robot.reaction_delay_s = 0.0;
    head->robot.braking_m_per_s2 = 0.0;
  }
  robot::KinematicChain chain;
  robot::RobotSurface surface;
  /// The covering of every link not in link_coverings.
  AuditCovering covering;
  /// Per link name: its own covering. A name that is not a surface link is refused.
  std::map<std::string, AuditCovering> link_coverings;
  /// The exposed body regions, transient (e.g. BodyRegionTable::AllLimits(kTransient)). A
  /// clamped entry is refused (an audit judges the free impacts of a motion).
  std::vector<materials::BodyLimits> regions;
  /// Set: the head too, under Park et al.'s criteria; its robot mass, speed, radius and
  /// covering are each point's, the rest (head layers, limits) this scene's.
  std::optional<Scene> head;
  /// The bare robot's contact area [m²] for a bare link's pressure; 0: not given, which is
  /// refused when a link is bare (its verdict would be the force's alone).
  double contact_area_m2 = 0.0;
  /// The radius of curvature [m] a covering is judged on at a flat point (robot::kFlat: a
  /// box's face, a cylinder's end disc, a flat surface-file point). The covering's Hertz
  /// contact needs a finite radius (docs/model.md §13), and no radius is a safe default
  /// (a larger one raises the force, a smaller one the pressure), so it is the user's:
  /// empty, a covered link with a flat point is refused (naming the link and the shape);
  /// given, every such point is judged at it and the result says so in its warnings. A
  /// bare link's flat points need none (its force and pressure do not read the radius).
  std::optional<double> flat_face_radius_m;
  /// Safety factor, criterion, crushing, unknown strengths.
  optim::DesignRule rule;
  /// The covering's travel rule as a limit (--keep-travel, keep_travel=True):
  /// false (default) judges injury and the law's validity, the travel reported only; true
  /// counts it unless the rule's criterion is the paper's (full compression allowed).
  bool keep_travel = false;
  /// The robot's reaction after first contact [s] and its braking deceleration [m/s²]
  /// (both 0: it does not brake), for every region and the head (docs/model.md §10.2).
  double reaction_delay_s = 0.0;
  double braking_m_per_s2 = 0.0;
  /// Rest speed, joint-limit checks, the singular tolerance.
  robot::ContactMotionOptions motion;
  /// The exposure zones (ExposureZone); empty: every region is exposed everywhere.
  std::vector<ExposureZone> exposure_zones;
};

/// The per-link design: the catalog materials to try (SelectCandidates order), and the
/// thickness scan. Empty materials: no design.
struct AuditDesignOptions {
  std::vector<optim::CandidateMaterial> materials;
  double min_thickness_m = 0.1e-3;
  double max_thickness_m = 0.05;
  int thickness_scan_points = 250;
  double thickness_resolution_m = 1e-6;
  double thickness_step_m = 0.5e-3;  ///< the recommendation is rounded up to this [m]
};

/// One link × region: the governing point-sample (largest ratio over the motion).
struct AuditCell {
  std::size_t link = 0;    ///< index into AuditResult::links
  std::size_t region = 0;  ///< index into AuditResult::regions
  /// v / (SF v_max) at the governing point-sample [-]: unscaled as every verdict's ratio, so
  /// SF × ratio <= 1 is safe and speed_scale = 1/(SF × ratio). For a bare link's force it is
  /// F_max / F_lim exactly. 0 when the link never moves; +inf where no speed is safe (v_max
  /// 0: a material refused or crushed at any speed).
  double governing_ratio = 0.0;
  /// The limit that binds v_max there. The head's criteria map onto it: laceration and
  /// contusion (surface stress and energy density of the skin) → kPressure, the covering's
  /// travel → kFullCompression, crush → kCrush (head_criterion has the head's own). kNone
  /// where v_max is the model's 100 m/s ceiling (nothing binds below it).
  optim::BodyLimitKind binding = optim::BodyLimitKind::kNone;
  /// The head's row only: its criterion (optim::LimitingCriterion::kNone on a body region's row).
  optim::LimitingCriterion head_criterion = optim::LimitingCriterion::kNone;
  /// The binding criterion's name, as every output shows it: the head's own
  /// ("laceration", "contusion", "fracture", "full-compression", "crush") on the head's row, else
  /// ToString(binding) ("force", "pressure", ...). The head model has no pressure limit.
  std::string_view binding_name() const noexcept {
    return head_criterion != optim::LimitingCriterion::kNone ? optim::ToString(head_criterion)
                                                             : optim::ToString(binding);
  }
  /// The governing sample (index, time [s]) and point (index into the link's points, its
  /// position in the link frame and in the base frame [m]); empty when the link never moves.
  std::optional<std::size_t> sample;
  double time_s = 0.0;
  std::size_t point = 0;
  Eigen::Vector3d point_in_link_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d point_in_base_m = Eigen::Vector3d::Zero();
  double speed_m_per_s = 0.0;           ///< [m/s]
  double reflected_mass_kg = 0.0;       ///< [kg]
  /// v_max there [m/s], at most the model's 100 m/s (MaxSafeSpeed's ceiling).
  double max_safe_speed_m_per_s = 0.0;
  /// min over the link's moving point-samples of v_max / v [-]; +inf when it never moves.
  double speed_scale = 0.0;
  /// Why the cell is not judged (AuditSetup::exposure_zones): "no exposure zone exposes the
  /// region", or "the link's moving points never enter a zone exposing the region". Empty when
  /// it is judged (or when the link never moves: then `sample` alone is empty). A not-judged
  /// cell has no sample, ratio 0 and scale +inf: it limits nothing, and it did not pass.
  std::string not_judged;
};

/// Per link: the thinnest catalog covering that makes the whole motion safe at full speed
/// against every region (and the head), checked again by a second audit of that link.
struct AuditLinkDesign {
  std::size_t link = 0;
  std::optional<optim::CandidateMaterial> material;  ///< empty: none in range (or no need: see message)
  std::optional<double> thickness_m;          ///< rounded up to the step
  double governing_ratio = 0.0;               ///< re-checked, at that covering [-]
  std::string message;
};

/// One sample's verdict for streaming (AuditOptions::on_sample): per link, the largest ratio
/// over its points and the regions [-] (0 for a link at rest), and the region that sets it.
/// For a braking robot these are the unbraked ratios, upper bounds of the braked ones (the
/// cells are the braked robot's; docs/model.md §14.4).
struct AuditSampleRow {
  std::size_t sample = 0;
  double time_s = 0.0;
  std::span<const double> link_ratio;
  std::span<const std::size_t> link_region;
};

struct AuditOptions {
  /// Keep the samples × links ratio matrix (AuditResult::ratio_over_time) for the heat map.
  /// false: memory does not grow with the trajectory's length (except for a braking robot,
  /// whose branch and bound keeps the point-samples that could govern a cell).
  bool keep_ratio_over_time = true;
  /// Called once per sample, in order (streaming output).
  std::function<void(const AuditSampleRow&)> on_sample;
  /// The per-link design (no design when its materials are empty).
  AuditDesignOptions design;
};

/// The answer of Audit.
struct AuditResult {
  optim::TrajectoryCheckStatus status = optim::TrajectoryCheckStatus::kAtRest;  ///< safe, unsafe, at-rest
  std::vector<std::string> links;    ///< the surface's links, base to tip
  std::vector<std::size_t> link_point_counts;
  /// "chest (sternum)", ..., and "head (Park et al. 2011)" last when the head is judged.
  std::vector<std::string> regions;
  /// links × regions, row-major (cells[link * regions.size() + region]).
  std::vector<AuditCell> cells;
  /// min over cells of speed_scale [-]: the factor every speed of the program may be scaled
  /// by; +inf at rest throughout. With the safety factor: ratio 1/SF ⇔ scale 1.
  double safe_speed_scale = 0.0;
  std::optional<std::size_t> limiting_cell;  ///< the cell that sets it
  std::size_t sample_count = 0;
  /// samples × links, row-major, when kept: the largest ratio per sample and link.
  std::vector<double> ratio_over_time;
  std::vector<double> time_s;  ///< the sample times, when kept
  std::vector<AuditLinkDesign> link_designs;
  /// The exposure zones judged with (AuditSetup::exposure_zones); empty: every region everywhere.
  std::vector<ExposureZone> exposure_zones;
  /// The number of cells not judged (AuditCell::not_judged).
  std::size_t not_judged_cells = 0;
  /// One sentence: "unsafe: slow the program to 0.62× (fr3_link7, chest (sternum), force,
  /// t = 0.42 s)".
  std::string message;
  /// What every verdict covers: one line per standard or model applied.
  std::vector<std::string> scope;
  std::vector<std::string> warnings;
  const AuditCell& cell(std::size_t link, std::size_t region) const {
    return cells[link * regions.size() + region];
  }
};

/// The names of the regions an audit of `setup` judges, in AuditResult::regions' order (known
/// before it runs: the streamed rows' header).
std::vector<std::string> AuditRegionNames(const AuditSetup& setup);

/// Audits `trajectory` (its samples are checked as ContactMotion checks them).
/// @throws std::invalid_argument naming the field: no regions and no head, a clamped region, a
///         link covering for a link not on the surface, a bare link without a contact area, a
///         covering's modulus, Poisson ratio or thickness out of range, a bad sample (file and
///         line), braking out of range.
AuditResult Audit(const AuditSetup& setup, const robot::JointTrajectory& trajectory,
                  const AuditOptions& options = {});

}  // namespace covopt::audit
