/// @file robot_bindings.cpp
/// covopt.reflected_mass and covopt.contact_motion: robot::ReflectedMass and
/// robot::ContactMotion on a URDF chain; the dicts are report::RobotJson (the object
/// `covopt robot --json` prints) and report::ContactMotionJson. See
/// python/covopt/__init__.py for the documentation.

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "covopt/report/robot_json.hpp"
#include "covopt/robot.hpp"
#include "bounded.hpp"
#include "robot_inputs.hpp"
#include "scene_keywords.hpp"

namespace py = pybind11;

namespace covopt::python {
namespace {

/// At most 40 characters of a repr, for messages.
std::string Excerpt(const std::string& text) {
  if (text.size() <= 40) return text;
  std::string excerpt = text.substr(0, 40);
  excerpt += "...";  // appended: GCC 12's LTO warns (-Wstringop-overread) on substr(...) + "..."
  return excerpt;
}

/// A finite float from a Python number, or ValueError naming `what`.
double Number(const py::handle& value, const std::string& what) {
  if (py::isinstance<py::bool_>(value) || py::isinstance<py::str>(value) ||
      !(py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value) ||
        py::hasattr(value, "__float__"))) {
    throw std::invalid_argument(what + ": expected a number (got " +
                                Excerpt(py::repr(value).cast<std::string>()) + ")");
  }
  // float(value) as Python computes it: 10**400 is an OverflowError there, a 2-D row a
  // TypeError; both become the ValueError that names `what`.
  PyObject* as_float = PyNumber_Float(value.ptr());
  if (as_float == nullptr) {
    const bool overflow = PyErr_ExceptionMatches(PyExc_OverflowError) != 0;
    PyErr_Clear();
    throw std::invalid_argument(what + (overflow ? ": must be a finite number" : ": expected a number") + " (got " +
                                Excerpt(py::repr(value).cast<std::string>()) + ")");
  }
  const double x = PyFloat_AsDouble(as_float);
  Py_DECREF(as_float);
  if (!std::isfinite(x)) {
    std::ostringstream message;
    message << what << ": must be a finite number (got " << x << ")";
    throw std::invalid_argument(message.str());
  }
  return x;
}

/// At most `at_most` numbers (default: one per joint of the largest URDF).
std::vector<double> Numbers(const py::handle& value, const std::string& what,
                            std::size_t at_most = robot::kMaxUrdfLinks) {
  if (py::isinstance<py::str>(value) || !py::isinstance<py::iterable>(value)) {
    throw std::invalid_argument(what + ": expected a sequence of numbers (got " +
                                Excerpt(py::repr(value).cast<std::string>()) + ")");
  }
  std::vector<double> numbers;
  std::size_t i = 0;
  ForEachBounded(value, at_most, what, [&](const py::handle item) {
    numbers.push_back(Number(item, what + "[" + std::to_string(i++) + "]"));
  });
  return numbers;
}

}  // namespace

Eigen::Vector3d Triple(const py::handle& value, const char* what) {
  const std::vector<double> v = Numbers(value, what);
  if (v.size() != 3) {
    throw std::invalid_argument(std::string(what) + ": expected 3 components (x, y, z) (got " +
                                std::to_string(v.size()) + ")");
  }
  return {v[0], v[1], v[2]};
}

namespace {

Eigen::VectorXd Vector(const std::vector<double>& v) {
  return Eigen::Map<const Eigen::VectorXd>(v.data(), static_cast<Eigen::Index>(v.size()));
}

}  // namespace

robot::ReflectedMassOptions ReflectedMassOptions(bool ignore_joint_limits) {
  robot::ReflectedMassOptions options;
  options.check_joint_limits = !ignore_joint_limits;
  return options;
}

Eigen::Matrix3d PayloadInertia(const py::handle& value) {
  static const std::string kExpected =
      "payload_inertia: expected 6 numbers (ixx, iyy, izz, ixy, ixz, iyz) or a symmetric 3 x 3 matrix, in kg m² "
      "about the centre of mass";
  if (py::isinstance<py::str>(value) || !py::isinstance<py::iterable>(value)) {
    throw std::invalid_argument(kExpected + " (got " + Excerpt(py::repr(value).cast<std::string>()) + ")");
  }
  const py::list items = py::list(py::reinterpret_borrow<py::object>(value));
  const bool nested = std::any_of(items.begin(), items.end(), [](const py::handle item) {
    return !py::isinstance<py::str>(item) && py::isinstance<py::iterable>(item);
  });
  if (!nested) {
    const std::vector<double> six = Numbers(items, "payload_inertia");
    if (six.size() != 6) {
      throw std::invalid_argument(kExpected + " (got " + std::to_string(six.size()) + " numbers)");
    }
    return robot::Payload::InertiaFromSix(six[0], six[1], six[2], six[3], six[4], six[5]);
  }
  if (items.size() != 3) throw std::invalid_argument(kExpected + " (got " + std::to_string(items.size()) + " rows)");
  Eigen::Matrix3d matrix;
  for (Eigen::Index i = 0; i < 3; ++i) {
    const std::string row_name = "payload_inertia[" + std::to_string(i) + "]";
    const std::vector<double> row = Numbers(items[static_cast<std::size_t>(i)], row_name);
    if (row.size() != 3) {
      throw std::invalid_argument(kExpected + " (got a row " + row_name + " of " + std::to_string(row.size()) +
                                  " numbers)");
    }
    for (Eigen::Index j = 0; j < 3; ++j) matrix(i, j) = row[static_cast<std::size_t>(j)];
  }
  for (Eigen::Index i = 0; i < 3; ++i) {
    for (Eigen::Index j = i + 1; j < 3; ++j) {
      if (matrix(i, j) != matrix(j, i)) {
        std::ostringstream message;
        message << "payload_inertia: a 3 x 3 inertia must be symmetric [kg m²] (got [" << i << "][" << j
                << "] = " << matrix(i, j) << " and [" << j << "][" << i << "] = " << matrix(j, i) << ")";
        throw std::invalid_argument(message.str());
      }
    }
  }
  return matrix;
}

robot::Payload PayloadFrom(const py::object& mass, const py::object& com, const py::object& inertia) {
  robot::Payload payload;
  if (mass.is_none()) {
    if (!com.is_none() || !inertia.is_none()) {
      throw std::invalid_argument(std::string(com.is_none() ? "payload_inertia" : "payload_com") +
                                  " needs payload_mass (the payload's mass in kg)");
    }
    return payload;
  }
  payload.mass_kg = Number(mass, "payload_mass");
  if (!com.is_none()) payload.center_of_mass_m = Triple(com, "payload_com");
  if (!inertia.is_none()) payload.inertia_kg_m2 = PayloadInertia(inertia);
  robot::CheckPayload(payload, robot::PayloadInputNames{"payload_mass", "payload_com", "payload_inertia"});
  return payload;
}

robot::Payload PayloadFrom(const py::tuple& keywords) {
  if (keywords.size() != 3) {
    throw std::invalid_argument("payload: expected (payload_mass, payload_com, payload_inertia)");
  }
  return PayloadFrom(keywords[0], keywords[1], keywords[2]);
}

robot::KinematicChain Chain(const py::object& urdf, const std::optional<std::string>& urdf_text,
                            const std::string& tip, const std::optional<std::string>& base,
                            const robot::Payload& payload) {
  robot::ChainSpec spec;
  spec.tip_link = tip;
  if (base) {
    if (base->empty()) throw std::invalid_argument("base: empty link name");
    spec.base_link = *base;
  }
  const bool have_file = !urdf.is_none();
  if (have_file == urdf_text.has_value()) {
    throw std::invalid_argument("give the robot model as urdf (a file path) or urdf_text (the URDF "
                                "itself), exactly one of them");
  }
  if (urdf_text) return robot::KinematicChain::FromUrdfString(*urdf_text, spec, "urdf_text").WithPayload(payload);
  const std::string path = py::str(py::module_::import("os").attr("fspath")(urdf)).cast<std::string>();
  return robot::KinematicChain::FromUrdfFile(path, spec).WithPayload(payload);
}

namespace {

py::object ReflectedMass(const py::object& urdf, const std::string& tip, const py::object& joints,
                         const std::optional<std::string>& base, const py::object& point,
                         const py::object& direction, const std::optional<std::string>& urdf_text,
                         bool ignore_joint_limits, const py::object& payload_mass, const py::object& payload_com,
                         const py::object& payload_inertia) {
  const robot::KinematicChain chain =
      Chain(urdf, urdf_text, tip, base, PayloadFrom(payload_mass, payload_com, payload_inertia));
  const Eigen::VectorXd q = Vector(Numbers(joints, "joints"));
  const Eigen::Vector3d p = Triple(point, "point");
  std::optional<Eigen::Vector3d> u;
  if (!direction.is_none()) u = Triple(direction, "direction");
  robot::ReflectedMassResult result;
  std::optional<report::RobotPayload> payload;  // as covopt robot: the masses without it too
  {
    py::gil_scoped_release release;
    result = robot::ReflectedMass(chain, q, p, u, ReflectedMassOptions(ignore_joint_limits));
    if (!chain.payload().empty()) {
      payload = report::RobotPayload{
          chain.payload(), robot::ReflectedMass(chain.WithPayload({}), q, p, u, ReflectedMassOptions(ignore_joint_limits))};
    }
  }
  return JsonToPython(report::RobotJson(result, {}, -1, payload));
}

}  // namespace

/// A trajectory: a CSV path (str or os.PathLike), or a dict with time_s (N), positions
/// (N x n) and velocities (N x n).
robot::JointTrajectory Trajectory(const py::object& trajectory, std::size_t joint_count) {
  if (py::isinstance<py::dict>(trajectory)) {
    const py::dict d = trajectory.cast<py::dict>();
    for (const auto& [key, value] : d) {
      const std::string name = py::str(key).cast<std::string>();
      if (name != "time_s" && name != "positions" && name != "velocities") {
        throw std::invalid_argument("trajectory: unknown key '" + Excerpt(name) +
                                    "' (a dict has time_s, positions, velocities)");
      }
    }
    for (const char* key : {"time_s", "positions", "velocities"}) {
      if (!d.contains(key)) {
        throw std::invalid_argument(std::string("trajectory: missing key '") + key +
                                    "' (a dict needs time_s, positions, velocities)");
      }
    }
    // Every array at most kMaxTrajectorySamples long, checked before it is read.
    robot::JointTrajectory t;
    t.time_s = Numbers(d["time_s"], "trajectory['time_s']", robot::kMaxTrajectorySamples);
    for (const char* key : {"positions", "velocities"}) {
      const py::object rows = d[key];
      if (py::isinstance<py::str>(rows) || !py::isinstance<py::iterable>(rows)) {
        throw std::invalid_argument(std::string("trajectory['") + key + "']: expected a sequence of rows (got " +
                                    Excerpt(py::repr(rows).cast<std::string>()) + ")");
      }
      std::vector<Eigen::VectorXd>& out = std::string_view(key) == "positions" ? t.positions : t.velocities;
      std::size_t i = 0;
      ForEachBounded(rows, robot::kMaxTrajectorySamples, std::string("trajectory['") + key + "']",
                     [&](const py::handle row) {
                       out.push_back(Vector(Numbers(row, std::string("trajectory['") + key + "'][" +
                                                              std::to_string(i++) + "]")));
                     });
    }
    if (t.positions.size() != t.size() || t.velocities.size() != t.size()) {
      throw std::invalid_argument("trajectory: time_s, positions and velocities must have the same number of "
                                  "samples (got " + std::to_string(t.size()) + ", " +
                                  std::to_string(t.positions.size()) + ", " + std::to_string(t.velocities.size()) + ")");
    }
    if (t.size() == 0) throw std::invalid_argument("trajectory: no samples");
    for (std::size_t k = 1; k < t.size(); ++k) {
      if (t.time_s[k] < t.time_s[k - 1]) {
        std::ostringstream message;
        message << "trajectory['time_s'][" << k << "]: time goes backwards (" << t.time_s[k] << " s after "
                << t.time_s[k - 1] << " s)";
        throw std::invalid_argument(message.str());
      }
    }
    return t;
  }
  const std::string path = py::str(py::module_::import("os").attr("fspath")(trajectory)).cast<std::string>();
  return robot::ReadJointTrajectory(std::filesystem::path(path), joint_count);
}

namespace {

py::object ContactMotion(const py::object& urdf, const std::string& tip, const py::object& trajectory,
                         const std::optional<std::string>& base, const py::object& point,
                         const std::optional<std::string>& urdf_text, bool ignore_joint_limits,
                         const py::object& payload_mass, const py::object& payload_com,
                         const py::object& payload_inertia) {
  const robot::KinematicChain chain =
      Chain(urdf, urdf_text, tip, base, PayloadFrom(payload_mass, payload_com, payload_inertia));
  const robot::JointTrajectory t = Trajectory(trajectory, chain.joint_count());
  const Eigen::Vector3d p = Triple(point, "point");
  robot::ContactMotionResult result;
  {
    py::gil_scoped_release release;
    robot::ContactMotionOptions options;
    options.reflected_mass = ReflectedMassOptions(ignore_joint_limits);
    result = robot::ContactMotion(chain, t, p, options);
  }
  return JsonToPython(report::ContactMotionJson(result, {}, -1));
}

/// ISO/TS 15066's m_R = M/2 + m_L [kg] (robot::IsoEffectiveMassKg), the keywords' names in
/// its messages.
double IsoRobotMass(const py::object& moving_mass, const py::object& payload_mass) {
  const double moving_kg = Number(moving_mass, "moving_mass");
  const double payload_kg = payload_mass.is_none() ? 0.0 : Number(payload_mass, "payload_mass");
  if (!(moving_kg > 0.0 && moving_kg <= robot::kMaxLinkMassKg)) {
    std::ostringstream message;
    message << "moving_mass: the total mass of the robot's moving parts must be in (0, 1e6] kg (got " << moving_kg
            << ")";
    throw std::invalid_argument(message.str());
  }
  robot::Payload payload;
  payload.mass_kg = payload_kg;
  robot::CheckPayload(payload, "payload_mass");
  return robot::IsoEffectiveMassKg(moving_kg, payload_kg);
}

}  // namespace

void BindRobot(py::module_& m) {
  m.def("reflected_mass", &ReflectedMass, py::arg("urdf"), py::arg("tip"), py::arg("joints"),
        py::arg("base") = py::none(), py::arg("point") = py::make_tuple(0.0, 0.0, 0.0),
        py::arg("direction") = py::none(), py::arg("urdf_text") = py::none(),
        py::arg("ignore_joint_limits") = false, py::arg("payload_mass") = py::none(),
        py::arg("payload_com") = py::none(), py::arg("payload_inertia") = py::none());
  m.def("contact_motion", &ContactMotion, py::arg("urdf"), py::arg("tip"), py::arg("trajectory"),
        py::arg("base") = py::none(), py::arg("point") = py::make_tuple(0.0, 0.0, 0.0),
        py::arg("urdf_text") = py::none(), py::arg("ignore_joint_limits") = false,
        py::arg("payload_mass") = py::none(), py::arg("payload_com") = py::none(),
        py::arg("payload_inertia") = py::none());
  m.def("iso_robot_mass", &IsoRobotMass, py::arg("moving_mass"), py::arg("payload_mass") = py::none());
}

}  // namespace covopt::python
