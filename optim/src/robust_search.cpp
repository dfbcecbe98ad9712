// The global search over an uncertainty box (optim/robust_design.hpp, GlobalSearchOptions) and
// what is built directly on it: the worst case of a box, and the speed and mass limits over it.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "covopt/optim/backends.hpp"
#include "covopt/optim/robust_search.hpp"
#include "robust_internal.hpp"

namespace covopt::optim {
namespace internal {
namespace {

/// The first 16 primes: the Halton bases (at most 15 searched inputs).
constexpr int kPrimes[16] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53};

/// The radical inverse of `index` in `base`: the Halton coordinate, in [0, 1).
double RadicalInverse(std::uint64_t index, int base) {
  double inverse = 1.0 / base, value = 0.0, factor = inverse;
  while (index > 0) {
    value += static_cast<double>(index % static_cast<std::uint64_t>(base)) * factor;
    index /= static_cast<std::uint64_t>(base);
    factor *= inverse;
  }
  return value;
}

/// max f over the searched inputs, as a minimisation of -f on x in [1, 2]^k (an offset box,
/// so NLopt's relative step tolerance means the same on every coordinate). Remembers every
/// point evaluated and the best one, with the stage that found it.
class BoxObjective : public Problem {
 public:
  BoxObjective(const UncertaintyBox& box, std::vector<std::size_t> searched, std::vector<double> fixed,
               const std::function<double(std::span<const double>)>& f)
      : box_(box), searched_(std::move(searched)), values_(std::move(fixed)), f_(f) {}

  std::size_t dimension() const override { return searched_.size(); }
  std::vector<double> lower_bounds() const override { return std::vector<double>(searched_.size(), 1.0); }
  std::vector<double> upper_bounds() const override { return std::vector<double>(searched_.size(), 2.0); }
  bool Objective(std::span<const double> x, double& value, std::span<double> /*gradient*/) const override {
    const double f = Evaluate(x);
    value = -f;
    return std::isfinite(f);
  }

  /// f at x in [1, 2]^k, recorded under the current stage.
  double Evaluate(std::span<const double> x) const {
    for (std::size_t k = 0; k < searched_.size(); ++k) {
      const UncertainInput& input = box_.inputs()[searched_[k]];
      const double t = std::clamp(x[k] - 1.0, 0.0, 1.0);
      values_[searched_[k]] = t == 1.0 ? input.high : input.low + t * (input.high - input.low);
    }
    const double f = f_(values_);
    ++evaluations_;
    if (std::isfinite(f)) {
      points_.push_back({f, std::vector<double>(x.begin(), x.end())});
      if (!best_ || f > best_value_) {
        best_ = true;
        best_value_ = f;
        best_values_ = values_;
        best_stage_ = stage_;
      }
    }
    return f;
  }

  void set_stage(std::string stage) const { stage_ = std::move(stage); }
  bool has_best() const { return best_; }
  double best_value() const { return best_value_; }
  const std::vector<double>& best_values() const { return best_values_; }
  const std::string& best_stage() const { return best_stage_; }
  long evaluations() const { return evaluations_; }

  /// Up to `count` of the best points evaluated, at least `separation` apart in every-coordinate
  /// (max) distance on [1, 2]^k, best first.
  std::vector<std::vector<double>> BestDistinct(std::size_t count, double separation) const {
    std::vector<std::size_t> order(points_.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return points_[a].first > points_[b].first; });
    std::vector<std::vector<double>> chosen;
    for (std::size_t i : order) {
      if (chosen.size() >= count) break;
      const std::vector<double>& x = points_[i].second;
      bool distinct = true;
      for (const std::vector<double>& c : chosen) {
        double distance = 0.0;
        for (std::size_t k = 0; k < x.size(); ++k) distance = std::max(distance, std::abs(x[k] - c[k]));
        if (distance < separation) distinct = false;
      }
      if (distinct) chosen.push_back(x);
    }
    return chosen;
  }

 private:
  const UncertaintyBox& box_;
  std::vector<std::size_t> searched_;
  mutable std::vector<double> values_;
  const std::function<double(std::span<const double>)>& f_;
  mutable std::vector<std::pair<double, std::vector<double>>> points_;
  mutable bool best_ = false;
  mutable double best_value_ = 0.0;
  mutable std::vector<double> best_values_;
  mutable std::string best_stage_;
  mutable std::string stage_;
  mutable long evaluations_ = 0;
};

}  // namespace

void ValidateSearch(const GlobalSearchOptions& s) {
  Require(s.max_corner_inputs >= 0 && s.max_corner_inputs <= 16,
          "max corner inputs must be in [0, 16] (got " + std::to_string(s.max_corner_inputs) + ")");
  Require(s.space_filling_points >= -1 && s.space_filling_points <= 1000000,
          "space-filling points must be in [0, 1000000], or -1 for the default (got " +
              std::to_string(s.space_filling_points) + ")");
  Require(s.global_evaluations >= -1 && s.global_evaluations <= 100000000,
          "global evaluations must be in [0, 1e8], or -1 for the default (got " +
              std::to_string(s.global_evaluations) + ")");
  Require(s.local_starts >= 0 && s.local_starts <= 20,
          "local starts must be in [0, 20] (got " + std::to_string(s.local_starts) + ")");
  Require(s.local_evaluations == -1 || (s.local_evaluations >= 10 && s.local_evaluations <= 100000000),
          "local evaluations must be in [10, 1e8], or -1 for the default (got " +
              std::to_string(s.local_evaluations) + ")");
}

BoxMaximum MaximizeOverBox(const UncertaintyBox& box, const GlobalSearchOptions& search,
                           const std::function<double(std::span<const double>)>& f) {
  // Point inputs at their value, pinned energy inputs at the top, the rest searched.
  std::vector<double> fixed = box.Centre();
  std::vector<std::size_t> searched;
  for (std::size_t i = 0; i < box.size(); ++i) {
    const UncertainInput& input = box.inputs()[i];
    if (input.low == input.high) continue;
    // With braking the energy argument does not hold (the brake acts from a time, on the robot
    // alone): every input is searched.
    if (search.pin_energy_inputs && IsEnergyInput(box.field(i)) && !box.brakes()) {
      fixed[i] = input.high;
      continue;
    }
    searched.push_back(i);
  }
  const std::size_t k = searched.size();
  BoxObjective objective(box, searched, fixed, f);
  BoxMaximum out;

  if (k == 0) {
    objective.set_stage("pinned");
    std::vector<double> none;
    (void)objective.Evaluate(none);
  } else {
    // 1. Corners.
    std::vector<double> x(k);
    if (static_cast<int>(k) <= search.max_corner_inputs) {
      objective.set_stage("corner");
      double corner_best = -std::numeric_limits<double>::infinity();
      for (std::uint64_t mask = 0; mask < (std::uint64_t{1} << k); ++mask) {
        for (std::size_t j = 0; j < k; ++j) x[j] = (mask >> j & 1U) ? 2.0 : 1.0;
        corner_best = std::max(corner_best, objective.Evaluate(x));
      }
      out.corner_value = corner_best;
    }
    // 2. Centre and a Halton sequence.
    objective.set_stage("centre");
    std::fill(x.begin(), x.end(), 1.5);
    (void)objective.Evaluate(x);
    objective.set_stage("space-filling");
    const long halton = search.space_filling_points >= 0 ? search.space_filling_points : 32 + 32 * static_cast<long>(k);
    for (long i = 1; i <= halton; ++i) {
      for (std::size_t j = 0; j < k; ++j) x[j] = 1.0 + RadicalInverse(static_cast<std::uint64_t>(i), kPrimes[j]);
      (void)objective.Evaluate(x);
    }
    // 3. DIRECT-L.
    const long global_budget = search.global_evaluations >= 0 ? search.global_evaluations : 500 + 200 * static_cast<long>(k);
    std::vector<std::vector<double>> starts;
    if (global_budget > 0) {
      objective.set_stage("global");
      NloptOptions global;
      global.algorithm = NloptAlgorithm::kDirectL;
      global.max_evaluations = global_budget;
      const std::vector<double> centre(k, 1.5);
      const SolveResult result = SolveWithNlopt(objective, centre, global);
      out.global = result.report;
      if (result.is_usable()) starts.push_back(result.x);
    }
    // 4. COBYLA from the best distinct points.
    if (search.local_starts > 0) {
      const long local_budget = search.local_evaluations > 0 ? search.local_evaluations : 100 + 50 * static_cast<long>(k);
      for (std::vector<double>& point : objective.BestDistinct(static_cast<std::size_t>(search.local_starts), 1e-3)) {
        if (starts.size() >= static_cast<std::size_t>(search.local_starts)) break;
        bool known = false;
        for (const std::vector<double>& s : starts) known = known || s == point;
        if (!known) starts.push_back(std::move(point));
      }
      objective.set_stage("local");
      NloptOptions local;
      local.algorithm = NloptAlgorithm::kCobyla;
      local.max_evaluations = local_budget;
      local.relative_x_tolerance = 1e-10;
      double best_before = objective.best_value();
      for (const std::vector<double>& start : starts) {
        const SolveResult result = SolveWithNlopt(objective, start, local);
        if (out.local.backend.empty() || objective.best_value() > best_before) out.local = result.report;
        best_before = objective.best_value();
      }
    }
  }
  if (!objective.has_best()) {
    throw std::runtime_error("the search over the box found no point where the function is finite");
  }
  out.values = objective.best_values();
  out.value = objective.best_value();
  out.found_by = objective.best_stage();
  out.evaluations = objective.evaluations();
  return out;
}

WorstCase WorstCaseOnScene(const UncertaintyBox& box, const Scene& base, const ImpactCriterion& criterion,
                           const GlobalSearchOptions& search) {
  const auto started = std::chrono::steady_clock::now();
  Scene scene = base;
  TimePathCounter counter;
  ImpactCriterion counted = criterion;
  counted.counter = &counter;
  // A braking robot: a point whose unbraked bound cannot beat the worst impact found so far
  // (the incumbent) is not run on the time path; its bound, no larger than the incumbent, is
  // what the search sees, and the point kept is always one judged in full. A failed run is the
  // worst point (the largest finite value): it is never read as safe.
  double incumbent = -std::numeric_limits<double>::infinity();
  const std::function<double(std::span<const double>)> governing = [&](std::span<const double> values) {
    ApplyInputs(box, values, scene);
    Screening screening;
    screening.at_or_below = incumbent;
    const Judged j = JudgeScene(scene, counted, screening);
    if (j.failed) return std::numeric_limits<double>::max();
    if (j.by != JudgedBy::kBound) incumbent = std::max(incumbent, j.governing_ratio);
    return j.governing_ratio;
  };
  const BoxMaximum maximum = MaximizeOverBox(box, search, governing);
  WorstCase worst;
  worst.values = maximum.values;
  worst.scene = base;
  ApplyInputs(box, worst.values, worst.scene);
  FillWorstCase(JudgeScene(worst.scene, counted), worst);
  worst.time_path = counter.Use();
  if (criterion.counter) criterion.counter->Add(worst.time_path);
  worst.corner_governing_ratio = maximum.corner_value;
  worst.found_by = maximum.found_by;
  worst.global = maximum.global;
  worst.local = maximum.local;
  worst.evaluations = maximum.evaluations + 1;
  worst.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return worst;
}

}  // namespace internal

using internal::ImpactCriterion;

WorstCase FindWorstCase(const UncertaintyBox& box, const WorstCaseOptions& options) {
  ImpactCriterion criterion = internal::MakeCriterion(options.criterion(), options.safety_factor, options.limits,
                                                      options.compressive_strength_Pa, options.allow_crushing);
  criterion.time_path = options.time_path;
  internal::ValidateSearch(options.search);
  if (box.brakes()) ValidateTimeIntegrationOptions(options.time_path, "time_path.");
  return internal::WorstCaseOnScene(box, box.nominal(), criterion, options.search);
}

namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// A robust limit (RobustSpeedLimit, RobustMassLimit) at the box's worst point: `limit_at`
/// (MaxSafeSpeed or MaxSafeMass) evaluated once more there, counted with the search's.
template <typename RobustLimit, typename LimitAt>
RobustLimit AtWorstPoint(const UncertaintyBox& box, const internal::BoxMaximum& maximum, LimitAt limit_at,
                         std::chrono::steady_clock::time_point started) {
  RobustLimit out;
  out.values = maximum.values;
  out.scene = box.SceneAt(out.values);
  out.limit = limit_at(out.scene);
  out.found_by = maximum.found_by;
  out.evaluations = maximum.evaluations + 1;
  out.seconds = SecondsSince(started);
  return out;
}

}  // namespace

RobustSpeedLimit MaxSafeSpeedOverBox(const UncertaintyBox& box, const SpeedLimitOptions& options,
                                     const GlobalSearchOptions& search) {
  const auto started = std::chrono::steady_clock::now();
  internal::RefuseRange(box, "speed", "the speed limit is what is computed; the speed cannot be uncertain");
  internal::ValidateSearch(search);
  (void)MaxSafeSpeed(box.nominal(), options);  // validates the options
  Scene scene = box.nominal();
  const std::function<double(std::span<const double>)> lower_speed = [&](std::span<const double> values) {
    internal::ApplyInputs(box, values, scene);
    return -MaxSafeSpeed(scene, options).max_safe_speed_m_per_s;
  };
  const internal::BoxMaximum maximum = internal::MaximizeOverBox(box, search, lower_speed);
  return AtWorstPoint<RobustSpeedLimit>(
      box, maximum, [&](const Scene& worst) { return MaxSafeSpeed(worst, options); }, started);
}

RobustMassLimit MaxSafeMassOverBox(const UncertaintyBox& box, const SpeedLimitOptions& options,
                                   const GlobalSearchOptions& search) {
  const auto started = std::chrono::steady_clock::now();
  internal::RefuseRange(box, "robot-mass",
                        "the mass limit is what is computed; the robot mass cannot be uncertain");
  internal::ValidateSearch(search);
  (void)MaxSafeMass(box.nominal(), options);
  Scene scene = box.nominal();
  // A fixed robot (+inf) as the answer everywhere compares as the largest value; -inf is
  // finite enough for the search only if some point is limited, so map +inf to a large value.
  const std::function<double(std::span<const double>)> lower_mass = [&](std::span<const double> values) {
    internal::ApplyInputs(box, values, scene);
    const double mass = MaxSafeMass(scene, options).max_safe_mass_kg;
    return std::isinf(mass) ? -std::numeric_limits<double>::max() : -mass;
  };
  const internal::BoxMaximum maximum = internal::MaximizeOverBox(box, search, lower_mass);
  return AtWorstPoint<RobustMassLimit>(
      box, maximum, [&](const Scene& worst) { return MaxSafeMass(worst, options); }, started);
}

}  // namespace covopt::optim
