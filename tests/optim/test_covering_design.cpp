// The covering design problems on the paper's scene (10 kg, 2 m/s, R_r 15 mm, free head):
// the continuous thinnest admissible covering is the same from every global algorithm, seed
// and Ipopt starting point, and meets both limits; the default criterion (no full
// compression) against the paper's; at 10 mm no E_c prevents contusion (Fig. 13);
// the ranking of the paper's Table IV materials is stable; the oracle's analytic gradient
// matches finite differences; infeasibility is an answer; bad options are rejected.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <stdexcept>
#include <thread>
#include <vector>

#include <covopt/optim/covering_design.hpp>

using namespace covopt;
using namespace covopt::optim;

namespace {

/// Materials for the tests of the injury and travel criteria: declared not to crush, so the
/// crush criterion (tests/optim/test_crush_criterion.cpp) leaves them alone.
std::vector<CandidateMaterial> Elastic(std::vector<CandidateMaterial> materials) {
  for (CandidateMaterial& m : materials) m.crush_behaviour = covopt::materials::CrushBehaviour::kDoesNotCrush;
  return materials;
}

std::vector<CandidateMaterial> TableIv() {
  return Elastic({{"polystyrene 27.6 MPa", 27.6e6, 0.22},
                  {"polystyrene 48.3 MPa", 48.3e6, 0.25},
                  {"polyurethane 62.1 MPa", 62.1e6, 0.20},
                  {"polyurethane 137.9 MPa", 137.9e6, 0.29}});
}

}  // namespace

TEST_CASE("The continuous thinnest safe covering is reproducible and meets both limits",
          "[design]") {
  const Scene scene;  // the paper's scene
  DesignOptions reference_options;
  const ThinnestSafeCovering reference = FindThinnestSafeCovering(scene, {}, reference_options);
  REQUIRE(reference.continuous.feasible);
  CHECK(reference.continuous.source == "ipopt");  // the polish agrees with the bracket
  CHECK(reference.continuous.bracket.termination == Termination::kConverged);
  const DesignScore& best = reference.continuous.score;
  CHECK(best.laceration_ratio <= 1.0);
  CHECK(best.contusion_ratio <= 1.0);
  CHECK(best.contusion_ratio > 1.0 - 1e-6);  // contusion is the binding limit
  CHECK(best.design.thickness_m > 0.010);
  CHECK(best.design.thickness_m < 0.020);

  for (NloptAlgorithm algorithm : {NloptAlgorithm::kDirectL, NloptAlgorithm::kIsres, NloptAlgorithm::kMlsl}) {
    for (unsigned long seed : {1ul, 7ul, 20110509ul}) {
      DesignOptions options;
      options.global_algorithm = algorithm;
      options.seed = seed;
      const ThinnestSafeCovering run = FindThinnestSafeCovering(scene, {}, options);
      INFO(ToString(algorithm) << " seed " << seed);
      CHECK(run.continuous.score.design.thickness_m ==
            Approx(best.design.thickness_m).epsilon(1e-6));
      CHECK(run.continuous.score.design.youngs_modulus_Pa ==
            Approx(best.design.youngs_modulus_Pa).epsilon(1e-3));  // flat in E (docs/model.md §5 item 7)
    }
  }
}

TEST_CASE("The optimum does not depend on where the search starts", "[design]") {
  const Scene scene;
  const ThinnestSafeCovering reference = FindThinnestSafeCovering(scene, {});
  for (NloptAlgorithm algorithm : {NloptAlgorithm::kIsres, NloptAlgorithm::kMlsl}) {
    for (const CoveringDesign start : {CoveringDesign{0.2e6, 0.002}, CoveringDesign{500e6, 0.045},
                                       CoveringDesign{27.6e6, 0.015}}) {
      DesignOptions options;
      options.global_algorithm = algorithm;
      options.initial_design = start;
      const ThinnestSafeCovering run = FindThinnestSafeCovering(scene, {}, options);
      INFO(ToString(algorithm) << " from " << start.youngs_modulus_Pa << " Pa, " << start.thickness_m << " m");
      CHECK(run.continuous.source == "ipopt");
      CHECK(run.continuous.score.design.thickness_m ==
            Approx(reference.continuous.score.design.thickness_m).epsilon(1e-6));
    }
  }
}

TEST_CASE("At 10 mm no modulus prevents contusion, at 15 mm one does (Fig. 13, paper criterion)", "[design]") {
  const Scene scene;
  DesignOptions paper;
  paper.allow_full_compression = true;
  const LeastInjuryAtThickness at_10 = MinimizeInjuryAtThickness(scene, 0.010, TableIv(), paper);
  CHECK(at_10.criterion == DesignCriterion::kPaper);
  CHECK(at_10.continuous.score.laceration_ratio < 1.0);
  CHECK(at_10.continuous.score.contusion_ratio > 1.0);
  CHECK(at_10.verdict == DesignVerdict::kNothingSafe);
  CHECK_FALSE(at_10.recommendation.has_value());
  // The 1-D minimum really is the minimum: nothing on a fine E_c grid beats it.
  const CoveringOracle oracle(scene, 0.25);
  for (int i = 0; i <= 400; ++i) {
    const double modulus = std::pow(10.0, 5.0 + 4.0 * i / 400.0);
    CHECK(oracle.Score({modulus, 0.010}).worst_ratio() >= at_10.continuous.score.worst_ratio() * (1 - 1e-12));
  }
  const LeastInjuryAtThickness at_15 = MinimizeInjuryAtThickness(scene, 0.015, TableIv(), paper);
  CHECK(at_15.continuous.score.safe(1.0));
  CHECK(at_15.continuous.score.peaks.fully_compressed);  // safe only with the robot on bone
}

TEST_CASE("Under the default criterion the least injury at a thickness is over moduli that do not bottom out",
          "[design]") {
  const Scene scene;
  const CoveringOracle oracle(scene, 0.25);
  for (const double thickness : {0.010, 0.015, 0.016}) {
    const LeastInjuryAtThickness at = MinimizeInjuryAtThickness(scene, thickness, TableIv());
    INFO("b_c " << thickness);
    CHECK(at.criterion == DesignCriterion::kNoFullCompression);
    CHECK_FALSE(at.continuous.every_modulus_fully_compressed);
    CHECK_FALSE(at.continuous.score.peaks.fully_compressed);
    // Brute force: nothing on a fine grid of non-bottomed moduli beats it.
    for (int i = 0; i <= 400; ++i) {
      const DesignScore s = oracle.Score({std::pow(10.0, 5.0 + 4.0 * i / 400.0), thickness});
      if (!s.peaks.fully_compressed) CHECK(s.worst_ratio() >= at.continuous.score.worst_ratio() * (1 - 1e-12));
    }
    // Paper's "larger than 15 mm": 15 mm is not enough once bottoming out is failure, 16 mm is.
    CHECK(at.continuous.feasible == (thickness > 0.0151));
  }
  // 0.3 mm: no modulus up to 1 GPa keeps the covering from bottoming out; said so.
  const LeastInjuryAtThickness thin = MinimizeInjuryAtThickness(scene, 0.0003, {});
  CHECK(thin.continuous.every_modulus_fully_compressed);
  CHECK_FALSE(thin.continuous.feasible);
  CHECK(thin.verdict == DesignVerdict::kNothingSafe);
}

TEST_CASE("The default criterion moves the paper's optimum to a covering that does not bottom out", "[design]") {
  const Scene scene;
  DesignOptions paper;
  paper.allow_full_compression = true;
  const ThinnestSafeCovering old_optimum = FindThinnestSafeCovering(scene, {}, paper);
  const ThinnestSafeCovering new_optimum = FindThinnestSafeCovering(scene, {});
  REQUIRE(old_optimum.continuous.feasible);
  REQUIRE(new_optimum.continuous.feasible);
  CHECK(old_optimum.criterion == DesignCriterion::kPaper);
  CHECK(new_optimum.criterion == DesignCriterion::kNoFullCompression);
  // Paper's criterion: 14.2 mm at ~13 MPa, safe only with the robot on bone.
  CHECK(old_optimum.continuous.score.design.thickness_m == Approx(14.23e-3).margin(0.01e-3));
  CHECK(old_optimum.continuous.score.peaks.fully_compressed);
  // Default: ~15.06 mm at ~16 MPa, at the edge of full compression and of contusion at once.
  const DesignScore& best = new_optimum.continuous.score;
  CHECK(best.design.thickness_m == Approx(15.06e-3).margin(0.01e-3));
  CHECK(best.design.youngs_modulus_Pa == Approx(16.1e6).epsilon(0.01));
  CHECK_FALSE(best.peaks.fully_compressed);
  CHECK(best.compression_ratio == Approx(1.0).margin(1e-6));
  CHECK(best.contusion_ratio == Approx(1.0).margin(1e-6));
  CHECK(best.admissible(1.0, DesignCriterion::kNoFullCompression));
  // Slightly thinner, no modulus is admissible: the optimum is sharp.
  const CoveringOracle oracle(scene, 0.25);
  for (int i = 0; i <= 400; ++i) {
    const DesignScore s = oracle.Score({std::pow(10.0, 5.0 + 4.0 * i / 400.0), best.design.thickness_m - 1e-6});
    CHECK_FALSE(s.admissible(1.0, DesignCriterion::kNoFullCompression));
  }
}

TEST_CASE("A 2 kg robot is not made 'safe' by a thin covering that bottoms out at once", "[design]") {
  Scene scene;
  scene.robot.mass_kg = 2.0;
  const std::vector<CandidateMaterial> sponge = Elastic({{"sponge", 1.5e6, 0.25}});
  DesignOptions paper;
  paper.allow_full_compression = true;
  const ThinnestSafeCovering artefact = FindThinnestSafeCovering(scene, sponge, paper);
  REQUIRE_FALSE(artefact.bare_robot.safe(1.0));  // contusion 1.30 without a covering
  REQUIRE(artefact.recommendation.has_value());
  // The paper's criterion takes the thinnest sliver: fully compressed, force above the bare robot's.
  const CandidateOutcome& sliver = artefact.candidates[*artefact.recommendation];
  CHECK(*sliver.recommended_thickness_m <= 0.5e-3);
  CHECK(sliver.score.peaks.fully_compressed);
  const ThinnestSafeCovering honest = FindThinnestSafeCovering(scene, sponge);
  REQUIRE(honest.recommendation.has_value());
  const CandidateOutcome& real = honest.candidates[*honest.recommendation];
  CHECK_FALSE(real.score.peaks.fully_compressed);
  CHECK(*real.recommended_thickness_m > 2e-3);
  CHECK_FALSE(honest.continuous.score.peaks.fully_compressed);
  CHECK(honest.continuous.score.design.thickness_m > 1e-3);
}

TEST_CASE("Stock rounding that would pass the maximum thickness keeps the exact thickness and says so",
          "[design]") {
  const std::vector<CandidateMaterial> foam = Elastic({{"foam", 10.3e6, 0.25}});
  const ThinnestSafeCovering free = FindThinnestSafeCovering(Scene{}, foam);
  REQUIRE(free.recommendation.has_value());
  const double exact = *free.candidates[0].min_safe_thickness_m;
  const double stock = *free.candidates[0].recommended_thickness_m;
  REQUIRE(stock > exact);
  // Stock thicknesses are clean multiples of the step (no 0.018000000000000002).
  CHECK(std::abs(stock / 0.5e-3 - std::round(stock / 0.5e-3)) < 1e-12);
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", stock);  // the decimal it is meant to be, exactly
  CHECK(std::strtod(text, nullptr) == stock);
  DesignOptions tight;
  tight.space.max_thickness_m = 0.5 * (exact + stock);
  const ThinnestSafeCovering capped = FindThinnestSafeCovering(Scene{}, foam, tight);
  REQUIRE(capped.recommendation.has_value());
  const CandidateOutcome& c = capped.candidates[0];
  CHECK(*c.recommended_thickness_m == Approx(exact).margin(2e-6));
  REQUIRE(c.stock_thickness_beyond_max_m.has_value());
  CHECK(*c.stock_thickness_beyond_max_m == Approx(stock));
  CHECK(c.safe);
}

TEST_CASE("The Table IV ranking is stable and polystyrene 27.6 MPa comes first", "[design]") {
  const Scene scene;
  std::vector<std::string> first_order;
  for (NloptAlgorithm algorithm : {NloptAlgorithm::kDirectL, NloptAlgorithm::kMlsl}) {
    DesignOptions options;
    options.global_algorithm = algorithm;
    const ThinnestSafeCovering r = FindThinnestSafeCovering(scene, TableIv(), options);
    REQUIRE(r.verdict == DesignVerdict::kCoveringFound);
    REQUIRE(r.recommendation == 0u);
    std::vector<std::string> order;
    for (const CandidateOutcome& c : r.candidates) order.push_back(c.material.name);
    if (first_order.empty()) first_order = order;
    CHECK(order == first_order);
    const CandidateOutcome& top = r.candidates.front();
    CHECK(top.material.name == "polystyrene 27.6 MPa");
    REQUIRE(top.min_safe_thickness_m.has_value());
    // Thinner than the snapped thickness is unsafe, the recommended thickness is safe.
    const CoveringOracle oracle(scene, 0.22);
    CHECK_FALSE(oracle.ScoreMaterial({27.6e6, *top.min_safe_thickness_m - 2e-6}, 0.22).safe(1.0));
    CHECK(oracle.ScoreMaterial({27.6e6, *top.recommended_thickness_m}, 0.22).safe(1.0));
    CHECK(*top.recommended_thickness_m >= *top.min_safe_thickness_m);
    // No real material beats the continuous optimum.
    CHECK(*top.min_safe_thickness_m >= r.continuous.score.design.thickness_m);
  }
}

TEST_CASE("The oracle's analytic gradient matches finite differences", "[design]") {
  const CoveringOracle oracle(Scene{}, 0.25);
  for (const CoveringDesign design : {CoveringDesign{13e6, 0.014}, CoveringDesign{1e8, 0.006},
                                      CoveringDesign{1e6, 0.03}}) {
    RatioGradient g;
    (void)oracle.Score(design, g);
    const double u = std::log10(design.youngs_modulus_Pa), hu = 1e-6, hb = design.thickness_m * 1e-6;
    const DesignScore up_u = oracle.Score({std::pow(10.0, u + hu), design.thickness_m});
    const DesignScore dn_u = oracle.Score({std::pow(10.0, u - hu), design.thickness_m});
    const DesignScore up_b = oracle.Score({design.youngs_modulus_Pa, design.thickness_m + hb});
    const DesignScore dn_b = oracle.Score({design.youngs_modulus_Pa, design.thickness_m - hb});
    CHECK(g.laceration[0] == Approx((up_u.laceration_ratio - dn_u.laceration_ratio) / (2 * hu)).epsilon(1e-5));
    CHECK(g.contusion[0] == Approx((up_u.contusion_ratio - dn_u.contusion_ratio) / (2 * hu)).epsilon(1e-5));
    CHECK(g.laceration[1] == Approx((up_b.laceration_ratio - dn_b.laceration_ratio) / (2 * hb)).epsilon(1e-5));
    CHECK(g.contusion[1] == Approx((up_b.contusion_ratio - dn_b.contusion_ratio) / (2 * hb)).epsilon(1e-5));
  }
}

TEST_CASE("A safe bare robot and an impossible scene are answers, not errors", "[design]") {
  Scene slow;
  slow.robot.speed_m_per_s = 0.2;
  const ThinnestSafeCovering gentle = FindThinnestSafeCovering(slow, TableIv());
  CHECK(gentle.verdict == DesignVerdict::kBareRobotSafe);
  CHECK(gentle.bare_robot.safe(1.0));

  Scene violent;
  violent.robot.speed_m_per_s = 8.0;
  const ThinnestSafeCovering hopeless = FindThinnestSafeCovering(violent, TableIv());
  CHECK(hopeless.verdict == DesignVerdict::kNothingSafe);
  CHECK_FALSE(hopeless.continuous.feasible);
  CHECK_FALSE(hopeless.recommendation.has_value());
  REQUIRE(hopeless.candidates.size() == 4);
  for (const CandidateOutcome& c : hopeless.candidates) {
    CHECK_FALSE(c.safe);
    CHECK(c.margin < 0.0);
    CHECK_FALSE(c.min_safe_thickness_m.has_value());
  }
  // Least unsafe first.
  CHECK(hopeless.candidates.front().margin >= hopeless.candidates.back().margin);
}

TEST_CASE("A safety factor makes the design thicker", "[design]") {
  DesignOptions strict;
  strict.safety_factor = 1.2;
  const ThinnestSafeCovering a = FindThinnestSafeCovering(Scene{}, {});
  const ThinnestSafeCovering b = FindThinnestSafeCovering(Scene{}, {}, strict);
  REQUIRE(b.continuous.feasible);
  CHECK(b.continuous.score.design.thickness_m > a.continuous.score.design.thickness_m);
  CHECK(b.continuous.score.worst_ratio() <= 1.0 / 1.2);
}

TEST_CASE("Bad design options are rejected naming the option", "[design]") {
  DesignOptions bad;
  bad.safety_factor = 0.5;
  CHECK_THROWS_WITH(FindThinnestSafeCovering(Scene{}, {}, bad), Catch::Contains("safety factor"));
  bad = {};
  bad.space.max_thickness_m = -1;
  CHECK_THROWS_WITH(FindThinnestSafeCovering(Scene{}, {}, bad), Catch::Contains("max thickness"));
  CHECK_THROWS_WITH(MinimizeInjuryAtThickness(Scene{}, 0.0, {}), Catch::Contains("thickness"));
  Scene broken;
  broken.robot.speed_m_per_s = -1;
  CHECK_THROWS_WITH(FindThinnestSafeCovering(broken, {}), Catch::Contains("robot.speed"));
}

TEST_CASE("Design searches run concurrently from several threads with identical results", "[design]") {
  const std::vector<CandidateMaterial> materials = TableIv();
  const ThinnestSafeCovering reference = FindThinnestSafeCovering(Scene{}, materials);
  ThinnestSafeCovering results[2];
  std::thread a([&] { results[0] = FindThinnestSafeCovering(Scene{}, materials); });
  std::thread b([&] { results[1] = FindThinnestSafeCovering(Scene{}, materials); });
  a.join();
  b.join();
  for (const ThinnestSafeCovering& r : results) {
    CHECK(r.continuous.score.design.thickness_m == reference.continuous.score.design.thickness_m);
    CHECK(r.continuous.score.design.youngs_modulus_Pa == reference.continuous.score.design.youngs_modulus_Pa);
    REQUIRE(r.candidates.size() == reference.candidates.size());
    for (std::size_t i = 0; i < r.candidates.size(); ++i) {
      CHECK(r.candidates[i].material.name == reference.candidates[i].material.name);
      CHECK(r.candidates[i].min_safe_thickness_m == reference.candidates[i].min_safe_thickness_m);
    }
  }
}
