#pragma once
// What the audit tests share: the FR3 (base to fr3_link8), its URDF surface at 80 mm and the
// pick move, read once.
#include <string>
#include <utility>

#include <covopt/robot/kinematic_chain.hpp>
#include <covopt/robot/surface.hpp>
#include <covopt/robot/trajectory.hpp>

namespace covopt::audit::testing {

struct Fr3 {
  robot::KinematicChain chain;
  robot::RobotSurface surface;
  robot::JointTrajectory pick;
};

inline const Fr3& TheFr3() {
  static const Fr3 fr3 = [] {
    const std::string models = COVOPT_ROBOT_MODELS_DIR;
    const std::string urdf = models + "/franka_fr3.urdf";
    robot::KinematicChain chain = robot::KinematicChain::FromUrdfFile(urdf, {"", "fr3_link8"});
    robot::SurfaceOptions options;
    options.spacing_m = 0.08;
    robot::RobotSurface surface = robot::SurfaceFromUrdfFile(urdf, chain, options);
    robot::JointTrajectory pick = robot::ReadJointTrajectory(models + "/franka_fr3_pick.csv", chain.joint_count());
    return Fr3{std::move(chain), std::move(surface), std::move(pick)};
  }();
  return fr3;
}

}  // namespace covopt::audit::testing
