// The design map of `covopt optimize`: a grid of coverings around the answer, each scored by
// the request's oracle and judged by its rule (DesignScore::governing / admissible).
#include "covopt/optim/design_map.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include <covopt/core/number_format.hpp>

namespace covopt::optim {
namespace {

std::string Mm(double metres) { return FormatSignificant(metres * 1e3, 4) + " mm"; }

/// `count` points from `low` to `high`, linear or geometric.
std::vector<double> Axis(double low, double high, int count, bool geometric) {
  std::vector<double> axis(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) {
    const double f = static_cast<double>(k) / (count - 1);
    axis[static_cast<std::size_t>(k)] =
        geometric ? std::exp(std::log(low) + f * (std::log(high) - std::log(low))) : low + f * (high - low);
  }
  axis.front() = low;
  axis.back() = high;
  return axis;
}

}  // namespace

double CriterionRatio(const DesignScore& score, LimitingCriterion criterion, const DesignRule& rule) noexcept {
  switch (criterion) {
    case LimitingCriterion::kLaceration: return score.laceration_ratio;
    case LimitingCriterion::kContusion: return score.contusion_ratio;
    case LimitingCriterion::kFullCompression: return score.compression_ratio;
    case LimitingCriterion::kCrush: return score.crush_ratio;
    case LimitingCriterion::kFracture: return score.fracture_ratio;
    case LimitingCriterion::kLawValidity: return score.validity_ratio(rule) / rule.safety_factor;
    case LimitingCriterion::kNone: break;
  }
  return 0.0;
}

DesignMap ComputeDesignMap(const DesignRequest& request, const DesignResult& result, const DesignMapOptions& options) {
  for (const auto& [value, name] : {std::pair{options.thickness_points, "thickness_points"},
                                    std::pair{options.modulus_points, "modulus_points"}}) {
    if (value < 2 || value > 1000) {
      throw std::invalid_argument(std::string("design map: ") + name + " must be in [2, 1000] (got " +
                                  std::to_string(value) + ")");
    }
  }
  const DesignOptions& design = request.options;
  DesignMap map;
  map.scene = request.scene;
  map.problem = result.problem;
  map.fixed_thickness_m = result.thickness_m;
  map.rule = result.rule;
  map.limits = design.limits;
  map.verdict = result.verdict;
  map.message = result.message;
  map.poisson_ratio = design.covering_poisson_ratio;

  // The chosen design: the recommendation, else the continuous optimum (when a covering is
  // needed at all).
  if (result.recommendation) {
    const CandidateOutcome& c = result.candidates[*result.recommendation];
    map.material = c.material;
    map.poisson_ratio = c.material.poisson_ratio;
    const double b = c.recommended_thickness_m.value_or(c.score.design.thickness_m);
    map.chosen = DesignMapMark{c.material.name + ", " + Mm(b), {c.material.youngs_modulus_Pa, b}, c.material.name,
                               c.safe};
  } else if (result.covering_needed()) {
    const DesignScore& s = result.continuous.score;
    map.chosen = DesignMapMark{std::string(result.continuous.feasible ? "continuous optimum"
                                                                      : "least-unsafe continuous design") +
                                   ", " + Mm(s.design.thickness_m),
                               s.design, std::nullopt, result.continuous.feasible && s.admissible(result.rule)};
  }
  for (const CandidateOutcome& c : result.candidates) {
    const double b = c.recommended_thickness_m.value_or(c.score.design.thickness_m);
    map.candidates.push_back({c.material.name, {c.material.youngs_modulus_Pa, b}, c.material.name, c.safe});
  }

  // The grid: around the chosen design, clipped to the design space.
  const DesignSpace& space = design.space;
  double b_high = space.max_thickness_m;
  double e_low = space.min_modulus_Pa, e_high = space.max_modulus_Pa;
  if (map.chosen && map.chosen->design.thickness_m > 0.0 && map.chosen->design.youngs_modulus_Pa > 0.0) {
    b_high = std::min(space.max_thickness_m, std::max(2.5 * map.chosen->design.thickness_m, 4.0 * space.min_thickness_m));
    const double e = map.chosen->design.youngs_modulus_Pa;
    e_low = std::max(space.min_modulus_Pa, e / 100.0);
    e_high = std::min(space.max_modulus_Pa, e * 100.0);
    if (!(e_high > e_low * 10.0)) {  // at the edge of the box: still four decades where there are
      e_low = std::max(space.min_modulus_Pa, e_high / 1e4);
      e_high = std::min(space.max_modulus_Pa, e_low * 1e4);
    }
  }
  map.thickness_m = Axis(space.min_thickness_m, b_high, options.thickness_points, false);
  map.modulus_Pa = Axis(e_low, e_high, options.modulus_points, true);

  // The same oracle, ν and crush check as the optimiser's scoring of that design.
  const std::unique_ptr<DesignOracle> oracle =
      MakeOracle(request.scene, design.covering_poisson_ratio, design.limits, design.oracle);
  const auto score = [&](const CoveringDesign& d) {
    DesignScore s = oracle->ScoreMaterial(d, map.poisson_ratio);
    if (map.material) CheckCrush(*map.material, s);
    return s;
  };
  map.scores.reserve(map.thickness_m.size() * map.modulus_Pa.size());
  for (const double e : map.modulus_Pa) {
    for (const double b : map.thickness_m) map.scores.push_back(score({e, b}));
  }
  // The chosen material as the optimiser scored it: under the design's covering law (a material
  // with a measured curve: the foam law), which the (E_c, b_c) grid, a Hertz ideal, cannot show.
  if (map.chosen && map.material) {
    DesignScore s = oracle->ScoreCovering(CoveringOf(*map.material, map.chosen->design.thickness_m, design.covering_law));
    CheckCrush(*map.material, s);
    map.chosen_score = s;
  } else if (map.chosen) {
    map.chosen_score = score(map.chosen->design);
  }

  map.criteria = {LimitingCriterion::kLaceration, LimitingCriterion::kContusion, LimitingCriterion::kFracture};
  if (map.rule.compression_counts()) map.criteria.push_back(LimitingCriterion::kFullCompression);
  if (!map.rule.crushing_allowed && map.material &&
      map.material->crush_behaviour == materials::CrushBehaviour::kCrushes) {
    map.criteria.push_back(LimitingCriterion::kCrush);
  }
  // A solid elastomer's Hertz limits (strain, contact radius: docs/model.md §12.2) bind inside
  // the travel; a compressible covering's validity is its travel, the full-compression contour's.
  if (map.poisson_ratio >= kSolidElastomerMinPoissonRatio) map.criteria.push_back(LimitingCriterion::kLawValidity);
  map.oracle = oracle->Report();
  return map;
}

}  // namespace covopt::optim
