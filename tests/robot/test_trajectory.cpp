// Joint trajectories (ReadJointTrajectory: header, time, n positions, n velocities) and the
// contact point's motion along them (ContactMotion): speed |J_v q̇| and reflected mass along
// the motion against the planar arm's closed form; a sample at rest; and the reader's
// errors, each naming the line and column.
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>

#include <catch2/catch.hpp>

#include "covopt/robot.hpp"

using Catch::Matchers::Contains;
using covopt::robot::ReadJointTrajectory;

namespace {

const std::string kPlanar = std::string(COVOPT_ROBOT_TEST_DATA_DIR) + "/planar_2link.urdf";

covopt::robot::JointTrajectory Read(const std::string& text, std::size_t joints = 2) {
  std::istringstream in(text);
  return ReadJointTrajectory(in, joints, "traj.csv");
}

std::string ReadError(const std::string& text, std::size_t joints = 2) {
  try {
    Read(text, joints);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  FAIL("no std::invalid_argument thrown");
  return {};
}

}  // namespace

TEST_CASE("a trajectory CSV is read into times, positions and velocities") {
  const auto trajectory = Read(
      "time_s,q1,q2,qd1,qd2\n"
      "# comment\n"
      "0, 0.1, 0.2, 1.0, -1.0\n"
      "\n"
      "0.5, 0.3 ,0.4,0,0\r\n"
      "0.5, 0.3, 0.4, 0, 0\n");
  REQUIRE(trajectory.size() == 3);
  CHECK(trajectory.time_s[1] == 0.5);
  CHECK(trajectory.positions[0] == Eigen::Vector2d(0.1, 0.2));
  CHECK(trajectory.velocities[0] == Eigen::Vector2d(1.0, -1.0));
  CHECK(trajectory.positions[1] == Eigen::Vector2d(0.3, 0.4));
}

TEST_CASE("trajectory errors name the line, the column and what it should hold") {
  CHECK_THAT(ReadError("t,q1,q2,qd1,qd2\n0,1,2,3\n"),
             Contains("traj.csv:2: 4 columns, expected 5 (time [s], 2 joint positions [rad], 2 joint velocities [rad/s])"));
  CHECK_THAT(ReadError("t,q1,q2\n"), Contains("traj.csv:1: 3 columns, expected 5"));
  CHECK_THAT(ReadError("t,q1,q2,qd1,qd2\n0,1,nan,3,4\n"),
             Contains("traj.csv:2, column 3 (q2 [rad]): expected a finite number (got 'nan')"));
  CHECK_THAT(ReadError("t,q1,q2,qd1,qd2\n0,1,2,3,fast\n"),
             Contains("traj.csv:2, column 5 (qd2 [rad/s])"));
  CHECK_THAT(ReadError("t,q1,q2,qd1,qd2\n0,1,2,3,\n"), Contains("column 5"));
  CHECK_THAT(ReadError("t,q1,q2,qd1,qd2\n0,1,2,3,1e999\n"), Contains("column 5"));
  CHECK_THAT(ReadError("t,q1,q2,qd1,qd2\n1,0,0,0,0\n0.5,0,0,0,0\n"),
             Contains("traj.csv:3, column 1 (time [s]): time goes backwards (0.5 s after 1 s)"));
  CHECK_THAT(ReadError(""), Contains("traj.csv: empty trajectory"));
  CHECK_THAT(ReadError("t,q1,q2,qd1,qd2\n"), Contains("header but no samples"));
  CHECK_THAT(ReadError("t,q1,q2,qd1,qd2\n0,1,2,3,4\n", 1), Contains("5 columns, expected 3"));
}

TEST_CASE("a missing trajectory file is named") {
  try {
    ReadJointTrajectory(std::filesystem::path("/nonexistent/t.csv"), 2);
    FAIL("no error");
  } catch (const std::invalid_argument& e) {
    CHECK_THAT(e.what(), Contains("/nonexistent/t.csv: no such trajectory file"));
  }
}

TEST_CASE("the contact point's speed and reflected mass along the motion match the closed form") {
  const auto chain = covopt::robot::KinematicChain::FromUrdfFile(kPlanar, {"", "tool"});
  const auto trajectory = Read(
      "t,q1,q2,qd1,qd2\n"
      "0.0, 0.3, 1.2, 0.5, -0.8\n"
      "0.1, 0.4, 1.0, 0.0, 0.0\n"
      "0.2, 0.5, 0.0, 1.0, 0.0\n");
  const auto motion = covopt::robot::ContactMotion(chain, trajectory, Eigen::Vector3d::Zero());
  REQUIRE(motion.samples.size() == 3);
  // Sample 1: v = J q̇ with the closed-form J of the tip (l1 = 1, l2 = 0.8).
  {
    const double q1 = 0.3, q2 = 1.2, a = q1 + q2;
    Eigen::Matrix<double, 3, 2> J = Eigen::Matrix<double, 3, 2>::Zero();
    J << -std::sin(q1) - 0.8 * std::sin(a), -0.8 * std::sin(a), std::cos(q1) + 0.8 * std::cos(a),
        0.8 * std::cos(a), 0, 0;
    const Eigen::Vector3d v = J * Eigen::Vector2d(0.5, -0.8);
    const auto& s = motion.samples[0];
    CHECK((s.velocity_m_per_s - v).norm() < 1e-12);
    CHECK(s.speed_m_per_s == Approx(v.norm()).epsilon(1e-12));
    CHECK(s.moving);
    CHECK(s.direction.isApprox(v.normalized()));
    const auto along = covopt::robot::ReflectedMass(chain, Eigen::Vector2d(q1, q2), Eigen::Vector3d::Zero(), v);
    CHECK(s.reflected_mass_kg == Approx(*along.reflected_mass_kg).epsilon(1e-14));
    CHECK(s.time_s == 0.0);
  }
  // Sample 2: at rest: no direction, the largest reflected mass (infinite for a planar arm).
  CHECK_FALSE(motion.samples[1].moving);
  CHECK(motion.samples[1].speed_m_per_s == 0.0);
  CHECK(motion.samples[1].direction.isZero());
  CHECK(std::isinf(motion.samples[1].reflected_mass_kg));
  // Sample 3: stretched arm turning about the shoulder: the tip moves across the arm at
  // (l1 + l2) q̇1 = 1.8 m/s, with the finite mass across it.
  CHECK(motion.samples[2].speed_m_per_s == Approx(1.8).epsilon(1e-12));
  CHECK(std::isfinite(motion.samples[2].reflected_mass_kg));
  CHECK(motion.status == covopt::robot::ContactMotionStatus::kSuccess);
  CHECK_THAT(motion.message, Contains("3 samples") && Contains("1.8 m/s"));
}

TEST_CASE("along its own motion a point's reflected mass is finite, even at a singularity") {
  // v = J q̇ lies in the range of J, which is the range of J M^-1 J': u' Λ^-1 u > 0 along the
  // motion. The stretched planar arm (q2 = 0) is singular along the arm, but whatever the
  // joint speeds the tip moves across it, with a finite mass.
  const auto chain = covopt::robot::KinematicChain::FromUrdfFile(kPlanar, {"", "tool"});
  const auto motion = covopt::robot::ContactMotion(
      chain, Read("t,a,b,c,d\n0,0,0,1,1\n0.1,0.2,0,-0.5,3\n"), Eigen::Vector3d::Zero());
  for (const auto& sample : motion.samples) {
    CHECK(sample.moving);
    CHECK(std::isfinite(sample.reflected_mass_kg));
  }
  CHECK(motion.status == covopt::robot::ContactMotionStatus::kSuccess);
  CHECK(motion.warnings.empty());
}

TEST_CASE("links beyond the tip ride along as payload, their joints locked, with a warning") {
  // The cart's chain stops at the cart; the swinging arm (1 kg) hangs beyond it, held at
  // swing = 0: along the rail the cart carries 4 + 1 kg.
  const auto chain = covopt::robot::KinematicChain::FromUrdfFile(
      std::string(COVOPT_ROBOT_TEST_DATA_DIR) + "/prismatic_cart.urdf", {"", "cart"});
  CHECK(chain.locked_joint_names() == std::vector<std::string>{"swing"});
  CHECK(chain.moving_mass_kg() == Approx(5.0));
  const auto motion = covopt::robot::ContactMotion(chain, Read("t,s,sd\n0,0,1\n", 1),
                                                   Eigen::Vector3d::Zero());
  CHECK(motion.samples[0].reflected_mass_kg == Approx(4.0 + 1.0).epsilon(1e-14));
  REQUIRE(motion.warnings.size() == 1);
  CHECK_THAT(motion.warnings[0], Contains("locked at 0 (swing)"));
  const auto mass = covopt::robot::ReflectedMass(chain, Eigen::VectorXd::Zero(1),
                                                 Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX());
  CHECK_THAT(mass.warnings[0], Contains("locked at 0 (swing)"));
}

TEST_CASE("ContactMotion refuses samples that do not fit the chain") {
  const auto chain = covopt::robot::KinematicChain::FromUrdfFile(kPlanar, {"", "tool"});
  const auto trajectory = Read("t,a,b\n0,1,2\n", 1);  // 1 joint's worth for a 2-joint arm
  try {
    covopt::robot::ContactMotion(chain, trajectory, Eigen::Vector3d::Zero());
    FAIL("no error");
  } catch (const std::invalid_argument& e) {
    CHECK_THAT(e.what(), Contains("trajectory sample 1 positions: 1 value given") &&
                             Contains("2 movable joints"));
  }
}
