#pragma once
/// @file trajectory.hpp
/// A joint trajectory and the motion of a contact point along it: per sample, the point's
/// velocity J_v(q) q̇, its speed and direction, and the reflected mass along that direction
/// (reflected_mass.hpp). This is the kinematics of a trajectory check; the injury ratios and
/// speed limits at each sample are the caller's.
///
/// The CSV file: an optional header line, then one line per sample:
///
///     time_s, q1, ..., qn, qd1, ..., qdn
///
/// time [s] (non-decreasing), the n joint positions [rad, or m for a prismatic joint], the n
/// joint velocities [rad/s or m/s], in the chain's joint order (KinematicChain::joint_names).
/// Blank lines and lines starting with '#' are skipped. The first other line is the header
/// unless every one of its cells is a number: then the file has no header, that line is the
/// first sample, and the trajectory carries a warning saying the columns were assumed to be
/// time, positions, velocities. Either way every line must have exactly 1 + 2n columns.
/// Numbers are decimal (1, -0.5, 2.5e-3; no hex, inf or nan). Limits: at most
/// kMaxTrajectoryBytes and kMaxTrajectorySamples; larger input is refused as soon as it is seen.

#include <cstddef>
#include <filesystem>
#include <istream>
#include <ostream>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "covopt/robot/kinematic_chain.hpp"
#include "covopt/robot/reflected_mass.hpp"

namespace covopt::robot {

/// The largest trajectory file read [bytes]: 64 MiB.
inline constexpr std::size_t kMaxTrajectoryBytes = std::size_t{64} << 20;
/// The most samples a trajectory may have: 10⁶.
inline constexpr std::size_t kMaxTrajectorySamples = 1000000;

/// Joint positions and velocities over time.
struct JointTrajectory {
  std::vector<double> time_s;                ///< sample times [s], non-decreasing
  std::vector<Eigen::VectorXd> positions;    ///< q per sample [rad or m]
  std::vector<Eigen::VectorXd> velocities;   ///< q̇ per sample [rad/s or m/s]
  /// Where the samples came from, for messages: the file (ReadJointTrajectory) and each
  /// sample's line in it; empty: "trajectory sample <i>".
  std::string source_name;
  std::vector<std::size_t> line_numbers;
  /// What the reader assumed (no header line); ContactMotion repeats them.
  std::vector<std::string> warnings;
  std::size_t size() const noexcept { return time_s.size(); }
};

/// Reads a trajectory CSV of `joint_count` joints from `in`; messages call it `source_name`.
/// @throws std::invalid_argument "<source>:<line>: ..." for no samples, a line with the wrong
///         number of columns (saying how many are expected and what they are), a value that is
///         not a finite decimal number (naming the column: "column 3 (q2 [rad])"), a time
///         earlier than the line before's, more than kMaxTrajectoryBytes or
///         kMaxTrajectorySamples. Positions and velocities are checked by ContactMotion.
JointTrajectory ReadJointTrajectory(std::istream& in, std::size_t joint_count,
                                    const std::string& source_name = "trajectory");
/// As above, from the file at `path`.
/// @throws std::invalid_argument also when the file is missing or unreadable.
JointTrajectory ReadJointTrajectory(const std::filesystem::path& path, std::size_t joint_count);

/// Writes `trajectory` as a trajectory CSV that ReadJointTrajectory reads back: a header line
/// "time_s,<joint>,...,<joint>_velocity,..." from `joint_names` (the chain's joint order), then one
/// line per sample, every number in its shortest round-trip form (FormatShortest).
/// @throws std::invalid_argument when the samples' sizes do not match the joint names.
void WriteJointTrajectory(std::ostream& out, const JointTrajectory& trajectory,
                          const std::vector<std::string>& joint_names);

/// The contact point's motion at one sample.
struct ContactMotionSample {
  double time_s = 0.0;                                          ///< [s]
  Eigen::Vector3d contact_point_m = Eigen::Vector3d::Zero();    ///< base frame [m]
  Eigen::Vector3d velocity_m_per_s = Eigen::Vector3d::Zero();   ///< J_v q̇, base frame [m/s]
  double speed_m_per_s = 0.0;                                   ///< |J_v q̇| [m/s]
  /// True when the point moves (speed > ContactMotionOptions::rest_speed_m_per_s).
  bool moving = false;
  /// The unit direction of motion (base frame); zero when the point is at rest.
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  /// The reflected mass along the motion [kg] (+infinity: fixed). At rest the direction is
  /// undefined and this is the largest reflected mass over all directions (the conservative
  /// choice; with zero speed there is no impact anyway).
  double reflected_mass_kg = 0.0;
};

/// Settings of ContactMotion.
struct ContactMotionOptions {
  /// A sample whose contact point moves at or below this speed is at rest [m/s], >= 0.
  /// Default 1e-9 m/s.
  double rest_speed_m_per_s = 1e-9;
  /// How reflected masses are computed. Default: ReflectedMassOptions{}.
  ReflectedMassOptions reflected_mass;
};

/// How ContactMotion ended.
enum class ContactMotionStatus {
  kSuccess,          ///< every sample's reflected mass is finite
  kFixedDirections,  ///< some samples move along a fixed (infinite-mass) direction: warnings
};
/// "success" or "fixed-directions".
const char* ToString(ContactMotionStatus status) noexcept;

/// The contact point's motion along a trajectory.
struct ContactMotionResult {
  ContactMotionStatus status = ContactMotionStatus::kSuccess;
  std::string message;  ///< e.g. "120 samples, peak speed 1.23 m/s at t = 0.50 s"
  std::vector<ContactMotionSample> samples;
  std::vector<std::string> joint_names;  ///< the order of q and q̇
  std::vector<std::string> warnings;
  std::string BriefReport() const;
};

/// Per sample: the velocity, speed, direction and reflected mass of the point
/// `point_in_tip_m` [m, tip frame].
/// @throws std::invalid_argument for a trajectory whose sample sizes do not match the chain
///         (naming the sample), non-finite values, a position or velocity outside its
///         plausible range or (options.reflected_mass.check_joint_limits) the URDF's limits,
///         naming the file, line and column (or the sample) and the value, or as ReflectedMass.
ContactMotionResult ContactMotion(const KinematicChain& chain, const JointTrajectory& trajectory,
                                  const Eigen::Vector3d& point_in_tip_m,
                                  const ContactMotionOptions& options = {});

}  // namespace covopt::robot
