// The uncertainty box (optim/robust_design.hpp): validation, sampling from each input's
// distribution on per-sample random streams, the normal distribution function and its
// inverse, the Wilson interval, and the judgement of one impact shared by every robust search.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <boost/math/special_functions/erf.hpp>

#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/core/quantity.hpp>
#include <covopt/core/time_integration.hpp>

#include "covopt/optim/robust_box.hpp"
#include "robust_internal.hpp"

namespace covopt::optim {
namespace internal {

void ValidateCriterion(const ImpactCriterion& c) {
  Require(std::isfinite(c.safety_factor) && c.safety_factor >= 1.0 && c.safety_factor <= 100.0,
          "safety factor must be in [1, 100] (got " + Number(c.safety_factor) + ")");
  const double laceration = c.limits.laceration_tensile_stress_Pa;
  const double contusion = c.limits.contusion_energy_density_J_per_m2;
  Require(std::isfinite(laceration) && laceration > 0.0,
          "laceration limit must be finite and > 0 Pa (got " + Number(laceration) + ")");
  Require(std::isfinite(contusion) && contusion > 0.0,
          "contusion limit must be finite and > 0 J/m2 (got " + Number(contusion) + ")");
  const double fracture = c.limits.fracture_force_N;
  Require(std::isfinite(fracture) && fracture >= 0.0,
          "fracture force must be finite and >= 0 N, 0 for the struck area's (got " + Number(fracture) + ")");
}

ImpactCriterion MakeCriterion(DesignCriterion rule, double safety_factor, const InjuryLimits& limits,
                              double compressive_strength_Pa, bool allow_crushing) {
  Require(std::isfinite(compressive_strength_Pa) && compressive_strength_Pa >= 0.0,
          "compressive strength must be finite and >= 0 Pa (got " + Number(compressive_strength_Pa) + ")");
  ImpactCriterion c{rule, safety_factor, limits};
  c.compressive_strength_Pa = compressive_strength_Pa;
  c.crush_counts = compressive_strength_Pa > 0.0 && !allow_crushing;
  ValidateCriterion(c);
  return c;
}

void TimePathCounter::Fail(const std::string& message) {
  ++failed_;
  const std::lock_guard<std::mutex> lock(mutex_);
  if (first_failure_.empty()) first_failure_ = message;
}

void TimePathCounter::Add(const TimePathUse& use) {
  screened_ += use.screened;
  brake_after_peak_ += use.brake_after_peak;
  runs_ += use.runs;
  failed_ += use.failed;
  const std::lock_guard<std::mutex> lock(mutex_);
  if (first_failure_.empty()) first_failure_ = use.first_failure;
}

TimePathUse TimePathCounter::Use() const {
  TimePathUse use;
  use.screened = screened_.load();
  use.brake_after_peak = brake_after_peak_.load();
  use.runs = runs_.load();
  use.failed = failed_.load();
  const std::lock_guard<std::mutex> lock(mutex_);
  use.first_failure = first_failure_;
  return use;
}

/// The scene's fields that differ from the paper's scene (Scene{}), "name = value, ...".
std::string SceneText(const Scene& scene) {
  static const Scene paper{};
  std::string text;
  for (const SceneField& field : SceneFields()) {
    const double value = field.value(scene);
    if (value == field.value(paper)) continue;
    text += (text.empty() ? "" : ", ") + std::string(field.name) + " = " + FormatQuantity(value, field.spec.kind);
  }
  return text.empty() ? "the paper's scene" : text;
}

Scene Unbraked(const Scene& scene) {
  Scene unbraked = scene;
  unbraked.robot.braking_m_per_s2 = 0.0;
  unbraked.robot.reaction_delay_s = 0.0;
  return unbraked;
}

namespace {

/// The ratios, events and governing ratio of an impact from its peaks.
void JudgePeaks(Judged& j, const ImpactCriterion& c, HeadArea area) {
  j.laceration_ratio = j.peaks.max_tensile_stress_Pa / c.limits.laceration_tensile_stress_Pa;
  j.contusion_ratio = j.peaks.max_energy_density_J_per_m2 / c.limits.contusion_energy_density_J_per_m2;
  j.fracture_ratio = j.peaks.peak_force_N / FractureLimit(c.limits, area);
  if (j.covered) {
    j.compression_ratio = j.peaks.covering_compression_ratio();
    j.fully_compressed = j.peaks.fully_compressed;
    if (c.compressive_strength_Pa > 0.0) j.crush_ratio = j.peaks.max_compressive_stress_Pa / c.compressive_strength_Pa;
  }
  const double sf = c.safety_factor;
  j.laceration = sf * j.laceration_ratio > 1.0;
  j.contusion = sf * j.contusion_ratio > 1.0;
  j.fracture = sf * j.fracture_ratio > 1.0;
  j.crushed = sf * j.crush_ratio > 1.0;
  const bool compression_counts = j.covered && c.criterion == DesignCriterion::kNoFullCompression;
  const bool crush_counts = j.covered && c.crush_counts && c.compressive_strength_Pa > 0.0;
  j.governing_ratio = sf * j.laceration_ratio;
  j.binding = LimitingCriterion::kLaceration;
  auto consider = [&j, sf](double ratio, LimitingCriterion criterion) {
    if (sf * ratio > j.governing_ratio) {
      j.governing_ratio = sf * ratio;
      j.binding = criterion;
    }
  };
  consider(j.contusion_ratio, LimitingCriterion::kContusion);
  consider(j.fracture_ratio, LimitingCriterion::kFracture);
  if (compression_counts) consider(j.compression_ratio, LimitingCriterion::kFullCompression);
  if (crush_counts) consider(j.crush_ratio, LimitingCriterion::kCrush);
  j.admissible = j.governing_ratio <= 1.0 && !(compression_counts && j.fully_compressed);
}

/// The covering's law validity at j's peaks (as DesignScore::validity_ratio and validity_fails):
/// it counts as its ratio (not derated, so unscaled in g); out of it, the impact is inadmissible.
void JudgeValidity(Judged& j, const ImpactModel& model, const ImpactCriterion& c) {
  if (!j.covered) return;
  j.validity = CoveringLawValidity(model, j.peaks);
  const bool accepted = c.criterion == DesignCriterion::kPaper && j.peaks.covering_law == CoveringLaw::kHertz;
  const double ratio = accepted ? j.validity.ratio_full_compression_allowed : j.validity.ratio;
  if (ratio > j.governing_ratio) {
    j.governing_ratio = ratio;
    j.binding = LimitingCriterion::kLawValidity;
  }
  if (accepted ? !(ratio > 1.0) : j.validity.within) return;
  j.out_of_validity = true;
  j.admissible = false;
}

/// A failed time-path run: every ratio +inf, every event, inadmissible.
void JudgeFailed(Judged& j) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  j.failed = true;
  j.laceration_ratio = j.contusion_ratio = j.fracture_ratio = j.governing_ratio = inf;
  j.compression_ratio = j.covered ? inf : 0.0;
  j.crush_ratio = 0.0;
  j.fully_compressed = j.covered;
  j.laceration = j.contusion = j.fracture = true;
  j.admissible = false;
}

}  // namespace

Judged JudgeScene(const Scene& scene, const ImpactCriterion& c, const Screening& screening) {
  const bool brakes = scene.robot_brakes();
  const ImpactModel model = ImpactModel::FromScene(brakes ? Unbraked(scene) : scene);
  Judged j;
  j.peaks = ExactPeaks(model);
  j.covered = model.has_covering();
  JudgePeaks(j, c, scene.head.area);
  JudgeValidity(j, model, c);
  if (!brakes) return j;
  // Braking only takes energy out of the impact: the unbraked judgement bounds the braked
  // one (docs/model.md §11). Until the brake starts the two impacts are the same; a brake that
  // starts at or after the unbraked maximum compression (half the conservative contact's
  // duration) leaves δ_max, and with it every peak, as it was.
  if (scene.robot.reaction_delay_s >= 0.5 * ExactContactDuration(model, j.peaks)) {
    j.by = JudgedBy::kBrakeAfterPeak;
    if (c.counter) c.counter->BrakeAfterPeak();
    return j;
  }
  const bool no_event = j.admissible && !j.injured() && !j.crushed && !j.fully_compressed;
  if ((screening.when_admissible && no_event) || j.governing_ratio <= screening.at_or_below) {
    j.by = JudgedBy::kBound;
    if (c.counter) c.counter->Screened();
    return j;
  }
  j.by = JudgedBy::kTimePath;
  if (c.counter) c.counter->Run();
  TimeIntegrationOptions options = c.time_path;
  options.record_history = false;
  const ImpactModel result_model = ImpactModel::FromScene(scene);
  const ImpactResult result = SimulateImpact(result_model, options);
  if (!result.ok()) {
    JudgeFailed(j);
    if (c.counter) {
      c.counter->Fail("time path at " + SceneText(scene) + ": " + std::string(covopt::ToString(result.status)) +
                      ": " + result.message);
    }
    return j;
  }
  j.peaks = result.peaks;
  JudgePeaks(j, c, scene.head.area);
  JudgeValidity(j, result_model, c);
  return j;
}

void FillWorstCase(const Judged& j, WorstCase& worst) {
  worst.laceration_ratio = j.laceration_ratio;
  worst.contusion_ratio = j.contusion_ratio;
  worst.compression_ratio = j.compression_ratio;
  worst.fully_compressed = j.fully_compressed;
  worst.crush_ratio = j.crush_ratio;
  worst.fracture_ratio = j.fracture_ratio;
  worst.governing_ratio = j.governing_ratio;
  worst.binding = j.binding;
  worst.admissible = j.admissible;
}

void ApplyInputs(const UncertaintyBox& box, std::span<const double> values, Scene& scene) {
  for (std::size_t i = 0; i < box.size(); ++i) box.field(i).field(scene) = values[i];
}

bool IsEnergyInput(const SceneField& field) {
  return field.name == "robot-mass" || field.name == "head-mass" || field.name == "speed";
}

void RefuseRange(const UncertaintyBox& box, std::string_view field_name, const std::string& why) {
  const UncertainInput* input = box.Find(field_name);
  if (input && input->low < input->high) {
    const SceneField& field = *FindSceneField(field_name);
    throw std::invalid_argument(field.dotted_name() + " range " +
                                FormatQuantity(input->low, field.spec.kind) + ".." +
                                FormatQuantity(input->high, field.spec.kind) + ": " + why);
  }
}

namespace {

constexpr std::uint64_t kGoldenGamma = 0x9e3779b97f4a7c15ULL;

/// SplitMix64's output function (Steele, Lea & Flood 2014): a bijection of 64-bit words.
std::uint64_t Mix64(std::uint64_t z) noexcept {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

/// One sample's random stream: SplitMix64 from a start that depends on (seed, index) only.
class SampleStream {
 public:
  SampleStream(std::uint64_t seed, std::uint64_t index) noexcept : state_(Mix64(Mix64(seed) + index)) {}
  /// A uniform number in (0, 1): 53 random bits, centred in their cell (never 0 or 1).
  double Uniform() noexcept {
    state_ += kGoldenGamma;
    return (static_cast<double>(Mix64(state_) >> 11) + 0.5) * 0x1.0p-53;
  }

 private:
  std::uint64_t state_;
};

}  // namespace

}  // namespace internal

void UncertaintyBox::DrawInto(std::uint64_t seed, std::uint64_t index, std::span<double> values) const {
  const UncertaintyBox& box = *this;
  internal::SampleStream stream(seed, index);
  for (std::size_t i = 0; i < box.size(); ++i) {
    const UncertainInput& input = box.inputs_[i];
    const double u = stream.Uniform();  // drawn for every input, so input j always takes draw j
    double x = input.low;
    if (input.low < input.high) {
      if (input.distribution == InputDistribution::kUniform) {
        x = input.low + u * (input.high - input.low);
      } else {
        // Inverse-CDF sampling of the truncated normal law: p = Φ(α) + u (Φ(β) − Φ(α)). Above
        // the median the complement 1 − p = (1 − Φ(β)) + (1 − u)(Φ(β) − Φ(α)) is formed directly
        // (1 − u is exact), so the upper tail keeps its relative accuracy.
        const UncertaintyBox::Sampling& s = box.sampling_[i];
        const double mass = s.cdf_high - s.cdf_low;
        const double p = s.cdf_low + u * mass;
        const double z = p <= 0.5 ? InverseStandardNormalCdf(p)
                                  : -InverseStandardNormalCdf(s.tail_high + (1.0 - u) * mass);
        const double y = s.location + s.scale * z;
        x = input.distribution == InputDistribution::kNormal ? y : std::exp(y);
      }
      x = std::clamp(x, input.low, input.high);  // rounding only
    }
    values[i] = x;
  }
}

using internal::Number;
using internal::Require;

std::string_view ToString(InputDistribution distribution) noexcept {
  switch (distribution) {
    case InputDistribution::kUniform: return "uniform";
    case InputDistribution::kNormal: return "normal";
    case InputDistribution::kLognormal: return "lognormal";
  }
  return "unknown";
}

namespace {

/// Boost.Math reports a domain or overflow error through errno instead of throwing (Φ and Φ⁻¹
/// are noexcept and screen their arguments first).
using NoThrow = boost::math::policies::policy<boost::math::policies::domain_error<boost::math::policies::errno_on_error>,
                                              boost::math::policies::overflow_error<boost::math::policies::errno_on_error>>;
/// The same, computing in double: Φ⁻¹ runs once per normal input of every Monte Carlo sample.
using NoThrowInDouble = boost::math::policies::normalise<NoThrow, boost::math::policies::promote_double<false>>::type;

}  // namespace

double StandardNormalCdf(double z) noexcept {
  return 0.5 * boost::math::erfc(-z * std::numbers::sqrt2 / 2.0, NoThrow());
}

double InverseStandardNormalCdf(double p) noexcept {
  if (std::isnan(p) || p < 0.0 || p > 1.0) return std::numeric_limits<double>::quiet_NaN();
  if (p == 0.0) return -std::numeric_limits<double>::infinity();
  if (p == 1.0) return std::numeric_limits<double>::infinity();
  return -std::numbers::sqrt2 * boost::math::erfc_inv(2.0 * p, NoThrowInDouble());  // 2p is exact
}

ProbabilityEstimate WilsonEstimate(std::uint64_t count, std::uint64_t samples) {
  Require(samples > 0, "a probability needs at least one sample (got 0)");
  Require(count <= samples, "event count " + std::to_string(count) + " exceeds the samples (" +
                                std::to_string(samples) + ")");
  constexpr double z = 1.959963984540054;  // Φ⁻¹(0.975)
  ProbabilityEstimate e;
  e.count = count;
  e.samples = samples;
  const double n = static_cast<double>(samples);
  const double p = static_cast<double>(count) / n;
  e.probability = p;
  const double z2n = z * z / n;
  const double centre = (p + z2n / 2.0) / (1.0 + z2n);
  const double half = z / (1.0 + z2n) * std::sqrt(p * (1.0 - p) / n + z2n / (4.0 * n));
  e.ci95_low = count == 0 ? 0.0 : std::max(0.0, centre - half);
  e.ci95_high = count == samples ? 1.0 : std::min(1.0, centre + half);
  return e;
}

std::optional<std::uint64_t> MostEventsWithUpperBoundWithin(double probability, std::uint64_t samples) {
  Require(samples > 0, "a probability needs at least one sample (got 0)");
  if (WilsonEstimate(0, samples).ci95_high > probability) return std::nullopt;
  // The bound exceeds count / samples, so the answer is below probability × samples + 1.
  std::uint64_t within = 0;
  std::uint64_t beyond = std::min<std::uint64_t>(
      samples, static_cast<std::uint64_t>(std::floor(probability * static_cast<double>(samples))) + 1);
  if (WilsonEstimate(beyond, samples).ci95_high <= probability) return beyond;
  while (beyond - within > 1) {
    const std::uint64_t mid = within + (beyond - within) / 2;
    (WilsonEstimate(mid, samples).ci95_high <= probability ? within : beyond) = mid;
  }
  return within;
}

namespace {

/// The inputs of the scenes beyond the two-mass model the robust analysis covers (docs/model.md
/// §10): contact damping and the neck (a braking robot is covered, §11).
bool IsExtendedInput(const SceneField& field) {
  return field.name == "damping" || field.name == "torso-mass" || field.name == "neck-stiffness" ||
         field.name == "neck-damping";
}

std::string Range(const SceneField& field, double low, double high) {
  return FormatQuantity(low, field.spec.kind) + ".." + FormatQuantity(high, field.spec.kind);
}

std::string ValueText(const SceneField& field, double value) {
  return std::isnan(value) ? std::string("nan") : FormatQuantity(value, field.spec.kind);
}

/// Throws unless [low, high] is a range `field` can take in `nominal`: finite ends, low <= high,
/// a field the nominal scene does not hold at +inf, and no covering-thickness range from 0.
void CheckRange(const SceneField& field, double low, double high, const Scene& nominal) {
  const std::string name = field.dotted_name();
  if (!std::isfinite(low) || !std::isfinite(high)) {
    throw std::invalid_argument(name + " range " + ValueText(field, low) + ".." + ValueText(field, high) +
                                ": both ends must be finite (a range cannot reach 'fixed' or 'flat')");
  }
  Require(low <= high, name + " range " + Range(field, low, high) + ": low must not exceed high");
  const double nominal_value = field.value(nominal);
  if (std::isinf(nominal_value)) {
    throw std::invalid_argument(name + " range " + Range(field, low, high) + ": the scene holds " + name +
                                " at " + FormatQuantity(nominal_value, field.spec.kind) +
                                " (a body held still, or a flat robot); a range cannot apply to it");
  }
  if (field.name == "covering-thickness" && low == 0.0 && high > 0.0) {
    throw std::invalid_argument(name + " range " + Range(field, low, high) +
                                ": must not include 0 (no covering) with thicker coverings: no covering is "
                                "not the limit of a thin one (docs/model.md §5 item 4)");
  }
}

/// Throws unless every corner of the box is a valid scene (the model's input domain is a box and
/// one linear condition, so then every point is), naming the corner.
void CheckCorners(const UncertaintyBox& box, const Scene& nominal) {
  std::vector<std::size_t> ranged;
  for (std::size_t i = 0; i < box.size(); ++i) {
    if (box.inputs()[i].low < box.inputs()[i].high) ranged.push_back(i);
  }
  std::vector<double> values(box.size());
  const std::uint64_t corners = std::uint64_t{1} << ranged.size();  // at most 2^15 fields
  for (std::uint64_t mask = 0; mask < corners; ++mask) {
    for (std::size_t i = 0; i < box.size(); ++i) values[i] = box.inputs()[i].low;
    for (std::size_t k = 0; k < ranged.size(); ++k) {
      if (mask >> k & 1U) values[ranged[k]] = box.inputs()[ranged[k]].high;
    }
    Scene scene = nominal;
    internal::ApplyInputs(box, values, scene);
    try {
      (void)ImpactModel::FromScene(scene);
    } catch (const std::invalid_argument& error) {
      std::string corner;
      for (std::size_t i = 0; i < box.size(); ++i) {
        corner += (corner.empty() ? "" : ", ") + std::string(box.field(i).name) + " = " +
                  FormatQuantity(values[i], box.field(i).spec.kind);
      }
      throw std::invalid_argument("the box leaves the model's input range at the corner " + corner + ": " +
                                  error.what());
    }
  }
}

}  // namespace

UncertaintyBox UncertaintyBox::FromScene(const Scene& nominal, std::span<const UncertainInput> inputs) {
  (void)ImpactModel::FromScene(nominal);  // the nominal scene itself must be valid
  if (nominal.is_damped() || nominal.head.has_neck()) {
    throw std::invalid_argument(
        "the robust analysis covers the two-mass impact, conservative or with a braking robot: the scene has "
        "contact damping or a neck (docs/model.md §10, §11); give damping and torso-mass 0");
  }
  UncertaintyBox box;
  box.nominal_ = nominal;
  for (const UncertainInput& given : inputs) {
    const SceneField* field = FindSceneField(given.field);
    Require(field != nullptr, "uncertain input '" + given.field + "': no scene quantity '" + given.field +
                                  "'; the quantities are " + SceneFieldNames());
    const std::string name = field->dotted_name();
    for (const SceneField* seen : box.fields_) {
      Require(seen != field, name + " is given a range twice; give each input once");
    }
    if (IsExtendedInput(*field)) {
      throw std::invalid_argument(name + " cannot be uncertain: the robust analysis covers the two-mass impact, "
                                         "conservative or with a braking robot (docs/model.md §10, §11)");
    }
    const double low = given.low, high = given.high;
    CheckRange(*field, low, high, nominal);
    UncertainInput input = given;
    input.field = std::string(field->name);
    Sampling sampling;
    if (input.distribution != InputDistribution::kUniform) {
      const std::string law(ToString(input.distribution));
      Require(low < high, name + ": a " + law + " distribution needs a range (low < high); got the point " +
                              FormatQuantity(low, field->spec.kind));
      const double mean = input.mean, sd = input.standard_deviation;
      Require(std::isfinite(sd) && sd > 0.0, name + ": the " + law + " standard deviation must be finite and > 0 (got " +
                                                 ValueText(*field, sd) + ")");
      Require(std::isfinite(mean) && mean >= low && mean <= high,
              name + ": the " + law + " mean must lie in the range " + Range(*field, low, high) + " (got " +
                  ValueText(*field, mean) + ")");
      double alpha, beta;
      if (input.distribution == InputDistribution::kNormal) {
        sampling.location = mean;
        sampling.scale = sd;
        alpha = (low - mean) / sd;
        beta = (high - mean) / sd;
      } else if (input.distribution == InputDistribution::kLognormal) {
        Require(low >= 0.0, name + ": a lognormal distribution needs a range within [0, inf) (got " +
                                Range(*field, low, high) + ")");
        Require(mean > 0.0, name + ": the lognormal mean must be > 0 (got " + ValueText(*field, mean) + ")");
        const double sigma2 = std::log1p((sd / mean) * (sd / mean));
        sampling.scale = std::sqrt(sigma2);
        sampling.location = std::log(mean) - sigma2 / 2.0;
        alpha = low > 0.0 ? (std::log(low) - sampling.location) / sampling.scale
                          : -std::numeric_limits<double>::infinity();
        beta = (std::log(high) - sampling.location) / sampling.scale;
      } else {
        throw std::invalid_argument(name + ": unknown distribution");
      }
      sampling.cdf_low = StandardNormalCdf(alpha);
      sampling.cdf_high = StandardNormalCdf(beta);
      sampling.tail_high = StandardNormalCdf(-beta);
      Require(sampling.cdf_high - sampling.cdf_low > 0.0,
              name + ": the " + law + " distribution has no probability in the range " + Range(*field, low, high));
    }
    box.inputs_.push_back(input);
    box.fields_.push_back(field);
    box.sampling_.push_back(sampling);
  }

  CheckCorners(box, nominal);
  return box;
}

const UncertainInput* UncertaintyBox::Find(std::string_view field) const noexcept {
  const SceneField* wanted = FindSceneField(field);
  for (std::size_t i = 0; i < fields_.size(); ++i) {
    if (fields_[i] == wanted) return &inputs_[i];
  }
  return nullptr;
}

bool UncertaintyBox::brakes() const noexcept {
  if (nominal_.robot_brakes()) return true;
  for (std::size_t i = 0; i < inputs_.size(); ++i) {
    if (fields_[i]->name == "braking" && inputs_[i].high > 0.0) return true;
  }
  return false;
}

void TimePathUse::Add(const TimePathUse& other) {
  screened += other.screened;
  brake_after_peak += other.brake_after_peak;
  runs += other.runs;
  failed += other.failed;
  if (first_failure.empty()) first_failure = other.first_failure;
}

Scene UncertaintyBox::SceneAt(std::span<const double> values) const {
  Require(values.size() == size(), "SceneAt: " + std::to_string(values.size()) + " values for " +
                                       std::to_string(size()) + " uncertain inputs");
  Scene scene = nominal_;
  internal::ApplyInputs(*this, values, scene);
  return scene;
}

std::vector<double> UncertaintyBox::Centre() const {
  std::vector<double> centre;
  centre.reserve(size());
  for (const UncertainInput& input : inputs_) {
    centre.push_back(input.low == input.high ? input.low : 0.5 * (input.low + input.high));
  }
  return centre;
}

std::vector<double> DrawInputs(const UncertaintyBox& box, std::uint64_t seed, std::uint64_t index) {
  std::vector<double> values(box.size());
  box.DrawInto(seed, index, values);
  return values;
}

}  // namespace covopt::optim
