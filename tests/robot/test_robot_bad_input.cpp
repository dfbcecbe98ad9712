// Bad input to covopt::robot gets one clear std::invalid_argument naming what and where:
// missing, unreadable or malformed URDFs (urdfdom's own console output silenced), unknown
// links, a base that is not an ancestor of the tip, unsupported joint types, a joint count
// that does not match, non-finite joints, points and directions, a zero direction.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include <catch2/catch.hpp>
#include <unistd.h>

#include "covopt/robot.hpp"
#include "robot_test_support.hpp"

using covopt::robot::ChainSpec;
using covopt::robot::KinematicChain;
using Catch::Matchers::Contains;

namespace {

using covopt::robot::testing::kPlanar;
using covopt::robot::testing::MessageOf;

}  // namespace

TEST_CASE("a missing URDF file is named") {
  const std::string message =
      MessageOf([] { KinematicChain::FromUrdfFile("/nonexistent/robot.urdf", {"", "tip"}); });
  CHECK_THAT(message, Contains("/nonexistent/robot.urdf") && Contains("no such URDF file"));
}

TEST_CASE("a directory or an unreadable file is not a URDF") {
  CHECK_THAT(MessageOf([] { KinematicChain::FromUrdfFile("/tmp", {"", "tip"}); }),
             Contains("/tmp") && Contains("directory"));
  if (::geteuid() != 0) {  // root reads anything
    const auto path = std::filesystem::temp_directory_path() /
                      ("covopt-unreadable-" + std::to_string(::getpid()) + ".urdf");
    std::ofstream(path) << "<robot name='x'><link name='a'/></robot>";
    std::filesystem::permissions(path, std::filesystem::perms::none);
    const std::string message = MessageOf([&] { KinematicChain::FromUrdfFile(path, {"", "a"}); });
    std::filesystem::remove(path);
    CHECK_THAT(message, Contains("cannot read"));
  }
}

TEST_CASE("a malformed URDF gets one line with urdfdom's reason and the source's name") {
  SECTION("not XML") {
    const std::string message =
        MessageOf([] { KinematicChain::FromUrdfString("<robot name='x'><link", {"", "a"}, "broken.urdf"); });
    CHECK_THAT(message, Contains("broken.urdf: malformed URDF"));
    CHECK(message.find('\n') == std::string::npos);
  }
  SECTION("a joint naming a link that does not exist") {
    const std::string message = MessageOf([] {
      KinematicChain::FromUrdfString(
          "<robot name='x'><link name='a'/><joint name='j' type='fixed'><parent link='a'/>"
          "<child link='ghost'/></joint></robot>",
          {"", "a"}, "ghost.urdf");
    });
    CHECK_THAT(message, Contains("ghost.urdf: malformed URDF") && Contains("ghost"));
  }
  SECTION("no robot element") {
    CHECK_THAT(MessageOf([] { KinematicChain::FromUrdfString("<xml/>", {"", "a"}, "empty.urdf"); }),
               Contains("empty.urdf: malformed URDF"));
  }
}

TEST_CASE("unknown base or tip links are named, with the links there are") {
  CHECK_THAT(MessageOf([] { KinematicChain::FromUrdfFile(kPlanar, {"", "hand"}); }),
             Contains("tip link 'hand' is not in the URDF") && Contains("link2"));
  CHECK_THAT(MessageOf([] { KinematicChain::FromUrdfFile(kPlanar, {"world", "link2"}); }),
             Contains("base link 'world' is not in the URDF"));
  CHECK_THAT(MessageOf([] { KinematicChain::FromUrdfFile(kPlanar, {"", ""}); }),
             Contains("tip link"));
}

TEST_CASE("a base that is not an ancestor of the tip is refused") {
  CHECK_THAT(MessageOf([] { KinematicChain::FromUrdfFile(kPlanar, {"link2", "link1"}); }),
             Contains("base link 'link2' is not an ancestor of tip link 'link1'"));
  CHECK_THAT(MessageOf([] { KinematicChain::FromUrdfFile(kPlanar, {"tool", "tool_rotated"}); }),
             Contains("not an ancestor"));
}

TEST_CASE("a floating or planar joint on the chain is refused, naming the joint and its type") {
  const std::string type = GENERATE(std::string("floating"), std::string("planar"));
  const std::string urdf = "<robot name='x'><link name='a'/><link name='b'/><joint name='odd' type='" +
                           type + "'><parent link='a'/><child link='b'/><axis xyz='0 0 1'/>"
                           "<limit lower='-1' upper='1' effort='1' velocity='1'/></joint></robot>";
  CHECK_THAT(MessageOf([&] { KinematicChain::FromUrdfString(urdf, {"", "b"}, "odd.urdf"); }),
             Contains("odd.urdf: joint 'odd' has type '" + type + "', which is not supported"));
  // Off the chain it does not matter: the chain a -> a is refused for having no movable joint.
  CHECK_THAT(MessageOf([&] { KinematicChain::FromUrdfString(urdf, {"", "a"}); }), Contains("no movable joint"));
}

TEST_CASE("joint positions must match the chain in number and be finite") {
  const KinematicChain chain = KinematicChain::FromUrdfFile(kPlanar, {"", "tool"});
  const Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  CHECK_THAT(MessageOf([&] { covopt::robot::ReflectedMass(chain, Eigen::Vector3d(0, 0, 0), origin, {}); }),
             Contains("3 values given") && Contains("2 movable joints (shoulder, elbow)"));
  CHECK_THAT(MessageOf([&] {
               covopt::robot::ReflectedMass(chain, Eigen::Vector2d(0.1, std::nan("")), origin, {});
             }),
             Contains("joint 2 (elbow) must be a finite number"));
  CHECK_THAT(MessageOf([&] {
               covopt::robot::JointSpaceInertia(
                   chain, Eigen::Vector2d(std::numeric_limits<double>::infinity(), 0));
             }),
             Contains("joint 1 (shoulder)"));
}

TEST_CASE("a zero or non-finite direction and a non-finite point are refused") {
  const KinematicChain chain = KinematicChain::FromUrdfFile(kPlanar, {"", "tool"});
  const Eigen::Vector2d q(0.1, 0.2);
  CHECK_THAT(MessageOf([&] {
               covopt::robot::ReflectedMass(chain, q, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
             }),
             Contains("direction: must be a non-zero vector"));
  CHECK_THAT(MessageOf([&] {
               covopt::robot::ReflectedMass(chain, q, Eigen::Vector3d::Zero(),
                                            Eigen::Vector3d(1, std::nan(""), 0));
             }),
             Contains("direction: component 2 must be a finite number"));
  CHECK_THAT(MessageOf([&] {
               covopt::robot::ReflectedMass(chain, q, Eigen::Vector3d(0, 0, std::nan("")), {});
             }),
             Contains("point: component 3"));
  covopt::robot::ReflectedMassOptions options;
  options.singular_relative_tolerance = 1.0;
  CHECK_THAT(MessageOf([&] {
               covopt::robot::ReflectedMass(chain, q, Eigen::Vector3d::Zero(), {}, options);
             }),
             Contains("singular_relative_tolerance must be in [0, 1)"));
}

TEST_CASE("a joint that moves no mass makes M singular and is reported, not divided by") {
  const char* urdf = R"(<robot name="massless">
    <link name="base"/>
    <joint name="j" type="continuous"><parent link="base"/><child link="tip"/><axis xyz="0 0 1"/></joint>
    <link name="tip"/>
  </robot>)";
  const auto chain = KinematicChain::FromUrdfString(urdf, {"", "tip"}, "massless.urdf");
  CHECK_THAT(MessageOf([&] {
               covopt::robot::ReflectedMass(chain, Eigen::VectorXd::Zero(1), Eigen::Vector3d(1, 0, 0), {});
             }),
             Contains("massless.urdf") && Contains("not positive definite"));
  // ChainSampleKinematics::Update (link_kinematics.hpp) likewise.
  covopt::robot::ChainSampleKinematics kin(chain);
  CHECK_THAT(MessageOf([&] { kin.Update(Eigen::VectorXd::Zero(1), Eigen::VectorXd::Ones(1)); }),
             Contains("massless.urdf") && Contains("not positive definite"));
}
