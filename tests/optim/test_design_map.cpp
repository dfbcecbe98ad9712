// The design map (optim/design_map.hpp): the chosen design scored on it as the optimiser scored
// it; the map's limit contours and the optimiser's admissibility agree at every grid point;
// an independent time-path computation of a few cells; the contusion ratio falls with the
// thickness and with a softer covering wherever the covering is not bottomed out
// (docs/model.md §6: "a softer covering at that thickness bottoms out, a stiffer one exceeds
// the contusion limit"); the continuous optimum as the chosen design; grid sizes out of range.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <covopt/core.hpp>
#include <covopt/materials.hpp>
#include <covopt/optim.hpp>
#include <covopt/optim/design_map.hpp>

using namespace covopt;
using namespace covopt::optim;

namespace {

DesignRequest CatalogRequest(double safety_factor) {
  DesignRequest request;
  request.materials = SelectCandidates(materials::Catalog::BuiltIn());
  request.options.safety_factor = safety_factor;
  // Room for a material that holds over its stated uncertainty at SF 2 (the default answer).
  request.options.space.max_thickness_m = 0.1;
  return request;
}

/// Every criterion the map draws holds at a point (SF × ratio <= 1).
bool OnSafeSideOfEveryContour(const DesignMap& map, const DesignScore& s) {
  for (const LimitingCriterion c : map.criteria) {
    if (map.rule.safety_factor * CriterionRatio(s, c, map.rule) > 1.0) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("the design map scores the recommendation as the optimiser did, and its contours are the optimiser's "
          "criteria",
          "[design_map]") {
  for (const double sf : {1.0, 2.0}) {
    CAPTURE(sf);
    const DesignRequest request = CatalogRequest(sf);
    const DesignResult result = Design(request);
    REQUIRE(result.recommendation);
    const DesignMap map = ComputeDesignMap(request, result);
    REQUIRE(map.thickness_m.size() == 41);
    REQUIRE(map.modulus_Pa.size() == 31);
    REQUIRE(map.scores.size() == 41 * 31);

    // The chosen design: the recommendation, scored with its material's ν and crush check.
    const CandidateOutcome& rec = result.candidates[*result.recommendation];
    REQUIRE(map.chosen);
    REQUIRE(map.chosen_score);
    CHECK(map.chosen->material == rec.material.name);
    CHECK(map.chosen->design.thickness_m == *rec.recommended_thickness_m);
    CHECK(map.chosen->admissible);
    CHECK(map.poisson_ratio == rec.material.poisson_ratio);
    CHECK(map.chosen_score->laceration_ratio == rec.score.laceration_ratio);
    CHECK(map.chosen_score->contusion_ratio == rec.score.contusion_ratio);
    CHECK(map.chosen_score->compression_ratio == rec.score.compression_ratio);
    CHECK(map.chosen_score->crush_ratio == rec.score.crush_ratio);
    CHECK(map.chosen_score->governing(map.rule).ratio == rec.score.governing(result.rule).ratio);
    CHECK(map.chosen_score->governing(map.rule).criterion == rec.score.governing(result.rule).criterion);
    CHECK(map.chosen_score->admissible(map.rule));

    // The grid spans the chosen design; its axes increase (the modulus geometrically).
    CHECK(map.thickness_m.front() <= map.chosen->design.thickness_m);
    CHECK(map.thickness_m.back() >= map.chosen->design.thickness_m);
    CHECK(map.modulus_Pa.front() <= map.chosen->design.youngs_modulus_Pa);
    CHECK(map.modulus_Pa.back() >= map.chosen->design.youngs_modulus_Pa);
    for (std::size_t j = 1; j + 1 < map.modulus_Pa.size(); ++j) {
      CHECK(map.modulus_Pa[j] / map.modulus_Pa[j - 1] == Approx(map.modulus_Pa[j + 1] / map.modulus_Pa[j]));
    }

    // The default rule: laceration, contusion, fracture, full compression, and crush only for
    // a material that crushes.
    const bool crushes = rec.material.crush_behaviour == materials::CrushBehaviour::kCrushes;
    // and the law's validity for a solid elastomer (its Hertz strain and contact-radius limits).
    const bool elastomer = rec.material.poisson_ratio >= kSolidElastomerMinPoissonRatio;
    CHECK(map.criteria.size() == 4u + (crushes ? 1u : 0u) + (elastomer ? 1u : 0u));

    // Contour consistency: on the safe side of every contour <=> admissible by the optimiser's
    // own check, at every grid point; admissible points exist on both sides of the chosen one.
    std::size_t admissible = 0;
    for (const DesignScore& s : map.scores) {
      CHECK(OnSafeSideOfEveryContour(map, s) == s.admissible(result.rule));
      admissible += s.admissible(result.rule) ? 1 : 0;
    }
    CHECK(admissible > 0);
    CHECK(admissible < map.scores.size());
  }
}

TEST_CASE("the design map's cells agree with an independent time-path computation", "[design_map]") {
  const DesignRequest request = CatalogRequest(1.0);
  const DesignResult result = Design(request);
  const DesignMap map = ComputeDesignMap(request, result);
  REQUIRE(map.oracle.kind == OracleKind::kExact);
  TimeIntegrationOptions tight;
  tight.relative_tolerance = 1e-10;
  for (const auto& [i, j] : {std::pair<std::size_t, std::size_t>{0, 0}, {40, 30}, {20, 15}, {7, 22}, {33, 4}}) {
    CAPTURE(i, j);
    Scene scene = request.scene;
    scene.covering.thickness_m = map.thickness_m[i];
    scene.covering.youngs_modulus_Pa = map.modulus_Pa[j];
    scene.covering.poisson_ratio = map.poisson_ratio;
    const ImpactResult impact = SimulateImpact(ImpactModel::FromScene(scene), tight);
    REQUIRE(impact.ok());
    const DesignScore& s = map.at(i, j);
    const InjuryLimits limits;
    CHECK(s.laceration_ratio ==
          Approx(impact.peaks.max_tensile_stress_Pa / limits.laceration_tensile_stress_Pa).epsilon(1e-6));
    CHECK(s.contusion_ratio ==
          Approx(impact.peaks.max_energy_density_J_per_m2 / limits.contusion_energy_density_J_per_m2).epsilon(1e-6));
    CHECK(s.compression_ratio == Approx(impact.peaks.covering_compression_ratio()).epsilon(1e-6).margin(1e-9));
  }
}

TEST_CASE("on the design map the contusion ratio falls with thickness and softness until the covering bottoms out",
          "[design_map]") {
  const DesignRequest request = CatalogRequest(1.0);
  const DesignResult result = Design(request);
  const DesignMap map = ComputeDesignMap(request, result);
  const auto bottomed = [](const DesignScore& s) { return s.peaks.fully_compressed || s.compression_ratio >= 1.0; };
  std::size_t thicker = 0, softer = 0;
  for (std::size_t j = 0; j < map.modulus_Pa.size(); ++j) {
    for (std::size_t i = 0; i < map.thickness_m.size(); ++i) {
      const DesignScore& s = map.at(i, j);
      if (bottomed(s)) continue;
      if (i + 1 < map.thickness_m.size() && !bottomed(map.at(i + 1, j))) {
        CHECK(map.at(i + 1, j).contusion_ratio < s.contusion_ratio);
        ++thicker;
      }
      if (j > 0 && !bottomed(map.at(i, j - 1))) {
        CHECK(map.at(i, j - 1).contusion_ratio < s.contusion_ratio);
        ++softer;
      }
    }
  }
  CHECK(thicker > 100);
  CHECK(softer > 100);
}

TEST_CASE("without catalog materials the design map marks the continuous optimum, and nothing when the bare robot "
          "is safe",
          "[design_map]") {
  DesignRequest request;  // no materials: the continuous optimum alone
  const DesignResult result = Design(request);
  REQUIRE(result.continuous.feasible);
  const DesignMap map = ComputeDesignMap(request, result, {21, 11});
  CHECK(map.scores.size() == 21 * 11);
  REQUIRE(map.chosen);
  CHECK_FALSE(map.chosen->material);
  CHECK_FALSE(map.material);
  CHECK(map.poisson_ratio == request.options.covering_poisson_ratio);
  CHECK(map.chosen_score->contusion_ratio == Approx(result.continuous.score.contusion_ratio).epsilon(1e-12));
  CHECK(map.chosen_score->laceration_ratio == Approx(result.continuous.score.laceration_ratio).epsilon(1e-12));
  CHECK(map.criteria.size() == 4);  // no material: no crush criterion

  DesignRequest slow;
  slow.scene.robot.speed_m_per_s = 0.3;
  const DesignResult bare = Design(slow);
  REQUIRE(bare.verdict == DesignVerdict::kBareRobotSafe);
  const DesignMap none = ComputeDesignMap(slow, bare, {5, 5});
  CHECK_FALSE(none.chosen);
  CHECK_FALSE(none.chosen_score);
  CHECK(none.thickness_m.back() == slow.options.space.max_thickness_m);  // the whole design space

  CHECK_THROWS_WITH(ComputeDesignMap(request, result, {1, 31}),
                    "design map: thickness_points must be in [2, 1000] (got 1)");
  CHECK_THROWS_WITH(ComputeDesignMap(request, result, {41, 1001}),
                    "design map: modulus_points must be in [2, 1000] (got 1001)");
}
