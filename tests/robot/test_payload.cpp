// A payload on the tip (KinematicChain::WithPayload) against closed forms on the planar test
// arm, the zero payload's exact reproduction of the bare chain, the refusal of non-physical
// payloads, and ISO/TS 15066's fallback m_R = M/2 + m_L. The 3-D arm's payload against the
// independent sum over its links is in test_independent_inertia.cpp.
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include "covopt/robot.hpp"
#include "robot_test_support.hpp"

namespace {

using covopt::robot::ChainSpec;
using covopt::robot::KinematicChain;
using covopt::robot::Payload;
using covopt::robot::testing::kPlanar;
using covopt::robot::testing::MessageOf;

Payload PointMass(double mass_kg, const Eigen::Vector3d& com_m) {
  Payload payload;
  payload.mass_kg = mass_kg;
  payload.center_of_mass_m = com_m;
  return payload;
}

}  // namespace

TEST_CASE("a payload on a one-joint arm adds m_p + I_zz/r^2 to the tangential reflected mass") {
  // link1 -> link2: the elbow alone; link2 is 1.5 kg with its centre of mass at 0.4 m and
  // I_zz 0.05 kg m^2, so M = 0.05 + 1.5 * 0.4^2 = 0.29 kg m^2 and at r along the link the
  // mass across it is M / r^2.
  const auto bare = KinematicChain::FromUrdfFile(kPlanar, ChainSpec{"link1", "link2"});
  const Eigen::VectorXd q = Eigen::VectorXd::Constant(1, 0.3);
  const double r = 0.8;
  const Eigen::Vector3d point(r, 0.0, 0.0);
  const Eigen::Vector3d across(-std::sin(0.3), std::cos(0.3), 0.0);
  const double bare_mass = *covopt::robot::ReflectedMass(bare, q, point, across).reflected_mass_kg;
  CHECK(bare_mass == Approx(0.29 / (r * r)).epsilon(1e-12));

  SECTION("a point mass at the contact point adds its own mass") {
    const auto loaded = bare.WithPayload(PointMass(2.0, point));
    CHECK(*covopt::robot::ReflectedMass(loaded, q, point, across).reflected_mass_kg ==
          Approx(0.29 / (r * r) + 2.0).epsilon(1e-12));
    CHECK(loaded.payload().mass_kg == 2.0);
    CHECK(loaded.moving_mass_kg() == bare.moving_mass_kg());  // the robot's own M, without m_L
  }
  SECTION("a centre of mass off the tip axis and an inertia: M + m_p |c|^2 + I_zz") {
    Payload payload = PointMass(1.2, Eigen::Vector3d(0.1, 0.05, -0.3));
    payload.inertia_kg_m2 = Payload::InertiaFromSix(0.004, 0.005, 0.003, 0.0005, -0.0002, 0.0001);
    const auto loaded = bare.WithPayload(payload);
    // About the elbow's z axis the payload adds m_p (c_x^2 + c_y^2) + I_zz.
    const double M = 0.29 + 1.2 * (0.1 * 0.1 + 0.05 * 0.05) + 0.003;
    CHECK(covopt::robot::JointSpaceInertia(loaded, q)(0, 0) == Approx(M).epsilon(1e-12));
    CHECK(*covopt::robot::ReflectedMass(loaded, q, point, across).reflected_mass_kg ==
          Approx(M / (r * r)).epsilon(1e-12));
  }
}

TEST_CASE("a payload in a rotated tip frame: M(q) grows by the payload's own Jacobian sum") {
  // tool_rotated: 0.85 m along link 2, turned 90 deg about z and 30 deg about x. The payload's
  // share, written here from the closed-form kinematics (not KDL):
  //   M_p = m_p Jc' Jc + (R I R')_zz [1 1; 1 1],  Jc = [ez x (c - 0), ez x (c - p_elbow)].
  const auto bare = KinematicChain::FromUrdfFile(kPlanar, ChainSpec{"", "tool_rotated"});
  Payload payload = PointMass(3.0, Eigen::Vector3d(0.02, -0.04, 0.12));
  payload.inertia_kg_m2 = Payload::InertiaFromSix(0.02, 0.03, 0.015, 0.002, -0.004, 0.003);
  const auto loaded = bare.WithPayload(payload);
  const Eigen::Vector2d q(0.4, -1.1);
  const Eigen::Vector3d ez = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d elbow(std::cos(q[0]), std::sin(q[0]), 0.0);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(q[0] + q[1], ez).toRotationMatrix() *
                            Eigen::AngleAxisd(M_PI / 2, ez).toRotationMatrix() *
                            Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d tip = elbow + Eigen::AngleAxisd(q[0] + q[1], ez).toRotationMatrix() * Eigen::Vector3d(0.85, 0, 0);
  const Eigen::Vector3d com = tip + R * payload.center_of_mass_m;
  Eigen::Matrix<double, 3, 2> Jc;
  Jc.col(0) = ez.cross(com);
  Jc.col(1) = ez.cross(com - elbow);
  const double izz = (R * payload.inertia_kg_m2 * R.transpose())(2, 2);
  const Eigen::Matrix2d share = payload.mass_kg * Jc.transpose() * Jc + izz * Eigen::Matrix2d::Ones();
  const Eigen::MatrixXd expected = covopt::robot::JointSpaceInertia(bare, q) + share;
  const Eigen::MatrixXd got = covopt::robot::JointSpaceInertia(loaded, q);
  INFO("KDL\n" << got << "\nexpected\n" << expected);
  CHECK((got - expected).cwiseAbs().maxCoeff() < 1e-12 * expected.cwiseAbs().maxCoeff());
  // The reflected mass is 1/(u' J M^-1 J' u) with that M.
  const Eigen::Vector3d point(0.0, 0.01, 0.05);
  const Eigen::Vector3d u = Eigen::Vector3d(0.6, 0.8, 0.0);
  const Eigen::MatrixXd J = covopt::robot::ContactJacobian(bare, q, point);
  const double independent = 1.0 / (u.transpose() * J * expected.inverse() * J.transpose() * u)(0, 0);
  CHECK(*covopt::robot::ReflectedMass(loaded, q, point, u).reflected_mass_kg == Approx(independent).epsilon(1e-10));
}

TEST_CASE("no payload reproduces the bare chain exactly, and a payload is replaced, not stacked") {
  const auto bare = KinematicChain::FromUrdfFile(kPlanar, ChainSpec{"", "tool_rotated"});
  const Eigen::Vector2d q(0.7, 0.9);
  const Eigen::Vector3d point(0.01, 0.02, 0.03), u(1.0, 0.3, 0.0);
  const auto reference = covopt::robot::ReflectedMass(bare, q, point, u);
  const auto loaded = bare.WithPayload(PointMass(5.0, Eigen::Vector3d(0.0, 0.0, 0.2)));
  for (const KinematicChain& chain : {bare.WithPayload(Payload{}), loaded.WithPayload(Payload{})}) {
    const auto result = covopt::robot::ReflectedMass(chain, q, point, u);
    CHECK(*result.reflected_mass_kg == *reference.reflected_mass_kg);  // bit for bit
    CHECK(result.inverse_reflected_mass_per_kg == reference.inverse_reflected_mass_per_kg);
    CHECK(chain.payload().empty());
  }
  CHECK(*covopt::robot::ReflectedMass(loaded, q, point, u).reflected_mass_kg > *reference.reflected_mass_kg);
  const auto twice = loaded.WithPayload(PointMass(5.0, Eigen::Vector3d(0.0, 0.0, 0.2)));
  CHECK(covopt::robot::JointSpaceInertia(twice, q) == covopt::robot::JointSpaceInertia(loaded, q));
  // The chain it was made from is unchanged.
  CHECK(covopt::robot::ReflectedMass(bare, q, point, u).reflected_mass_kg == reference.reflected_mass_kg);
}

TEST_CASE("a non-physical payload is refused in one line naming the field") {
  const auto bare = KinematicChain::FromUrdfFile(kPlanar, ChainSpec{"", "tool"});
  const auto refuse = [&](const Payload& payload) { return MessageOf([&] { (void)bare.WithPayload(payload); }); };
  const Eigen::Vector3d com(0.0, 0.0, 0.1);
  Payload p = PointMass(1.0, com);
  p.inertia_kg_m2 = Eigen::Vector3d(1e-3, 1e-3, 3e-3).asDiagonal();  // 3 > 1 + 1
  CHECK_THAT(refuse(p), Catch::Contains("payload: inertia largest principal moment = 0.003") &&
                            Catch::Contains("triangle inequality"));
  p.inertia_kg_m2 = Eigen::Vector3d(1e-3, 1e-3, -1e-4).asDiagonal();
  CHECK_THAT(refuse(p), Catch::Contains("payload: inertia smallest principal moment") &&
                            Catch::Contains("positive semi-definite"));
  // Diagonal entries fine, but the off-diagonal makes it indefinite: 1 - 2 < 0.
  p.inertia_kg_m2 = Payload::InertiaFromSix(1e-3, 1e-3, 1e-3, 2e-3, 0.0, 0.0);
  CHECK_THAT(refuse(p), Catch::Contains("smallest principal moment"));
  p.inertia_kg_m2 = Eigen::Matrix3d::Identity() * 1e-3;
  p.inertia_kg_m2(0, 1) = 1e-4;  // ixy != iyx
  CHECK_THAT(refuse(p), Catch::Contains("payload: inertia ixy = 0.0001") && Catch::Contains("symmetric"));
  p.inertia_kg_m2 = Eigen::Matrix3d::Identity() * std::numeric_limits<double>::quiet_NaN();
  CHECK_THAT(refuse(p), Catch::Contains("payload: inertia ixx = nan"));
  CHECK_THAT(refuse(PointMass(-1.0, com)), Catch::Contains("payload: mass = -1 is not allowed (a mass in [0, 1e4] kg)"));
  CHECK_THAT(refuse(PointMass(2e4, com)), Catch::Contains("payload: mass = 20000"));
  CHECK_THAT(refuse(PointMass(std::numeric_limits<double>::infinity(), com)), Catch::Contains("payload: mass = inf"));
  CHECK_THAT(refuse(PointMass(1.0, Eigen::Vector3d(0.0, 0.0, 150.0))),  // 150 mm typed as m
             Catch::Contains("payload: centre of mass z = 150") && Catch::Contains("millimetres"));
  CHECK_THAT(refuse(PointMass(0.0, com)), Catch::Contains("without a mass"));
  // The message is one line.
  CHECK(refuse(PointMass(-1.0, com)).find('\n') == std::string::npos);
  // A point mass, and a thin rod (I_xx = 0, I_yy = I_zz: the triangle's edge), pass.
  p = PointMass(1.0, com);
  p.inertia_kg_m2 = Eigen::Vector3d(0.0, 0.02, 0.02).asDiagonal();
  CHECK_NOTHROW(bare.WithPayload(p));
  CHECK_NOTHROW(bare.WithPayload(PointMass(1.0, com)));
}

TEST_CASE("ISO/TS 15066's effective mass estimate is M/2 + m_L") {
  using covopt::robot::IsoEffectiveMassKg;
  CHECK(IsoEffectiveMassKg(30.0, 2.0) == 17.0);
  CHECK(IsoEffectiveMassKg(18.0, 0.0) == 9.0);
  CHECK(IsoEffectiveMassKg(1.0, 3.5) == 3.5 + 0.5);
  CHECK_THAT(MessageOf([] { (void)IsoEffectiveMassKg(0.0, 1.0); }), Catch::Contains("moving mass M = 0"));
  CHECK_THAT(MessageOf([] { (void)IsoEffectiveMassKg(20.0, -1.0); }), Catch::Contains("payload mass m_L = -1"));
  CHECK_THAT(MessageOf([] { (void)IsoEffectiveMassKg(std::nan(""), 1.0); }), Catch::Contains("moving mass M = nan"));
}
