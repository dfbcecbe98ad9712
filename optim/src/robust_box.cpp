// The uncertainty box (optim/robust_design.hpp): validation, sampling from each input's
// distribution on per-sample random streams, the normal distribution function and its
// inverse, the Wilson interval, and the judgement of one impact shared by every robust search.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/core/quantity.hpp>

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
}

Judged JudgeScene(const Scene& scene, const ImpactCriterion& c) {
  const ImpactModel model = ImpactModel::FromScene(scene);
  Judged j;
  j.peaks = ExactPeaks(model);
  j.covered = model.has_covering();
  j.laceration_ratio = j.peaks.max_tensile_stress_Pa / c.limits.laceration_tensile_stress_Pa;
  j.contusion_ratio = j.peaks.max_energy_density_J_per_m2 / c.limits.contusion_energy_density_J_per_m2;
  if (j.covered) {
    j.compression_ratio = j.peaks.covering_compression_ratio();
    j.fully_compressed = j.peaks.fully_compressed;
    if (c.compressive_strength_Pa > 0.0) j.crush_ratio = j.peaks.max_compressive_stress_Pa / c.compressive_strength_Pa;
  }
  const double sf = c.safety_factor;
  j.laceration = sf * j.laceration_ratio > 1.0;
  j.contusion = sf * j.contusion_ratio > 1.0;
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
  if (compression_counts) consider(j.compression_ratio, LimitingCriterion::kFullCompression);
  if (crush_counts) consider(j.crush_ratio, LimitingCriterion::kCrush);
  j.admissible = j.governing_ratio <= 1.0 && !(compression_counts && j.fully_compressed);
  return j;
}

void FillWorstCase(const Judged& j, WorstCase& worst) {
  worst.laceration_ratio = j.laceration_ratio;
  worst.contusion_ratio = j.contusion_ratio;
  worst.compression_ratio = j.compression_ratio;
  worst.fully_compressed = j.fully_compressed;
  worst.crush_ratio = j.crush_ratio;
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

double StandardNormalCdf(double z) noexcept { return 0.5 * std::erfc(-z * std::numbers::sqrt2 / 2.0); }

double InverseStandardNormalCdf(double p) noexcept {
  // Wichura, M. J. (1988) Algorithm AS 241: The percentage points of the normal distribution.
  // Applied Statistics 37, 477-484: PPND16, rational approximations in three regions.
  if (std::isnan(p) || p < 0.0 || p > 1.0) return std::numeric_limits<double>::quiet_NaN();
  if (p == 0.0) return -std::numeric_limits<double>::infinity();
  if (p == 1.0) return std::numeric_limits<double>::infinity();
  const double q = p - 0.5;
  if (std::abs(q) <= 0.425) {
    const double r = 0.180625 - q * q;
    return q *
           (((((((r * 2509.0809287301226727 + 33430.575583588128105) * r + 67265.770927008700853) * r +
                45921.953931549871457) * r + 13731.693765509461125) * r + 1971.5909503065514427) * r +
             133.14166789178437745) * r + 3.387132872796366608) /
           (((((((r * 5226.495278852545925 + 28729.085735721942674) * r + 39307.89580009271061) * r +
                21213.794301586595867) * r + 5394.1960214247511077) * r + 687.1870074920579083) * r +
             42.313330701600911252) * r + 1.0);
  }
  double r = std::sqrt(-std::log(q < 0.0 ? p : 1.0 - p));
  double value;
  if (r <= 5.0) {
    r -= 1.6;
    value = (((((((r * 7.7454501427834140764e-4 + 0.0227238449892691845833) * r + 0.24178072517745061177) * r +
                 1.27045825245236838258) * r + 3.64784832476320460504) * r + 5.7694972214606914055) * r +
              4.6303378461565452959) * r + 1.42343711074968357734) /
            (((((((r * 1.05075007164441684324e-9 + 5.475938084995344946e-4) * r + 0.0151986665636164571966) * r +
                 0.14810397642748007459) * r + 0.68976733498510000455) * r + 1.6763848301838038494) * r +
              2.05319162663775882187) * r + 1.0);
  } else {
    r -= 5.0;
    value = (((((((r * 2.01033439929228813265e-7 + 2.71155556874348757815e-5) * r + 0.0012426609473880784386) * r +
                 0.026532189526576123093) * r + 0.29656057182850489123) * r + 1.7848265399172913358) * r +
              5.4637849111641143699) * r + 6.6579046435011037772) /
            (((((((r * 2.04426310338993978564e-15 + 1.4215117583164458887e-7) * r + 1.8463183175100546818e-5) * r +
                 7.868691311456132591e-4) * r + 0.0148753612908506148525) * r + 0.13692988092273580531) * r +
              0.59983220655588793769) * r + 1.0);
  }
  return q < 0.0 ? -value : value;
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

/// The inputs of the scenes beyond the conservative two-mass model (docs/model.md §10).
bool IsExtendedInput(const SceneField& field) {
  return field.name == "damping" || field.name == "reaction-delay" || field.name == "braking" ||
         field.name == "torso-mass" || field.name == "neck-stiffness" || field.name == "neck-damping";
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
  if (!nominal.is_conservative_two_mass()) {
    throw std::invalid_argument(
        "the robust analysis runs on the exact path, which covers the conservative two-mass scene "
        "only: the scene has contact damping, braking or a neck (docs/model.md §10); give damping, "
        "braking and torso-mass 0");
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
      throw std::invalid_argument(name + " cannot be uncertain: the robust analysis runs on the exact path, "
                                         "which covers the conservative two-mass scene only (docs/model.md §10)");
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
