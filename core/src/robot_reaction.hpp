#pragma once
// Private: the checks of the robot's reaction (a braking deceleration after a reaction delay,
// docs/model.md §10.2), shared by the head's scene (impact_model.cpp) and the body-region
// contact (body_contact.cpp, §13.10), so that both refuse the same inputs with the same words.

namespace covopt::internal {

/// robot.reaction_delay in [0, 10] s, robot.braking in [0, 1e4] m/s², and braking only for a
/// robot that moves (a finite robot.mass).
/// @throws std::invalid_argument naming the field, the value and the allowed range.
void CheckRobotReaction(double reaction_delay_s, double braking_m_per_s2, double robot_mass_kg);

}  // namespace covopt::internal
