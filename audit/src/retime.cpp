// `covopt retime`: the fastest timing of a program's path that is safe at every sample
// (docs/model.md, "Re-timing"). The audit of the program gives each sample's safe path speed;
// the time-optimal parameterisation (TOPP-RA, optim/time_optimal_path.hpp) finds the fastest
// timing under it and the joints' limits; the re-timed program is audited again.
#include "covopt/audit/retime.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <covopt/core/number_format.hpp>

#include "retime_internal.hpp"
#include "validation_internal.hpp"

namespace covopt::audit {

const char* ToString(RetimeStatus status) noexcept {
  switch (status) {
    case RetimeStatus::kSafe: return "safe";
    case RetimeStatus::kAtRest: return "at-rest";
    case RetimeStatus::kInfeasible: return "infeasible";
    case RetimeStatus::kNotSafe: return "not-safe";
    case RetimeStatus::kEvaluationFailed: return "evaluation-failed";
  }
  return "unknown";
}

namespace detail {
namespace {

using optim::internal::Number;
using optim::internal::Require;

/// A per-joint limit vector: its size and every entry in range (> 0; finite unless `may_be_inf`).
void ValidateJointLimits(const Eigen::VectorXd& limits, std::size_t joint_count, const std::string& field,
                         const char* unit, bool may_be_inf) {
  Require(static_cast<std::size_t>(limits.size()) == joint_count,
          field + " has " + std::to_string(limits.size()) + " entries; the chain has " +
              std::to_string(joint_count) + " joints (one value per joint)");
  for (Eigen::Index j = 0; j < limits.size(); ++j) {
    const double a = limits[j];
    const bool ok = a > 0.0 && (may_be_inf ? !std::isnan(a) : std::isfinite(a));
    Require(ok, field + "[" + std::to_string(j) + "] must be " + (may_be_inf ? "> 0 " : "finite and > 0 ") + unit +
                    (may_be_inf ? " (or +inf: none)" : "") + " (got " + Number(a) + ")");
  }
}

/// The URDF's velocity limit of every movable joint (+inf where it gives none, with a warning).
Eigen::VectorXd UrdfSpeedLimits(const robot::KinematicChain& chain, std::vector<std::string>& warnings) {
  Eigen::VectorXd limits(static_cast<Eigen::Index>(chain.joint_count()));
  Eigen::Index j = 0;
  std::string unlimited;
  for (const robot::ChainJoint& joint : chain.joints()) {
    if (joint.type == robot::JointType::kFixed) continue;
    if (j >= limits.size()) break;
    const bool given = joint.limits.has_velocity && joint.limits.velocity > 0.0;
    limits[j++] = given ? joint.limits.velocity : kInf;
    if (!given) unlimited += (unlimited.empty() ? "" : ", ") + joint.name;
  }
  for (; j < limits.size(); ++j) limits[j] = kInf;
  if (!unlimited.empty()) {
    warnings.push_back("joint speed limits: the URDF gives none for " + unlimited +
                       "; their speed is not limited (give joint_speed_limits)");
  }
  return limits;
}

}  // namespace

RetimeInputs PrepareRetime(const robot::KinematicChain& chain, const robot::JointTrajectory& trajectory,
                           const RetimeOptions& options) {
  const std::size_t n = chain.joint_count();
  Require(std::isfinite(options.max_speed_scale) && options.max_speed_scale > 0.0 && options.max_speed_scale <= 100.0,
          "max_speed_scale must be in (0, 100] (got " + Number(options.max_speed_scale) + ")");
  Require(std::isfinite(options.tolerance) && options.tolerance >= 0.0 && options.tolerance <= 1e-2,
          "tolerance must be in [0, 1e-2] (got " + Number(options.tolerance) + ")");
  Require(options.joint_acceleration_limits.has_value(),
          "joint_acceleration_limits: none given; a URDF gives no acceleration limits (--joint-accel-limit: one "
          "value for every joint or one per joint, rad/s²)");
  RetimeInputs in;
  ValidateJointLimits(*options.joint_acceleration_limits, n, "joint_acceleration_limits", "rad/s² (m/s²)", false);
  in.acceleration_limits = *options.joint_acceleration_limits;
  if (options.joint_speed_limits) {
    ValidateJointLimits(*options.joint_speed_limits, n, "joint_speed_limits", "rad/s (m/s)", true);
    in.speed_limits = *options.joint_speed_limits;
  } else {
    in.speed_limits = UrdfSpeedLimits(chain, in.warnings);
  }
  Require(trajectory.size() >= 2, "trajectory: " + std::to_string(trajectory.size()) +
                                      " sample(s); a path to re-time needs at least 2");
  Require(trajectory.velocities.size() == trajectory.size() && trajectory.positions.size() == trajectory.size(),
          "trajectory: time_s, positions and velocities differ in length");
  for (std::size_t i = 0; i + 1 < trajectory.size(); ++i) {
    const double t0 = trajectory.time_s[i], t1 = trajectory.time_s[i + 1];
    Require(std::isfinite(t0) && std::isfinite(t1) && t1 > t0,
            SampleWhere(trajectory, i + 1) + ": time " + Number(t1) + " s is not after the sample before's " +
                Number(t0) + " s; a path to re-time needs strictly increasing times");
  }
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    Require(static_cast<std::size_t>(trajectory.velocities[i].size()) == n,
            SampleWhere(trajectory, i) + ": " + std::to_string(trajectory.velocities[i].size()) +
                " velocities; the chain has " + std::to_string(n) + " joints");
  }
  in.path.s = trajectory.time_s;
  in.path.dq_ds = trajectory.velocities;
  in.joint_scale = JointSpeedScale(in.path, in.speed_limits, in.acceleration_limits);
  return in;
}

double JointSpeedScale(const optim::PathSamples& path, const Eigen::VectorXd& speed_limits,
                       const Eigen::VectorXd& acceleration_limits) {
  double c = kInf;
  for (std::size_t i = 0; i < path.s.size(); ++i) {
    const Eigen::VectorXd& dq = path.dq_ds[i];
    for (Eigen::Index j = 0; j < dq.size(); ++j) {
      if (std::abs(dq[j]) > 0.0) c = std::min(c, speed_limits[j] / std::abs(dq[j]));
      if (i + 1 == path.s.size()) continue;
      // q'' on the segment, as the parameterisation differences it: at a constant path speed c,
      // |q̈_j| = |q''_j| c² <= a_j.
      const double ddq = (path.dq_ds[i + 1][j] - dq[j]) / (path.s[i + 1] - path.s[i]);
      if (std::abs(ddq) > 0.0) c = std::min(c, std::sqrt(acceleration_limits[j] / std::abs(ddq)));
    }
  }
  return c;
}

SafePathSpeed SafePathSpeedOf(const AuditSetup& setup, const robot::JointTrajectory& trajectory,
                              bool keep_ratio_over_time, AuditResult& audit) {
  SafePathSpeed out;
  const std::size_t n = trajectory.size();
  out.speed.assign(n, kInf);
  out.link.assign(n, 0);
  out.region.assign(n, 0);
  const double sf = setup.rule.safety_factor;
  AuditOptions options;
  options.keep_ratio_over_time = keep_ratio_over_time;
  options.on_sample = [&](const AuditSampleRow& row) {
    double worst = 0.0;
    for (std::size_t l = 0; l < row.link_ratio.size(); ++l) {
      if (row.link_ratio[l] > worst) {
        worst = row.link_ratio[l];
        out.link[row.sample] = l;
        out.region[row.sample] = row.link_region[l];
      }
    }
    out.speed[row.sample] = worst > 0.0 ? 1.0 / (sf * worst) : kInf;  // +inf ratio: 0 (no safe speed)
  };
  audit = Audit(setup, trajectory, options);
  return out;
}

namespace {

/// The re-timed program: the original's positions at the profile's times (from the original's
/// first time), velocities q'(s_i) ṡ_i.
robot::JointTrajectory Retimed(const robot::JointTrajectory& original, const optim::TimeOptimalProfile& profile) {
  robot::JointTrajectory out;
  out.source_name = (original.source_name.empty() ? std::string("trajectory") : original.source_name) +
                    " (re-timed)";
  out.positions = original.positions;
  out.time_s.resize(original.size());
  out.velocities.resize(original.size());
  for (std::size_t i = 0; i < original.size(); ++i) {
    out.time_s[i] = original.time_s.front() + profile.time_s[i];
    out.velocities[i] = original.velocities[i] * profile.path_speed[i];
  }
  return out;
}

std::string Seconds(double t) { return FormatSignificant(t, 4) + " s"; }

/// The first sample with no safe speed (a region refused at any speed), if any.
std::optional<std::size_t> NoSafeSpeed(const SafePathSpeed& safe) {
  for (std::size_t i = 0; i < safe.speed.size(); ++i) {
    if (!(safe.speed[i] > 0.0)) return i;
  }
  return std::nullopt;
}

void SetScope(const RetimeInputs& in, double max_speed_scale, RetimeResult& r) {
  r.scope = r.before.scope;
  std::string line =
      "Re-timing: the program's path kept, its timing the time-optimal parameterisation (TOPP-RA, Pham and Pham "
      "2018) under each sample's safe path speed from the audit";
  line += max_speed_scale == 1.0 ? ", never faster than programmed"
                                 : ", at most " + FormatSignificant(max_speed_scale, 4) + "× the programmed speed";
  line += ", the joints' speed limits (";
  for (Eigen::Index j = 0; j < in.speed_limits.size(); ++j) {
    line += (j ? ", " : "") + FormatSignificant(in.speed_limits[j], 4);
  }
  line += " rad/s or m/s) and acceleration limits (";
  for (Eigen::Index j = 0; j < in.acceleration_limits.size(); ++j) {
    line += (j ? ", " : "") + FormatSignificant(in.acceleration_limits[j], 4);
  }
  line += " rad/s² or m/s²); the re-timed program audited again";
  r.scope.push_back(std::move(line));
}

}  // namespace

RetimeResult RetimeWith(const AuditSetup& setup, const robot::JointTrajectory& trajectory,
                        const RetimeOptions& options, const RetimeInputs& in) {
  RetimeResult r;
  r.joint_speed_limits = in.speed_limits;
  r.joint_acceleration_limits = in.acceleration_limits;
  r.original_time_s = trajectory.time_s;
  r.original_cycle_time_s = trajectory.time_s.back() - trajectory.time_s.front();
  const SafePathSpeed safe = SafePathSpeedFor(setup, trajectory, options.keep_ratio_over_time, r.before);
  r.safe_path_speed = safe.speed;
  r.limiting_link = safe.link;
  r.limiting_region = safe.region;
  r.warnings = r.before.warnings;
  r.warnings.insert(r.warnings.end(), in.warnings.begin(), in.warnings.end());
  r.warnings.insert(r.warnings.end(), safe.warnings.begin(), safe.warnings.end());
  SetScope(in, options.max_speed_scale, r);
  r.uniform_speed_scale = std::min({r.before.safe_speed_scale, options.max_speed_scale, in.joint_scale});
  r.uniform_cycle_time_s = r.uniform_speed_scale > 0.0 ? r.original_cycle_time_s / r.uniform_speed_scale : kInf;
  r.cycle_time_s = kInf;
  if (r.before.status == optim::TrajectoryCheckStatus::kEvaluationFailed || safe.failure) {
    r.status = RetimeStatus::kEvaluationFailed;
    r.message = safe.failure ? "evaluation failed: " + *safe.failure : r.before.message;
    return r;
  }
  if (r.before.status == optim::TrajectoryCheckStatus::kAtRest) {
    r.status = RetimeStatus::kAtRest;
    r.trajectory = trajectory;
    r.path_speed.assign(trajectory.size(), 1.0);
    r.bound.assign(trajectory.size(), optim::PathSpeedBound::kPathSpeed);
    r.cycle_time_s = r.original_cycle_time_s;
    r.uniform_speed_scale = 1.0;
    r.uniform_cycle_time_s = r.original_cycle_time_s;
    r.message = "at rest: no surface point moves; the program is returned unchanged";
    return r;
  }
  if (const std::optional<std::size_t> i = NoSafeSpeed(safe)) {
    r.status = RetimeStatus::kInfeasible;
    r.message = "infeasible: at t = " + Seconds(trajectory.time_s[*i]) + " " + r.before.links[safe.link[*i]] +
                " has no safe speed against " + r.before.regions[safe.region[*i]] + "; no timing is safe";
    return r;
  }
  optim::PathLimits limits{std::vector<double>(trajectory.size()), in.speed_limits, in.acceleration_limits};
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    // A hair below the limit (1e-7, relative): the re-timed program at its limit must audit as safe
    // (scale >= 1) in `covopt audit` too, not at 1 - 4e-16 from rounding.
    limits.max_path_speed[i] = std::min(safe.speed[i] * (1.0 - 1e-7), options.max_speed_scale);
  }
  r.profile = optim::TimeOptimalParameterization(in.path, limits);
  if (!r.profile.ok()) {
    r.status = RetimeStatus::kInfeasible;
    r.message = "infeasible: " + r.profile.message;
    return r;
  }
  r.path_speed = r.profile.path_speed;
  r.bound = r.profile.bound;
  r.cycle_time_s = r.profile.duration_s();
  robot::JointTrajectory retimed = Retimed(trajectory, r.profile);
  AuditOptions again;
  again.keep_ratio_over_time = options.keep_ratio_over_time;
  try {
    r.after = Audit(setup, retimed, again);
  } catch (const std::invalid_argument& e) {  // e.g. a joint speed beyond the plausible range
    r.status = RetimeStatus::kNotSafe;
    r.message = std::string("not safe: the re-timed program could not be audited: ") + e.what();
    return r;
  }
  const std::string times = "(original " + Seconds(r.original_cycle_time_s) + ", uniform slow-down " +
                            Seconds(r.uniform_cycle_time_s) + ")";
  if (r.after.status == optim::TrajectoryCheckStatus::kEvaluationFailed ||
      !(r.after.safe_speed_scale >= 1.0 - options.tolerance)) {
    r.status = RetimeStatus::kNotSafe;
    r.message = "not safe: the re-timed program's audit finds " + r.after.message + " " + times +
                "; a defect of the re-timing, not an answer";
    return r;
  }
  r.status = RetimeStatus::kSafe;
  r.trajectory = std::move(retimed);
  r.message = "safe: re-timed to " + Seconds(r.cycle_time_s) + " " + times;
  return r;
}

}  // namespace detail

RetimeResult Retime(const AuditSetup& setup, const robot::JointTrajectory& trajectory,
                    const RetimeOptions& options) {
  const detail::RetimeInputs in = detail::PrepareRetime(setup.chain, trajectory, options);
  return detail::RetimeWith(setup, trajectory, options, in);
}

}  // namespace covopt::audit
