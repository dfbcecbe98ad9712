/// @file trajectory_bindings.cpp
/// covopt.check_trajectory: a robot motion judged against a covering, as `covopt robot
/// --trajectory --json`. The robot and trajectory are read as covopt.contact_motion reads them
/// (robot_inputs.hpp), the scene as a covopt.Scene (scene_keywords.hpp);
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
#include "report_charts.hpp"
#include "robot_inputs.hpp"
#include "scene_keywords.hpp"

namespace py = pybind11;

namespace covopt::python {

void RefuseSampleKeywords(const SceneInputs& inputs) {
  for (const char* keyword : {"robot_mass", "speed"}) {
    if (inputs.Gave(keyword)) {
      throw std::invalid_argument(std::string("check_trajectory() takes the robot's ") +
                                  (std::string(keyword) == "speed" ? "contact-point speed" : "reflected mass") +
                                  " from each sample of the trajectory; drop " + keyword + " from the scene");
    }
  }
}

optim::TrajectoryCheckOptions TrajectoryCheckOptionsFrom(const SceneInputs& inputs, const py::kwargs& kwargs) {
  optim::TrajectoryCheckOptions options;
  options.limit.limits = inputs.limits;
  options.limit.safety_factor = inputs.safety_factor;
  options.limit.allow_full_compression = Flag(kwargs, "allow_full_compression");
  options.limit.keep_travel = Flag(kwargs, "keep_travel");
  options.limit.allow_crushing = Flag(kwargs, "allow_crushing");
  options.limit.covering_compressive_strength_Pa = inputs.CrushCheck().compressive_strength_Pa;
  return options;
}

robot::ContactMotionResult ReadContactMotion(const py::object& urdf, const std::string& tip,
                                             const py::object& trajectory, const std::optional<std::string>& base,
                                             const py::object& point, const std::optional<std::string>& urdf_text,
                                             bool ignore_joint_limits, const robot::Payload& payload) {
  const robot::KinematicChain chain = Chain(urdf, urdf_text, tip, base, payload);
  const robot::JointTrajectory joints = Trajectory(trajectory, chain.joint_count());
  const Eigen::Vector3d p = Triple(point, "point");
  py::gil_scoped_release release;
  robot::ContactMotionOptions motion_options;
  motion_options.reflected_mass = ReflectedMassOptions(ignore_joint_limits);
  return robot::ContactMotion(chain, joints, p, motion_options);
}

namespace {

py::object CheckTrajectory(const py::object& urdf, const std::string& tip, const py::object& trajectory,
                           const std::optional<std::string>& base, const py::object& point,
                           const std::optional<std::string>& urdf_text, bool ignore_joint_limits,
                           const py::tuple& payload, const SceneInputs& inputs, const py::kwargs& kwargs) {
  RefuseSampleKeywords(inputs);
  const optim::TrajectoryCheckOptions options = TrajectoryCheckOptionsFrom(inputs, kwargs);
  const robot::ContactMotionResult motion =
      ReadContactMotion(urdf, tip, trajectory, base, point, urdf_text, ignore_joint_limits, PayloadFrom(payload));
  optim::TrajectoryCheck check;
  try {
    py::gil_scoped_release release;
    check = optim::CheckTrajectory(inputs.scene, optim::MotionSamples(motion.samples), options);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(inputs.Attributed(e.what()));
  }
  if (check.status == optim::TrajectoryCheckStatus::kEvaluationFailed) {
    RaiseComputationError(check.message, std::string(optim::ToString(check.status)));  // as the CLI's exit 1
  }
  chart::TrajectoryChartInput input{check, inputs.scene, options.limit, TrajectoryName(trajectory), tip};
  return WithReportCharts(
      JsonToPython(report::TrajectoryCheckJson(check, motion, inputs.scene, inputs.covering_material, options.limit,
                                               InputAndCrushWarnings(inputs), -1)),
      [input = std::move(input)] { return std::vector{chart::TrajectoryChart(input)}; });
}

}  // namespace

void BindTrajectory(py::module_& m) {
  m.def("check_trajectory", &CheckTrajectory, py::arg("urdf"), py::arg("tip"), py::arg("trajectory"),
        py::arg("base"), py::arg("point"), py::arg("urdf_text"), py::arg("ignore_joint_limits"), py::arg("payload"),
        py::arg("scene"));
}

}  // namespace covopt::python
