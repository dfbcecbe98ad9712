#pragma once
/// @file robust_probability.hpp
/// The probability of injury over an uncertainty box's distributions (robust_design.hpp):
/// Monte Carlo estimates with Wilson 95 % intervals (EstimateInjuryProbability), and the
/// thinnest covering whose probability of failing the criterion is shown to be <= P
/// (FindProbabilityDesign).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "covopt/optim/covering_design.hpp"
#include "covopt/optim/robust_box.hpp"

namespace covopt::optim {

// ----------------------------------------------------------------------------------------
// Probability of injury
// ----------------------------------------------------------------------------------------

/// A proportion estimated from samples, with its Wilson score 95 % interval (z = 1.959964):
///     centre = (p + z²/2n) / (1 + z²/n),  half width = z/(1 + z²/n) sqrt(p(1-p)/n + z²/4n²).
/// Unlike p ± z sqrt(p(1-p)/n) it stays inside [0, 1] and is not empty at p = 0 or 1.
struct ProbabilityEstimate {
  std::uint64_t count = 0;    ///< samples with the event
  std::uint64_t samples = 0;  ///< samples drawn
  double probability = 0.0;   ///< count / samples
  double ci95_low = 0.0;      ///< Wilson 95 % interval
  double ci95_high = 0.0;
};
/// The estimate and Wilson interval of `count` events in `samples` (> 0) draws.
ProbabilityEstimate WilsonEstimate(std::uint64_t count, std::uint64_t samples);

/// The most events out of `samples` whose Wilson 95 % upper bound is still <= `probability`
/// (the bound rises with the count); empty when even 0 events' bound, z²/(n + z²), is above
/// it (too few samples to show the target).
std::optional<std::uint64_t> MostEventsWithUpperBoundWithin(double probability, std::uint64_t samples);

/// Options of EstimateInjuryProbability.
struct InjuryProbabilityOptions {
  /// Scenes drawn, in [1, 1e10]. Default: 100 000.
  std::uint64_t samples = 100000;
  /// Sample i's inputs come from its own random stream, a function of (seed, i) only
  /// (DrawInputs). Default: 20110509.
  std::uint64_t seed = 20110509;
  /// Worker threads counting the calling thread, 0..4096; 0 = hardware concurrency. The
  /// result is bit-identical for any count. Default: 0.
  unsigned threads = 0;
  /// Samples per unit of work, 1..10^7. Default: 8192.
  std::uint64_t block_samples = 8192;
  /// Criterion, safety factor and limits, as WorstCaseOptions.
  bool allow_full_compression = false;
  DesignCriterion criterion() const noexcept {
    return allow_full_compression ? DesignCriterion::kPaper : DesignCriterion::kNoFullCompression;
  }
  double safety_factor = 1.0;
  InjuryLimits limits;
  /// The covering material's compressive strength [Pa] and whether crushing is allowed, as
  /// WorstCaseOptions: a sample that crushes the covering is inadmissible unless allowed.
  double compressive_strength_Pa = 0.0;
  bool allow_crushing = false;
  /// Called on the calling thread with the fraction of samples done, in [0, 1], last with 1.
  /// An exception it throws stops the work (the threads are joined) and propagates.
  std::function<void(double fraction_done)> progress;
  /// The time path's integrator and tolerances for a braking robot (UncertaintyBox::brakes()):
  /// a sample with no event unbraked has none braked, the others run on it (docs/model.md
  /// §11). Checked then only. Default: ARKODE ERK 5(4), rtol 1e-8.
  TimeIntegrationOptions time_path;
};

/// EstimateInjuryProbability's answer.
struct InjuryProbability {
  ProbabilityEstimate laceration;        ///< SF r_L > 1
  ProbabilityEstimate contusion;         ///< SF r_C > 1
  ProbabilityEstimate fracture;          ///< SF r_F > 1 (docs/model.md §7.1)
  ProbabilityEstimate any;               ///< any injury: laceration, contusion or fracture
  ProbabilityEstimate fully_compressed;  ///< the covering fully compressed at the peak
  /// SF r_crush > 1: the covering crushes (0 without a material of known strength)
  ProbabilityEstimate crushed;
  /// Fails the design criterion: any injury, the covering crushed (unless crushing is allowed)
  /// or, under the default criterion, fully compressed (= `any` under the paper's criterion
  /// without a crush check).
  ProbabilityEstimate inadmissible;
  std::uint64_t seed = 0;
  unsigned threads = 0;  ///< threads used
  /// A braking robot: how the samples were judged. A failed time-path run counts as every
  /// event (injured, fully compressed, inadmissible), never as safe.
  TimePathUse time_path;
  double seconds = 0.0;
};

/// The fractions of `options.samples` scenes drawn from the box (each input from its
/// distribution, independently) that are injured, for the nominal scene's covering.
/// @throws std::invalid_argument for bad options.
InjuryProbability EstimateInjuryProbability(const UncertaintyBox& box,
                                            const InjuryProbabilityOptions& options = {});

/// Φ(z), the standard normal distribution function, 0.5 erfc(−z/√2).
double StandardNormalCdf(double z) noexcept;
/// Φ⁻¹(p) for p in (0, 1), −√2 erfc⁻¹(2p) (Boost.Math), within a few units in the last place;
/// −inf at 0, +inf at 1, NaN outside [0, 1].
double InverseStandardNormalCdf(double p) noexcept;

// ----------------------------------------------------------------------------------------
// Design for a probability of injury
// ----------------------------------------------------------------------------------------

/// Options of FindProbabilityDesign.
struct ProbabilityDesignOptions {
  /// The design problem (space, criterion, safety factor, limits, ν_c, catalog scan, stock
  /// step, bracket grid) as in RobustDesignOptions::design (exact path; its solver and oracle
  /// settings are not used). Materials run one after another;
  /// the samples of each design are spread over `sampling.threads`.
  DesignOptions design;
  /// samples, seed, threads and block_samples; progress is called after each stage (the bare
  /// robot, the continuous optimum, each material) with the fraction of stages done. Its
  /// criterion, safety factor and limits are ignored: `design`'s apply.
  InjuryProbabilityOptions sampling;
  /// The largest acceptable probability of failing the criterion (P(inadmissible)), in [0, 1).
  double max_probability = 0.01;
  /// Also the continuous (E_c, b_c) optimum (a scan in log10 E_c at each thickness; no
  /// golden sections, since the estimate is a step function of the design). Default: true.
  bool continuous = true;
};

/// One material's outcome against a probability target.
struct ProbabilityCandidate {
  CandidateMaterial material;
  /// Thinnest thickness whose estimate is <= P (scan then bisection) [m].
  std::optional<double> min_thickness_m;
  /// Rounded up to the stock step and confirmed [m].
  std::optional<double> recommended_thickness_m;
  /// The estimate at the recommended thickness (at the maximum thickness when none).
  InjuryProbability at_design;
  bool meets_target = false;
};

/// The continuous optimum against a probability target.
struct ProbabilityContinuousOptimum {
  bool feasible = false;
  CoveringDesign design;  ///< thinnest (E_c [Pa], b_c [m]) meeting the target
  InjuryProbability at_design;
};

/// FindProbabilityDesign's answer.
struct ProbabilityDesign {
  DesignVerdict verdict = DesignVerdict::kNothingSafe;
  DesignCriterion criterion = DesignCriterion::kNoFullCompression;
  double max_probability = 0.0;
  /// The most failing samples a design may have: its 95 % upper bound is then <= max_probability.
  std::uint64_t allowed_failures = 0;
  InjuryProbability bare_robot;
  std::optional<ProbabilityContinuousOptimum> continuous;
  /// Materials meeting the target by recommended thickness, ties by estimate; then the rest by
  /// estimate at the maximum thickness.
  std::vector<ProbabilityCandidate> candidates;
  std::optional<std::size_t> recommendation;
  /// Exact-path evaluations, all designs. A rejected design stops early, and how many samples
  /// the threads had evaluated by then varies from run to run: this count (only) does.
  std::uint64_t sample_evaluations = 0;
  /// A braking robot: how the samples were judged, all designs (the time path with
  /// design.oracle.time_path's settings); a failed run counts as every event.
  TimePathUse time_path;
  double seconds = 0.0;
};

/// The thinnest covering whose probability of failing the criterion (any injury or, under the
/// default criterion, full compression; crushing for a material of known strength) is shown
/// to be <= max_probability: the upper end of its estimate's Wilson 95 % interval is at or
/// below it, not just the point estimate. Every design is judged on the same N scenes (common
/// random numbers: sample i is DrawInputs(box, seed, i) for every design), so designs differ
/// by their covering alone, not by sampling noise. A design is rejected as soon as its
/// failures exceed the most whose upper bound is within the target
/// (MostEventsWithUpperBoundWithin), which does not depend on the order the samples are
/// counted in. A material of unknown strength meets no target unless the design options allow
/// it or crushing.
/// @throws std::invalid_argument for bad options, a range on a covering field, or too few
///         samples for the target (even 0 failures would leave its upper bound above it).
ProbabilityDesign FindProbabilityDesign(const UncertaintyBox& box,
                                        std::span<const CandidateMaterial> materials,
                                        const ProbabilityDesignOptions& options = {});

}  // namespace covopt::optim
