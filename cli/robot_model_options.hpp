#pragma once
/// @file robot_model_options.hpp
/// The robot-model option group shared by `covopt robot`, `optimize`, `simulate` and
/// `speed-limit`: the reflected mass from a URDF instead of a typed --robot-mass.
///
///     --urdf FILE [--base LINK] --tip LINK --joints Q1,Q2,... [--point X,Y,Z] [--direction X,Y,Z]
///
/// Joint positions in rad, or with a unit: 30deg, 0.5rad (revolute and continuous joints),
/// 100mm, 0.1m (prismatic joints). The contact point in the tip link's frame, each
/// coordinate a length (bare numbers in m: 0.05,0,0 or 50mm,0,0), default its origin. The
/// impact direction in the base frame, any length (normalised), plain numbers. A tool or
/// payload on the tip link: --payload-mass M (kg, or 500g), --payload-com X,Y,Z (its centre
/// of mass in the tip frame, lengths as --point) and --payload-inertia IXX,IYY,IZZ,IXY,IXZ,IYZ
/// (about the centre of mass, tip-frame axes, plain numbers in kg m²; default: a point mass).

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "covopt/robot/kinematic_chain.hpp"
#include "covopt/robot/reflected_mass.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The group's flags as typed.
struct RobotModelOptions {
  std::optional<std::string> urdf;       ///< --urdf FILE
  std::optional<std::string> base;       ///< --base LINK (default: the URDF's root link)
  std::optional<std::string> tip;        ///< --tip LINK
  std::optional<std::string> joints;     ///< --joints Q1,Q2,...
  std::optional<std::string> point;      ///< --point X,Y,Z (tip frame)
  std::optional<std::string> direction;  ///< --direction X,Y,Z (base frame)
  std::optional<std::string> payload_mass;     ///< --payload-mass M (kg, or with a unit)
  std::optional<std::string> payload_com;      ///< --payload-com X,Y,Z (tip frame; m, or with units)
  std::optional<std::string> payload_inertia;  ///< --payload-inertia IXX,IYY,IZZ,IXY,IXZ,IYZ [kg m²]
  /// --ignore-joint-limits: do not check positions (and velocities) against the URDF's
  /// <limit>s; the answer carries a warning that says so.
  bool ignore_joint_limits = false;
  /// Any of the group's flags was given.
  bool given() const noexcept {
    return urdf || base || tip || joints || point || direction || ignore_joint_limits || payload_mass ||
           payload_com || payload_inertia;
  }
  /// The library's options for these flags (check_joint_limits unless --ignore-joint-limits).
  robot::ReflectedMassOptions reflected_mass_options() const {
    robot::ReflectedMassOptions options;
    options.check_joint_limits = !ignore_joint_limits;
    return options;
  }
};

/// Adds the group's flags to `sub` under the help group `group`; `direction_required` says
/// in the help whether --direction is required (optimize, simulate, speed-limit) or
/// optional (robot).
void AddRobotModelOptions(CLI::App& sub, RobotModelOptions& options, bool direction_required,
                          const std::string& group = "Robot model");

/// What the group's flags resolve to.
struct RobotModelInput {
  robot::KinematicChain chain;
  Eigen::VectorXd joint_positions;             ///< [rad or m], chain order
  Eigen::Vector3d point_in_tip_m = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> direction;    ///< base frame, as typed (not normalised)
};

/// Reads --urdf/--base/--tip/--point/--payload-* and the URDF, not the joints (a trajectory brings its
/// own): the chain and the contact point; joint_positions empty, no direction.
/// @throws InputError as ResolveRobotModelInput for those flags.
RobotModelInput ResolveRobotModelChain(const RobotModelOptions& options);

/// Reads the flags and the URDF.
/// @throws InputError naming the flag and the value: --urdf, --tip or --joints missing, a
///         bad file, unknown links, a joint count that does not match (naming the joints), a
///         non-numeric or non-finite joint, an angle beyond a full turn, a point or direction
///         without exactly three components, a zero direction, --direction missing when
///         `require_direction`.
RobotModelInput ResolveRobotModelInput(const RobotModelOptions& options, bool require_direction);

/// The group resolved to a reflected mass, for a scene's robot.mass.
struct RobotModelMass {
  /// The reflected mass along --direction [kg]; covopt::kFixed (infinite) when the robot
  /// cannot move that way.
  double mass_kg = 0.0;
  /// "--urdf 'FILE' (tip at joints ...)": where the mass came from, for messages.
  std::string source;
  /// One line for the output: "robot mass 3.214 kg: reflected mass of tool0 at (x, y, z) m
  /// along (ux, uy, uz), from FILE", then the library's warnings (fixed directions, locked
  /// joints).
  std::vector<std::string> notes;
  robot::ReflectedMassResult result;
};

/// Resolves the group (with --direction required) to the scene's robot mass.
/// `robot_mass_flag_given`: --robot-mass was typed too, which is bad input (give one).
/// @throws InputError as ResolveRobotModelInput, and when --robot-mass is given too.
RobotModelMass ResolveRobotModelMass(const RobotModelOptions& options, bool robot_mass_flag_given);

/// The scene-field key of the robot mass ("robot.mass"), whose flag --urdf replaces.
inline constexpr const char* kRobotMassField = "robot.mass";

}  // namespace covopt::cli
