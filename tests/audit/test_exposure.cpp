// The audit's exposure zones (AuditSetup::exposure_zones, docs/model.md §14): a zone that
// excludes a region changes exactly that region's cells; a partial zone judges only the
// point-samples inside it (brute force over every point-sample); a point on a face is inside;
// bad zones are refused naming the zone and the field.
#include <algorithm>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/audit/audit.hpp>
#include <covopt/materials/body_regions.hpp>
#include <covopt/materials/catalog.hpp>
#include <covopt/optim/body_region_check.hpp>
#include <covopt/optim/design.hpp>
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
using covopt::materials::BodyRegionTable;
using covopt::robot::testing::MessageOf;


using covopt::audit::testing::Fr3;
using covopt::audit::testing::TheFr3;

/// The FR3 with a 10 mm foam on every link against the chest, the dominant palm and the
/// abdomen, and the head when asked.
ca::AuditSetup Fr3Setup(bool head) {
  const Fr3& fr3 = TheFr3();
  ca::AuditSetup setup{fr3.chain, fr3.surface};
  const std::vector<std::string> names{"PU foam PORON 4701-30 320"};
  const co::CandidateMaterial foam = co::SelectCandidates(covopt::materials::Catalog::BuiltIn(), names).front();
  setup.covering = {covopt::CoveringSpec{foam.youngs_modulus_Pa, foam.poisson_ratio, 0.01}, foam};
  const auto& t = BodyRegionTable::BuiltIn();
  setup.regions = {t.Limits("chest", "", ContactType::kTransient),
                   t.Limits("hands-fingers", "palm-dominant", ContactType::kTransient),
                   t.Limits("abdomen", "", ContactType::kTransient)};
  if (head) setup.head = covopt::Scene{};
  return setup;
}

ca::ExposureZone Zone(std::string name, Eigen::Vector3d min_m, Eigen::Vector3d max_m, std::vector<std::string> regions) {
  return ca::ExposureZone{.name = std::move(name), .min_m = min_m, .max_m = max_m, .regions = std::move(regions),
                          .origin = "test"};
}

const Eigen::Vector3d kLow{-10.0, -10.0, -10.0}, kHigh{10.0, 10.0, 10.0};

bool SameCell(const ca::AuditCell& a, const ca::AuditCell& b) {
  return a.sample == b.sample && a.point == b.point && a.governing_ratio == b.governing_ratio &&
         a.speed_scale == b.speed_scale && a.binding == b.binding && a.not_judged.empty() && b.not_judged.empty();
}

}  // namespace

TEST_CASE("a zone that excludes a region changes exactly that region's cells", "[audit][exposure]") {
  const ca::AuditSetup plain = Fr3Setup(true);
  const ca::AuditResult all = ca::Audit(plain, TheFr3().pick);
  ca::AuditSetup zoned = plain;
  // The whole cell, every region but the chest (by its region's name, and the head by its own).
  zoned.exposure_zones = {Zone("everywhere", kLow, kHigh, {"hands-fingers", "abdomen (abdominal-muscle)", "head"})};
  const ca::AuditResult some = ca::Audit(zoned, TheFr3().pick);
  REQUIRE(some.cells.size() == all.cells.size());
  REQUIRE(all.regions[0].rfind("chest", 0) == 0);
  std::size_t not_judged = 0;
  for (std::size_t k = 0; k < all.cells.size(); ++k) {
    const ca::AuditCell &a = all.cells[k], &b = some.cells[k];
    if (a.region == 0) {
      CHECK_FALSE(b.sample);
      CHECK(b.governing_ratio == 0.0);
      CHECK(b.not_judged == "no exposure zone exposes the region");
      ++not_judged;
    } else {
      CHECK(SameCell(a, b));
    }
  }
  CHECK(some.not_judged_cells == not_judged);
  CHECK(not_judged == all.links.size());
  CHECK(some.exposure_zones.size() == 1);
  // The program's scale is the minimum over the judged cells only: never below the full audit's.
  CHECK(some.safe_speed_scale >= all.safe_speed_scale);
  CHECK(std::any_of(some.scope.begin(), some.scope.end(),
                    [](const std::string& s) { return s.find("Exposure zones (1") != std::string::npos; }));
  // "all" in one zone is the audit without zones.
  zoned.exposure_zones = {Zone("all of it", kLow, kHigh, {"all"})};
  const ca::AuditResult every = ca::Audit(zoned, TheFr3().pick);
  for (std::size_t k = 0; k < all.cells.size(); ++k) CHECK(SameCell(all.cells[k], every.cells[k]));
}

TEST_CASE("a partial zone judges exactly the point-samples inside it, a face counting as inside", "[audit][exposure]") {
  const ca::AuditSetup plain = Fr3Setup(false);
  const Fr3& fr3 = TheFr3();
  // Every 4th sample: the brute force below takes each point-sample's limit directly.
  rb::JointTrajectory path;
  for (std::size_t i = 0; i < fr3.pick.size(); i += 4) {
    path.time_s.push_back(fr3.pick.time_s[i]);
    path.positions.push_back(fr3.pick.positions[i]);
    path.velocities.push_back(fr3.pick.velocities[i]);
  }
  const ca::AuditResult all = ca::Audit(plain, path);
  // The box above z = the limiting cell's governing point (on its lower face): the palm there.
  const ca::AuditCell& limit = all.cells[*all.limiting_cell];
  const double z0 = limit.point_in_base_m.z();
  ca::AuditSetup zoned = plain;
  zoned.exposure_zones = {Zone("above", {-10, -10, z0}, {10, 10, 10}, {"all"})};
  const ca::AuditResult above = ca::Audit(zoned, path);
  CHECK(SameCell(above.cells[*all.limiting_cell], limit));  // its point lies on the face: inside

  // Brute force: per link and region the largest ratio over the point-samples with z >= z0.
  const double sf = plain.rule.safety_factor;
  rb::ChainSampleKinematics kin(plain.chain, plain.motion);
  std::vector<double> brute(all.cells.size(), 0.0);
  for (std::size_t i = 0; i < path.size(); ++i) {
    kin.Update(path.positions[i], path.velocities[i], "sample");
    for (std::size_t l = 0; l < plain.surface.links.size(); ++l) {
      const rb::LinkSurface& link = plain.surface.links[l];
      const std::size_t chain_index = *kin.LinkIndex(link.link);
      for (const rb::SurfacePoint& p : link.points) {
        const rb::PointMotion m = kin.Point(chain_index, p.position_m);
        if (!m.moving || m.speed_m_per_s < 1e-6 || m.position_m.z() < z0) continue;
        for (std::size_t r = 0; r < plain.regions.size(); ++r) {
          covopt::BodyContactScene scene;
          scene.robot_mass_kg = m.reflected_mass_kg;
          scene.robot_radius_m = p.radius_of_curvature_m;
          scene.covering = plain.covering.covering;
          const double v_max =
              co::MaxSafeSpeed(scene, plain.regions[r], co::BodyRegionOptions{plain.rule, plain.covering.material, false})
                  .max_safe_speed_m_per_s;
          double& cell = brute[l * plain.regions.size() + r];
          cell = std::max(cell, m.speed_m_per_s / (sf * v_max));
        }
      }
    }
  }
  std::size_t changed = 0;
  for (std::size_t k = 0; k < above.cells.size(); ++k) {
    const ca::AuditCell& c = above.cells[k];
    CHECK(c.governing_ratio == Approx(brute[k]).epsilon(1e-9));
    if (c.sample) {
      CHECK(c.point_in_base_m.z() >= z0);
      CHECK(c.governing_ratio <= all.cells[k].governing_ratio);
    } else if (all.cells[k].sample) {
      CHECK(c.not_judged == "the link's moving points never enter a zone exposing the region");
    }
    if (!SameCell(c, all.cells[k])) ++changed;
  }
  CHECK(changed > 0);  // the zone leaves some point-samples out
}

TEST_CASE("bad exposure zones are refused naming the zone and the field", "[audit][exposure][bad-input]") {
  const ca::AuditSetup plain = Fr3Setup(true);
  const auto message = [&](const ca::ExposureZone& zone) {
    ca::AuditSetup setup = plain;
    setup.exposure_zones = {zone, Zone("table", kLow, kHigh, {"all"})};
    return MessageOf([&] { ca::Audit(setup, TheFr3().pick); });
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THAT(message(Zone("z", {0, 0, 1}, {1, 1, 0.5}, {"all"})),
             Catch::Contains("test: exposure_zones[0] 'z': min_m [0, 0, 1] lies above max_m [1, 1, 0.5] along z"));
  CHECK_THAT(message(Zone("z", {0, nan, 0}, {1, 1, 1}, {"all"})), Catch::Contains("finite"));
  CHECK_THAT(message(Zone("z", {0, 0, 0}, {1, 1, 1}, {})), Catch::Contains("'z': regions: empty"));
  CHECK_THAT(message(Zone("z", {0, 0, 0}, {1, 1, 1}, {"elbow-ish"})),
             Catch::Contains("regions: 'elbow-ish' is not a body region"));
  CHECK_THAT(message(Zone("table", {0, 0, 0}, {1, 1, 1}, {"all"})),
             Catch::Contains("exposure_zones[1] 'table': name: 'table' names two zones"));
  // A region of the table the audit does not judge is left out, not refused.
  ca::AuditSetup setup = plain;
  setup.exposure_zones = {Zone("legs", kLow, kHigh, {"lower-legs"})};
  const ca::AuditResult none = ca::Audit(setup, TheFr3().pick);
  CHECK(none.not_judged_cells == none.cells.size());
  CHECK_FALSE(none.limiting_cell);
  CHECK(none.message.rfind("not judged", 0) == 0);
}

TEST_CASE("a braking robot's search judges the same point-samples as the zones admit", "[audit][exposure][braking]") {
  ca::AuditSetup zoned = Fr3Setup(false);
  zoned.reaction_delay_s = 0.005;
  zoned.braking_m_per_s2 = 50.0;
  const double z0 = 0.5;
  zoned.exposure_zones = {Zone("above", {-10, -10, z0}, {10, 10, 10}, {"hands-fingers", "abdomen"})};
  ca::AuditSetup unbraked = zoned;
  unbraked.reaction_delay_s = unbraked.braking_m_per_s2 = 0.0;
  const ca::AuditResult braked = ca::Audit(zoned, TheFr3().pick);
  const ca::AuditResult bound = ca::Audit(unbraked, TheFr3().pick);
  REQUIRE(braked.cells.size() == bound.cells.size());
  for (std::size_t k = 0; k < braked.cells.size(); ++k) {
    const ca::AuditCell& c = braked.cells[k];
    if (c.region == 0) CHECK(c.not_judged == "no exposure zone exposes the region");  // the chest
    CHECK(c.sample.has_value() == bound.cells[k].sample.has_value());
    if (!c.sample) continue;
    CHECK(c.point_in_base_m.z() >= z0);
    CHECK(c.governing_ratio <= bound.cells[k].governing_ratio * (1.0 + 1e-9));  // braking only takes energy out
  }
}
