#pragma once
/// @file kinematic_chain.hpp
/// A serial chain of a robot described in URDF: the links from a base link to a tip link, the
/// joints between them (fixed joints kept, with their origins) and the links' masses and
/// inertias. It is built once from the URDF text and is then an immutable value; the
/// kinematics and dynamics (Orocos KDL) stay behind it.
///
///     covopt::robot::ChainSpec spec;
///     spec.tip_link = "fr3_link8";                      // base: the URDF's root link
///     const auto chain = covopt::robot::KinematicChain::FromUrdfFile("fr3.urdf", spec);
///     chain.joint_names();                              // {"fr3_joint1", ..., "fr3_joint7"}
///
/// Joint types: revolute, continuous, prismatic and fixed; any other type on the chain
/// (floating, planar) is refused with a message naming the joint and its type. The URDF is
/// converted as the ROS package kdl_parser does (treeFromUrdfModel): one KDL segment per
/// joint, carrying the joint's origin and the child link's <inertial> (mass, centre of mass,
/// inertia tensor rotated into the link frame). Links that move with the chain but are not
/// on it — everything beyond the tip (a flange, a gripper), side branches — are added to the
/// inertia of the chain link they hang from, rigidly, as at joint position 0 (exact for
/// fixed joints; movable ones are held, with a warning: the mass of a robot with those
/// joints locked, which is larger than with them free). URDF has no rotor (reflected motor) inertia
/// field, so every KDL joint gets inertia 0 (robot/README.md: what KDL 1.5.1 would do with it).

#include <cstddef>
#include <filesystem>
#include <numbers>
#include <memory>
#include <string>
#include <vector>

#include "covopt/robot/payload.hpp"

namespace covopt::robot {

/// The plausible ranges of the inputs (docs/model.md §9.2). Anything outside is refused with a
/// message naming the field and the value: such values are typos, wrong units or attacks, and
/// beyond them sums and norms could overflow into NaN directions or a false "fixed" robot.
/// The largest URDF read [bytes]: 16 MiB (the shipped models are < 100 kB).
inline constexpr std::size_t kMaxUrdfBytes = std::size_t{16} << 20;
/// The most links a URDF may have (deeper trees would only be stack-deep recursion).
inline constexpr std::size_t kMaxUrdfLinks = 10000;
/// The largest coordinate of a joint origin, a centre of mass or a contact point [m].
inline constexpr double kMaxLengthM = 1e3;
/// The largest link mass [kg].
inline constexpr double kMaxLinkMassKg = 1e6;
/// The largest inertia tensor entry [kg m²] (kMaxLinkMassKg at kMaxLengthM).
inline constexpr double kMaxInertiaKgM2 = 1e12;
/// The largest |q| of a revolute or continuous joint: a full turn [rad]; more is almost surely
/// degrees.
inline constexpr double kMaxRotationRad = 2.0 * std::numbers::pi;
/// The largest |q| of a prismatic joint [m]; more is almost surely millimetres.
inline constexpr double kMaxTranslationM = 10.0;
/// The largest |q̇| of any joint [rad/s or m/s].
inline constexpr double kMaxJointVelocity = 1e3;

/// Which part of the robot the chain spans.
struct ChainSpec {
  /// The chain's first link; its frame is the base frame of every result. Default: empty,
  /// the URDF's root link.
  std::string base_link;
  /// The chain's last link (the one that hits); required.
  std::string tip_link;
};

/// The joint types a chain may hold.
enum class JointType {
  kRevolute,    ///< rotation about the joint axis, position in rad, within the URDF's limits
  kContinuous,  ///< rotation without limits, position in rad
  kPrismatic,   ///< translation along the joint axis, position in m
  kFixed,       ///< no motion; its origin still places the links after it
};
/// "revolute", "continuous", "prismatic" or "fixed".
const char* ToString(JointType type) noexcept;

/// A joint's limits from the URDF's <limit lower upper velocity>. urdfdom defaults lower and
/// upper to 0 and requires velocity; covopt reads lower == upper (for example both left out)
/// as "no position range given", and velocity 0 as "no velocity limit given" (as MoveIt does),
/// each with a warning on the chain. Continuous joints have no position range.
struct JointLimits {
  bool has_position = false;  ///< lower < upper was given (revolute, prismatic)
  double lower = 0.0;         ///< [rad or m]
  double upper = 0.0;         ///< [rad or m]
  bool has_velocity = false;  ///< velocity > 0 was given
  double velocity = 0.0;      ///< the largest |q̇| [rad/s or m/s]
};

/// One joint of the chain, base to tip.
struct ChainJoint {
  std::string name;
  JointType type = JointType::kFixed;
  std::string parent_link;
  std::string child_link;
  JointLimits limits;  ///< movable joints only
};

/// A URDF chain from a base link to a tip link. Cheap to copy (the KDL chain is shared).
class KinematicChain {
 public:
  /// Reads the URDF file at `path` and takes the chain base -> tip.
  /// @throws std::invalid_argument naming the file and what is wrong: missing or unreadable
  ///         file, malformed URDF (urdfdom's own console output is silenced), unknown base or
  ///         tip link, a base that is not an ancestor of the tip, an unsupported joint type
  ///         on the chain (naming the joint and its type), a chain without movable joints, a
  ///         file over kMaxUrdfBytes or more than kMaxUrdfLinks links, a link with two parents
  ///         (the joints form a cycle), and naming the link or joint, the field and the value:
  ///         a mass outside [0, kMaxLinkMassKg], an inertia tensor that is not finite, not
  ///         positive semi-definite or breaks the triangle inequality of its principal moments,
  ///         an origin coordinate beyond kMaxLengthM, a zero or non-finite joint axis, joint
  ///         limits with lower > upper or a negative velocity.
  static KinematicChain FromUrdfFile(const std::filesystem::path& path, const ChainSpec& spec);
  /// As FromUrdfFile, from the URDF text; messages call it `source_name`.
  static KinematicChain FromUrdfString(const std::string& urdf_text, const ChainSpec& spec,
                                       const std::string& source_name = "URDF text");

  /// The robot's name (the URDF's <robot name=...>).
  const std::string& robot_name() const noexcept;
  /// The chain's base and tip link names.
  const std::string& base_link() const noexcept;
  const std::string& tip_link() const noexcept;
  /// Where the URDF came from (the file's path or `source_name`), for messages.
  const std::string& source_name() const noexcept;
  /// Every joint base to tip, fixed ones included.
  const std::vector<ChainJoint>& joints() const noexcept;
  /// The names of the movable joints (revolute, continuous, prismatic) in chain order: the
  /// order of joint positions q and velocities q̇ everywhere in covopt::robot.
  const std::vector<std::string>& joint_names() const noexcept;
  /// The number of movable joints, n.
  std::size_t joint_count() const noexcept;
  /// The total mass of the robot that moves with the chain [kg]: the links after the base and
  /// whatever hangs off them in the URDF (the base link's own mass excluded), without the
  /// payload (ISO/TS 15066's M; payload().mass_kg is its m_L).
  double moving_mass_kg() const noexcept;
  /// The payload on the tip (WithPayload); all zero when none.
  const Payload& payload() const noexcept;
  /// This chain with `payload` rigidly mounted on the tip link (payload.hpp): its mass,
  /// centre of mass and inertia added to the tip segment's rigid-body inertia (KDL
  /// RigidBodyInertia addition). It replaces any payload this chain had; an empty payload
  /// gives back the URDF's chain exactly. The KDL chain is copied; this one is unchanged.
  /// @throws std::invalid_argument as CheckPayload ("payload: <field> = <value> ...").
  KinematicChain WithPayload(const Payload& payload) const;
  /// The movable joints off the chain (beyond the tip, or on side branches) whose links are
  /// counted as rigid payload of the chain link they hang from, held at position 0.
  const std::vector<std::string>& locked_joint_names() const noexcept;
  /// What a reader must know about the chain (locked joints); ReflectedMass repeats them.
  const std::vector<std::string>& warnings() const noexcept;

  /// The KDL chain (a KDL::Chain), for the library's own sources; opaque to users.
  struct Impl;
  const Impl& impl() const noexcept { return *impl_; }

 private:
  explicit KinematicChain(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
  std::shared_ptr<const Impl> impl_;
};

}  // namespace covopt::robot
