// The tool and the payload on the audited surface (audit/tool_surface.hpp, robot::AddTipSurface):
// the FR3 with a gripper has a "tool" row that moves with the flange, whose governing cell is a
// hand computation at its point (speed and reflected mass from the chain at the flange offset,
// v_max from the region's closed form); its own covering changes its row only; a surface
// file's [[tool]] is the same row; every bad spec is refused naming the field.
#include <cmath>
#include <cstddef>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/audit/audit.hpp>
#include <covopt/audit/tool_surface.hpp>
#include <covopt/materials/body_regions.hpp>
#include <covopt/optim/body_region_check.hpp>
#include <covopt/robot/link_kinematics.hpp>
#include <covopt/robot/surface.hpp>
#include <covopt/robot/trajectory.hpp>

#include "../robot/robot_test_support.hpp"
#include "fr3_pick.hpp"

namespace {

namespace ca = covopt::audit;
namespace co = covopt::optim;
namespace rb = covopt::robot;
using covopt::ContactType;
using covopt::robot::testing::MessageOf;

const std::string kModels = COVOPT_ROBOT_MODELS_DIR;
const std::string kUrdf = kModels + "/franka_fr3.urdf";

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The Franka Hand's rough envelope: a box turned -45° about the flange's z, two finger capsules.
const std::vector<std::string> kGripper{"box:center=0,0,0.045;size=0.08,0.2,0.09;edge=10mm;rpy=0,0,-0.785398",
                                        "capsule:from=0.0141,0.0141,0.09;to=0.0141,0.0141,0.105;radius=10mm",
                                        "capsule:from=-0.0141,-0.0141,0.09;to=-0.0141,-0.0141,0.105;radius=10mm"};

using covopt::audit::testing::Fr3;
using covopt::audit::testing::TheFr3;

const Fr3& Gripped() {
  static const Fr3 fr3 = [] {
    Fr3 gripped = TheFr3();
    std::vector<rb::SurfaceShape> shapes;
    for (const std::string& spec : kGripper) shapes.push_back(ca::ParseTipShape(spec, "tool_surface"));
    rb::AddTipSurface(gripped.surface, gripped.chain, "tool", shapes);
    return gripped;
  }();
  return fr3;
}

ca::AuditSetup Setup() {
  const Fr3& fr3 = Gripped();
  ca::AuditSetup setup{fr3.chain, fr3.surface};
  const auto& t = covopt::materials::BodyRegionTable::BuiltIn();
  setup.regions = {t.Limits("chest", "", ContactType::kTransient),
                   t.Limits("hands-fingers", "palm-dominant", ContactType::kTransient)};
  setup.covering.covering = covopt::CoveringSpec{0.5e6, 0.45, 0.01};
  setup.flat_face_radius_m = 0.02;  // the box's faces
  return setup;
}

}  // namespace

TEST_CASE("the gripper is audited as its own row: its cell is the hand computation at the flange offset",
          "[audit][tool]") {
  const ca::AuditSetup setup = Setup();
  const ca::AuditResult result = ca::Audit(setup, Gripped().pick);
  REQUIRE(result.links.back() == "tool");
  const std::size_t tool = result.links.size() - 1;
  CHECK(result.link_point_counts[tool] > 20);
  rb::ChainSampleKinematics kin(setup.chain, setup.motion);
  const std::size_t tip = *kin.LinkIndex("fr3_link8");
  for (std::size_t r = 0; r < result.regions.size(); ++r) {
    const ca::AuditCell& c = result.cell(tool, r);
    REQUIRE(c.sample);
    CHECK(c.speed_m_per_s > 0.1);  // it moves
    const std::size_t i = *c.sample;
    kin.Update(Gripped().pick.positions[i], Gripped().pick.velocities[i], "sample");
    const rb::PointMotion m = kin.Point(tip, c.point_in_link_m);
    CHECK(m.speed_m_per_s == Approx(c.speed_m_per_s).epsilon(1e-12));
    CHECK(m.reflected_mass_kg == Approx(c.reflected_mass_kg).epsilon(1e-12));
    CHECK((m.position_m - c.point_in_base_m).norm() < 1e-12);
    // The point is on the gripper: within its envelope below the flange.
    CHECK(c.point_in_link_m.z() >= -1e-9);
    CHECK(c.point_in_link_m.z() <= 0.115 + 1e-9);
    const rb::SurfacePoint& p = setup.surface.links[tool].points[c.point];
    covopt::BodyContactScene scene;
    scene.robot_mass_kg = m.reflected_mass_kg;
    scene.robot_radius_m = std::isfinite(p.radius_of_curvature_m) ? p.radius_of_curvature_m : *setup.flat_face_radius_m;
    scene.covering = setup.covering.covering;
    const double v_max =
        co::MaxSafeSpeed(scene, setup.regions[r], co::BodyRegionOptions{setup.rule, std::nullopt, false}).max_safe_speed_m_per_s;
    CHECK(c.max_safe_speed_m_per_s == Approx(v_max).epsilon(1e-9));
    CHECK(c.governing_ratio == Approx(m.speed_m_per_s / (setup.rule.safety_factor * v_max)).epsilon(1e-9));
  }
  // Its own covering changes its row only.
  ca::AuditSetup thicker = setup;
  thicker.link_coverings["tool"] = ca::AuditCovering{covopt::CoveringSpec{0.5e6, 0.45, 0.03}, std::nullopt};
  const ca::AuditResult covered = ca::Audit(thicker, Gripped().pick);
  for (std::size_t k = 0; k < result.cells.size(); ++k) {
    if (result.cells[k].link == tool) {
      CHECK(covered.cells[k].governing_ratio < result.cells[k].governing_ratio);
    } else {
      CHECK(covered.cells[k].governing_ratio == result.cells[k].governing_ratio);
    }
  }
}

TEST_CASE("a surface file's [[tool]] and [[payload]] are rows carried by the tip link", "[audit][tool]") {
  const rb::SurfaceFileShapes file = rb::ParseSurfaceFile(
      "[[tool]]\nsegments = [ { from_m = [0, 0, 0.02], to_m = [0, 0, 0.12], radius_m = 0.04 } ]\n"
      "[[payload]]\npoints = [ { at_m = [0, 0, 0.2], radius_m = 0.03 } ]\n",
      "grip.toml");
  const rb::KinematicChain& chain = Gripped().chain;
  rb::SurfaceOptions options;
  options.spacing_m = 0.08;
  const rb::RobotSurface surface =
      rb::SurfaceFromUrdfString(ReadText(kUrdf), chain, options, kUrdf, &file);
  REQUIRE(surface.links.size() >= 2);
  const rb::LinkSurface& tool = surface.links[surface.links.size() - 2];
  const rb::LinkSurface& payload = surface.links.back();
  CHECK(tool.link == "tool");
  CHECK(tool.carrier() == "fr3_link8");
  CHECK(payload.link == "payload");
  CHECK(payload.points.size() == 1);
  // The same capsule from a spec: the same points.
  rb::RobotSurface from_spec = rb::SurfaceFromUrdfFile(kUrdf, chain, options);
  rb::AddTipSurface(from_spec, chain, "tool", {ca::ParseTipShape("capsule:from=0,0,20mm;to=0,0,0.12;radius=4cm", "t")});
  REQUIRE(from_spec.links.back().points.size() == tool.points.size());
  for (std::size_t k = 0; k < tool.points.size(); ++k) {
    CHECK((from_spec.links.back().points[k].position_m - tool.points[k].position_m).norm() < 1e-12);
  }
  CHECK_THAT(MessageOf([] { rb::ParseSurfaceFile("[[tool]]\nname = \"x\"\n", "g.toml"); }), Catch::Contains("g.toml:2:1"));
}

TEST_CASE("a bad tool shape spec is refused naming the field, the key and the value", "[audit][tool][bad-input]") {
  const auto message = [](const std::string& spec) { return MessageOf([&] { ca::ParseTipShape(spec, "--tool-surface"); }); };
  CHECK_THAT(message("cone:center=0,0,0"), Catch::StartsWith("--tool-surface 'cone:center=0,0,0': shape: expected capsule:"));
  CHECK_THAT(message("sphere:center=0,0,0.1"), Catch::Contains(": radius: missing"));
  CHECK_THAT(message("sphere:center=0,0,0.1;radius=40"), Catch::Contains("radius: must be in [0.1 mm, 1000 mm] (got 40000 mm)"));
  CHECK_THAT(message("sphere:center=0,0;radius=40mm"), Catch::Contains("center: expected 3 lengths x,y,z (got '0,0')"));
  CHECK_THAT(message("sphere:center=0,0,3;radius=40mm"), Catch::Contains("center: each coordinate must be within ±2 m"));
  CHECK_THAT(message("sphere:centre=0,0,0.1;radius=40mm"), Catch::Contains("centre: a sphere takes center, radius"));
  CHECK_THAT(message("sphere:center=0,0,0.1;radius=4mm;radius=5mm"), Catch::Contains("radius: given twice"));
  CHECK_THAT(message("box:center=0,0,0.05;size=0.08,0.2,0.1"), Catch::Contains("edge: missing"));
  CHECK_THAT(message("box:center=0,0,0.05;size=0.08,0.2,0.1;edge=50mm"), Catch::Contains("edge: must be in [0.1 mm, 40 mm]"));
  CHECK_THAT(message("box:center=0,0,0.05;size=0.08,0.2,0;edge=5mm"), Catch::Contains("size: each extent must be in"));
  CHECK_THAT(message("box:center=0,0,0.05;size=0.08,0.2,0.1;edge=5mm;rpy=0,x,0"), Catch::Contains("rpy: each angle"));
  CHECK_THAT(message("capsule:from=0,0,0.1;to=0,0,0.1;radius=5mm"), Catch::Contains("to: coincides with from"));
  CHECK_THAT(message("capsule:from=0,0,nan;to=0,0,0.1;radius=5mm"), Catch::Contains("from:"));
}
