#pragma once
/// @file robot_inputs.hpp
/// How the robot calls read their Python arguments (defined in robot_bindings.cpp), for the
/// other binding files: covopt.check_trajectory takes the robot as covopt.contact_motion does.

#include <cstddef>
#include <optional>
#include <string>

#include <Eigen/Core>
#include <pybind11/pybind11.h>

#include "covopt/robot/kinematic_chain.hpp"
#include "covopt/optim/trajectory_check.hpp"
#include "covopt/robot/trajectory.hpp"
#include "scene_keywords.hpp"

namespace covopt::python {

/// The keywords payload_mass [kg] (None or 0: no payload), payload_com (x, y, z) [m, tip
/// frame] and payload_inertia (ixx, iyy, izz, ixy, ixz, iyz, or a symmetric 3 x 3 matrix:
/// PayloadInertia) [kg m², about the centre of mass, tip-frame axes; None: a point mass] as a checked robot::Payload, as the CLI's
/// --payload-mass/--payload-com/--payload-inertia.
/// @throws std::invalid_argument naming the keyword, the value and the allowed range
///         (robot::CheckPayload), or payload_com/payload_inertia without payload_mass.
robot::Payload PayloadFrom(const pybind11::object& mass, const pybind11::object& com,
                           const pybind11::object& inertia);

/// PayloadFrom of the tuple (payload_mass, payload_com, payload_inertia) the Python wrappers
/// pass to the check_trajectory bindings.
/// @throws std::invalid_argument as PayloadFrom, or for a tuple that is not three items.
robot::Payload PayloadFrom(const pybind11::tuple& keywords);

/// The chain base -> tip of the URDF file `urdf` (str or os.PathLike), or of the URDF text
/// `urdf_text`: exactly one of them, with `payload` on its tip (KinematicChain::WithPayload).
/// @throws std::invalid_argument otherwise, or as robot::KinematicChain::FromUrdfFile.
robot::KinematicChain Chain(const pybind11::object& urdf, const std::optional<std::string>& urdf_text,
                            const std::string& tip, const std::optional<std::string>& base,
                            const robot::Payload& payload = {});

/// A trajectory of `joint_count` joints: a CSV path (str or os.PathLike, read by
/// robot::ReadJointTrajectory), or a dict with time_s (N), positions (N x n) and velocities
/// (N x n), no other key, at most robot::kMaxTrajectorySamples samples.
/// @throws std::invalid_argument naming the key, the sample or the line.
robot::JointTrajectory Trajectory(const pybind11::object& trajectory, std::size_t joint_count);

/// The library's options for the keyword ignore_joint_limits.
robot::ReflectedMassOptions ReflectedMassOptions(bool ignore_joint_limits);

/// payload_inertia [kg m², about the centre of mass, tip-frame axes]: six numbers (ixx, iyy,
/// izz, ixy, ixz, iyz, the order of the CLI's --payload-inertia and URDF's <inertia>) or a
/// symmetric 3 x 3 matrix (nested sequences or a numpy array: np.eye(3)), each finite.
/// @throws std::invalid_argument naming payload_inertia, the shapes it takes and what it got.
Eigen::Matrix3d PayloadInertia(const pybind11::handle& value);

/// Three finite numbers (x, y, z). @throws std::invalid_argument naming `what`.
Eigen::Vector3d Triple(const pybind11::handle& value, const char* what);

/// check_trajectory's scene may not give robot_mass or speed: each sample brings its own.
/// @throws std::invalid_argument naming the keyword (trajectory_bindings.cpp).
void RefuseSampleKeywords(const SceneInputs& inputs);

/// The head's trajectory check options: the scene's limits and safety factor,
/// allow_full_compression=, allow_crushing=, the covering's crush strength.
optim::TrajectoryCheckOptions TrajectoryCheckOptionsFrom(const SceneInputs& inputs, const pybind11::kwargs& kwargs);

/// The contact point's motion along `trajectory` (robot::ContactMotion), read as
/// covopt.contact_motion reads its arguments (`payload` on the tip); computed without the GIL.
robot::ContactMotionResult ReadContactMotion(const pybind11::object& urdf, const std::string& tip,
                                             const pybind11::object& trajectory, const std::optional<std::string>& base,
                                             const pybind11::object& point, const std::optional<std::string>& urdf_text,
                                             bool ignore_joint_limits, const robot::Payload& payload);

}  // namespace covopt::python
