#pragma once
/// @file robust_design.hpp
/// Design for a population instead of one head: scene inputs known only within ranges.
///
/// An UncertaintyBox is a nominal Scene plus uncertain inputs, each a scene field
/// (covopt::SceneFields(), e.g. "head-mass") with an interval [low, high] in SI and a
/// distribution for sampling. On it:
///
///   FindWorstCase                 the worst impact over the box for the scene's covering: a
///                                 global search (corners, centre, a Halton sample, NLopt
///                                 DIRECT-L, COBYLA refinements), not only the corners.
///   FindRobustThinnestCovering    the thinnest covering admissible for EVERY value in the box:
///                                 per catalog material and as a continuous (E_c, b_c) optimum.
///   MaxSafeSpeedOverBox,          the largest speed / reflected mass safe for every value in
///   MaxSafeMassOverBox            the box: the global minimum of MaxSafeSpeed / MaxSafeMass.
///   EstimateInjuryProbability     Monte Carlo: the probability of laceration, contusion, either,
///                                 with Wilson 95 % intervals; reproducible from the seed and
///                                 bit-identical for any thread count.
///   FindProbabilityDesign         the thinnest covering whose probability of failing the design
///                                 criterion is <= P, with common random numbers across designs.
///   ComputeElasticities           (x / r) dr/dx of each ratio for every scene input at a design:
///                                 analytic for E_c and b_c, checked finite differences otherwise.
///
/// The criterion (docs/model.md §6) is the design's: an impact is admissible when
/// SF r_L <= 1 and SF r_C <= 1 and, under the default "no-full-compression" criterion, the
/// covering is not fully compressed at the peak (δ_max <= t2). One number measures how close
/// an impact is to failing, the governing ratio
///
///     g = max(SF r_L, SF r_C, r_δ)        r_δ = δ_max / t2, counted only under the default
///                                          criterion and with a covering
///
/// (admissible <=> g <= 1, up to the flag fully_compressed at r_δ = 1 exactly); the worst case
/// of a box is the impact of largest g.
///
/// Scope: the two-mass impact, conservative (the exact path) or with a braking robot (the time
/// path, screened by the exact path's bound: braking only takes energy out of the impact, so
/// an impact admissible unbraked is admissible braked, and a brake that starts after the
/// unbraked maximum changes no peak; docs/model.md §11, "A braking robot"). reaction-delay and
/// braking may be uncertain. Contact damping and a neck are refused (nominal or as ranges).
///
/// Monotone inputs. The reflected robot mass, the head mass and the speed enter the exact path
/// only through the impact energy ½ μ v0² (μ = 1/(1/m_r + 1/m_h)); δ_max grows with it and every
/// peak is a non-decreasing function of δ_max (docs/model.md §9.1). Their worst case is
/// therefore the top of their range, for every other value; GlobalSearchOptions::
/// pin_energy_inputs (default on) fixes them there instead of searching them.
///
/// This header declares the robust thinnest covering and includes the rest, one header per
/// source: robust_box.hpp (the box, sampling), robust_search.hpp (worst case, limits over the
/// box), robust_probability.hpp (injury probability, design for a probability) and
/// robust_sensitivity.hpp (elasticities).

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "covopt/optim/covering_design.hpp"
#include "covopt/optim/robust_box.hpp"
#include "covopt/optim/robust_probability.hpp"
#include "covopt/optim/robust_search.hpp"
#include "covopt/optim/robust_sensitivity.hpp"

namespace covopt::optim {

// ----------------------------------------------------------------------------------------
// Robust thinnest covering
// ----------------------------------------------------------------------------------------

/// Options of FindRobustThinnestCovering.
struct RobustDesignOptions {
  /// The design problem as FindThinnestSafeCovering poses it: search space, criterion, safety
  /// factor, limits, ν_c of the continuous design, the catalog scan (thickness_scan_points,
  /// thickness_resolution_m), thickness_step_m, threads (materials in parallel; the result is
  /// identical for any count), bracket_thickness_points and modulus_points_per_decade (the
  /// continuous nested search). Its NLopt and Ipopt settings and its oracle choice are not
  /// used: the robust searches run on the exact path, and for a braking robot on the time path
  /// with oracle.time_path's integrator and tolerances (screened by the exact path's bound).
  DesignOptions design;
  /// The inner worst-case search run to confirm each design.
  GlobalSearchOptions worst_case;
  /// Scenario rounds per material (and for the continuous optimum), in [1, 1000]. Default: 50.
  int max_scenario_rounds = 50;
  /// Also the continuous (E_c, b_c) optimum. Default: true.
  bool continuous = true;
};

/// One catalog material's robust outcome.
struct RobustCandidate {
  /// As FindThinnestSafeCovering's; `score` is the impact at the worst case of the box at the
  /// recommended thickness (at the maximum thickness when none is admissible), and `safe`
  /// means admissible for the whole box.
  CandidateOutcome outcome;
  /// That worst case: its input values, ratios and what binds.
  WorstCase worst_case;
  /// The worst case at min_safe_thickness_m, where it binds (g = 1 to the thickness
  /// resolution): the input values that set the design. Empty when none is admissible.
  std::optional<WorstCase> worst_case_at_thinnest;
  /// Scenario rounds this material needed (see FindRobustThinnestCovering).
  int scenario_rounds = 0;
  /// The rounds ran out before the design could be confirmed: not recommended.
  bool unconfirmed = false;
};

/// The continuous robust optimum.
struct RobustContinuousOptimum {
  /// A design admissible for the whole box exists within the search space.
  bool feasible = false;
  CoveringDesign design;  ///< thinnest robust design (E_c [Pa], b_c [m]); when infeasible, the
                          ///< least-g modulus at the maximum thickness
  WorstCase worst_case;   ///< the worst case of the box at `design`: what sets it
  int scenario_rounds = 0;
  bool unconfirmed = false;  ///< the rounds ran out
};

/// FindRobustThinnestCovering's answer.
struct RobustThinnestCovering {
  DesignVerdict verdict = DesignVerdict::kNothingSafe;
  DesignCriterion criterion = DesignCriterion::kNoFullCompression;
  WorstCase bare_robot;  ///< the worst case of the box without a covering (ratios only)
  std::optional<RobustContinuousOptimum> continuous;  ///< when asked for
  /// Admissible materials by recommended thickness (thinnest first), ties by margin; then the
  /// rest by margin at the maximum thickness.
  std::vector<RobustCandidate> candidates;
  std::optional<std::size_t> recommendation;  ///< the first candidate, when it is admissible
  /// The scenarios (input values [SI]) the designs were checked against at the start: the
  /// centre and the worst case at the nominal scene's covering.
  std::vector<std::vector<double>> initial_scenarios;
  long evaluations = 0;  ///< impacts judged, all stages
  /// A braking robot: how the impacts were judged (screened, brake after the peak, time-path
  /// runs) and any failed time-path run. A failure is judged inadmissible, so no design rests
  /// on one; it can only make a design thicker or leave none.
  TimePathUse time_path;
  double seconds = 0.0;
};

/// The thinnest covering admissible for every value in the box (the worst case over the box
/// has g <= 1), per catalog material and, if asked, as a continuous optimum.
///
/// Method (scenario generation, Blankenship & Falk 1976): a design is first judged against a
/// finite set S of input values (at the start: the centre and the nominal covering's worst
/// case). Per material, the thinnest thickness admissible for all of S is found by
/// FindThinnestSafeCovering's scan-then-bisect; the global worst-case search then checks the
/// whole box there; if it finds a violation, that point joins S and the search repeats (a
/// thickness inadmissible for S is inadmissible for the box, so the answer only moves up).
/// The continuous optimum runs the same loop around the nested search (a scan in b_c; at each
/// b_c the modulus minimising max over S of g, by a scan in log10 E_c and golden sections;
/// bisection). The rounded stock thickness is confirmed by the global search too. Each
/// material starts from the same S, so the result does not depend on the thread count.
/// @throws std::invalid_argument for bad options, or a range on covering-modulus,
///   covering-poisson or covering-thickness (the design chooses them).
RobustThinnestCovering FindRobustThinnestCovering(const UncertaintyBox& box,
                                                  std::span<const CandidateMaterial> materials,
                                                  const RobustDesignOptions& options = {});

/// The probability of injury of `result`'s recommendation over the box's distributions: the
/// box's nominal scene with the recommended material's modulus and Poisson ratio at its
/// recommended thickness, sampled by EstimateInjuryProbability with `sampling`'s samples,
/// seed, threads, block size and progress, and `options.design`'s criterion, safety factor
/// and limits. Empty when there is no recommendation.
/// @throws std::invalid_argument as EstimateInjuryProbability.
std::optional<InjuryProbability> EstimateRecommendationInjuryProbability(const UncertaintyBox& box,
                                                                         const RobustThinnestCovering& result,
                                                                         const RobustDesignOptions& options,
                                                                         InjuryProbabilityOptions sampling);

}  // namespace covopt::optim
