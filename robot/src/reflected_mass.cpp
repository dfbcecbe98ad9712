#include "covopt/robot/reflected_mass.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <kdl/chaindynparam.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainjnttojacsolver.hpp>
#include <kdl/jacobian.hpp>
#include <kdl/jntspaceinertiamatrix.hpp>

#include "chain_impl.hpp"

namespace covopt::robot {

const char* ToString(ReflectedMassStatus status) noexcept {
  switch (status) {
    case ReflectedMassStatus::kSuccess: return "success";
    case ReflectedMassStatus::kFixedDirections: return "fixed-directions";
  }
  return "unknown";
}

namespace internal {

KDL::JntArray ToJntArray(const KinematicChain& chain, const Eigen::VectorXd& q, const char* what) {
  const std::vector<std::string>& names = chain.joint_names();
  if (static_cast<std::size_t>(q.size()) != names.size()) {
    std::ostringstream message;
    message << what << ": " << q.size() << " value" << (q.size() == 1 ? "" : "s")
            << " given, but the chain " << chain.base_link() << " -> " << chain.tip_link()
            << " has " << names.size() << " movable joint" << (names.size() == 1 ? "" : "s");
    if (!names.empty()) {
      message << " (";
      for (std::size_t i = 0; i < names.size(); ++i) message << (i ? ", " : "") << names[i];
      message << ")";
    }
    throw std::invalid_argument(message.str());
  }
  KDL::JntArray array(static_cast<unsigned>(q.size()));
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    if (!std::isfinite(q[i])) {
      std::ostringstream message;
      message << what << ": joint " << (i + 1) << " (" << names[static_cast<std::size_t>(i)]
              << ") must be a finite number (got " << q[i] << ")";
      throw std::invalid_argument(message.str());
    }
    array(static_cast<unsigned>(i)) = q[i];
  }
  return array;
}

namespace {

bool Rotational(JointType type) { return type == JointType::kRevolute || type == JointType::kContinuous; }

const ChainJoint& MovableJoint(const KinematicChain& chain, std::size_t index) {
  std::size_t seen = 0;
  for (const ChainJoint& joint : chain.joints()) {
    if (joint.type != JointType::kFixed && seen++ == index) return joint;
  }
  throw std::logic_error("MovableJoint: index out of range");
}

[[noreturn]] void RefuseJointValue(const std::string& where, double value, const char* unit,
                                   const std::string& allowed) {
  std::ostringstream message;
  message << where << ": " << value << " " << unit << " is not allowed (" << allowed << ")";
  throw std::invalid_argument(message.str());
}

std::string Range(double lower, double upper, const char* unit) {
  std::ostringstream range;
  range << "[" << lower << ", " << upper << "] " << unit;
  return range.str();
}

constexpr const char* kIgnoreHint = "; --ignore-joint-limits or ignore_joint_limits=True skips this check";

}  // namespace

void CheckJointPositions(const KinematicChain& chain, const Eigen::VectorXd& q, bool check_limits,
                         const JointWhere& where) {
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    const auto index = static_cast<std::size_t>(i);
    const ChainJoint& joint = MovableJoint(chain, index);
    const bool rotational = Rotational(joint.type);
    const char* unit = rotational ? "rad" : "m";
    const double bound = rotational ? kMaxRotationRad : kMaxTranslationM;
    if (!(std::abs(q[i]) <= bound)) {
      RefuseJointValue(where(index), q[i], unit,
                       rotational ? "within a full turn, " + Range(-bound, bound, unit) +
                                        ": positions are in radians; degrees? multiply by pi/180"
                                  : "within " + Range(-bound, bound, unit) + ": positions are in metres");
    }
    const JointLimits& limits = joint.limits;
    if (check_limits && limits.has_position && (q[i] < limits.lower - 1e-9 || q[i] > limits.upper + 1e-9)) {
      RefuseJointValue(where(index), q[i], unit,
                       "outside the URDF's limits " + Range(limits.lower, limits.upper, unit) + " of joint '" +
                           joint.name + "'" + kIgnoreHint);
    }
  }
}

void CheckJointVelocities(const KinematicChain& chain, const Eigen::VectorXd& qd, bool check_limits,
                          const JointWhere& where) {
  for (Eigen::Index i = 0; i < qd.size(); ++i) {
    const auto index = static_cast<std::size_t>(i);
    const ChainJoint& joint = MovableJoint(chain, index);
    const char* unit = Rotational(joint.type) ? "rad/s" : "m/s";
    if (!(std::abs(qd[i]) <= kMaxJointVelocity)) {
      RefuseJointValue(where(index), qd[i], unit, "within " + Range(-kMaxJointVelocity, kMaxJointVelocity, unit));
    }
    const JointLimits& limits = joint.limits;
    if (check_limits && limits.has_velocity && std::abs(qd[i]) > limits.velocity * (1.0 + 1e-9)) {
      RefuseJointValue(where(index), qd[i], unit,
                       "outside the URDF's velocity limit " + Range(-limits.velocity, limits.velocity, unit) +
                           " of joint '" + joint.name + "'" + kIgnoreHint);
    }
  }
}

std::string JointLimitsIgnoredWarning(const KinematicChain& chain) {
  return "the joint limits of " + chain.source_name() +
         " were not checked (--ignore-joint-limits / ignore_joint_limits=True): the answer is for "
         "configurations the URDF says the robot cannot reach";
}

void CheckFinite(const Eigen::Vector3d& v, const char* what) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(v[i])) {
      std::ostringstream message;
      message << what << ": component " << (i + 1) << " must be a finite number (got " << v[i]
              << ")";
      throw std::invalid_argument(message.str());
    }
  }
}

void CheckPoint(const Eigen::Vector3d& point_in_tip_m) {
  CheckFinite(point_in_tip_m, "point");
  for (int i = 0; i < 3; ++i) {
    if (std::abs(point_in_tip_m[i]) > kMaxLengthM) {
      std::ostringstream message;
      message << "point: component " << (i + 1) << " = " << point_in_tip_m[i]
              << " m is not allowed (within [-1000, 1000] m of the tip link's origin)";
      throw std::invalid_argument(message.str());
    }
  }
}

}  // namespace internal

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The unit vector with the sign that makes its largest-magnitude component positive, so the
/// same direction prints the same way whichever sign the eigen solver returns.
Eigen::Vector3d CanonicalSign(const Eigen::Vector3d& v) {
  Eigen::Index largest = 0;
  v.cwiseAbs().maxCoeff(&largest);
  return v[largest] < 0 ? Eigen::Vector3d(-v) : v;
}

/// "(x, y, z)" to 4 digits; rounding noise (below 5e-13 of the largest component, or 5e-13 for a
/// point near the origin) and negative zeros print as 0.
std::string FormatVector(const Eigen::Vector3d& v) {
  const double noise = 5e-13 * std::max(1.0, v.cwiseAbs().maxCoeff());
  const auto clean = [noise](double x) { return std::abs(x) < noise ? 0.0 : x; };
  std::ostringstream out;
  out.precision(4);
  out << "(" << clean(v[0]) << ", " << clean(v[1]) << ", " << clean(v[2]) << ")";
  return out.str();
}

std::string FormatMass(double mass_kg) {
  if (!std::isfinite(mass_kg)) return "fixed (infinite)";
  std::ostringstream out;
  out.precision(4);
  out << mass_kg << " kg";
  return out.str();
}

Eigen::MatrixXd MassMatrix(const KinematicChain& chain, const KDL::JntArray& q) {
  const unsigned n = q.rows();
  KDL::JntSpaceInertiaMatrix inertia(n);
  KDL::ChainDynParam dynamics(chain.impl().chain, KDL::Vector::Zero());
  if (n > 0 && dynamics.JntToMass(q, inertia) < 0) {
    throw std::runtime_error("KDL ChainDynParam::JntToMass failed");
  }
  return inertia.data;
}

Eigen::Matrix<double, 3, Eigen::Dynamic> PointJacobian(const KinematicChain& chain,
                                                       const KDL::JntArray& q,
                                                       const Eigen::Vector3d& point_in_tip_m,
                                                       Eigen::Vector3d* point_in_base_m) {
  const KDL::Chain& kdl_chain = chain.impl().chain;
  KDL::Frame tip;
  KDL::ChainFkSolverPos_recursive forward(kdl_chain);
  if (forward.JntToCart(q, tip) < 0) throw std::runtime_error("KDL forward kinematics failed");
  // The Jacobian's reference point is the tip frame's origin; move it to the contact point,
  // expressed in the base frame (Jacobian::changeRefPoint takes the base-frame offset).
  const KDL::Vector offset_in_base =
      tip.M * KDL::Vector(point_in_tip_m[0], point_in_tip_m[1], point_in_tip_m[2]);
  const KDL::Vector point = tip.p + offset_in_base;
  if (point_in_base_m != nullptr) *point_in_base_m = Eigen::Vector3d(point.x(), point.y(), point.z());
  const unsigned n = q.rows();
  Eigen::Matrix<double, 3, Eigen::Dynamic> linear(3, n);
  if (n == 0) return linear;
  KDL::Jacobian jacobian(n);
  KDL::ChainJntToJacSolver solver(kdl_chain);
  if (solver.JntToJac(q, jacobian) < 0) throw std::runtime_error("KDL ChainJntToJacSolver failed");
  jacobian.changeRefPoint(offset_in_base);
  linear = jacobian.data.topRows(3);
  return linear;
}

}  // namespace

Eigen::MatrixXd JointSpaceInertia(const KinematicChain& chain, const Eigen::VectorXd& q) {
  return MassMatrix(chain, internal::ToJntArray(chain, q));
}

Eigen::Matrix<double, 3, Eigen::Dynamic> ContactJacobian(const KinematicChain& chain,
                                                         const Eigen::VectorXd& q,
                                                         const Eigen::Vector3d& point_in_tip_m) {
  const KDL::JntArray joints = internal::ToJntArray(chain, q);
  internal::CheckPoint(point_in_tip_m);
  return PointJacobian(chain, joints, point_in_tip_m, nullptr);
}

Eigen::Vector3d ContactPoint(const KinematicChain& chain, const Eigen::VectorXd& q,
                             const Eigen::Vector3d& point_in_tip_m) {
  const KDL::JntArray joints = internal::ToJntArray(chain, q);
  internal::CheckPoint(point_in_tip_m);
  Eigen::Vector3d point;
  PointJacobian(chain, joints, point_in_tip_m, &point);
  return point;
}

namespace internal {

void CheckSingularTolerance(const ReflectedMassOptions& options) {
  const double tolerance = options.singular_relative_tolerance;
  if (!(tolerance >= 0.0 && tolerance < 1.0)) {
    std::ostringstream message;
    message << "singular_relative_tolerance must be in [0, 1) (got " << tolerance << ")";
    throw std::invalid_argument(message.str());
  }
}

void RefuseSingularInertia(const KinematicChain& chain) {
  throw std::invalid_argument(
      chain.source_name() +
      ": the joint-space inertia matrix is not positive definite at these joints: a joint "
      "moves no mass or inertia (give the links after it an <inertial>)");
}

void CheckContactMotionOptions(const ContactMotionOptions& options) {
  if (!(options.rest_speed_m_per_s >= 0.0) || !std::isfinite(options.rest_speed_m_per_s)) {
    std::ostringstream message;
    message << "rest_speed_m_per_s must be a finite number >= 0 m/s (got "
            << options.rest_speed_m_per_s << ")";
    throw std::invalid_argument(message.str());
  }
  CheckSingularTolerance(options.reflected_mass);
}

KDL::JntArray CheckSample(const KinematicChain& chain, const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                          bool check_limits, const std::string& positions_name,
                          const std::string& velocities_name, const JointWhere& position_where,
                          const JointWhere& velocity_where) {
  KDL::JntArray joints = ToJntArray(chain, q, positions_name.c_str());
  ToJntArray(chain, qd, velocities_name.c_str());
  CheckJointPositions(chain, q, check_limits, position_where);
  CheckJointVelocities(chain, qd, check_limits, velocity_where);
  return joints;
}

PointInertia ComputePointInertia(const KinematicChain& chain, const KDL::JntArray& joints,
                                 const Eigen::Vector3d& point_in_tip_m) {
  PointInertia point;
  point.jacobian = PointJacobian(chain, joints, point_in_tip_m, &point.contact_point_m);
  if (joints.rows() > 0) {
    const Eigen::MatrixXd mass = MassMatrix(chain, joints);
    const Eigen::LLT<Eigen::MatrixXd> cholesky(mass);
    if (cholesky.info() != Eigen::Success) RefuseSingularInertia(chain);
    const Eigen::MatrixXd m_inverse_jt = cholesky.solve(point.jacobian.transpose());
    point.inverse_mass = point.jacobian * m_inverse_jt;
    point.inverse_mass = 0.5 * (point.inverse_mass + point.inverse_mass.transpose()).eval();
  }
  return point;
}

namespace {

/// uᵀ Λ⁻¹ u or an eigenvalue at or below this is zero (ReflectedMassOptions).
double ZeroBelow(const Eigen::Vector3d& ascending_eigenvalues, const ReflectedMassOptions& options) {
  return options.singular_relative_tolerance * std::max(ascending_eigenvalues[2], 0.0);
}

/// 1 / value [kg], or +infinity (fixed) when value is zero by ZeroBelow.
double Reciprocal(double value, double zero_below) {
  return value > zero_below && value > 0.0 ? 1.0 / value : kInfinity;
}

}  // namespace

double ReflectedMassAlongOrMax(const PointInertia& point, const std::optional<Eigen::Vector3d>& unit_direction,
                               const ReflectedMassOptions& options) {
  const Eigen::Vector3d lambda =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(point.inverse_mass).eigenvalues();  // as ReflectedMassAt
  const double zero_below = ZeroBelow(lambda, options);
  if (!unit_direction) return Reciprocal(lambda[0], zero_below);
  return Reciprocal(unit_direction->dot(point.inverse_mass * *unit_direction), zero_below);
}

ReflectedMassResult ReflectedMassAt(const KinematicChain& chain, const PointInertia& point,
                                    const std::optional<Eigen::Vector3d>& unit_direction,
                                    const ReflectedMassOptions& options) {
  ReflectedMassResult result;
  result.direction = unit_direction;
  result.joint_names = chain.joint_names();
  result.contact_point_m = point.contact_point_m;
  const Eigen::Matrix3d& inverse_mass = point.inverse_mass;
  result.inverse_reflected_mass_per_kg = inverse_mass;

  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inverse_mass);
  const Eigen::Vector3d& lambda = eigen.eigenvalues();  // ascending
  const double zero_below = ZeroBelow(lambda, options);
  auto reciprocal = [zero_below](double value) { return Reciprocal(value, zero_below); };
  result.max_reflected_mass_kg = reciprocal(lambda[0]);
  result.max_direction = CanonicalSign(eigen.eigenvectors().col(0));
  result.min_reflected_mass_kg = reciprocal(lambda[2]);
  result.min_direction = CanonicalSign(eigen.eigenvectors().col(2));
  if (result.direction) {
    result.reflected_mass_kg =
        reciprocal(result.direction->dot(inverse_mass * *result.direction));
  }

  std::ostringstream message;
  if (result.reflected_mass_kg) {
    message << "reflected mass " << FormatMass(*result.reflected_mass_kg) << " along "
            << FormatVector(*result.direction) << "; ";
  }
  message << FormatMass(result.min_reflected_mass_kg) << " to "
          << FormatMass(result.max_reflected_mass_kg) << " over all directions";
  result.message = message.str();

  const std::string where = "the contact point " + FormatVector(result.contact_point_m) +
                            " m (base frame) of " + chain.tip_link();
  if (!std::isfinite(result.min_reflected_mass_kg)) {
    result.warnings.push_back(where + " cannot move in any direction at these joints: its "
                              "reflected mass is infinite (fixed) in every direction");
  } else if (!std::isfinite(result.max_reflected_mass_kg)) {
    const int rank = (lambda.array() > zero_below).count();
    std::ostringstream warning;
    if (rank == 1) {
      warning << where << " can move only along " << FormatVector(result.min_direction)
              << " at these joints (singular configuration): the reflected mass is infinite "
                 "(fixed) in every direction normal to it, e.g. "
              << FormatVector(result.max_direction);
    } else {
      warning << where << " cannot move along " << FormatVector(result.max_direction)
              << " at these joints (singular configuration, or a direction the joints do not "
                 "reach): the reflected mass along it is infinite (fixed)";
    }
    result.warnings.push_back(warning.str());
  }
  if (result.reflected_mass_kg && !std::isfinite(*result.reflected_mass_kg)) {
    result.warnings.push_back("along the requested direction " + FormatVector(*result.direction) +
                              " the robot cannot move " + where +
                              ": the reflected mass is infinite (fixed), as for a fixed robot");
  }
  result.warnings.insert(result.warnings.begin(), chain.warnings().begin(), chain.warnings().end());
  const bool any_fixed = !std::isfinite(result.max_reflected_mass_kg);
  result.status = any_fixed ? ReflectedMassStatus::kFixedDirections : ReflectedMassStatus::kSuccess;
  return result;
}

}  // namespace internal

ReflectedMassResult ReflectedMass(const KinematicChain& chain, const Eigen::VectorXd& q,
                                  const Eigen::Vector3d& point_in_tip_m,
                                  const std::optional<Eigen::Vector3d>& direction_in_base,
                                  const ReflectedMassOptions& options) {
  internal::CheckSingularTolerance(options);
  const KDL::JntArray joints = internal::ToJntArray(chain, q);
  internal::CheckJointPositions(chain, q, options.check_joint_limits, [&chain](std::size_t i) {
    return "joints: joint " + std::to_string(i + 1) + " (" + chain.joint_names()[i] + ")";
  });
  internal::CheckPoint(point_in_tip_m);
  std::optional<Eigen::Vector3d> unit_direction;
  if (direction_in_base) {
    internal::CheckFinite(*direction_in_base, "direction");
    // Scaled by its largest component first: the norm of (1e308, 1e308, 0) does not overflow.
    const double largest = direction_in_base->cwiseAbs().maxCoeff();
    if (!(largest > 0.0)) {
      throw std::invalid_argument(
          "direction: must be a non-zero vector (got (0, 0, 0)); give the impact direction "
          "in the base frame, e.g. 1,0,0");
    }
    unit_direction = (*direction_in_base / largest).normalized();
  }
  ReflectedMassResult result = internal::ReflectedMassAt(
      chain, internal::ComputePointInertia(chain, joints, point_in_tip_m), unit_direction, options);
  if (!options.check_joint_limits) result.warnings.push_back(internal::JointLimitsIgnoredWarning(chain));
  return result;
}

std::string ReflectedMassResult::BriefReport() const {
  std::ostringstream out;
  out << "Reflected mass: " << message << "\n";
  out << "  largest  " << FormatMass(max_reflected_mass_kg) << " along "
      << FormatVector(max_direction) << "\n";
  out << "  smallest " << FormatMass(min_reflected_mass_kg) << " along "
      << FormatVector(min_direction) << "\n";
  out << "  contact point " << FormatVector(contact_point_m) << " m (base frame)\n";
  for (const std::string& warning : warnings) out << "  warning: " << warning << "\n";
  return out.str();
}

}  // namespace covopt::robot
