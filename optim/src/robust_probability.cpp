// The probability of injury over an uncertainty box by Monte Carlo, and the thinnest covering
// whose probability stays below a target (optim/robust_design.hpp). Every sample draws its
// inputs from its own stream (DrawInputs), samples are counted in fixed blocks on worker
// threads, and the counts are integers: the result is identical for any thread count.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <covopt/core/parallel_for.hpp>

#include "covopt/optim/robust_design.hpp"
#include "robust_internal.hpp"

namespace covopt::optim {
namespace {

using internal::ImpactCriterion;
using internal::Require;

constexpr std::uint64_t kNoStop = std::numeric_limits<std::uint64_t>::max();
/// How often (in samples) a worker adds its failures to the shared total when a stop
/// threshold is set.
constexpr std::uint64_t kStopCheckSamples = 256;

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct SampleCounts {
  std::uint64_t laceration = 0, contusion = 0, fracture = 0, any = 0, fully_compressed = 0, crushed = 0, inadmissible = 0;
  /// Stopped because the inadmissible count passed the threshold (the counts are then partial).
  bool stopped = false;
  unsigned threads = 0;
  std::uint64_t evaluated = 0;  ///< samples evaluated (fewer than asked when stopped)
};

struct CountRequest {
  std::uint64_t samples = 0;
  std::uint64_t seed = 0;
  unsigned threads = 1;  ///< 0 = the hardware's (ParallelThreads)
  std::uint64_t block_samples = 8192;
  /// Stop as soon as more than this many samples are inadmissible (kNoStop: never).
  std::uint64_t stop_above = kNoStop;
  const std::function<void(double)>* progress = nullptr;
};

/// Counts the events over samples 0..N-1 of the box applied to `base`.
SampleCounts CountSamples(const UncertaintyBox& box, const Scene& base, const ImpactCriterion& criterion,
                          const CountRequest& request) {
  const std::uint64_t n = request.samples;
  const std::uint64_t block = request.block_samples;
  const std::uint64_t blocks = (n + block - 1) / block;
  const unsigned threads = ParallelThreads(blocks, request.threads);
  std::atomic<std::uint64_t> done{0};
  std::atomic<std::uint64_t> inadmissible_total{0};
  std::atomic<bool> stop{false};
  std::vector<SampleCounts> per_thread(threads);

  // One block of samples, counted into its worker's counts (integers: the sums do not
  // depend on which worker counted which block).
  const auto count_block = [&](std::uint64_t b, unsigned worker) {
    if (stop.load(std::memory_order_relaxed)) return;
    SampleCounts& c = per_thread[worker];
    Scene scene = base;
    std::vector<double> values(box.size());
    std::uint64_t unreported_failures = 0;
    const std::uint64_t first = b * block, last = std::min(n, first + block);
    for (std::uint64_t i = first; i < last; ++i) {
      internal::DrawInputsInto(box, request.seed, i, values);
      internal::ApplyInputs(box, values, scene);
      // A braking robot's sample with no event unbraked has none braked (docs/model.md §11).
      const internal::Judged j = internal::JudgeScene(scene, criterion, {.when_admissible = true});
      c.laceration += j.laceration;
      c.contusion += j.contusion;
      c.fracture += j.fracture;
      c.any += j.injured();
      c.crushed += j.crushed;
      c.fully_compressed += j.fully_compressed;
      c.inadmissible += !j.admissible;
      unreported_failures += !j.admissible;
      ++c.evaluated;
      if (request.stop_above != kNoStop && ((i - first) % kStopCheckSamples == kStopCheckSamples - 1 || i + 1 == last)) {
        // The shared total only grows, so passing the threshold is final whatever the order.
        if (inadmissible_total.fetch_add(unreported_failures) + unreported_failures > request.stop_above) {
          stop.store(true);
        }
        unreported_failures = 0;
        if (stop.load(std::memory_order_relaxed)) return;
      }
    }
    const std::uint64_t finished = done.fetch_add(last - first) + (last - first);
    if (worker == 0 && request.progress && *request.progress) (*request.progress)(static_cast<double>(finished) / n);
  };
  ParallelFor(blocks, threads, count_block);
  SampleCounts total;
  total.threads = threads;
  for (const SampleCounts& c : per_thread) {
    total.laceration += c.laceration;
    total.contusion += c.contusion;
    total.fracture += c.fracture;
    total.any += c.any;
    total.crushed += c.crushed;
    total.fully_compressed += c.fully_compressed;
    total.inadmissible += c.inadmissible;
    total.evaluated += c.evaluated;
  }
  total.stopped = request.stop_above != kNoStop && total.inadmissible > request.stop_above;
  if (!total.stopped && request.progress && *request.progress) (*request.progress)(1.0);
  return total;
}

void ValidateSampling(const InjuryProbabilityOptions& o) {
  Require(o.samples >= 1 && o.samples <= 10'000'000'000ULL,
          "samples must be in [1, 1e10] (got " + std::to_string(o.samples) + ")");
  Require(o.block_samples >= 1 && o.block_samples <= 10'000'000ULL,
          "block samples must be in [1, 1e7] (got " + std::to_string(o.block_samples) + ")");
  Require(o.threads <= 4096, "threads must be in [0, 4096] (got " + std::to_string(o.threads) + ")");
}

InjuryProbability ToProbability(const SampleCounts& c, std::uint64_t samples, std::uint64_t seed) {
  InjuryProbability p;
  p.laceration = WilsonEstimate(c.laceration, samples);
  p.contusion = WilsonEstimate(c.contusion, samples);
  p.fracture = WilsonEstimate(c.fracture, samples);
  p.any = WilsonEstimate(c.any, samples);
  p.crushed = WilsonEstimate(c.crushed, samples);
  p.fully_compressed = WilsonEstimate(c.fully_compressed, samples);
  p.inadmissible = WilsonEstimate(c.inadmissible, samples);
  p.seed = seed;
  p.threads = c.threads;
  return p;
}

}  // namespace

InjuryProbability EstimateInjuryProbability(const UncertaintyBox& box, const InjuryProbabilityOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  ValidateSampling(options);
  internal::TimePathCounter counter;
  ImpactCriterion criterion = internal::MakeCriterion(options.criterion(), options.safety_factor, options.limits,
                                                      options.compressive_strength_Pa, options.allow_crushing);
  criterion.time_path = options.time_path;
  criterion.counter = &counter;
  if (box.brakes()) ValidateTimeIntegrationOptions(options.time_path, "time_path.");
  CountRequest request;
  request.samples = options.samples;
  request.seed = options.seed;
  request.threads = options.threads;
  request.block_samples = options.block_samples;
  request.progress = &options.progress;
  const SampleCounts counts = CountSamples(box, box.nominal(), criterion, request);
  InjuryProbability p = ToProbability(counts, options.samples, options.seed);
  p.time_path = counter.Use();
  p.seconds = SecondsSince(started);
  return p;
}

namespace {

/// Judges coverings against the probability target on the same samples (common random numbers).
class ProbabilityJudge {
 public:
  /// Judges by the options' criterion and, for a `material` that crushes, its strength.
  ProbabilityJudge(const UncertaintyBox& box, const ProbabilityDesignOptions& o, std::uint64_t allowed_failures,
                   internal::TimePathCounter& counter, const CandidateMaterial* material = nullptr)
      : box_(box), criterion_{o.design.criterion(), o.design.safety_factor, o.design.limits}, allowed_(allowed_failures) {
    criterion_.time_path = o.design.oracle.time_path;
    criterion_.counter = &counter;
    if (material && material->crush_behaviour == materials::CrushBehaviour::kCrushes) {
      criterion_.compressive_strength_Pa = material->compressive_strength_Pa;
      criterion_.crush_counts = !o.design.allow_crushing;
    }
    request_.samples = o.sampling.samples;
    request_.seed = o.sampling.seed;
    request_.threads = o.sampling.threads;
    request_.block_samples = o.sampling.block_samples;
  }

  /// The estimate of inadmissible samples is <= the target (stops early when it cannot be).
  bool Meets(const CoveringSpec& covering) const {
    CountRequest request = request_;
    request.stop_above = allowed_;
    const SampleCounts c = Count(covering, request);
    return !c.stopped && c.inadmissible <= allowed_;
  }
  /// The inadmissible count if it is <= `at_most`, else empty (stops early).
  std::optional<std::uint64_t> FailuresUpTo(const CoveringSpec& covering, std::uint64_t at_most) const {
    CountRequest request = request_;
    request.stop_above = at_most;
    const SampleCounts c = Count(covering, request);
    if (c.stopped) return std::nullopt;
    return c.inadmissible;
  }
  /// The full estimate.
  InjuryProbability Estimate(const Scene& scene) const {
    const auto started = std::chrono::steady_clock::now();
    internal::TimePathCounter own;
    ImpactCriterion counted = criterion_;
    counted.counter = &own;
    const SampleCounts c = CountSamples(box_, scene, counted, request_);
    evaluated_ += c.evaluated;
    InjuryProbability p = ToProbability(c, request_.samples, request_.seed);
    p.time_path = own.Use();
    criterion_.counter->Add(p.time_path);
    p.seconds = SecondsSince(started);
    return p;
  }
  InjuryProbability Estimate(const CoveringSpec& covering) const {
    Scene scene = box_.nominal();
    scene.covering = covering;
    return Estimate(scene);
  }
  std::uint64_t evaluated() const { return evaluated_.load(); }

 private:
  SampleCounts Count(const CoveringSpec& covering, const CountRequest& request) const {
    Scene scene = box_.nominal();
    scene.covering = covering;
    return CountOn(scene, request);
  }
  SampleCounts CountOn(const Scene& scene, const CountRequest& request) const {
    const SampleCounts c = CountSamples(box_, scene, criterion_, request);
    evaluated_ += c.evaluated;
    return c;
  }

  const UncertaintyBox& box_;
  ImpactCriterion criterion_;
  std::uint64_t allowed_;
  CountRequest request_;
  mutable std::atomic<std::uint64_t> evaluated_{0};
};

ProbabilityCandidate ProbabilitySnapMaterial(const ProbabilityJudge& judge, const CandidateMaterial& material,
                                             const DesignOptions& o) {
  const DesignSpace& space = o.space;
  auto covering = [&](double b) { return CoveringOf(material, b, o.covering_law); };
  ProbabilityCandidate candidate;
  candidate.material = material;
  const DesignRule rule = o.rule();
  if (material.crush_behaviour == materials::CrushBehaviour::kUnknown && rule.refuses_unknown_strength()) {
    candidate.at_design = judge.Estimate(covering(space.max_thickness_m));  // never meets the target
    return candidate;
  }
  double failing = 0.0, meeting = 0.0;
  bool found = false;
  for (int k = 0; k < o.thickness_scan_points && !found; ++k) {
    const double b = internal::ScanThickness(space, o.thickness_scan_points, k);
    if (judge.Meets(covering(b))) {
      found = true;
      meeting = b;
    } else {
      failing = b;
    }
  }
  if (!found) {
    candidate.at_design = judge.Estimate(covering(space.max_thickness_m));
    return candidate;
  }
  if (failing > 0.0) {
    while (meeting - failing > o.thickness_resolution_m) {
      const double mid = 0.5 * (failing + meeting);
      (judge.Meets(covering(mid)) ? meeting : failing) = mid;
    }
  }
  candidate.min_thickness_m = meeting;
  double recommended = meeting;
  if (o.thickness_step_m > 0.0) {
    double steps = std::ceil(meeting / o.thickness_step_m - 1e-9);
    for (double stock = internal::StockThickness(steps, o.thickness_step_m);;
         stock = internal::StockThickness(++steps, o.thickness_step_m)) {
      if (stock > space.max_thickness_m * (1 + 1e-12)) break;  // keep the exact thickness
      if (judge.Meets(covering(stock))) {
        recommended = stock;
        break;
      }
    }
  }
  candidate.recommended_thickness_m = recommended;
  candidate.at_design = judge.Estimate(covering(recommended));
  candidate.meets_target = true;
  return candidate;
}

ProbabilityContinuousOptimum ProbabilityContinuous(const ProbabilityJudge& judge, const DesignOptions& o) {
  const double lo = std::log10(o.space.min_modulus_Pa), hi = std::log10(o.space.max_modulus_Pa);
  const int n = std::max(9, static_cast<int>(std::ceil(o.modulus_points_per_decade * (hi - lo))) + 1);
  std::vector<double> moduli;
  for (int i = 0; i < n; ++i) moduli.push_back(i == n - 1 ? hi : lo + (hi - lo) * i / (n - 1));
  auto covering = [&](double u, double b) {
    return CoveringSpec{std::pow(10.0, u), o.covering_poisson_ratio, b};
  };
  std::optional<double> hint;  // the modulus that met the target last: tried first
  // Some modulus of the scan meets the target at b: the one found, or empty.
  auto feasible_at = [&](double b) -> std::optional<double> {
    std::vector<double> order = moduli;
    if (hint) {
      std::stable_sort(order.begin(), order.end(),
                       [&](double x, double y) { return std::abs(x - *hint) < std::abs(y - *hint); });
    }
    for (double u : order) {
      if (judge.Meets(covering(u, b))) return u;
    }
    return std::nullopt;
  };
  ProbabilityContinuousOptimum out;
  const std::vector<double> grid = internal::BracketGrid(o);
  std::optional<std::size_t> first;
  for (std::size_t k = 0; k < grid.size() && !first; ++k) {
    if (const std::optional<double> u = feasible_at(grid[k])) {
      first = k;
      hint = u;
    }
  }
  if (!first) {
    // Nothing meets the target: report the least-failing modulus of the scan at the maximum thickness.
    double best_u = moduli.front();
    std::uint64_t best = kNoStop;
    for (double u : moduli) {
      const std::optional<std::uint64_t> failures =
          judge.FailuresUpTo(covering(u, o.space.max_thickness_m), best == kNoStop ? kNoStop - 1 : best);
      if (failures && *failures < best) {
        best = *failures;
        best_u = u;
      }
    }
    out.design = {std::pow(10.0, best_u), o.space.max_thickness_m};
    out.at_design = judge.Estimate(covering(best_u, o.space.max_thickness_m));
    return out;
  }
  double b = grid[*first];
  if (*first > 0) {
    double failing = grid[*first - 1];
    while (b - failing > o.thickness_resolution_m) {
      const double mid = 0.5 * (failing + b);
      if (const std::optional<double> u = feasible_at(mid)) {
        b = mid;
        hint = u;
      } else {
        failing = mid;
      }
    }
  }
  // At the answer: the modulus of fewest failures among those of the scan.
  double best_u = *hint;
  std::uint64_t best = *judge.FailuresUpTo(covering(best_u, b), kNoStop - 1);
  for (double u : moduli) {
    if (u == *hint) continue;
    const std::optional<std::uint64_t> failures = judge.FailuresUpTo(covering(u, b), best);
    if (failures && *failures < best) {
      best = *failures;
      best_u = u;
    }
  }
  out.feasible = true;
  out.design = {std::pow(10.0, best_u), b};
  out.at_design = judge.Estimate(covering(best_u, b));
  return out;
}

}  // namespace

ProbabilityDesign FindProbabilityDesign(const UncertaintyBox& box, std::span<const CandidateMaterial> materials,
                                        const ProbabilityDesignOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const DesignOptions& o = options.design;
  internal::ValidateDesign(o);
  ValidateSampling(options.sampling);
  // 0 cannot be shown by any finite number of samples (the upper bound of 0 events is > 0).
  Require(std::isfinite(options.max_probability) && options.max_probability > 0.0 && options.max_probability < 1.0,
          "max injury probability must be in (0, 1) (got " + internal::Number(options.max_probability) + ")");
  internal::RefuseCoveringRanges(box);
  for (const CandidateMaterial& m : materials) {
    Require(std::isfinite(m.youngs_modulus_Pa) && m.youngs_modulus_Pa > 0.0 && m.youngs_modulus_Pa <= 1e13,
            "material '" + m.name + "': modulus must be in (0, 1e13] Pa (got " + internal::Number(m.youngs_modulus_Pa) +
                ")");
    Require(m.poisson_ratio > -1.0 && m.poisson_ratio <= 0.5,
            "material '" + m.name + "': poisson ratio must be in (-1, 0.5] (got " + internal::Number(m.poisson_ratio) +
                ")");
  }
  const std::optional<std::uint64_t> allowed =
      MostEventsWithUpperBoundWithin(options.max_probability, options.sampling.samples);
  if (!allowed) {
    // 0 failures in n samples has the upper bound z²/(n + z²): n >= z² (1 − P) / P shows P.
    constexpr double z2 = 1.959963984540054 * 1.959963984540054;
    const double needed = std::ceil(z2 * (1.0 - options.max_probability) / options.max_probability);
    throw std::invalid_argument(
        "max injury probability " + internal::Number(options.max_probability) + " needs at least " +
        internal::Number(needed) + " samples (got " + std::to_string(options.sampling.samples) +
        "): with fewer, even no failing sample leaves the 95 % upper bound above the target");
  }
  internal::TimePathCounter counter;
  if (box.brakes()) ValidateTimeIntegrationOptions(o.oracle.time_path, "oracle.time_path.");
  const ProbabilityJudge judge(box, options, *allowed, counter);
  const std::size_t stages = 1 + materials.size() + (options.continuous ? 1 : 0);
  std::size_t stages_done = 0;
  auto stage_done = [&] {
    ++stages_done;
    if (options.sampling.progress) options.sampling.progress(static_cast<double>(stages_done) / stages);
  };

  ProbabilityDesign out;
  out.criterion = o.criterion();
  out.max_probability = options.max_probability;
  Scene bare = box.nominal();
  bare.covering.thickness_m = 0.0;
  out.bare_robot = judge.Estimate(bare);
  stage_done();
  if (options.continuous) {
    out.continuous = ProbabilityContinuous(judge, o);
    stage_done();
  }
  std::uint64_t material_evaluations = 0;
  for (const CandidateMaterial& material : materials) {
    const ProbabilityJudge material_judge(box, options, *allowed, counter, &material);
    out.candidates.push_back(ProbabilitySnapMaterial(material_judge, material, o));
    material_evaluations += material_judge.evaluated();
    stage_done();
  }
  std::stable_sort(out.candidates.begin(), out.candidates.end(),
                   [](const ProbabilityCandidate& a, const ProbabilityCandidate& b) {
                     if (a.meets_target != b.meets_target) return a.meets_target;
                     if (a.meets_target && *a.recommended_thickness_m != *b.recommended_thickness_m) {
                       return *a.recommended_thickness_m < *b.recommended_thickness_m;
                     }
                     if (a.at_design.inadmissible.count != b.at_design.inadmissible.count) {
                       return a.at_design.inadmissible.count < b.at_design.inadmissible.count;
                     }
                     return a.material.name < b.material.name;
                   });
  out.allowed_failures = *allowed;
  const bool any_meets = !out.candidates.empty() && out.candidates.front().meets_target;
  out.verdict = internal::RobustVerdict(out.bare_robot.inadmissible.count <= *allowed, any_meets,
                                        out.continuous && !out.continuous->feasible);
  if (out.verdict == DesignVerdict::kCoveringFound) out.recommendation = 0;
  out.sample_evaluations = judge.evaluated() + material_evaluations;
  out.time_path = counter.Use();
  out.seconds = SecondsSince(started);
  return out;
}

}  // namespace covopt::optim
