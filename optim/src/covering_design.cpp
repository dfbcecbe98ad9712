// The covering design problems: oracle, continuous search (NLopt then Ipopt), catalog snap.
#include "covopt/optim/covering_design.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <numbers>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/core/sensitivity.hpp>

namespace covopt::optim {
namespace {

constexpr double kLn10 = std::numbers::ln10;

std::string Number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", value);
  return buffer;
}

void Require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument(message);
}

void ValidateOptions(const DesignOptions& o) {
  const DesignSpace& s = o.space;
  Require(std::isfinite(s.min_modulus_Pa) && s.min_modulus_Pa > 0,
          "min modulus must be > 0 Pa (got " + Number(s.min_modulus_Pa) + ")");
  Require(std::isfinite(s.max_modulus_Pa) && s.max_modulus_Pa > s.min_modulus_Pa && s.max_modulus_Pa <= 1e13,
          "max modulus must be in (min modulus " + Number(s.min_modulus_Pa) + " Pa, 1e13 Pa] (got " +
              Number(s.max_modulus_Pa) + ")");
  Require(std::isfinite(s.min_thickness_m) && s.min_thickness_m > 0,
          "min thickness must be > 0 m (got " + Number(s.min_thickness_m) + ")");
  Require(std::isfinite(s.max_thickness_m) && s.max_thickness_m > s.min_thickness_m && s.max_thickness_m <= 1.0,
          "max thickness must be in (min thickness " + Number(s.min_thickness_m) + " m, 1 m] (got " +
              Number(s.max_thickness_m) + ")");
  Require(std::isfinite(o.safety_factor) && o.safety_factor >= 1.0 && o.safety_factor <= 100.0,
          "safety factor must be in [1, 100] (got " + Number(o.safety_factor) + ")");
  Require(o.covering_poisson_ratio > -1.0 && o.covering_poisson_ratio <= 0.5,
          "covering poisson ratio must be in (-1, 0.5] (got " + Number(o.covering_poisson_ratio) + ")");
  Require(o.global_evaluations >= 10, "global evaluations must be >= 10 (got " +
                                          std::to_string(o.global_evaluations) + ")");
  Require(o.thickness_scan_points >= 10, "thickness scan points must be >= 10");
  Require(o.thickness_resolution_m > 0, "thickness resolution must be > 0 m");
  Require(o.threads >= 1 && o.threads <= 256,
          "threads must be in [1, 256] (got " + std::to_string(o.threads) + ")");
  Require(std::isfinite(o.thickness_step_m) && o.thickness_step_m >= 0,
          "thickness step must be >= 0 m (got " + Number(o.thickness_step_m) + ")");
}

/// Problem (a): x = (log10 E_c, b_c / b_max), both of order one (Ipopt is sensitive to
/// scaling: with b_c in metres it reported local infeasibility from feasible basins);
/// min b_c/b_max s.t. ln(SF r_i) <= 0.
class ThinnestProblem : public Problem {
 public:
  ThinnestProblem(const CoveringOracle& oracle, const DesignOptions& o)
      : oracle_(oracle), o_(o),
        lower_{std::log10(o.space.min_modulus_Pa), o.space.min_thickness_m / o.space.max_thickness_m},
        upper_{std::log10(o.space.max_modulus_Pa), 1.0} {}
  std::size_t dimension() const override { return 2; }
  std::size_t inequality_count() const override { return 2; }
  std::vector<double> lower_bounds() const override { return lower_; }
  std::vector<double> upper_bounds() const override { return upper_; }
  /// The same problem on a box around `centre` (±half a decade in E_c, ×0.5..1.5 in b_c),
  /// clipped to the design space: the local stage's trust region. Ipopt started on the whole
  /// box can take a first quasi-Newton step of the full box width, into the bottomed-out
  /// basin near b_c -> 0, and report local infeasibility from there.
  ThinnestProblem Around(std::span<const double> centre) const {
    ThinnestProblem local(oracle_, o_);
    local.lower_ = {std::max(lower_[0], centre[0] - 0.5), std::max(lower_[1], 0.5 * centre[1])};
    local.upper_ = {std::min(upper_[0], centre[0] + 0.5), std::min(upper_[1], 1.5 * centre[1])};
    return local;
  }
  /// x lies on a bound of this box that is not a bound of the design space.
  bool OnArtificialBound(std::span<const double> x, const ThinnestProblem& full) const {
    for (int i = 0; i < 2; ++i) {
      const double tolerance = 1e-7 * (upper_[i] - lower_[i]);
      if ((x[i] - lower_[i] < tolerance && lower_[i] > full.lower_[i]) ||
          (upper_[i] - x[i] < tolerance && upper_[i] < full.upper_[i])) {
        return true;
      }
    }
    return false;
  }
  CoveringDesign Design(std::span<const double> x) const {
    return {std::pow(10.0, x[0]), x[1] * o_.space.max_thickness_m};
  }
  bool Objective(std::span<const double> x, double& value, std::span<double> g) const override {
    value = x[1];
    if (!g.empty()) {
      g[0] = 0.0;
      g[1] = 1.0;
    }
    return true;
  }
  bool Constraints(std::span<const double> x, std::span<double> c, std::span<double> jac) const override {
    RatioGradient gradient;
    const DesignScore score = jac.empty() ? oracle_.Score(Design(x)) : oracle_.Score(Design(x), gradient);
    c[0] = std::log(o_.safety_factor * score.laceration_ratio);
    c[1] = std::log(o_.safety_factor * score.contusion_ratio);
    if (!jac.empty()) {
      const double db_dx = o_.space.max_thickness_m;
      jac[0] = gradient.laceration[0] / score.laceration_ratio;
      jac[1] = gradient.laceration[1] * db_dx / score.laceration_ratio;
      jac[2] = gradient.contusion[0] / score.contusion_ratio;
      jac[3] = gradient.contusion[1] * db_dx / score.contusion_ratio;
    }
    return true;
  }

 private:
  const CoveringOracle& oracle_;
  const DesignOptions& o_;
  std::vector<double> lower_, upper_;
};

/// Problem (b), global form: x = (log10 E_c); min ln(SF max(r_L, r_C)) at fixed b_c.
class WorstRatioProblem : public Problem {
 public:
  WorstRatioProblem(const CoveringOracle& oracle, const DesignOptions& o, double thickness)
      : oracle_(oracle), o_(o), thickness_(thickness) {}
  std::size_t dimension() const override { return 1; }
  std::vector<double> lower_bounds() const override { return {std::log10(o_.space.min_modulus_Pa)}; }
  std::vector<double> upper_bounds() const override { return {std::log10(o_.space.max_modulus_Pa)}; }
  bool Objective(std::span<const double> x, double& value, std::span<double> g) const override {
    RatioGradient gradient;
    const CoveringDesign design{std::pow(10.0, x[0]), thickness_};
    const DesignScore score = g.empty() ? oracle_.Score(design) : oracle_.Score(design, gradient);
    const bool laceration = score.laceration_ratio >= score.contusion_ratio;
    value = std::log(o_.safety_factor * score.worst_ratio());
    if (!g.empty()) {  // a subgradient of the max
      g[0] = laceration ? gradient.laceration[0] / score.laceration_ratio
                        : gradient.contusion[0] / score.contusion_ratio;
    }
    return true;
  }

 private:
  const CoveringOracle& oracle_;
  const DesignOptions& o_;
  double thickness_;
};

/// Problem (b), smooth epigraph form for Ipopt: x = (log10 E_c, s); min s s.t. ln(SF r_i) <= s.
class EpigraphProblem : public Problem {
 public:
  EpigraphProblem(const CoveringOracle& oracle, const DesignOptions& o, double thickness)
      : oracle_(oracle), o_(o), thickness_(thickness) {}
  std::size_t dimension() const override { return 2; }
  std::size_t inequality_count() const override { return 2; }
  std::vector<double> lower_bounds() const override { return {std::log10(o_.space.min_modulus_Pa), -50.0}; }
  std::vector<double> upper_bounds() const override { return {std::log10(o_.space.max_modulus_Pa), 50.0}; }
  bool Objective(std::span<const double> x, double& value, std::span<double> g) const override {
    value = x[1];
    if (!g.empty()) {
      g[0] = 0.0;
      g[1] = 1.0;
    }
    return true;
  }
  bool Constraints(std::span<const double> x, std::span<double> c, std::span<double> jac) const override {
    const CoveringDesign design{std::pow(10.0, x[0]), thickness_};
    RatioGradient gradient;
    const DesignScore score = jac.empty() ? oracle_.Score(design) : oracle_.Score(design, gradient);
    c[0] = std::log(o_.safety_factor * score.laceration_ratio) - x[1];
    c[1] = std::log(o_.safety_factor * score.contusion_ratio) - x[1];
    if (!jac.empty()) {
      jac[0] = gradient.laceration[0] / score.laceration_ratio;
      jac[1] = -1.0;
      jac[2] = gradient.contusion[0] / score.contusion_ratio;
      jac[3] = -1.0;
    }
    return true;
  }

 private:
  const CoveringOracle& oracle_;
  const DesignOptions& o_;
  double thickness_;
};

NloptOptions GlobalOptions(const DesignOptions& o) {
  NloptOptions n;
  n.algorithm = o.global_algorithm;
  n.max_evaluations = o.global_evaluations;
  n.seed = o.seed;
  n.penalty_weight = 10.0;  // objective in [0, 1]; a multiplier above 10 would mean ~no constraint
  n.constraint_tolerance = 1e-6;
  return n;
}

/// Thinnest safe thickness of one material: the first safe point of a scan, then bisection.
CandidateOutcome SnapMaterial(const CoveringOracle& oracle, const CandidateMaterial& material,
                              const DesignOptions& o) {
  const double sf = o.safety_factor;
  const DesignSpace& space = o.space;
  auto score_at = [&](double b) {
    return oracle.ScoreMaterial({material.youngs_modulus_Pa, b}, material.poisson_ratio);
  };
  CandidateOutcome outcome;
  outcome.material = material;
  const int points = o.thickness_scan_points;
  double unsafe = 0.0, safe = 0.0;
  bool found = false;
  for (int k = 0; k < points && !found; ++k) {
    const double b = space.min_thickness_m + (space.max_thickness_m - space.min_thickness_m) * k / (points - 1);
    if (score_at(b).safe(sf)) {
      found = true;
      safe = b;
    } else {
      unsafe = b;
    }
  }
  if (!found) {
    outcome.score = score_at(space.max_thickness_m);
    outcome.margin = outcome.score.margin(sf);
    return outcome;
  }
  if (unsafe > 0.0) {
    while (safe - unsafe > o.thickness_resolution_m) {
      const double mid = 0.5 * (unsafe + safe);
      (score_at(mid).safe(sf) ? safe : unsafe) = mid;
    }
  }
  outcome.min_safe_thickness_m = safe;
  double recommended = safe;
  if (o.thickness_step_m > 0.0) {
    recommended = std::ceil(safe / o.thickness_step_m - 1e-9) * o.thickness_step_m;
    // Safety need not be monotone: step up until the rounded thickness is safe too.
    while (recommended <= space.max_thickness_m + 1e-12 && !score_at(recommended).safe(sf)) {
      recommended += o.thickness_step_m;
    }
    if (recommended > space.max_thickness_m + 1e-12) recommended = safe;  // keep the exact one
  }
  outcome.recommended_thickness_m = recommended;
  outcome.score = score_at(recommended);
  outcome.safe = outcome.score.safe(sf);
  outcome.margin = outcome.score.margin(sf);
  return outcome;
}

/// SnapMaterial for every material, on options.threads threads; outcome i is material i's,
/// whatever the thread count (each thread writes only its own slots). The first exception
/// thrown by any thread is rethrown here after all have joined.
std::vector<CandidateOutcome> SnapMaterials(const CoveringOracle& oracle,
                                            std::span<const CandidateMaterial> materials,
                                            const DesignOptions& o) {
  std::vector<CandidateOutcome> outcomes(materials.size());
  const std::size_t threads =
      std::min<std::size_t>(static_cast<std::size_t>(o.threads), materials.size());
  if (threads <= 1) {
    for (std::size_t i = 0; i < materials.size(); ++i) outcomes[i] = SnapMaterial(oracle, materials[i], o);
    return outcomes;
  }
  std::vector<std::exception_ptr> errors(threads);
  std::vector<std::thread> pool;
  pool.reserve(threads);
  for (std::size_t t = 0; t < threads; ++t) {
    pool.emplace_back([&, t] {
      try {
        for (std::size_t i = t; i < materials.size(); i += threads) {
          outcomes[i] = SnapMaterial(oracle, materials[i], o);
        }
      } catch (...) {
        errors[t] = std::current_exception();
      }
    });
  }
  for (std::thread& thread : pool) thread.join();
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
  return outcomes;
}

/// Nudges a design that meets the constraints only to solver tolerance onto the safe side.
DesignScore MakeStrictlySafe(const CoveringOracle& oracle, DesignScore score, double sf, double max_b) {
  for (int k = 0; k < 40 && !score.safe(sf) && score.margin(sf) > -1e-6; ++k) {
    CoveringDesign d = score.design;
    d.thickness_m = std::min(max_b, d.thickness_m * (1.0 + 1e-9 * std::pow(2.0, k)));
    score = oracle.Score(d);
  }
  return score;
}

}  // namespace

const char* ToString(DesignVerdict verdict) noexcept {
  switch (verdict) {
    case DesignVerdict::kCoveringFound: return "covering-found";
    case DesignVerdict::kBareRobotSafe: return "bare-robot-safe";
    case DesignVerdict::kNoSafeMaterial: return "no-safe-material";
    case DesignVerdict::kNothingSafe: return "nothing-safe";
  }
  return "unknown";
}

CoveringOracle::CoveringOracle(const Scene& scene, double covering_poisson_ratio,
                               const InjuryLimits& limits)
    : scene_(scene), limits_(limits) {
  scene_.covering.poisson_ratio = covering_poisson_ratio;
  Scene bare = scene_;
  bare.covering.thickness_m = 0.0;
  (void)ImpactModel::FromScene(bare);  // validates everything but the design
  Require(limits.laceration_tensile_stress_Pa > 0 && limits.contusion_energy_density_J_per_m2 > 0,
          "injury limits must be > 0");
}

DesignScore CoveringOracle::ScoreMaterial(const CoveringDesign& design, double poisson_ratio) const {
  ++evaluations_;
  Scene scene = scene_;
  scene.covering = {design.youngs_modulus_Pa, poisson_ratio, design.thickness_m};
  DesignScore score;
  score.design = design;
  score.poisson_ratio = poisson_ratio;
  score.peaks = ExactPeaks(ImpactModel::FromScene(scene));
  const InjuryAssessment a = Assess(score.peaks, limits_);
  score.laceration_ratio = a.laceration.ratio;
  score.contusion_ratio = a.contusion.ratio;
  return score;
}

DesignScore CoveringOracle::Score(const CoveringDesign& design) const {
  return ScoreMaterial(design, scene_.covering.poisson_ratio);
}

DesignScore CoveringOracle::Score(const CoveringDesign& design, RatioGradient& gradient) const {
  ++evaluations_;
  Scene scene = scene_;
  scene.covering.youngs_modulus_Pa = design.youngs_modulus_Pa;
  scene.covering.thickness_m = design.thickness_m;
  const ImpactModel model = ImpactModel::FromScene(scene);
  DesignScore score;
  score.design = design;
  score.poisson_ratio = scene.covering.poisson_ratio;
  score.peaks = ExactPeaks(model);
  const InjuryAssessment a = Assess(score.peaks, limits_);
  score.laceration_ratio = a.laceration.ratio;
  score.contusion_ratio = a.contusion.ratio;
  const PeakSensitivities s = ExactPeakSensitivities(model, score.peaks);
  const double per_log10 = design.youngs_modulus_Pa * kLn10;  // dE/du, u = log10 E
  gradient.laceration[0] = s.per_covering_modulus.max_tensile_stress * per_log10 / limits_.laceration_tensile_stress_Pa;
  gradient.laceration[1] = s.per_covering_thickness.max_tensile_stress / limits_.laceration_tensile_stress_Pa;
  gradient.contusion[0] = s.per_covering_modulus.max_energy_density * per_log10 / limits_.contusion_energy_density_J_per_m2;
  gradient.contusion[1] = s.per_covering_thickness.max_energy_density / limits_.contusion_energy_density_J_per_m2;
  return score;
}

DesignScore CoveringOracle::ScoreBare() const {
  ++evaluations_;
  Scene scene = scene_;
  scene.covering.thickness_m = 0.0;
  DesignScore score;
  score.peaks = ExactPeaks(ImpactModel::FromScene(scene));
  const InjuryAssessment a = Assess(score.peaks, limits_);
  score.laceration_ratio = a.laceration.ratio;
  score.contusion_ratio = a.contusion.ratio;
  return score;
}

ThinnestSafeCovering FindThinnestSafeCovering(const Scene& scene,
                                              std::span<const CandidateMaterial> materials,
                                              const DesignOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  ValidateOptions(options);
  const CoveringOracle oracle(scene, options.covering_poisson_ratio, options.limits);
  const double sf = options.safety_factor;
  ThinnestSafeCovering out;
  out.bare_robot = oracle.ScoreBare();

  // Continuous optimum: global search, then Ipopt from its point.
  const ThinnestProblem problem(oracle, options);
  const std::vector<double> lower = problem.lower_bounds(), upper = problem.upper_bounds();
  std::vector<double> start = {0.5 * (lower[0] + upper[0]), 0.5 * (lower[1] + upper[1])};
  if (options.initial_design) {
    start = {std::log10(options.initial_design->youngs_modulus_Pa),
             options.initial_design->thickness_m / options.space.max_thickness_m};
  }
  const SolveResult global = SolveWithNlopt(problem, start, GlobalOptions(options));
  out.continuous.global = global.report;
  SolveResult chosen = global;
  out.continuous.source = "global";
  if (options.local_polish && global.is_usable()) {
    // Ipopt in a trust region around the global point, re-centred while it ends on the
    // region's (artificial) edge.
    SolveResult local;
    std::vector<double> centre = global.x;
    for (int attempt = 0; attempt < 4; ++attempt) {
      const ThinnestProblem region = problem.Around(centre);
      local = SolveWithIpopt(region, centre, options.ipopt);
      if (!local.is_usable() || !region.OnArtificialBound(local.x, problem)) break;
      centre = local.x;
    }
    out.continuous.local = local.report;
    const bool local_feasible = local.is_usable() && local.max_violation <= 1e-7;
    const bool global_feasible = global.max_violation <= 1e-7;
    if (local_feasible && (!global_feasible || local.x[1] <= global.x[1] + 1e-12)) {
      chosen = local;
      out.continuous.source = "ipopt";
    } else {
      out.continuous.source = std::string("global (ipopt ended ") + ToString(local.report.termination) +
                              " / " + local.report.raw_name + "; its point was not better)";
    }
  }
  DesignScore best = oracle.Score(problem.Design(chosen.x));
  best = MakeStrictlySafe(oracle, best, sf, options.space.max_thickness_m);
  out.continuous.score = best;
  out.continuous.feasible = best.safe(sf);
  if (!out.continuous.feasible) {
    // Nothing meets the limits within the bound: report the least-injury design at the
    // maximum thickness instead (problem b there).
    const LeastInjuryAtThickness fallback =
        MinimizeInjuryAtThickness(scene, options.space.max_thickness_m, {}, options);
    out.continuous.score = fallback.continuous.score;
    out.continuous.source += "; infeasible: least injury at the maximum thickness reported";
    out.evaluations += fallback.evaluations;
  }

  // Snap to each material, rank.
  out.candidates = SnapMaterials(oracle, materials, options);
  std::stable_sort(out.candidates.begin(), out.candidates.end(),
                   [](const CandidateOutcome& a, const CandidateOutcome& b) {
                     if (a.safe != b.safe) return a.safe;
                     if (a.safe && *a.recommended_thickness_m != *b.recommended_thickness_m) {
                       return *a.recommended_thickness_m < *b.recommended_thickness_m;
                     }
                     if (a.margin != b.margin) return a.margin > b.margin;
                     return a.material.name < b.material.name;
                   });
  const bool any_safe = !out.candidates.empty() && out.candidates.front().safe;
  if (out.bare_robot.safe(sf)) {
    out.verdict = DesignVerdict::kBareRobotSafe;
  } else if (any_safe) {
    out.verdict = DesignVerdict::kCoveringFound;
    out.recommendation = 0;
  } else {
    out.verdict = out.continuous.feasible ? DesignVerdict::kNoSafeMaterial : DesignVerdict::kNothingSafe;
  }
  out.evaluations += oracle.evaluations();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return out;
}

LeastInjuryAtThickness MinimizeInjuryAtThickness(const Scene& scene, double thickness_m,
                                                 std::span<const CandidateMaterial> materials,
                                                 const DesignOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  ValidateOptions(options);
  Require(std::isfinite(thickness_m) && thickness_m > 0.0 && thickness_m <= 1.0,
          "thickness must be in (0, 1] m (got " + Number(thickness_m) + ")");
  const CoveringOracle oracle(scene, options.covering_poisson_ratio, options.limits);
  const double sf = options.safety_factor;
  LeastInjuryAtThickness out;
  out.thickness_m = thickness_m;
  out.bare_robot = oracle.ScoreBare();

  const WorstRatioProblem global_problem(oracle, options, thickness_m);
  const double centre = 0.5 * (global_problem.lower_bounds()[0] + global_problem.upper_bounds()[0]);
  NloptOptions global_options = GlobalOptions(options);
  global_options.max_evaluations = std::min<long>(options.global_evaluations, 400);  // 1-D
  const SolveResult global = SolveWithNlopt(global_problem, std::vector<double>{centre}, global_options);
  out.continuous.global = global.report;
  double best_log_modulus = global.x.empty() ? centre : global.x[0];
  out.continuous.source = "global";
  if (options.local_polish && global.is_usable()) {
    const EpigraphProblem epigraph(oracle, options, thickness_m);
    const SolveResult local =
        SolveWithIpopt(epigraph, std::vector<double>{global.x[0], global.objective + 1e-3}, options.ipopt);
    out.continuous.local = local.report;
    if (local.is_usable() && local.max_violation <= 1e-7 && local.objective <= global.objective + 1e-12) {
      best_log_modulus = local.x[0];
      out.continuous.source = "ipopt";
    } else {
      out.continuous.source = std::string("global (ipopt ended ") + ToString(local.report.termination) +
                              " / " + local.report.raw_name + "; its point was not better)";
    }
  }
  out.continuous.score = oracle.Score({std::pow(10.0, best_log_modulus), thickness_m});
  out.continuous.feasible = true;

  for (const CandidateMaterial& material : materials) {
    CandidateOutcome outcome;
    outcome.material = material;
    outcome.score = oracle.ScoreMaterial({material.youngs_modulus_Pa, thickness_m}, material.poisson_ratio);
    outcome.safe = outcome.score.safe(sf);
    outcome.margin = outcome.score.margin(sf);
    if (outcome.safe) outcome.recommended_thickness_m = thickness_m;
    out.candidates.push_back(outcome);
  }
  std::stable_sort(out.candidates.begin(), out.candidates.end(),
                   [](const CandidateOutcome& a, const CandidateOutcome& b) {
                     if (a.margin != b.margin) return a.margin > b.margin;
                     return a.material.name < b.material.name;
                   });
  if (!out.candidates.empty() && out.candidates.front().safe) {
    out.verdict = DesignVerdict::kCoveringFound;
    out.recommendation = 0;
  } else {
    out.verdict = out.continuous.score.safe(sf) ? DesignVerdict::kNoSafeMaterial : DesignVerdict::kNothingSafe;
  }
  out.evaluations = oracle.evaluations();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return out;
}

}  // namespace covopt::optim
