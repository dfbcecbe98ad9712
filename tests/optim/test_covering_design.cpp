// The covering design problems on the paper's scene (10 kg, 2 m/s, R_r 15 mm, free head):
// the continuous thinnest safe covering is the same from every global algorithm, seed and
// Ipopt starting point, and meets both limits; at 10 mm no E_c prevents contusion (Fig. 13);
// the ranking of the paper's Table IV materials is stable; the oracle's analytic gradient
// matches finite differences; infeasibility is an answer; bad options are rejected.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>
#include <thread>
#include <vector>

#include <covopt/optim/covering_design.hpp>

using namespace covopt;
using namespace covopt::optim;

namespace {

std::vector<CandidateMaterial> TableIv() {
  return {{"polystyrene 27.6 MPa", 27.6e6, 0.22},
          {"polystyrene 48.3 MPa", 48.3e6, 0.25},
          {"polyurethane 62.1 MPa", 62.1e6, 0.20},
          {"polyurethane 137.9 MPa", 137.9e6, 0.29}};
}

}  // namespace

TEST_CASE("The continuous thinnest safe covering is reproducible and meets both limits",
          "[design]") {
  const Scene scene;  // the paper's scene
  DesignOptions reference_options;
  const ThinnestSafeCovering reference = FindThinnestSafeCovering(scene, {}, reference_options);
  REQUIRE(reference.continuous.feasible);
  CHECK(reference.continuous.source == "ipopt");
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
            Approx(best.design.youngs_modulus_Pa).epsilon(1e-3));  // flat in E (DESIGN §5.7)
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

TEST_CASE("At 10 mm no modulus prevents contusion, at 15 mm one does (Fig. 13)", "[design]") {
  const Scene scene;
  const LeastInjuryAtThickness at_10 = MinimizeInjuryAtThickness(scene, 0.010, TableIv());
  CHECK(at_10.continuous.score.laceration_ratio < 1.0);
  CHECK(at_10.continuous.score.contusion_ratio > 1.0);
  CHECK(at_10.verdict == DesignVerdict::kNothingSafe);
  CHECK_FALSE(at_10.recommendation.has_value());
  // The 1-D minimum really is the minimum: nothing on a fine E_c grid beats it.
  const CoveringOracle oracle(scene, 0.25);
  for (int i = 0; i <= 400; ++i) {
    const double modulus = std::pow(10.0, 5.0 + 4.0 * i / 400.0);
    CHECK(oracle.Score({modulus, 0.010}).worst_ratio() >= at_10.continuous.score.worst_ratio() * (1 - 1e-9));
  }
  const LeastInjuryAtThickness at_15 = MinimizeInjuryAtThickness(scene, 0.015, TableIv());
  CHECK(at_15.continuous.score.safe(1.0));
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
