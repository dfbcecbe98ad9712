#pragma once
// Shared internals of Retime (retime.cpp), its braking robot's per-sample limits
// (retime_braking.cpp) and the cycle-time sweep (retime_sweep.cpp). Not installed.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <covopt/optim/time_optimal_path.hpp>

#include "audit_internal.hpp"
#include "covopt/audit/retime.hpp"

namespace covopt::audit::detail {

/// What does not depend on the covering: the validated joint limits, the path (s = the
/// original's times, q'(s) = its velocities) and the joints' uniform speed scale.
struct RetimeInputs {
  Eigen::VectorXd speed_limits;
  Eigen::VectorXd acceleration_limits;
  optim::PathSamples path;
  /// The largest constant path speed the joints allow: min over samples and joints of
  /// v_j/|q'_j| and sqrt(a_j/|q''_j|) (q'' per segment, as the parameterisation differences it).
  double joint_scale = 0.0;
  std::vector<std::string> warnings;
};

/// Validates `options` and the trajectory's times and sizes (throws naming the field) and
/// prepares the inputs.
RetimeInputs PrepareRetime(const robot::KinematicChain& chain, const robot::JointTrajectory& trajectory,
                           const RetimeOptions& options);

/// min over samples and joints of v_j/|q'_j| and sqrt(a_j/|q''_j|) (+inf: no joint moves).
double JointSpeedScale(const optim::PathSamples& path, const Eigen::VectorXd& speed_limits,
                       const Eigen::VectorXd& acceleration_limits);

/// Per sample: the largest safe path speed ṡ_max = 1/(SF × the largest ratio over links) (+inf
/// where nothing moves, 0 where no speed is safe) and the link and region that set it.
struct SafePathSpeed {
  std::vector<double> speed;
  std::vector<std::size_t> link;
  std::vector<std::size_t> region;
  std::vector<std::string> warnings;
  std::optional<std::string> failure;  ///< the braked time path failed
};

/// The unbraked per-sample limits, from the audit's streamed rows; the audit into `audit`.
SafePathSpeed SafePathSpeedOf(const AuditSetup& setup, const robot::JointTrajectory& trajectory,
                              bool keep_ratio_over_time, AuditResult& audit);

/// As SafePathSpeedOf, and for a braking robot each sample's braked limit (retime_braking.cpp).
SafePathSpeed SafePathSpeedFor(const AuditSetup& setup, const robot::JointTrajectory& trajectory,
                               bool keep_ratio_over_time, AuditResult& audit);

/// Retime with prepared inputs (the sweep shares them).
RetimeResult RetimeWith(const AuditSetup& setup, const robot::JointTrajectory& trajectory,
                        const RetimeOptions& options, const RetimeInputs& in);

}  // namespace covopt::audit::detail
