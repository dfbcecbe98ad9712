#pragma once
// The shipped Franka FR3 model and its pick move (robot/models/), shared by
// bench_link_kinematics.cpp and bench_audit.cpp: loaded once per process.
#include <string>

#include <covopt/robot/kinematic_chain.hpp>
#include <covopt/robot/trajectory.hpp>

inline const std::string kFr3Urdf = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3.urdf";

/// The FR3 from its base to the flange (fr3_link8).
inline const covopt::robot::KinematicChain& Fr3() {
  static const covopt::robot::KinematicChain chain =
      covopt::robot::KinematicChain::FromUrdfFile(kFr3Urdf, {"", "fr3_link8"});
  return chain;
}

/// robot/models/franka_fr3_pick.csv: 101 samples, 1.5 s.
inline const covopt::robot::JointTrajectory& Pick() {
  static const covopt::robot::JointTrajectory trajectory =
      covopt::robot::ReadJointTrajectory(std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3_pick.csv", 7);
  return trajectory;
}
