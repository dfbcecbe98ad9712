// ChainSampleKinematics (link_kinematics.hpp): every link's frame, twist and Jacobian at one
// sample, and any point's position, velocity and reflected mass, on the shipped FR3 and UR5e.
// Checked against other routes: the velocity against finite differences of the positions
// (Update at q ± h q̇), positions and Jacobians against KDL's forward kinematics and Jacobian
// solver on the chain cut at the link (ContactPoint, ContactJacobian), the reflected mass
// against ReflectedMass on the tip link and against J M⁻¹ Jᵀ formed densely from
// JointSpaceInertia and ContactJacobian elsewhere; and points on several links against the
// independent numpy reference (python/tests/robot_reference.py) through
// tests/robot/data/link_points_numpy.txt, which python/tests/test_robot_crosscheck.py checks
// is still what that reference gives.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <new>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <catch2/catch.hpp>

#include "covopt/robot.hpp"
#include "robot_test_support.hpp"

// Counts heap allocations, to show that Point allocates nothing. (GCC takes the replacement
// operator delete's free() of operator new's pointer for a mismatch; both are malloc/free here.)
namespace {
std::atomic<std::size_t> g_allocations{0};
}  // namespace
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

namespace {

using covopt::robot::ChainSampleKinematics;
using covopt::robot::ChainSpec;
using covopt::robot::KinematicChain;
using covopt::robot::PointMotion;
using covopt::robot::testing::MessageOf;
using Catch::Matchers::Contains;

const std::string kModels = COVOPT_ROBOT_MODELS_DIR;
const std::string kFr3 = kModels + "/franka_fr3.urdf";
const std::string kUr5e = kModels + "/ur5e.urdf";

struct Robot {
  std::string urdf;
  std::string tip;
};
const std::vector<Robot>& Robots() {
  static const std::vector<Robot> robots = {{kFr3, "fr3_link8"}, {kUr5e, "tool0"}};
  return robots;
}

/// A random q inside the URDF's limits (0.05 rad inside) and q̇ within half the velocity limits.
void RandomSample(const KinematicChain& chain, std::mt19937& random, Eigen::VectorXd& q, Eigen::VectorXd& qd) {
  q.resize(static_cast<Eigen::Index>(chain.joint_count()));
  qd.resize(q.size());
  Eigen::Index i = 0;
  for (const auto& joint : chain.joints()) {
    if (joint.type == covopt::robot::JointType::kFixed) continue;
    const double lower = joint.limits.has_position ? std::max(joint.limits.lower, -3.0) + 0.05 : -3.0;
    const double upper = joint.limits.has_position ? std::min(joint.limits.upper, 3.0) - 0.05 : 3.0;
    q[i] = std::uniform_real_distribution<double>(lower, upper)(random);
    const double speed = joint.limits.has_velocity ? 0.5 * joint.limits.velocity : 1.0;
    qd[i] = std::uniform_real_distribution<double>(-speed, speed)(random);
    ++i;
  }
}

/// The middle of every joint's position range.
Eigen::VectorXd MidRange(const KinematicChain& chain) {
  Eigen::VectorXd q(static_cast<Eigen::Index>(chain.joint_count()));
  Eigen::Index i = 0;
  for (const auto& joint : chain.joints()) {
    if (joint.type != covopt::robot::JointType::kFixed) q[i++] = 0.5 * (joint.limits.lower + joint.limits.upper);
  }
  return q;
}

/// A few points in a link's frame, up to 0.15 m off its origin.
std::vector<Eigen::Vector3d> SomePoints() {
  return {Eigen::Vector3d::Zero(), {0.1, 0.0, 0.0}, {0.0, -0.08, 0.05}, {0.03, 0.12, -0.1}};
}

}  // namespace

TEST_CASE("link kinematics: links, their indices and the joints that move them") {
  for (const Robot& robot : Robots()) {
    const auto chain = KinematicChain::FromUrdfFile(robot.urdf, {"", robot.tip});
    const ChainSampleKinematics kin(chain);
    // One link per chain joint (fixed ones too), named by the joints' child links.
    REQUIRE(kin.link_names().size() == chain.joints().size());
    std::size_t movable = 0;
    for (std::size_t i = 0; i < chain.joints().size(); ++i) {
      const auto& joint = chain.joints()[i];
      if (joint.type != covopt::robot::JointType::kFixed) ++movable;
      CHECK(kin.link_names()[i] == joint.child_link);
      CHECK(kin.LinkIndex(joint.child_link) == i);
      CHECK(kin.JointsMovingLink(i) == movable);
    }
    CHECK(kin.JointsMovingLink(kin.link_names().size() - 1) == chain.joint_count());
    CHECK_FALSE(kin.LinkIndex(chain.base_link()).has_value());  // the base is not a moving link
    CHECK_FALSE(kin.LinkIndex("no_such_link").has_value());
    CHECK_THAT(MessageOf([&] { kin.JointsMovingLink(kin.link_names().size()); }),
               Contains("link index " + std::to_string(kin.link_names().size())));
  }
}

TEST_CASE("link kinematics: positions and Jacobians agree with KDL on the chain cut at each link") {
  std::mt19937 random(25);
  for (const Robot& robot : Robots()) {
    const auto chain = KinematicChain::FromUrdfFile(robot.urdf, {"", robot.tip});
    ChainSampleKinematics kin(chain);
    Eigen::VectorXd q, qd;
    for (int trial = 0; trial < 5; ++trial) {
      RandomSample(chain, random, q, qd);
      kin.Update(q, qd);
      for (std::size_t link = 0; link < kin.link_names().size(); ++link) {
        const std::size_t k = kin.JointsMovingLink(link);
        if (k == 0) continue;  // a chain cut there would have no movable joint
        const auto cut = KinematicChain::FromUrdfFile(robot.urdf, {"", kin.link_names()[link]});
        REQUIRE(cut.joint_count() == k);
        const Eigen::VectorXd q_cut = q.head(static_cast<Eigen::Index>(k));
        for (const Eigen::Vector3d& p : SomePoints()) {
          const PointMotion m = kin.Point(link, p);
          const Eigen::Vector3d position = covopt::robot::ContactPoint(cut, q_cut, p);
          CHECK((m.position_m - position).norm() < 1e-13);
          const auto jacobian = covopt::robot::ContactJacobian(cut, q_cut, p);
          const Eigen::Vector3d v = jacobian * qd.head(static_cast<Eigen::Index>(k));
          CHECK((m.velocity_m_per_s - v).norm() < 1e-12 * std::max(1.0, v.norm()));
          CHECK(m.speed_m_per_s == Approx(v.norm()).epsilon(1e-12));
        }
      }
    }
  }
}

TEST_CASE("link kinematics: the velocity is the derivative of the position along q̇ (finite differences)") {
  std::mt19937 random(7);
  const double h = 1e-6;  // s: q ± h q̇
  for (const Robot& robot : Robots()) {
    const auto chain = KinematicChain::FromUrdfFile(robot.urdf, {"", robot.tip});
    ChainSampleKinematics kin(chain);
    ChainSampleKinematics ahead(chain);
    ChainSampleKinematics behind(chain);
    Eigen::VectorXd q, qd;
    for (int trial = 0; trial < 5; ++trial) {
      RandomSample(chain, random, q, qd);
      kin.Update(q, qd);
      ahead.Update(q + h * qd, qd);
      behind.Update(q - h * qd, qd);
      for (std::size_t link = 0; link < kin.link_names().size(); ++link) {
        for (const Eigen::Vector3d& p : SomePoints()) {
          const Eigen::Vector3d difference =
              (ahead.Point(link, p).position_m - behind.Point(link, p).position_m) / (2.0 * h);
          const PointMotion m = kin.Point(link, p);
          CHECK((m.velocity_m_per_s - difference).norm() < 1e-7);
          // The frame's own accessors agree with the point at the origin.
          CHECK((kin.LinkOrigin(link) + kin.LinkRotation(link) * p - m.position_m).norm() < 1e-15);
        }
      }
    }
  }
}

TEST_CASE("link kinematics: on the tip link the reflected mass is ReflectedMass's along the motion") {
  std::mt19937 random(11);
  for (const Robot& robot : Robots()) {
    const auto chain = KinematicChain::FromUrdfFile(robot.urdf, {"", robot.tip});
    ChainSampleKinematics kin(chain);
    const std::size_t tip = *kin.LinkIndex(robot.tip);
    Eigen::VectorXd q, qd;
    for (int trial = 0; trial < 5; ++trial) {
      RandomSample(chain, random, q, qd);
      kin.Update(q, qd);
      for (const Eigen::Vector3d& p : SomePoints()) {
        const PointMotion m = kin.Point(tip, p);
        REQUIRE(m.moving);
        CHECK(m.direction.norm() == Approx(1.0).epsilon(1e-15));
        const auto reference = covopt::robot::ReflectedMass(chain, q, p, m.direction);
        REQUIRE(reference.reflected_mass_kg.has_value());
        CHECK(m.reflected_mass_kg == Approx(*reference.reflected_mass_kg).epsilon(1e-12));
        CHECK((m.position_m - reference.contact_point_m).norm() < 1e-13);
      }
    }
  }
}

TEST_CASE("link kinematics: on every link the reflected mass is 1/(uᵀ J M⁻¹ Jᵀ u), J zero beyond the link") {
  std::mt19937 random(3);
  for (const Robot& robot : Robots()) {
    const auto chain = KinematicChain::FromUrdfFile(robot.urdf, {"", robot.tip});
    ChainSampleKinematics kin(chain);
    Eigen::VectorXd q, qd;
    const auto n = static_cast<Eigen::Index>(chain.joint_count());
    std::size_t checked = 0;
    for (int trial = 0; trial < 3; ++trial) {
      RandomSample(chain, random, q, qd);
      kin.Update(q, qd);
      const Eigen::MatrixXd mass = covopt::robot::JointSpaceInertia(chain, q);
      for (std::size_t link = 0; link < kin.link_names().size(); ++link) {
        const auto k = static_cast<Eigen::Index>(kin.JointsMovingLink(link));
        if (k == 0) continue;
        const auto cut = KinematicChain::FromUrdfFile(robot.urdf, {"", kin.link_names()[link]});
        for (const Eigen::Vector3d& p : SomePoints()) {
          Eigen::MatrixXd jacobian = Eigen::MatrixXd::Zero(3, n);
          jacobian.leftCols(k) = covopt::robot::ContactJacobian(cut, q.head(k), p);
          const PointMotion m = kin.Point(link, p);
          if (!m.moving) continue;  // on the axis of the only joint that moves the link
          ++checked;
          const Eigen::Matrix3d inverse = jacobian * mass.ldlt().solve(jacobian.transpose());
          CHECK(m.reflected_mass_kg == Approx(1.0 / m.direction.dot(inverse * m.direction)).epsilon(1e-10));
          CHECK(std::isfinite(m.reflected_mass_kg));
        }
      }
    }
    CHECK(checked > 3 * 4 * (chain.joint_count() - 1));
  }
}

TEST_CASE("link kinematics: a link no joint moves, and a sample at rest, have zero speed and no mass") {
  for (const Robot& robot : Robots()) {
    const auto chain = KinematicChain::FromUrdfFile(robot.urdf, {"", robot.tip});
    ChainSampleKinematics kin(chain);
    const Eigen::VectorXd q = MidRange(chain);
    const Eigen::VectorXd qd = Eigen::VectorXd::Constant(q.size(), 0.5);
    kin.Update(q, qd);
    REQUIRE(kin.JointsMovingLink(0) == 0);  // fr3_link0 / base_link_inertia: fixed to the base
    const PointMotion still = kin.Point(0, Eigen::Vector3d(0.1, 0.2, 0.3));
    CHECK(still.velocity_m_per_s.isZero(0.0));
    CHECK_FALSE(still.moving);
    CHECK(still.direction.isZero(0.0));
    CHECK(still.reflected_mass_kg == 0.0);
    // Its frame is the fixed joint's origin: where the cut-off model says.
    CHECK((still.position_m - (kin.LinkOrigin(0) + kin.LinkRotation(0) * Eigen::Vector3d(0.1, 0.2, 0.3))).norm() <
          1e-15);

    kin.Update(q, Eigen::VectorXd::Zero(q.size()));
    const PointMotion rest = kin.Point(kin.link_names().size() - 1, Eigen::Vector3d(0.0, 0.0, 0.1));
    CHECK_FALSE(rest.moving);
    CHECK(rest.speed_m_per_s == 0.0);
    CHECK(rest.reflected_mass_kg == 0.0);
  }
}

TEST_CASE("link kinematics: a point on the first moving link turns about joint 1 alone") {
  // FR3 joint 1 turns about the base z axis at the origin: v = q̇1 ẑ × p, |v| = q̇1 ρ.
  const auto chain = KinematicChain::FromUrdfFile(kFr3, {"", "fr3_link8"});
  ChainSampleKinematics kin(chain);
  const Eigen::VectorXd q = MidRange(chain);
  Eigen::VectorXd qd = Eigen::VectorXd::Zero(7);
  qd[0] = 0.8;
  qd[3] = 1.0;  // moves only links after joint 4
  kin.Update(q, qd);
  const std::size_t link1 = *kin.LinkIndex("fr3_link1");
  REQUIRE(kin.JointsMovingLink(link1) == 1);
  const PointMotion m = kin.Point(link1, Eigen::Vector3d(0.1, -0.2, 0.05));
  const Eigen::Vector3d expected = 0.8 * Eigen::Vector3d::UnitZ().cross(m.position_m);
  CHECK((m.velocity_m_per_s - expected).norm() < 1e-15);
  // J_v = (ẑ × p) e₁ᵀ, so uᵀΛ⁻¹u = (M⁻¹)₁₁ ρ² along the motion: the other joints are free
  // (not M₁₁/ρ², the mass with them locked, which is larger).
  const double rho2 = m.position_m.head<2>().squaredNorm();
  const Eigen::MatrixXd mass = covopt::robot::JointSpaceInertia(chain, q);
  CHECK(m.reflected_mass_kg == Approx(1.0 / (mass.inverse()(0, 0) * rho2)).epsilon(1e-12));
  CHECK(m.reflected_mass_kg < mass(0, 0) / rho2);
}

TEST_CASE("link kinematics: Point allocates nothing") {
  const auto chain = KinematicChain::FromUrdfFile(kFr3, {"", "fr3_link8"});
  ChainSampleKinematics kin(chain);
  Eigen::VectorXd q(7);
  q << 0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785;
  const Eigen::VectorXd qd = Eigen::VectorXd::Constant(7, 0.3);
  kin.Update(q, qd);
  double total = 0.0;
  const std::size_t before = g_allocations.load();
  for (std::size_t link = 0; link < kin.link_names().size(); ++link) {
    total += kin.Point(link, Eigen::Vector3d(0.02, 0.03, 0.04)).reflected_mass_kg;
  }
  const std::size_t after = g_allocations.load();
  CHECK(after == before);
  CHECK(total > 0.0);
}

TEST_CASE("link kinematics: Update refuses a bad sample as ContactMotion does, naming where and the joint") {
  const auto chain = KinematicChain::FromUrdfFile(kFr3, {"", "fr3_link8"});
  ChainSampleKinematics kin(chain);
  Eigen::VectorXd q(7);
  q << 0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785;
  const Eigen::VectorXd qd = Eigen::VectorXd::Zero(7);
  CHECK_THAT(MessageOf([&] { kin.Update(q.head(6), qd, "pick.csv:12"); }),
             Contains("pick.csv:12 positions") && Contains("6 values given") && Contains("fr3_joint7"));
  CHECK_THAT(MessageOf([&] { kin.Update(q, qd.head(3), "pick.csv:12"); }),
             Contains("pick.csv:12 velocities") && Contains("3 values given"));
  Eigen::VectorXd bad = q;
  bad[2] = std::nan("");
  CHECK_THAT(MessageOf([&] { kin.Update(bad, qd, "pick.csv:12"); }),
             Contains("pick.csv:12 positions: joint 3 (fr3_joint3)") && Contains("finite"));
  bad = q;
  bad[3] = 0.5;  // fr3_joint4 is [-3.0718, -0.0698] rad
  CHECK_THAT(MessageOf([&] { kin.Update(bad, qd, "pick.csv:12"); }),
             Contains("pick.csv:12, q4 (joint 'fr3_joint4')") && Contains("URDF's limits"));
  bad = q;
  bad[0] = 90.0;  // degrees
  CHECK_THAT(MessageOf([&] { kin.Update(bad, qd, "pick.csv:12"); }),
             Contains("q1 (joint 'fr3_joint1')") && Contains("degrees?"));
  Eigen::VectorXd fast = qd;
  fast[5] = 5.0;  // over fr3_joint6's velocity limit
  CHECK_THAT(MessageOf([&] { kin.Update(q, fast, "pick.csv:12"); }),
             Contains("pick.csv:12, qd6 (joint 'fr3_joint6')") && Contains("velocity limit"));
  fast[5] = 2e3;
  CHECK_THAT(MessageOf([&] { kin.Update(q, fast, "pick.csv:12"); }), Contains("qd6") && Contains("1000"));

  // Without the URDF's limits the same sample passes; the plausible ranges still hold.
  covopt::robot::ContactMotionOptions lax;
  lax.reflected_mass.check_joint_limits = false;
  ChainSampleKinematics lax_kin(chain, lax);
  bad = q;
  bad[3] = 0.5;
  CHECK_NOTHROW(lax_kin.Update(bad, qd));
  bad[0] = 90.0;
  CHECK_THAT(MessageOf([&] { lax_kin.Update(bad, qd); }), Contains("sample, q1 (joint 'fr3_joint1')"));

  // ContactMotion refuses the same sample with the same rule.
  covopt::robot::JointTrajectory trajectory;
  trajectory.time_s = {0.0};
  bad = q;
  bad[3] = 0.5;
  trajectory.positions = {bad};
  trajectory.velocities = {qd};
  CHECK_THAT(MessageOf([&] { covopt::robot::ContactMotion(chain, trajectory, Eigen::Vector3d::Zero()); }),
             Contains("joint 'fr3_joint4'") && Contains("URDF's limits"));
}

TEST_CASE("link kinematics: bad options and a massless joint are refused") {
  const auto chain = KinematicChain::FromUrdfFile(kFr3, {"", "fr3_link8"});
  covopt::robot::ContactMotionOptions options;
  options.rest_speed_m_per_s = -1.0;
  CHECK_THAT(MessageOf([&] { ChainSampleKinematics kin(chain, options); }), Contains("rest_speed_m_per_s"));
  options = {};
  options.reflected_mass.singular_relative_tolerance = 1.0;
  CHECK_THAT(MessageOf([&] { ChainSampleKinematics kin(chain, options); }), Contains("singular_relative_tolerance"));

  const char* urdf = R"(<robot name="massless">
    <link name="base"/>
    <joint name="j" type="continuous"><parent link="base"/><child link="tip"/><axis xyz="0 0 1"/></joint>
    <link name="tip"/>
  </robot>)";
  const auto massless = KinematicChain::FromUrdfString(urdf, {"", "tip"}, "massless.urdf");
  ChainSampleKinematics kin(massless);
  CHECK_THAT(MessageOf([&] { kin.Update(Eigen::VectorXd::Zero(1), Eigen::VectorXd::Ones(1)); }),
             Contains("massless.urdf") && Contains("not positive definite"));
}

TEST_CASE("link kinematics: points on several links of FR3 and UR5e agree with the numpy reference") {
  // tests/robot/data/link_points_numpy.txt: scripts/make-link-points-reference.py, from
  // python/tests/robot_reference.py (no KDL, no covopt).
  std::ifstream in(std::string(COVOPT_ROBOT_TEST_DATA_DIR) + "/link_points_numpy.txt");
  REQUIRE(in);
  std::string line;
  std::size_t rows = 0;
  std::size_t moving = 0;
  std::vector<std::string> links_seen;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    std::string urdf, tip, link;
    std::size_t n = 0;
    row >> urdf >> tip >> link >> n;
    Eigen::VectorXd q(static_cast<Eigen::Index>(n)), qd(static_cast<Eigen::Index>(n));
    for (auto& x : q) row >> x;
    for (auto& x : qd) row >> x;
    Eigen::Vector3d point, position, velocity;
    double mass = 0.0;
    row >> point.x() >> point.y() >> point.z() >> position.x() >> position.y() >> position.z() >> velocity.x() >>
        velocity.y() >> velocity.z() >> mass;
    REQUIRE(row);
    const auto chain = KinematicChain::FromUrdfFile(kModels + "/" + urdf, {"", tip});
    ChainSampleKinematics kin(chain);
    kin.Update(q, qd);
    const auto index = kin.LinkIndex(link);
    REQUIRE(index.has_value());
    const PointMotion m = kin.Point(*index, point);
    INFO(urdf << " " << link << " point " << point.transpose());
    CHECK((m.position_m - position).norm() < 1e-12);
    CHECK((m.velocity_m_per_s - velocity).norm() < 1e-12 * std::max(1.0, velocity.norm()));
    if (mass == 0.0) {
      CHECK_FALSE(m.moving);
      CHECK(m.reflected_mass_kg == 0.0);
    } else {
      CHECK(m.reflected_mass_kg == Approx(mass).epsilon(1e-9));
      ++moving;
    }
    if (std::find(links_seen.begin(), links_seen.end(), link) == links_seen.end()) links_seen.push_back(link);
    ++rows;
  }
  CHECK(rows == 99);
  CHECK(moving > 70);
  CHECK(links_seen.size() == 11);
}
