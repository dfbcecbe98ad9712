#pragma once
/// @file chain_impl.hpp
/// KinematicChain's insides (private to covopt_robot): the KDL chain and what the public
/// accessors return.

#include <cstddef>
#include <filesystem>
#include <functional>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <kdl/chain.hpp>
#include <kdl/jntarray.hpp>
#include <kdl/rigidbodyinertia.hpp>

#include "covopt/robot/kinematic_chain.hpp"
#include "covopt/robot/reflected_mass.hpp"
#include "covopt/robot/trajectory.hpp"

namespace covopt::robot {

struct KinematicChain::Impl {
  std::string robot_name;
  std::string source_name;
  std::string base_link;
  std::string tip_link;
  std::vector<ChainJoint> joints;
  std::vector<std::string> joint_names;
  double moving_mass_kg = 0.0;
  std::vector<std::string> lumped_joint_names;
  std::vector<std::string> warnings;
  /// The payload on the tip and the tip segment's inertia without it (WithPayload).
  Payload payload;
  KDL::RigidBodyInertia bare_tip_inertia = KDL::RigidBodyInertia::Zero();
  KDL::Chain chain;
};

namespace internal {

/// @throws std::invalid_argument "<where>: <field> = <value> is not allowed (<allowed>)".
[[noreturn]] void Refuse(const std::string& where, const std::string& field, double value,
                         const std::string& allowed);

/// Checks an inertia tensor (symmetric; only its lower triangle is read): principal moments
/// >= 0 and each at most the sum of the other two, to 1e-6 of the largest (URDFs round).
/// @throws std::invalid_argument "<where>: <field> smallest principal moment = ..." or
///         "... largest principal moment = ...", saying why.
void CheckPrincipalMoments(const Eigen::Matrix3d& tensor, const std::string& where, const std::string& field);

/// Reads `in` to its end, at most `limit_bytes`: a device or FIFO is not read forever.
/// @throws std::invalid_argument "<source>: larger than <limit> MiB, the limit for <what>"
///         as soon as byte limit+1 arrives, or when the stream cannot be read.
std::string ReadBounded(std::istream& in, std::size_t limit_bytes, const std::string& source,
                        const std::string& what);
/// As ReadBounded, from the file at `path` (a missing file or a directory is refused).
std::string ReadBoundedFile(const std::filesystem::path& path, std::size_t limit_bytes,
                            const std::string& what);

/// "joints: joint 2 (shoulder)": where joint `index` of a q or q̇ is, for messages.
using JointWhere = std::function<std::string(std::size_t index)>;

/// Checks joint positions against the plausible range (a full turn, kMaxTranslationM) and,
/// when `check_limits`, the URDF's position limits.
/// @throws std::invalid_argument "<where>: <value> rad is ..." naming the allowed range.
void CheckJointPositions(const KinematicChain& chain, const Eigen::VectorXd& q, bool check_limits,
                         const JointWhere& where);
/// As CheckJointPositions for joint velocities (kMaxJointVelocity, the URDF's velocity limit).
void CheckJointVelocities(const KinematicChain& chain, const Eigen::VectorXd& qd, bool check_limits,
                          const JointWhere& where);
/// The warning a result carries when the joint limits were not checked.
std::string JointLimitsIgnoredWarning(const KinematicChain& chain);

/// Checks q against the chain (length, finite values) and copies it into a KDL::JntArray.
/// @throws std::invalid_argument "joints: ..." naming the joint and value.
KDL::JntArray ToJntArray(const KinematicChain& chain, const Eigen::VectorXd& q,
                         const char* what = "joints");

/// Checks that every component of `v` is finite.
/// @throws std::invalid_argument "<what>: component <i> must be finite (got nan)".
void CheckFinite(const Eigen::Vector3d& v, const char* what);

/// CheckFinite, and every coordinate within ±kMaxLengthM.
/// @throws std::invalid_argument "point: component <i> = <v> m is not allowed (...)".
void CheckPoint(const Eigen::Vector3d& point_in_tip_m);

/// @throws std::invalid_argument unless options.singular_relative_tolerance is in [0, 1).
void CheckSingularTolerance(const ReflectedMassOptions& options);

/// The checks of ContactMotion's options: rest_speed_m_per_s finite and >= 0, and
/// CheckSingularTolerance.
void CheckContactMotionOptions(const ContactMotionOptions& options);

/// The checks of one trajectory sample (ContactMotion's and ChainSampleKinematics::Update's):
/// q and q̇ of the chain's length and finite (ToJntArray, messages "<positions_name>: ..." and
/// "<velocities_name>: ..."), then CheckJointPositions and CheckJointVelocities.
/// @returns q as a KDL::JntArray.
KDL::JntArray CheckSample(const KinematicChain& chain, const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                          bool check_limits, const std::string& positions_name,
                          const std::string& velocities_name, const JointWhere& position_where,
                          const JointWhere& velocity_where);

/// @throws std::invalid_argument "<source>: the joint-space inertia matrix is not positive
///         definite ..." (a joint that moves no mass).
[[noreturn]] void RefuseSingularInertia(const KinematicChain& chain);

/// The kinematics and inertia of a contact point at one configuration, computed once: what
/// ReflectedMass needs, and ContactMotion too (the point's velocity is jacobian · q̇).
struct PointInertia {
  Eigen::Matrix<double, 3, Eigen::Dynamic> jacobian;         ///< J_v, base frame [m/rad or m/m]
  Eigen::Vector3d contact_point_m = Eigen::Vector3d::Zero();  ///< base frame [m]
  Eigen::Matrix3d inverse_mass = Eigen::Matrix3d::Zero();     ///< Λ⁻¹ = J_v M⁻¹ J_vᵀ [1/kg]
};

/// J_v, the contact point and Λ⁻¹ at `joints` (already checked).
/// @throws std::invalid_argument when M is not positive definite.
PointInertia ComputePointInertia(const KinematicChain& chain, const KDL::JntArray& joints,
                                 const Eigen::Vector3d& point_in_tip_m);

/// The reflected mass along `unit_direction`, or without one the largest over all directions
/// [kg] (+infinity: fixed), as ReflectedMassAt computes them but without its text: what
/// ContactMotion needs per sample.
double ReflectedMassAlongOrMax(const PointInertia& point, const std::optional<Eigen::Vector3d>& unit_direction,
                               const ReflectedMassOptions& options);

/// ReflectedMass's answer from a computed PointInertia; `unit_direction` already normalised.
ReflectedMassResult ReflectedMassAt(const KinematicChain& chain, const PointInertia& point,
                                    const std::optional<Eigen::Vector3d>& unit_direction,
                                    const ReflectedMassOptions& options);

}  // namespace internal
}  // namespace covopt::robot
