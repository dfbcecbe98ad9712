// How Orocos KDL 1.5.1 treats a joint's rotor inertia (KDL::Joint's `inertia` argument), and
// what covopt's URDF conversion sets: URDF has no rotor-inertia field, so the conversion
// gives every joint 0 and M(q) is the links' rigid-body inertia alone (robot/README.md).
#include <cmath>

#include <catch2/catch.hpp>
#include <kdl/chain.hpp>
#include <kdl/chaindynparam.hpp>
#include <kdl/jntspaceinertiamatrix.hpp>

#include "covopt/robot.hpp"

namespace {

/// One joint about z carrying 1 kg at 1 m (Izz 0.1 kg m^2 about its centre of mass): the
/// link's inertia about the axis is 1.1 kg m^2.
double KdlMassOfOneJoint(double rotor_inertia_kg_m2) {
  KDL::Chain chain;
  chain.addSegment(KDL::Segment(
      "link", KDL::Joint("joint", KDL::Joint::RotZ, 1.0, 0.0, rotor_inertia_kg_m2),
      KDL::Frame::Identity(),
      KDL::RigidBodyInertia(1.0, KDL::Vector(1.0, 0.0, 0.0),
                            KDL::RotationalInertia(0.0, 0.0, 0.1))));
  KDL::ChainDynParam dynamics(chain, KDL::Vector::Zero());
  KDL::JntArray q(1);
  KDL::JntSpaceInertiaMatrix M(1);
  REQUIRE(dynamics.JntToMass(q, M) >= 0);
  return M(0, 0);
}

}  // namespace

TEST_CASE("KDL 1.5.1's JntToMass adds a joint's rotor inertia to M's diagonal") {
  CHECK(KdlMassOfOneJoint(0.0) == Approx(1.1).epsilon(1e-14));
  CHECK(KdlMassOfOneJoint(0.5) == Approx(1.6).epsilon(1e-14));
}

TEST_CASE("covopt's URDF conversion sets no rotor inertia: M is the links' inertia alone") {
  const char* urdf = R"(<robot name="one_joint">
    <link name="base"/>
    <joint name="joint" type="continuous"><parent link="base"/><child link="link"/>
      <axis xyz="0 0 1"/><dynamics damping="3.0" friction="1.0"/></joint>
    <link name="link"><inertial><origin xyz="1 0 0"/><mass value="1"/>
      <inertia ixx="0.05" ixy="0" ixz="0" iyy="0.05" iyz="0" izz="0.1"/></inertial></link>
  </robot>)";
  const auto chain = covopt::robot::KinematicChain::FromUrdfString(urdf, {"", "link"});
  const Eigen::MatrixXd M = covopt::robot::JointSpaceInertia(chain, Eigen::VectorXd::Zero(1));
  CHECK(M(0, 0) == Approx(1.1).epsilon(1e-14));
  // The reflected mass at the centre of mass across the arm is then I/r^2 = 1.1 kg.
  const auto result = covopt::robot::ReflectedMass(chain, Eigen::VectorXd::Zero(1),
                                                   Eigen::Vector3d(1, 0, 0), Eigen::Vector3d::UnitY());
  CHECK(*result.reflected_mass_kg == Approx(1.1).epsilon(1e-14));
}
