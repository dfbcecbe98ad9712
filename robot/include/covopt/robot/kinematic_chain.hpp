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
#include <memory>
#include <string>
#include <vector>

namespace covopt::robot {

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
  kRevolute,    ///< rotation about the joint axis, position in rad (limits not used)
  kContinuous,  ///< rotation without limits, position in rad
  kPrismatic,   ///< translation along the joint axis, position in m
  kFixed,       ///< no motion; its origin still places the links after it
};
/// "revolute", "continuous", "prismatic" or "fixed".
const char* ToString(JointType type) noexcept;

/// One joint of the chain, base to tip.
struct ChainJoint {
  std::string name;
  JointType type = JointType::kFixed;
  std::string parent_link;
  std::string child_link;
};

/// A URDF chain from a base link to a tip link. Cheap to copy (the KDL chain is shared).
class KinematicChain {
 public:
  /// Reads the URDF file at `path` and takes the chain base -> tip.
  /// @throws std::invalid_argument naming the file and what is wrong: missing or unreadable
  ///         file, malformed URDF (urdfdom's own console output is silenced), unknown base or
  ///         tip link, a base that is not an ancestor of the tip, an unsupported joint type
  ///         on the chain (naming the joint and its type), a non-finite mass or inertia.
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
  /// The total mass that moves with the chain [kg]: the links after the base and whatever
  /// hangs off them (the base link's own mass excluded).
  double moving_mass_kg() const noexcept;
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
