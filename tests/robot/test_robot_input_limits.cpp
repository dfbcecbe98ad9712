// Inputs that once gave wrong answers with no error (issue 22): a trajectory without a header,
// positions in degrees, the URDF's joint limits, a URDF whose joints form a cycle, a chain
// without movable joints, NaN or implausible inertias, masses and origins, a zero axis,
// overflowing directions and points, hex floats, and inputs beyond the size limits.
#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>

#include <catch2/catch.hpp>

#include "covopt/robot.hpp"
#include "robot_test_support.hpp"

using Catch::Matchers::Contains;
using covopt::robot::KinematicChain;

namespace {

using covopt::robot::testing::kPlanar;
using covopt::robot::testing::MessageOf;

covopt::robot::JointTrajectory Read(const std::string& text, std::size_t joints = 2) {
  std::istringstream in(text);
  return covopt::robot::ReadJointTrajectory(in, joints, "traj.csv");
}

/// A one-joint arm: `joint` is the revolute joint's body (origin, axis, limit), `inertial` the
/// moving link's; `extra` more joints and links.
std::string OneJointUrdf(const std::string& joint, const std::string& inertial, const std::string& extra = "") {
  return "<robot name='r'><link name='base'/>"
         "<joint name='j1' type='revolute'><parent link='base'/><child link='arm'/>" +
         joint + "</joint><link name='arm'><inertial>" + inertial + "</inertial></link>" + extra + "</robot>";
}

const std::string kJoint = "<origin xyz='0 0 0'/><axis xyz='0 0 1'/><limit lower='-1' upper='1' effort='1' velocity='2'/>";
const std::string kInertial = "<origin xyz='0.5 0 0'/><mass value='2'/><inertia ixx='0.01' ixy='0' ixz='0' iyy='0.1' iyz='0' izz='0.1'/>";

KinematicChain Chain(const std::string& urdf, const std::string& tip = "arm") {
  return KinematicChain::FromUrdfString(urdf, {"", tip}, "r.urdf");
}

std::string InertialWith(const std::string& mass, const std::string& ixx, const std::string& izz) {
  return "<origin xyz='0.5 0 0'/><mass value='" + mass + "'/><inertia ixx='" + ixx +
         "' ixy='0' ixz='0' iyy='0.1' iyz='0' izz='" + izz + "'/>";
}

}  // namespace

TEST_CASE("a trajectory whose first line is all numbers has no header: every line is a sample, with a warning") {
  const auto headerless = Read("0,0.1,0.2,1,-1\n0.5,0.3,0.4,0,0\n");
  REQUIRE(headerless.size() == 2);  // the first row is not dropped
  CHECK(headerless.positions[0] == Eigen::Vector2d(0.1, 0.2));
  REQUIRE(headerless.warnings.size() == 1);
  CHECK_THAT(headerless.warnings[0], Contains("no header line") && Contains("time [s], the 2 joint positions"));
  const auto with_header = Read("t,q1,q2,qd1,qd2\n0,0.1,0.2,1,-1\n");
  CHECK(with_header.size() == 1);
  CHECK(with_header.warnings.empty());
  // The warning reaches ContactMotion's answer.
  const auto chain = KinematicChain::FromUrdfFile(kPlanar, {"", "tool"});
  const auto motion = covopt::robot::ContactMotion(chain, headerless, Eigen::Vector3d::Zero());
  CHECK(std::any_of(motion.warnings.begin(), motion.warnings.end(),
                    [](const std::string& w) { return w.find("no header line") != std::string::npos; }));
  // A header-less line must still have 1 + 2n columns.
  CHECK_THAT(MessageOf([] { Read("0,0.1,0.2\n"); }), Contains("traj.csv:1: 3 columns, expected 5"));
}

TEST_CASE("trajectory numbers are decimal: hex floats, inf and overlong cells are refused, briefly") {
  CHECK_THAT(MessageOf([] { Read("t,a,b,c,d\n0,0x1p3,0,0,0\n"); }),
             Contains("traj.csv:2, column 2 (q1 [rad]): expected a finite number (got '0x1p3'), in decimal"));
  CHECK_THAT(MessageOf([] { Read("t,a,b,c,d\n0,inf,0,0,0\n"); }), Contains("got 'inf'"));
  const std::string message = MessageOf([] { Read("t,a,b,c,d\n0," + std::string(100000, '1') + "x,0,0,0\n"); });
  CHECK(message.size() < 300);
  CHECK(Read("t,a,b,c,d\n+0,-0.5,+1e-1,2.5E-3,0\n").positions[0][1] == 0.1);
}

TEST_CASE("positions beyond a full turn are refused naming line, column, value and that they are radians") {
  const auto chain = KinematicChain::FromUrdfFile(kPlanar, {"", "tool"});
  const auto degrees = Read("t,q1,q2,qd1,qd2\n0,0,0,0,0\n1,0,-90,0,0\n");
  CHECK_THAT(MessageOf([&] { covopt::robot::ContactMotion(chain, degrees, Eigen::Vector3d::Zero()); }),
             Contains("traj.csv:3, column 3 (q2 [rad], joint 'elbow'): -90 rad is not allowed") &&
                 Contains("[-6.28319, 6.28319] rad") && Contains("radians; degrees?"));
  const auto huge = Read("0,1e300,0,0,0\n");
  CHECK_THAT(MessageOf([&] { covopt::robot::ContactMotion(chain, huge, Eigen::Vector3d::Zero()); }),
             Contains("column 2 (q1 [rad], joint 'shoulder'): 1e+300 rad"));
  const Eigen::Vector2d q(0.0, -90.0);
  CHECK_THAT(MessageOf([&] { covopt::robot::ReflectedMass(chain, q, Eigen::Vector3d::Zero(), std::nullopt); }),
             Contains("joints: joint 2 (elbow): -90 rad is not allowed (within a full turn"));
}

TEST_CASE("the URDF's joint limits are checked unless the caller ignores them, with a warning") {
  const auto chain = KinematicChain::FromUrdfFile(kPlanar, {"", "tool"});  // shoulder [-3.14, 3.14], 2 rad/s
  REQUIRE(chain.joints()[0].limits.has_position);
  CHECK(chain.joints()[0].limits.upper == 3.14);
  CHECK_FALSE(chain.joints()[1].limits.has_position);  // continuous
  const Eigen::Vector2d q(3.5, 0.0);
  CHECK_THAT(MessageOf([&] { covopt::robot::ReflectedMass(chain, q, Eigen::Vector3d::Zero(), std::nullopt); }),
             Contains("joints: joint 1 (shoulder): 3.5 rad is not allowed (outside the URDF's limits [-3.14, 3.14] "
                      "rad of joint 'shoulder'") && Contains("--ignore-joint-limits"));
  covopt::robot::ReflectedMassOptions ignore;
  ignore.check_joint_limits = false;
  const auto result = covopt::robot::ReflectedMass(chain, q, Eigen::Vector3d::Zero(), std::nullopt, ignore);
  CHECK_THAT(result.warnings.back(), Contains("joint limits") && Contains("were not checked"));

  const auto fast = Read("0,0,0,2.5,0\n");
  CHECK_THAT(MessageOf([&] { covopt::robot::ContactMotion(chain, fast, Eigen::Vector3d::Zero()); }),
             Contains("traj.csv:1, column 4 (qd1 [rad/s], joint 'shoulder'): 2.5 rad/s is not allowed (outside "
                      "the URDF's velocity limit [-2, 2] rad/s"));
  covopt::robot::ContactMotionOptions options;
  options.reflected_mass = ignore;
  const auto motion = covopt::robot::ContactMotion(chain, fast, Eigen::Vector3d::Zero(), options);
  CHECK_THAT(motion.warnings.back(), Contains("were not checked"));
  // A dict-like trajectory (no lines) names the sample.
  covopt::robot::JointTrajectory typed;
  typed.time_s = {0.0};
  typed.positions = {Eigen::Vector2d(3.5, 0.0)};
  typed.velocities = {Eigen::Vector2d::Zero()};
  CHECK_THAT(MessageOf([&] { covopt::robot::ContactMotion(chain, typed, Eigen::Vector3d::Zero()); }),
             Contains("trajectory sample 1, q1 (joint 'shoulder'): 3.5 rad"));
}

TEST_CASE("joint limit semantics: velocity 0 and lower = upper mean not given, and lower > upper is refused") {
  const auto unlimited = Chain(OneJointUrdf("<axis xyz='0 0 1'/><limit effort='1' velocity='0'/>", kInertial));
  CHECK_FALSE(unlimited.joints()[0].limits.has_position);
  CHECK_FALSE(unlimited.joints()[0].limits.has_velocity);
  CHECK_THAT(unlimited.warnings().at(0), Contains("joint 'j1' has no position range"));
  CHECK_NOTHROW(covopt::robot::ReflectedMass(unlimited, Eigen::VectorXd::Constant(1, 2.0), Eigen::Vector3d::Zero(),
                                             std::nullopt));
  CHECK_THAT(MessageOf([] { Chain(OneJointUrdf("<axis xyz='0 0 1'/><limit lower='1' upper='-1' effort='1' velocity='1'/>",
                                               kInertial)); }),
             Contains("r.urdf: joint 'j1': <limit lower> = 1 is not allowed (lower <= upper"));
  CHECK_THAT(MessageOf([] { Chain(OneJointUrdf("<axis xyz='0 0 1'/><limit lower='-1' upper='1' effort='1' velocity='-1'/>",
                                               kInertial)); }),
             Contains("<limit velocity> = -1 is not allowed"));
}

TEST_CASE("a URDF whose joints form a cycle is refused at once, naming the link with two parents") {
  const std::string cycle = OneJointUrdf(
      kJoint, kInertial,
      "<link name='arm2'/><joint name='j2' type='fixed'><parent link='arm'/><child link='arm2'/></joint>"
      "<joint name='j3' type='fixed'><parent link='arm2'/><child link='arm'/></joint>");
  CHECK_THAT(MessageOf([&] { Chain(cycle, "arm2"); }), Contains("link 'arm' has two parents") && Contains("cycle"));
  const std::string self = OneJointUrdf(kJoint, kInertial, "<joint name='j2' type='fixed'><parent link='arm'/><child link='arm'/></joint>");
  CHECK_THAT(MessageOf([&] { Chain(self); }), Contains("cycle"));
}

TEST_CASE("a chain without a movable joint is refused, not reported as a fixed robot") {
  CHECK_THAT(MessageOf([] { KinematicChain::FromUrdfFile(kPlanar, {"link2", "link2"}); }),
             Contains("the chain link2 -> link2 has no movable joint"));
  CHECK_THAT(MessageOf([] { KinematicChain::FromUrdfFile(kPlanar, {"link2", "tool"}); }), Contains("no movable joint"));
}

TEST_CASE("masses and inertias must be finite and physical, and the message names link, field and value") {
  CHECK_THAT(MessageOf([] { Chain(OneJointUrdf(kJoint, InertialWith("2", "0.01", "nan"))); }),
             Contains("r.urdf: malformed URDF") && Contains("izz is not a valid double") && Contains("Link [arm]"));
  CHECK_THAT(MessageOf([] { Chain(OneJointUrdf(kJoint, InertialWith("nan", "0.01", "0.1"))); }),
             Contains("mass [nan] is not a float") && Contains("Link [arm]"));
  CHECK_THAT(MessageOf([] { Chain(OneJointUrdf(kJoint, InertialWith("-1", "0.01", "0.1"))); }),
             Contains("<mass> value = -1"));
  CHECK_THAT(MessageOf([] { Chain(OneJointUrdf(kJoint, InertialWith("1e308", "0.01", "0.1"))); }),
             Contains("<mass> value = 1e+308"));
  CHECK_THAT(MessageOf([] { Chain(OneJointUrdf(kJoint, InertialWith("2", "0.01", "-0.1"))); }),
             Contains("link 'arm'") && Contains("smallest principal moment = -0.1") && Contains("positive semi-definite"));
  CHECK_THAT(MessageOf([] { Chain(OneJointUrdf(kJoint, InertialWith("2", "0.01", "0.5"))); }),
             Contains("largest principal moment = 0.5") && Contains("triangle inequality"));
  CHECK_THAT(MessageOf([] { Chain(OneJointUrdf(kJoint, "<origin xyz='1e308 0 0'/><mass value='1'/><inertia ixx='0' ixy='0' ixz='0' iyy='0' iyz='0' izz='0'/>")); }),
             Contains("<inertial> <origin> xyz x = 1e+308 is not allowed"));
}

TEST_CASE("joint origins and axes: a zero axis and an origin of 1e308 m are refused") {
  CHECK_THAT(MessageOf([] { Chain(OneJointUrdf("<axis xyz='0 0 0'/><limit lower='-1' upper='1' effort='1' velocity='1'/>", kInertial)); }),
             Contains("r.urdf: joint 'j1': <axis xyz> = (0, 0, 0) is not allowed"));
  CHECK_THAT(MessageOf([] { Chain(OneJointUrdf("<origin xyz='0 1e308 0'/><axis xyz='0 0 1'/><limit lower='-1' upper='1' effort='1' velocity='1'/>", kInertial)); }),
             Contains("joint 'j1': <origin> xyz y = 1e+308 is not allowed (a finite length within ±1000 m)"));
  // A huge but finite axis is normalised without overflow.
  const auto chain = Chain(OneJointUrdf("<axis xyz='0 0 1e308'/><limit lower='-1' upper='1' effort='1' velocity='1'/>", kInertial));
  const auto result = covopt::robot::ReflectedMass(chain, Eigen::VectorXd::Zero(1), Eigen::Vector3d(1, 0, 0), std::nullopt);
  CHECK(std::isfinite(result.min_reflected_mass_kg));
}

TEST_CASE("a direction of 1e308 components is normalised without overflow, and a point of 1e308 m is refused") {
  const auto chain = KinematicChain::FromUrdfFile(kPlanar, {"", "tool"});
  const Eigen::Vector2d q(0.3, 0.6);
  const auto result = covopt::robot::ReflectedMass(chain, q, Eigen::Vector3d::Zero(), Eigen::Vector3d(1e308, 1e308, 0));
  REQUIRE(result.direction);
  CHECK(result.direction->isApprox(Eigen::Vector3d(1, 1, 0).normalized()));
  const auto reference = covopt::robot::ReflectedMass(chain, q, Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 1, 0));
  CHECK(*result.reflected_mass_kg == Approx(*reference.reflected_mass_kg));
  CHECK_THAT(MessageOf([&] { covopt::robot::ReflectedMass(chain, q, Eigen::Vector3d(1e308, 0, 0), std::nullopt); }),
             Contains("point: component 1 = 1e+308 m is not allowed"));
}

TEST_CASE("inputs beyond the size limits are refused at once, a device included") {
  CHECK_THAT(MessageOf([] { KinematicChain::FromUrdfFile("/dev/zero", {"", "tip"}); }),
             Contains("/dev/zero: larger than 16 MiB, the limit for a URDF file"));
  CHECK_THAT(MessageOf([] { covopt::robot::ReadJointTrajectory(std::filesystem::path("/dev/zero"), 2); }),
             Contains("/dev/zero: larger than 64 MiB, the limit for a trajectory file"));
  std::string rows;
  rows.reserve(11000000);
  for (std::size_t i = 0; i <= covopt::robot::kMaxTrajectorySamples; ++i) rows += "0,0,0,0,0\n";
  CHECK_THAT(MessageOf([&] { Read(rows); }),
             Contains("traj.csv:1000001: more than 1000000 samples, the limit for a trajectory"));
}
