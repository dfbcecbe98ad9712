#pragma once
// Private: the bracketed limit search of speed_limit.hpp ("Scenes beyond the conservative
// two-mass model"), shared by the head's MaxSafeSpeed/MaxSafeMass on the time path and the body
// regions' speed limit of a braking robot (body_region_check.cpp, docs/model.md §13.10): a
// geometric scan upward from a value known (or checked) safe, the first inadmissible point
// found, and the step from the last admissible one narrowed to a relative resolution.
#include <algorithm>
#include <cmath>
#include <limits>

#include "covopt/optim/speed_limit.hpp"

namespace covopt::optim::internal {

/// One evaluation of the searched criterion at one value.
template <class Judgement>
struct LimitProbe {
  Judgement judgement;
  /// Not an answer (the time path failed): the search stops and says so.
  bool failed = false;
  bool admissible = false;
  /// Optional: log(SF × governing ratio), continuous and increasing in the value, <= 0 where
  /// the ratio admits it. When both ends of the bracket give a finite excess (the unsafe end's
  /// > 0), the narrowing takes the Illinois (modified regula falsi) point in log(value) rather
  /// than the geometric midpoint: a few evaluations instead of about 33. NaN (the default):
  /// the midpoint, always.
  double excess = std::numeric_limits<double>::quiet_NaN();
};

/// Grid points per decade of the scan, and the narrowing's relative resolution.
inline constexpr double kScanPointsPerDecade = 4.0;
inline constexpr double kBisectionResolution = 1e-10;

/// What a bracketed search found.
template <class Judgement>
struct LimitBracket {
  /// kLimited, kSafeUpToSearchLimit (value = highest), kNoSafeValue (lowest inadmissible,
  /// value 0) or kEvaluationFailed (value 0; failed_at says where).
  SpeedLimitStatus status = SpeedLimitStatus::kLimited;
  double value = 0.0;
  Judgement at;         ///< at `value` (at `lowest` for kNoSafeValue; the failed one's for kEvaluationFailed)
  Judgement unsafe_at;  ///< the closest inadmissible value's (kLimited), or lowest's (kNoSafeValue)
  double failed_at = 0.0;
  int evaluations = 0;
};

/// Scans evaluate(value) upward from `lowest` to `highest` (> lowest > 0) on a geometric grid of
/// kScanPointsPerDecade points per decade (at least 2 points), stops at the first inadmissible
/// point, and narrows the step from the last admissible one to kBisectionResolution relative.
/// Scanning upward keeps the definition of a limit (every lower value safe) at the grid's
/// resolution even where the criterion were not monotone. `evaluate` returns a
/// LimitProbe<Judgement>.
template <class Judgement, class Evaluate>
LimitBracket<Judgement> BracketLimit(double lowest, double highest, Evaluate evaluate) {
  LimitBracket<Judgement> out;
  auto at = [&](double value) {
    ++out.evaluations;
    return evaluate(value);
  };
  // A failed evaluation says nothing about safety: the search stops and reports it.
  auto failed = [&](LimitProbe<Judgement>& e, double value) {
    if (!e.failed) return false;
    out.status = SpeedLimitStatus::kEvaluationFailed;
    out.failed_at = value;
    out.at = std::move(e.judgement);
    return true;
  };
  LimitProbe<Judgement> bottom = at(lowest);
  if (failed(bottom, lowest)) return out;
  if (!bottom.admissible) {
    out.status = SpeedLimitStatus::kNoSafeValue;
    out.at = bottom.judgement;
    out.unsafe_at = std::move(bottom.judgement);
    return out;
  }
  const int points = std::max(2, static_cast<int>(std::ceil(kScanPointsPerDecade * std::log10(highest / lowest))));
  double safe = lowest, unsafe = 0.0;
  LimitProbe<Judgement> safe_at = std::move(bottom), unsafe_at;
  for (int i = 1; i <= points; ++i) {
    const double value = i == points ? highest : lowest * std::pow(highest / lowest, static_cast<double>(i) / points);
    LimitProbe<Judgement> e = at(value);
    if (failed(e, value)) return out;
    if (!e.admissible) {
      unsafe = value;
      unsafe_at = std::move(e);
      break;
    }
    safe = value;
    safe_at = std::move(e);
  }
  if (unsafe == 0.0) {
    out.status = SpeedLimitStatus::kSafeUpToSearchLimit;
    out.value = highest;
    out.at = std::move(safe_at.judgement);
    return out;
  }
  // The Illinois weights of the two ends' excess (halved on an end kept twice in a row).
  double safe_weight = 1.0, unsafe_weight = 1.0;
  int kept_side = 0;  // -1: the safe end moved last, +1: the unsafe end
  const double step_floor = 0.25 * kBisectionResolution;  // in log(value)
  while (unsafe / safe - 1.0 > kBisectionResolution) {
    double mid = std::sqrt(safe * unsafe);  // the geometric midpoint
    const double g_safe = safe_weight * safe_at.excess, g_unsafe = unsafe_weight * unsafe_at.excess;
    if (std::isfinite(g_safe) && std::isfinite(g_unsafe) && g_safe <= 0.0 && g_unsafe > 0.0) {
      const double low = std::log(safe), high = std::log(unsafe);
      const double next = low - g_safe * (high - low) / (g_unsafe - g_safe);
      mid = std::exp(std::clamp(next, low + step_floor, high - step_floor));  // progress on every step
    }
    LimitProbe<Judgement> e = at(mid);
    if (failed(e, mid)) return out;
    if (e.admissible) {
      safe = mid;
      safe_at = std::move(e);
      safe_weight = 1.0;
      unsafe_weight = kept_side == -1 ? 0.5 * unsafe_weight : 1.0;
      kept_side = -1;
    } else {
      unsafe = mid;
      unsafe_at = std::move(e);
      unsafe_weight = 1.0;
      safe_weight = kept_side == +1 ? 0.5 * safe_weight : 1.0;
      kept_side = +1;
    }
  }
  out.status = SpeedLimitStatus::kLimited;
  out.value = safe;
  out.at = std::move(safe_at.judgement);
  out.unsafe_at = std::move(unsafe_at.judgement);
  return out;
}

}  // namespace covopt::optim::internal
