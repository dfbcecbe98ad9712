// SpeedLimitTable (optim/speed_limit_table.hpp): one row per covering and value, each the
// answer of MaxSafeSpeed / MaxSafeMass at that value; bad input names its covering. And
// MotionSamples (optim/trajectory_check.hpp), the adapter from any motion's samples.
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/materials/body_regions.hpp>
#include <covopt/materials/contact_target.hpp>
#include <covopt/optim/speed_limit_table.hpp>
#include <covopt/optim/target_speed_limits.hpp>
#include <covopt/optim/trajectory_check.hpp>

namespace {

using covopt::Scene;
namespace co = covopt::optim;

TEST_CASE("a speed-limit table holds MaxSafeSpeed per covering and robot mass, in order", "[speed_limit_table]") {
  Scene thin;
  thin.covering.thickness_m = 0.005;
  Scene bare;
  bare.covering.thickness_m = 0.0;
  const std::vector<co::SpeedLimitCovering> coverings = {{thin, std::string("foam"), {}}, {bare, std::string("foam"), {}}};
  const std::vector<double> masses = {2.0, 10.0, covopt::kFixed};
  const std::vector<co::SpeedLimitRow> rows = co::SpeedLimitTable(co::SpeedLimitQuantity::kSpeed, coverings, masses);
  REQUIRE(rows.size() == 6);
  for (std::size_t c = 0; c < coverings.size(); ++c) {
    for (std::size_t v = 0; v < masses.size(); ++v) {
      const co::SpeedLimitRow& row = rows[c * masses.size() + v];
      Scene scene = coverings[c].scene;
      scene.robot.mass_kg = masses[v];
      CHECK(row.robot_mass_kg == masses[v]);
      CHECK(row.speed_limit.max_safe_speed_m_per_s == co::MaxSafeSpeed(scene).max_safe_speed_m_per_s);
      // The material names a covering only where the scene has one.
      CHECK(row.material.has_value() == (c == 0));
    }
  }
  CHECK(co::FirstFailedRow(co::SpeedLimitQuantity::kSpeed, rows) == nullptr);
  CHECK(co::SpeedLimitOracle(co::SpeedLimitQuantity::kSpeed, rows).evaluations >= rows.front().speed_limit.oracle.evaluations);
  CHECK(co::ToString(co::SpeedLimitQuantity::kMass) == "mass");
}

TEST_CASE("a speed-limit table solving for the mass holds MaxSafeMass per speed", "[speed_limit_table]") {
  const std::vector<co::SpeedLimitCovering> coverings = {{Scene{}, std::nullopt, {}}};
  const std::vector<double> speeds = {0.5, 2.0};
  const auto rows = co::SpeedLimitTable(co::SpeedLimitQuantity::kMass, coverings, speeds);
  REQUIRE(rows.size() == 2);
  for (std::size_t v = 0; v < speeds.size(); ++v) {
    Scene scene;
    scene.robot.speed_m_per_s = speeds[v];
    CHECK(rows[v].speed_m_per_s == speeds[v]);
    CHECK(rows[v].mass_limit.max_safe_mass_kg == co::MaxSafeMass(scene).max_safe_mass_kg);
    CHECK(co::RowMessage(co::SpeedLimitQuantity::kMass, rows[v]) == rows[v].mass_limit.message);
  }
}

TEST_CASE("a bad scene in a speed-limit table names its covering", "[speed_limit_table]") {
  Scene bad;
  bad.head.mass_kg = -1.0;
  const std::vector<co::SpeedLimitCovering> coverings = {{Scene{}, std::nullopt, {}}, {bad, std::nullopt, {}}};
  const std::vector<double> masses = {5.0};
  try {
    (void)co::SpeedLimitTable(co::SpeedLimitQuantity::kSpeed, coverings, masses);
    FAIL("no error");
  } catch (const co::SpeedLimitTableError& e) {
    CHECK(e.covering_index() == 1);
    CHECK(std::string(e.what()).find("head") != std::string::npos);
  }
}

TEST_CASE("MotionSamples takes time, speed and reflected mass from any motion's samples", "[trajectory]") {
  struct RobotSample {
    double time_s, speed_m_per_s, reflected_mass_kg, other;
  };
  const std::vector<RobotSample> motion = {{0.0, 0.0, 3.0, 9.0}, {0.1, 0.5, covopt::kFixed, 9.0}};
  const std::vector<co::MotionSample> samples = co::MotionSamples(motion);
  REQUIRE(samples.size() == 2);
  CHECK(samples[1].time_s == 0.1);
  CHECK(samples[1].speed_m_per_s == 0.5);
  CHECK(std::isinf(samples[1].reflected_mass_kg));
}

}  // namespace

TEST_CASE("the targets' speed-limit table: the regions' rows and the head's where named, per mass", "[speed_limit_table]") {
  Scene scene;
  scene.covering.thickness_m = 0.01;
  covopt::materials::ContactTargets targets;
  const std::vector<covopt::materials::BodyLimits> all =
      covopt::materials::BodyRegionTable::BuiltIn().AllLimits(covopt::ContactType::kTransient);
  targets.targets = {{all.front()}, {std::nullopt}, {all.back()}};  // a region, the head, a region
  co::TargetSpeedLimitRequest request;
  request.scene = scene;
  request.contact_scene.robot_radius_m = scene.robot.radius_m;
  request.contact_scene.speed_m_per_s = scene.robot.speed_m_per_s;
  request.contact_scene.covering = scene.covering;
  request.robot_masses_kg = {2.0, 10.0};
  const co::TargetSpeedLimits table = co::TargetSpeedLimitTable(request, targets);
  CHECK(table.failure.empty());
  REQUIRE(table.rows.size() == 6);
  for (std::size_t m = 0; m < 2; ++m) {
    const double mass = request.robot_masses_kg[m];
    const co::TargetSpeedLimit* rows = &table.rows[3 * m];
    for (std::size_t t = 0; t < 3; ++t) CHECK(rows[t].robot_mass_kg == mass);
    // The regions' rows are BodyRegionSpeedLimitTable's at that mass, in the order named.
    covopt::BodyContactScene at = request.contact_scene;
    at.robot_mass_kg = mass;
    const std::vector<covopt::materials::BodyLimits> iso{all.front(), all.back()};
    const std::vector<co::BodyRegionSpeedLimitRow> expected = co::BodyRegionSpeedLimitTable(at, iso);
    REQUIRE(rows[0].region.has_value());
    REQUIRE(rows[2].region.has_value());
    CHECK(rows[0].region->bare.max_safe_speed_m_per_s == expected[0].bare.max_safe_speed_m_per_s);
    CHECK(rows[2].region->bare.max_safe_speed_m_per_s == expected[1].bare.max_safe_speed_m_per_s);
    // The head's is MaxSafeSpeed's, bare and with the covering.
    REQUIRE_FALSE(rows[1].region.has_value());
    Scene head = scene;
    head.robot.mass_kg = mass;
    REQUIRE(rows[1].head_covered.has_value());
    CHECK(rows[1].head_covered->max_safe_speed_m_per_s == co::MaxSafeSpeed(head).max_safe_speed_m_per_s);
    head.covering.thickness_m = 0.0;
    CHECK(rows[1].head_bare->max_safe_speed_m_per_s == co::MaxSafeSpeed(head).max_safe_speed_m_per_s);
  }
  // The heavier robot is limited to a lower speed on the head.
  CHECK(table.rows[4].head_bare->max_safe_speed_m_per_s < table.rows[1].head_bare->max_safe_speed_m_per_s);
}
