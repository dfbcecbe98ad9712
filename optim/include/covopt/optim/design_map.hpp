#pragma once
/// @file design_map.hpp
/// The design map of `covopt optimize`: every covering on a grid of thickness x Young's
/// modulus around the answer, judged by the very oracle and rule the design request used
/// (DesignScore::governing and DesignScore::admissible), so the limit contours drawn from it
/// are the optimiser's criteria and the chosen design sits where the optimiser put it.
///
///     const covopt::optim::DesignResult result = covopt::optim::Design(request);
///     const covopt::optim::DesignMap map = covopt::optim::ComputeDesignMap(request, result);
///     const covopt::optim::DesignScore& s = map.at(i, j);  // thickness_m[i], modulus_Pa[j]

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <covopt/core/impact_result.hpp>
#include <covopt/core/scene.hpp>

#include "covopt/optim/covering_design.hpp"
#include "covopt/optim/design.hpp"
#include "covopt/optim/oracle.hpp"

namespace covopt::optim {

/// The grid's size.
struct DesignMapOptions {
  int thickness_points = 41;  ///< along the thickness (linear axis), in [2, 1000]
  int modulus_points = 31;    ///< along the modulus (log axis), in [2, 1000]
};

/// A design marked on the map.
struct DesignMapMark {
  /// "XPS Foamular 250, 16 mm", "continuous optimum", ...
  std::string label;
  CoveringDesign design;
  /// The catalog material (its name), empty for the continuous optimum.
  std::optional<std::string> material;
  /// Admissible under the map's rule (as the optimiser judged it).
  bool admissible = false;
};

/// Every covering of a grid judged as the design request judges one.
struct DesignMap {
  /// The request's scene: the covering is what the map varies.
  Scene scene;
  DesignProblem problem = DesignProblem::kThinnestSafeCovering;
  /// Problem (b)'s thickness [m]; empty for problem (a).
  std::optional<double> fixed_thickness_m;
  /// The rule every point is judged by (the result's: criteria and safety factor).
  DesignRule rule;
  /// The laceration [Pa] and contusion [J/m²] limits.
  InjuryLimits limits;
  /// The material whose Poisson ratio and crush behaviour every grid point has: the
  /// recommended one; empty when the chosen design is the continuous optimum (then ν is the
  /// request's covering_poisson_ratio and there is no crush criterion).
  std::optional<CandidateMaterial> material;
  double poisson_ratio = 0.25;  ///< ν of every grid point [-]
  /// The grid's axes, increasing: thickness [m] linear, modulus [Pa] log-spaced.
  std::vector<double> thickness_m;
  std::vector<double> modulus_Pa;
  /// scores[j * thickness_m.size() + i] at (thickness_m[i], modulus_Pa[j]).
  std::vector<DesignScore> scores;
  /// The criteria that count under the rule at these points, in the order laceration,
  /// contusion, fracture (docs/model.md §7.1), full compression (criterion no-full-compression), crush (a material of known
  /// strength, crushing not allowed), the law's validity (a solid elastomer, ν >= 0.45: its Hertz
  /// strain and contact-radius limits): one limit contour each, at ratio 1 / safety factor.
  std::vector<LimitingCriterion> criteria;
  /// The design the request chose (the recommendation, else the continuous optimum), scored
  /// here by the same oracle; empty when the bare robot is safe (nothing is chosen).
  std::optional<DesignMapMark> chosen;
  /// Its score by the map's oracle (equal to the optimiser's: a material under the design's
  /// covering law, so a curve material under the foam law, which the grid of (E_c, b_c) does not show).
  std::optional<DesignScore> chosen_score;
  /// Every catalog candidate at its recommended thickness (or the thickness it was scored at).
  std::vector<DesignMapMark> candidates;
  /// The result's verdict and headline.
  DesignVerdict verdict = DesignVerdict::kNothingSafe;
  std::string message;
  /// The oracle that scored the grid (the request's choice) and what it cost.
  OracleReport oracle;

  const DesignScore& at(std::size_t thickness_index, std::size_t modulus_index) const {
    return scores[modulus_index * thickness_m.size() + thickness_index];
  }
};

/// The ratio of one criterion in a score under `rule` [-] (unscaled: the limit is 1 / safety
/// factor): laceration_ratio, contusion_ratio, compression_ratio, crush_ratio, fracture_ratio;
/// for kLawValidity, which the safety factor does not derate, DesignScore::validity_ratio(rule) /
/// SF (as DesignScore::governing); 0 for kNone.
double CriterionRatio(const DesignScore& score, LimitingCriterion criterion, const DesignRule& rule) noexcept;

/// The design map of `request` and its answer `result`. The grid spans, around the chosen
/// design (b*, E*): thickness from the search's minimum to min(max thickness, 2.5 b*),
/// modulus over four decades centred on E*, both clipped to the design space; without a
/// chosen design, the whole design space. Each point is scored by the oracle the request
/// chose (MakeOracle), with the material's ν and its crush check (CheckCrush) as the
/// catalog snap scores that material, or with the continuous design's ν.
/// @throws std::invalid_argument for a grid size out of range, or as MakeOracle for the
///         request's scene and oracle options.
DesignMap ComputeDesignMap(const DesignRequest& request, const DesignResult& result,
                           const DesignMapOptions& options = {});

}  // namespace covopt::optim
