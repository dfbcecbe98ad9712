// The head's fracture check (docs/model.md §7.1): the table of the lowest published fracture
// forces by struck area, its names, and Assess judging the peak force against the struck area's.
#include <catch2/catch.hpp>

#include <stdexcept>
#include <string>

#include <covopt/core/exact.hpp>
#include <covopt/core/head_area.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/core/impact_result.hpp>

using namespace covopt;
using Catch::Matchers::Contains;

namespace {

/// The bare head hit: a 5.145 kg robot of radius 60 mm at 2.3 m/s, no covering.
Scene BareHit(double speed_m_per_s = 2.3) {
  Scene scene;
  scene.robot.mass_kg = 5.145;
  scene.robot.radius_m = 0.060;
  scene.robot.speed_m_per_s = speed_m_per_s;
  scene.covering.thickness_m = 0.0;
  return scene;
}

ImpactPeaks Peaks(const Scene& scene) { return ExactPeaks(ImpactModel::FromScene(scene)); }

}  // namespace

TEST_CASE("fracture table: every area has a positive force, a range, conditions and a source", "[fracture]") {
  REQUIRE(FractureForces().size() == 6);
  for (const FractureForce& row : FractureForces()) {
    CHECK(row.force_N > 0.0);
    CHECK_FALSE(row.range.empty());
    CHECK_FALSE(row.conditions.empty());
    CHECK_FALSE(row.source.empty());
    CHECK(&FractureForceOf(row.area) == &row);
    CHECK(ParseHeadArea(ToString(row.area)) == row.area);
  }
  // The published values (docs/model.md §7.1): frontal 700 lbf (Hodgson et al. 1970),
  // temporo-parietal 5 kN (Allsop et al. 1991), the facial bones lower.
  CHECK(FractureForceOf(HeadArea::kFrontal).force_N == Approx(700 * 4.4482216).epsilon(1e-3));
  CHECK(FractureForceOf(HeadArea::kTemporoParietal).force_N == 5000.0);
  CHECK(FractureForceOf(HeadArea::kNasal).force_N == 450.0);
  CHECK(FractureForceOf(HeadArea::kMaxilla).force_N == 970.0);
  CHECK(FractureForceOf(HeadArea::kMandibleFront).force_N == 2500.0);
  CHECK(FractureForceOf(HeadArea::kMandibleSide).force_N == 600.0);
  for (const FractureForce& row : FractureForces()) {
    if (row.area != HeadArea::kFrontal && row.area != HeadArea::kTemporoParietal) {
      CHECK(row.force_N < FractureForceOf(HeadArea::kFrontal).force_N);
    }
  }
}

TEST_CASE("head area names: case ignored, an unknown one refused naming the field and the choices", "[fracture]") {
  CHECK(ParseHeadArea("Temporo-Parietal") == HeadArea::kTemporoParietal);
  CHECK_FALSE(ParseHeadArea("cheek").has_value());
  CHECK(HeadAreaChoices() == "frontal, temporo-parietal, nasal, maxilla, mandible-front, mandible-side");
  CHECK_THROWS_WITH(ParseHeadAreaOrThrow("head.area", "cheek"),
                    Contains("head.area must be one of frontal, temporo-parietal, nasal") && Contains("\"cheek\""));
  CHECK(Scene{}.head.area == HeadArea::kFrontal);
}

TEST_CASE("fracture verdict: the issue's 2.8 kN bare hit against each area's fracture force", "[fracture]") {
  const ImpactPeaks peaks = Peaks(BareHit());
  REQUIRE(peaks.peak_force_N == Approx(2800).epsilon(0.05));
  // The forehead (default): below Hodgson et al.'s lowest fracture load, ratio F / 3114 N.
  const InjuryAssessment forehead = Assess(peaks);
  CHECK(forehead.area == HeadArea::kFrontal);
  CHECK(forehead.fracture.value == peaks.peak_force_N);
  CHECK(forehead.fracture.limit == FractureForceOf(HeadArea::kFrontal).force_N);
  CHECK(forehead.fracture.ratio == Approx(peaks.peak_force_N / 3113.755).epsilon(1e-4));
  CHECK(forehead.fracture.safe);
  // The skin limits pass: the scalp survives what breaks the nose or the jaw.
  const InjuryAssessment nose = Assess(peaks, {}, HeadArea::kNasal);
  CHECK(nose.laceration.safe);
  CHECK(nose.contusion.safe);
  CHECK_FALSE(nose.fracture.safe);
  CHECK(nose.fracture.ratio == Approx(peaks.peak_force_N / 450.0));
  CHECK_FALSE(nose.safe());
  CHECK_FALSE(Assess(peaks, {}, HeadArea::kMandibleFront).safe());
  CHECK(Assess(peaks, {}, HeadArea::kTemporoParietal).safe());
}

TEST_CASE("fracture verdict: a force over the frontal bone's lowest published value is not safe", "[fracture]") {
  const ImpactPeaks slower = Peaks(BareHit(2.3));
  const ImpactPeaks faster = Peaks(BareHit(2.6));  // F grows with v0 (docs/model.md §7)
  REQUIRE(slower.peak_force_N < 3113.755);
  REQUIRE(faster.peak_force_N > 3113.755);
  CHECK(Assess(slower).fracture.safe);
  CHECK_FALSE(Assess(faster).fracture.safe);
  CHECK_FALSE(Assess(faster).safe());
}

TEST_CASE("fracture verdict: a given fracture force replaces the area's published one", "[fracture]") {
  const ImpactPeaks peaks = Peaks(BareHit());
  InjuryLimits limits;
  CHECK(FractureLimit(limits, HeadArea::kNasal) == 450.0);
  limits.fracture_force_N = 4000.0;
  CHECK(FractureLimit(limits, HeadArea::kNasal) == 4000.0);
  const InjuryAssessment given = Assess(peaks, limits, HeadArea::kNasal);
  CHECK(given.fracture.limit == 4000.0);
  CHECK(given.fracture.safe);
  CHECK_NOTHROW(CheckInjuryLimits(limits));
  limits.fracture_force_N = 0.5;
  CHECK_THROWS_WITH(CheckInjuryLimits(limits), Contains("limits.fracture_force_N") && Contains("0.5"));
}
