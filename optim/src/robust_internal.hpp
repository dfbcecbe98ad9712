#pragma once
// Shared internals of the robust design (optim/robust_design.hpp): judging one impact, the
// global search over a box, formatting and validation helpers. Not installed.

#include <atomic>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <covopt/core/impact_result.hpp>
#include <covopt/core/scene.hpp>
#include <covopt/core/time_integration.hpp>

#include "covopt/optim/robust_design.hpp"
#include "validation_internal.hpp"

namespace covopt::optim::internal {

/// Counts how the impacts of a braking robot were judged (TimePathUse), from any thread.
class TimePathCounter {
 public:
  void Screened() { ++screened_; }
  void BrakeAfterPeak() { ++brake_after_peak_; }
  void Run() { ++runs_; }
  void Fail(const std::string& message);
  /// Adds a finished search's counts.
  void Add(const TimePathUse& use);
  TimePathUse Use() const;

 private:
  std::atomic<long> screened_{0}, brake_after_peak_{0}, runs_{0}, failed_{0};
  mutable std::mutex mutex_;
  std::string first_failure_;
};

/// The criterion an impact is judged by.
struct ImpactCriterion {
  DesignCriterion criterion = DesignCriterion::kNoFullCompression;
  double safety_factor = 1.0;
  InjuryLimits limits;
  /// The covering material's compressive strength [Pa] when it crushes and the strength is
  /// known: the crush ratio σ_c,max / strength is computed; 0: no crush check.
  double compressive_strength_Pa = 0.0;
  /// The crush ratio counts (the no-crush criterion; not for a sacrificial liner).
  bool crush_counts = false;
  /// The time path's settings for a braking robot (record_history is ignored).
  TimeIntegrationOptions time_path{};
  /// Where a braking robot's judgements are counted; nullptr: nowhere.
  TimePathCounter* counter = nullptr;
};
/// Checks the safety factor ([1, 100]) and the limits (finite, > 0).
void ValidateCriterion(const ImpactCriterion& criterion);
/// The criterion of a worst-case or probability question: its rule, safety factor, limits,
/// and the covering material's compressive strength [Pa] (0: no crush check); the crush ratio
/// counts unless `allow_crushing`. Validated (ValidateCriterion, the strength finite, >= 0).
ImpactCriterion MakeCriterion(DesignCriterion rule, double safety_factor, const InjuryLimits& limits,
                              double compressive_strength_Pa, bool allow_crushing);

/// Where a judgement came from.
enum class JudgedBy {
  kExactPath,       ///< a scene without braking: the exact path
  kBound,           ///< a braking robot, decided by the unbraked exact path's upper bound
  kBrakeAfterPeak,  ///< a brake that starts after the unbraked maximum: the exact path's peaks
  kTimePath,        ///< the time path
};

/// One impact, judged.
struct Judged {
  JudgedBy by = JudgedBy::kExactPath;
  /// The time path failed: ratios +inf, every event set, inadmissible.
  bool failed = false;
  ImpactPeaks peaks;
  bool covered = false;
  double laceration_ratio = 0.0;
  double contusion_ratio = 0.0;
  double compression_ratio = 0.0;  ///< the covering's travel used; 0 without a covering
  bool fully_compressed = false;   ///< with a covering only
  double crush_ratio = 0.0;        ///< σ_c,max / strength; 0 without a crush check
  /// F_max / the struck area's lowest published fracture force (docs/model.md §7.1)
  double fracture_ratio = 0.0;
  double governing_ratio = 0.0;    ///< g (robust_design.hpp)
  LimitingCriterion binding = LimitingCriterion::kLaceration;
  bool laceration = false;  ///< SF r_L > 1
  bool contusion = false;   ///< SF r_C > 1
  bool fracture = false;    ///< SF r_F > 1
  /// SF r_crush > 1 with a crush check (counted whether or not crushing is allowed)
  bool crushed = false;
  /// An injury: laceration, contusion or fracture.
  bool injured() const noexcept { return laceration || contusion || fracture; }
  /// The covering left its law's validity (CoveringLawValidity; a fully compressed Hertz
  /// covering under the paper's criterion excepted): inadmissible, "law-validity" binds.
  bool out_of_validity = false;
  CoveringValidity validity;
  bool admissible = false;
};

/// When the exact path's bound may stand for a braking robot's impact (docs/model.md §11,
/// "A braking robot"): braking only lowers every ratio, so the unbraked judgement is an upper
/// bound of the braked one.
struct Screening {
  /// The unbraked impact has no event (no injury, not fully compressed) and is admissible:
  /// then neither has the braked one. For admissibility checks and counts.
  bool when_admissible = false;
  /// The unbraked governing ratio is <= this: the braked one cannot exceed it (a worst-case
  /// search's incumbent).
  double at_or_below = -std::numeric_limits<double>::infinity();
};

/// The impact of `scene`, judged: the exact path without braking; with braking, the exact
/// path when the brake starts at or after the unbraked maximum (the peaks are the same), the
/// unbraked bound where `screening` lets it decide, else the time path (criterion.time_path;
/// a failed run is judged inadmissible with infinite ratios and counted).
/// @throws std::invalid_argument for an invalid scene.
Judged JudgeScene(const Scene& scene, const ImpactCriterion& criterion, const Screening& screening = {});

/// The same scene without braking (reaction delay and deceleration 0).
Scene Unbraked(const Scene& scene);

/// Sets the box's inputs in `scene` to `values` [SI] (values.size() == box.size()).
void ApplyInputs(const UncertaintyBox& box, std::span<const double> values, Scene& scene);

/// The field names robot-mass, head-mass and speed: the inputs that act through the impact
/// energy only.
bool IsEnergyInput(const SceneField& field);
/// Throws if the box has a range (low < high) on `field_name`, with `why`.
void RefuseRange(const UncertaintyBox& box, std::string_view field_name, const std::string& why);

/// What the global search looks for: the largest value of f over the box.
struct BoxMaximum {
  std::vector<double> values;  ///< every input [SI] at the best point
  double value = 0.0;
  std::string found_by;
  std::optional<double> corner_value;
  SolverReport global;
  SolverReport local;
  long evaluations = 0;
};

/// Checks GlobalSearchOptions.
void ValidateSearch(const GlobalSearchOptions& search);

/// The global search of GlobalSearchOptions for max f over the box; f gets every input's
/// value [SI] and must return a finite number. Point inputs sit at their value; with
/// search.pin_energy_inputs, energy inputs sit at their high end.
BoxMaximum MaximizeOverBox(const UncertaintyBox& box, const GlobalSearchOptions& search,
                           const std::function<double(std::span<const double>)>& f);

/// FindWorstCase for the box's inputs applied to `base` instead of the nominal scene (a
/// design's covering in place of the nominal one).
WorstCase WorstCaseOnScene(const UncertaintyBox& box, const Scene& base,
                           const ImpactCriterion& criterion, const GlobalSearchOptions& search);

/// Fills a WorstCase's ratios from a judged impact.
void FillWorstCase(const Judged& judged, WorstCase& worst);

/// The input values [SI] of sample `index` into `values` (size box.size()).
inline void DrawInputsInto(const UncertaintyBox& box, std::uint64_t seed, std::uint64_t index,
                           std::span<double> values) {
  box.DrawInto(seed, index, values);
}

/// Checks the fields of DesignOptions the robust designs use.
void ValidateDesign(const DesignOptions& options);
/// Throws for a range on covering-modulus, covering-poisson or covering-thickness.
void RefuseCoveringRanges(const UncertaintyBox& box);
/// A multiple of the thickness step, printed-clean (12 significant digits): k × 0.5 mm is
/// 0.018, not 0.018000000000000002.
double StockThickness(double steps, double step_m);
/// Point k of the catalog scan's `points` thicknesses over the design space [m].
double ScanThickness(const DesignSpace& space, int points, int k);
/// The thinnest admissible thickness of a catalog snap: the first of `points` scan
/// thicknesses over `space` (ScanThickness, thin to thick) at which `admissible_at(b)` holds,
/// bisected against the scan point before it to `resolution_m` [m]. The admissible set need
/// not be an interval, hence the scan first. Empty when no scan point is admissible.
template <class Admissible>
std::optional<double> ThinnestAdmissibleThickness(const DesignSpace& space, int points, double resolution_m,
                                                  const Admissible& admissible_at) {
  double inadmissible = 0.0, admissible = 0.0;
  bool found = false;
  for (int k = 0; k < points && !found; ++k) {
    const double b = ScanThickness(space, points, k);
    if (admissible_at(b)) {
      found = true;
      admissible = b;
    } else {
      inadmissible = b;
    }
  }
  if (!found) return std::nullopt;
  if (inadmissible > 0.0) {
    while (admissible - inadmissible > resolution_m) {
      const double mid = 0.5 * (inadmissible + admissible);
      (admissible_at(mid) ? admissible : inadmissible) = mid;
    }
  }
  return admissible;
}

/// The snap's rounding up to stock: the score `score_at(stock)` of the first multiple of
/// `step_m` (StockThickness) at or above `thickness_m` that `admissible(score)` accepts (the
/// admissible set need not be an interval: it steps up until one is). Empty when the next
/// multiple passes `max_thickness_m`; `beyond_max_m` then gets that multiple.
template <class ScoreAt, class Admissible>
auto FirstAdmissibleStock(double thickness_m, double step_m, double max_thickness_m, const ScoreAt& score_at,
                          const Admissible& admissible, std::optional<double>& beyond_max_m)
    -> std::optional<decltype(score_at(0.0))> {
  double steps = std::ceil(thickness_m / step_m - 1e-9);
  for (double stock = StockThickness(steps, step_m);; stock = StockThickness(++steps, step_m)) {
    if (stock > max_thickness_m * (1 + 1e-12)) {
      beyond_max_m = stock;
      return std::nullopt;
    }
    auto score = score_at(stock);
    if (admissible(score)) return score;
  }
}

/// The nested search's thickness grid: half linear, half geometric [m], with
/// `extra_thickness_m` (an admissible thickness known beforehand) when given. Shared with
/// FindThinnestSafeCovering's stage 2.
std::vector<double> BracketGrid(const DesignOptions& options, std::optional<double> extra_thickness_m = std::nullopt);

/// A robust design's verdict: the bare robot safe, else a covering found (the first
/// candidate meets the requirement), else nothing safe when the continuous optimum was asked
/// for and is infeasible, else no safe material.
inline DesignVerdict RobustVerdict(bool bare_robot_safe, bool covering_found, bool continuous_infeasible) {
  if (bare_robot_safe) return DesignVerdict::kBareRobotSafe;
  if (covering_found) return DesignVerdict::kCoveringFound;
  if (continuous_infeasible) return DesignVerdict::kNothingSafe;
  return DesignVerdict::kNoSafeMaterial;
}

/// Golden-section search for the least value on [a, c], to an interval narrower than
/// `tolerance`: `at(u)` evaluates point u and `value(point)` is what is minimised. Returns the
/// best point evaluated (the first of equal ones). Shared by the modulus searches of
/// FindThinnestSafeCovering and the robust design. (Boost.Math's brent_find_minima would stop
/// at √ε relative, about 1e-7 in log10 E_c, far short of these searches' 1e-12 and 1e-10.)
template <class At, class Value>
auto GoldenSection(const At& at, const Value& value, double a, double c, double tolerance) {
  constexpr double kInvPhi = 0.6180339887498949;
  double x1 = c - kInvPhi * (c - a), x2 = a + kInvPhi * (c - a);
  auto s1 = at(x1), s2 = at(x2);
  auto best = value(s1) <= value(s2) ? s1 : s2;
  while (c - a > tolerance) {
    if (value(s1) <= value(s2)) {
      c = x2;
      x2 = x1;
      s2 = s1;
      x1 = c - kInvPhi * (c - a);
      s1 = at(x1);
      if (value(s1) < value(best)) best = s1;
    } else {
      a = x1;
      x1 = x2;
      s1 = s2;
      x2 = a + kInvPhi * (c - a);
      s2 = at(x2);
      if (value(s2) < value(best)) best = s2;
    }
  }
  return best;
}

}  // namespace covopt::optim::internal
