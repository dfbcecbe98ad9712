// The no-crush criterion and the one margin over every criterion (docs/model.md §6, §12): a
// material whose peak compressive stress times the safety factor exceeds its strength is
// inadmissible, a strength equal to that stress passes, the safety factor halves the allowed
// stress and reserves the covering's travel, the governing criterion is named, materials of
// unknown strength are refused unless allowed, and a probability target is met on the upper
// end of the 95 % interval only.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/optim/covering_design.hpp>
#include <covopt/optim/design.hpp>
#include <covopt/optim/robust_design.hpp>
#include <covopt/optim/speed_limit.hpp>

using namespace covopt;
using namespace covopt::optim;
using covopt::materials::CrushBehaviour;

namespace {

CandidateMaterial Crushing(const std::string& name, double modulus_Pa, double strength_Pa) {
  CandidateMaterial m{name, modulus_Pa, 0.25};
  m.crush_behaviour = CrushBehaviour::kCrushes;
  m.compressive_strength_Pa = strength_Pa;
  return m;
}

CandidateMaterial NotCrushing(const std::string& name, double modulus_Pa) {
  CandidateMaterial m{name, modulus_Pa, 0.25};
  m.crush_behaviour = CrushBehaviour::kDoesNotCrush;
  return m;
}

/// The score of `material` at `thickness_m` on the paper's scene, with its crush check.
DesignScore ScoreOn(const CandidateMaterial& material, double thickness_m, const Scene& scene = Scene{}) {
  const CoveringOracle oracle(scene, 0.25);
  DesignScore score = oracle.ScoreMaterial({material.youngs_modulus_Pa, thickness_m}, material.poisson_ratio);
  CheckCrush(material, score);
  return score;
}

/// The paper's scene at 1.5 m/s: soft coverings keep every ratio below 1/2 within 50 mm.
Scene Slow() {
  Scene scene;
  scene.robot.speed_m_per_s = 1.5;
  return scene;
}

}  // namespace

TEST_CASE("A strength equal to the peak compressive stress passes, a hair less crushes", "[design][crush]") {
  // 40 mm of a 5 MPa foam on the paper's scene: injury and travel ratios well below 1/2.
  const double thickness = 0.040, modulus = 5e6;
  const DesignScore probe = ScoreOn(NotCrushing("probe", modulus), thickness, Slow());
  const double stress = probe.peaks.max_compressive_stress_Pa;
  REQUIRE(probe.worst_ratio() < 0.5);
  REQUIRE(probe.compression_ratio < 0.5);
  REQUIRE(probe.crush_check == CrushCheck::kDoesNotCrush);
  CHECK(probe.admissible(DesignRule{}));

  const DesignScore exact = ScoreOn(Crushing("exact", modulus, stress), thickness, Slow());
  CHECK(exact.crush_check == CrushCheck::kChecked);
  CHECK(exact.crush_ratio == 1.0);
  CHECK(exact.admissible(DesignRule{}));
  CHECK(exact.governing(DesignRule{}).criterion == LimitingCriterion::kCrush);
  CHECK(exact.margin(DesignRule{}) == 0.0);

  const DesignScore weaker = ScoreOn(Crushing("weaker", modulus, stress * (1 - 1e-12)), thickness, Slow());
  CHECK_FALSE(weaker.admissible(DesignRule{}));
  CHECK(weaker.margin(DesignRule{}) < 0.0);
  // A sacrificial liner: reported, not counted.
  DesignRule liner;
  liner.crushing_allowed = true;
  CHECK(weaker.admissible(liner));
  CHECK(weaker.governing(liner).criterion != LimitingCriterion::kCrush);
}

TEST_CASE("A safety factor of 2 halves the allowed stress and the covering's travel", "[design][crush]") {
  const double thickness = 0.040, modulus = 5e6;
  const Scene slow = Slow();
  const double stress = ScoreOn(NotCrushing("probe", modulus), thickness, slow).peaks.max_compressive_stress_Pa;
  DesignRule two;
  two.safety_factor = 2.0;
  CHECK(ScoreOn(Crushing("twice", modulus, 2 * stress), thickness, slow).admissible(two));
  CHECK_FALSE(ScoreOn(Crushing("just under", modulus, 2 * stress * (1 - 1e-12)), thickness, slow).admissible(two));
  CHECK(ScoreOn(Crushing("once", modulus, stress), thickness, slow).admissible(DesignRule{}));
  CHECK_FALSE(ScoreOn(Crushing("once", modulus, stress), thickness, slow).admissible(two));

  // Travel: the thinnest design under SF 2 uses at most half the covering's travel
  // (δ_max <= t1 + 0.8 b_c / 2), and a little thinner uses more.
  const Scene& scene = slow;
  DesignOptions options;
  options.safety_factor = 2.0;
  options.thickness_step_m = 0.0;
  const std::vector<CandidateMaterial> rubber = {NotCrushing("rubber", 3e6)};
  const ThinnestSafeCovering design = FindThinnestSafeCovering(scene, rubber, options);
  REQUIRE(design.candidates.front().safe);
  const DesignScore& at = design.candidates.front().score;
  const double t1 = 0.8 * scene.scalp.thickness_m;
  CHECK(at.peaks.max_penetration_m <= t1 + 0.8 * at.design.thickness_m / 2 * (1 + 1e-12));
  CHECK(2 * at.compression_ratio <= 1.0);
  CHECK(design.candidates.front().score.governing(options.rule()).criterion == LimitingCriterion::kFullCompression);
  const DesignScore thinner = ScoreOn(rubber.front(), at.design.thickness_m - 2e-6, scene);
  CHECK(2 * thinner.compression_ratio > 1.0);
  // The reserve is real: at SF 1 the same material is admissible thinner, fully using its travel.
  const ThinnestSafeCovering once = FindThinnestSafeCovering(scene, rubber, DesignOptions{});
  CHECK(*once.candidates.front().recommended_thickness_m < at.design.thickness_m);
  // And the SF-2 design takes more than the SF-1 speed before it bottoms out.
  Scene faster = scene;
  faster.covering = {3e6, 0.25, at.design.thickness_m};
  faster.robot.speed_m_per_s *= 1.3;
  CHECK_FALSE(ExactPeaks(ImpactModel::FromScene(faster)).fully_compressed);
}

TEST_CASE("The covering's travel ratio leaves the scalp out and is 1 at full compression", "[design][crush]") {
  const Scene scene;
  const DesignScore s = ScoreOn(NotCrushing("foam", 10e6), 0.020);
  const double t1 = 0.8 * scene.scalp.thickness_m, travel = 0.8 * 0.020;
  CHECK(s.compression_ratio == Approx((s.peaks.max_penetration_m - t1) / travel).epsilon(1e-14));
  CHECK(s.peaks.covering_travel_start_m == Approx(t1).epsilon(1e-15));
  // A stiff covering that stops inside the scalp's travel uses none of its own.
  const DesignScore stiff = ScoreOn(NotCrushing("stiff", 900e6), 0.050);
  if (stiff.peaks.max_penetration_m < t1) CHECK(stiff.compression_ratio == 0.0);
  // The bare robot has no covering travel.
  CHECK(CoveringOracle(scene, 0.25).ScoreBare().compression_ratio == 0.0);
}

TEST_CASE("The thinnest design of a crushing material is set by its strength, and is thicker", "[design][crush]") {
  const Scene scene;
  DesignOptions options;
  options.thickness_step_m = 0.0;
  const CandidateMaterial elastic = NotCrushing("elastic", 16.7e6);
  const ThinnestSafeCovering free = FindThinnestSafeCovering(scene, std::vector{elastic}, options);
  REQUIRE(free.candidates.front().safe);
  const double stress = free.candidates.front().score.peaks.max_compressive_stress_Pa;
  // FOAMULAR 250's 25 psi: crushes at every thickness up to 50 mm.
  const CandidateMaterial xps = Crushing("xps", 16.7e6, 172.4e3);
  const ThinnestSafeCovering crushed = FindThinnestSafeCovering(scene, std::vector{xps}, options);
  CHECK_FALSE(crushed.candidates.front().safe);
  CHECK(crushed.candidates.front().score.governing(options.rule()).criterion == LimitingCriterion::kCrush);
  CHECK(crushed.candidates.front().score.crush_ratio > 5.0);
  // A strength a little above the stress at the free optimum: admissible, no thinner than it.
  const CandidateMaterial strong = Crushing("strong", 16.7e6, 1.05 * stress);
  const ThinnestSafeCovering held = FindThinnestSafeCovering(scene, std::vector{strong}, options);
  REQUIRE(held.candidates.front().safe);
  CHECK(*held.candidates.front().min_safe_thickness_m >= *free.candidates.front().min_safe_thickness_m - 1e-6);
  CHECK(held.candidates.front().score.crush_ratio <= 1.0);
  // The continuous optimum carries the strength it would need.
  CHECK(crushed.continuous.score.required_strength_Pa(1.0) == crushed.continuous.score.peaks.max_compressive_stress_Pa);
}

TEST_CASE("Unknown strength is refused unless allowed, then warned", "[design][crush]") {
  DesignRequest request;
  request.materials = {CandidateMaterial{"mystery", 5e6, 0.25}};  // crush behaviour unknown
  const DesignResult refused = Design(request);
  REQUIRE(refused.ok());
  CHECK_FALSE(refused.recommendation.has_value());
  CHECK(refused.verdict == DesignVerdict::kNoSafeMaterial);
  CHECK(refused.message.find("unknown strength") != std::string::npos);
  request.options.allow_unknown_strength = true;
  const DesignResult allowed = Design(request);
  REQUIRE(allowed.recommendation.has_value());
  bool warned = false;
  for (const std::string& w : allowed.warnings) warned = warned || w.find("unverified for crushing") != std::string::npos;
  CHECK(warned);
  // Every verdict says what it covers, and what the standard says of the head.
  REQUIRE(allowed.scope.size() == 2);
  CHECK(allowed.scope[0].find("not crushed") != std::string::npos);
  CHECK(allowed.scope[1].find("A.3.2") != std::string::npos);
  CHECK(allowed.scope[1].find("130 N") != std::string::npos);
  CHECK(allowed.rule.Parts() ==
        std::vector<std::string>{"laceration", "contusion", "fracture", "full-compression", "crush", "law-validity"});
}

TEST_CASE("A crushing material's candidate of bad strength is bad input", "[design][crush]") {
  const std::vector<CandidateMaterial> bad = {Crushing("zero", 5e6, 0.0)};
  CHECK_THROWS_WITH(FindThinnestSafeCovering(Scene{}, bad), Catch::Contains("compressive strength"));
}

TEST_CASE("A probability target is met on the upper end of the 95 % interval", "[robust][crush]") {
  // 10 of 1000 is a 1 % estimate whose interval reaches 1.8 %: not shown to be <= 1 %.
  const std::optional<std::uint64_t> allowed = MostEventsWithUpperBoundWithin(0.01, 1000);
  REQUIRE(allowed.has_value());
  CHECK(*allowed < 10);
  CHECK(WilsonEstimate(*allowed, 1000).ci95_high <= 0.01);
  CHECK(WilsonEstimate(*allowed + 1, 1000).ci95_high > 0.01);
  CHECK(WilsonEstimate(10, 1000).ci95_high > 0.01);
  // Brute force over every count.
  for (std::uint64_t n : {400u, 1000u, 12345u}) {
    std::uint64_t most = 0;
    bool any = false;
    for (std::uint64_t k = 0; k <= n; ++k) {
      if (WilsonEstimate(k, n).ci95_high <= 0.02) {
        most = k;
        any = true;
      }
    }
    const std::optional<std::uint64_t> fast = MostEventsWithUpperBoundWithin(0.02, n);
    REQUIRE(fast.has_value() == any);
    if (any) CHECK(*fast == most);
  }
  // Too few samples to show 1 %: even none failing leaves the bound at 3.7 %.
  CHECK_FALSE(MostEventsWithUpperBoundWithin(0.01, 100).has_value());
  Scene scene;
  const std::vector<UncertainInput> inputs = {{"head-mass", 3.7, 5.8}};
  const UncertaintyBox box = UncertaintyBox::FromScene(scene, inputs);
  ProbabilityDesignOptions options;
  options.sampling.samples = 100;
  options.max_probability = 0.01;
  CHECK_THROWS_WITH(FindProbabilityDesign(box, {}, options), Catch::Contains("needs at least 381 samples"));
}

TEST_CASE("The speed limit of a crushing covering is where SF x stress reaches its strength", "[speed-limit][crush]") {
  Scene scene;
  scene.covering = {16.7e6, 0.25, 0.016};
  for (const double sf : {1.0, 2.0}) {
    SpeedLimitOptions options;
    options.safety_factor = sf;
    options.covering_compressive_strength_Pa = 1.5e6;
    const SpeedLimit limit = MaxSafeSpeed(scene, options);
    INFO("SF " << sf);
    REQUIRE(limit.status == SpeedLimitStatus::kLimited);
    CHECK(limit.limited_by == LimitingCriterion::kCrush);
    CHECK(sf * limit.at_limit.crush_ratio == Approx(1.0).epsilon(1e-9));
    Scene below = scene, above = scene;
    below.robot.speed_m_per_s = limit.max_safe_speed_m_per_s * (1 - 1e-7);
    above.robot.speed_m_per_s = limit.max_safe_speed_m_per_s * (1 + 1e-7);
    CHECK(JudgeImpact(below, options).admissible);
    CHECK_FALSE(JudgeImpact(above, options).admissible);
    // Without the strength the limit is higher (contusion or compression binds later).
    SpeedLimitOptions unchecked = options;
    unchecked.covering_compressive_strength_Pa = 0.0;
    CHECK(MaxSafeSpeed(scene, unchecked).max_safe_speed_m_per_s > limit.max_safe_speed_m_per_s);
    unchecked.allow_crushing = true;
    unchecked.covering_compressive_strength_Pa = 1.5e6;
    CHECK(MaxSafeSpeed(scene, unchecked).limited_by != LimitingCriterion::kCrush);
  }
}

TEST_CASE("The speed limit's travel reserve under a safety factor", "[speed-limit][crush]") {
  Scene scene;
  scene.covering = {3e6, 0.25, 0.030};
  SpeedLimitOptions options;
  options.safety_factor = 2.0;
  options.limits.laceration_tensile_stress_Pa = 1e12;  // only the travel binds
  options.limits.contusion_energy_density_J_per_m2 = 1e12;
  const SpeedLimit limit = MaxSafeSpeed(scene, options);
  REQUIRE(limit.limited_by == LimitingCriterion::kFullCompression);
  CHECK(limit.at_limit.compression_ratio == Approx(0.5).epsilon(1e-9));
}
