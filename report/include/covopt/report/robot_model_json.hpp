#pragma once
/// @file robot_model_json.hpp
/// Where a result's robot mass came from when it was not typed as a number: a URDF's reflected
/// mass at a configuration (`--urdf FILE --tip LINK --joints ... --direction ...`), or ISO/TS
/// 15066's estimate M/2 + m_L (`--robot-moving-mass M --payload-mass m_L`). The result's JSON
/// gets it as the input object "robot_model", and its summary's robot (model file, joints,
/// configuration, reflected mass, payload) is filled from it, so a report shows the robot as
/// an input and on its first page, not only in a warning.

#include <string>
#include <vector>

namespace covopt::report {

/// The robot model behind a robot mass.
struct RobotModelInputs {
  /// "urdf" (a reflected mass from the model) or "iso-estimate" (M/2 + m_L).
  std::string source;
  std::string urdf_file;                ///< as given; "" for the ISO estimate
  std::string base_link;                ///< the chain's base link
  std::string tip_link;                 ///< the link that hits
  std::vector<std::string> joint_names;  ///< the chain's movable joints, in order
  std::vector<double> joint_positions;  ///< [rad, or m for a prismatic joint], in that order
  std::vector<double> contact_point_m;  ///< the contact point in the base frame [m] (3 values)
  std::vector<double> direction;        ///< the impact direction, unit, base frame [-] (3 values)
  double moving_mass_kg = 0.0;          ///< ISO's M [kg] (the ISO estimate only; 0 else)
  double payload_mass_kg = 0.0;         ///< the payload on the tip [kg]
  double reflected_mass_kg = 0.0;       ///< the robot mass the result used [kg]; +inf: fixed
};

/// `json_object` (a command's --json object) with "robot_model" {source, urdf_file, base_link,
/// tip_link, joint_names, joint_positions, contact_point_m, direction, moving_mass_kg (null for
/// a URDF), payload_mass_kg, reflected_mass_kg ("fixed" when infinite)} added, and, when it has
/// a "summary", the summary's robot set from it (model_file, joints, motion "configuration
/// fr3_joint1 = 0 rad, ...", or "ISO/TS 15066 estimate M/2 + m_L, M = ... kg", reflected mass,
/// payload). When the object has "input_sources" (report/input_sources.hpp), "robot_model" goes
/// right before it and each of its values gets its source there ("flag --joints", "flag
/// --direction", "flag --tip", "flag --urdf" for what the model gives, "flag
/// --robot-moving-mass", "flag --payload-mass" or "default" for no payload).
/// @throws std::invalid_argument when json_object is not a JSON object.
std::string WithRobotModel(const std::string& json_object, const RobotModelInputs& model);

}  // namespace covopt::report
