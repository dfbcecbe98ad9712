#pragma once
/// @file covering_design.hpp
/// Covering design on top of the exact impact path: the oracle, the two design problems,
/// and the snap of the continuous optimum to real materials.
///
/// (a) Thinnest safe covering: minimise b_c subject to laceration and contusion ratios
///     <= 1/safety_factor, over E_c (log-scaled) and b_c.
/// (b) Least injury at a given thickness: minimise max(ratios) over E_c at fixed b_c.
///
/// Both run an NLopt global search first (the landscape is multimodal, DESIGN.md §5.7), then
/// Ipopt from the global result with analytic gradients (core/sensitivity.hpp). "No covering"
/// is its own candidate, never the b_c -> 0 limit of the search (DESIGN.md §5.4). Every
/// catalog material gets its own thinnest safe thickness by a bracketed 1-D solve (a scan for
/// the first safe thickness, then bisection: safety need not be monotone in b_c for stiff
/// materials). Everything is a value: no printing, no shared state; safe to call from several
/// threads (Ipopt runs are serialised inside the backend).

#include <atomic>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <covopt/core/impact_result.hpp>
#include <covopt/core/scene.hpp>

#include "covopt/optim/backends.hpp"
#include "covopt/optim/problem.hpp"

namespace covopt::optim {

/// A covering: modulus [Pa] and thickness [m].
struct CoveringDesign {
  double youngs_modulus_Pa = 0.0;
  double thickness_m = 0.0;
};

/// The box of the continuous search. E_c is searched in log10.
struct DesignSpace {
  double min_modulus_Pa = 0.1e6;   ///< 0.1 MPa
  double max_modulus_Pa = 1e9;     ///< 1 GPa
  /// Thinnest covering considered [m]; b_c = 0 (no covering) is a separate candidate.
  double min_thickness_m = 0.1e-3;
  double max_thickness_m = 0.05;   ///< 50 mm
};

/// The injury ratios of one design.
struct DesignScore {
  CoveringDesign design;
  double poisson_ratio = 0.25;
  ImpactPeaks peaks;
  double laceration_ratio = 0.0;  ///< σ_t,max / laceration limit
  double contusion_ratio = 0.0;   ///< e_A,max / contusion limit
  double worst_ratio() const noexcept {
    return laceration_ratio > contusion_ratio ? laceration_ratio : contusion_ratio;
  }
  /// Both ratios <= 1/safety_factor.
  bool safe(double safety_factor) const noexcept { return worst_ratio() * safety_factor <= 1.0; }
  /// 1 - safety_factor * worst ratio: >= 0 when safe, the fraction of the (derated) limit
  /// left over.
  double margin(double safety_factor) const noexcept { return 1.0 - safety_factor * worst_ratio(); }
};

/// d(ratio)/d(log10 E_c) and d(ratio)/d(b_c) [1/m].
struct RatioGradient {
  double laceration[2] = {0.0, 0.0};
  double contusion[2] = {0.0, 0.0};
};

/// The exact path as an objective/constraint oracle over covering designs.
class CoveringOracle {
 public:
  /// `scene`'s covering is replaced by each design; ν_c = `covering_poisson_ratio`.
  /// @throws std::invalid_argument if the rest of the scene is invalid.
  CoveringOracle(const Scene& scene, double covering_poisson_ratio, const InjuryLimits& limits = {});

  /// Ratios of a design (thickness > 0). @throws std::invalid_argument for an invalid design.
  DesignScore Score(const CoveringDesign& design) const;
  /// Ratios and their analytic gradient.
  DesignScore Score(const CoveringDesign& design, RatioGradient& gradient) const;
  /// The same scene without covering.
  DesignScore ScoreBare() const;
  /// Ratios of a design with another Poisson ratio (a catalog material).
  DesignScore ScoreMaterial(const CoveringDesign& design, double poisson_ratio) const;

  const Scene& scene() const noexcept { return scene_; }
  /// Exact-path evaluations so far (thread-safe counter).
  long evaluations() const noexcept { return evaluations_.load(); }

 private:
  Scene scene_;
  InjuryLimits limits_;
  mutable std::atomic<long> evaluations_{0};
};

/// A real material the continuous optimum can snap to.
struct CandidateMaterial {
  std::string name;
  double youngs_modulus_Pa = 0.0;
  double poisson_ratio = 0.25;
  /// ν was not known for this material and poisson_ratio is a default.
  bool poisson_assumed = false;
};

/// Options of the design searches. Defaults: the bounds, DIRECT-L then Ipopt.
struct DesignOptions {
  DesignSpace space;
  /// Ratios must be <= 1/safety_factor (>= 1).
  double safety_factor = 1.0;
  /// ν_c of the continuous design (DESIGN.md §1: 0.25 where none is given).
  double covering_poisson_ratio = 0.25;
  InjuryLimits limits;
  /// Global stage. DIRECT-L by default: deterministic, and on this 2-D box it finds the
  /// basin of the thinnest safe design within ~1000 evaluations (see tests/optim).
  NloptAlgorithm global_algorithm = NloptAlgorithm::kDirectL;
  long global_evaluations = 1000;
  unsigned long seed = 20110509;
  /// Where the global stage starts (ISRES, MLSL use it; DIRECT-L samples the box from its
  /// centre regardless). Empty: the centre of the design space.
  std::optional<CoveringDesign> initial_design;
  /// Local stage: Ipopt from the global result, with analytic gradients.
  bool local_polish = true;
  IpoptOptions ipopt;
  /// Catalog snap: the scan for the first safe thickness uses this many points over the
  /// thickness range, then bisects to thickness_resolution_m.
  int thickness_scan_points = 250;
  double thickness_resolution_m = 1e-6;
  /// Threads of the catalog snap (each material is independent), in [1, 256]. The outcomes
  /// are assembled in the materials' order before ranking, so the result is bit-identical
  /// for any thread count.
  int threads = 1;
  /// The recommended thickness is rounded up to a multiple of this [m] (0 = not rounded),
  /// as sold; the rounded thickness is checked safe again.
  double thickness_step_m = 0.5e-3;
};

/// The continuous optimum of a design problem, and how it was found.
struct ContinuousOptimum {
  /// A design meeting the constraints was found (problem a) / always true for problem b.
  bool feasible = false;
  DesignScore score;
  SolverReport global;  ///< NLopt stage
  SolverReport local;   ///< Ipopt stage (backend empty when not run)
  /// Which stage's point was kept and why ("ipopt", or "global: ipopt ended with ...").
  std::string source;
};

/// One catalog material's outcome.
struct CandidateOutcome {
  CandidateMaterial material;
  /// Thinnest safe thickness [m] (to the resolution); empty when none within the bound.
  std::optional<double> min_safe_thickness_m;
  /// min_safe_thickness rounded up to the thickness step and confirmed safe [m].
  std::optional<double> recommended_thickness_m;
  /// Score at the recommended thickness (problem a), at the given thickness (problem b), or at
  /// the maximum thickness when the material is not safe within the bound.
  DesignScore score;
  double margin = 0.0;  ///< score.margin(safety_factor)
  bool safe = false;
};

/// Overall outcome of a design search (infeasibility is an answer, not an error).
enum class DesignVerdict {
  kCoveringFound,      ///< a material is safe (problem a) / the best is safe (problem b)
  kBareRobotSafe,      ///< no covering is needed at all
  kNoSafeMaterial,     ///< no catalog material is safe within the bound (continuous may be)
  kNothingSafe,        ///< not even the continuous optimum is safe within the bound
};
const char* ToString(DesignVerdict verdict) noexcept;

/// Problem (a): the thinnest safe covering.
struct ThinnestSafeCovering {
  DesignVerdict verdict = DesignVerdict::kNothingSafe;
  DesignScore bare_robot;  ///< the scene without covering
  ContinuousOptimum continuous;
  /// Safe materials by recommended thickness (thinnest first), ties by margin; then the
  /// unsafe ones by margin at the maximum thickness.
  std::vector<CandidateOutcome> candidates;
  /// Index of the recommended material in `candidates` (the first, when any is safe).
  std::optional<std::size_t> recommendation;
  long evaluations = 0;  ///< exact-path evaluations in all stages
  double seconds = 0.0;
};

/// Problem (b): the least injury at a given thickness.
struct LeastInjuryAtThickness {
  DesignVerdict verdict = DesignVerdict::kNothingSafe;
  double thickness_m = 0.0;
  DesignScore bare_robot;
  ContinuousOptimum continuous;  ///< the E_c minimising the worst ratio at this thickness
  /// Materials by worst ratio at this thickness (safest first).
  std::vector<CandidateOutcome> candidates;
  std::optional<std::size_t> recommendation;  ///< the first candidate, when it is safe
  long evaluations = 0;
  double seconds = 0.0;
};

/// @throws std::invalid_argument naming the option/scene field for bad input.
ThinnestSafeCovering FindThinnestSafeCovering(const Scene& scene,
                                              std::span<const CandidateMaterial> materials,
                                              const DesignOptions& options = {});

/// @throws std::invalid_argument naming the option/scene field for bad input.
LeastInjuryAtThickness MinimizeInjuryAtThickness(const Scene& scene, double thickness_m,
                                                 std::span<const CandidateMaterial> materials,
                                                 const DesignOptions& options = {});

}  // namespace covopt::optim
