// How the judging commands count the covering's law (issue 35): the travel
// rule ("full-compression" / "within-curve") is a limit only with keep_travel; the law's validity
// ("law-validity") counts always, so a fully compressed Hertz covering limits the speed at its
// full compression unless the paper's criterion accepts it; a foam used up is within its law and
// is reported at its own speed. Each limit is checked against a brute-force bisection on the
// verdict itself.
#include <cmath>
#include <memory>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/core/compressive_curve.hpp>
#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/core/verdict.hpp>
#include <covopt/optim/body_region_check.hpp>
#include <covopt/optim/speed_limit.hpp>
#include <covopt/optim/verdicts.hpp>

#include "vn600_curve.hpp"

namespace {

using covopt::CompressiveCurve;
using covopt::ImpactModel;
using covopt::ImpactPeaks;
using covopt::Scene;
using covopt::optim::LimitingCriterion;
using covopt::optim::MaxSafeSpeed;
using covopt::optim::SpeedLimit;
using covopt::optim::SpeedLimitOptions;
using covopt::optim::SpeedLimitStatus;

std::shared_ptr<const CompressiveCurve> Vn600() { return covopt::testing::Vn600Curve(); }

Scene FoamScene(double thickness_m) {
  Scene scene;
  scene.robot.radius_m = 0.015;
  scene.covering = covopt::CoveringSpec{
      .youngs_modulus_Pa = 1e6, .poisson_ratio = 0.0, .thickness_m = thickness_m, .compressive_curve = Vn600()};
  return scene;
}

/// A stiff Hertz covering (ν 0.3, not a solid elastomer) on a light robot: it bottoms out
/// before any injury ratio reaches 1.
Scene HertzScene() {
  Scene scene;
  scene.robot.mass_kg = 1.0;
  scene.robot.radius_m = 0.015;
  scene.covering = covopt::CoveringSpec{.youngs_modulus_Pa = 5.884e6, .poisson_ratio = 0.3, .thickness_m = 0.02};
  return scene;
}

/// The head verdict of the impact at `speed`, as the limit search judges it.
bool Safe(const Scene& base, double speed, const SpeedLimitOptions& options) {
  Scene scene = base;
  scene.robot.speed_m_per_s = speed;
  const ImpactPeaks peaks = covopt::ExactPeaks(ImpactModel::FromScene(scene));
  return covopt::optim::HeadVerdict(scene, peaks, options).safe();
}

/// The largest speed whose verdict is safe, by bisection on the verdict (monotone in the speed).
double BruteForceLimit(const Scene& scene, const SpeedLimitOptions& options) {
  double lo = 1e-6, hi = 100.0;
  if (!Safe(scene, lo, options)) return 0.0;
  if (Safe(scene, hi, options)) return hi;
  for (int i = 0; i < 200; ++i) {
    const double mid = std::sqrt(lo * hi);
    (Safe(scene, mid, options) ? lo : hi) = mid;
  }
  return lo;
}

bool IsInjury(LimitingCriterion c) {
  return c == LimitingCriterion::kLaceration || c == LimitingCriterion::kContusion ||
         c == LimitingCriterion::kFracture;
}

}  // namespace

TEST_CASE("law-validity: a design rule that counts always and is not derated", "[judging_law]") {
  covopt::Verdict v;
  v.safety_factor = 2.0;
  v.Add("laceration", covopt::CriterionPart::kInjury, "Pa", 0.1e6, 1e6, "Park et al. 2011");
  const covopt::Criterion& within = covopt::AddLawValidity(v, true);
  CHECK(within.name == covopt::kLawValidityRule);
  CHECK(within.counted);
  CHECK(within.passed);
  CHECK(within.derated_limit == 1.0);
  CHECK(v.safe());
  covopt::Verdict out;
  out.safety_factor = 1.0;
  out.Add("laceration", covopt::CriterionPart::kInjury, "Pa", 0.1e6, 1e6, "Park et al. 2011");
  covopt::AddLawValidity(out, false);
  CHECK(out.injury_safe());
  CHECK_FALSE(out.design_rules_met());
  CHECK_FALSE(out.safe());
  CHECK(out.governing_name() == covopt::kLawValidityRule);
  // How far along its limits: the validity ratio is the value against 1, not derated, so at SF 2
  // a validity ratio of 0.8 governs over a laceration ratio of 0.3 (derated: 0.6) and leaves a
  // margin of 0.2; the same ratio as an injury's would be 1.6, unsafe.
  covopt::Verdict along;
  along.safety_factor = 2.0;
  along.Add("laceration", covopt::CriterionPart::kInjury, "Pa", 0.3e6, 1e6, "Park et al. 2011");
  const covopt::Criterion& c = covopt::AddLawValidity(along, true, 0.8);
  CHECK(c.value == 0.8);
  CHECK(c.limit == 1.0);
  CHECK(c.derated_limit == 1.0);
  CHECK(c.ratio == Approx(0.4));
  CHECK(along.safe());
  CHECK(along.governing_name() == covopt::kLawValidityRule);
  CHECK(along.margin() == Approx(0.2));
  covopt::AddLawValidity(along, false, 1.25);  // out of it: fails, margin -0.25
  CHECK_FALSE(along.safe());
  CHECK(along.margin() == Approx(-0.25));
}

TEST_CASE("judging a foam head without the travel rule: injury limits, the used-up speed reported",
          "[judging_law]") {
  for (double h : {0.005, 0.01, 0.02}) {
    CAPTURE(h);
    const Scene scene = FoamScene(h);
    SpeedLimitOptions judged;
    judged.keep_travel = false;
    const SpeedLimit limit = MaxSafeSpeed(scene, judged);
    REQUIRE(limit.status == SpeedLimitStatus::kLimited);
    CHECK(IsInjury(limit.limited_by));
    CHECK(limit.covering_law == "foam");
    CHECK(limit.validity.within);
    // The layer is used up well below the limit: said, with its own speed (the energy balance at
    // the curve's end), and checked against the exact path on either side of it.
    REQUIRE(limit.covering_used_up_m_per_s.has_value());
    const double used_up = *limit.covering_used_up_m_per_s;
    CHECK(used_up < limit.max_safe_speed_m_per_s);
    CHECK_THAT(limit.message, Catch::Contains("covering used up at v = "));
    Scene below = scene, above = scene;
    below.robot.speed_m_per_s = used_up * (1.0 - 1e-9);
    above.robot.speed_m_per_s = used_up * (1.0 + 1e-9);
    CHECK_FALSE(covopt::ExactPeaks(ImpactModel::FromScene(below)).fully_compressed);
    CHECK(covopt::ExactPeaks(ImpactModel::FromScene(above)).fully_compressed);
    // The answer is the verdict's own limit.
    CHECK(limit.max_safe_speed_m_per_s == Approx(BruteForceLimit(scene, judged)).epsilon(1e-9));
    // With the travel rule kept the limit is the used-up speed at most (today's rule), and lower.
    SpeedLimitOptions kept;
    const SpeedLimit travel = MaxSafeSpeed(scene, kept);
    CHECK(travel.limited_by == LimitingCriterion::kFullCompression);
    CHECK(travel.max_safe_speed_m_per_s <= used_up * (1.0 + 1e-12));
    CHECK(travel.max_safe_speed_m_per_s < limit.max_safe_speed_m_per_s);
  }
}

TEST_CASE("a foam head judged without the travel rule is never below the bare robot", "[judging_law]") {
  Scene bare = FoamScene(0.01);
  bare.covering.thickness_m = 0.0;
  SpeedLimitOptions judged;
  judged.keep_travel = false;
  const double bare_limit = MaxSafeSpeed(bare, judged).max_safe_speed_m_per_s;
  for (double h : {0.005, 0.01, 0.02, 0.04}) {
    CAPTURE(h);
    CHECK(MaxSafeSpeed(FoamScene(h), judged).max_safe_speed_m_per_s >= bare_limit);
  }
}

TEST_CASE("a fully compressed Hertz covering is limited by law-validity without the travel rule",
          "[judging_law]") {
  const Scene scene = HertzScene();
  SpeedLimitOptions kept;  // the library's default: today's rule
  const SpeedLimit travel = MaxSafeSpeed(scene, kept);
  REQUIRE(travel.limited_by == LimitingCriterion::kFullCompression);
  CHECK(travel.covering_law == "hertz");

  SpeedLimitOptions judged;
  judged.keep_travel = false;
  const SpeedLimit validity = MaxSafeSpeed(scene, judged);
  CHECK(validity.limited_by == LimitingCriterion::kLawValidity);
  // At SF 1 the travel rule and the law's validity both end at full compression.
  CHECK(validity.max_safe_speed_m_per_s == Approx(travel.max_safe_speed_m_per_s).epsilon(1e-12));
  CHECK(validity.max_safe_speed_m_per_s == Approx(BruteForceLimit(scene, judged)).epsilon(1e-9));
  CHECK(validity.validity.within);
  // The used-up speed is the limit itself here: not said as a separate speed.
  REQUIRE(validity.covering_used_up_m_per_s.has_value());
  CHECK(*validity.covering_used_up_m_per_s == Approx(validity.max_safe_speed_m_per_s).epsilon(1e-9));
  CHECK_THAT(validity.message, !Catch::Contains("covering used up"));

  // A safety factor reserves travel under the travel rule only: the validity is the model's.
  kept.safety_factor = judged.safety_factor = 1.5;
  const SpeedLimit reserved = MaxSafeSpeed(scene, kept);
  const SpeedLimit derated = MaxSafeSpeed(scene, judged);
  CHECK(reserved.max_safe_speed_m_per_s < derated.max_safe_speed_m_per_s);
  CHECK(derated.max_safe_speed_m_per_s == Approx(BruteForceLimit(scene, judged)).epsilon(1e-9));

  // The paper's criterion accepts full compression: the law-validity criterion passes past it.
  SpeedLimitOptions paper;
  paper.keep_travel = false;
  paper.allow_full_compression = true;
  const SpeedLimit accepted = MaxSafeSpeed(scene, paper);
  CHECK(accepted.max_safe_speed_m_per_s > validity.max_safe_speed_m_per_s);
  CHECK(accepted.limited_by != LimitingCriterion::kLawValidity);
  CHECK(accepted.validity.within);
  CHECK(accepted.max_safe_speed_m_per_s == Approx(BruteForceLimit(scene, paper)).epsilon(1e-9));
}

TEST_CASE("simulate's verdict: law-validity counts, the travel rule only with keep_travel", "[judging_law]") {
  Scene scene = HertzScene();
  scene.robot.speed_m_per_s = 10.0;  // far past full compression
  const ImpactPeaks peaks = covopt::ExactPeaks(ImpactModel::FromScene(scene));
  REQUIRE(peaks.fully_compressed);
  const covopt::optim::CoveringCrushCheck crush;
  const covopt::Verdict judged = covopt::optim::SimulationVerdict(scene, peaks, {}, 1.0, crush);
  const covopt::Criterion* validity = judged.Find(covopt::kLawValidityRule);
  REQUIRE(validity != nullptr);
  CHECK_FALSE(validity->passed);
  CHECK_FALSE(judged.safe());
  const covopt::Criterion* travel = judged.Find(covopt::optim::kFullCompressionRule);
  REQUIRE(travel != nullptr);
  CHECK_FALSE(travel->counted);
  const covopt::Verdict kept = covopt::optim::SimulationVerdict(scene, peaks, {}, 1.0, crush, false, true);
  CHECK(kept.Find(covopt::optim::kFullCompressionRule)->counted);
  const covopt::Verdict paper = covopt::optim::SimulationVerdict(scene, peaks, {}, 1.0, crush, true);
  CHECK(paper.Find(covopt::kLawValidityRule)->passed);

  // A foam used up is within its law: only the injury criteria can make it unsafe.
  Scene foam = FoamScene(0.01);
  foam.robot.speed_m_per_s = 0.5;  // used up at about 0.2 m/s, injury-limited above 1 m/s
  const ImpactPeaks foam_peaks = covopt::ExactPeaks(ImpactModel::FromScene(foam));
  REQUIRE(foam_peaks.fully_compressed);
  const covopt::Verdict used_up = covopt::optim::SimulationVerdict(foam, foam_peaks, {}, 1.0, crush);
  CHECK(used_up.Find(covopt::kLawValidityRule)->passed);
  CHECK_FALSE(used_up.Find(covopt::optim::kWithinCurveRule)->counted);
  CHECK(used_up.safe());
  CHECK_FALSE(covopt::optim::SimulationVerdict(foam, foam_peaks, {}, 1.0, crush, false, true).safe());
}

TEST_CASE("a design score out of its law's validity is never safe", "[judging_law]") {
  covopt::optim::DesignScore score;
  score.design.thickness_m = 0.01;
  score.peaks.covering_law = covopt::CoveringLaw::kHertz;
  const covopt::optim::DesignRule rule;
  CHECK(covopt::optim::HeadVerdict(score, {}, rule, 0.0).safe());
  score.validity = {false, "solid elastomer beyond its strain limit"};
  const covopt::Verdict v = covopt::optim::HeadVerdict(score, {}, rule, 0.0);
  CHECK_FALSE(v.safe());
  CHECK_FALSE(v.Find(covopt::kLawValidityRule)->passed);
}

TEST_CASE("the body regions' options keep the travel only when asked", "[judging_law]") {
  using covopt::optim::BodyRegionOptionsOf;
  CHECK_FALSE(BodyRegionOptionsOf(1.0, false, false, false, nullptr).keep_travel);
  CHECK(BodyRegionOptionsOf(1.0, false, false, false, nullptr, true).keep_travel);
  CHECK_FALSE(BodyRegionOptionsOf(1.0, true, false, false, nullptr, true).keep_travel);
}
