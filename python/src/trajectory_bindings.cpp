/// @file trajectory_bindings.cpp
/// covopt.check_trajectory: a robot motion judged against a covering, as `covopt robot
/// --trajectory --json`. The robot and trajectory are read as covopt.contact_motion reads them
/// (robot_inputs.hpp), the scene keywords as covopt.speed_limit reads them (scene_keywords.hpp);
/// robot::ContactMotion -> optim::MotionSamples -> optim::CheckTrajectory; the dict is
/// report::TrajectoryCheckJson. See python/covopt/__init__.py for the documentation.

#include <optional>
#include <stdexcept>
#include <string>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "covopt/optim/trajectory_check.hpp"
#include "covopt/report/trajectory_json.hpp"
#include "covopt/robot/trajectory.hpp"
#include "robot_inputs.hpp"
#include "scene_keywords.hpp"

namespace py = pybind11;

namespace covopt::python {
namespace {

py::object CheckTrajectory(const py::object& urdf, const std::string& tip, const py::object& trajectory,
                           const std::optional<std::string>& base, const py::object& point,
                           const std::optional<std::string>& urdf_text, bool ignore_joint_limits,
                           const py::kwargs& kwargs) {
  for (const char* keyword : {"robot_mass", "speed"}) {
    if (kwargs.contains(keyword) && !py::object(kwargs[keyword]).is_none()) {
      throw std::invalid_argument(std::string("check_trajectory() takes the robot's ") +
                                  (std::string(keyword) == "speed" ? "contact-point speed" : "reflected mass") +
                                  " from each sample of the trajectory; drop " + keyword);
    }
  }
  const SceneKeywordInputs inputs =
      ReadSceneKeywords(kwargs, "check_trajectory", {"allow_full_compression", "allow_crushing"});
  const optim::CoveringCrushCheck crush = CrushCheckOf(inputs, kwargs);
  optim::TrajectoryCheckOptions options;
  options.limit.limits = inputs.limits;
  options.limit.safety_factor = inputs.safety_factor;
  if (kwargs.contains("allow_full_compression") && !py::object(kwargs["allow_full_compression"]).is_none()) {
    options.limit.allow_full_compression = py::bool_(kwargs["allow_full_compression"]).cast<bool>();
  }
  if (kwargs.contains("allow_crushing") && !py::object(kwargs["allow_crushing"]).is_none()) {
    options.limit.allow_crushing = py::bool_(kwargs["allow_crushing"]).cast<bool>();
  }
  options.limit.covering_compressive_strength_Pa = crush.compressive_strength_Pa;

  const robot::KinematicChain chain = Chain(urdf, urdf_text, tip, base);
  const robot::JointTrajectory joints = Trajectory(trajectory, chain.joint_count());
  const Eigen::Vector3d p = Triple(point, "point");
  robot::ContactMotionResult motion;
  optim::TrajectoryCheck check;
  {
    py::gil_scoped_release release;
    robot::ContactMotionOptions motion_options;
    motion_options.reflected_mass = ReflectedMassOptions(ignore_joint_limits);
    motion = robot::ContactMotion(chain, joints, p, motion_options);
    try {
      check = optim::CheckTrajectory(inputs.scene, optim::MotionSamples(motion.samples), options);
    } catch (const std::invalid_argument& e) {
      py::gil_scoped_acquire acquire;  // AttributeSceneError reads the keywords
      throw std::invalid_argument(AttributeSceneError(e.what(), kwargs));
    }
  }
  if (check.status == optim::TrajectoryCheckStatus::kEvaluationFailed) {
    RaiseComputationError(check.message, std::string(optim::ToString(check.status)));  // as the CLI's exit 1
  }
  return JsonToPython(
      report::TrajectoryCheckJson(check, motion, inputs.scene, inputs.covering_material, options.limit, crush.notes, -1));
}

}  // namespace

void BindTrajectory(py::module_& m) {
  m.def("check_trajectory", &CheckTrajectory, py::arg("urdf"), py::arg("tip"), py::arg("trajectory"),
        py::arg("base") = py::none(), py::arg("point") = py::make_tuple(0.0, 0.0, 0.0),
        py::arg("urdf_text") = py::none(), py::arg("ignore_joint_limits") = false);
}

}  // namespace covopt::python
