#pragma once
/// @file robot.hpp
/// covopt::robot: a robot's reflected mass at a contact point from its URDF (kinematic chain,
/// joint-space inertia and Jacobian through Orocos KDL), a payload on the tip (and ISO/TS
/// 15066's M/2 + m_L without a model), and a contact point's motion along a
/// joint trajectory.
#include "covopt/robot/kinematic_chain.hpp"
#include "covopt/robot/link_kinematics.hpp"
#include "covopt/robot/payload.hpp"
#include "covopt/robot/reflected_mass.hpp"
#include "covopt/robot/surface.hpp"
#include "covopt/robot/trajectory.hpp"
