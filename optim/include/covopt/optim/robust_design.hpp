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
/// Scope of this first version: the exact path only, so the nominal scene must be the paper's
/// conservative two-mass impact (Scene::is_conservative_two_mass: no damping, no braking, no
/// neck) and those six inputs cannot be uncertain; docs/model.md §10.4 says which path answers
/// the others.
///
/// Monotone inputs. The reflected robot mass, the head mass and the speed enter the exact path
/// only through the impact energy ½ μ v0² (μ = 1/(1/m_r + 1/m_h)); δ_max grows with it and every
/// peak is a non-decreasing function of δ_max (docs/model.md §9.1). Their worst case is
/// therefore the top of their range, for every other value; GlobalSearchOptions::
/// pin_energy_inputs (default on) fixes them there instead of searching them.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <covopt/core/scene.hpp>
#include <covopt/core/scene_fields.hpp>

#include "covopt/optim/covering_design.hpp"
#include "covopt/optim/problem.hpp"
#include "covopt/optim/speed_limit.hpp"

namespace covopt::optim {

class UncertaintyBox;
namespace internal {
void DrawInputsInto(const UncertaintyBox& box, std::uint64_t seed, std::uint64_t index,
                    std::span<double> values);
}  // namespace internal

// ----------------------------------------------------------------------------------------
// The box
// ----------------------------------------------------------------------------------------

/// How an uncertain input is drawn when sampling (the worst-case searches use the range only).
enum class InputDistribution {
  kUniform,    ///< uniform on [low, high] (default)
  kNormal,     ///< normal(mean, standard_deviation), truncated to [low, high]
  /// lognormal with the given mean and standard deviation of the VALUE (not of its log),
  /// truncated to [low, high]: ln x ~ normal(μ, σ) with σ² = ln(1 + sd²/mean²),
  /// μ = ln(mean) − σ²/2. Both parameters carry the field's unit, as a command line writes
  /// them ("lognormal:4.5kg:0.6kg").
  kLognormal,
};
/// "uniform", "normal", "lognormal".
const char* ToString(InputDistribution distribution) noexcept;

/// One scene input known only within a range.
struct UncertainInput {
  /// The scene field: its name ("head-mass") or dotted name ("head.mass"); see SceneFields().
  std::string field;
  /// The range [low, high] in the field's SI unit (kg, m, m/s, Pa or -), finite. low == high
  /// is a point: the input takes that value and is not searched (nor given a distribution).
  double low = 0.0;
  double high = 0.0;
  /// How it is sampled. Default: uniform on [low, high].
  InputDistribution distribution = InputDistribution::kUniform;
  /// kNormal, kLognormal: the mean of the untruncated distribution [SI], inside [low, high].
  double mean = 0.0;
  /// kNormal, kLognormal: its standard deviation [SI], > 0.
  double standard_deviation = 0.0;
};

/// A nominal scene and the inputs that vary in it: a validated, immutable value.
class UncertaintyBox {
 public:
  /// Validates `inputs` against `nominal`.
  /// @throws std::invalid_argument naming the field, the value and what is allowed, for: an
  ///   unknown field; a field given twice (by either name); low > high; a non-finite end (a
  ///   range cannot reach 'fixed' or 'flat'); a range on a field the nominal scene holds at
  ///   +inf (a fixed body, a flat robot); a covering-thickness range that includes 0 with
  ///   more (no covering is not the limit of a thin one, docs/model.md §5 item 4); a
  ///   distribution on a point, a standard deviation not > 0, a mean outside [low, high], a
  ///   lognormal with low < 0; an input of the extended scenes (damping, reaction-delay,
  ///   braking, torso-mass, neck-stiffness, neck-damping) or a nominal scene that has one;
  ///   an invalid nominal scene; and any corner of the box that is not a valid scene
  ///   (ImpactModel::FromScene's message, with the corner). The model's input ranges are
  ///   boxes and one linear condition (scalp thickness < head radius), so valid corners make
  ///   every point of the box valid.
  static UncertaintyBox FromScene(const Scene& nominal, std::span<const UncertainInput> inputs);

  /// The nominal scene: every field that is not uncertain keeps its value.
  const Scene& nominal() const noexcept { return nominal_; }
  /// The inputs as given, with `field` replaced by the field's name ("head-mass").
  std::span<const UncertainInput> inputs() const noexcept { return inputs_; }
  /// The scene field of input i.
  const SceneField& field(std::size_t i) const noexcept { return *fields_[i]; }
  std::size_t size() const noexcept { return inputs_.size(); }
  /// The input on `field` (name or dotted name), or nullptr.
  const UncertainInput* Find(std::string_view field) const noexcept;
  /// The nominal scene with input i set to values[i] [SI] (values.size() == size()).
  Scene SceneAt(std::span<const double> values) const;
  /// The centre of the box: (low + high) / 2 for every input [SI].
  std::vector<double> Centre() const;

 private:
  /// Per input, for sampling: the location and scale of the normal law (of x, or of ln x for
  /// a lognormal), Φ at the standardised low end, Φ at the high end and 1 − Φ there.
  struct Sampling {
    double location = 0.0, scale = 1.0, cdf_low = 0.0, cdf_high = 1.0, tail_high = 0.0;
  };
  friend void internal::DrawInputsInto(const UncertaintyBox& box, std::uint64_t seed,
                                       std::uint64_t index, std::span<double> values);

  UncertaintyBox() = default;
  Scene nominal_{};
  std::vector<UncertainInput> inputs_;
  std::vector<const SceneField*> fields_;
  std::vector<Sampling> sampling_;
};

// ----------------------------------------------------------------------------------------
// Worst case over the box
// ----------------------------------------------------------------------------------------

/// The global search over a box, used by every worst-case question here. The searched inputs
/// (those with low < high that are not pinned) are scaled to [0, 1]; the search evaluates
///   1. every corner, when there are at most max_corner_inputs searched inputs;
///   2. the centre and a Halton sequence of space_filling_points points;
///   3. NLopt DIRECT-L with global_evaluations evaluations;
///   4. NLopt COBYLA from the local_starts best distinct points found so far (one of them
///      DIRECT-L's), each with local_evaluations evaluations, to a relative step of 1e-10;
/// and keeps the best point evaluated. Deterministic.
struct GlobalSearchOptions {
  /// Enumerate all 2^k corners when k <= this, in [0, 16]. Default: 10 (1024 corners).
  int max_corner_inputs = 10;
  /// Halton points after the centre, >= 0; -1 = 32 + 32 k. Default: -1.
  int space_filling_points = -1;
  /// DIRECT-L's evaluation budget, >= 0 (0: skip the stage); -1 = 500 + 200 k. Default: -1.
  long global_evaluations = -1;
  /// COBYLA refinements, in [0, 20]. Default: 3.
  int local_starts = 3;
  /// Evaluations per refinement, >= 10; -1 = 100 + 50 k. Default: -1.
  long local_evaluations = -1;
  /// Hold robot-mass, head-mass and speed at their worst end (the top of the range for a
  /// worst impact, see the file comment) instead of searching them. Default: true.
  bool pin_energy_inputs = true;
};

/// Options of FindWorstCase.
struct WorstCaseOptions {
  /// false (default): criterion "no-full-compression"; true: the paper's, ratios only.
  bool allow_full_compression = false;
  DesignCriterion criterion() const noexcept {
    return allow_full_compression ? DesignCriterion::kPaper : DesignCriterion::kNoFullCompression;
  }
  /// Ratios must be <= 1/safety_factor, in [1, 100] [-]. Default: 1.
  double safety_factor = 1.0;
  /// The laceration [Pa] and contusion [J/m²] limits. Default: 1 MPa and 2.52 J/cm².
  InjuryLimits limits;
  GlobalSearchOptions search;
};

/// The worst impact over a box.
struct WorstCase {
  /// The inputs at the worst case [SI], in the order of UncertaintyBox::inputs().
  std::vector<double> values;
  /// The nominal scene with those values.
  Scene scene;
  double laceration_ratio = 0.0;   ///< σ_t,max / laceration limit [-]
  double contusion_ratio = 0.0;    ///< e_A,max / contusion limit [-]
  /// The covering's travel used [-] (DesignScore::compression_ratio); 0 without a covering.
  double compression_ratio = 0.0;
  bool fully_compressed = false;   ///< the covering is fully compressed at the peak
  /// σ_c,max / the material's compressive strength [-] when a crushing material is judged; else 0.
  double crush_ratio = 0.0;
  /// g = SF × max(r_L, r_C, r_δ (default criterion, with a covering), r_crush (a material of
  /// known strength, crushing not allowed)) [-]: what the search maximised.
  double governing_ratio = 0.0;
  /// The criterion that attains g (kNone never).
  LimitingCriterion binding = LimitingCriterion::kLaceration;
  /// g <= 1 and, under the default criterion, not fully compressed: the whole box is
  /// admissible (as far as the search can tell).
  bool admissible = false;
  /// The largest g over the corners, when they were enumerated (GlobalSearchOptions::
  /// max_corner_inputs): how far a corners-only check would have fallen short.
  std::optional<double> corner_governing_ratio;
  /// The stage whose point was kept: "corner", "centre", "space-filling", "global" (DIRECT-L),
  /// "local" (COBYLA), or "pinned" (nothing left to search).
  std::string found_by;
  SolverReport global;  ///< the DIRECT-L stage (backend empty when skipped)
  SolverReport local;   ///< the refinement that gave the best point (or the last one)
  long evaluations = 0;  ///< exact-path evaluations
  double seconds = 0.0;
};

/// The worst impact over the box for the nominal scene's covering (or bare robot).
/// @throws std::invalid_argument for bad options.
WorstCase FindWorstCase(const UncertaintyBox& box, const WorstCaseOptions& options = {});

// ----------------------------------------------------------------------------------------
// Robust thinnest covering
// ----------------------------------------------------------------------------------------

/// Options of FindRobustThinnestCovering.
struct RobustDesignOptions {
  /// The design problem as FindThinnestSafeCovering poses it: search space, criterion, safety
  /// factor, limits, ν_c of the continuous design, the catalog scan (thickness_scan_points,
  /// thickness_resolution_m), thickness_step_m, threads (materials in parallel; the result is
  /// identical for any count), bracket_thickness_points and modulus_points_per_decade (the
  /// continuous nested search). Its NLopt and Ipopt settings and its oracle are not used: the
  /// robust searches run on the exact path.
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
  long evaluations = 0;  ///< exact-path evaluations, all stages
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

// ----------------------------------------------------------------------------------------
// Speed and mass limits over the box
// ----------------------------------------------------------------------------------------

/// MaxSafeSpeedOverBox's answer.
struct RobustSpeedLimit {
  /// MaxSafeSpeed at the worst case: the largest speed safe for every value in the box.
  SpeedLimit limit;
  std::vector<double> values;  ///< the inputs there [SI], in the box's order
  Scene scene;                 ///< the scene there
  std::string found_by;        ///< as WorstCase::found_by
  long evaluations = 0;        ///< MaxSafeSpeed evaluations
  double seconds = 0.0;
};

/// MaxSafeMassOverBox's answer.
struct RobustMassLimit {
  MassLimit limit;  ///< MaxSafeMass at the worst case
  std::vector<double> values;
  Scene scene;
  std::string found_by;
  long evaluations = 0;
  double seconds = 0.0;
};

/// min over the box of MaxSafeSpeed (the same global search; robot and head mass pinned at
/// the top of their ranges when `search.pin_energy_inputs`: a heavier body only lowers it).
/// @throws std::invalid_argument for a range on the speed ("speed: the speed limit is what is
///   computed; it cannot be uncertain") or bad options.
RobustSpeedLimit MaxSafeSpeedOverBox(const UncertaintyBox& box, const SpeedLimitOptions& options = {},
                                     const GlobalSearchOptions& search = {});

/// min over the box of MaxSafeMass (speed and head mass pinned at the top when
/// `search.pin_energy_inputs`).
/// @throws std::invalid_argument for a range on robot-mass or bad options.
RobustMassLimit MaxSafeMassOverBox(const UncertaintyBox& box, const SpeedLimitOptions& options = {},
                                   const GlobalSearchOptions& search = {});

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
  /// Called on the calling thread with the fraction of samples done, in [0, 1], last with 1.
  /// An exception it throws stops the work (the threads are joined) and propagates.
  std::function<void(double fraction_done)> progress;
};

/// EstimateInjuryProbability's answer.
struct InjuryProbability {
  ProbabilityEstimate laceration;        ///< SF r_L > 1
  ProbabilityEstimate contusion;         ///< SF r_C > 1
  ProbabilityEstimate any;               ///< either
  ProbabilityEstimate fully_compressed;  ///< the covering fully compressed at the peak
  /// Fails the design criterion: any injury or, under the default criterion, fully compressed
  /// (= `any` under the paper's criterion).
  ProbabilityEstimate inadmissible;
  std::uint64_t seed = 0;
  unsigned threads = 0;  ///< threads used
  double seconds = 0.0;
};

/// The fractions of `options.samples` scenes drawn from the box (each input from its
/// distribution, independently) that are injured, for the nominal scene's covering.
/// @throws std::invalid_argument for bad options.
InjuryProbability EstimateInjuryProbability(const UncertaintyBox& box,
                                            const InjuryProbabilityOptions& options = {});

/// The inputs [SI] of sample `index` for `seed`, in the box's order: what
/// EstimateInjuryProbability evaluates. Each input j takes the j-th draw of the sample's
/// stream (a SplitMix64 sequence started at mix(mix(seed) + index)), a uniform u in (0, 1)
/// mapped by the inverse of the (truncated) distribution function, so a sample does not
/// depend on the others or on the thread that draws it.
std::vector<double> DrawInputs(const UncertaintyBox& box, std::uint64_t seed, std::uint64_t index);

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

// ----------------------------------------------------------------------------------------
// Sensitivities
// ----------------------------------------------------------------------------------------

/// How a derivative was obtained.
enum class DerivativeMethod {
  kAnalytic,            ///< ExactPeakSensitivities (covering modulus and thickness)
  kCentralDifference,   ///< central differences in ln x at two steps
  kOneSidedDifference,  ///< second-order one-sided differences (at the edge of a field's range)
};
/// "analytic", "central-difference", "one-sided-difference".
const char* ToString(DerivativeMethod method) noexcept;

/// The elasticities d ln r / d ln x = (x / r) dr/dx of the ratios to one scene input.
struct InputElasticity {
  std::string field;  ///< the field's name ("head-mass")
  double value = 0.0; ///< x [SI]
  double laceration = 0.0;  ///< of r_L [-]
  double contusion = 0.0;   ///< of r_C [-]
  /// of r_δ = δ_max / t2 [-]; empty without a covering.
  std::optional<double> compression;
  DerivativeMethod method = DerivativeMethod::kCentralDifference;
  /// The two step sizes agreed to ElasticityOptions::tolerance (always true for kAnalytic).
  /// False near a phase switch (a kink of the law) or where a step leaves the field's range
  /// on both sides; the numbers are then the smaller step's.
  bool reliable = true;
  /// The largest disagreement of the two steps, |e1 − e2| / max(|e1|, |e2|, 1e-6) [-].
  double discrepancy = 0.0;
};

/// Options of ComputeElasticities.
struct ElasticityOptions {
  /// The laceration [Pa] and contusion [J/m²] limits (they scale the ratios only).
  InjuryLimits limits;
  /// The two steps in ln x: h and h/10, in [1e-6, 0.1]. Default: 1e-3.
  double log_step = 1e-3;
  /// Agreement required of the two steps, in (0, 1). Default: 1e-4.
  double tolerance = 1e-4;
};

/// The elasticities at one scene (its covering is the design).
struct ElasticityTable {
  double laceration_ratio = 0.0;
  double contusion_ratio = 0.0;
  std::optional<double> compression_ratio;  ///< δ_max / t2; empty without a covering
  /// One row per scene field that is finite and non-zero in the scene (without a covering,
  /// the covering's fields are left out), sorted by the magnitude of the elasticity of the
  /// larger injury ratio at the scene (r_L or r_C), largest first, ties in SceneFields()
  /// order: a tornado chart's order.
  std::vector<InputElasticity> rows;
  long evaluations = 0;  ///< exact-path evaluations
};

/// Elasticities of r_L, r_C and r_δ to every scene input at `scene`.
/// @throws std::invalid_argument for an invalid scene, a scene outside the exact path's
///   conservative two-mass model, or bad options.
ElasticityTable ComputeElasticities(const Scene& scene, const ElasticityOptions& options = {});

}  // namespace covopt::optim
