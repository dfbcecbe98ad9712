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
///
/// Without a URDF, ISO/TS 15066's own estimate of the robot's effective mass:
///
///     --robot-moving-mass M [--payload-mass m_L]      robot mass = M/2 + m_L
///
/// M is the total mass of the robot's moving parts (kg, or with a unit). It replaces
/// --robot-mass and takes no URDF flag, no --payload-com and no --payload-inertia.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "covopt/robot/kinematic_chain.hpp"
#include "covopt/report/robot_model_json.hpp"
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
  /// --robot-moving-mass M: ISO/TS 15066's M, for its m_R = M/2 + m_L without a URDF.
  std::optional<std::string> robot_moving_mass;
  /// --ignore-joint-limits: do not check positions (and velocities) against the URDF's
  /// <limit>s; the answer carries a warning that says so.
  bool ignore_joint_limits = false;
  /// Any of the group's flags was given.
  bool given() const noexcept {
    return urdf || base || tip || joints || point || direction || ignore_joint_limits || payload_mass ||
           payload_com || payload_inertia || robot_moving_mass;
  }
  /// The robot mass is ISO/TS 15066's M/2 + m_L (--robot-moving-mass, or --payload-mass
  /// without --urdf, which ResolveRobotModelMass refuses without M).
  bool iso_fallback() const noexcept { return !urdf && (robot_moving_mass || payload_mass); }
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

/// The payload of --payload-mass/--payload-com/--payload-inertia, checked (robot::CheckPayload);
/// all zero (empty()) without --payload-mass or with --payload-mass 0. A command that builds its own chain mounts it
/// with KinematicChain::WithPayload; ResolveRobotModelChain does.
/// @throws InputError naming the flag, the value and the allowed range: a mass not in
///         [0, 1e4] kg, a --payload-com or --payload-inertia without --payload-mass, a centre of
///         mass not three lengths within 10 m, an inertia not six finite numbers or not
///         physical (a negative principal moment, the triangle inequality broken).
robot::Payload PayloadFromOptions(const RobotModelOptions& options);

/// Reads --urdf/--base/--tip/--point/--payload-* and the URDF, not the joints (a trajectory brings its
/// own): the chain (with the payload mounted on its tip) and the contact point; joint_positions
/// empty, no direction.
/// @throws InputError as ResolveRobotModelInput for those flags, and for --robot-moving-mass
///         (the ISO fallback needs no URDF: with one it contradicts it, and a command that
///         needs the robot model cannot use it).
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
  /// "--urdf 'FILE' (tip LINK)", or "--robot-moving-mass 'M' --payload-mass 'm_L' (ISO/TS
  /// 15066 M/2 + m_L)": where the mass came from, for messages.
  std::string source;
  /// One line for the output: "robot mass 3.214 kg: reflected mass of tool0 at (x, y, z) m
  /// along (ux, uy, uz), from FILE", then the library's warnings (fixed directions, locked
  /// joints); for the ISO fallback, "robot mass 17 kg: ISO/TS 15066's estimate M/2 + m_L = ...,
  /// not a reflected mass ...".
  std::vector<std::string> notes;
  robot::ReflectedMassResult result;
  /// The model as the result's "robot_model" input and its summary's robot (report::WithRobotModel).
  report::RobotModelInputs inputs;
};

/// Resolves the group (with --direction required) to the scene's robot mass: the reflected
/// mass from --urdf, or without it (iso_fallback()) ISO/TS 15066's M/2 + m_L from
/// --robot-moving-mass and --payload-mass, with a note that says which.
/// `robot_mass_flag_given`: --robot-mass was typed too, which is bad input (give one).
/// @throws InputError as ResolveRobotModelInput, and when --robot-mass is given too; for the
///         ISO fallback, when M is missing (--payload-mass alone), not a mass in (0, 1e6] kg,
///         or comes with --payload-com/--payload-inertia or a URDF flag (--tip, --joints, ...).
RobotModelMass ResolveRobotModelMass(const RobotModelOptions& options, bool robot_mass_flag_given);

/// The scene-field key of the robot mass ("robot.mass"), whose flag --urdf replaces.
inline constexpr const char* kRobotMassField = "robot.mass";

}  // namespace covopt::cli
