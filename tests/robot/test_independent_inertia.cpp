// covopt::robot (URDF -> KDL -> M(q), J(q)) against an independent computation written here:
// a made-up 3-D arm of six joints (four revolute, one prismatic, one fixed; tilted origins
// and axes; centres of mass off the axes; full inertia tensors in rotated <inertial>
// frames). The test writes the arm's URDF from its table, and computes from the same table,
// with its own forward kinematics (URDF's rpy = Rz(yaw) Ry(pitch) Rx(roll)), never through
// KDL:
//
//     M = Σ_i m_i J_vi' J_vi + J_ωi' (R_i I_i R_i') J_ωi
//
// J_vi, J_ωi: the Jacobians of link i's centre of mass and its angular velocity; R_i: the
// inertial frame's orientation in the base frame; I_i: the URDF inertia tensor.
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include "covopt/robot.hpp"

namespace {

struct JointRow {
  const char* name;
  const char* type;  // revolute | prismatic | fixed
  Eigen::Vector3d xyz, rpy, axis;
};
struct LinkRow {
  double mass;
  Eigen::Vector3d com, rpy;
  double ixx, ixy, ixz, iyy, iyz, izz;
};

const std::vector<JointRow>& Joints() {
  static const std::vector<JointRow> joints = {
      {"j1", "revolute", {0.0, 0.0, 0.3}, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}},
      {"j2", "revolute", {0.05, 0.0, 0.1}, {-M_PI / 2, 0.0, 0.0}, {0.0, 0.0, 1.0}},
      {"j3", "prismatic", {0.4, 0.02, 0.0}, {0.1, 0.2, 0.3}, {0.6, 0.0, 0.8}},
      {"j4", "fixed", {0.1, 0.0, 0.05}, {0.4, -0.3, 1.0}, {1.0, 0.0, 0.0}},
      {"j5", "revolute", {0.0, 0.1, 0.2}, {0.0, M_PI / 2, 0.0}, {0.0, 0.6, 0.8}},
      {"j6", "revolute", {0.15, 0.0, 0.0}, {0.2, 0.0, 0.0}, {0.0, 1.0, 0.0}},
  };
  return joints;
}
// links[0] is the base (not moving); links[i] is joint i's child.
const std::vector<LinkRow>& Links() {
  static const std::vector<LinkRow> links = {
      {5.0, {0.0, 0.0, 0.1}, {0.0, 0.0, 0.0}, 0.1, 0.0, 0.0, 0.1, 0.0, 0.1},
      {3.2, {0.02, -0.01, 0.05}, {0.1, 0.0, 0.2}, 0.03, 0.001, -0.002, 0.025, 0.003, 0.02},
      {2.5, {0.2, 0.01, 0.0}, {0.0, 0.3, 0.0}, 0.01, -0.002, 0.001, 0.04, 0.0015, 0.042},
      {1.1, {0.05, 0.0, 0.02}, {0.5, 0.1, -0.2}, 0.004, 0.0005, 0.0, 0.006, -0.0007, 0.005},
      {0.3, {0.0, 0.02, 0.01}, {0.0, 0.0, 0.7}, 0.0008, 0.0, 0.0001, 0.0009, 0.0, 0.0007},
      {0.9, {0.01, 0.03, 0.06}, {-0.3, 0.2, 0.1}, 0.003, -0.0004, 0.0002, 0.0025, 0.0003, 0.002},
      {0.6, {0.04, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.0012, 0.0, 0.0, 0.0015, 0.0, 0.0011},
  };
  return links;
}

std::string Urdf() {
  std::ostringstream out;
  out.precision(17);
  auto vec = [&](const Eigen::Vector3d& v) {
    std::ostringstream s;
    s.precision(17);
    s << v.x() << " " << v.y() << " " << v.z();
    return s.str();
  };
  out << "<robot name=\"made_up_arm\">\n";
  for (std::size_t i = 0; i < Links().size(); ++i) {
    const LinkRow& l = Links()[i];
    out << "<link name=\"l" << i << "\"><inertial><origin xyz=\"" << vec(l.com) << "\" rpy=\""
        << vec(l.rpy) << "\"/><mass value=\"" << l.mass << "\"/><inertia ixx=\"" << l.ixx
        << "\" ixy=\"" << l.ixy << "\" ixz=\"" << l.ixz << "\" iyy=\"" << l.iyy << "\" iyz=\""
        << l.iyz << "\" izz=\"" << l.izz << "\"/></inertial></link>\n";
  }
  for (std::size_t i = 0; i < Joints().size(); ++i) {
    const JointRow& j = Joints()[i];
    out << "<joint name=\"" << j.name << "\" type=\"" << j.type << "\"><parent link=\"l" << i
        << "\"/><child link=\"l" << i + 1 << "\"/><origin xyz=\"" << vec(j.xyz) << "\" rpy=\""
        << vec(j.rpy) << "\"/><axis xyz=\"" << vec(j.axis)
        << "\"/><limit lower=\"-3\" upper=\"3\" effort=\"1\" velocity=\"1\"/></joint>\n";
  }
  out << "</robot>\n";
  return out.str();
}

Eigen::Matrix3d Rpy(const Eigen::Vector3d& rpy) {
  return (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

struct Pose {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
};

/// Independent kinematics of the table: each link's pose, each movable joint's world axis
/// and a point on it, in the base link l0's frame.
struct Kinematics {
  std::vector<Pose> link;                   // link i's frame (i = 0..6)
  std::vector<Eigen::Vector3d> axis, origin;  // per movable joint, world
  std::vector<bool> prismatic;
  std::vector<int> first_link_moved;        // the first link index the joint moves
};

Kinematics Forward(const Eigen::VectorXd& q) {
  Kinematics k;
  k.link.push_back(Pose{});
  int qi = 0;
  for (std::size_t i = 0; i < Joints().size(); ++i) {
    const JointRow& j = Joints()[i];
    Pose joint_frame;
    joint_frame.R = k.link.back().R * Rpy(j.rpy);
    joint_frame.p = k.link.back().p + k.link.back().R * j.xyz;
    Pose child = joint_frame;
    const std::string type = j.type;
    if (type != "fixed") {
      const Eigen::Vector3d a = joint_frame.R * j.axis.normalized();
      k.axis.push_back(a);
      k.origin.push_back(joint_frame.p);
      k.prismatic.push_back(type == "prismatic");
      k.first_link_moved.push_back(static_cast<int>(i) + 1);
      if (type == "prismatic") {
        child.p += a * q[qi];
      } else {
        child.R = Eigen::AngleAxisd(q[qi], a).toRotationMatrix() * joint_frame.R;
      }
      ++qi;
    }
    k.link.push_back(child);
  }
  return k;
}

Eigen::MatrixXd IndependentMass(const Eigen::VectorXd& q) {
  const Kinematics k = Forward(q);
  const auto n = static_cast<Eigen::Index>(k.axis.size());
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t i = 1; i < Links().size(); ++i) {
    const LinkRow& l = Links()[i];
    const Eigen::Vector3d com = k.link[i].p + k.link[i].R * l.com;
    const Eigen::Matrix3d R = k.link[i].R * Rpy(l.rpy);
    Eigen::Matrix3d I;
    I << l.ixx, l.ixy, l.ixz, l.ixy, l.iyy, l.iyz, l.ixz, l.iyz, l.izz;
    Eigen::MatrixXd Jv = Eigen::MatrixXd::Zero(3, n), Jw = Eigen::MatrixXd::Zero(3, n);
    for (Eigen::Index j = 0; j < n; ++j) {
      if (k.first_link_moved[static_cast<std::size_t>(j)] > static_cast<int>(i)) continue;
      if (k.prismatic[static_cast<std::size_t>(j)]) {
        Jv.col(j) = k.axis[static_cast<std::size_t>(j)];
      } else {
        Jv.col(j) = k.axis[static_cast<std::size_t>(j)].cross(com - k.origin[static_cast<std::size_t>(j)]);
        Jw.col(j) = k.axis[static_cast<std::size_t>(j)];
      }
    }
    M += l.mass * Jv.transpose() * Jv + Jw.transpose() * (R * I * R.transpose()) * Jw;
  }
  return M;
}

/// A payload's share of M: a rigid body on the tip link l6 (centre of mass `com` and tensor
/// `I` about it, both in l6's frame), as one more term of the sum.
Eigen::MatrixXd IndependentPayloadShare(const Eigen::VectorXd& q, double mass, const Eigen::Vector3d& com_in_tip,
                                        const Eigen::Matrix3d& I) {
  const Kinematics k = Forward(q);
  const auto n = static_cast<Eigen::Index>(k.axis.size());
  const Eigen::Vector3d com = k.link.back().p + k.link.back().R * com_in_tip;
  const Eigen::Matrix3d R = k.link.back().R;
  Eigen::MatrixXd Jv = Eigen::MatrixXd::Zero(3, n), Jw = Eigen::MatrixXd::Zero(3, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto js = static_cast<std::size_t>(j);
    if (k.prismatic[js]) {
      Jv.col(j) = k.axis[js];
    } else {
      Jv.col(j) = k.axis[js].cross(com - k.origin[js]);
      Jw.col(j) = k.axis[js];
    }
  }
  return mass * Jv.transpose() * Jv + Jw.transpose() * (R * I * R.transpose()) * Jw;
}

Eigen::Vector3d IndependentPoint(const Eigen::VectorXd& q, const Eigen::Vector3d& point_in_tip) {
  const Kinematics k = Forward(q);
  return k.link.back().p + k.link.back().R * point_in_tip;
}

}  // namespace

TEST_CASE("M(q) of a 3-D six-joint arm agrees with an independent sum over its links") {
  const auto chain = covopt::robot::KinematicChain::FromUrdfString(Urdf(), {"", "l6"}, "made_up_arm");
  REQUIRE(chain.joint_names() == std::vector<std::string>{"j1", "j2", "j3", "j5", "j6"});
  const Eigen::VectorXd q = GENERATE(Eigen::VectorXd((Eigen::VectorXd(5) << 0, 0, 0, 0, 0).finished()),
                                     Eigen::VectorXd((Eigen::VectorXd(5) << 0.3, -0.7, 0.12, 1.1, -0.4).finished()),
                                     Eigen::VectorXd((Eigen::VectorXd(5) << -2.0, 1.4, -0.05, -0.9, 2.5).finished()));
  const Eigen::MatrixXd kdl = covopt::robot::JointSpaceInertia(chain, q);
  const Eigen::MatrixXd independent = IndependentMass(q);
  INFO("q = " << q.transpose() << "\nKDL\n" << kdl << "\nindependent\n" << independent);
  CHECK((kdl - independent).cwiseAbs().maxCoeff() < 1e-12 * independent.cwiseAbs().maxCoeff());
  CHECK(chain.moving_mass_kg() == Approx(3.2 + 2.5 + 1.1 + 0.3 + 0.9 + 0.6));
}

TEST_CASE("the 3-D arm's contact Jacobian is the derivative of the independent kinematics") {
  const auto chain = covopt::robot::KinematicChain::FromUrdfString(Urdf(), {"", "l6"}, "made_up_arm");
  Eigen::VectorXd q(5);
  q << 0.3, -0.7, 0.12, 1.1, -0.4;
  const Eigen::Vector3d point(0.05, -0.02, 0.11);
  CHECK((covopt::robot::ContactPoint(chain, q, point) - IndependentPoint(q, point)).norm() < 1e-12);
  const auto J = covopt::robot::ContactJacobian(chain, q, point);
  const double h = 1e-6;
  for (Eigen::Index j = 0; j < q.size(); ++j) {
    Eigen::VectorXd up = q, down = q;
    up[j] += h;
    down[j] -= h;
    const Eigen::Vector3d derivative = (IndependentPoint(up, point) - IndependentPoint(down, point)) / (2 * h);
    INFO("column " << j << ": KDL " << J.col(j).transpose() << ", finite difference " << derivative.transpose());
    CHECK((J.col(j) - derivative).norm() < 1e-8);
  }
  // And the reflected mass is the independent 1/(u' J M^-1 J' u), extremes from its eigenvalues.
  const Eigen::Vector3d u = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  const auto result = covopt::robot::ReflectedMass(chain, q, point, u);
  const Eigen::Matrix3d inverse = J * IndependentMass(q).inverse() * J.transpose();
  CHECK(*result.reflected_mass_kg == Approx(1.0 / u.dot(inverse * u)).epsilon(1e-10));
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(inverse);
  CHECK(result.max_reflected_mass_kg == Approx(1.0 / eigen.eigenvalues()[0]).epsilon(1e-10));
  CHECK(result.min_reflected_mass_kg == Approx(1.0 / eigen.eigenvalues()[2]).epsilon(1e-10));
  CHECK(result.status == covopt::robot::ReflectedMassStatus::kSuccess);
  CHECK(result.warnings.empty());
  CHECK(*result.reflected_mass_kg <= result.max_reflected_mass_kg * (1 + 1e-12));
  CHECK(*result.reflected_mass_kg >= result.min_reflected_mass_kg * (1 - 1e-12));
  // Along the extreme directions the directional mass is the extreme.
  CHECK(*covopt::robot::ReflectedMass(chain, q, point, result.max_direction).reflected_mass_kg ==
        Approx(result.max_reflected_mass_kg).epsilon(1e-10));
}

TEST_CASE("a payload on the 3-D arm's tip adds its independent share to M(q) and the reflected mass") {
  const auto bare = covopt::robot::KinematicChain::FromUrdfString(Urdf(), {"", "l6"}, "made_up_arm");
  covopt::robot::Payload payload;
  payload.mass_kg = 1.7;
  payload.center_of_mass_m = Eigen::Vector3d(0.03, -0.05, 0.12);
  payload.inertia_kg_m2 = covopt::robot::Payload::InertiaFromSix(0.006, 0.008, 0.004, 0.001, -0.0007, 0.0012);
  const auto loaded = bare.WithPayload(payload);
  Eigen::VectorXd q(5);
  q << 0.3, -0.7, 0.12, 1.1, -0.4;
  const Eigen::MatrixXd independent =
      IndependentMass(q) + IndependentPayloadShare(q, payload.mass_kg, payload.center_of_mass_m, payload.inertia_kg_m2);
  const Eigen::MatrixXd kdl = covopt::robot::JointSpaceInertia(loaded, q);
  INFO("KDL\n" << kdl << "\nindependent\n" << independent);
  CHECK((kdl - independent).cwiseAbs().maxCoeff() < 1e-12 * independent.cwiseAbs().maxCoeff());
  const Eigen::Vector3d point(0.05, -0.02, 0.11);
  const Eigen::Vector3d u = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
  const Eigen::MatrixXd J = covopt::robot::ContactJacobian(bare, q, point);
  const double expected = 1.0 / (u.transpose() * J * independent.inverse() * J.transpose() * u)(0, 0);
  const double got = *covopt::robot::ReflectedMass(loaded, q, point, u).reflected_mass_kg;
  CHECK(got == Approx(expected).epsilon(1e-10));
  CHECK(got > *covopt::robot::ReflectedMass(bare, q, point, u).reflected_mass_kg);
}
