// covopt::robot on small arms with closed forms: a planar two-link arm (M(q) and J(q) of the
// textbook, e.g. Spong, Hutchinson & Vidyasagar, Robot Modeling and Control §7.4), its
// stretched (singular) configuration, a contact point offset from the tip frame, a fixed
// joint with a rotated origin, and a cart on a prismatic joint.
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include "covopt/robot.hpp"

using covopt::robot::ChainSpec;
using covopt::robot::KinematicChain;
using covopt::robot::ReflectedMass;
using covopt::robot::ReflectedMassStatus;

namespace {

const std::string kDataDir = COVOPT_ROBOT_TEST_DATA_DIR;

KinematicChain Planar(const std::string& tip = "link2", const std::string& base = "") {
  return KinematicChain::FromUrdfFile(kDataDir + "/planar_2link.urdf", ChainSpec{base, tip});
}

// The arm's parameters (planar_2link.urdf).
constexpr double l1 = 1.0, lc1 = 0.5, m1 = 2.0, I1 = 0.1;
constexpr double l2 = 0.8, lc2 = 0.4, m2 = 1.5, I2 = 0.05;

Eigen::Matrix2d ClosedFormMass(double q2) {
  Eigen::Matrix2d M;
  M(0, 0) = I1 + I2 + m1 * lc1 * lc1 + m2 * (l1 * l1 + lc2 * lc2 + 2 * l1 * lc2 * std::cos(q2));
  M(0, 1) = M(1, 0) = I2 + m2 * (lc2 * lc2 + l1 * lc2 * std::cos(q2));
  M(1, 1) = I2 + m2 * lc2 * lc2;
  return M;
}

/// The linear Jacobian of the point at `reach` along link 2 and `side` across it.
Eigen::Matrix<double, 3, 2> ClosedFormJacobian(double q1, double q2, double reach, double side) {
  const double a = q1 + q2;
  // p = l1 (c1, s1) + reach (c12, s12) + side (-s12, c12)
  Eigen::Matrix<double, 3, 2> J = Eigen::Matrix<double, 3, 2>::Zero();
  const double dx12 = -reach * std::sin(a) - side * std::cos(a);
  const double dy12 = reach * std::cos(a) - side * std::sin(a);
  J(0, 0) = -l1 * std::sin(q1) + dx12;
  J(1, 0) = l1 * std::cos(q1) + dy12;
  J(0, 1) = dx12;
  J(1, 1) = dy12;
  return J;
}

double ClosedFormReflectedMass(const Eigen::Matrix<double, 3, 2>& J, const Eigen::Matrix2d& M,
                               const Eigen::Vector3d& u) {
  const Eigen::Matrix3d inverse = J * M.inverse() * J.transpose();
  return 1.0 / (u.dot(inverse * u));
}

}  // namespace

TEST_CASE("the planar arm's chain has its two movable joints in order and keeps the fixed one") {
  const KinematicChain chain = Planar("tool");
  CHECK(chain.robot_name() == "planar_2link");
  CHECK(chain.base_link() == "base_link");
  CHECK(chain.joint_count() == 2);
  REQUIRE(chain.joint_names() == std::vector<std::string>{"shoulder", "elbow"});
  REQUIRE(chain.joints().size() == 3);
  CHECK(chain.joints()[2].name == "tool_joint");
  CHECK(chain.joints()[2].type == covopt::robot::JointType::kFixed);
  CHECK(chain.joints()[1].type == covopt::robot::JointType::kContinuous);
  CHECK(chain.moving_mass_kg() == Approx(m1 + m2));
}

TEST_CASE("M(q) of the planar arm is the closed form") {
  const KinematicChain chain = Planar();
  const double q1 = GENERATE(-1.0, 0.0, 0.7);
  const double q2 = GENERATE(-2.5, 0.0, 0.3, 1.9);
  const Eigen::MatrixXd M = covopt::robot::JointSpaceInertia(chain, Eigen::Vector2d(q1, q2));
  const Eigen::Matrix2d expected = ClosedFormMass(q2);
  INFO("q = " << q1 << ", " << q2 << "\nM =\n" << M << "\nexpected\n" << expected);
  CHECK((M - expected).cwiseAbs().maxCoeff() < 1e-12);
}

TEST_CASE("the contact Jacobian of the planar arm is the closed form, offset point included") {
  const KinematicChain chain = Planar();
  const double q1 = GENERATE(-0.4, 1.1);
  const double q2 = GENERATE(-1.3, 0.6);
  const double side = GENERATE(0.0, 0.1);
  const Eigen::Vector3d point(l2, side, 0.0);  // in link2's frame
  const auto J = covopt::robot::ContactJacobian(chain, Eigen::Vector2d(q1, q2), point);
  const Eigen::Matrix<double, 3, 2> expected = ClosedFormJacobian(q1, q2, l2, side);
  INFO("J =\n" << J << "\nexpected\n" << expected);
  CHECK((J - expected).cwiseAbs().maxCoeff() < 1e-12);
  const double a = q1 + q2;
  const Eigen::Vector3d position = covopt::robot::ContactPoint(chain, Eigen::Vector2d(q1, q2), point);
  CHECK(position.x() == Approx(l1 * std::cos(q1) + l2 * std::cos(a) - side * std::sin(a)));
  CHECK(position.y() == Approx(l1 * std::sin(q1) + l2 * std::sin(a) + side * std::cos(a)));
  CHECK(position.z() == Approx(0.0).margin(1e-15));
}

TEST_CASE("the reflected mass of the planar arm along a direction is 1/(u' J M^-1 J' u)") {
  const KinematicChain chain = Planar("tool");
  const Eigen::Vector2d q(0.3, 1.2);
  const Eigen::Vector3d u_raw(1.0, 2.0, 0.0);
  const auto result = ReflectedMass(chain, q, Eigen::Vector3d::Zero(), u_raw);
  const Eigen::Vector3d u = u_raw.normalized();
  const double expected = ClosedFormReflectedMass(ClosedFormJacobian(q[0], q[1], l2, 0.0),
                                                  ClosedFormMass(q[1]), u);
  REQUIRE(result.reflected_mass_kg);
  CHECK(*result.reflected_mass_kg == Approx(expected).epsilon(1e-12));
  CHECK(result.direction->isApprox(u));
  CHECK(result.joint_names == std::vector<std::string>{"shoulder", "elbow"});
  // In the plane the extremes are the reciprocal eigenvalues of the 2x2 block, and every
  // direction's mass lies between them; out of the plane (z) the arm cannot move: fixed.
  const Eigen::Matrix<double, 3, 2> J = ClosedFormJacobian(q[0], q[1], l2, 0.0);
  const Eigen::Matrix2d inverse =
      (J * ClosedFormMass(q[1]).inverse() * J.transpose()).topLeftCorner<2, 2>();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(inverse);
  CHECK(result.min_reflected_mass_kg == Approx(1.0 / eigen.eigenvalues()[1]).epsilon(1e-12));
  CHECK(result.min_direction.z() == Approx(0.0).margin(1e-12));
  CHECK(std::isinf(result.max_reflected_mass_kg));
  CHECK(result.max_direction.isApprox(Eigen::Vector3d::UnitZ()));
  CHECK(result.status == ReflectedMassStatus::kFixedDirections);
  REQUIRE(result.warnings.size() == 1);
  CHECK_THAT(result.warnings[0], Catch::Contains("infinite (fixed)"));
  CHECK(*result.reflected_mass_kg >= result.min_reflected_mass_kg * (1 - 1e-12));
  // Masses scale with the links: doubling every mass and inertia would double m_u; instead
  // check the direction's sign does not matter.
  const auto reversed = ReflectedMass(chain, q, Eigen::Vector3d::Zero(), Eigen::Vector3d(-u_raw));
  CHECK(*reversed.reflected_mass_kg == Approx(*result.reflected_mass_kg).epsilon(1e-14));
}

TEST_CASE("the stretched planar arm is singular: infinite mass along the arm, finite across it") {
  const KinematicChain chain = Planar("tool");
  const double q1 = GENERATE(0.0, 0.6);
  const Eigen::Vector2d q(q1, 0.0);
  const Eigen::Vector3d along(std::cos(q1), std::sin(q1), 0.0);
  const Eigen::Vector3d across(-std::sin(q1), std::cos(q1), 0.0);
  const auto along_arm = ReflectedMass(chain, q, Eigen::Vector3d::Zero(), along);
  REQUIRE(along_arm.reflected_mass_kg);
  CHECK(std::isinf(*along_arm.reflected_mass_kg));
  CHECK(along_arm.status == ReflectedMassStatus::kFixedDirections);
  bool warned_along = false;
  for (const auto& warning : along_arm.warnings) {
    warned_along = warned_along || warning.find("requested direction") != std::string::npos;
  }
  CHECK(warned_along);
  const auto across_arm = ReflectedMass(chain, q, Eigen::Vector3d::Zero(), across);
  const double expected = ClosedFormReflectedMass(ClosedFormJacobian(q1, 0.0, l2, 0.0),
                                                  ClosedFormMass(0.0), across);
  CHECK(*across_arm.reflected_mass_kg == Approx(expected).epsilon(1e-12));
  CHECK(across_arm.min_reflected_mass_kg == Approx(expected).epsilon(1e-12));
  CHECK(across_arm.min_direction.cwiseAbs().isApprox(across.cwiseAbs()));
  // Slightly bent, the mass along the arm is finite and large: the singularity is a limit.
  const auto bent = ReflectedMass(chain, Eigen::Vector2d(q1, 1e-3), Eigen::Vector3d::Zero(), along);
  CHECK(std::isfinite(*bent.reflected_mass_kg));
  CHECK(*bent.reflected_mass_kg > 1e4 * expected);
}

TEST_CASE("a point offset from the tip frame changes the contact point and the mass as closed-form") {
  const KinematicChain chain = Planar("link2");
  const Eigen::Vector2d q(0.2, 0.9);
  const Eigen::Vector3d offset(0.5, 0.1, 0.0);
  const Eigen::Vector3d u(0.0, 1.0, 0.0);
  const auto result = ReflectedMass(chain, q, offset, u);
  const double expected = ClosedFormReflectedMass(ClosedFormJacobian(q[0], q[1], 0.5, 0.1),
                                                  ClosedFormMass(q[1]), u);
  CHECK(*result.reflected_mass_kg == Approx(expected).epsilon(1e-12));
  const double a = q[0] + q[1];
  CHECK(result.contact_point_m.x() == Approx(std::cos(q[0]) + 0.5 * std::cos(a) - 0.1 * std::sin(a)));
  // Nearer the elbow the same arm feels heavier across the link (less lever on the elbow).
  const auto nearer = ReflectedMass(chain, q, Eigen::Vector3d(0.1, 0.0, 0.0),
                                    Eigen::Vector3d(-std::sin(a), std::cos(a), 0.0));
  const auto farther = ReflectedMass(chain, q, Eigen::Vector3d(0.8, 0.0, 0.0),
                                     Eigen::Vector3d(-std::sin(a), std::cos(a), 0.0));
  CHECK(*nearer.reflected_mass_kg > *farther.reflected_mass_kg);
}

TEST_CASE("a fixed joint with a rotated origin: the point is read in the rotated tool frame") {
  // tool_rotated is link2's frame moved 0.85 m along x and turned 90 deg about z, then 30 deg
  // about x (URDF rpy: R = Rz(yaw) Ry(pitch) Rx(roll)). Its x axis is link2's y axis, so the
  // point (0.1, 0, 0) in tool_rotated is (0.85, 0.1, 0) in link2.
  const KinematicChain rotated = Planar("tool_rotated");
  const KinematicChain plain = Planar("link2");
  CHECK(rotated.joint_count() == 2);
  const Eigen::Vector2d q(-0.3, 0.8);
  const Eigen::Vector3d u = Eigen::Vector3d(1.0, -1.0, 0.0).normalized();
  const auto through_fixed = ReflectedMass(rotated, q, Eigen::Vector3d(0.1, 0.0, 0.0), u);
  const auto direct = ReflectedMass(plain, q, Eigen::Vector3d(0.85, 0.1, 0.0), u);
  CHECK((through_fixed.contact_point_m - direct.contact_point_m).norm() < 1e-12);
  CHECK(*through_fixed.reflected_mass_kg == Approx(*direct.reflected_mass_kg).epsilon(1e-12));
  const double expected = ClosedFormReflectedMass(ClosedFormJacobian(q[0], q[1], 0.85, 0.1),
                                                  ClosedFormMass(q[1]), u);
  CHECK(*through_fixed.reflected_mass_kg == Approx(expected).epsilon(1e-12));
  // The roll tilts the tool's z axis: R = Rz(90 deg) Rx(30 deg) takes (0, 0, 0.1) to
  // (0.1 sin 30 deg, 0, 0.1 cos 30 deg) in link2's frame, whose z is the base's.
  const Eigen::Vector3d lifted =
      covopt::robot::ContactPoint(rotated, q, Eigen::Vector3d(0.0, 0.0, 0.1));
  const Eigen::Vector3d in_link2 = covopt::robot::ContactPoint(
      plain, q, Eigen::Vector3d(0.85 + 0.1 * std::sin(M_PI / 6), 0.0, 0.1 * std::cos(M_PI / 6)));
  CHECK((lifted - in_link2).norm() < 1e-12);
}

TEST_CASE("a prismatic joint: a cart's reflected mass along its rail is the closed form") {
  const KinematicChain chain =
      KinematicChain::FromUrdfFile(kDataDir + "/prismatic_cart.urdf", ChainSpec{"", "arm"});
  REQUIRE(chain.joints()[0].type == covopt::robot::JointType::kPrismatic);
  const double q2 = GENERATE(0.0, 0.7);
  const Eigen::Vector2d q(0.25, q2);
  Eigen::Matrix2d M;
  M << 5.0, -0.5 * std::sin(q2), -0.5 * std::sin(q2), 0.25 + 0.001;
  CHECK((covopt::robot::JointSpaceInertia(chain, q) - M).cwiseAbs().maxCoeff() < 1e-12);
  // At the arm's centre of mass: J = [[1, -0.5 s2], [0, 0.5 c2], [0, 0]].
  Eigen::Matrix<double, 3, 2> J = Eigen::Matrix<double, 3, 2>::Zero();
  J << 1.0, -0.5 * std::sin(q2), 0.0, 0.5 * std::cos(q2), 0.0, 0.0;
  const Eigen::Vector3d u = Eigen::Vector3d::UnitX();
  const auto result = ReflectedMass(chain, q, Eigen::Vector3d(0.5, 0.0, 0.0), u);
  CHECK(*result.reflected_mass_kg == Approx(1.0 / (u.dot(J * M.inverse() * J.transpose() * u))).epsilon(1e-12));
  CHECK(result.contact_point_m.x() == Approx(0.25 + 0.5 * std::cos(q2)));
  // With the arm along the rail (q2 = 0) the arm's mass rides with the cart: 5 kg along x.
  if (q2 == 0.0) CHECK(*result.reflected_mass_kg == Approx(5.0).epsilon(1e-12));
}

TEST_CASE("a base link inside the chain starts the chain there") {
  const KinematicChain chain = Planar("tool", "link1");
  CHECK(chain.joint_names() == std::vector<std::string>{"elbow"});
  // From link1, only the elbow moves: J = l2 (-s2, c2), M = I2 + m2 lc2^2.
  const double q2 = 0.4;
  const auto result = ReflectedMass(chain, Eigen::VectorXd::Constant(1, q2), Eigen::Vector3d::Zero(),
                                    Eigen::Vector3d(-std::sin(q2), std::cos(q2), 0.0));
  CHECK(*result.reflected_mass_kg == Approx((I2 + m2 * lc2 * lc2) / (l2 * l2)).epsilon(1e-12));
  // In link1's frame the elbow sits at (l1, 0, 0).
  CHECK(result.contact_point_m.isApprox(Eigen::Vector3d(l1 + l2 * std::cos(q2), l2 * std::sin(q2), 0.0)));
}
