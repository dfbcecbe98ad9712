// The covering design problems: oracle, continuous search (NLopt then Ipopt), catalog snap.
#include "covopt/optim/covering_design.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/core/parallel_for.hpp>

#include "robust_internal.hpp"
#include "validation_internal.hpp"

namespace covopt::optim {
namespace {

/// The continuous optimum's thickness is bisected to this [m].
constexpr double kThicknessTolerance_m = 1e-11;
/// The covering's travel ratio in the logarithmic constraint is at least this: it is 0 while
/// δ_max stays within the scalp's travel, far inside the constraint, where it is flat.
constexpr double kLeastTravelRatio = 1e-12;

using internal::Number;
using internal::Require;

void ValidateOptions(const DesignOptions& o) {
  internal::ValidateDesignSpace(o.space);
  Require(std::isfinite(o.safety_factor) && o.safety_factor >= 1.0 && o.safety_factor <= 100.0,
          "safety factor must be in [1, 100] (got " + Number(o.safety_factor) + ")");
  Require(o.covering_poisson_ratio > -1.0 && o.covering_poisson_ratio <= 0.5,
          "covering poisson ratio must be in (-1, 0.5] (got " + Number(o.covering_poisson_ratio) + ")");
  Require(o.global_evaluations >= 10, "global evaluations must be >= 10 (got " +
                                          std::to_string(o.global_evaluations) + ")");
  Require(o.thickness_scan_points >= 10, "thickness scan points must be >= 10");
  Require(o.bracket_thickness_points >= 4 && o.bracket_thickness_points <= 100000,
          "bracket thickness points must be in [4, 100000] (got " + std::to_string(o.bracket_thickness_points) + ")");
  Require(o.modulus_points_per_decade >= 2 && o.modulus_points_per_decade <= 10000,
          "modulus points per decade must be in [2, 10000] (got " + std::to_string(o.modulus_points_per_decade) + ")");
  Require(o.thickness_resolution_m > 0, "thickness resolution must be > 0 m");
  Require(o.threads >= 1 && o.threads <= 256,
          "threads must be in [1, 256] (got " + std::to_string(o.threads) + ")");
  Require(std::isfinite(o.thickness_step_m) && o.thickness_step_m >= 0,
          "thickness step must be >= 0 m (got " + Number(o.thickness_step_m) + ")");
}

void ValidateCandidates(std::span<const CandidateMaterial> materials, CoveringLaw law) {
  for (const CandidateMaterial& m : materials) {
    (void)CoveringOf(m, 1e-3, law);  // law foam needs a curve
    if (m.crush_behaviour != materials::CrushBehaviour::kCrushes) continue;
    internal::CheckCompressiveStrength(m.compressive_strength_Pa, "material '" + m.name + "': ");
  }
}

/// A design problem for Ipopt on the oracle: minimise the last of two variables (b_c/b_max, or
/// the epigraph's s) under constraints the oracle scores. Second derivatives by central
/// differences of the oracle's Jacobian (the objective is linear), with the oracle's step:
/// only the polish's convergence rate depends on them, its point is fixed by the first
/// derivatives.
class MinimizeSecondVariable : public Problem {
 public:
  bool Objective(std::span<const double> x, double& value, std::span<double> g) const override {
    value = x[1];
    if (!g.empty()) {
      g[0] = 0.0;
      g[1] = 1.0;
    }
    return true;
  }
  bool provides_lagrangian_hessian() const override { return true; }
  bool LagrangianHessian(std::span<const double> x, double objective_factor, std::span<const double> multipliers,
                         std::span<double> lower_triangle) const override {
    return CentralDifferenceLagrangianHessian(*this, x, objective_factor, multipliers, lower_triangle,
                                              oracle_.DifferenceStep());
  }

 protected:
  MinimizeSecondVariable(const DesignOracle& oracle, const DesignOptions& o) : oracle_(oracle), o_(o) {}
  const DesignOracle& oracle_;
  const DesignOptions& o_;
};

/// Problem (a): x = (log10 E_c, b_c / b_max), both of order one (Ipopt is sensitive to
/// scaling: with b_c in metres it reported local infeasibility from feasible basins);
/// min b_c/b_max s.t. ln(SF r_i) <= 0 and, under the default criterion, ln(SF r_δ) <= 0 with
/// r_δ the covering's travel ratio (DesignScore::compression_ratio).
class ThinnestProblem : public MinimizeSecondVariable {
 public:
  ThinnestProblem(const DesignOracle& oracle, const DesignOptions& o)
      : MinimizeSecondVariable(oracle, o),
        lower_{std::log10(o.space.min_modulus_Pa), o.space.min_thickness_m / o.space.max_thickness_m},
        upper_{std::log10(o.space.max_modulus_Pa), 1.0} {}
  std::size_t dimension() const override { return 2; }
  std::size_t inequality_count() const override {
    return o_.criterion() == DesignCriterion::kNoFullCompression ? 4 : 3;
  }
  std::vector<double> lower_bounds() const override { return lower_; }
  std::vector<double> upper_bounds() const override { return upper_; }
  /// The same problem on a box around `centre` (±`log_width` decades in E_c, ×(1 ± `relative_width`)
  /// in b_c), clipped to the design space: the local stage's trust region. Ipopt started on the
  /// whole box can take a first quasi-Newton step of the full box width, into the bottomed-out
  /// basin near b_c -> 0, and report local infeasibility from there.
  ThinnestProblem Around(std::span<const double> centre, double log_width, double relative_width) const {
    ThinnestProblem local(oracle_, o_);
    local.lower_ = {std::max(lower_[0], centre[0] - log_width), std::max(lower_[1], (1 - relative_width) * centre[1])};
    local.upper_ = {std::min(upper_[0], centre[0] + log_width), std::min(upper_[1], (1 + relative_width) * centre[1])};
    return local;
  }
  CoveringDesign Design(std::span<const double> x) const {
    return {std::pow(10.0, x[0]), x[1] * o_.space.max_thickness_m};
  }
  std::vector<double> Point(const CoveringDesign& d) const {
    return {std::log10(d.youngs_modulus_Pa), d.thickness_m / o_.space.max_thickness_m};
  }
  bool Constraints(std::span<const double> x, std::span<double> c, std::span<double> jac) const override {
    RatioGradient gradient;
    const DesignScore score = jac.empty() ? oracle_.Score(Design(x)) : oracle_.Score(Design(x), gradient);
    if (score.failed) return false;
    c[0] = std::log(o_.safety_factor * score.laceration_ratio);
    c[1] = std::log(o_.safety_factor * score.contusion_ratio);
    c[2] = std::log(o_.safety_factor * score.fracture_ratio);
    const bool compression = inequality_count() == 4;
    const double travel = std::max(score.compression_ratio, kLeastTravelRatio);
    if (compression) c[3] = std::log(o_.safety_factor * travel);
    if (!jac.empty()) {
      const double db_dx = o_.space.max_thickness_m;
      jac[0] = gradient.laceration[0] / score.laceration_ratio;
      jac[1] = gradient.laceration[1] * db_dx / score.laceration_ratio;
      jac[2] = gradient.contusion[0] / score.contusion_ratio;
      jac[3] = gradient.contusion[1] * db_dx / score.contusion_ratio;
      jac[4] = gradient.fracture[0] / score.fracture_ratio;
      jac[5] = gradient.fracture[1] * db_dx / score.fracture_ratio;
      if (compression) {
        jac[6] = gradient.compression[0] / travel;
        jac[7] = gradient.compression[1] * db_dx / travel;
      }
    }
    return true;
  }

 private:
  std::vector<double> lower_, upper_;
};

/// Problem (b), global form: x = (log10 E_c) in [lower, log10 E_max];
/// min ln(SF max(r_L, r_C)) at fixed b_c. The admissible moduli form one interval (δ_max falls
/// as E_c grows), so the compression condition is the lower bound.
class WorstRatioProblem : public Problem {
 public:
  WorstRatioProblem(const DesignOracle& oracle, const DesignOptions& o, double thickness, double lower)
      : oracle_(oracle), o_(o), thickness_(thickness), lower_(lower) {}
  std::size_t dimension() const override { return 1; }
  std::vector<double> lower_bounds() const override { return {lower_}; }
  std::vector<double> upper_bounds() const override { return {std::log10(o_.space.max_modulus_Pa)}; }
  bool Objective(std::span<const double> x, double& value, std::span<double> g) const override {
    RatioGradient gradient;
    const CoveringDesign design{std::pow(10.0, x[0]), thickness_};
    const DesignScore score = g.empty() ? oracle_.Score(design) : oracle_.Score(design, gradient);
    if (score.failed) return false;
    value = std::log(o_.safety_factor * score.worst_ratio());
    if (!g.empty()) {  // a subgradient of the max
      const double worst = score.worst_ratio();
      g[0] = worst == score.laceration_ratio  ? gradient.laceration[0] / score.laceration_ratio
             : worst == score.contusion_ratio ? gradient.contusion[0] / score.contusion_ratio
                                              : gradient.fracture[0] / score.fracture_ratio;
    }
    return true;
  }

 private:
  const DesignOracle& oracle_;
  const DesignOptions& o_;
  double thickness_;
  double lower_;
};

/// Problem (b), smooth epigraph form for Ipopt: x = (log10 E_c, s); min s s.t. ln(SF r_i) <= s,
/// log10 E_c in [lower, log10 E_max].
class EpigraphProblem : public MinimizeSecondVariable {
 public:
  EpigraphProblem(const DesignOracle& oracle, const DesignOptions& o, double thickness, double lower)
      : MinimizeSecondVariable(oracle, o), thickness_(thickness), lower_(lower) {}
  std::size_t dimension() const override { return 2; }
  std::size_t inequality_count() const override { return 3; }
  std::vector<double> lower_bounds() const override { return {lower_, -50.0}; }
  std::vector<double> upper_bounds() const override { return {std::log10(o_.space.max_modulus_Pa), 50.0}; }
  bool Constraints(std::span<const double> x, std::span<double> c, std::span<double> jac) const override {
    const CoveringDesign design{std::pow(10.0, x[0]), thickness_};
    RatioGradient gradient;
    const DesignScore score = jac.empty() ? oracle_.Score(design) : oracle_.Score(design, gradient);
    if (score.failed) return false;
    c[0] = std::log(o_.safety_factor * score.laceration_ratio) - x[1];
    c[1] = std::log(o_.safety_factor * score.contusion_ratio) - x[1];
    c[2] = std::log(o_.safety_factor * score.fracture_ratio) - x[1];
    if (!jac.empty()) {
      jac[0] = gradient.laceration[0] / score.laceration_ratio;
      jac[1] = -1.0;
      jac[2] = gradient.contusion[0] / score.contusion_ratio;
      jac[3] = -1.0;
      jac[4] = gradient.fracture[0] / score.fracture_ratio;
      jac[5] = -1.0;
    }
    return true;
  }

 private:
  double thickness_;
  double lower_;
};

/// The best modulus at one thickness, as the nested search finds it.
struct ModulusChoice {
  /// Some modulus in the box keeps the covering from full compression (always, for the
  /// paper's criterion).
  bool admissible_modulus_exists = true;
  double lowest_admissible_log_modulus = 0.0;  ///< u_c = log10 of the softest such modulus
  DesignScore score;                           ///< at the modulus of least worst ratio
};

/// The 1-D global search in u = log10 E_c at a fixed thickness (see the header: stage 2).
class ModulusSearch {
 public:
  ModulusSearch(const DesignOracle& oracle, const DesignOptions& o)
      : oracle_(oracle), o_(o), lo_(std::log10(o.space.min_modulus_Pa)), hi_(std::log10(o.space.max_modulus_Pa)) {}

  /// The admissible interval of moduli at `thickness_m`, and the least worst ratio on it.
  /// With `screen` set, a thickness whose scanned worst ratio is far above the limit (x3)
  /// is not refined: its sampled minimum already shows it inadmissible (the ratios change by
  /// a few percent between scan points, which are 1/points_per_decade decades apart).
  ModulusChoice Best(double thickness_m, bool screen = false) const {
    ModulusChoice choice;
    double lower = lo_;
    if (o_.criterion() == DesignCriterion::kNoFullCompression) {
      const double sf = o_.safety_factor;
      const DesignScore stiffest = At(hi_, thickness_m);
      if (stiffest.compression_exceeded(sf)) {
        choice.admissible_modulus_exists = false;
        choice.lowest_admissible_log_modulus = hi_;
        choice.score = stiffest;
        return choice;
      }
      if (At(lo_, thickness_m).compression_exceeded(sf)) {
        // δ_max falls as E_c grows (F rises with E_c at every δ): bisect the boundary of the
        // travel the safety factor leaves.
        double compressed = lo_, free = hi_;
        while (free - compressed > kLogModulusTolerance) {
          const double mid = 0.5 * (compressed + free);
          (At(mid, thickness_m).compression_exceeded(sf) ? compressed : free) = mid;
        }
        lower = free;
      }
    }
    choice.lowest_admissible_log_modulus = lower;
    choice.score = MinimizeWorst(thickness_m, lower, hi_, screen);
    return choice;
  }

  /// min over u in [a, c] of the worst ratio: a uniform scan, then golden-section refinement
  /// of the best local minima of the scan. Returns the best point evaluated.
  DesignScore MinimizeWorst(double thickness_m, double a, double c, bool screen = false) const {
    const int n = std::max(9, static_cast<int>(std::ceil(o_.modulus_points_per_decade * (c - a))) + 1);
    std::vector<DesignScore> samples;
    samples.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) samples.push_back(At(Grid(a, c, n, i), thickness_m));
    std::size_t best = 0;
    for (std::size_t i = 1; i < samples.size(); ++i) {
      if (samples[i].worst_ratio() < samples[best].worst_ratio()) best = i;
    }
    DesignScore result = samples[best];
    if (screen && o_.safety_factor * result.worst_ratio() > kScreenFactor) return result;
    // Local minima of the sampled sequence, best first; refine those close to the best.
    std::vector<std::size_t> minima;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const double w = samples[i].worst_ratio();
      const bool left = i == 0 || w <= samples[i - 1].worst_ratio();
      const bool right = i + 1 == samples.size() || w <= samples[i + 1].worst_ratio();
      if (left && right && w <= kRefineWithin * samples[best].worst_ratio()) minima.push_back(i);
    }
    std::stable_sort(minima.begin(), minima.end(), [&](std::size_t x, std::size_t y) {
      return samples[x].worst_ratio() < samples[y].worst_ratio();
    });
    if (minima.size() > kMaxRefinedMinima) minima.resize(kMaxRefinedMinima);
    for (std::size_t i : minima) {
      const double left = Grid(a, c, n, i == 0 ? 0 : static_cast<int>(i) - 1);
      const double right = Grid(a, c, n, std::min(n - 1, static_cast<int>(i) + 1));
      const DesignScore refined = Golden(thickness_m, left, right);
      if (refined.worst_ratio() < result.worst_ratio()) result = refined;
    }
    return result;
  }

 private:
  static constexpr double kLogModulusTolerance = 1e-12;
  static constexpr double kScreenFactor = 3.0;
  static constexpr double kRefineWithin = 1.05;
  static constexpr std::size_t kMaxRefinedMinima = 3;

  static double Grid(double a, double c, int n, int i) {
    return i == n - 1 ? c : a + (c - a) * i / (n - 1);
  }
  DesignScore At(double u, double thickness_m) const { return oracle_.Score({std::pow(10.0, u), thickness_m}); }

  /// Golden-section search for the least worst ratio on [a, c]; the best point evaluated.
  DesignScore Golden(double thickness_m, double a, double c) const {
    return internal::GoldenSection([&](double u) { return At(u, thickness_m); },
                                   [](const DesignScore& s) { return s.worst_ratio(); }, a, c, kLogModulusTolerance);
  }

  const DesignOracle& oracle_;
  const DesignOptions& o_;
  double lo_, hi_;
};

/// Admissible at this thickness: some modulus keeps the covering from full compression
/// (criterion permitting) and the least worst ratio there is within the derated limits.
bool Admissible(const ModulusChoice& choice, const DesignOptions& o) {
  return choice.admissible_modulus_exists && choice.score.admissible(o.safety_factor, o.criterion());
}

/// Stage 2 of problem (a): the thinnest admissible thickness by a scan in b_c (from thin to
/// thick) and bisection. `upper_bracket` (an admissible thickness from stage 1, if any) joins
/// the grid. Empty when nothing in the box is admissible.
std::optional<ModulusChoice> BracketThinnest(const ModulusSearch& search, const DesignOptions& o,
                                             std::optional<double> upper_bracket) {
  const std::vector<double> grid = internal::BracketGrid(o, upper_bracket);

  for (std::size_t k = 0; k < grid.size(); ++k) {
    ModulusChoice choice = search.Best(grid[k], /*screen=*/true);
    if (!Admissible(choice, o)) continue;
    if (k == 0) return choice;
    double inadmissible = grid[k - 1], admissible = grid[k];
    while (admissible - inadmissible > kThicknessTolerance_m) {
      const double mid = 0.5 * (inadmissible + admissible);
      ModulusChoice at_mid = search.Best(mid);
      if (Admissible(at_mid, o)) {
        admissible = mid;
        choice = at_mid;
      } else {
        inadmissible = mid;
      }
    }
    return choice;
  }
  return std::nullopt;
}

NloptOptions GlobalOptions(const DesignOptions& o) {
  NloptOptions n;
  n.algorithm = o.global_algorithm;
  n.max_evaluations = o.global_evaluations;
  n.seed = o.seed;
  n.penalty_weight = 10.0;  // objective in [0, 1]; a multiplier above 10 would mean ~no constraint
  n.constraint_tolerance = 1e-6;
  return n;
}

/// Thinnest admissible thickness of one material: the first admissible point of a scan, then
/// bisection; then rounded up to stock.
CandidateOutcome SnapMaterial(const DesignOracle& oracle, const CandidateMaterial& material,
                              const DesignOptions& o) {
  const DesignRule rule = o.rule();
  const DesignSpace& space = o.space;
  auto score_at = [&](double b) {
    DesignScore score = oracle.ScoreCovering(CoveringOf(material, b, o.covering_law));
    CheckCrush(material, score);
    return score;
  };
  auto admissible_at = [&](double b) { return score_at(b).admissible(rule); };
  CandidateOutcome outcome;
  outcome.material = material;
  const std::optional<double> thinnest =
      internal::ThinnestAdmissibleThickness(space, o.thickness_scan_points, o.thickness_resolution_m, admissible_at);
  if (!thinnest) {
    outcome.score = score_at(space.max_thickness_m);
    outcome.margin = outcome.score.margin(rule);
    return outcome;
  }
  const double admissible = *thinnest;
  outcome.min_safe_thickness_m = admissible;
  std::optional<DesignScore> at_stock;  // the admissible stock thickness's score, once found
  if (o.thickness_step_m > 0.0) {
    at_stock = internal::FirstAdmissibleStock(
        admissible, o.thickness_step_m, space.max_thickness_m, score_at,
        [&](const DesignScore& score) { return score.admissible(rule); }, outcome.stock_thickness_beyond_max_m);
  }
  outcome.score = at_stock ? *at_stock : score_at(admissible);
  outcome.recommended_thickness_m = outcome.score.design.thickness_m;
  outcome.safe = outcome.score.admissible(rule);
  outcome.margin = outcome.score.margin(rule);
  return outcome;
}

/// SnapMaterial for every material, on options.threads threads (ParallelFor); outcome i is
/// material i's, whatever the thread count. The first exception thrown by any thread is
/// rethrown here after all have joined.
std::vector<CandidateOutcome> SnapMaterials(const DesignOracle& oracle,
                                            std::span<const CandidateMaterial> materials,
                                            const DesignOptions& o) {
  std::vector<CandidateOutcome> outcomes(materials.size());
  ParallelFor(materials.size(), static_cast<unsigned>(o.threads), [&](std::size_t i, unsigned) {
    outcomes[i] = SnapMaterial(oracle, materials[i], o);
  });
  return outcomes;
}

}  // namespace

CoveringLaw DesignLawOf(const CandidateMaterial& material, CoveringLaw law) noexcept {
  return law != CoveringLaw::kHertz && material.compressive_curve ? CoveringLaw::kFoam : CoveringLaw::kHertz;
}

CoveringSpec CoveringOf(const CandidateMaterial& material, double thickness_m, CoveringLaw law) {
  if (law == CoveringLaw::kFoam && !material.compressive_curve) {
    throw std::invalid_argument("covering law foam: material '" + material.name +
                                "' has no compressive_curve (the foam law needs a measured curve); choose materials "
                                "with a curve (materials find --has-curve) or --covering-law auto|hertz");
  }
  const bool foam = DesignLawOf(material, law) == CoveringLaw::kFoam;
  return CoveringSpec{.youngs_modulus_Pa = material.youngs_modulus_Pa,
                      .poisson_ratio = material.poisson_ratio,
                      .thickness_m = thickness_m,
                      .compressive_curve = foam ? material.compressive_curve : nullptr,
                      .law = foam ? CoveringLaw::kFoam : CoveringLaw::kHertz};
}

void CheckCrush(const CandidateMaterial& material, DesignScore& score) noexcept {
  score.crush_ratio = 0.0;
  switch (material.crush_behaviour) {
    case materials::CrushBehaviour::kCrushes:
      score.crush_check = CrushCheck::kChecked;
      score.crush_ratio = score.failed ? std::numeric_limits<double>::infinity()
                                       : score.peaks.max_compressive_stress_Pa / material.compressive_strength_Pa;
      return;
    case materials::CrushBehaviour::kDoesNotCrush: score.crush_check = CrushCheck::kDoesNotCrush; return;
    case materials::CrushBehaviour::kUnknown: score.crush_check = CrushCheck::kUnknownStrength; return;
  }
}

std::string_view ToString(DesignVerdict verdict) noexcept {
  switch (verdict) {
    case DesignVerdict::kCoveringFound: return "covering-found";
    case DesignVerdict::kBareRobotSafe: return "bare-robot-safe";
    case DesignVerdict::kNoSafeMaterial: return "no-safe-material";
    case DesignVerdict::kNothingSafe: return "nothing-safe";
  }
  return "unknown";
}

namespace {

/// A SolverReport for covopt's own bracketed stage.
SolverReport BracketReport(bool found, long evaluations, double seconds) {
  SolverReport r;
  r.backend = "covopt:bracket";
  r.termination = found ? Termination::kConverged : Termination::kInfeasible;
  r.raw_code = found ? 0 : 1;
  r.raw_name = found ? "bracketed" : "no-admissible-design-in-box";
  r.objective_evaluations = evaluations;
  r.seconds = seconds;
  return r;
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string Ended(const SolverReport& r) {
  return std::string(ToString(r.termination)) + (r.raw_name.empty() ? "" : " / " + r.raw_name);
}

/// Stage 3 of FindThinnestSafeCovering: Ipopt from the bracketed optimum `best`, kept (into
/// `best`) only if admissible and not thicker; `continuous` gets the local report and source.
void PolishWithIpopt(const ThinnestProblem& problem, const DesignOracle& oracle, const DesignOptions& options,
                     DesignScore& best, ContinuousOptimum& continuous) {
  const std::vector<double> centre = problem.Point(best.design);
  const ThinnestProblem region = problem.Around(centre, 0.25, 0.05);
  IpoptOptions polish = options.ipopt;
  polish.warm_start = true;  // the bracket's point is the optimum to ~1e-11 m: confirm it
  const SolveResult local = SolveWithIpopt(region, centre, polish);
  continuous.local = local.report;
  if (local.is_usable()) {
    const DesignScore polished = oracle.Score(problem.Design(local.x));
    // Not thicker than the bracket, to the bracket's own resolution.
    if (polished.admissible(options.safety_factor, options.criterion()) &&
        polished.design.thickness_m <= best.design.thickness_m + kThicknessTolerance_m) {
      best = polished;
      continuous.source = "ipopt";
      return;
    }
  }
  continuous.source = "bracket (ipopt ended " + Ended(local.report) +
                      (local.is_usable() ? "; its point was not admissible or not thinner)" : ")");
}

}  // namespace

ThinnestSafeCovering FindThinnestSafeCovering(const Scene& scene,
                                              std::span<const CandidateMaterial> materials,
                                              const DesignOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  ValidateOptions(options);
  ValidateCandidates(materials, options.covering_law);
  const std::unique_ptr<DesignOracle> owned_oracle =
      MakeOracle(scene, options.covering_poisson_ratio, options.limits, options.oracle);
  const DesignOracle& oracle = *owned_oracle;
  const double sf = options.safety_factor;
  const DesignCriterion criterion = options.criterion();
  ThinnestSafeCovering out;
  out.criterion = criterion;
  out.bare_robot = oracle.ScoreBare();

  // Stage 1: NLopt on the 2-D problem. Its point, re-checked by the oracle, is at most an
  // upper bracket: nothing is reported from it unless stage 2 confirms it.
  const ThinnestProblem problem(oracle, options);
  const std::vector<double> lower = problem.lower_bounds(), upper = problem.upper_bounds();
  std::vector<double> start = {0.5 * (lower[0] + upper[0]), 0.5 * (lower[1] + upper[1])};
  if (options.initial_design) start = problem.Point(*options.initial_design);
  const SolveResult global = SolveWithNlopt(problem, start, GlobalOptions(options));
  out.continuous.global = global.report;
  std::optional<double> upper_bracket;
  if (global.is_usable()) {
    const DesignScore at_global = oracle.Score(problem.Design(global.x));
    if (at_global.admissible(sf, criterion)) upper_bracket = at_global.design.thickness_m;
  }

  std::optional<OracleReport> fallback_oracle;  // the fallback's own oracle, if it ran

  // Stage 2: the nested bracketed search.
  const auto bracket_started = std::chrono::steady_clock::now();
  const long before_bracket = oracle.evaluations();
  const ModulusSearch search(oracle, options);
  const std::optional<ModulusChoice> bracketed = BracketThinnest(search, options, upper_bracket);
  out.continuous.bracket = BracketReport(bracketed.has_value(), oracle.evaluations() - before_bracket,
                                         SecondsSince(bracket_started));

  if (bracketed) {
    DesignScore best = bracketed->score;
    out.continuous.source = "bracket";
    if (options.local_polish) PolishWithIpopt(problem, oracle, options, best, out.continuous);
    out.continuous.score = best;
    out.continuous.feasible = true;
  } else {
    // Nothing is admissible within the box: report the least-injury design at the maximum
    // thickness instead (problem b there), marked infeasible.
    const LeastInjuryAtThickness fallback =
        MinimizeInjuryAtThickness(scene, options.space.max_thickness_m, {}, options);
    out.continuous.score = fallback.continuous.score;
    out.continuous.local = fallback.continuous.local;
    out.continuous.feasible = false;
    out.continuous.source = "none admissible in the box: least injury at the maximum thickness (" +
                            fallback.continuous.source + ")";
    out.evaluations += fallback.evaluations;
    fallback_oracle = fallback.oracle;
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
  out.oracle = oracle.Report();
  if (fallback_oracle) {
    out.oracle.evaluations += fallback_oracle->evaluations;
    out.oracle.gradient_evaluations += fallback_oracle->gradient_evaluations;
    out.oracle.failed_evaluations += fallback_oracle->failed_evaluations;
    if (out.oracle.first_failure.empty()) out.oracle.first_failure = fallback_oracle->first_failure;
    out.oracle.gradient_step_disagreement =
        std::max(out.oracle.gradient_step_disagreement, fallback_oracle->gradient_step_disagreement);
  }
  out.seconds = SecondsSince(started);
  return out;
}

LeastInjuryAtThickness MinimizeInjuryAtThickness(const Scene& scene, double thickness_m,
                                                 std::span<const CandidateMaterial> materials,
                                                 const DesignOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  ValidateOptions(options);
  ValidateCandidates(materials, options.covering_law);
  Require(std::isfinite(thickness_m) && thickness_m > 0.0 && thickness_m <= 1.0,
          "thickness must be in (0, 1] m (got " + Number(thickness_m) + ")");
  const std::unique_ptr<DesignOracle> owned_oracle =
      MakeOracle(scene, options.covering_poisson_ratio, options.limits, options.oracle);
  const DesignOracle& oracle = *owned_oracle;
  const double sf = options.safety_factor;
  const DesignCriterion criterion = options.criterion();
  LeastInjuryAtThickness out;
  out.criterion = criterion;
  out.thickness_m = thickness_m;
  out.bare_robot = oracle.ScoreBare();

  // The nested search's 1-D stage: the admissible moduli [u_c, max] and the best among them.
  const auto bracket_started = std::chrono::steady_clock::now();
  const ModulusSearch search(oracle, options);
  const ModulusChoice choice = search.Best(thickness_m);
  DesignScore best = choice.score;
  double lower = choice.lowest_admissible_log_modulus;
  if (!choice.admissible_modulus_exists) {
    // Every modulus bottoms out: the least injury regardless, said so.
    out.continuous.every_modulus_fully_compressed = true;
    lower = std::log10(options.space.min_modulus_Pa);
    best = search.MinimizeWorst(thickness_m, lower, std::log10(options.space.max_modulus_Pa));
  }
  out.continuous.bracket = BracketReport(true, oracle.evaluations(), SecondsSince(bracket_started));
  out.continuous.source = "bracket";
  // A point from another stage must stay on the same side of the compression boundary.
  auto compression_ok = [&](const DesignScore& score) {
    return criterion == DesignCriterion::kPaper || out.continuous.every_modulus_fully_compressed ||
           !score.compression_exceeded(sf);
  };

  // NLopt's global search on the same interval; its point is kept only if it is better.
  const WorstRatioProblem global_problem(oracle, options, thickness_m, lower);
  NloptOptions global_options = GlobalOptions(options);
  global_options.max_evaluations = std::min<long>(options.global_evaluations, 400);  // 1-D
  const std::vector<double> start{std::log10(best.design.youngs_modulus_Pa)};
  const SolveResult global = SolveWithNlopt(global_problem, start, global_options);
  out.continuous.global = global.report;
  if (global.is_usable()) {
    const DesignScore at_global = oracle.Score({std::pow(10.0, global.x[0]), thickness_m});
    if (compression_ok(at_global) && at_global.worst_ratio() < best.worst_ratio()) {
      best = at_global;
      out.continuous.source = "global";
    }
  }
  if (options.local_polish) {
    const EpigraphProblem epigraph(oracle, options, thickness_m, lower);
    const double u = std::log10(best.design.youngs_modulus_Pa);
    const SolveResult local =
        SolveWithIpopt(epigraph, std::vector<double>{u, std::log(sf * best.worst_ratio()) + 1e-3}, options.ipopt);
    out.continuous.local = local.report;
    bool kept = false;
    if (local.is_usable()) {
      const DesignScore polished = oracle.Score({std::pow(10.0, local.x[0]), thickness_m});
      if (compression_ok(polished) && polished.worst_ratio() < best.worst_ratio()) {
        best = polished;
        kept = true;
        out.continuous.source = "ipopt";
      }
    }
    if (!kept) out.continuous.source += " (ipopt ended " + Ended(local.report) + "; its point was not better)";
  }
  out.continuous.score = best;
  out.continuous.feasible = best.admissible(sf, criterion);

  const DesignRule rule = options.rule();
  for (const CandidateMaterial& material : materials) {
    CandidateOutcome outcome;
    outcome.material = material;
    outcome.score = oracle.ScoreCovering(CoveringOf(material, thickness_m, options.covering_law));
    CheckCrush(material, outcome.score);
    outcome.safe = outcome.score.admissible(rule);
    outcome.margin = outcome.score.margin(rule);
    if (outcome.safe) outcome.recommended_thickness_m = thickness_m;
    out.candidates.push_back(outcome);
  }
  std::stable_sort(out.candidates.begin(), out.candidates.end(),
                   [](const CandidateOutcome& a, const CandidateOutcome& b) {
                     if (a.safe != b.safe) return a.safe;
                     if (a.margin != b.margin) return a.margin > b.margin;
                     return a.material.name < b.material.name;
                   });
  if (!out.candidates.empty() && out.candidates.front().safe) {
    out.verdict = DesignVerdict::kCoveringFound;
    out.recommendation = 0;
  } else {
    out.verdict = out.continuous.feasible ? DesignVerdict::kNoSafeMaterial : DesignVerdict::kNothingSafe;
  }
  out.evaluations = oracle.evaluations();
  out.oracle = oracle.Report();
  out.seconds = SecondsSince(started);
  return out;
}

}  // namespace covopt::optim
