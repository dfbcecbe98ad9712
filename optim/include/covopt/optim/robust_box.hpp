#pragma once
/// @file robust_box.hpp
/// The uncertainty box of the robust design (robust_design.hpp): a nominal Scene plus scene
/// inputs known only within ranges, each with a distribution for sampling.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <covopt/core/scene.hpp>
#include <covopt/core/scene_fields.hpp>
#include <covopt/core/time_integration.hpp>

namespace covopt::optim {

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
std::string_view ToString(InputDistribution distribution) noexcept;

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
  ///   lognormal with low < 0; a range on damping, torso-mass, neck-stiffness or neck-damping,
  ///   or a nominal scene with contact damping or a neck (a braking robot, and ranges on
  ///   reaction-delay and braking, are accepted: docs/model.md §11, "A braking robot");
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
  /// The inputs [SI] of sample `index` for `seed` into `values` (size()): DrawInputs without
  /// allocating.
  void DrawInto(std::uint64_t seed, std::uint64_t index, std::span<double> values) const;
  /// Some scene of the box has a braking robot (the nominal scene brakes, or braking's range
  /// reaches above 0): its impacts are judged on the time path, screened by the exact path's
  /// bound (docs/model.md §11, "A braking robot").
  bool brakes() const noexcept;

 private:
  /// Per input, for sampling: the location and scale of the normal law (of x, or of ln x for
  /// a lognormal), Φ at the standardised low end, Φ at the high end and 1 − Φ there.
  struct Sampling {
    double location = 0.0, scale = 1.0, cdf_low = 0.0, cdf_high = 1.0, tail_high = 0.0;
  };

  UncertaintyBox() = default;
  Scene nominal_{};
  std::vector<UncertainInput> inputs_;
  std::vector<const SceneField*> fields_;
  std::vector<Sampling> sampling_;
};

/// How a robust search judged the impacts of a braking robot (docs/model.md §11, "A braking
/// robot"). Braking only takes energy out of the impact, so the unbraked impact's ratios (the
/// exact path) bound the braked ones from above; the time path runs only where that bound
/// cannot decide. All zero for a box without braking.
struct TimePathUse {
  /// Impacts decided by the exact path's bound: the unbraked impact was admissible (hence the
  /// braked one), or, in a worst-case search, could not exceed the worst impact found so far.
  long screened = 0;
  /// Impacts whose brake starts at or after the unbraked impact's maximum compression: the
  /// braked peaks are the unbraked ones, which the exact path gives.
  long brake_after_peak = 0;
  long runs = 0;  ///< time-path runs (SimulateImpact)
  /// Runs that failed (a status other than success): judged inadmissible with infinite
  /// ratios, never safe; a result that rests on one says so.
  long failed = 0;
  std::string first_failure;  ///< the first failure's message; empty if none
  /// Adds `other`'s counts (the first failure kept).
  void Add(const TimePathUse& other);
};

/// The inputs [SI] of sample `index` for `seed`, in the box's order: what
/// EstimateInjuryProbability evaluates. Each input j takes the j-th draw of the sample's
/// stream (a SplitMix64 sequence started at mix(mix(seed) + index)), a uniform u in (0, 1)
/// mapped by the inverse of the (truncated) distribution function, so a sample does not
/// depend on the others or on the thread that draws it.
std::vector<double> DrawInputs(const UncertaintyBox& box, std::uint64_t seed, std::uint64_t index);

}  // namespace covopt::optim
