#pragma once
/// @file reflected_mass.hpp
/// The reflected (effective) mass of a robot at a contact point: the mass a body hit by that
/// point feels along the direction u of the impact (Khatib's operational-space inertia):
///
///     Λ⁻¹ = J_v M⁻¹ J_vᵀ            [1/kg], 3×3, symmetric positive semi-definite
///     m_u = 1 / (uᵀ Λ⁻¹ u)          [kg], |u| = 1
///
/// J_v [m/rad or m/m]: the 3×n linear Jacobian of the contact point, in the base frame; M
/// [kg m², kg m, kg]: the n×n joint-space inertia matrix (KDL ChainDynParam::JntToMass, the
/// Jacobian from ChainJntToJacSolver moved to the contact point with Jacobian::changeRefPoint).
/// Over all directions m_u ranges from 1/λ_max to 1/λ_min, the reciprocal eigenvalues of Λ⁻¹,
/// along their eigenvectors.
///
/// A direction the contact point cannot move in (a singular configuration, or a planar arm's
/// normal) has uᵀ Λ⁻¹ u = 0 and an infinite reflected mass: the robot is as good as fixed
/// along it. Numerically, uᵀ Λ⁻¹ u <= singular_relative_tolerance · λ_max counts as zero
/// (the mass is then more than 1/singular_relative_tolerance times the smallest reflected
/// mass); such a mass is +infinity, reported as "fixed", with a warning. Drives, gears and
/// the controller are not modelled: the rigid-body mass only (robot/README.md).

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "covopt/robot/kinematic_chain.hpp"

namespace covopt::robot {

/// Settings of ReflectedMass and ContactMotion.
struct ReflectedMassOptions {
  /// A quadratic form uᵀ Λ⁻¹ u (or an eigenvalue of Λ⁻¹) at or below this times the largest
  /// eigenvalue of Λ⁻¹ is zero: the reflected mass along it is infinite ("fixed") [-], in
  /// [0, 1). Default 1e-9 (rounding in Λ⁻¹ is ~1e-16 relative; a mass 10⁹ times the
  /// smallest is, for an impact, a fixed wall).
  double singular_relative_tolerance = 1e-9;
  /// Check the joint positions (and, along a trajectory, velocities) against the URDF's
  /// <limit>s (JointLimits). false: skipped, and the result carries a warning that says so.
  /// The plausible ranges (a full turn, kMaxTranslationM, kMaxJointVelocity) are always checked.
  bool check_joint_limits = true;
  /// Gravity does not enter the mass matrix; kept out of the API.
};

/// How ReflectedMass ended.
enum class ReflectedMassStatus {
  kSuccess,          ///< every reflected mass is finite
  kFixedDirections,  ///< some directions have an infinite (fixed) reflected mass: see warnings
};
/// "success" or "fixed-directions".
const char* ToString(ReflectedMassStatus status) noexcept;

/// The reflected mass of a chain at one configuration and contact point.
struct ReflectedMassResult {
  ReflectedMassStatus status = ReflectedMassStatus::kSuccess;
  /// One sentence: "reflected mass 3.21 kg along (1, 0, 0); 1.20 kg .. 8.40 kg over all
  /// directions".
  std::string message;
  /// The mass along the requested direction [kg]; +infinity when the robot cannot move the
  /// point along it; empty when no direction was given.
  std::optional<double> reflected_mass_kg;
  /// The requested direction, normalised, in the base frame [-]; empty when none was given.
  std::optional<Eigen::Vector3d> direction;
  /// The largest reflected mass over all directions [kg] (+infinity when some direction is
  /// fixed) and its direction (unit, base frame, sign chosen so its largest component is
  /// positive).
  double max_reflected_mass_kg = 0.0;
  Eigen::Vector3d max_direction = Eigen::Vector3d::Zero();
  /// The smallest reflected mass over all directions [kg] (+infinity when the point cannot
  /// move at all) and its direction (as max_direction).
  double min_reflected_mass_kg = 0.0;
  Eigen::Vector3d min_direction = Eigen::Vector3d::Zero();
  /// The contact point in the base frame [m].
  Eigen::Vector3d contact_point_m = Eigen::Vector3d::Zero();
  /// Λ⁻¹ = J_v M⁻¹ J_vᵀ [1/kg], base frame.
  Eigen::Matrix3d inverse_reflected_mass_per_kg = Eigen::Matrix3d::Zero();
  /// The chain's movable joints, in the order of q.
  std::vector<std::string> joint_names;
  /// What a reader must know: fixed (infinite-mass) directions and why.
  std::vector<std::string> warnings;

  /// Every reflected mass asked for is finite.
  bool all_finite() const noexcept { return status == ReflectedMassStatus::kSuccess; }
  /// A few lines: the message, the extremes with their directions, the contact point.
  std::string BriefReport() const;
};

/// The joint-space inertia matrix M(q) [kg m² for revolute pairs, kg m for mixed, kg for
/// prismatic pairs], n×n, from KDL's ChainDynParam::JntToMass.
/// @throws std::invalid_argument as ReflectedMass for q.
Eigen::MatrixXd JointSpaceInertia(const KinematicChain& chain, const Eigen::VectorXd& q);

/// The 3×n linear Jacobian of the point `point_in_tip_m` [m, tip frame] in the base frame
/// [m/rad or m/m]: ∂p/∂q.
/// @throws std::invalid_argument as ReflectedMass for q and the point.
Eigen::Matrix<double, 3, Eigen::Dynamic> ContactJacobian(const KinematicChain& chain,
                                                         const Eigen::VectorXd& q,
                                                         const Eigen::Vector3d& point_in_tip_m);

/// The point `point_in_tip_m` [m, tip frame] in the base frame [m] (forward kinematics).
Eigen::Vector3d ContactPoint(const KinematicChain& chain, const Eigen::VectorXd& q,
                             const Eigen::Vector3d& point_in_tip_m);

/// The reflected mass at joint positions `q` (rad for revolute and continuous joints, m for
/// prismatic ones, in chain.joint_names() order) of the point `point_in_tip_m` [m, in the tip
/// link's frame] along `direction_in_base` (any length > 0, normalised here; empty: only the
/// extremes over all directions).
/// @throws std::invalid_argument naming the value: q of the wrong length (naming the chain's
///         joints), a non-finite joint position, a revolute position beyond a full turn
///         (kMaxRotationRad: degrees?) or a prismatic one beyond kMaxTranslationM, a position
///         outside the URDF's limits (options.check_joint_limits), a point coordinate beyond
///         kMaxLengthM, a non-finite or zero direction, a bad tolerance, or an M that is not
///         positive definite (a joint that moves no mass: its links need an <inertial>).
ReflectedMassResult ReflectedMass(const KinematicChain& chain, const Eigen::VectorXd& q,
                                  const Eigen::Vector3d& point_in_tip_m,
                                  const std::optional<Eigen::Vector3d>& direction_in_base,
                                  const ReflectedMassOptions& options = {});

}  // namespace covopt::robot
