#pragma once
/// @file link_kinematics.hpp
/// The motion of any point of any chain link at one sample (q, q̇): its position, velocity and
/// the reflected mass along its velocity. The whole-robot audit (covopt/audit/audit.hpp) asks
/// this for every surface point (surface.hpp) at every trajectory sample, so the work is split:
///
///     ChainSampleKinematics kin(chain);        // once: storage for the chain's size
///     kin.Update(q, qdot);                     // per sample: M(q), its Cholesky factor L,
///                                              //   every link's frame, twist and 6×n Jacobian
///     PointMotion m = kin.Point(link, p_link); // per point: O(n²), no allocation
///
/// Per point, with o the link frame's origin, J_v(o) and J_ω the link's linear and angular
/// Jacobians (base frame; the columns of joints beyond the link are zero: they do not move it):
///
///     p       = R_link p_link + o                       [m]
///     v       = v_o + ω × (p − o)                       [m/s]   (= J_v(p) q̇)
///     J_v(p)ᵀu = J_v(o)ᵀu + J_ωᵀ((p − o) × u)           u = v/|v|
///     m_u     = 1 / |L⁻¹ J_v(p)ᵀ u|²                    [kg]    (= 1/(uᵀ J_v M⁻¹ J_vᵀ u))
///
/// This is the same reflected mass as ReflectedMass(chain, q, p_tip, u) for a point on the
/// tip link, by another route (tests compare them, and both with numpy).
/// A point whose speed is at or below ContactMotionOptions::rest_speed_m_per_s is at rest: its
/// direction is zero and its reflected mass is not computed (no impact without speed).

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "covopt/robot/kinematic_chain.hpp"
#include "covopt/robot/reflected_mass.hpp"
#include "covopt/robot/trajectory.hpp"

namespace covopt::robot {

/// One point's motion at one sample (base frame).
struct PointMotion {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();         ///< [m]
  Eigen::Vector3d velocity_m_per_s = Eigen::Vector3d::Zero();   ///< [m/s]
  double speed_m_per_s = 0.0;                                   ///< |v| [m/s]
  /// speed > rest speed (ContactMotionOptions::rest_speed_m_per_s).
  bool moving = false;
  /// v/|v| [-]; zero at rest.
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  /// The reflected mass along the motion [kg]; +infinity when uᵀΛ⁻¹u is at or below
  /// singular_relative_tolerance · trace(Λ⁻¹) (fixed); 0 at rest (not computed).
  double reflected_mass_kg = 0.0;
};

/// The kinematics and joint-space inertia of a chain at one sample, for many points on any of
/// its links. Not thread-safe (one per thread); cheap to move.
class ChainSampleKinematics {
 public:
  /// Storage for `chain` (which it keeps a copy of; KinematicChain is cheap to copy).
  /// @throws std::invalid_argument for bad options (as ContactMotion).
  explicit ChainSampleKinematics(const KinematicChain& chain, const ContactMotionOptions& options = {});
  ~ChainSampleKinematics();
  ChainSampleKinematics(ChainSampleKinematics&&) noexcept;
  ChainSampleKinematics& operator=(ChainSampleKinematics&&) noexcept;

  /// The chain's links after the base, base to tip (one per KDL segment: movable and fixed
  /// joints alike), in the order of link indices.
  const std::vector<std::string>& link_names() const noexcept;
  /// The index of `link_name` among link_names(); empty when it is not on the chain.
  std::optional<std::size_t> LinkIndex(std::string_view link_name) const noexcept;
  /// The number of movable joints that move link `link_index` (0: it never moves).
  std::size_t JointsMovingLink(std::size_t link_index) const;

  /// Sets the sample: joint positions [rad or m] and velocities [rad/s or m/s] in
  /// chain.joint_names() order. Computes M(q), its Cholesky factor and every link's frame,
  /// twist and Jacobian.
  /// @throws std::invalid_argument as ContactMotion for one sample (sizes, non-finite values,
  ///         plausible ranges, the URDF's limits when options.reflected_mass.check_joint_limits),
  ///         naming `where` (e.g. "trajectory.csv:12") and the joint; or an M that is not
  ///         positive definite.
  void Update(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
              const std::string& where = "sample");

  /// The motion of the point `point_in_link_m` [m, in link `link_index`'s frame] at the
  /// sample last set by Update. No allocation.
  /// @pre Update was called; link_index < link_names().size().
  PointMotion Point(std::size_t link_index, const Eigen::Vector3d& point_in_link_m) const noexcept;

  /// The link's frame origin in the base frame [m] and rotation, at the current sample.
  Eigen::Vector3d LinkOrigin(std::size_t link_index) const;
  Eigen::Matrix3d LinkRotation(std::size_t link_index) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace covopt::robot
