#pragma once
/// @file covering_design.hpp
/// Covering design on top of an impact oracle (oracle.hpp: the exact path, or the time path
/// where the scene needs it): the two design problems, and the snap of the continuous optimum
/// to real materials.
///
/// (a) Thinnest admissible covering: minimise b_c over E_c (log-scaled) and b_c such that
///     the laceration and contusion ratios are <= 1/safety_factor and, under the default
///     criterion, the covering is not fully compressed at the peak (docs/model.md §6).
/// (b) Least injury at a given thickness: minimise max(ratios) over the admissible E_c at
///     fixed b_c.
///
/// The design criterion (docs/model.md §6). Default "no-full-compression": a covering is
/// admissible when it is safe AND δ_max <= t2 (the robot never reaches the bone through
/// it). With DesignOptions::allow_full_compression the paper's criterion (safety only)
/// applies. The bare robot is always its own candidate, judged on safety alone; it is never
/// the b_c -> 0 limit of the search (docs/model.md §5 item 4).
///
/// The continuous search of (a) has three stages, every one reported:
///  1. global  NLopt (DIRECT-L by default) on the 2-D problem: an upper bracket for b_c*.
///  2. bracket covopt's nested search, which does not depend on stage 1: b_c is scanned
///     from thin to thick on a grid (linear and geometric points); at each b_c the best
///     modulus is found by a 1-D global search in log10 E_c (the admissible moduli form
///     one interval [u_c, max] because δ_max falls with E_c, u_c by bisection; a uniform
///     scan of that interval, then golden-section refinement of its best local minima);
///     the first admissible grid point is bisected against the one before it.
///  3. local   Ipopt from the bracketed optimum with the oracle's gradients (analytic on the
///     exact path, CVODES forward sensitivities or a central difference on the time path;
///     second derivatives by central differences of them), warm-started, in a small trust
///     region; its point is kept only when a re-check by the oracle finds it admissible and
///     not thicker.
/// Every stage asks the same oracle (DesignOptions::oracle; ChooseOracle). A failed oracle
/// evaluation (a time-path integration that did not succeed) is an inadmissible point to the
/// bracketed search and the snap, a failed evaluation to NLopt and Ipopt; it is counted in
/// the result's OracleReport.
/// A stage that fails is reported with its status and never supplies the answer. Every
/// catalog material gets its own thinnest admissible thickness by a scan then bisection
/// (the admissible set need not be an interval for one material). Everything is a value:
/// no printing, no shared state; safe to call from several threads (Ipopt runs are
/// serialised inside the backend).

#include <atomic>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <covopt/core/compressive_curve.hpp>
#include <covopt/core/impact_result.hpp>
#include <covopt/core/scene.hpp>
#include <covopt/materials/material.hpp>

#include "covopt/optim/backends.hpp"
#include "covopt/optim/oracle.hpp"
#include "covopt/optim/problem.hpp"

namespace covopt::optim {

/// The box of the continuous search. E_c is searched in log10.
struct DesignSpace {
  double min_modulus_Pa = 0.1e6;   ///< 0.1 MPa
  double max_modulus_Pa = 1e9;     ///< 1 GPa
  /// Thinnest covering considered [m]; b_c = 0 (no covering) is a separate candidate.
  double min_thickness_m = 0.1e-3;
  double max_thickness_m = 0.05;   ///< 50 mm
};

/// A real material the continuous optimum can snap to.
struct CandidateMaterial {
  std::string name;
  double youngs_modulus_Pa = 0.0;
  double poisson_ratio = 0.25;
  /// ν was not known for this material and poisson_ratio is a default.
  bool poisson_assumed = false;
  /// The catalog family ("foam", "elastomer", ...); empty when not from a catalog.
  std::string family{};
  /// Whether it crushes (docs/model.md §12). Default: unknown, which the default rule refuses
  /// as a recommendation; SelectCandidates copies the catalog's.
  materials::CrushBehaviour crush_behaviour = materials::CrushBehaviour::kUnknown;
  /// Compressive strength [Pa] (yield or 10 % strain), > 0; used when crush_behaviour is
  /// kCrushes.
  double compressive_strength_Pa = 0.0;
  /// The material's measured compressive curve (covopt/core/compressive_curve.hpp), shared and
  /// immutable; null: none, and the Hertz law describes the material. Under the covering law
  /// auto (the default) a material with a curve is designed with the foam law (docs/model.md §16).
  std::shared_ptr<const CompressiveCurve> compressive_curve{};
  /// With a curve: true for a flexible foam that recovers, false for a crushable liner; empty
  /// without a curve.
  std::optional<bool> recovers{};
  /// The range of the factor the curve's stresses may take at impact rates [-]; empty when the
  /// catalog states none.
  std::optional<materials::Bounds> rate_factor{};
  /// A grade band standing in for a measured curve: its range of σ(25 %) [Pa]; empty otherwise.
  std::optional<materials::Bounds> stress_at_25_band_Pa{};
};

/// Sets score.crush_check and score.crush_ratio (σ_c,max / strength) for `material`
/// (docs/model.md §12); a failed score keeps an infinite crush ratio.
void CheckCrush(const CandidateMaterial& material, DesignScore& score) noexcept;

/// Options of the design searches. Defaults: the bounds, DIRECT-L then Ipopt.
struct DesignOptions {
  /// The continuous search box. Default: E_c 0.1 MPa .. 1 GPa, b_c 0.1 .. 50 mm.
  DesignSpace space;
  /// false (default): a covering fully compressed at the peak is not admissible, however low
  /// its ratios (criterion "no-full-compression"). true: the paper's criterion, safety only.
  bool allow_full_compression = false;
  DesignCriterion criterion() const noexcept {
    return allow_full_compression ? DesignCriterion::kPaper : DesignCriterion::kNoFullCompression;
  }
  /// false (default): a catalog material whose peak compressive stress times the safety factor
  /// exceeds its compressive strength is not admissible (criterion "no-crush"). true: a
  /// sacrificial liner, crushed at the first impact, may be recommended (warned).
  bool allow_crushing = false;
  /// false (default): a material of unknown strength is never recommended. true: it may be,
  /// with a warning that the design is unverified for crushing.
  bool allow_unknown_strength = false;
  /// Every ratio that counts (injury, covering travel, crush) must be <= 1/safety_factor, in
  /// [1, 100] [-]. Default: 1.
  double safety_factor = 1.0;
  /// The admissibility rule these options define.
  DesignRule rule() const noexcept {
    return DesignRule{safety_factor, criterion(), allow_crushing, allow_unknown_strength};
  }
  /// ν_c of the continuous design [-] (docs/model.md §1: 0.25 where none is given).
  double covering_poisson_ratio = 0.25;
  /// The laceration [Pa] and contusion [J/m²] limits. Default: 1 MPa and 2.52 J/cm².
  InjuryLimits limits;
  /// Global stage. DIRECT-L by default: deterministic, and on this 2-D box it finds the
  /// basin of the thinnest safe design within ~1000 evaluations (see tests/optim).
  NloptAlgorithm global_algorithm = NloptAlgorithm::kDirectL;
  /// Evaluation budget of the global stage, >= 10. Default: 1000.
  long global_evaluations = 1000;
  /// Seed of the stochastic global algorithms (ISRES, MLSL). Default: 20110509.
  unsigned long seed = 20110509;
  /// Where the global stage starts (ISRES, MLSL use it; DIRECT-L samples the box from its
  /// centre regardless). Empty: the centre of the design space.
  std::optional<CoveringDesign> initial_design;
  /// Bracketed stage: grid points in b_c (half linear, half geometric over the thickness
  /// range) and points per decade of the uniform scan in log10 E_c at each b_c. An
  /// admissible window of b_c narrower than the grid spacing before the first admissible
  /// grid point, or a basin in log10 E_c narrower than the scan spacing, is what this stage
  /// could miss; the brute-force tests check that the defaults do not. Defaults: 120 and 20.
  int bracket_thickness_points = 120;
  int modulus_points_per_decade = 20;
  /// Local stage: Ipopt from the bracketed result, with analytic gradients; problem (a)
  /// warm-starts it (IpoptOptions::warm_start). Default: on.
  bool local_polish = true;
  /// Ipopt's settings. Default: IpoptOptions{} (tol 1e-10, no bound relaxation).
  IpoptOptions ipopt;
  /// Which path scores the designs: auto (default: the exact path where the scene admits it,
  /// the time path otherwise), exact, or time-path with its integrator and tolerance.
  OracleOptions oracle;
  /// Catalog snap: the scan for the first safe thickness uses this many points over the
  /// thickness range, then bisects to thickness_resolution_m [m]. Defaults: 250, 1 µm.
  int thickness_scan_points = 250;
  double thickness_resolution_m = 1e-6;
  /// Threads of the catalog snap (each material is independent), in [1, 256]. The outcomes
  /// are assembled in the materials' order before ranking, so the result is bit-identical
  /// for any thread count. Default: 1.
  int threads = 1;
  /// The recommended thickness is rounded up to a multiple of this [m] (0 = not rounded),
  /// as sold; the rounded thickness is checked admissible again. Default: 0.5 mm.
  double thickness_step_m = 0.5e-3;
};

/// The continuous optimum of a design problem, and how it was found.
struct ContinuousOptimum {
  /// `score` is admissible under the options' criterion: an admissible design exists within
  /// the bound (problem a) / the best modulus at the thickness is admissible (problem b).
  bool feasible = false;
  DesignScore score;
  SolverReport global;   ///< NLopt stage
  SolverReport bracket;  ///< covopt's nested bracketed search ("covopt:bracket")
  SolverReport local;    ///< Ipopt stage (backend empty when not run)
  /// Which stage's point was kept and why ("ipopt", "bracket (ipopt ended ...)", ...).
  std::string source;
  /// Problem (b) only: no modulus in the search box keeps the covering from full
  /// compression at this thickness (the score is then the least-injury modulus regardless).
  bool every_modulus_fully_compressed = false;
};

/// One catalog material's outcome.
struct CandidateOutcome {
  CandidateMaterial material;
  /// Thinnest safe thickness [m] (to the resolution); empty when none within the bound.
  std::optional<double> min_safe_thickness_m;
  /// min_safe_thickness rounded up to the thickness step and confirmed admissible [m].
  std::optional<double> recommended_thickness_m;
  /// The stock thickness (the next admissible multiple of the step) that would have passed
  /// the maximum thickness [m]; the exact thinnest admissible thickness is then recommended.
  std::optional<double> stock_thickness_beyond_max_m;
  /// Score at the recommended thickness (problem a), at the given thickness (problem b), or at
  /// the maximum thickness when the material is not safe within the bound.
  DesignScore score;
  double margin = 0.0;  ///< score.margin(rule): 1 − SF × the governing ratio over every criterion
  /// Admissible under the options' criterion (safe, and not fully compressed by default).
  bool safe = false;
};

/// Overall outcome of a design search (infeasibility is an answer, not an error).
enum class DesignVerdict {
  kCoveringFound,      ///< a material is safe (problem a) / the best is safe (problem b)
  kBareRobotSafe,      ///< no covering is needed at all
  kNoSafeMaterial,     ///< no catalog material is safe within the bound (continuous may be)
  kNothingSafe,        ///< not even the continuous optimum is safe within the bound
};
std::string_view ToString(DesignVerdict verdict) noexcept;

/// Problem (a): the thinnest admissible covering (safe, and by default not fully compressed).
struct ThinnestSafeCovering {
  DesignVerdict verdict = DesignVerdict::kNothingSafe;
  DesignCriterion criterion = DesignCriterion::kNoFullCompression;
  DesignScore bare_robot;  ///< the scene without covering
  ContinuousOptimum continuous;
  /// Safe materials by recommended thickness (thinnest first), ties by margin; then the
  /// unsafe ones by margin at the maximum thickness.
  std::vector<CandidateOutcome> candidates;
  /// Index of the recommended material in `candidates` (the first, when any is safe).
  std::optional<std::size_t> recommendation;
  long evaluations = 0;  ///< oracle evaluations in all stages
  double seconds = 0.0;
  OracleReport oracle;   ///< which oracle ran, why, and its failed evaluations
};

/// Problem (b): the least injury at a given thickness.
struct LeastInjuryAtThickness {
  DesignVerdict verdict = DesignVerdict::kNothingSafe;
  DesignCriterion criterion = DesignCriterion::kNoFullCompression;
  double thickness_m = 0.0;
  DesignScore bare_robot;
  ContinuousOptimum continuous;  ///< the E_c minimising the worst ratio at this thickness
  /// Materials by worst ratio at this thickness (safest first).
  std::vector<CandidateOutcome> candidates;
  std::optional<std::size_t> recommendation;  ///< the first candidate, when it is safe
  long evaluations = 0;  ///< oracle evaluations
  double seconds = 0.0;
  OracleReport oracle;   ///< which oracle ran, why, and its failed evaluations
};

/// @throws std::invalid_argument naming the option/scene field for bad input, or for
///         oracle exact on a scene the exact path cannot answer.
ThinnestSafeCovering FindThinnestSafeCovering(const Scene& scene,
                                              std::span<const CandidateMaterial> materials,
                                              const DesignOptions& options = {});

/// @throws std::invalid_argument naming the option/scene field for bad input.
LeastInjuryAtThickness MinimizeInjuryAtThickness(const Scene& scene, double thickness_m,
                                                 std::span<const CandidateMaterial> materials,
                                                 const DesignOptions& options = {});

}  // namespace covopt::optim
