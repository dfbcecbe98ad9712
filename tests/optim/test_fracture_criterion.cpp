// The head's fracture check in the design rules (docs/model.md §7.1): the fracture ratio
// counts in every verdict, speed limit and design of the head, and the robust worst case and
// probability count every criterion, crush and fracture included (docs/model.md §11, §12).
#include <catch2/catch.hpp>

#include <vector>

#include <covopt/core/exact.hpp>
#include <covopt/core/head_area.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/optim/covering_design.hpp>
#include <covopt/optim/robust_probability.hpp>
#include <covopt/optim/robust_search.hpp>
#include <covopt/optim/speed_limit.hpp>

using namespace covopt;
using namespace covopt::optim;

namespace {

/// The bare head hit: a 5.145 kg robot of radius 60 mm, no covering.
Scene BareHit(HeadArea area) {
  Scene scene;
  scene.robot.mass_kg = 5.145;
  scene.robot.radius_m = 0.060;
  scene.robot.speed_m_per_s = 2.3;
  scene.covering.thickness_m = 0.0;
  scene.head.area = area;
  return scene;
}

/// The ranged trial: 16 mm of XPS Foamular 250 (catalog: E 16.71 MPa, ν 0.25 assumed,
/// strength 25 psi), head mass 3.7..5.8 kg, scalp 2..5 mm, the rest simulate's defaults.
constexpr double kXpsStrength_Pa = 172.368925e3;
UncertaintyBox XpsBox() {
  Scene scene;
  scene.covering = {16.71e6, 0.25, 0.016};
  return UncertaintyBox::FromScene(scene, std::vector<UncertainInput>{{"head-mass", 3.7, 5.8},
                                                                       {"scalp-thickness", 0.002, 0.005}});
}

}  // namespace

TEST_CASE("fracture criterion: a score's fracture ratio governs and makes it inadmissible", "[fracture]") {
  DesignScore score;
  score.laceration_ratio = 0.5;
  score.contusion_ratio = 0.6;
  score.fracture_ratio = 1.2;
  const DesignRule rule;
  CHECK(score.governing(rule).criterion == LimitingCriterion::kFracture);
  CHECK(score.governing(rule).ratio == 1.2);
  CHECK(score.worst_ratio() == 1.2);
  CHECK_FALSE(score.safe(1.0));
  CHECK_FALSE(score.admissible(rule));
  score.fracture_ratio = 0.7;
  CHECK(score.admissible(rule));
  CHECK(ToString(LimitingCriterion::kFracture) == "fracture");
  CHECK(rule.Parts() == std::vector<std::string>{"laceration", "contusion", "fracture", "full-compression", "crush", "law-validity"});
}

TEST_CASE("fracture criterion: the speed limit of a nose is set by its fracture force", "[fracture]") {
  SpeedLimitOptions options;
  const SpeedLimit forehead = MaxSafeSpeed(BareHit(HeadArea::kFrontal), options);
  const SpeedLimit nose = MaxSafeSpeed(BareHit(HeadArea::kNasal), options);
  REQUIRE(nose.status == SpeedLimitStatus::kLimited);
  CHECK(nose.limited_by == LimitingCriterion::kFracture);
  CHECK(nose.max_safe_speed_m_per_s < forehead.max_safe_speed_m_per_s);
  CHECK(nose.at_limit.fracture_ratio == Approx(1.0).epsilon(1e-6));
  // At the limit the peak force is the nasal bone's 450 N; just above, the impact is not admissible.
  Scene at = BareHit(HeadArea::kNasal);
  at.robot.speed_m_per_s = nose.max_safe_speed_m_per_s;
  CHECK(ExactPeaks(ImpactModel::FromScene(at)).peak_force_N == Approx(450.0).epsilon(1e-6));
  CHECK(JudgeImpact(at, options).admissible);
  at.robot.speed_m_per_s *= 1.001;
  CHECK_FALSE(JudgeImpact(at, options).admissible);
  // A safety factor derates the force: F at the limit is 450 N / 2.
  options.safety_factor = 2.0;
  at.robot.speed_m_per_s = MaxSafeSpeed(BareHit(HeadArea::kNasal), options).max_safe_speed_m_per_s;
  CHECK(ExactPeaks(ImpactModel::FromScene(at)).peak_force_N == Approx(225.0).epsilon(1e-6));
}

TEST_CASE("fracture criterion: the thinnest safe covering keeps the peak force within the fracture force",
          "[fracture]") {
  // The paper's scene struck on the jaw's side (600 N): the design's force must stay below it.
  Scene scene;
  scene.head.area = HeadArea::kMandibleSide;
  const ThinnestSafeCovering jaw = FindThinnestSafeCovering(scene, {});
  REQUIRE(jaw.continuous.feasible);
  CHECK(jaw.continuous.score.fracture_ratio <= 1.0 + 1e-9);
  CHECK(jaw.continuous.score.peaks.peak_force_N <= 600.0 * (1 + 1e-9));
  const ThinnestSafeCovering forehead = FindThinnestSafeCovering(Scene{}, {});
  REQUIRE(forehead.continuous.feasible);
  CHECK(forehead.continuous.score.peaks.peak_force_N > 600.0);  // the forehead's design would break the jaw
}

TEST_CASE("robust worst case counts crush: 16 mm XPS Foamular 250 crushes everywhere", "[fracture][robust]") {
  WorstCaseOptions options;
  options.compressive_strength_Pa = kXpsStrength_Pa;
  const WorstCase worst = FindWorstCase(XpsBox(), options);
  CHECK(worst.binding == LimitingCriterion::kCrush);
  CHECK(worst.crush_ratio > 15.0);
  CHECK(worst.governing_ratio == Approx(worst.crush_ratio));
  CHECK_FALSE(worst.admissible);
  // A sacrificial liner: the crush ratio is reported but does not bind.
  options.allow_crushing = true;
  const WorstCase liner = FindWorstCase(XpsBox(), options);
  CHECK(liner.binding != LimitingCriterion::kCrush);
  CHECK(liner.crush_ratio > 15.0);
}

TEST_CASE("robust probability counts crush: every sample of 16 mm XPS Foamular 250 is inadmissible",
          "[fracture][robust]") {
  InjuryProbabilityOptions options;
  options.samples = 2000;
  options.threads = 1;
  options.compressive_strength_Pa = kXpsStrength_Pa;
  const InjuryProbability p = EstimateInjuryProbability(XpsBox(), options);
  CHECK(p.crushed.count == 2000);
  CHECK(p.inadmissible.count == 2000);
  CHECK(p.contusion.count < 2000);  // the injury alone would have passed some samples
  options.allow_crushing = true;
  const InjuryProbability liner = EstimateInjuryProbability(XpsBox(), options);
  CHECK(liner.crushed.count == 2000);
  CHECK(liner.inadmissible.count < 2000);
}

TEST_CASE("robust worst case and probability count fracture", "[fracture][robust]") {
  Scene scene = BareHit(HeadArea::kNasal);
  const UncertaintyBox box =
      UncertaintyBox::FromScene(scene, std::vector<UncertainInput>{{"head-mass", 3.7, 5.8}});
  const WorstCase worst = FindWorstCase(box);
  CHECK(worst.binding == LimitingCriterion::kFracture);
  CHECK(worst.fracture_ratio > 5.0);  // 2.8 kN on a 450 N nose
  CHECK_FALSE(worst.admissible);
  InjuryProbabilityOptions options;
  options.samples = 500;
  options.threads = 1;
  const InjuryProbability p = EstimateInjuryProbability(box, options);
  CHECK(p.fracture.count == 500);
  CHECK(p.any.count == 500);
  CHECK(p.inadmissible.count == 500);
}

TEST_CASE("robust criterion: a bad compressive strength is refused naming it", "[fracture][robust]") {
  WorstCaseOptions options;
  options.compressive_strength_Pa = -1.0;
  CHECK_THROWS_WITH(FindWorstCase(XpsBox(), options), Catch::Matchers::Contains("compressive strength"));
}
