#include "covopt/report/design_text.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/core/verdict.hpp"
#include "covopt/optim/summaries.hpp"
#include "covopt/report/design_answer_text.hpp"
#include "covopt/report/robust_text.hpp"
#include "covopt/report/scene_headline.hpp"
#include "covopt/report/summary_json.hpp"

namespace covopt::report {
namespace {

using optim::CandidateOutcome;
using optim::DesignScore;

std::string Mm(double metres) { return fmt::format("{:.2f} mm", metres * 1e3); }
std::string MPa(double pascals) { return fmt::format("{:.3g} MPa", pascals * 1e-6); }

/// The crush column of a candidate: its ratio, "no crush" or "unknown".
std::string CrushCell(const DesignScore& s) {
  switch (s.crush_check) {
    case optim::CrushCheck::kChecked: return fmt::format("{:.3f}", s.crush_ratio);
    case optim::CrushCheck::kDoesNotCrush: return "no crush";
    case optim::CrushCheck::kUnknownStrength: return "unknown";
    case optim::CrushCheck::kNoMaterial: break;
  }
  return "-";
}

/// Prints the first `rows` candidates (none for 0) and the ν footnote when a shown row needs it.
void PrintCandidates(std::ostream& out, const std::vector<CandidateOutcome>& candidates, int rows,
                     bool fixed_thickness, const optim::DesignRule& rule) {
  const int shown = std::min<int>(rows, static_cast<int>(candidates.size()));
  if (shown > 0) {
    fmt::print(out, "  {:<3} {:<28} {:>9} {:>6} {:>5} {:>10} {:>7} {:>7} {:>7} {:>8} {:>8}  {}\n", "#", "material",
               "E [MPa]", "ν", "law", "thickness", "lacer.", "contus.", "compr.", "crush", "margin", "governs");
  }
  bool assumed_shown = false;
  for (int i = 0; i < shown; ++i) {
    const CandidateOutcome& c = candidates[static_cast<std::size_t>(i)];
    // Problem (b) evaluates every material at the given thickness; problem (a) shows the
    // thinnest admissible one, or "> max" when none is admissible within the bound.
    const std::string thickness = c.recommended_thickness_m || fixed_thickness
                                      ? Mm(c.score.design.thickness_m)
                                      : fmt::format("> {}", Mm(c.score.design.thickness_m));
    const bool unknown_refused =
        c.score.crush_check == optim::CrushCheck::kUnknownStrength && rule.refuses_unknown_strength();
    const CoveringLaw law = c.score.peaks.covering_law;
    fmt::print(out, "  {:<3} {:<28} {:>9.4g} {:>6} {:>5} {:>10} {:>7.3f} {:>7.3f} {:>7.3f} {:>8} {:>8}  {}{}{}\n", i + 1,
               c.material.name.substr(0, 28), c.material.youngs_modulus_Pa * 1e-6,
               fmt::format("{:.2f}{}", c.material.poisson_ratio, c.material.poisson_assumed ? "*" : ""),
               ToString(law), thickness, c.score.laceration_ratio, c.score.contusion_ratio, c.score.compression_ratio,
               CrushCell(c.score), FormatPercent(c.margin), optim::ToString(c.score.governing(rule).criterion, law),
               unknown_refused                  ? "; strength unknown, not recommended"
               : c.score.peaks.fully_compressed ? (law == CoveringLaw::kFoam ? "; used up" : "; fully compressed")
                                                : "",
               c.score.validity.within ? "" : "; out of its law's validity");
    assumed_shown = assumed_shown || c.material.poisson_assumed;
  }
  if (static_cast<int>(candidates.size()) > shown) {
    fmt::print(out, "  ... {} {} (--top N, or --json for all)\n", candidates.size() - shown,
               shown > 0 ? "more" : "candidates");
  }
  if (assumed_shown) fmt::print(out, "  * ν unknown for this material: 0.25 assumed\n");
}

/// How the Ipopt polish's gradients were computed, for the Oracle line.
std::string_view GradientWords(optim::GradientSource source) {
  switch (source) {
    case optim::GradientSource::kAnalytic: return "analytic";
    case optim::GradientSource::kForwardSensitivities: return "CVODES forward-sensitivity";
    case optim::GradientSource::kCentralDifference: return "central-difference";
  }
  return "unknown";
}

/// "the covering uses 93 % of its travel at the peak" and the like. The travel is the
/// covering's own 0.8 b_c beyond the scalp's (ImpactPeaks::covering_compression_ratio).
std::string CompressionWords(const DesignScore& s) {
  if (s.bare()) return "";
  if (s.peaks.covering_law == CoveringLaw::kFoam) {
    if (s.peaks.fully_compressed) return "its measured curve used up at the peak (a rigid stop)";
    return fmt::format("{:.0f} % of its measured curve's strain used at the peak", 100.0 * s.compression_ratio);
  }
  if (s.peaks.fully_compressed) return "fully compressed at the peak";
  if (s.compression_ratio > 0.9995) return "at the edge of full compression at the peak";
  return fmt::format("{:.0f} % of the covering's travel used at the peak", 100.0 * s.compression_ratio);
}

/// "crush ratio 0.41 (σ_c,max 1.2 MPa, strength 3.0 MPa)", "does not crush", "strength unknown".
std::string CrushWords(const DesignScore& s, const CandidateOutcome& c) {
  switch (s.crush_check) {
    case optim::CrushCheck::kChecked:
      return fmt::format("crush ratio {:.3f} (peak compressive stress {}, compressive strength {})", s.crush_ratio,
                         MPa(s.peaks.max_compressive_stress_Pa), MPa(c.material.compressive_strength_Pa));
    case optim::CrushCheck::kDoesNotCrush:
      return fmt::format("does not crush (peak compressive stress {}; full compression is its limit)",
                         MPa(s.peaks.max_compressive_stress_Pa));
    case optim::CrushCheck::kUnknownStrength:
      return fmt::format("compressive strength unknown: unverified for crushing at {}",
                         MPa(s.peaks.max_compressive_stress_Pa));
    case optim::CrushCheck::kNoMaterial: break;
  }
  return "";
}

void PrintScope(std::ostream& out, const optim::DesignRule& rule) {
  fmt::print(out, "\nScope\n");
  for (const std::string& line : optim::HeadVerdictScope(rule)) fmt::print(out, "  {}\n", line);
}

}  // namespace

/// The report of FindProbabilityDesign (optimize --max-injury-probability).
void PrintProbabilityDesign(std::ostream& out, const DesignText& r, const optim::UncertaintyBox& box,
                            const optim::ProbabilityDesignOptions& options, const optim::ProbabilityDesign& result) {
  const optim::DesignRule rule = options.design.rule();
  const double max_probability = options.max_probability;
  fmt::print(out, "Scene      {} (nominal; the ranges below vary)\n", DesignedSceneHeadline(r.request.scene));
  fmt::print(out, "Design for a probability of failing the criterion <= {:g} over {} input{}, {} samples, seed {}\n",
             max_probability, box.size(), box.size() == 1 ? "" : "s", options.sampling.samples, options.sampling.seed);
  fmt::print(out, "Criterion  {}\n", rule.Describe());
  fmt::print(out, "Target     met when the upper end of the 95 % (Wilson) interval of P(inadmissible) is <= {:g}: at "
                  "most {} failing samples of {}\n",
             max_probability, result.allowed_failures, options.sampling.samples);
  for (const InputRange& range : r.ranges) fmt::print(out, "  {:<20} {}  (from {})\n", range.name, range.text, range.source);
  const auto line = [&](const optim::InjuryProbability& p) {
    return fmt::format("P(inadmissible) {:.6f} [{:.6f}, {:.6f}], P(laceration) {:.6f}, P(contusion) {:.6f}",
                       p.inadmissible.probability, p.inadmissible.ci95_low, p.inadmissible.ci95_high,
                       p.laceration.probability, p.contusion.probability);
  };
  fmt::print(out, "\nVerdict: {}\n", optim::ToString(result.verdict));
  if (result.recommendation) {
    const optim::ProbabilityCandidate& c = result.candidates[*result.recommendation];
    fmt::print(out, "Recommended: {} (E {}), {} (thinnest meeting the target {})\n", c.material.name,
               MPa(c.material.youngs_modulus_Pa), Mm(*c.recommended_thickness_m), Mm(*c.min_thickness_m));
    fmt::print(out, "  {}\n  the 95 % upper bound {:.6f} is <= the target {:g}\n", line(c.at_design),
               c.at_design.inadmissible.ci95_high, max_probability);
  }
  if (result.continuous) {
    fmt::print(out, "Continuous optimum: {}: E_c {}, b_c {}; {}\n",
               result.continuous->feasible ? "meets the target" : "misses the target",
               MPa(result.continuous->design.youngs_modulus_Pa), Mm(result.continuous->design.thickness_m),
               line(result.continuous->at_design));
  }
  fmt::print(out, "Bare robot: {}\n", line(result.bare_robot));
  fmt::print(out, "\nCandidates:\n  {:<3} {:<28} {:>9} {:>10} {:>14}  {}\n", "#", "material", "E [MPa]", "thickness",
             "P(inadmiss.)", "95 % interval");
  const int shown = std::min<int>(r.runners_up, static_cast<int>(result.candidates.size()));
  for (int i = 0; i < shown; ++i) {
    const optim::ProbabilityCandidate& c = result.candidates[static_cast<std::size_t>(i)];
    fmt::print(out, "  {:<3} {:<28} {:>9.4g} {:>10} {:>14.6f}  [{:.6f}, {:.6f}]\n", i + 1,
               c.material.name.substr(0, 28), c.material.youngs_modulus_Pa * 1e-6,
               c.recommended_thickness_m ? Mm(*c.recommended_thickness_m) : "> max",
               c.at_design.inadmissible.probability, c.at_design.inadmissible.ci95_low,
               c.at_design.inadmissible.ci95_high);
  }
  fmt::print(out, "\nSearch: {} sampled impacts, {:.2f} s\n", result.sample_evaluations, result.seconds);
  PrintTimePathUse(out, box, result.time_path);
  PrintScope(out, rule);
  for (const std::string& w : r.warnings) fmt::print(out, "warning: {}\n", w);
}

namespace {

/// The candidate table of the robust design, each at its worst case over the box.
void PrintRobustCandidates(std::ostream& out, const DesignText& r, const optim::RobustThinnestCovering& result,
                           const optim::DesignRule& rule) {
  fmt::print(out,
             "\nCandidates (each at its worst case over the box):\n  {:<3} {:<28} {:>9} {:>5} {:>10} {:>7} {:>7} {:>7} "
             "{:>8} {:>8}  {:<16} {:>6}\n",
             "#", "material", "E [MPa]", "law", "thickness", "lacer.", "contus.", "compr.", "crush", "margin", "governs",
             "rounds");
  const int shown = std::min<int>(r.runners_up, static_cast<int>(result.candidates.size()));
  for (int i = 0; i < shown; ++i) {
    const optim::RobustCandidate& c = result.candidates[static_cast<std::size_t>(i)];
    const CoveringLaw law = c.outcome.score.peaks.covering_law;
    fmt::print(out, "  {:<3} {:<28} {:>9.4g} {:>5} {:>10} {:>7.3f} {:>7.3f} {:>7.3f} {:>8} {:>8}  {:<16} {:>6}{}{}\n",
               i + 1, c.outcome.material.name.substr(0, 28), c.outcome.material.youngs_modulus_Pa * 1e-6, ToString(law),
               c.outcome.recommended_thickness_m ? Mm(*c.outcome.recommended_thickness_m)
                                                 : fmt::format("> {}", Mm(c.outcome.score.design.thickness_m)),
               c.worst_case.laceration_ratio, c.worst_case.contusion_ratio, c.worst_case.compression_ratio,
               CrushCell(c.outcome.score), FormatPercent(c.outcome.margin),
               optim::ToString(c.outcome.score.governing(rule).criterion, law), c.scenario_rounds,
               c.unconfirmed ? "  unconfirmed" : "", c.outcome.score.validity.within ? "" : "  out of its law's validity");
  }
  if (static_cast<int>(result.candidates.size()) > shown) {
    fmt::print(out, "  ... {} more (--top N, or --json for all)\n", result.candidates.size() - static_cast<std::size_t>(shown));
  }
}


}  // namespace

/// The report of FindRobustThinnestCovering, with the recommendation's probability when sampled.
void PrintRobustDesign(std::ostream& out, const DesignText& r, const optim::UncertaintyBox& box,
                       const optim::RobustDesignOptions& options, const optim::RobustThinnestCovering& result,
                       const std::optional<optim::InjuryProbability>& probability) {
  const optim::DesignRule rule = options.design.rule();
  fmt::print(out, "Scene      {} (nominal; the ranges below vary)\n", DesignedSceneHeadline(r.request.scene));
  fmt::print(out, "Criterion  {}\n", rule.Describe());
  fmt::print(out, "Robust design over {} uncertain input{}:\n", box.size(), box.size() == 1 ? "" : "s");
  for (const InputRange& range : r.ranges) fmt::print(out, "  {:<20} {}  (from {})\n", range.name, range.text, range.source);
  fmt::print(out, "\nVerdict: {}\n", optim::ToString(result.verdict));
  if (result.recommendation) {
    const optim::RobustCandidate& c = result.candidates[*result.recommendation];
    fmt::print(out, "Recommended: {} (E {}, ν {:.2f}{}), {} — admissible for every value in the box (thinnest {})\n",
               c.outcome.material.name, MPa(c.outcome.material.youngs_modulus_Pa), c.outcome.material.poisson_ratio,
               c.outcome.material.poisson_assumed ? " assumed" : "", Mm(*c.outcome.recommended_thickness_m),
               Mm(*c.outcome.min_safe_thickness_m));
    if (c.worst_case_at_thinnest) {
      fmt::print(out, "  What sets the design, at {}:\n", Mm(*c.outcome.min_safe_thickness_m));
      PrintWorstCase(out, box, *c.worst_case_at_thinnest, "  ");
    }
    fmt::print(out, "  At {}:\n", Mm(*c.outcome.recommended_thickness_m));
    PrintWorstCase(out, box, c.worst_case, "  ");
  }
  if (result.continuous) {
    const optim::RobustContinuousOptimum& c = *result.continuous;
    fmt::print(out, "Continuous optimum: E_c {}, b_c {}{}\n", MPa(c.design.youngs_modulus_Pa), Mm(c.design.thickness_m),
               c.feasible ? "" : " (not admissible for the whole box within the search space)");
    PrintWorstCase(out, box, c.worst_case, "  ");
  }
  fmt::print(out, "Bare robot over the box:\n");
  PrintWorstCase(out, box, result.bare_robot, "  ");
  PrintRobustCandidates(out, r, result, rule);
  if (probability) {
    fmt::print(out, "\nThe recommendation over the box's distribution:\n");
    PrintInjuryProbability(out, *probability, "  ");
  }
  fmt::print(out, "\nSearch: {} {}evaluations, {:.1f} ms\n", result.evaluations, box.brakes() ? "" : "exact-path ",
             result.seconds * 1e3);
  PrintTimePathUse(out, box, result.time_path);
  PrintScope(out, rule);
  for (const std::string& w : r.warnings) fmt::print(out, "warning: {}\n", w);
}

namespace {

/// The recommendation of a deterministic design: its material, ratios, margin and thickness.
void PrintRecommendation(std::ostream& out, const DesignText& r, const optim::DesignResult& result) {
  const CandidateOutcome& c = result.candidates[*result.recommendation];
  const optim::DesignRule& rule = result.rule;
  const double sf = r.request.options.safety_factor;
  const optim::GoverningRatio governing = c.score.governing(rule);
  fmt::print(out, "  {} ({}), E {}, ν {:.2f}{}\n", c.material.name, c.material.family,
             MPa(c.material.youngs_modulus_Pa), c.material.poisson_ratio,
             c.material.poisson_assumed ? " (ν unknown, 0.25 assumed)" : "");
  fmt::print(out, "  laceration ratio {:.3f}, contusion ratio {:.3f}, compression ratio {:.3f}; {}\n",
             c.score.laceration_ratio, c.score.contusion_ratio, c.score.compression_ratio, CrushWords(c.score, c));
  fmt::print(out, "  governed by {} (ratio {:.3f}): margin {} of the {}; {}\n",
             optim::ToString(governing.criterion, c.score.peaks.covering_law), governing.ratio, FormatPercent(c.margin),
             sf > 1 ? "derated limit" : "limit", CompressionWords(c.score));
  fmt::print(out, "  covering law {}{}; validity: {}\n", ToString(c.score.peaks.covering_law),
             c.score.peaks.covering_law == CoveringLaw::kFoam ? " (its measured compressive curve; design rule within-curve)"
                                                              : " (design rule full-compression)",
             c.score.validity.within ? c.score.validity.note : "OUT: " + c.score.validity.note);
  if (c.min_safe_thickness_m && !r.request.thickness_m) {
    if (c.stock_thickness_beyond_max_m) {
      fmt::print(out,
                 "  thinnest admissible thickness {}; rounding up to stock ({}) would pass the maximum {}, "
                 "so {} is recommended (cut to size)\n",
                 Mm(*c.min_safe_thickness_m), Mm(*c.stock_thickness_beyond_max_m),
                 Mm(r.request.options.space.max_thickness_m), Mm(*c.recommended_thickness_m));
    } else if (*c.recommended_thickness_m > *c.min_safe_thickness_m) {
      fmt::print(out, "  thinnest admissible thickness {}, rounded up to {} (a multiple of {})\n",
                 Mm(*c.min_safe_thickness_m), Mm(*c.recommended_thickness_m), Mm(r.request.options.thickness_step_m));
    } else {
      fmt::print(out, "  thinnest admissible thickness {}\n", Mm(*c.min_safe_thickness_m));
    }
  }
}

/// The bare robot and the continuous optimum (or best design at a fixed thickness).
void PrintBareAndContinuous(std::ostream& out, const DesignText& r, const optim::DesignResult& result) {
  const optim::ContinuousOptimum& continuous = result.continuous;
  const DesignScore& bare = result.bare_robot;
  const bool bare_safe = !result.covering_needed();
  const double sf = r.request.options.safety_factor;
  fmt::print(out, "\nBare robot          laceration ratio {:.3f}, contusion ratio {:.3f}: {}\n", bare.laceration_ratio,
             bare.contusion_ratio, bare_safe ? "safe" : "UNSAFE");
  if (bare_safe && !r.request.thickness_m) {
    fmt::print(out, "Continuous optimum  none needed: the bare robot is safe\n");
    return;
  }
  const DesignScore& best = continuous.score;
  fmt::print(out, "Continuous {}  E_c* = {}, b_c* = {} (ν {:.2f}): laceration {:.3f}, contusion {:.3f}, {}{}; a Hertz "
                  "ideal (no measured curve)\n",
             r.request.thickness_m ? "best   " : "optimum", MPa(best.design.youngs_modulus_Pa), Mm(best.design.thickness_m),
             best.poisson_ratio, best.laceration_ratio, best.contusion_ratio, CompressionWords(best),
             best.admissible(sf, result.criterion) ? "" : " (not admissible)");
  if (!result.rule.crushing_allowed) {
    fmt::print(out, "                    needs a material of compressive strength >= {} (peak compressive stress {} "
                    "x safety factor {:g}), or one that does not crush\n",
               MPa(best.required_strength_Pa(sf)), MPa(best.peaks.max_compressive_stress_Pa), sf);
  }
  if (result.recommendation && !r.request.thickness_m && continuous.feasible) {
    const CandidateOutcome& c = result.candidates[*result.recommendation];
    const double extra = *c.recommended_thickness_m - best.design.thickness_m;
    if (c.score.peaks.covering_law == CoveringLaw::kFoam) {
      fmt::print(out, "                    the recommendation is a foam layer (its measured curve, not a modulus), {} {}\n",
                 Mm(std::abs(extra)), extra >= 0 ? "thicker" : "thinner");
    } else {
      fmt::print(out, "                    the recommendation is {:.2f}x its modulus and {} {}\n",
                 c.material.youngs_modulus_Pa / best.design.youngs_modulus_Pa, Mm(std::abs(extra)),
                 extra >= 0 ? "thicker" : "thinner");
    }
  }
}

/// The solver and oracle lines, the scope and the warnings.
void PrintSolverAndWarnings(std::ostream& out, const DesignText& r, const optim::DesignResult& result) {
  const optim::ContinuousOptimum& continuous = result.continuous;
  const optim::SolverReport& global = continuous.global;
  const optim::SolverReport& local = continuous.local;
  fmt::print(out, "\nSolver  global {}: {} ({} evaluations); bracket: {} ({} evaluations); local {}; {} {} "
                  "evaluations, {:.1f} ms\n",
             global.backend, optim::ToString(global.termination), global.objective_evaluations,
             optim::ToString(continuous.bracket.termination), continuous.bracket.objective_evaluations,
             local.backend.empty() ? std::string("not run")
                                   : fmt::format("{}: {} ({})", local.backend, optim::ToString(local.termination),
                                                 local.raw_name),
             result.evaluations, result.oracle.kind == optim::OracleKind::kExact ? "exact-path" : "time-path",
             result.seconds * 1e3);
  fmt::print(out, "        kept: {}\n", continuous.source);
  fmt::print(out, "Oracle  {}, {} gradients; {}\n", result.oracle.Name(), GradientWords(result.oracle.gradient),
             result.oracle.reason);
  fmt::print(out, "\nScope\n");
  for (const std::string& line : result.scope) fmt::print(out, "  {}\n", line);
  for (const std::string& w : r.warnings) fmt::print(out, "Warning: {}\n", w);       // about the input
  for (const std::string& w : result.warnings) fmt::print(out, "Warning: {}\n", w);  // about the answer
}


}  // namespace

/// The report of a deterministic design (optim::Design).
void PrintDesign(std::ostream& out, const DesignText& r, const optim::DesignResult& result) {
  const double sf = r.request.options.safety_factor;
  const double laceration_limit = r.request.options.limits.laceration_tensile_stress_Pa;
  const double contusion_limit = r.request.options.limits.contusion_energy_density_J_per_m2;
  fmt::print(out, "Scene      {}\n", DesignedSceneHeadline(r.request.scene));
  fmt::print(out, "Limits     laceration {:g} MPa, contusion {:g} J/cm², safety factor {:g}{}{}\n", laceration_limit * 1e-6,
             contusion_limit * 1e-4, sf,
             sf > 1 ? fmt::format(": designed to {:.4g} MPa and {:.4g} J/cm²", laceration_limit * 1e-6 / sf,
                                  contusion_limit * 1e-4 / sf)
                    : std::string(),
             r.request.thickness_m ? fmt::format("; thickness fixed at {}", Mm(*r.request.thickness_m))
                                   : fmt::format("; thickness up to {}", Mm(r.request.options.space.max_thickness_m)));
  const optim::DesignRule& rule = result.rule;
  fmt::print(out, "Criterion  {}{}\n", rule.Describe(),
             result.criterion == optim::DesignCriterion::kNoFullCompression && !rule.crushing_allowed
                 ? " (--allow-full-compression for the paper's criterion, --allow-crushing for a sacrificial liner)"
                 : "");
  fmt::print(out, "\n{}\n", result.message);
  fmt::print(out, "\nVerdict\n{}\n", SummaryText(optim::SummarizeDesign(r.request, result), 2));
  if (result.recommendation) PrintRecommendation(out, r, result);
  PrintDesignAnswer(out, result, r.runners_up);  // the range checked, or the nearest changes
  PrintBareAndContinuous(out, r, result);
  const std::vector<CandidateOutcome>& candidates = result.candidates;
  fmt::print(out, "\nCandidates ({})\n",
             candidates.empty()      ? "none: the catalog filter left nothing"
             : r.request.thickness_m ? "admissible first, then by margin at this thickness"
                                     : "admissible first, by stock thickness then margin; then the rest by margin at "
                                       "the maximum thickness");
  PrintCandidates(out, candidates, r.runners_up, r.request.thickness_m.has_value(), rule);
  fmt::print(out, "  ratios: laceration, contusion, compression (law hertz: the covering's own travel used, 0.8 b_c "
                  "beyond the scalp's 0.8 b_s; law foam: the share of its measured curve's strain used), crush (peak "
                  "compressive stress / compressive strength); margin = 1 - SF x the governing one\n");
  PrintSolverAndWarnings(out, r, result);
}

}  // namespace covopt::report
