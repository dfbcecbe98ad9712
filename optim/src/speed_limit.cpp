// The maximum safe impact speed and reflected mass (optim/speed_limit.hpp): the limit is
// found on the penetration axis, where every criterion is a monotone function of δ_max, and
// mapped back through the energy balance U(δ_max) = ½ μ v0²; for a scene without that energy
// integral (a braking robot, a neck), by a bracketed bisection on the time path.
#include "covopt/optim/speed_limit.hpp"
#include "covopt/optim/verdicts.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/core/number_format.hpp>
#include <covopt/core/physical_floors.hpp>
#include <covopt/core/quantity.hpp>
#include <covopt/core/time_integration.hpp>

#include "limit_bracket.hpp"

namespace covopt::optim {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// The model's lowest impact speed [m/s] (ImpactModel::FromScene).
constexpr double kMinSpeed_m_per_s = 1e-6;
constexpr double kHertzPressureFactor = 3.0 / (2.0 * 3.14159265358979323846);  // k = 3/(2π)

[[noreturn]] void Reject(const std::string& field, const std::string& requirement, double value) {
  throw std::invalid_argument(field + " must be " + requirement + " (got " + FormatShortest(value) + ")");
}

void CheckOptions(const SpeedLimitOptions& o) {
  if (!(o.safety_factor >= 1.0 && o.safety_factor <= 100.0)) {
    Reject("safety_factor", "in [1, 100]", o.safety_factor);
  }
  CheckInjuryLimits(o.limits);
  if (!(o.max_speed_m_per_s >= kMinSpeed_m_per_s && o.max_speed_m_per_s <= 100.0)) {
    Reject("max_speed_m_per_s", "in [1e-06, 100] m/s", o.max_speed_m_per_s);
  }
  if (!(o.max_mass_kg >= kMinMass_kg && o.max_mass_kg <= 1e6)) Reject("max_mass_kg", "in [0.001, 1e+06] kg", o.max_mass_kg);
  // 0 or at least the modulus floor (physical_floors.hpp): a denormal strength made crush
  // ratios of 1e300 and inf.
  const double strength = o.covering_compressive_strength_Pa;
  if (!(strength == 0.0 || (strength >= kMinModulus_Pa && strength <= 1e13))) {
    Reject("covering_compressive_strength_Pa", "0 (no crush check) or in [1000, 1e+13] Pa", strength);
  }
}

/// x >= x0 solving  offset (x - x0) + coeff/power (x^power - x0^power) = gap  (gap >= 0):
/// the left side is increasing and convex for x >= x0 (offset >= 0, coeff > 0, power >= 1),
/// so Newton started above the root descends monotonically onto it (as the exact path's
/// energy balance does); either term alone reaching the gap bounds the root from above.
double SolveOffsetPower(double offset, double coeff, double power, double x0, double gap) {
  if (!(gap > 0.0)) return x0;
  if (offset == 0.0 && x0 == 0.0) return std::pow(gap * power / coeff, 1.0 / power);
  const double x0_pow = x0 > 0.0 ? std::pow(x0, power) : 0.0;
  double x = std::pow(gap * power / coeff + x0_pow, 1.0 / power);
  if (offset > 0.0) x = std::min(x, x0 + gap / offset);
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double x_pow_m1 = std::pow(x, power - 1.0);
    const double g = offset * (x - x0) + coeff / power * (x_pow_m1 * x - x0_pow) - gap;
    const double slope = offset + coeff * x_pow_m1;
    const double next = x - g / slope;
    if (!(next < x)) break;  // converged: the monotone sequence stopped decreasing
    x = std::max(next, x0);
  }
  return x;
}

/// A penetration on the δ axis and the segment of the force law it was found in.
struct Crossing {
  double penetration_m = kInfinity;  ///< +inf: never reached
  std::size_t segment = 0;
};

/// The largest δ up to which the running maximum of σ_c over [0, δ] stays <= target [Pa]
/// (ImpactPeaks' σ_c,max of a contact reaching δ).
Crossing StressCrossing(const ImpactModel& model, double target_Pa, std::size_t first = 0) {
  // σ_c,max over the segments passed is at their ends, each checked <= target on the way.
  for (std::size_t i = first; i < model.segment_count(); ++i) {
    const ForceLawSegment& seg = model.segment(i);
    const double at_start = model.StateInSegment(i, seg.start_m).compressive_stress_Pa;
    if (at_start > target_Pa) return {seg.start_m, i};  // a jump up at the switch
    const bool last = i + 1 == model.segment_count();
    if (!last) {
      const double at_end = model.StateInSegment(i, seg.end_m).compressive_stress_Pa;
      if (at_end <= target_Pa) continue;
    }
    // σ_i(δ) = σ_off + k K c x^(n-1) is increasing in the segment and crosses the target here.
    const double n = seg.exponent;
    if (!(n > 1.0)) {
      if (last) return {};  // constant: never crosses
      continue;
    }
    const double kc = kHertzPressureFactor * seg.stiffness * seg.curvature_per_m;
    const double x = std::pow(std::max(target_Pa - seg.stress_offset_Pa, 0.0) / kc, 1.0 / (n - 1.0));
    return {std::clamp(seg.origin_m + x, seg.start_m, seg.end_m), i};
  }
  return {};
}

/// The largest δ up to which the running maximum of F over [0, δ] stays <= target [N]
/// (ImpactPeaks' F_max of a contact reaching δ; F = F_off + K x^n in each segment).
Crossing ForceCrossing(const ImpactModel& model, double target_N, std::size_t first = 0) {
  for (std::size_t i = first; i < model.segment_count(); ++i) {
    const ForceLawSegment& seg = model.segment(i);
    if (model.StateInSegment(i, seg.start_m).force_N > target_N) return {seg.start_m, i};  // a jump up
    const bool last = i + 1 == model.segment_count();
    if (!last && model.StateInSegment(i, seg.end_m).force_N <= target_N) continue;
    const double x = std::pow(std::max(target_N - seg.force_offset_N, 0.0) / seg.stiffness, 1.0 / seg.exponent);
    return {std::clamp(seg.origin_m + x, seg.start_m, seg.end_m), i};
  }
  return {};
}

/// The largest δ up to which e(δ) <= target [J/m²] (e is continuous and increasing).
Crossing EnergyDensityCrossing(const ImpactModel& model, double target_J_per_m2, std::size_t first = 0) {
  for (std::size_t i = first; i < model.segment_count(); ++i) {
    const ForceLawSegment& seg = model.segment(i);
    const bool last = i + 1 == model.segment_count();
    if (!last && model.StateInSegment(i, seg.end_m).energy_density_J_per_m2 <= target_J_per_m2) continue;
    // e_i = e_start + σ_off (x - x0) + k K c (x^n - x0^n)/n,  x = δ - origin, x0 = start - origin.
    const double kc = kHertzPressureFactor * seg.stiffness * seg.curvature_per_m;
    const double x0 = seg.start_m - seg.origin_m;
    const double x = SolveOffsetPower(seg.stress_offset_Pa, kc, seg.exponent, x0,
                                      target_J_per_m2 - seg.energy_density_at_start_J_per_m2);
    return {std::clamp(seg.origin_m + x, seg.start_m, seg.end_m), i};
  }
  return {};
}

/// The foam law (docs/model.md §16): the crossing of a quantity that grows on the layer (segment
/// 0) as `on_layer(δ)`: inside the layer where it passes the target there, by `strain_at` (the
/// curve's closed-form inverse, empty where there is none: then bisection); else on the bare
/// chain past the stop, by `past_stop` from segment 1 (§2's power laws, their jumps up at the
/// stop included).
template <class OnLayer, class StrainAt, class PastStop>
Crossing FoamCrossing(const ImpactModel& model, double target, OnLayer on_layer, StrainAt strain_at,
                      PastStop past_stop) {
  const ForceLawSegment& layer = model.segment(0);
  if (!(on_layer(layer.end_m) > target)) return past_stop(1);
  if (const std::optional<double> strain = strain_at(target)) {
    return {std::clamp(*strain * layer.foam_thickness_m, 0.0, layer.end_m), 0};
  }
  double lo = 0.0, hi = layer.end_m;
  for (int iteration = 0; iteration < 200 && hi - lo > 1e-15 * hi; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    (on_layer(mid) > target ? hi : lo) = mid;
  }
  return {lo, 0};
}

/// The foam law's crossings of F, σ_c, σ_t and e (FoamCrossing): the layer's F = A W(δ/h),
/// σ_c = σ(δ/h) and e = h W(δ/h) invert on the curve; σ_t = (1 − 2ν_t) W(ε)/(2ε) by bisection.
Crossing FoamForceCrossing(const ImpactModel& model, double target_N) {
  const ForceLawSegment& layer = model.segment(0);
  return FoamCrossing(
      model, target_N, [&](double d) { return model.StateInSegment(0, d).force_N; },
      [&](double f) { return layer.curve->StrainAtEnergyDensity(f / layer.foam_area_m2); },
      [&](std::size_t first) { return ForceCrossing(model, target_N, first); });
}
Crossing FoamStressCrossing(const ImpactModel& model, double target_Pa) {
  const ForceLawSegment& layer = model.segment(0);
  return FoamCrossing(
      model, target_Pa, [&](double d) { return model.StateInSegment(0, d).compressive_stress_Pa; },
      [&](double s) { return layer.curve->StrainAtStress(s); },
      [&](std::size_t first) { return StressCrossing(model, target_Pa, first); });
}
Crossing FoamTensileCrossing(const ImpactModel& model, double target_Pa) {
  const double tensile_factor = model.TensileFromCompressive(1.0);  // (1 - 2ν_t)/3 past the stop
  return FoamCrossing(
      model, target_Pa, [&](double d) { return model.TensileStressInSegment(0, d); },
      [](double) { return std::optional<double>(); },
      [&](std::size_t first) {
        return tensile_factor > 0.0 ? StressCrossing(model, target_Pa / tensile_factor, first) : Crossing{};
      });
}
Crossing FoamEnergyDensityCrossing(const ImpactModel& model, double target_J_per_m2) {
  const ForceLawSegment& layer = model.segment(0);
  return FoamCrossing(
      model, target_J_per_m2, [&](double d) { return model.StateInSegment(0, d).energy_density_J_per_m2; },
      [&](double e) { return layer.curve->StrainAtEnergyDensity(e / layer.foam_thickness_m); },
      [&](std::size_t first) { return EnergyDensityCrossing(model, target_J_per_m2, first); });
}

/// The largest δ up to which a Hertz covering stays within its law's validity (JudgedValidity):
/// its full compression t2, or (a law that leaves its validity before, e.g. a solid elastomer's
/// strain limit) the first δ out of it, by bisection on [0, t2] (the validity is lost once, as
/// the compression grows). Never reached for the bare robot and under the foam law (a used-up
/// layer is a modelled stop), nor past t2 when full compression is accepted.
Crossing ValidityCrossing(const ImpactModel& model, bool accept_full_compression) {
  if (!model.has_covering() || model.is_foam()) return {};
  const std::size_t last = model.segment_count() - 1;
  const double full = PeaksAtMaxPenetration(model, last, model.segment(last).start_m).full_compression_penetration_m;
  const auto within = [&](double d) {
    return JudgedValidity(model, PeaksAtMaxPenetration(model, model.SegmentIndexAt(d), d), accept_full_compression)
        .within;
  };
  if (within(full)) {
    if (accept_full_compression) return {};
    return {full, model.SegmentIndexAt(full)};
  }
  double lo = 0.0, hi = full;
  for (int iteration = 0; iteration < 200 && hi - lo > 1e-15 * hi; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    (within(mid) ? lo : hi) = mid;
  }
  return {lo, model.SegmentIndexAt(lo)};
}

/// The speed [m/s] at which the covering's travel is used up (the foam's stop, a Hertz
/// covering's full compression t2), on the energy balance: sqrt(2 U(stop) / μ); empty bare or
/// above `max_speed_m_per_s`.
std::optional<double> UsedUpSpeed(const ImpactModel& model, double max_speed_m_per_s) {
  if (!model.has_covering()) return std::nullopt;
  const std::size_t last = model.segment_count() - 1;
  const double stop = PeaksAtMaxPenetration(model, last, model.segment(last).start_m).full_compression_penetration_m;
  const double energy = model.StateInSegment(model.SegmentIndexAt(stop), stop).potential_energy_J;
  const double speed = std::sqrt(2.0 * energy / model.effective_mass_kg());
  if (!(speed <= max_speed_m_per_s)) return std::nullopt;
  return speed;
}

/// "foam" or "hertz" for a covered scene, "" bare (the law ImpactModel takes).
std::string CoveringLawName(const Scene& scene) {
  if (!(scene.covering.thickness_m > 0.0)) return "";
  return std::string(covopt::ToString(ImpactModel::FromScene(scene).covering_law()));
}

/// The smallest δ at which a criterion reaches its limit, which one, and U there [J].
struct PenetrationLimit {
  double penetration_m = kInfinity;
  LimitingCriterion by = LimitingCriterion::kNone;
  double energy_J = kInfinity;
};

PenetrationLimit FindPenetrationLimit(const ImpactModel& model, const SpeedLimitOptions& options) {
  const double s = options.safety_factor;
  const double tensile_factor = model.TensileFromCompressive(1.0);  // (1 - 2ν_t)/3 >= 0
  PenetrationLimit limit;
  auto consider = [&](const Crossing& crossing, LimitingCriterion by) {
    if (crossing.penetration_m < limit.penetration_m) {
      limit.penetration_m = crossing.penetration_m;
      limit.by = by;
      limit.energy_J = model.StateInSegment(crossing.segment, crossing.penetration_m).potential_energy_J;
    }
  };
  const bool foam = model.is_foam();
  if (foam) {
    consider(FoamTensileCrossing(model, options.limits.laceration_tensile_stress_Pa / s), LimitingCriterion::kLaceration);
  } else if (tensile_factor > 0.0) {
    consider(StressCrossing(model, options.limits.laceration_tensile_stress_Pa / (s * tensile_factor)),
             LimitingCriterion::kLaceration);
  }
  const double contusion = options.limits.contusion_energy_density_J_per_m2 / s;
  consider(foam ? FoamEnergyDensityCrossing(model, contusion) : EnergyDensityCrossing(model, contusion),
           LimitingCriterion::kContusion);
  const double fracture = FractureLimit(options.limits, model.scene().head.area) / s;
  consider(foam ? FoamForceCrossing(model, fracture) : ForceCrossing(model, fracture), LimitingCriterion::kFracture);
  if (options.criterion() == DesignCriterion::kNoFullCompression && model.has_covering()) {
    // The covering's travel the safety factor leaves: s + (t2 − s)/SF (ImpactPeaks::
    // covering_compression_ratio), s the start of its travel; t2 itself at SF 1.
    const std::size_t last = model.segment_count() - 1;
    const ImpactPeaks at_full = PeaksAtMaxPenetration(model, last, model.segment(last).start_m);
    const double start = at_full.covering_travel_start_m, full = at_full.full_compression_penetration_m;
    const double reserved = s == 1.0 ? full : start + (full - start) / s;
    consider({reserved, model.SegmentIndexAt(reserved)}, LimitingCriterion::kFullCompression);
  }
  consider(ValidityCrossing(model, options.allow_full_compression), LimitingCriterion::kLawValidity);
  if (options.covering_compressive_strength_Pa > 0.0 && !options.allow_crushing && model.has_covering()) {
    const double strength = options.covering_compressive_strength_Pa / s;
    consider(foam ? FoamStressCrossing(model, strength) : StressCrossing(model, strength), LimitingCriterion::kCrush);
  }
  return limit;
}

/// Judges impacts on the oracle the options choose for the scene (exact or time path),
/// counting evaluations and failures for the result's OracleReport.
class Judge {
 public:
  Judge(const Scene& scene, const SpeedLimitOptions& options)
      : options_(options), selection_(ChooseOracle(scene, options.oracle.choice)) {
    if (selection_.kind == OracleKind::kTimePath) {
      ValidateTimeIntegrationOptions(options.oracle.time_path, "oracle.time_path.");
      time_path_ = options.oracle.time_path;
      time_path_.record_history = false;
    }
  }
  bool time_path() const noexcept { return selection_.kind == OracleKind::kTimePath; }

  /// The ratios of the impact of `scene`, and whether it is admissible.
  ImpactJudgement operator()(const Scene& scene) const {
    ++evaluations_;
    const ImpactModel model = ImpactModel::FromScene(scene);
    ImpactJudgement e;
    ImpactPeaks peaks;
    if (time_path()) {
      const ImpactResult result = SimulateImpact(model, time_path_);
      if (!result.ok()) {
        ++failed_;
        if (first_failure_.empty()) first_failure_ = std::string(covopt::ToString(result.status)) + ": " + result.message;
        e.failed = true;
        e.ratios.laceration_ratio = e.ratios.contusion_ratio = e.ratios.compression_ratio = kInfinity;
        e.ratios.fracture_ratio = kInfinity;
        return e;
      }
      peaks = result.peaks;
    } else {
      peaks = ExactPeaks(model);
    }
    e.ratios.laceration_ratio = peaks.max_tensile_stress_Pa / options_.limits.laceration_tensile_stress_Pa;
    e.ratios.contusion_ratio =
        peaks.max_energy_density_J_per_m2 / options_.limits.contusion_energy_density_J_per_m2;
    e.ratios.fracture_ratio = peaks.peak_force_N / FractureLimit(options_.limits, scene.head.area);
    e.ratios.compression_ratio = peaks.covering_compression_ratio();
    if (model.has_covering() && options_.covering_compressive_strength_Pa > 0.0) {
      e.ratios.crush_ratio = peaks.max_compressive_stress_Pa / options_.covering_compressive_strength_Pa;
    }
    e.ratios.max_penetration_m = peaks.max_penetration_m;
    e.peaks = peaks;
    if (model.has_covering()) e.validity = JudgedValidity(model, peaks, options_.allow_full_compression);
    e.admissible = HeadVerdict(scene, peaks, options_, &e.validity).safe();  // the one head rule (verdicts.hpp)
    return e;
  }

  /// The criterion an inadmissible impact violates (the largest excess when several do).
  LimitingCriterion Violated(const ImpactJudgement& e) const {
    if (e.failed) return LimitingCriterion::kNone;
    const double sf = options_.safety_factor;
    LimitingCriterion by = LimitingCriterion::kNone;
    double excess = 1.0;
    auto consider = [&](double value, LimitingCriterion criterion) {
      if (value > excess) {
        excess = value;
        by = criterion;
      }
    };
    consider(sf * e.ratios.laceration_ratio, LimitingCriterion::kLaceration);
    consider(sf * e.ratios.contusion_ratio, LimitingCriterion::kContusion);
    consider(sf * e.ratios.fracture_ratio, LimitingCriterion::kFracture);
    if (options_.criterion() == DesignCriterion::kNoFullCompression) {
      consider(sf * e.ratios.compression_ratio, LimitingCriterion::kFullCompression);
    }
    if (!options_.allow_crushing) consider(sf * e.ratios.crush_ratio, LimitingCriterion::kCrush);
    if (by == LimitingCriterion::kNone && !e.validity.within) by = LimitingCriterion::kLawValidity;
    return by;
  }

  OracleReport Report() const {
    OracleReport r;
    r.kind = selection_.kind;
    r.reason = selection_.reason;
    r.gradient = selection_.gradient;
    if (time_path()) {
      r.method = time_path_.method;
      r.relative_tolerance = time_path_.relative_tolerance;
    }
    r.evaluations = evaluations_;
    r.failed_evaluations = failed_;
    r.first_failure = first_failure_;
    return r;
  }

 private:
  const SpeedLimitOptions& options_;
  OracleSelection selection_;
  TimeIntegrationOptions time_path_;
  mutable long evaluations_ = 0;
  mutable long failed_ = 0;
  mutable std::string first_failure_;
};

/// Lowers `value` by a few ulps until the exact path at `set(value)` is admissible: the limit
/// computed on the δ axis can round to just above the switch or the limit it stands for.
template <class Setter>
ImpactJudgement NudgeDown(double& value, const Scene& scene, const Judge& judge, Setter set, double floor) {
  Scene probe = scene;
  set(probe, value);
  ImpactJudgement e = judge(probe);
  double step = 2.0 * std::numeric_limits<double>::epsilon();
  // Never below `floor`, the smallest value the library takes (a scene there would be refused).
  for (int attempt = 0; attempt < 40 && !e.admissible && value * (1.0 - step) >= floor; ++attempt, step *= 2.0) {
    value *= 1.0 - step;
    set(probe, value);
    e = judge(probe);
  }
  return e;
}

/// A limit bracketed on the oracle (speed_limit.hpp, limit_bracket.hpp), with the criterion
/// that binds it.
struct BracketedLimit {
  SpeedLimitStatus status = SpeedLimitStatus::kLimited;
  double value = 0.0;
  LimitingCriterion by = LimitingCriterion::kNone;
  ImpactJudgement at;  ///< at `value` (at `lowest` for kNoSafeValue)
  double failed_at = 0.0;  ///< the value whose evaluation failed (kEvaluationFailed)
};

template <class Setter>
BracketedLimit BracketOnOracle(const Judge& judge, const Scene& base, double lowest, double highest, Setter set) {
  const internal::LimitBracket<ImpactJudgement> found =
      internal::BracketLimit<ImpactJudgement>(lowest, highest, [&](double value) {
        Scene probe = base;
        set(probe, value);
        internal::LimitProbe<ImpactJudgement> e;
        e.judgement = judge(probe);
        e.failed = e.judgement.failed;
        e.admissible = e.judgement.admissible;
        return e;
      });
  BracketedLimit out;
  out.status = found.status;
  out.value = found.value;
  if (found.status != SpeedLimitStatus::kEvaluationFailed) out.at = found.at;  // else the ratios stay 0
  out.failed_at = found.failed_at;
  if (found.status == SpeedLimitStatus::kLimited || found.status == SpeedLimitStatus::kNoSafeValue) {
    out.by = judge.Violated(found.unsafe_at);
  }
  return out;
}

std::string RatiosText(const LimitRatios& r, bool covered) {
  std::string text = "laceration ratio " + FormatSignificant(r.laceration_ratio, 4) + ", contusion ratio " +
                     FormatSignificant(r.contusion_ratio, 4) + ", fracture ratio " +
                     FormatSignificant(r.fracture_ratio, 4);
  if (covered) text += ", compression ratio " + FormatSignificant(r.compression_ratio, 4);
  return text;
}

}  // namespace

std::string_view ToString(SpeedLimitStatus status) noexcept {
  switch (status) {
    case SpeedLimitStatus::kLimited: return "limited";
    case SpeedLimitStatus::kSafeUpToSearchLimit: return "safe-up-to-search-limit";
    case SpeedLimitStatus::kNoSafeValue: return "no-safe-value";
    case SpeedLimitStatus::kEvaluationFailed: return "evaluation-failed";
  }
  return "unknown";
}

std::string SpeedLimit::BriefReport() const {
  return message + "; at " + FormatSignificant(std::max(max_safe_speed_m_per_s, kMinSpeed_m_per_s), 6) +
         " m/s: " + RatiosText(at_limit, at_limit.compression_ratio > 0.0) + ".";
}

std::string MassLimit::BriefReport() const {
  return message + "; at " +
         (std::isinf(max_safe_mass_kg) ? std::string("a fixed robot")
                                       : FormatSignificant(max_safe_mass_kg, 6) + " kg") +
         ": " + RatiosText(at_limit, at_limit.compression_ratio > 0.0) + ".";
}

ImpactJudgement JudgeImpact(const Scene& scene, const SpeedLimitOptions& options) {
  CheckOptions(options);
  return Judge(scene, options)(scene);
}

namespace {

/// MaxSafeSpeed and MaxSafeMass on the δ axis (the exact path's scenes), below.
SpeedLimit MaxSafeSpeedOnPenetrationAxis(const Scene& base, const SpeedLimitOptions& options, const Judge& judge);
MassLimit MaxSafeMassOnPenetrationAxis(const Scene& base, const SpeedLimitOptions& options, const Judge& judge);

/// MaxSafeSpeed where there is no δ axis: bracketed on the oracle.
SpeedLimit MaxSafeSpeedOnOracle(const Scene& base, const SpeedLimitOptions& options, const Judge& judge) {
  const auto set_speed = [](Scene& s, double v) { s.robot.speed_m_per_s = v; };
  const BracketedLimit limit = BracketOnOracle(judge, base, kMinSpeed_m_per_s, options.max_speed_m_per_s, set_speed);
  SpeedLimit result;
  result.bracketed = true;
  result.status = limit.status;
  result.limited_by = limit.by;
  result.max_safe_speed_m_per_s = limit.value;
  result.at_limit = limit.at.ratios;
  result.validity = limit.at.validity;
  switch (limit.status) {
    case SpeedLimitStatus::kNoSafeValue:
      result.message = std::string("no safe speed: unsafe even at 1e-06 m/s (") + std::string(ToString(limit.by)) + ")";
      break;
    case SpeedLimitStatus::kSafeUpToSearchLimit:
      result.message = "safe up to the search limit of " + FormatSignificant(limit.value, 6) + " m/s" +
                       (options.max_speed_m_per_s == 100.0 ? " (the model's ceiling)" : "");
      break;
    case SpeedLimitStatus::kLimited:
      result.message = "max safe speed " + FormatSignificant(limit.value, 6) + " m/s, limited by " + std::string(ToString(limit.by));
      break;
    case SpeedLimitStatus::kEvaluationFailed:
      result.message = "no answer: the oracle failed at " + FormatSignificant(limit.failed_at, 6) + " m/s (" +
                       judge.Report().first_failure + ")";
      break;
  }
  result.oracle = judge.Report();
  return result;
}

/// MaxSafeMass where there is no δ axis: bracketed on the oracle.
MassLimit MaxSafeMassOnOracle(const Scene& base, const SpeedLimitOptions& options, const Judge& judge) {
  MassLimit result;
  result.bracketed = true;
  // A fixed robot (allowed unless it brakes) meets the head with μ = m_h.
  if (!base.robot_brakes() && std::isfinite(base.head.mass_kg)) {
    Scene fixed = base;
    fixed.robot.mass_kg = kFixed;
    const ImpactJudgement at = judge(fixed);
    if (at.admissible) {
      result.status = SpeedLimitStatus::kSafeUpToSearchLimit;
      result.max_safe_mass_kg = kFixed;
      result.at_limit = at.ratios;
      result.message = "safe for any reflected mass, even a fixed robot";
      result.oracle = judge.Report();
      return result;
    }
  }
  const auto set_mass = [](Scene& s, double m) { s.robot.mass_kg = m; };
  // From the mass floor (physical_floors.hpp, 1 g; the search once began at 1 mg): every
  // scene the bracket visits is one the library takes.
  const BracketedLimit limit = BracketOnOracle(judge, base, kMinMass_kg, options.max_mass_kg, set_mass);
  result.status = limit.status;
  result.limited_by = limit.by;
  result.max_safe_mass_kg = limit.value;
  result.at_limit = limit.at.ratios;
  result.validity = limit.at.validity;
  switch (limit.status) {
    case SpeedLimitStatus::kNoSafeValue:
      result.message = "no safe mass: unsafe even at " + FormatSignificant(kMinMass_kg, 6) + " kg, the model's floor (" +
                       std::string(ToString(limit.by)) + ")";
      break;
    case SpeedLimitStatus::kSafeUpToSearchLimit:
      result.message = "safe up to the search limit of " + FormatSignificant(limit.value, 6) + " kg" +
                       (options.max_mass_kg == 1e6 ? " (the model's ceiling)" : "");
      break;
    case SpeedLimitStatus::kLimited:
      result.message =
          "max safe reflected mass " + FormatSignificant(limit.value, 6) + " kg, limited by " + std::string(ToString(limit.by));
      break;
    case SpeedLimitStatus::kEvaluationFailed:
      result.message = "no answer: the oracle failed at " + FormatSignificant(limit.failed_at, 6) + " kg (" +
                       judge.Report().first_failure + ")";
      break;
  }
  result.oracle = judge.Report();
  return result;
}

}  // namespace

SpeedLimit MaxSafeSpeed(const Scene& scene, const SpeedLimitOptions& options) {
  CheckOptions(options);
  Scene base = scene;
  base.robot.speed_m_per_s = 1.0;  // ignored: the law does not depend on it
  const Judge judge(base, options);
  if (judge.time_path() || !base.is_conservative_two_mass()) {
    SpeedLimit result = MaxSafeSpeedOnOracle(base, options, judge);
    result.covering_law = CoveringLawName(base);
    return result;
  }
  SpeedLimit result = MaxSafeSpeedOnPenetrationAxis(base, options, judge);
  result.oracle = judge.Report();
  result.covering_law = CoveringLawName(base);
  const ImpactModel model = ImpactModel::FromScene(base);
  result.covering_used_up_m_per_s = UsedUpSpeed(model, options.max_speed_m_per_s);
  if (result.covering_used_up_m_per_s && *result.covering_used_up_m_per_s < result.max_safe_speed_m_per_s) {
    result.message += "; covering used up at v = " + FormatSignificant(*result.covering_used_up_m_per_s, 6) + " m/s";
  }
  return result;
}

MassLimit MaxSafeMass(const Scene& scene, const SpeedLimitOptions& options) {
  CheckOptions(options);
  Scene base = scene;
  base.robot.mass_kg = 1.0;  // ignored: the law does not depend on it
  const Judge judge(base, options);
  if (judge.time_path() || !base.is_conservative_two_mass()) {
    MassLimit result = MaxSafeMassOnOracle(base, options, judge);
    result.covering_law = CoveringLawName(base);
    return result;
  }
  MassLimit result = MaxSafeMassOnPenetrationAxis(base, options, judge);
  result.oracle = judge.Report();
  result.covering_law = CoveringLawName(base);
  if (!result.covering_law.empty() && result.status != SpeedLimitStatus::kNoSafeValue) {
    Scene at = base;
    at.robot.mass_kg = result.max_safe_mass_kg;
    result.validity = judge(at).validity;
  }
  return result;
}

namespace {

SpeedLimit MaxSafeSpeedOnPenetrationAxis(const Scene& base, const SpeedLimitOptions& options, const Judge& judge) {
  const ImpactModel model = ImpactModel::FromScene(base);
  const PenetrationLimit limit = FindPenetrationLimit(model, options);
  const double speed = std::sqrt(2.0 * limit.energy_J / model.effective_mass_kg());  // may be inf
  const auto set_speed = [](Scene& s, double v) { s.robot.speed_m_per_s = v; };

  SpeedLimit result;
  result.limited_by = limit.by;
  if (speed > options.max_speed_m_per_s) {
    result.status = SpeedLimitStatus::kSafeUpToSearchLimit;
    result.limited_by = LimitingCriterion::kNone;
    result.max_safe_speed_m_per_s = options.max_speed_m_per_s;
    const ImpactJudgement top = NudgeDown(result.max_safe_speed_m_per_s, base, judge, set_speed, kMinSpeed_m_per_s);
    result.at_limit = top.ratios;
    result.validity = top.validity;
    result.message = "safe up to the search limit of " + FormatSignificant(result.max_safe_speed_m_per_s, 6) +
                     " m/s" + (options.max_speed_m_per_s == 100.0 ? " (the model's ceiling)" : "");
    return result;
  }
  double value = speed;
  ImpactJudgement at = {};
  if (value >= kMinSpeed_m_per_s) at = NudgeDown(value, base, judge, set_speed, kMinSpeed_m_per_s);
  if (!(value >= kMinSpeed_m_per_s) || !at.admissible) {
    result.status = SpeedLimitStatus::kNoSafeValue;
    result.max_safe_speed_m_per_s = 0.0;
    Scene floor = base;
    floor.robot.speed_m_per_s = kMinSpeed_m_per_s;
    const ImpactJudgement bottom = judge(floor);
    result.at_limit = bottom.ratios;
    result.validity = bottom.validity;
    result.message = std::string("no safe speed: unsafe even at 1e-06 m/s (") + std::string(ToString(limit.by)) + ")";
    return result;
  }
  result.status = SpeedLimitStatus::kLimited;
  result.max_safe_speed_m_per_s = value;
  result.at_limit = at.ratios;
  result.validity = at.validity;
  result.message = "max safe speed " + FormatSignificant(value, 6) + " m/s, limited by " + std::string(ToString(limit.by));
  return result;
}

MassLimit MaxSafeMassOnPenetrationAxis(const Scene& base, const SpeedLimitOptions& options, const Judge& judge) {
  const ImpactModel model = ImpactModel::FromScene(base);
  const PenetrationLimit limit = FindPenetrationLimit(model, options);
  const double v0 = base.robot.speed_m_per_s;
  const double head = base.head.mass_kg;
  const double reduced = 2.0 * limit.energy_J / (v0 * v0);  // μ_max [kg], may be inf
  const auto set_mass = [](Scene& s, double m) { s.robot.mass_kg = m; };

  MassLimit result;
  result.limited_by = limit.by;
  // A fixed robot meets the free head with μ = m_h.
  if (std::isfinite(head) && reduced >= head) {
    Scene fixed = base;
    fixed.robot.mass_kg = kFixed;
    const ImpactJudgement at = judge(fixed);
    if (at.admissible) {
      result.status = SpeedLimitStatus::kSafeUpToSearchLimit;
      result.limited_by = LimitingCriterion::kNone;
      result.max_safe_mass_kg = kFixed;
      result.at_limit = at.ratios;
      result.message = "safe for any reflected mass, even a fixed robot";
      return result;
    }
  }
  const double mass = std::isinf(head) ? reduced : (reduced >= head ? kInfinity : reduced * head / (head - reduced));
  if (mass > options.max_mass_kg) {
    result.status = SpeedLimitStatus::kSafeUpToSearchLimit;
    result.limited_by = LimitingCriterion::kNone;
    result.max_safe_mass_kg = options.max_mass_kg;
    result.at_limit = NudgeDown(result.max_safe_mass_kg, base, judge, set_mass, kMinMass_kg).ratios;
    result.message = "safe up to the search limit of " + FormatSignificant(result.max_safe_mass_kg, 6) + " kg" +
                     (options.max_mass_kg == 1e6 ? " (the model's ceiling)" : "");
    return result;
  }
  double value = mass;
  ImpactJudgement at = {};
  // Below the mass floor (physical_floors.hpp) there is no scene to judge.
  if (value >= kMinMass_kg) at = NudgeDown(value, base, judge, set_mass, kMinMass_kg);
  if (!(value >= kMinMass_kg) || !at.admissible) {
    result.status = SpeedLimitStatus::kNoSafeValue;
    result.max_safe_mass_kg = 0.0;
    result.message = "no safe mass: the limit is below " + FormatSignificant(kMinMass_kg, 6) + " kg, the model's floor (" +
                     std::string(ToString(limit.by)) + ")";
    return result;
  }
  result.status = SpeedLimitStatus::kLimited;
  result.max_safe_mass_kg = value;
  result.at_limit = at.ratios;
  result.message = "max safe reflected mass " + FormatSignificant(value, 6) + " kg, limited by " + std::string(ToString(limit.by));
  return result;
}

}  // namespace

std::string DefaultCoveringNote(const Scene& scene) {
  return "no covering given: the default is assumed, " +
         FormatQuantity(scene.covering.thickness_m, QuantityKind::kLength) + " of " +
         FormatQuantity(scene.covering.youngs_modulus_Pa, QuantityKind::kModulus) +
         " (the paper's polystyrene foam, of unknown compressive strength, so crushing is not checked); give the "
         "covering's thickness with a catalog material (or its modulus), or a thickness of 0 for the bare robot";
}

CoveringCrushCheck CrushCheckFor(const Scene& scene, const materials::Material* material, bool covering_given) {
  CoveringCrushCheck check;
  if (!(scene.covering.thickness_m > 0.0)) return check;
  if (!covering_given && !material) {
    check.notes.push_back(DefaultCoveringNote(scene));
    return check;
  }
  if (!material) {
    check.notes.push_back("the covering is given by its modulus, not a catalog material: its compressive strength is "
                          "not known, so crushing is not checked (give a material)");
    return check;
  }
  switch (material->crush_behaviour) {
    case materials::CrushBehaviour::kCrushes:
      check.compressive_strength_Pa = material->compressive_strength_Pa.value_or(0.0);
      check.check = CrushCheck::kChecked;
      break;
    case materials::CrushBehaviour::kDoesNotCrush: check.check = CrushCheck::kDoesNotCrush; break;
    case materials::CrushBehaviour::kUnknown:
      check.check = CrushCheck::kUnknownStrength;
      check.notes.push_back("the compressive strength of '" + material->name +
                            "' is unknown: the limits are unverified for crushing");
      break;
  }
  return check;
}

InjuryVerdict CrushVerdict(const ImpactPeaks& peaks, double compressive_strength_Pa, double safety_factor) noexcept {
  InjuryVerdict verdict;
  verdict.value = peaks.max_compressive_stress_Pa;
  verdict.limit = compressive_strength_Pa;
  verdict.ratio = verdict.value / verdict.limit;
  verdict.safe = safety_factor * verdict.ratio <= 1.0;
  return verdict;
}

}  // namespace covopt::optim
