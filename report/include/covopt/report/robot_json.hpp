#pragma once
/// @file robot_json.hpp
/// A robot's reflected mass as JSON text: the object `covopt robot --json` prints and
/// `covopt.reflected_mass()` returns as a dict (both call RobotJson). Masses in kg, an
/// infinite (fixed) mass as the string "fixed", directions as unit 3-vectors in the base
/// frame, the contact point in m (base frame).

#include <optional>
#include <span>
#include <string>

#include "covopt/robot/payload.hpp"
#include "covopt/robot/reflected_mass.hpp"
#include "covopt/robot/trajectory.hpp"

namespace covopt::report {

/// A payload on the chain's tip (KinematicChain::payload()) and what it changes.
struct RobotPayload {
  robot::Payload payload;
  /// The same contact's reflected masses on the chain without it (chain.WithPayload({})).
  robot::ReflectedMassResult without_payload;
};

/// Keys: reflected_mass_kg (null without a direction), direction (null without one),
/// max_reflected_mass_kg, max_direction, min_reflected_mass_kg, min_direction,
/// contact_point_m, joint_names, payload, status, message, warnings (`input_warnings` first,
/// then the result's). payload is null without one, else {mass_kg, center_of_mass_m (tip
/// frame), inertia_kg_m2 (3 x 3 rows, about the centre of mass, tip-frame axes),
/// without_payload: {reflected_mass_kg, max_reflected_mass_kg, min_reflected_mass_kg}}: the
/// masses at the top level are those with the payload. `indent` as in nlohmann's dump: 2 (the
/// CLI's), or -1 for one line.
std::string RobotJson(const robot::ReflectedMassResult& result,
                      std::span<const std::string> input_warnings = {}, int indent = 2,
                      const std::optional<RobotPayload>& payload = std::nullopt);

/// The contact point's motion along a trajectory: samples [{time_s, speed_m_per_s, moving,
/// direction (null at rest), velocity_m_per_s, contact_point_m, reflected_mass_kg}],
/// joint_names, status, message, warnings.
std::string ContactMotionJson(const robot::ContactMotionResult& result,
                              std::span<const std::string> input_warnings = {}, int indent = 2);

}  // namespace covopt::report
