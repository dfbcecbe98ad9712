#pragma once
/// @file retime.hpp
/// `covopt retime`: the fastest program that is safe everywhere (docs/model.md, "Re-timing";
/// docs/guide/retime.md). The audit's answer to an unsafe program is one speed scale for all
/// of it, set by one link at one instant. Re-timing keeps the program's path (its joint
/// positions, sample by sample) and finds the fastest timing of it that is safe at every sample
/// and keeps the joints' speed and acceleration limits:
///   1. the audit of the program gives, per sample i, the largest safe path speed
///      ṡ_max(s_i) = min over links, points and regions of v_max/v (the safe speed scale of that
///      sample alone; with braking, the braked robot's, as the audit's cells are);
///   2. ṡ_max is capped by max_speed_scale (1: never faster than programmed), and the
///      time-optimal parameterisation (optim/time_optimal_path.hpp, TOPP-RA) finds ṡ(s) under it
///      and the joints' limits; the path coordinate s is the original program's time;
///   3. the re-timed trajectory (the same positions, new times, velocities q̇ = q'(s) ṡ) is
///      audited again: it must be safe at every sample (scale >= 1 - tolerance).
///
///     covopt::audit::RetimeOptions options;
///     options.joint_acceleration_limits = Eigen::VectorXd::Constant(7, 10.0);   // rad/s²
///     const auto r = covopt::audit::Retime(setup, trajectory, options);
///     r.cycle_time_s; r.uniform_cycle_time_s; r.trajectory;                    // the new program

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <covopt/optim/time_optimal_path.hpp>
#include <covopt/robot/trajectory.hpp>

#include "covopt/audit/audit.hpp"

namespace covopt::audit {

struct RetimeOptions {
  /// Per joint, the largest |q̈| [rad/s² or m/s²], > 0 and finite. Required: a URDF gives none
  /// (`--joint-accel-limit`, one value for every joint or one per joint).
  std::optional<Eigen::VectorXd> joint_acceleration_limits;
  /// Per joint, the largest |q̇| [rad/s or m/s], > 0 or +inf; empty (default): the URDF's
  /// <limit velocity> of each joint (+inf where it gives none, and a warning says so).
  std::optional<Eigen::VectorXd> joint_speed_limits;
  /// The largest path speed relative to the program [-], in (0, 100]. Default 1: the re-timed
  /// program never moves faster than programmed; it only slows where it must. Above 1 it may
  /// also speed up where the audit and the joints allow.
  double max_speed_scale = 1.0;
  /// The re-audit's acceptance: every sample's safe speed scale >= 1 - tolerance [-], in
  /// [0, 1e-2]. Default 1e-6.
  double tolerance = 1e-6;
  /// Keep the re-audit's samples × links ratio matrix (for the heat map). Default false.
  bool keep_ratio_over_time = false;
};

/// How Retime ended.
enum class RetimeStatus {
  kSafe,              ///< the re-timed program is safe at every sample (re-audited)
  kAtRest,            ///< no surface point moves: nothing to re-time (the program is returned)
  kInfeasible,        ///< no timing is safe: some sample has no safe speed (a region refused at
                      ///< any speed), or the joints' limits cannot be kept; message says where
  kNotSafe,           ///< the re-audit found a sample over the tolerance (a defect: reported,
                      ///< never presented as an answer)
  kEvaluationFailed,  ///< the audit could not judge (the braking robot's time path failed)
};
/// "safe", "at-rest", "infeasible", "not-safe", "evaluation-failed".
const char* ToString(RetimeStatus status) noexcept;

/// The answer of Retime.
struct RetimeResult {
  RetimeStatus status = RetimeStatus::kInfeasible;
  /// The re-timed program: the original's positions at new times, velocities q'(s) ṡ. Empty
  /// unless status is kSafe or kAtRest.
  robot::JointTrajectory trajectory;
  /// Per sample of the original program (same order): its time [s], the largest safe path
  /// speed from the audit ṡ_max (+inf where nothing moves) [-], the path speed chosen ṡ (the
  /// speed scale at that instant) [-], and what holds it there.
  std::vector<double> original_time_s;
  std::vector<double> safe_path_speed;
  std::vector<double> path_speed;
  std::vector<optim::PathSpeedBound> bound;
  /// The link and region whose limit gives safe_path_speed at each sample (indices into
  /// before.links and before.regions; meaningless where safe_path_speed is +inf).
  std::vector<std::size_t> limiting_link;
  std::vector<std::size_t> limiting_region;
  /// Cycle times [s]: the re-timed program's, the original's, and the uniform slow-down's
  /// (the original slowed by one factor c = min(the audit's safe speed scale, max_speed_scale,
  /// the joints' speed and acceleration scales), T / c).
  double cycle_time_s = 0.0;
  double original_cycle_time_s = 0.0;
  double uniform_cycle_time_s = 0.0;
  double uniform_speed_scale = 0.0;  ///< c [-]
  /// The audit of the original program and of the re-timed one.
  AuditResult before;
  AuditResult after;
  /// The joint limits used (per joint) [rad/s, rad/s²].
  Eigen::VectorXd joint_speed_limits;
  Eigen::VectorXd joint_acceleration_limits;
  /// The parameterisation's own answer (its status and message when infeasible).
  optim::TimeOptimalProfile profile;
  /// One sentence: "safe: re-timed to 1.734 s (original 1.5 s, uniform slow-down 3.316 s)".
  std::string message;
  std::vector<std::string> scope;
  std::vector<std::string> warnings;
};

/// Re-times `trajectory` for `setup` (Audit's setup: the surface, coverings, regions, head,
/// rule, braking, exposure zones).
/// @throws std::invalid_argument naming the field and the value: what Audit refuses, no
///         acceleration limits, limits of the wrong size, out of range or NaN, a
///         max_speed_scale or tolerance out of range, fewer than 2 samples, two samples at the
///         same time (a path needs increasing times).
RetimeResult Retime(const AuditSetup& setup, const robot::JointTrajectory& trajectory,
                    const RetimeOptions& options);

/// One covering of the cycle-time sweep: the covering every link wears (its thickness is the
/// sweep's), or the per-link design (every link's thinnest catalog covering; see
/// AuditDesignOptions) when `design` is set.
struct CycleTimeDesign {
  std::string name;  ///< "PU foam PORON 4701-30 320", "per-link design"
  AuditCovering covering;
  std::optional<AuditDesignOptions> design;
};

/// One point of the sweep.
struct CycleTimePoint {
  std::size_t design = 0;        ///< index into the designs
  double thickness_m = 0.0;      ///< [m]; the per-link design's largest link thickness
  RetimeStatus status = RetimeStatus::kInfeasible;
  double cycle_time_s = 0.0;          ///< [s]; +inf when infeasible
  double uniform_cycle_time_s = 0.0;  ///< [s]; +inf when no uniform scale is safe
  double safe_speed_scale = 0.0;      ///< the audit's uniform scale at this covering [-]
  std::string message;
};

/// Cycle time against covering thickness: Retime at every thickness of `thicknesses_m` [m, >= 0,
/// 0: bare] for every design (the per-link design's point is one per design, at no fixed
/// thickness). Points that fail are kept with their status and message.
std::vector<CycleTimePoint> CycleTimeAgainstThickness(const AuditSetup& setup,
                                                      const robot::JointTrajectory& trajectory,
                                                      const RetimeOptions& options,
                                                      const std::vector<CycleTimeDesign>& designs,
                                                      const std::vector<double>& thicknesses_m);

}  // namespace covopt::audit
