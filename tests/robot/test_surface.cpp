// The robot's surface: URDF collision geometry (spheres, cylinders, boxes, capsules written as
// a cylinder with two spheres), surface files, the sampling, and the FR3 model's capsules.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "covopt/robot/kinematic_chain.hpp"
#include "covopt/robot/link_kinematics.hpp"
#include "covopt/robot/surface.hpp"
#include "robot_test_support.hpp"

namespace {

using covopt::robot::KinematicChain;
using covopt::robot::kFlat;
using covopt::robot::RobotSurface;
using covopt::robot::SampleShape;
using covopt::robot::SurfaceFromUrdfString;
using covopt::robot::SurfaceOptions;
using covopt::robot::SurfacePoint;
using covopt::robot::SurfaceShape;
using covopt::robot::SurfaceShapeType;
using covopt::robot::testing::MessageOf;

/// A one-joint arm whose link 'arm' carries `collisions` (XML).
std::string ArmUrdf(const std::string& collisions) {
  return R"(<robot name="t"><link name="base"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="arm"/><origin xyz="0 0 0.1"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="2"/></joint>
  <link name="arm"><inertial><mass value="1"/><origin xyz="0.2 0 0"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>)" +
         collisions + R"(</link></robot>)";
}

std::string Collision(const std::string& xyz, const std::string& rpy, const std::string& geometry) {
  return "<collision><origin xyz=\"" + xyz + "\" rpy=\"" + rpy + "\"/><geometry>" + geometry +
         "</geometry></collision>";
}

RobotSurface Surface(const std::string& urdf, SurfaceOptions options = {}) {
  const KinematicChain chain = KinematicChain::FromUrdfString(urdf, {"", "arm"});
  return SurfaceFromUrdfString(urdf, chain, options);
}

double DistanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double t = ab.squaredNorm() == 0.0 ? 0.0 : std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

std::filesystem::path WriteTemp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("covopt_surface_test_" + name);
  std::ofstream(path) << text;
  return path;
}

}  // namespace

TEST_CASE("a sphere's points lie on it, with its radius and outward normals, at the spacing", "[robot][surface]") {
  SurfaceShape sphere;
  sphere.type = SurfaceShapeType::kSphere;
  sphere.a_m = {0.1, -0.2, 0.3};
  sphere.radius_m = 0.05;
  const double s = 0.02;
  const std::vector<SurfacePoint> points = SampleShape(sphere, s);
  // Rings of latitude every ceil(pi r / s) = 8 intervals: 2 poles and 7 rings.
  std::size_t expected = 2;
  for (int k = 1; k < 8; ++k) {
    const double rho = 0.05 * std::sin(std::numbers::pi * k / 8.0);
    expected += std::max<std::size_t>(4, static_cast<std::size_t>(std::ceil(2.0 * std::numbers::pi * rho / s)));
  }
  CHECK(points.size() == expected);
  for (const SurfacePoint& p : points) {
    CHECK((p.position_m - sphere.a_m).norm() == Approx(0.05).epsilon(1e-12));
    CHECK((p.normal - (p.position_m - sphere.a_m) / 0.05).norm() < 1e-12);
    CHECK(p.radius_of_curvature_m == 0.05);
  }
}

TEST_CASE("a capsule is sampled along its axis and over its ends at the spacing", "[robot][surface]") {
  SurfaceShape capsule;
  capsule.type = SurfaceShapeType::kCapsule;
  capsule.a_m = {0, 0, 0};
  capsule.b_m = {0, 0, 0.1};
  capsule.radius_m = 0.05;
  const std::vector<SurfacePoint> points = SampleShape(capsule, 0.05);
  // Side: 3 stations (0, 0.05, 0.1 m) x ceil(2 pi 0.05 / 0.05) = 7 around; each end: the pole
  // and one ring at 45 degrees of ceil(2 pi 0.05 sin 45 / 0.05) = 5 points.
  CHECK(points.size() == 3 * 7 + 2 * (1 + 5));
  for (const SurfacePoint& p : points) {
    CHECK(DistanceToSegment(p.position_m, capsule.a_m, capsule.b_m) == Approx(0.05).epsilon(1e-12));
    CHECK(p.radius_of_curvature_m == 0.05);
    CHECK(p.normal.norm() == Approx(1.0).epsilon(1e-12));
  }
  SECTION("every point of the surface is within the spacing of a sample (Monte Carlo)") {
    for (const double s : {0.05, 0.013}) {
      const std::vector<SurfacePoint> dense = SampleShape(capsule, s);
      std::mt19937 random(7);
      std::normal_distribution<double> normal;
      std::uniform_real_distribution<double> along(-0.05, 0.15);
      double worst = 0.0;
      for (int trial = 0; trial < 2000; ++trial) {
        Eigen::Vector3d direction(normal(random), normal(random), normal(random));
        const double z = along(random);
        direction.normalize();
        Eigen::Vector3d q;
        if (z < 0.0 || z > 0.1) {
          q = Eigen::Vector3d(0, 0, z < 0.0 ? 0.0 : 0.1) + 0.05 * (direction.z() * (z < 0.0 ? -1 : 1) > 0 ? direction : Eigen::Vector3d(direction.x(), direction.y(), -direction.z()));
        } else {
          q = Eigen::Vector3d(0, 0, z) + 0.05 * Eigen::Vector3d(direction.x(), direction.y(), 0).normalized();
        }
        double nearest = std::numeric_limits<double>::infinity();
        for (const SurfacePoint& p : dense) nearest = std::min(nearest, (p.position_m - q).norm());
        worst = std::max(worst, nearest);
      }
      CHECK(worst <= s);
    }
  }
}

TEST_CASE("a box's flat faces are kFlat and its rounded edges and corners have the edge radius", "[robot][surface]") {
  SurfaceShape box;
  box.type = SurfaceShapeType::kBox;
  box.pose.translation() = Eigen::Vector3d(0.1, 0.0, 0.0);
  box.pose.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  box.size_m = {0.2, 0.1, 0.06};
  box.edge_radius_m = 0.01;
  const std::vector<SurfacePoint> points = SampleShape(box, 0.02);
  const Eigen::Vector3d inner = box.size_m / 2.0 - Eigen::Vector3d::Constant(0.01);
  std::size_t flat = 0;
  std::size_t rounded = 0;
  for (const SurfacePoint& p : points) {
    const Eigen::Vector3d local = box.pose.inverse() * p.position_m;
    const Eigen::Vector3d clamped = local.cwiseMax(-inner).cwiseMin(inner);
    // Every point of the rounded box is the edge radius away from the inner box.
    CHECK((local - clamped).norm() == Approx(0.01).epsilon(1e-9));
    const bool on_face = ((local - clamped).array().abs() > 1e-12).count() == 1;
    if (on_face) {
      CHECK(p.radius_of_curvature_m == kFlat);
      ++flat;
    } else {
      CHECK(p.radius_of_curvature_m == 0.01);
      ++rounded;
    }
    CHECK((box.pose.linear().transpose() * p.normal - (local - clamped) / 0.01).norm() < 1e-9);
  }
  // Faces: cell midpoints, ceil(2c/s) per side: x 0.18 -> 9, y 0.08 -> 4, z 0.04 -> 2.
  CHECK(flat == 2 * (4 * 2 + 2 * 9 + 9 * 4));
  // Edges: one arc point (ceil(pi/2 0.01 / 0.02) = 1) at stations ceil(2c/s)+1 = 10, 5, 3;
  // corners 8.
  CHECK(rounded == 4 * (10 + 5 + 3) + 8);
}

TEST_CASE("URDF spheres, cylinders and boxes are read in the link frame", "[robot][surface]") {
  SurfaceOptions options;
  options.box_edge_radius_m = 0.005;
  options.spacing_m = 0.05;
  const RobotSurface surface =
      Surface(ArmUrdf(Collision("0.1 0 0", "0 0 0", "<sphere radius=\"0.04\"/>") +
                      Collision("0.2 0 0", "0 1.570796326794897 0", "<cylinder radius=\"0.03\" length=\"0.2\"/>") +
                      Collision("0 0 0.1", "0 0 0", "<box size=\"0.1 0.04 0.02\"/>")),
              options);
  REQUIRE(surface.links.size() == 1);
  const auto& shapes = surface.links[0].shapes;
  REQUIRE(shapes.size() == 3);
  CHECK(shapes[0].type == SurfaceShapeType::kSphere);
  CHECK((shapes[0].a_m - Eigen::Vector3d(0.1, 0, 0)).norm() < 1e-15);
  CHECK(shapes[0].radius_m == 0.04);
  CHECK(shapes[1].type == SurfaceShapeType::kCylinder);  // its end spheres are missing
  CHECK((shapes[1].a_m - Eigen::Vector3d(0.1, 0, 0)).norm() < 1e-12);  // pitch pi/2: z -> x
  CHECK((shapes[1].b_m - Eigen::Vector3d(0.3, 0, 0)).norm() < 1e-12);
  CHECK(shapes[2].type == SurfaceShapeType::kBox);
  CHECK(shapes[2].edge_radius_m == 0.005);
  std::size_t total = 0;
  for (std::size_t i = 0; i < shapes.size(); ++i) total += SampleShape(shapes[i], 0.05).size();
  CHECK(surface.links[0].points.size() == total);
  CHECK(surface.point_count() == total);
  // A cylinder's end discs are flat; its side has its radius.
  bool flat_seen = false;
  for (const SurfacePoint& p : surface.links[0].points) {
    if (p.shape_index == 1 && p.radius_of_curvature_m == kFlat) flat_seen = true;
  }
  CHECK(flat_seen);
}

TEST_CASE("a cylinder with a sphere of its radius on each end is one capsule", "[robot][surface]") {
  const std::string cylinder = Collision("0 0 0.2", "1.570796326794897 0 0", "<cylinder radius=\"0.05\" length=\"0.3\"/>");
  // rpy roll pi/2 turns z onto -y: the ends are (0, -0.15, 0.2) and (0, 0.15, 0.2).
  const std::string end1 = Collision("0 0.15 0.2", "0 0 0", "<sphere radius=\"0.05\"/>");
  const std::string end2 = Collision("0 -0.15 0.2", "0 0 0", "<sphere radius=\"0.05\"/>");
  SECTION("detected, whatever the order") {
    for (const std::string& xml : {cylinder + end1 + end2, end2 + cylinder + end1}) {
      const RobotSurface surface = Surface(ArmUrdf(xml));
      REQUIRE(surface.links[0].shapes.size() == 1);
      const SurfaceShape& capsule = surface.links[0].shapes[0];
      CHECK(capsule.type == SurfaceShapeType::kCapsule);
      CHECK(capsule.radius_m == 0.05);
      CHECK(std::abs((capsule.b_m - capsule.a_m).norm() - 0.3) < 1e-12);
      for (const SurfacePoint& p : surface.links[0].points) {
        CHECK(DistanceToSegment(p.position_m, {0, -0.15, 0.2}, {0, 0.15, 0.2}) == Approx(0.05).epsilon(1e-9));
      }
    }
  }
  SECTION("not when a sphere's radius or place differs") {
    const std::string smaller = Collision("0 0.15 0.2", "0 0 0", "<sphere radius=\"0.049\"/>");
    const std::string off = Collision("0 0.151 0.2", "0 0 0", "<sphere radius=\"0.05\"/>");
    for (const std::string& xml : {cylinder + smaller + end2, cylinder + off + end2, cylinder + end2}) {
      const RobotSurface surface = Surface(ArmUrdf(xml));
      std::size_t capsules = 0;
      for (const SurfaceShape& shape : surface.links[0].shapes) capsules += shape.type == SurfaceShapeType::kCapsule;
      CHECK(capsules == 0);
      CHECK(surface.links[0].shapes[0].type == SurfaceShapeType::kCylinder);
    }
  }
}

TEST_CASE("bad collision geometry is refused in one line", "[robot][surface]") {
  const auto message = [](const std::string& xml, SurfaceOptions options = {}) {
    return MessageOf([&] { Surface(ArmUrdf(xml), options); });
  };
  CHECK_THAT(message(Collision("0 0 0", "0 0 0", "<mesh filename=\"package://x/arm.stl\"/>")),
             Catch::Contains("link 'arm' has mesh collision geometry") && Catch::Contains("surface file"));
  CHECK_THAT(message(Collision("0 0 0", "0 0 0", "<box size=\"0.1 0.1 0.1\"/>")),
             Catch::Contains("<box> needs an edge radius"));
  SurfaceOptions too_round;
  too_round.box_edge_radius_m = 0.06;
  CHECK_THAT(message(Collision("0 0 0", "0 0 0", "<box size=\"0.1 0.1 0.1\"/>"), too_round),
             Catch::Contains("box edge radius = 0.06 m is not allowed"));
  too_round.box_edge_radius_m = 0.0;
  CHECK_THAT(message(Collision("0 0 0", "0 0 0", "<box size=\"0.1 0.1 0.1\"/>"), too_round),
             Catch::Contains("box edge radius = 0 m is not allowed"));
  CHECK_THAT(message(Collision("0 0 0", "0 0 0", "<sphere radius=\"-0.01\"/>")),
             Catch::Contains("radius") && Catch::Contains("-0.01"));
  CHECK_THAT(message(Collision("0 0 0", "0 0 0", "<cylinder radius=\"0.01\" length=\"0\"/>")),
             Catch::Contains("length"));
  // Geometry of a type urdfdom does not know.
  CHECK_THAT(message(Collision("0 0 0", "0 0 0", "<capsule radius=\"0.01\" length=\"0.1\"/>")),
             Catch::Contains("malformed URDF"));
  for (const std::string& text : {message(Collision("0 0 0", "0 0 0", "<mesh filename=\"a.stl\"/>")),
                                  message(Collision("0 0 0", "0 0 0", "<capsule radius=\"0.01\" length=\"0.1\"/>"))}) {
    CHECK(text.find('\n') == std::string::npos);
  }
  SurfaceOptions spacing;
  spacing.spacing_m = 0.0;
  CHECK_THAT(message(Collision("0 0 0", "0 0 0", "<sphere radius=\"0.01\"/>"), spacing),
             Catch::Contains("surface spacing = 0 m is not allowed"));
}

TEST_CASE("a surface file gives a mesh link its segments and points", "[robot][surface]") {
  const std::string urdf = ArmUrdf(Collision("0 0 0", "0 0 0", "<mesh filename=\"a.stl\"/>"));
  SurfaceOptions options;
  options.surface_file = WriteTemp("ok.toml", R"(# test
[[link]]
name = "arm"
segments = [ { from_m = [0, 0, 0], to_m = [0.3, 0, 0], radius_m = 0.04 } ]
points = [ { at_m = [0.35, 0, 0], radius_m = 0.01 }, { at_m = [0.1, 0.05, 0], radius_m = "flat" } ]
)");
  const RobotSurface surface = Surface(urdf, options);
  REQUIRE(surface.links.size() == 1);
  const auto& link = surface.links[0];
  REQUIRE(link.shapes.size() == 3);
  CHECK(link.shapes[0].type == SurfaceShapeType::kCapsule);
  CHECK(link.shapes[1].type == SurfaceShapeType::kPoint);
  CHECK(link.points.size() == SampleShape(link.shapes[0], 0.05).size() + 2);
  CHECK(link.points[link.points.size() - 2].radius_of_curvature_m == 0.01);
  CHECK(link.points.back().radius_of_curvature_m == kFlat);
  CHECK(link.points.back().normal.isZero());
}

TEST_CASE("surface file errors name the file, the place and the value", "[robot][surface]") {
  const std::string urdf = ArmUrdf(Collision("0 0 0", "0 0 0", "<mesh filename=\"a.stl\"/>"));
  const auto message = [&](const std::string& name, const std::string& toml) {
    SurfaceOptions options;
    options.surface_file = WriteTemp(name, toml);
    return MessageOf([&] { Surface(urdf, options); });
  };
  CHECK_THAT(message("other.toml", "[[link]]\nname = \"base\"\npoints = [ { at_m = [0,0,0], radius_m = 0.1 } ]\n"),
             Catch::Contains("link 'base' is not a moving link of the chain base -> arm (its links: arm)"));
  CHECK_THAT(message("missing.toml", "[[link]]\nname = \"wrist\"\npoints = [ { at_m = [0,0,0], radius_m = 0.1 } ]\n"),
             Catch::Contains("link 'wrist' is not a moving link"));
  CHECK_THAT(message("zero.toml", "[[link]]\nname = \"arm\"\nsegments = [ { from_m = [0,0,0], to_m = [1,0,0], radius_m = 0 } ]\n"),
             Catch::Contains("zero.toml:3:") && Catch::Contains("radius_m = 0 m is not allowed"));
  CHECK_THAT(message("negative.toml", "[[link]]\nname = \"arm\"\npoints = [ { at_m = [0,0,0], radius_m = -1 } ]\n"),
             Catch::Contains("radius_m = -1 m is not allowed"));
  CHECK_THAT(message("key.toml", "[[link]]\nname = \"arm\"\nsegment = [ { from_m = [0,0,0], to_m = [1,0,0], radius_m = 1 } ]\n"),
             Catch::Contains("unknown key 'segment'"));
  CHECK_THAT(message("twice.toml", "[[link]]\nname = \"arm\"\npoints = [ { at_m = [0,0,0], radius_m = 1 } ]\n"
                                   "[[link]]\nname = \"arm\"\npoints = [ { at_m = [0,0,0], radius_m = 1 } ]\n"),
             Catch::Contains("'arm' is given twice"));
  CHECK_THAT(message("empty.toml", "[[link]]\nname = \"arm\"\n"), Catch::Contains("give segments or points"));
  CHECK_THAT(message("coords.toml", "[[link]]\nname = \"arm\"\npoints = [ { at_m = [0,0], radius_m = 1 } ]\n"),
             Catch::Contains("at_m must be an array of 3 numbers"));
  CHECK_THAT(message("far.toml", "[[link]]\nname = \"arm\"\npoints = [ { at_m = [0,0,2000], radius_m = 1 } ]\n"),
             Catch::Contains("at_m component 2 = 2000 m is not allowed"));
  CHECK_THAT(message("bad.toml", "[[link]\n"), Catch::Contains("not a TOML surface file"));
  CHECK_THAT(MessageOf([&] {
               SurfaceOptions options;
               options.surface_file = "/nonexistent/surface.toml";
               Surface(urdf, options);
             }),
             Catch::Contains("no such surface file"));
}

TEST_CASE("every surface point of the FR3 model lies on its link's capsule from franka_description", "[robot][surface]") {
  const std::string path = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3.urdf";
  const KinematicChain chain = KinematicChain::FromUrdfFile(path, {"", "fr3_link8"});
  SurfaceOptions options;
  options.spacing_m = 0.03;
  const RobotSurface surface = covopt::robot::SurfaceFromUrdfFile(path, chain, options);
  // franka_description robots/common/franka_arm.xacro (b299b39), collision_capsule: centre,
  // direction, radius, length; link7's are in link7_sc, turned pi/4 about z.
  struct Capsule {
    const char* link;
    Eigen::Vector3d centre;
    Eigen::Vector3d direction;
    double radius;
    double length;
  };
  const double c = std::cos(std::numbers::pi / 4.0);
  const std::vector<Capsule> published{
      {"fr3_link0", {-0.075, 0, 0.06}, {1, 0, 0}, 0.06, 0.03},  {"fr3_link1", {0, 0, -0.1915}, {0, 0, 1}, 0.06, 0.283},
      {"fr3_link2", {0, 0, 0}, {0, 0, 1}, 0.06, 0.12},          {"fr3_link3", {0, 0, -0.145}, {0, 0, 1}, 0.06, 0.15},
      {"fr3_link4", {0, 0, 0}, {0, 0, 1}, 0.06, 0.12},          {"fr3_link5", {0, 0, -0.26}, {0, 0, 1}, 0.06, 0.10},
      {"fr3_link5", {0, 0.08, -0.13}, {0, 0, 1}, 0.025, 0.14},  {"fr3_link6", {0, 0, -0.03}, {0, 0, 1}, 0.05, 0.08},
      {"fr3_link7", {0, 0, 0.01}, {0, 0, 1}, 0.04, 0.14},       {"fr3_link7", {0.06 * c, 0.06 * c, 0.082}, {c, c, 0}, 0.03, 0.01}};
  REQUIRE(surface.links.size() == 8);  // fr3_link0 .. fr3_link7; fr3_link8 has no geometry
  REQUIRE(surface.warnings.size() == 1);
  CHECK_THAT(surface.warnings[0], Catch::Contains("fr3_link8"));
  std::size_t shapes = 0;
  for (const auto& link : surface.links) {
    for (const SurfaceShape& shape : link.shapes) {
      CHECK(shape.type == SurfaceShapeType::kCapsule);
      ++shapes;
    }
    REQUIRE(!link.points.empty());
    for (const SurfacePoint& p : link.points) {
      const SurfaceShape& shape = link.shapes.at(p.shape_index);
      bool on_a_published_capsule = false;
      for (const Capsule& capsule : published) {
        if (link.link != capsule.link || std::abs(capsule.radius - shape.radius_m) > 1e-12) continue;
        const Eigen::Vector3d half = 0.5 * capsule.length * capsule.direction;
        const double d = DistanceToSegment(p.position_m, capsule.centre - half, capsule.centre + half);
        if (std::abs(d - capsule.radius) < 1e-9) on_a_published_capsule = true;
      }
      CHECK(on_a_published_capsule);
      CHECK(p.radius_of_curvature_m == shape.radius_m);
    }
  }
  CHECK(shapes == published.size());
}

TEST_CASE("the UR5e surface file gives every moving link of the UR5e its capsules, on the URDF's joint axes", "[robot][surface]") {
  const std::string models = COVOPT_ROBOT_MODELS_DIR;
  const KinematicChain chain = KinematicChain::FromUrdfFile(models + "/ur5e.urdf", {"", "tool0"});
  // Without it the UR5e (no collision geometry) has no surface at all.
  const RobotSurface bare = covopt::robot::SurfaceFromUrdfFile(models + "/ur5e.urdf", chain);
  CHECK(bare.links.empty());
  CHECK(bare.warnings.size() == chain.joints().size());

  SurfaceOptions options;
  options.surface_file = models + "/ur5e_surface.toml";
  const RobotSurface surface = covopt::robot::SurfaceFromUrdfFile(models + "/ur5e.urdf", chain, options);
  const std::vector<std::string> meshed{"shoulder_link", "upper_arm_link", "forearm_link",
                                        "wrist_1_link",  "wrist_2_link",   "wrist_3_link"};
  REQUIRE(surface.links.size() == meshed.size());
  for (std::size_t i = 0; i < meshed.size(); ++i) {
    const auto& link = surface.links[i];
    CHECK(link.link == meshed[i]);
    CHECK_FALSE(link.points.empty());
    for (const SurfaceShape& shape : link.shapes) {
      CHECK(shape.type == SurfaceShapeType::kCapsule);
      CHECK(shape.radius_m > 0.03);
      CHECK(shape.radius_m < 0.1);
    }
    for (const SurfacePoint& p : link.points) {
      const SurfaceShape& shape = link.shapes.at(p.shape_index);
      CHECK(DistanceToSegment(p.position_m, shape.a_m, shape.b_m) == Approx(shape.radius_m).epsilon(1e-12));
    }
  }
  // The fixed links without a mesh (base_link_inertia, flange, tool0) are named, and only they.
  REQUIRE(surface.warnings.size() == 3);
  CHECK_THAT(surface.warnings[0], Catch::Contains("base_link_inertia"));
  CHECK_THAT(surface.warnings[1], Catch::Contains("'flange'"));
  CHECK_THAT(surface.warnings[2], Catch::Contains("'tool0'"));

  // Each joint housing's capsule lies on the joint's axis as the URDF places it: the link's
  // own joint (z through the origin) and, on the upper arm and forearm, the next joint's axis
  // (the next link's origin in this link's frame; both joint axes are z).
  covopt::robot::ChainSampleKinematics kin(chain);
  kin.Update(Eigen::VectorXd::Zero(6), Eigen::VectorXd::Zero(6));
  const auto on_z_axis_through = [](const SurfaceShape& s, const Eigen::Vector3d& at) {
    return std::abs(s.a_m.x() - at.x()) < 1e-9 && std::abs(s.a_m.y() - at.y()) < 1e-9 &&
           std::abs(s.b_m.x() - at.x()) < 1e-9 && std::abs(s.b_m.y() - at.y()) < 1e-9;
  };
  for (std::size_t i = 0; i < meshed.size(); ++i) {
    const auto& shapes = surface.links[i].shapes;
    CHECK(std::any_of(shapes.begin(), shapes.end(),
                      [&](const SurfaceShape& s) { return on_z_axis_through(s, Eigen::Vector3d::Zero()); }));
    if (meshed[i] == "upper_arm_link" || meshed[i] == "forearm_link") {
      const std::size_t here = *kin.LinkIndex(meshed[i]);
      const std::size_t next = *kin.LinkIndex(meshed[i + 1]);
      const Eigen::Vector3d next_origin =
          kin.LinkRotation(here).transpose() * (kin.LinkOrigin(next) - kin.LinkOrigin(here));
      CHECK(std::any_of(shapes.begin(), shapes.end(),
                        [&](const SurfaceShape& s) { return on_z_axis_through(s, next_origin); }));
    }
  }
}

TEST_CASE("the UR5e's surface refuses a mesh it has no file for, a link not on its chain and an unknown shape", "[robot][surface]") {
  const std::string models = COVOPT_ROBOT_MODELS_DIR;
  std::ifstream in(models + "/ur5e.urdf");
  const std::string urdf((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto with_collision = [&](const std::string& geometry) {
    std::string text = urdf;
    const std::string link = "<link name=\"wrist_3_link\">";
    text.insert(text.find(link) + link.size(), Collision("0 0 0", "0 0 0", geometry));
    return text;
  };
  const KinematicChain chain = KinematicChain::FromUrdfFile(models + "/ur5e.urdf", {"", "tool0"});
  const std::string mesh = with_collision("<mesh filename=\"package://ur_description/meshes/ur5e/collision/wrist3.stl\"/>");
  const std::string mesh_message = MessageOf([&] { SurfaceFromUrdfString(mesh, chain, {}, "ur5e+mesh.urdf"); });
  CHECK_THAT(mesh_message, Catch::Contains("link 'wrist_3_link' has mesh collision geometry") &&
                               Catch::Contains("wrist3.stl") && Catch::Contains("surface file"));
  // The shipped surface file covers that mesh link.
  SurfaceOptions options;
  options.surface_file = models + "/ur5e_surface.toml";
  CHECK(SurfaceFromUrdfString(mesh, chain, options).links.size() == 6);

  options.surface_file = WriteTemp("ur5e_other.toml", "[[link]]\nname = \"fr3_link3\"\nsegments = [ { from_m = [0,0,0], to_m = [0,0,0.1], radius_m = 0.05 } ]\n");
  const std::string other = MessageOf([&] { covopt::robot::SurfaceFromUrdfFile(models + "/ur5e.urdf", chain, options); });
  CHECK_THAT(other, Catch::Contains("link 'fr3_link3' is not a moving link of the chain base_link -> tool0") &&
                        Catch::Contains("shoulder_link"));
  const std::string unknown = MessageOf([&] { SurfaceFromUrdfString(with_collision("<capsule radius=\"0.04\" length=\"0.1\"/>"), chain); });
  CHECK_THAT(unknown, Catch::Contains("capsule") && Catch::Contains("wrist_3_link"));
  for (const std::string& text : {mesh_message, other, unknown}) CHECK(text.find('\n') == std::string::npos);
}
