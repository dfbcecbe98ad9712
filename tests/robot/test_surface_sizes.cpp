// The surface's size is estimated from its shapes and the spacing and refused before any point
// is made (a 100 m sphere at 1 mm once took 11 GB); the estimate bounds the count from above
// and is close to it. And the radius floor: a radius of curvature below covopt::kMinRadius_m
// (0.1 mm) is refused wherever a shape gives one (a denormal URDF sphere once read as safe).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "covopt/robot/kinematic_chain.hpp"
#include "covopt/robot/surface.hpp"
#include "robot_test_support.hpp"

namespace {

using covopt::robot::EstimateShapePoints;
using covopt::robot::KinematicChain;
using covopt::robot::kMaxSurfacePoints;
using covopt::robot::RobotSurface;
using covopt::robot::SampleShape;
using covopt::robot::SurfaceFromUrdfString;
using covopt::robot::SurfaceOptions;
using covopt::robot::SurfaceShape;
using covopt::robot::SurfaceShapeType;
using covopt::robot::testing::MessageOf;

/// base -> arm (joint j1) -> hand (joint j2) -> tool (fixed); `arm`, `hand` and `tool` carry
/// the given collision XML.
std::string TwoLinkUrdf(const std::string& arm, const std::string& hand = "", const std::string& tool = "") {
  const std::string inertial = R"(<inertial><mass value="1"/><origin xyz="0.1 0 0"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>)";
  return R"(<robot name="t"><link name="base"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="arm"/><origin xyz="0 0 0.1"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="2"/></joint>
  <link name="arm">)" + inertial + arm + R"(</link>
  <joint name="j2" type="revolute"><parent link="arm"/><child link="hand"/><origin xyz="0.3 0 0"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="2"/></joint>
  <link name="hand">)" + inertial + hand + R"(</link>
  <joint name="j3" type="fixed"><parent link="hand"/><child link="tool"/><origin xyz="0.1 0 0"/></joint>
  <link name="tool">)" + inertial + tool + R"(</link></robot>)";
}

std::string Geometry(const std::string& geometry, const std::string& xyz = "0 0 0") {
  return "<collision><origin xyz=\"" + xyz + "\" rpy=\"0 0 0\"/><geometry>" + geometry + "</geometry></collision>";
}

/// The surface of base -> `tip`.
RobotSurface Surface(const std::string& urdf, const std::string& tip, SurfaceOptions options = {}) {
  const KinematicChain chain = KinematicChain::FromUrdfString(urdf, {"", tip});
  return SurfaceFromUrdfString(urdf, chain, options);
}

std::filesystem::path WriteTemp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("covopt_surface_sizes_" + name);
  std::ofstream(path) << text;
  return path;
}

SurfaceShape Shape(SurfaceShapeType type, double r, double length = 0.0) {
  SurfaceShape shape;
  shape.type = type;
  shape.radius_m = r;
  shape.a_m = {0.01, -0.02, 0.03};
  shape.b_m = shape.a_m + length * Eigen::Vector3d(0.48, -0.6, 0.64);  // a unit direction
  shape.origin = std::string("test ") + covopt::robot::ToString(type);
  return shape;
}

SurfaceShape Box(const Eigen::Vector3d& size, double e) {
  SurfaceShape shape;
  shape.type = SurfaceShapeType::kBox;
  shape.pose.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  shape.size_m = size;
  shape.edge_radius_m = e;
  return shape;
}

}  // namespace

TEST_CASE("the estimate bounds every shape's point count from above, and closely", "[robot][surface][sizes]") {
  std::mt19937 random(20261206);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, unit(random)); };
  std::vector<SurfaceShape> shapes;
  for (int i = 0; i < 150; ++i) {
    const double r = log_uniform(1e-4, 0.5);
    shapes.push_back(Shape(SurfaceShapeType::kSphere, r));
    shapes.push_back(Shape(SurfaceShapeType::kCapsule, r, log_uniform(1e-4, 1.0)));
    shapes.push_back(Shape(SurfaceShapeType::kCapsule, r, 0.0));  // from = to: a sphere
    shapes.push_back(Shape(SurfaceShapeType::kCylinder, r, log_uniform(1e-4, 1.0)));
    const Eigen::Vector3d size(log_uniform(2e-4, 1.0), log_uniform(2e-4, 1.0), log_uniform(2e-4, 1.0));
    shapes.push_back(Box(size, log_uniform(1e-4, 0.5 * size.minCoeff())));
  }
  shapes.push_back(Shape(SurfaceShapeType::kPoint, 0.01));
  std::size_t checked = 0;
  for (const SurfaceShape& shape : shapes) {
    const double spacing = log_uniform(1e-3, 1.0);
    const double estimate = EstimateShapePoints(shape, spacing);
    if (estimate > 2e5) continue;  // keep the test quick; the closed forms do not change with size
    const double count = static_cast<double>(SampleShape(shape, spacing).size());
    INFO(covopt::robot::ToString(shape.type) << " r " << shape.radius_m << " length " << (shape.b_m - shape.a_m).norm()
                                             << " size " << shape.size_m.transpose() << " e " << shape.edge_radius_m
                                             << " spacing " << spacing << ": estimate " << estimate << ", count " << count);
    CHECK(estimate >= count);
    // Exact for boxes and points; on rings summed in closed form, at most 2 % and 4 points a
    // ring over (a ring is at least 4 points).
    if (shape.type == SurfaceShapeType::kBox || shape.type == SurfaceShapeType::kPoint) {
      CHECK(estimate == count);
    } else {
      CHECK(estimate <= 1.02 * count + 4.0 * std::sqrt(count) + 16.0);
    }
    ++checked;
  }
  CHECK(checked > 600);
}

TEST_CASE("the estimate of a large shape is about its area over the spacing squared, without making it", "[robot][surface][sizes]") {
  // A 1000 m sphere (the largest radius allowed) at 1 mm: 4π r² / s² = 1.26e13 points.
  const double estimate = EstimateShapePoints(Shape(SurfaceShapeType::kSphere, 1000.0), 1e-3);
  CHECK(estimate >= 4.0 * std::numbers::pi * 1e12);
  CHECK(estimate <= 1.001 * 4.0 * std::numbers::pi * 1e12);
  // Not finite: no estimate to trust.
  CHECK(std::isinf(EstimateShapePoints(Shape(SurfaceShapeType::kSphere, std::nan("")), 0.05)));
  // SampleShape refuses it before allocating (it once ended in std::bad_alloc).
  const std::string message = MessageOf([] { SampleShape(Shape(SurfaceShapeType::kSphere, 1000.0), 0.05); });
  CHECK_THAT(message, Catch::Contains("test sphere") && Catch::Contains("gives about 5.02") &&
                          Catch::Contains("more than the 1000000"));
}

TEST_CASE("a surface too large for the cap is refused before it is made, naming the shape and a spacing that does", "[robot][surface][sizes]") {
  // A 100 m URDF sphere at 1 mm (11 GB and more than a minute before this check) and at the
  // default 5 cm (4.2 GB and 9.6 s).
  const std::string urdf = TwoLinkUrdf(Geometry("<sphere radius=\"100\"/>"));
  SurfaceOptions fine;
  fine.spacing_m = 1e-3;
  const std::string at_1mm = MessageOf([&] { Surface(urdf, "arm", fine); });
  CHECK_THAT(at_1mm, Catch::Contains("sampled at a spacing of 0.001 m would have about 1.25") &&
                         Catch::Contains("more than the 1000000 allowed") &&
                         Catch::Contains("URDF <collision> 1 of link 'arm', a sphere of radius 100 m") &&
                         Catch::Contains("a spacing of at least 0.355 m (--surface-spacing"));
  const std::string at_default = MessageOf([&] { Surface(urdf, "arm"); });
  CHECK_THAT(at_default, Catch::Contains("would have about 5.02") && Catch::Contains("at least 0.355 m"));
  // The spacing it names does fit, and 1 mm less does not.
  SurfaceOptions suggested;
  suggested.spacing_m = 0.355;
  CHECK(Surface(urdf, "arm", suggested).point_count() <= kMaxSurfacePoints);
  suggested.spacing_m = 0.354;
  CHECK_THAT(MessageOf([&] { Surface(urdf, "arm", suggested); }), Catch::Contains("more than the 1000000"));
  // A 1000 m sphere cannot be sampled at any spacing.
  CHECK_THAT(MessageOf([&] { Surface(TwoLinkUrdf(Geometry("<sphere radius=\"1000\"/>")), "arm"); }),
             Catch::Contains("give smaller shapes (even the largest spacing, 1 m, gives about 1.25"));
  // The sum over shapes and links counts, not each shape alone: 3 spheres of 400 000 points.
  const std::string sphere = Geometry("<sphere radius=\"8.9\"/>");
  CHECK(EstimateShapePoints(Shape(SurfaceShapeType::kSphere, 8.9), 0.05) < 0.45e6);
  CHECK_THAT(MessageOf([&] { Surface(TwoLinkUrdf(sphere + sphere, sphere), "hand"); }),
             Catch::Contains("more than the 1000000 allowed"));
}

TEST_CASE("a surface file's huge segment is refused before it is sampled, naming its place", "[robot][surface][sizes]") {
  // A segment 999 m long of radius 999 m: both within the documented limits; it once hung.
  SurfaceOptions options;
  options.surface_file = WriteTemp("huge.toml", "[[link]]\nname = \"arm\"\n"
                                                "segments = [ { from_m = [0, 0, 0], to_m = [999, 0, 0], radius_m = 999 } ]\n");
  const std::string message = MessageOf([&] { Surface(TwoLinkUrdf(""), "arm", options); });
  CHECK_THAT(message, Catch::Contains("more than the 1000000 allowed") && Catch::Contains("huge.toml:3:") &&
                          Catch::Contains("a capsule of radius 999 m and length 999 m") &&
                          Catch::Contains("even the largest spacing, 1 m"));
}

TEST_CASE("a URDF radius of curvature below 0.1 mm is refused naming the element and the range", "[robot][surface][sizes]") {
  const auto message = [](const std::string& arm, SurfaceOptions options = {}) {
    return MessageOf([&] { Surface(TwoLinkUrdf(arm), "arm", options); });
  };
  // A denormal sphere once read "safe up to 3.946x"; 2.3e-308 m "unsafe 0x".
  for (const std::string radius : {"4.9e-324", "2.3e-308", "9.99e-05"}) {
    const std::string text = message(Geometry("<sphere radius=\"" + radius + "\"/>"));
    CHECK_THAT(text, Catch::Contains("link 'arm' <collision> 1: <sphere radius> = ") &&
                         Catch::Contains("m is not allowed (a radius in [0.0001, 1000] m"));
  }
  CHECK_THAT(message(Geometry("<cylinder radius=\"1e-5\" length=\"0.2\"/>")),
             Catch::Contains("<cylinder radius> = 1e-05 m is not allowed"));
  CHECK_THAT(message(Geometry("<cylinder radius=\"0.01\" length=\"1e-300\"/>")),
             Catch::Contains("<cylinder length> = 1e-300 m is not allowed (a length in [0.0001, 1000] m"));
  // A capsule (a cylinder with a sphere of its radius on each end) of a denormal radius.
  CHECK_THAT(message(Geometry("<cylinder radius=\"5e-324\" length=\"0.2\"/>") +
                     Geometry("<sphere radius=\"5e-324\"/>", "0 0 -0.1") + Geometry("<sphere radius=\"5e-324\"/>", "0 0 0.1")),
             Catch::Contains("<cylinder radius> = 4.94066e-324 m is not allowed"));
  SurfaceOptions edge;
  edge.box_edge_radius_m = 5e-5;
  CHECK_THAT(message(Geometry("<box size=\"0.1 0.1 0.1\"/>"), edge),
             Catch::Contains("box edge radius = 5e-05 m is not allowed (in [0.0001 m, half the box's smallest extent"));
  // The floor itself is allowed.
  CHECK(Surface(TwoLinkUrdf(Geometry("<sphere radius=\"0.0001\"/>")), "arm").point_count() > 0);
  edge.box_edge_radius_m = 1e-4;
  CHECK(Surface(TwoLinkUrdf(Geometry("<box size=\"0.1 0.1 0.1\"/>")), "arm", edge).point_count() > 0);
}

TEST_CASE("only the shapes a surface uses are held to the floor", "[robot][surface][sizes]") {
  const std::string tiny = Geometry("<sphere radius=\"4.9e-324\"/>");
  const std::string fine = Geometry("<sphere radius=\"0.05\"/>");
  // On a link after the tip (tool, beyond hand; hand beyond arm): not part of the surface.
  CHECK(Surface(TwoLinkUrdf(fine, fine, tiny), "hand").links.size() == 2);
  CHECK(Surface(TwoLinkUrdf(fine, tiny, tiny), "arm").links.size() == 1);
  // On the base link, which does not move.
  const std::string on_base = [&] {
    std::string urdf = TwoLinkUrdf(fine);
    urdf.replace(urdf.find("<link name=\"base\"/>"), 19, "<link name=\"base\">" + tiny + "</link>");
    return urdf;
  }();
  CHECK(Surface(on_base, "arm").links.size() == 1);
  // On a link whose shapes a surface file replaces.
  SurfaceOptions options;
  options.surface_file =
      WriteTemp("replace.toml", "[[link]]\nname = \"hand\"\npoints = [ { at_m = [0, 0, 0], radius_m = 0.02 } ]\n");
  CHECK(Surface(TwoLinkUrdf(fine, tiny), "hand", options).point_count() > 1);
  // On a chain link it does use: refused.
  CHECK_THAT(MessageOf([&] { Surface(TwoLinkUrdf(fine, tiny), "hand"); }),
             Catch::Contains("link 'hand' <collision> 1: <sphere radius>"));
}

TEST_CASE("a surface file's character that toml++ 3.3 cannot classify is a syntax error, not undefined behaviour", "[robot][surface][sizes]") {
  // Found by fuzz_surface_file under UBSan: toml++ 3.3.0 reached __builtin_unreachable() when
  // it asked whether U+0424 is whitespace; covopt/internal/toml.hpp mends it.
  const std::string points = "points = [ { at_m = [0, 0, 0], radius_m = 0.01 } ]\n";
  CHECK_THAT(MessageOf([&] { covopt::robot::ParseSurfaceFile("[[link]]\nname = \"arm\" \xd0\xa4\n" + points, "u.toml"); }),
             Catch::StartsWith("u.toml:2:"));
  // After a line-ending backslash in a multi-line string, U+00A7 is text (toml++'s own case).
  CHECK(covopt::robot::ParseSurfaceFile("[[link]]\nname = \"\"\"\\\n\xc2\xa7\"\"\"\n" + points, "m.toml").links.front().link ==
        "\xc2\xa7");
  // In comments and one-line strings any character is fine.
  CHECK(covopt::robot::ParseSurfaceFile("# \xd0\xa4 \xc2\xb5m\n[[link]]\nname = \"arm\" # \xc2\xa7\n" + points, "c.toml")
            .links.size() == 1);
  CHECK(covopt::robot::ParseSurfaceFile("[[link]]\nname = 'a\xd0\xa4'\n" + points, "s.toml").links.front().link ==
        "a\xd0\xa4");
}

TEST_CASE("a surface file's radius below 0.1 mm is refused naming file:line:column", "[robot][surface][sizes]") {
  const std::string urdf = TwoLinkUrdf("");
  const auto message = [&](const std::string& name, const std::string& toml) {
    SurfaceOptions options;
    options.surface_file = WriteTemp(name, toml);
    return MessageOf([&] { Surface(urdf, "arm", options); });
  };
  // A point of radius 1e-310 m once gave the bare head cell a ratio of 0.0185 (0.93 at 1 cm).
  CHECK_THAT(message("point.toml", "[[link]]\nname = \"arm\"\npoints = [\n  { at_m = [0, 0, 0], radius_m = 1e-310 },\n]\n"),
             Catch::Contains("point.toml:4:") && Catch::Contains("radius_m = 1e-310 m is not allowed") &&
                 Catch::Contains("a radius in [0.0001, 1000] m, or \"flat\""));
  CHECK_THAT(message("segment.toml", "[[link]]\nname = \"arm\"\n"
                                     "segments = [ { from_m = [0, 0, 0], to_m = [0.1, 0, 0], radius_m = 5e-5 } ]\n"),
             Catch::Contains("segment.toml:3:") && Catch::Contains("radius_m = 5e-05 m is not allowed (a radius in [0.0001, 1000] m;"));
  SurfaceOptions ok;
  ok.surface_file = WriteTemp("floor.toml", "[[link]]\nname = \"arm\"\npoints = [ { at_m = [0, 0, 0], radius_m = 1e-4 } ]\n");
  CHECK(Surface(urdf, "arm", ok).point_count() == 1);
}
