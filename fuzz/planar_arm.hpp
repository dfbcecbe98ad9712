#pragma once
// The fixed arm of the robot fuzz targets: the planar two-link arm of
// tests/robot/data/planar_2link.urdf, inlined (no file is read while fuzzing), and its chain
// base_link -> tool.
#include "covopt/robot.hpp"

namespace covopt::fuzz {

inline constexpr const char* kPlanarArm = R"(<robot name="planar_2link"><link name="base_link"/>
<joint name="shoulder" type="revolute"><parent link="base_link"/><child link="link1"/><axis xyz="0 0 1"/>
<limit lower="-3.14" upper="3.14" effort="100" velocity="2"/></joint>
<link name="link1"><inertial><origin xyz="0.5 0 0"/><mass value="2.0"/>
<inertia ixx="0.01" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>
<joint name="elbow" type="continuous"><parent link="link1"/><child link="link2"/><origin xyz="1.0 0 0"/>
<axis xyz="0 0 1"/></joint>
<link name="link2"><inertial><origin xyz="0.4 0 0"/><mass value="1.5"/>
<inertia ixx="0.005" ixy="0" ixz="0" iyy="0.05" iyz="0" izz="0.05"/></inertial></link>
<joint name="tool_joint" type="fixed"><parent link="link2"/><child link="tool"/><origin xyz="0.8 0 0"/></joint>
<link name="tool"/></robot>)";

inline const covopt::robot::KinematicChain& Arm() {
  static const auto chain = covopt::robot::KinematicChain::FromUrdfString(kPlanarArm, {"", "tool"}, "arm");
  return chain;
}

}  // namespace covopt::fuzz
