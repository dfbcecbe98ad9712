#pragma once
/// @file time_optimal_path.hpp
/// Time-optimal path parameterisation (TOPP) by reachability analysis (TOPP-RA: H. Pham and
/// Q.-C. Pham, "A New Approach to Time-Optimal Path Parameterization Based on Reachability
/// Analysis", IEEE Trans. Robotics 34(3):645-659, 2018; the algorithm of the `toppra` library,
/// which no Debian package carries, hence this implementation; docs/model.md, "Re-timing").
///
/// A path q(s) is given by samples s_0 < s_1 < ... < s_{N-1} and its derivative q'(s_i) = dq/ds
/// there; between samples q' is linear in s, so q'' is constant on each segment. A
/// parameterisation s(t) is the path speed ṡ at each sample; on a segment the path acceleration
/// u = s̈ is constant, so x = ṡ² is linear in s: x_{i+1} = x_i + 2 (s_{i+1} - s_i) u_i, and the
/// segment takes 2 (s_{i+1} - s_i) / (ṡ_i + ṡ_{i+1}).
///
/// Constraints, with x = ṡ² and u = s̈ (both linear in (x_i, u_i) on segment i):
///   - the path speed: ṡ_i <= max_path_speed[i] (covopt: the safety limit of the audit at sample i,
///     and the cap on the programmed speed);
///   - the joint speeds: |q'_j(s_i)| ṡ_i <= max_joint_speed[j] at every sample;
///   - the joint accelerations: q̈_j = q'_j(s) u + q''_j x is linear in s on a segment, so it is
///     bounded at both ends of every segment: |q'_j(s_i) u_i + q''_j,i x_i| <= a_j and
///     |q'_j(s_{i+1}) u_i + q''_j,i x_{i+1}| <= a_j. The bound then holds along the whole segment.
/// The backward pass computes each sample's controllable set K_i = [x_lo, x_hi] (two 2-variable
/// LPs per segment, solved together and exactly by eliminating u: every lower bound on u against
/// every upper bound); the forward pass takes at each sample the largest u that keeps x_{i+1} in
/// K_{i+1}. The result is time-optimal among the discretised profiles.
///
///     covopt::optim::PathSamples path{s, dq_ds};
///     covopt::optim::PathLimits limits{max_path_speed, max_joint_speed, max_joint_accel};
///     const auto profile = covopt::optim::TimeOptimalParameterization(path, limits);
///     if (profile.ok()) profile.time_s.back();   // the duration

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace covopt::optim {

/// A sampled path: the path coordinate and the joints' path derivative at each sample.
struct PathSamples {
  /// The path coordinate s_i, strictly increasing [any unit; covopt uses the original program's
  /// time, so ṡ = 1 is the programmed speed].
  std::vector<double> s;
  /// q'(s_i) = dq/ds per sample, one entry per joint [rad or m per unit of s].
  std::vector<Eigen::VectorXd> dq_ds;
};

/// The bounds a parameterisation keeps.
struct PathLimits {
  /// Per sample: the largest path speed ṡ_i [unit of s per second], > 0 or +inf (none).
  /// Size: the number of samples.
  std::vector<double> max_path_speed;
  /// Per joint: the largest |q̇_j| [rad/s or m/s], > 0 or +inf (none).
  Eigen::VectorXd max_joint_speed;
  /// Per joint: the largest |q̈_j| [rad/s² or m/s²], > 0 and finite.
  Eigen::VectorXd max_joint_acceleration;
};

struct TimeOptimalOptions {
  /// The path speed at the first and the last sample [unit of s per second]; empty (default):
  /// free within the constraints (the first is the largest reachable one; the last whatever the
  /// fastest profile ends with).
  std::optional<double> start_path_speed;
  std::optional<double> end_path_speed;
  /// Relative tolerance of the LPs' feasibility tests [-]. Default 1e-9.
  double tolerance = 1e-9;
};

/// How TimeOptimalParameterization ended.
enum class TimeOptimalStatus {
  kSuccess,     ///< a profile that keeps every constraint
  kInfeasible,  ///< no profile: some sample's controllable set is empty, or the path speed is 0
                ///< at two neighbouring samples (the path would take forever), or nothing bounds
                ///< it (no joint moves and max_path_speed is +inf); message says where (samples
                ///< and joints numbered from 0)
};
/// "success" or "infeasible".
const char* ToString(TimeOptimalStatus status) noexcept;

/// Which bound holds the path speed at a sample of the profile (the largest in K_i and the
/// forward pass's choice), for "where the program had to slow".
enum class PathSpeedBound {
  kPathSpeed,         ///< max_path_speed[i] (covopt: the safety limit or the programmed speed)
  kJointSpeed,        ///< a joint's speed limit
  kJointAcceleration, ///< a joint's acceleration limit (braking into, or speeding out of, a bound)
  kBoundary,          ///< a start or end path speed given in the options
};
/// "path-speed", "joint-speed", "joint-acceleration", "boundary".
const char* ToString(PathSpeedBound bound) noexcept;

/// A time-optimal profile, by value.
struct TimeOptimalProfile {
  TimeOptimalStatus status = TimeOptimalStatus::kInfeasible;
  /// ṡ_i per sample [unit of s per second].
  std::vector<double> path_speed;
  /// u_i = s̈ on segment i (N - 1 values) [unit of s per second²].
  std::vector<double> path_acceleration;
  /// t_i per sample [s], t_0 = 0; time_s.back() is the duration.
  std::vector<double> time_s;
  /// Per sample: what holds ṡ_i (the tightest bound at that sample).
  std::vector<PathSpeedBound> bound;
  /// Per sample: the controllable set K_i's ends [x = ṡ², (unit of s per second)²].
  std::vector<double> controllable_min;
  std::vector<double> controllable_max;
  /// "success: 101 samples, 1.734 s" or where it is infeasible ("infeasible at sample 42 (s =
  /// 0.63): joint 3's acceleration limit 2 rad/s² cannot be kept at any path speed").
  std::string message;
  bool ok() const noexcept { return status == TimeOptimalStatus::kSuccess; }
  double duration_s() const noexcept { return time_s.empty() ? 0.0 : time_s.back(); }
};

/// The time-optimal parameterisation of `path` under `limits`.
/// @throws std::invalid_argument naming the field and the value: fewer than 2 samples, sizes
///         that do not match (dq_ds, max_path_speed, the joint limits), s not strictly increasing
///         or not finite, a non-finite q', a path speed bound <= 0 or NaN, a joint speed limit
///         <= 0 or NaN, an acceleration limit <= 0 or not finite, a boundary speed < 0 or above
///         its sample's bounds, a tolerance outside (0, 1e-3].
TimeOptimalProfile TimeOptimalParameterization(const PathSamples& path, const PathLimits& limits,
                                               const TimeOptimalOptions& options = {});

}  // namespace covopt::optim
