// The thinnest covering admissible for every value of an uncertainty box
// (optim/robust_design.hpp, FindRobustThinnestCovering): scenario generation around
// FindThinnestSafeCovering's scan-then-bisect (per material) and nested search (continuous).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/core/number_format.hpp>
#include <covopt/core/parallel_for.hpp>

#include "covopt/optim/robust_design.hpp"
#include "robust_internal.hpp"

namespace covopt::optim {
namespace internal {

void ValidateDesign(const DesignOptions& o) {
  ValidateDesignSpace(o.space);
  Require(o.covering_poisson_ratio > -1.0 && o.covering_poisson_ratio <= 0.5,
          "covering poisson ratio must be in (-1, 0.5] (got " + Number(o.covering_poisson_ratio) + ")");
  Require(o.thickness_scan_points >= 10 && o.thickness_scan_points <= 1000000,
          "thickness scan points must be in [10, 1e6] (got " + std::to_string(o.thickness_scan_points) + ")");
  Require(o.bracket_thickness_points >= 4 && o.bracket_thickness_points <= 100000,
          "bracket thickness points must be in [4, 100000] (got " + std::to_string(o.bracket_thickness_points) + ")");
  Require(o.modulus_points_per_decade >= 2 && o.modulus_points_per_decade <= 10000,
          "modulus points per decade must be in [2, 10000] (got " + std::to_string(o.modulus_points_per_decade) + ")");
  Require(std::isfinite(o.thickness_resolution_m) && o.thickness_resolution_m > 0,
          "thickness resolution must be > 0 m (got " + Number(o.thickness_resolution_m) + ")");
  Require(o.threads >= 1 && o.threads <= 256, "threads must be in [1, 256] (got " + std::to_string(o.threads) + ")");
  Require(std::isfinite(o.thickness_step_m) && o.thickness_step_m >= 0,
          "thickness step must be >= 0 m (got " + Number(o.thickness_step_m) + ")");
  ValidateCriterion({o.criterion(), o.safety_factor, o.limits});
}

void RefuseCoveringRanges(const UncertaintyBox& box) {
  const std::string why = "the design chooses the covering; its fields cannot be uncertain here";
  RefuseRange(box, "covering-modulus", why);
  RefuseRange(box, "covering-poisson", why);
  RefuseRange(box, "covering-thickness", why);
}

double StockThickness(double steps, double step_m) {
  return std::strtod(FormatSignificant(steps * step_m, 12).c_str(), nullptr);
}

double ScanThickness(const DesignSpace& space, int points, int k) {
  return k == points - 1 ? space.max_thickness_m
                         : space.min_thickness_m + (space.max_thickness_m - space.min_thickness_m) * k / (points - 1);
}

std::vector<double> BracketGrid(const DesignOptions& o, std::optional<double> extra_thickness_m) {
  const DesignSpace& space = o.space;
  std::vector<double> grid;
  const int linear = std::max(2, o.bracket_thickness_points / 2);
  const int geometric = std::max(2, o.bracket_thickness_points - linear);
  for (int i = 0; i < linear; ++i) {
    grid.push_back(space.min_thickness_m + (space.max_thickness_m - space.min_thickness_m) * i / (linear - 1));
  }
  for (int i = 0; i < geometric; ++i) {
    grid.push_back(space.min_thickness_m *
                   std::pow(space.max_thickness_m / space.min_thickness_m, static_cast<double>(i) / (geometric - 1)));
  }
  grid.front() = space.min_thickness_m;
  grid.back() = space.max_thickness_m;
  if (extra_thickness_m) grid.push_back(*extra_thickness_m);
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  grid.back() = std::min(grid.back(), space.max_thickness_m);
  return grid;
}

}  // namespace internal

namespace {

using internal::ImpactCriterion;
using internal::Judged;

constexpr double kThicknessTolerance_m = 1e-9;  ///< the continuous optimum's bisection
constexpr double kLogModulusTolerance = 1e-10;  ///< golden sections in log10 E_c
/// The same for a braking robot, whose impacts the time path answers to its tolerance (about
/// 1e-8 relative): finer steps would resolve integration noise, at 0.1-0.2 ms a run.
constexpr double kBrakingLogModulusTolerance = 1e-6;

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// A finite set of input values ("scenarios") a design is judged against: g over the set is
/// the largest g of its scenes, admissible when every scene is.
class ScenarioSet {
 public:
  ScenarioSet(const UncertaintyBox& box, const ImpactCriterion& criterion) : box_(box), criterion_(criterion) {}

  void Add(const std::vector<double>& values) {
    for (const std::vector<double>& known : values_) {
      if (known == values) return;
    }
    values_.push_back(values);
    scenes_.push_back(box_.SceneAt(values));
  }
  const std::vector<std::vector<double>>& values() const { return values_; }

  struct Verdict {
    double governing = 0.0;  ///< max over the set
    bool admissible = true;
  };
  Verdict Judge(const CoveringSpec& covering) const {
    Verdict v;
    for (const Scene& base : scenes_) {
      Scene scene = base;
      scene.covering = covering;
      ++evaluations_;
      // Only admissibility and the largest g matter: a braking robot's impact that is admissible
      // unbraked is admissible (docs/model.md §11), and its bound stands for it.
      internal::Screening screening;
      screening.when_admissible = true;
      const Judged j = internal::JudgeScene(scene, criterion_, screening);
      v.governing = std::max(v.governing, j.governing_ratio);
      v.admissible = v.admissible && j.admissible;
    }
    return v;
  }
  /// Whether every scene is admissible: stops at the first that is not, and tries that one
  /// first next time (the answer is Judge(covering).admissible, with fewer impacts).
  bool Admissible(const CoveringSpec& covering) const {
    for (std::size_t k = 0; k < scenes_.size(); ++k) {
      const std::size_t i = (first_ + k) % scenes_.size();
      Scene scene = scenes_[i];
      scene.covering = covering;
      ++evaluations_;
      internal::Screening screening;
      screening.when_admissible = true;
      if (!internal::JudgeScene(scene, criterion_, screening).admissible) {
        first_ = i;
        return false;
      }
    }
    return true;
  }
  long evaluations() const { return evaluations_; }

 private:
  mutable std::size_t first_ = 0;
  const UncertaintyBox& box_;
  ImpactCriterion criterion_;
  std::vector<std::vector<double>> values_;
  std::vector<Scene> scenes_;
  mutable long evaluations_ = 0;
};

/// What one robust search shares: the box, the criterion, the options.
struct RobustContext {
  const UncertaintyBox& box;
  ImpactCriterion criterion;
  const RobustDesignOptions& options;

  /// The worst case of the whole box for one covering, judged by `judged_by` (default: the
  /// context's criterion).
  WorstCase WorstCaseFor(const CoveringSpec& covering, const ImpactCriterion* judged_by = nullptr) const {
    Scene base = box.nominal();
    base.covering = covering;
    return internal::WorstCaseOnScene(box, base, judged_by ? *judged_by : criterion, options.worst_case);
  }
  /// The criterion for one material: the context's, with its strength when it crushes.
  ImpactCriterion ForMaterial(const CandidateMaterial& material) const {
    ImpactCriterion c = criterion;
    if (material.crush_behaviour == materials::CrushBehaviour::kCrushes) {
      c.compressive_strength_Pa = material.compressive_strength_Pa;
      c.crush_counts = !options.design.allow_crushing;
    }
    return c;
  }
};

/// The DesignScore of a material's worst case (the impact there, on the time path for a
/// braking robot), with its crush check.
DesignScore ScoreOf(const WorstCase& worst, const CandidateMaterial& material, const ImpactCriterion& criterion) {
  DesignScore score;
  score.design = {worst.scene.covering.youngs_modulus_Pa, worst.scene.covering.thickness_m};
  score.poisson_ratio = worst.scene.covering.poisson_ratio;
  const Judged judged = internal::JudgeScene(worst.scene, criterion);
  score.peaks = judged.peaks;
  score.failed = judged.failed;
  if (judged.failed) score.peaks.fully_compressed = true;  // as the oracle marks a failed design
  score.laceration_ratio = worst.laceration_ratio;
  score.contusion_ratio = worst.contusion_ratio;
  score.fracture_ratio = worst.fracture_ratio;
  score.compression_ratio = worst.compression_ratio;
  score.validity = judged.validity;
  CheckCrush(material, score);
  return score;
}

/// One material's robust search: its criterion, the scenario set (grown by every violation
/// found) and the impacts its searches of the whole box cost.
class MaterialSearch {
 public:
  MaterialSearch(const RobustContext& context, const CandidateMaterial& material,
                 const std::vector<std::vector<double>>& initial)
      : context_(context), material_(material), criterion_(context.ForMaterial(material)), set_(context.box, criterion_) {
    for (const std::vector<double>& s : initial) set_.Add(s);
  }

  const ImpactCriterion& criterion() const { return criterion_; }
  /// The impacts judged so far: the scenario set's and the box searches'.
  long evaluations() const { return set_.evaluations() + search_evaluations_; }

  /// The thinnest thickness admissible for the whole box and its worst case there: the thinnest
  /// for the scenario set (scan, bisection) confirmed over the box, the set grown by every
  /// violation found; none when no thickness is admissible for the set, or none was confirmed
  /// within the rounds allowed (counted in `rounds`).
  std::optional<std::pair<double, WorstCase>> Thinnest(int& rounds) {
    const DesignOptions& o = context_.options.design;
    const DesignSpace& space = o.space;
    // Scan points below the first admissible one of a round stay inadmissible for the grown set:
    // the next round's scan starts there.
    int first_scan = 0;
    while (rounds < context_.options.max_scenario_rounds) {
      ++rounds;
      double inadmissible = first_scan > 0 ? internal::ScanThickness(space, o.thickness_scan_points, first_scan - 1) : 0.0;
      double admissible = 0.0;
      bool found = false;
      for (int k = first_scan; k < o.thickness_scan_points && !found; ++k) {
        const double b = internal::ScanThickness(space, o.thickness_scan_points, k);
        if (AdmissibleOnSet(b)) {
          found = true;
          admissible = b;
          first_scan = k;
        } else {
          inadmissible = b;
        }
      }
      if (!found) break;  // inadmissible for the set, hence for the box
      if (inadmissible > 0.0) {
        while (admissible - inadmissible > o.thickness_resolution_m) {
          const double mid = 0.5 * (inadmissible + admissible);
          (AdmissibleOnSet(mid) ? admissible : inadmissible) = mid;
        }
      }
      WorstCase worst = Confirm(admissible);
      if (worst.admissible) return std::pair{admissible, std::move(worst)};
      set_.Add(worst.values);
    }
    return std::nullopt;
  }

  /// The first stock thickness (a multiple of the step) from `thinnest` up admissible for the
  /// whole box, and its worst case; none beyond the maximum thickness (set in `outcome`).
  std::optional<WorstCase> AtStock(double thinnest, CandidateOutcome& outcome) {
    const DesignOptions& o = context_.options.design;
    double steps = std::ceil(thinnest / o.thickness_step_m - 1e-9);
    for (double stock = internal::StockThickness(steps, o.thickness_step_m);;
         stock = internal::StockThickness(++steps, o.thickness_step_m)) {
      if (stock > o.space.max_thickness_m * (1 + 1e-12)) {
        outcome.stock_thickness_beyond_max_m = stock;
        return std::nullopt;
      }
      if (!AdmissibleOnSet(stock)) continue;
      WorstCase worst = Confirm(stock);
      if (worst.admissible) return worst;
      set_.Add(worst.values);
    }
  }

  /// The worst case at the maximum thickness of a material that has no robust design, for the
  /// table. With a braking robot (the time path) a scenario of the set that is inadmissible
  /// there already shows the verdict, and the worst of the set is reported (found by
  /// "scenarios") instead of searching the whole box again; without braking, or when every
  /// scenario is admissible there, the box is searched.
  WorstCase WorstAtMax() {
    const double b = context_.options.design.space.max_thickness_m;
    if (context_.box.brakes()) {
      Scene base = context_.box.nominal();
      base.covering = Covering(b);
      WorstCase worst;
      for (const std::vector<double>& values : set_.values()) {
        Scene scene = base;
        internal::ApplyInputs(context_.box, values, scene);
        const Judged j = internal::JudgeScene(scene, criterion_);
        ++worst.evaluations;
        if (worst.values.empty() || j.governing_ratio > worst.governing_ratio) {
          worst.values = values;
          worst.scene = scene;
          internal::FillWorstCase(j, worst);
        }
      }
      if (!worst.values.empty() && !worst.admissible) {
        worst.found_by = "scenarios";
        search_evaluations_ += worst.evaluations;
        return worst;
      }
    }
    return Confirm(b);
  }

 private:
  CoveringSpec Covering(double b) const { return CoveringOf(material_, b, context_.options.design.covering_law); }
  bool AdmissibleOnSet(double b) const { return set_.Admissible(Covering(b)); }
  /// The worst case of the whole box at thickness `b`.
  WorstCase Confirm(double b) {
    WorstCase worst = context_.WorstCaseFor(Covering(b), &criterion_);
    search_evaluations_ += worst.evaluations;
    return worst;
  }

  const RobustContext& context_;
  const CandidateMaterial& material_;
  ImpactCriterion criterion_;
  ScenarioSet set_;
  long search_evaluations_ = 0;
};

/// One material: the thinnest thickness admissible for the whole box (MaterialSearch::Thinnest),
/// then the stock step; a material with none, or that the rule refuses, scored at its worst
/// case at the maximum thickness.
RobustCandidate RobustSnapMaterial(const RobustContext& context, const CandidateMaterial& material,
                                   const std::vector<std::vector<double>>& initial, long& evaluations) {
  const DesignOptions& o = context.options.design;
  MaterialSearch search(context, material, initial);
  RobustCandidate candidate;
  candidate.outcome.material = material;
  CandidateOutcome& outcome = candidate.outcome;
  const DesignRule rule = o.rule();
  const auto score_at_max = [&] {
    candidate.worst_case = search.WorstAtMax();
    outcome.score = ScoreOf(candidate.worst_case, material, search.criterion());
    outcome.margin = outcome.score.margin(rule);
    evaluations += search.evaluations();
    return candidate;
  };
  if (material.crush_behaviour == materials::CrushBehaviour::kUnknown && rule.refuses_unknown_strength()) {
    return score_at_max();  // never admissible under the rule
  }
  std::optional<std::pair<double, WorstCase>> thinnest = search.Thinnest(candidate.scenario_rounds);
  if (!thinnest) {
    candidate.unconfirmed = candidate.scenario_rounds >= context.options.max_scenario_rounds;
    return score_at_max();
  }
  outcome.min_safe_thickness_m = thinnest->first;
  std::optional<WorstCase> at_stock;
  if (o.thickness_step_m > 0.0) at_stock = search.AtStock(thinnest->first, outcome);
  candidate.worst_case = at_stock ? *at_stock : thinnest->second;
  candidate.worst_case_at_thinnest = std::move(thinnest->second);
  outcome.score = ScoreOf(candidate.worst_case, material, search.criterion());
  outcome.recommended_thickness_m = candidate.worst_case.scene.covering.thickness_m;
  // The box's verdict, and the rule's word on a material of unknown strength.
  outcome.safe = candidate.worst_case.admissible && outcome.score.admissible(rule);
  outcome.margin = outcome.score.margin(rule);
  evaluations += search.evaluations();
  return candidate;
}

/// The nested search against a scenario set: at a thickness, the modulus of least g over the
/// set (scan in log10 E_c, golden sections of the best local minima).
class RobustModulusSearch {
 public:
  RobustModulusSearch(const ScenarioSet& set, const DesignOptions& o, bool brakes)
      : set_(set),
        o_(o),
        lo_(std::log10(o.space.min_modulus_Pa)),
        hi_(std::log10(o.space.max_modulus_Pa)),
        tolerance_(brakes ? kBrakingLogModulusTolerance : kLogModulusTolerance) {}

  struct Choice {
    double log_modulus = 0.0;
    double governing = 0.0;
    bool admissible = false;
  };

  Choice Best(double b, bool screen) const {
    const int n = std::max(9, static_cast<int>(std::ceil(o_.modulus_points_per_decade * (hi_ - lo_))) + 1);
    std::vector<Choice> samples;
    samples.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) samples.push_back(At(Grid(n, i), b));
    std::size_t best = 0;
    for (std::size_t i = 1; i < samples.size(); ++i) {
      if (samples[i].governing < samples[best].governing) best = i;
    }
    Choice result = samples[best];
    if (screen && result.governing > 3.0) return result;
    std::vector<std::size_t> minima;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const double g = samples[i].governing;
      const bool left = i == 0 || g <= samples[i - 1].governing;
      const bool right = i + 1 == samples.size() || g <= samples[i + 1].governing;
      if (left && right && g <= 1.05 * samples[best].governing) minima.push_back(i);
    }
    std::stable_sort(minima.begin(), minima.end(),
                     [&](std::size_t x, std::size_t y) { return samples[x].governing < samples[y].governing; });
    if (minima.size() > 3) minima.resize(3);
    for (std::size_t i : minima) {
      const double left = Grid(n, i == 0 ? 0 : static_cast<int>(i) - 1);
      const double right = Grid(n, std::min(n - 1, static_cast<int>(i) + 1));
      const Choice refined = Golden(b, left, right);
      if (refined.governing < result.governing || (refined.admissible && !result.admissible)) result = refined;
    }
    return result;
  }

 private:
  double Grid(int n, int i) const { return i == n - 1 ? hi_ : lo_ + (hi_ - lo_) * i / (n - 1); }
  Choice At(double u, double b) const {
    const ScenarioSet::Verdict v = set_.Judge({std::pow(10.0, u), o_.covering_poisson_ratio, b});
    return {u, v.governing, v.admissible};
  }
  Choice Golden(double b, double a, double c) const {
    return internal::GoldenSection([&](double u) { return At(u, b); }, [](const Choice& s) { return s.governing; },
                                   a, c, tolerance_);
  }

  const ScenarioSet& set_;
  const DesignOptions& o_;
  double lo_, hi_;
  double tolerance_;
};

RobustContinuousOptimum RobustContinuous(const RobustContext& context,
                                         const std::vector<std::vector<double>>& initial, long& evaluations) {
  const DesignOptions& o = context.options.design;
  ScenarioSet set(context.box, context.criterion);
  for (const std::vector<double>& s : initial) set.Add(s);
  const bool brakes = context.box.brakes();
  const RobustModulusSearch search(set, o, brakes);
  // A braking robot: the bisection stops at the catalog snap's resolution (the time path's
  // noise is far above 1e-9 m).
  const double thickness_tolerance_m = brakes ? o.thickness_resolution_m : kThicknessTolerance_m;
  const std::vector<double> grid = internal::BracketGrid(o);
  RobustContinuousOptimum out;
  long search_evaluations = 0;
  auto design_of = [&](const RobustModulusSearch::Choice& choice, double b) {
    return CoveringDesign{std::pow(10.0, choice.log_modulus), b};
  };
  auto confirm = [&](const CoveringDesign& d) {
    WorstCase worst = context.WorstCaseFor({d.youngs_modulus_Pa, o.covering_poisson_ratio, d.thickness_m});
    search_evaluations += worst.evaluations;
    return worst;
  };
  bool confirmed = false;
  while (out.scenario_rounds < context.options.max_scenario_rounds) {
    ++out.scenario_rounds;
    std::optional<std::size_t> first;
    RobustModulusSearch::Choice choice;
    for (std::size_t k = 0; k < grid.size(); ++k) {
      choice = search.Best(grid[k], /*screen=*/true);
      if (choice.admissible) {
        first = k;
        break;
      }
    }
    if (!first) break;  // nothing admissible for the set, hence for the box
    double b = grid[*first];
    if (*first > 0) {
      double inadmissible = grid[*first - 1];
      while (b - inadmissible > thickness_tolerance_m) {
        const double mid = 0.5 * (inadmissible + b);
        const RobustModulusSearch::Choice at_mid = search.Best(mid, false);
        if (at_mid.admissible) {
          b = mid;
          choice = at_mid;
        } else {
          inadmissible = mid;
        }
      }
    }
    out.design = design_of(choice, b);
    out.worst_case = confirm(out.design);
    if (out.worst_case.admissible) {
      confirmed = true;
      break;
    }
    set.Add(out.worst_case.values);
  }
  if (confirmed) {
    out.feasible = true;
  } else {
    out.unconfirmed = out.scenario_rounds >= context.options.max_scenario_rounds;
    // The least-g modulus for the set at the maximum thickness, and the box's worst case there.
    const RobustModulusSearch::Choice at_max = search.Best(o.space.max_thickness_m, false);
    out.design = design_of(at_max, o.space.max_thickness_m);
    out.worst_case = confirm(out.design);
  }
  evaluations += set.evaluations() + search_evaluations;
  return out;
}

}  // namespace

std::optional<InjuryProbability> EstimateRecommendationInjuryProbability(const UncertaintyBox& box,
                                                                         const RobustThinnestCovering& result,
                                                                         const RobustDesignOptions& options,
                                                                         InjuryProbabilityOptions sampling) {
  if (!result.recommendation) return std::nullopt;
  const CandidateOutcome& c = result.candidates[*result.recommendation].outcome;
  Scene designed = box.nominal();
  designed.covering = CoveringOf(c.material, *c.recommended_thickness_m, options.design.covering_law);
  const UncertaintyBox at_design = UncertaintyBox::FromScene(designed, box.inputs());
  sampling.safety_factor = options.design.safety_factor;
  sampling.limits = options.design.limits;
  sampling.allow_full_compression = options.design.allow_full_compression;
  return EstimateInjuryProbability(at_design, sampling);
}

RobustThinnestCovering FindRobustThinnestCovering(const UncertaintyBox& box,
                                                  std::span<const CandidateMaterial> materials,
                                                  const RobustDesignOptions& options) {
  const auto started = std::chrono::steady_clock::now();
  const DesignOptions& o = options.design;
  internal::ValidateDesign(o);
  internal::ValidateSearch(options.worst_case);
  internal::Require(options.max_scenario_rounds >= 1 && options.max_scenario_rounds <= 1000,
                    "max scenario rounds must be in [1, 1000] (got " + std::to_string(options.max_scenario_rounds) + ")");
  internal::RefuseCoveringRanges(box);
  for (const CandidateMaterial& m : materials) {
    internal::Require(std::isfinite(m.youngs_modulus_Pa) && m.youngs_modulus_Pa > 0.0 && m.youngs_modulus_Pa <= 1e13,
                      "material '" + m.name + "': modulus must be in (0, 1e13] Pa (got " +
                          internal::Number(m.youngs_modulus_Pa) + ")");
    internal::Require(m.poisson_ratio > -1.0 && m.poisson_ratio <= 0.5,
                      "material '" + m.name + "': poisson ratio must be in (-1, 0.5] (got " +
                          internal::Number(m.poisson_ratio) + ")");
  }
  internal::TimePathCounter counter;
  ImpactCriterion criterion{o.criterion(), o.safety_factor, o.limits};
  criterion.time_path = o.oracle.time_path;
  criterion.counter = &counter;
  if (box.brakes()) ValidateTimeIntegrationOptions(o.oracle.time_path, "oracle.time_path.");
  const RobustContext context{box, criterion, options};
  RobustThinnestCovering out;
  out.criterion = o.criterion();
  long evaluations = 0;

  Scene bare = box.nominal();
  bare.covering.thickness_m = 0.0;
  out.bare_robot = internal::WorstCaseOnScene(box, bare, criterion, options.worst_case);
  evaluations += out.bare_robot.evaluations;

  // The initial scenarios: the centre, and the worst case at the nominal scene's covering.
  out.initial_scenarios.push_back(box.Centre());
  {
    const WorstCase nominal = internal::WorstCaseOnScene(box, box.nominal(), criterion, options.worst_case);
    evaluations += nominal.evaluations;
    if (nominal.values != out.initial_scenarios.front()) out.initial_scenarios.push_back(nominal.values);
  }

  if (options.continuous) out.continuous = RobustContinuous(context, out.initial_scenarios, evaluations);

  // Materials, each from the same initial scenarios: results independent of the thread count.
  std::vector<RobustCandidate> candidates(materials.size());
  std::vector<long> material_evaluations(materials.size(), 0);
  ParallelFor(materials.size(), static_cast<unsigned>(o.threads), [&](std::size_t i, unsigned) {
    candidates[i] = RobustSnapMaterial(context, materials[i], out.initial_scenarios, material_evaluations[i]);
  });
  for (long e : material_evaluations) evaluations += e;
  std::stable_sort(candidates.begin(), candidates.end(), [](const RobustCandidate& x, const RobustCandidate& y) {
    const CandidateOutcome& a = x.outcome;
    const CandidateOutcome& b = y.outcome;
    if (a.safe != b.safe) return a.safe;
    if (a.safe && *a.recommended_thickness_m != *b.recommended_thickness_m) {
      return *a.recommended_thickness_m < *b.recommended_thickness_m;
    }
    if (a.margin != b.margin) return a.margin > b.margin;
    return a.material.name < b.material.name;
  });
  out.candidates = std::move(candidates);
  const bool any_safe = !out.candidates.empty() && out.candidates.front().outcome.safe;
  out.verdict = internal::RobustVerdict(out.bare_robot.admissible, any_safe,
                                        out.continuous && !out.continuous->feasible);
  if (out.verdict == DesignVerdict::kCoveringFound) out.recommendation = 0;
  out.evaluations = evaluations;
  out.time_path = counter.Use();
  out.seconds = SecondsSince(started);
  return out;
}

}  // namespace covopt::optim
