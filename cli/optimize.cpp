#include "optimize.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <thread>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/physical_floors.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/quantity.hpp"
#include "covopt/materials/catalog.hpp"
#include "covopt/optim/design.hpp"
#include "covopt/optim/design_map.hpp"
#include "covopt/report/design_json.hpp"
#include "covopt/report/robust_json.hpp"
#include "body_region_commands.hpp"
#include "design_flag_ranges.hpp"
#include "errors.hpp"
#include "materials_command.hpp"
#include "oracle_options.hpp"
#include "output.hpp"
#include "plot.hpp"
#include "quantity.hpp"
#include "report_option.hpp"
#include "scene_fields.hpp"
#include "scene_file.hpp"
#include "simulate.hpp"

namespace covopt::cli {
namespace {

using optim::CandidateOutcome;
using optim::DesignOptions;
using optim::DesignScore;

constexpr std::string_view kFooter = R"(Values take a unit as in 'covopt simulate' (10kg, 2m/s, 15mm, 27.6MPa).
The covering is what this command designs: its flags are not taken here.
Without --thickness: the thinnest covering keeping laceration and contusion
below their limits divided by --safety-factor, over E_c (log scale) and b_c,
then every catalog material's own thinnest safe thickness, rounded up to
--thickness-step. With --thickness: the least injury at that thickness.

The oracle (--oracle): auto takes the exact path where the scene has an
energy integral (the two-mass impact, conservative or damped) and the
time path otherwise (a braking robot, a neck); time-path runs the
SUNDIALS integrator --method at --rtol (gradients for Ipopt from CVODES
forward sensitivities, or a central difference with braking or a neck).

Exit codes: 0 an answer (also "no material is safe"); 1 the search failed;
2 bad input.)";

struct Resolved {
  optim::DesignRequest request;
  /// Scene inputs given as ranges LO..HI: the robust design (docs/model.md §11).
  std::vector<SceneRange> ranges;
  std::vector<std::string> warnings;  ///< about the input (the library adds its own)
  int runners_up = 8;
};

double Parse(const std::optional<std::string>& text, const QuantitySpec& spec, std::string_view flag,
             double fallback) {
  return text ? ParseQuantity(*text, spec, flag) : fallback;
}

/// A whole number in [min, max] as typed after `flag` (no sign for min >= 0, no unit).
unsigned long long ParseCount(const std::string& text, std::string_view flag, unsigned long long min,
                              unsigned long long max) {
  unsigned long long value = 0;
  const char* const end = text.data() + text.size();
  const auto [stop, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || stop != end || value < min || value > max) {
    throw InputError(fmt::format("{}: expected a whole number in [{}, {}] (got '{}')", flag, min, max, text));
  }
  return value;
}

bool IsCoveringField(const SceneField& field) { return field.table == "covering"; }

/// --oracle, --method and --rtol into the request's OracleOptions (the scene must be read).
void ResolveOracle(const OptimizeOptions& o, Resolved& r) {
  r.request.options.oracle = ResolveOracleFlags(o.oracle_flags, r.request.scene, "optimise", r.warnings);
}

/// The scene (file, flags, ranges, --urdf) into `r`, with the scene file's limits.
void ResolveScene(const OptimizeOptions& o, Resolved& r) {
  DesignOptions& d = r.request.options;
  if (o.scene_file) {
    SceneFileExtras extras;
    for (const std::string& name : ApplySceneFile(*o.scene_file, r.request.scene, &extras)) {
      if (name.rfind("covering.", 0) == 0) {
        r.warnings.push_back(fmt::format("{} in {} is ignored: the covering is what optimize designs",
                                         name, *o.scene_file));
      }
    }
    for (const SceneRange& range : extras.ranges) {
      if (range.field.rfind("covering.", 0) != 0) r.ranges.push_back(range);  // covering: warned above
    }
    if (extras.laceration_limit_Pa) d.limits.laceration_tensile_stress_Pa = *extras.laceration_limit_Pa;
    if (extras.contusion_limit_J_per_m2) d.limits.contusion_energy_density_J_per_m2 = *extras.contusion_limit_J_per_m2;
    if (extras.safety_factor) d.safety_factor = *extras.safety_factor;
  }
  std::vector<scene_file::SceneInput> inputs;  // the values, for the library's one resolution
  for (const SceneField& field : SceneFields()) {
    const auto typed = o.scene_values.find(field.dotted_name());
    if (typed != o.scene_values.end()) {
      std::erase_if(r.ranges, [&](const SceneRange& range) { return range.field == field.dotted_name(); });
      if (IsRangeText(typed->second)) {
        r.ranges.push_back(AsInputError([&] { return scene_file::ParseSceneRange(typed->second, field, field.flag); }));
      } else {
        inputs.push_back({typed->first, typed->second, ""});
      }
    }
  }
  scene_file::ResolvedScene resolved{r.request.scene, d.limits, d.safety_factor, nullptr};
  ApplySceneFlagInputs(inputs, resolved);
  r.request.scene = resolved.scene;
  SetNominalValues(r.request.scene, r.ranges);
  if (o.thresholds) r.request.scene.model.thresholds = ParseThresholds(*o.thresholds, "--thresholds");
  if (o.head_area) r.request.scene.head.area = ParseHeadArea(*o.head_area, "--head-area");
  if (o.robot_model.given()) {  // --urdf ...: robot.mass from the robot model
    RobotModelMass mass = ResolveRobotModelMass(o.robot_model, o.scene_values.count(kRobotMassField) != 0);
    r.request.scene.robot.mass_kg = mass.mass_kg;
    std::erase_if(r.ranges, [](const SceneRange& range) { return range.field == kRobotMassField; });
    r.warnings.insert(r.warnings.begin(), mass.notes.begin(), mass.notes.end());
  }
}

/// The design flags (criterion, space, limits, safety factor, ν, step, --thickness) into `r`,
/// each checked against its range with the flag's name.
void ResolveDesignFlags(const OptimizeOptions& o, Resolved& r) {
  DesignOptions& d = r.request.options;
  namespace specs = covopt::quantity_specs;
  d.allow_full_compression = o.allow_full_compression;
  d.allow_crushing = o.allow_crushing;
  d.allow_unknown_strength = o.allow_unknown_strength;
  d.space.max_thickness_m = Parse(o.max_thickness, specs::kCoveringThickness, "--max-thickness", d.space.max_thickness_m);
  d.space.min_modulus_Pa = Parse(o.min_modulus, specs::kCoveringModulus, "--min-modulus", d.space.min_modulus_Pa);
  d.space.max_modulus_Pa = Parse(o.max_modulus, specs::kCoveringModulus, "--max-modulus", d.space.max_modulus_Pa);
  d.safety_factor = Parse(o.safety_factor, specs::kSafetyFactor, "--safety-factor", d.safety_factor);
  d.covering_poisson_ratio = Parse(o.covering_poisson, specs::kPoissonRatio, "--covering-poisson", d.covering_poisson_ratio);
  d.thickness_step_m = Parse(o.thickness_step, specs::kThicknessStep, "--thickness-step", d.thickness_step_m);
  d.limits.laceration_tensile_stress_Pa =
      Parse(o.laceration_limit, specs::kLacerationLimit, "--laceration-limit", d.limits.laceration_tensile_stress_Pa);
  d.limits.contusion_energy_density_J_per_m2 =
      Parse(o.contusion_limit, specs::kContusionLimit, "--contusion-limit", d.limits.contusion_energy_density_J_per_m2);
  // Range checks with the flag's name (the library would name its own fields).
  auto require = [](bool ok, const std::string& message) {
    if (!ok) throw InputError(message);
  };
  RequireMaxThickness(d.space.max_thickness_m, d.space.min_thickness_m, o.max_thickness);
  require(d.space.min_modulus_Pa > 0 && d.space.max_modulus_Pa > d.space.min_modulus_Pa &&
              d.space.max_modulus_Pa <= 1e13,
          fmt::format("--min-modulus/--max-modulus must satisfy 0 < min < max <= 1e13 Pa (got {} Pa, {} Pa)",
                      d.space.min_modulus_Pa, d.space.max_modulus_Pa));
  require(d.safety_factor >= 1.0 && d.safety_factor <= 100.0,
          fmt::format("--safety-factor must be in [1, 100] (got '{}')", o.safety_factor.value_or(fmt::format("{}", d.safety_factor))));
  require(d.covering_poisson_ratio > -1.0 && d.covering_poisson_ratio <= 0.5,
          fmt::format("--covering-poisson must be in (-1, 0.5] (got '{}')", o.covering_poisson.value_or("")));
  RequireThicknessStep(d.thickness_step_m, o.thickness_step);
  // The limits' one range (scene_file::CheckLimitValue), as simulate, scene files and Python.
  const std::span<const LimitField> limit_fields = LimitFields();
  CheckLimitValue(limit_fields[0], d.limits.laceration_tensile_stress_Pa, "--laceration-limit",
                  fmt::format("'{}'", o.laceration_limit.value_or("")));
  CheckLimitValue(limit_fields[1], d.limits.contusion_energy_density_J_per_m2, "--contusion-limit",
                  fmt::format("'{}'", o.contusion_limit.value_or("")));
  if (o.thickness) {
    r.request.thickness_m = ParseQuantity(*o.thickness, specs::kCoveringThickness, "--thickness");
    require(*r.request.thickness_m >= kMinLayerThickness_m && *r.request.thickness_m <= 1.0,
            fmt::format("--thickness must be in [0.1 mm, 1 m] (got '{}'); for no covering use "
                        "'covopt simulate --covering-thickness 0'",
                        *o.thickness));
    if (o.max_thickness) {
      throw InputError(fmt::format("--thickness {} and --max-thickness {} conflict: --thickness fixes the thickness "
                                   "(the least injury there), --max-thickness bounds the search for the thinnest; "
                                   "give one",
                                   *o.thickness, *o.max_thickness));
    }
  }
}

Resolved Resolve(const OptimizeOptions& o) {
  Resolved r;
  DesignOptions& d = r.request.options;
  ResolveScene(o, r);
  ResolveDesignFlags(o, r);
  if (o.global_algorithm) {
    const std::string& g = *o.global_algorithm;
    if (g == "direct-l") d.global_algorithm = optim::NloptAlgorithm::kDirectL;
    else if (g == "isres") d.global_algorithm = optim::NloptAlgorithm::kIsres;
    else if (g == "mlsl") d.global_algorithm = optim::NloptAlgorithm::kMlsl;
    else throw InputError(fmt::format("--global: expected direct-l, isres or mlsl (got '{}')", g));
  }
  if (o.seed) d.seed = ParseCount(*o.seed, "--seed", 0, std::numeric_limits<unsigned long>::max());
  if (o.runners_up) r.runners_up = static_cast<int>(ParseCount(*o.runners_up, "--top", 0, 1000000));
  if (o.threads) {  // 0 = every core, as simulate's sampling and sweep take it
    const auto threads = ParseCount(*o.threads, "--threads", 0, 256);
    d.threads = threads == 0 ? static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 256u))
                             : static_cast<int>(threads);
  }
  ResolveOracle(o, r);

  // The candidates: the built-in catalog and --catalog files (or only those, --no-builtin), filtered.
  const materials::Catalog catalog = [&] {
    try {
      return LoadCatalog(o.catalog);
    } catch (const InputError& e) {
      const std::string what = e.what();
      throw InputError(what.rfind("--", 0) == 0 ? what : "--catalog: " + what);
    }
  }();
  try {
    r.request.materials = optim::SelectCandidates(catalog, o.materials, o.families);
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    throw InputError((what.rfind("no family", 0) == 0 ? "--family: " : "--material: ") + what);
  }
  return r;
}

std::string Percent(double fraction) { return fmt::format("{:.1f} %", 100.0 * fraction); }
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
    fmt::print(out, "  {:<3} {:<28} {:>9} {:>6} {:>10} {:>7} {:>7} {:>7} {:>8} {:>8}  {}\n", "#", "material",
               "E [MPa]", "ν", "thickness", "lacer.", "contus.", "compr.", "crush", "margin", "governs");
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
    fmt::print(out, "  {:<3} {:<28} {:>9.4g} {:>6} {:>10} {:>7.3f} {:>7.3f} {:>7.3f} {:>8} {:>8}  {}{}\n", i + 1,
               c.material.name.substr(0, 28), c.material.youngs_modulus_Pa * 1e-6,
               fmt::format("{:.2f}{}", c.material.poisson_ratio, c.material.poisson_assumed ? "*" : ""),
               thickness, c.score.laceration_ratio, c.score.contusion_ratio, c.score.compression_ratio,
               CrushCell(c.score), Percent(c.margin), optim::ToString(c.score.governing(rule).criterion),
               unknown_refused                 ? "; strength unknown, not recommended"
               : c.score.peaks.fully_compressed ? "; fully compressed"
                                                : "");
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

/// The candidate table as CSV: every candidate, SI units in the header.
std::string CandidatesCsv(const std::vector<CandidateOutcome>& candidates, const optim::DesignRule& rule) {
  std::string csv =
      "rank,material,family,youngs_modulus_Pa,poisson_ratio,poisson_assumed,crush_behaviour,compressive_strength_Pa,"
      "admissible,thickness_m,min_safe_thickness_m,laceration_ratio,contusion_ratio,compression_ratio,crush_ratio,"
      "governing_criterion,governing_ratio,margin,max_compressive_stress_Pa,fully_compressed\n";
  const auto quoted = [](const std::string& text) { return CsvField(text); };
  const auto number = [](double v) { return std::isfinite(v) ? fmt::format("{}", v) : std::string(); };
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const CandidateOutcome& c = candidates[i];
    const optim::GoverningRatio g = c.score.governing(rule);
    const bool crushes = c.material.crush_behaviour == materials::CrushBehaviour::kCrushes;
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", i + 1, quoted(c.material.name),
                       quoted(c.material.family), number(c.material.youngs_modulus_Pa),
                       number(c.material.poisson_ratio), c.material.poisson_assumed,
                       materials::ToString(c.material.crush_behaviour),
                       crushes ? number(c.material.compressive_strength_Pa) : "", c.safe,
                       number(c.score.design.thickness_m),
                       c.min_safe_thickness_m ? number(*c.min_safe_thickness_m) : "",
                       number(c.score.laceration_ratio), number(c.score.contusion_ratio),
                       number(c.score.compression_ratio),
                       c.score.crush_check == optim::CrushCheck::kChecked ? number(c.score.crush_ratio) : "",
                       optim::ToString(g.criterion), number(g.ratio), number(c.margin),
                       number(c.score.peaks.max_compressive_stress_Pa), c.score.peaks.fully_compressed);
  }
  return csv;
}

/// "Scene ..." of the reports: the (nominal) scene, its covering to be designed.
std::string DesignSceneLine(const Resolved& r) {
  Scene nominal = r.request.scene;
  nominal.covering.thickness_m = 0.0;
  std::string scene_line = SceneHeadline(nominal);
  if (const auto at = scene_line.find("no covering"); at != std::string::npos) {
    scene_line.replace(at, 11, "covering to be designed");
  }
  return scene_line;
}

void PrintScope(std::ostream& out, const optim::DesignRule& rule) {
  fmt::print(out, "\nScope\n");
  for (const std::string& line : optim::HeadVerdictScope(rule)) fmt::print(out, "  {}\n", line);
}

/// What optimize with scene ranges reads beyond the deterministic request: the box, and the
/// sampling (--samples) and probability target (--max-injury-probability) when given.
struct RobustInputs {
  optim::UncertaintyBox box;
  std::optional<optim::InjuryProbabilityOptions> sampling;
  std::optional<double> max_probability;
};

/// The robust inputs. @throws std::invalid_argument (InputError and the library's checks).
RobustInputs ResolveRobust(const OptimizeOptions& o, const Resolved& r) {
  if (o.thickness) {
    throw InputError("--thickness with scene ranges: the robust design finds the thickness; for one covering over "
                     "the box use 'covopt simulate --covering-thickness ... --material ...' with the ranges");
  }
  if (o.oracle_flags.given()) {
    throw InputError(fmt::format("--{} with scene ranges: the robust searches choose their path (the exact path; the "
                                 "time path at its defaults for a braking robot)",
                                 o.oracle_flags.oracle ? "oracle" : o.oracle_flags.method ? "method" : "rtol"));
  }
  UncertaintyFlags flags = o.uncertainty;
  flags.seed = o.seed;
  flags.threads = o.threads ? o.threads : std::optional<std::string>{};
  std::optional<optim::InjuryProbabilityOptions> sampling = ResolveSampling(flags, r.ranges);
  std::optional<double> max_probability;
  if (o.max_injury_probability) {
    const double p = ParseQuantity(*o.max_injury_probability, quantity_specs::kTolerance, "--max-injury-probability");
    if (!(p > 0.0 && p < 1.0)) {
      throw InputError(fmt::format("--max-injury-probability must be in (0, 1) (got '{}')", *o.max_injury_probability));
    }
    if (!sampling) throw InputError("--max-injury-probability needs --samples N (the probability is estimated)");
    max_probability = p;
  }
  return {MakeUncertaintyBox(r.request.scene, ResolveUncertainInputs(r.ranges, o.uncertainty.distributions), r.ranges),
          std::move(sampling), max_probability};
}

/// The report of FindProbabilityDesign (optimize --max-injury-probability).
void PrintProbabilityDesign(std::ostream& out, const Resolved& r, const optim::UncertaintyBox& box,
                            const optim::ProbabilityDesignOptions& options, const optim::ProbabilityDesign& result) {
  const optim::DesignRule rule = options.design.rule();
  const double max_probability = options.max_probability;
  fmt::print(out, "Scene      {} (nominal; the ranges below vary)\n", DesignSceneLine(r));
  fmt::print(out, "Design for a probability of failing the criterion <= {:g} over {} input{}, {} samples, seed {}\n",
             max_probability, box.size(), box.size() == 1 ? "" : "s", options.sampling.samples, options.sampling.seed);
  fmt::print(out, "Criterion  {}\n", rule.Describe());
  fmt::print(out, "Target     met when the upper end of the 95 % (Wilson) interval of P(inadmissible) is <= {:g}: at "
                  "most {} failing samples of {}\n",
             max_probability, result.allowed_failures, options.sampling.samples);
  for (const SceneRange& range : r.ranges) fmt::print(out, "  {:<20} {}  (from {})\n", range.name, range.text, range.source);
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


/// optimize --max-injury-probability: the thinnest covering whose probability of failing the
/// criterion is <= P (FindProbabilityDesign).
int RunProbabilityDesign(const OptimizeOptions& o, const Resolved& r, const RobustInputs& inputs, std::ostream& out,
                         std::ostream& err) {
  const CommandErrors errors(err, "optimize");
  optim::ProbabilityDesignOptions options;
  options.design = r.request.options;
  options.sampling = *inputs.sampling;
  options.max_probability = *inputs.max_probability;
  optim::ProbabilityDesign result;
  try {
    SamplingProgressBar bar(err, "designing");
    options.sampling.progress = bar.Callback();
    result = optim::FindProbabilityDesign(inputs.box, r.request.materials, options);
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(e.what());
  }
  if (o.json || o.report_file) {
    try {
      PrintAndReport(out, o.json, report::ProbabilityDesignJson(inputs.box, options, result, r.warnings), o.run,
                     o.report_file, report::ReportKind::kOptimize, nullptr);
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (!o.json) {
    PrintProbabilityDesign(out, r, inputs.box, options, result);
  }
  return 0;
}

/// The candidate table of the robust design, each at its worst case over the box.
void PrintRobustCandidates(std::ostream& out, const Resolved& r, const optim::RobustThinnestCovering& result,
                           const optim::DesignRule& rule) {
  fmt::print(out, "\nCandidates (each at its worst case over the box):\n  {:<3} {:<28} {:>9} {:>10} {:>7} {:>7} {:>7} {:>8} {:>8}  {:<16} {:>6}\n",
             "#", "material", "E [MPa]", "thickness", "lacer.", "contus.", "compr.", "crush", "margin", "governs",
             "rounds");
  const int shown = std::min<int>(r.runners_up, static_cast<int>(result.candidates.size()));
  for (int i = 0; i < shown; ++i) {
    const optim::RobustCandidate& c = result.candidates[static_cast<std::size_t>(i)];
    fmt::print(out, "  {:<3} {:<28} {:>9.4g} {:>10} {:>7.3f} {:>7.3f} {:>7.3f} {:>8} {:>8}  {:<16} {:>6}{}\n", i + 1,
               c.outcome.material.name.substr(0, 28), c.outcome.material.youngs_modulus_Pa * 1e-6,
               c.outcome.recommended_thickness_m ? Mm(*c.outcome.recommended_thickness_m)
                                                 : fmt::format("> {}", Mm(c.outcome.score.design.thickness_m)),
               c.worst_case.laceration_ratio, c.worst_case.contusion_ratio, c.worst_case.compression_ratio,
               CrushCell(c.outcome.score), Percent(c.outcome.margin),
               optim::ToString(c.outcome.score.governing(rule).criterion), c.scenario_rounds,
               c.unconfirmed ? "  unconfirmed" : "");
  }
  if (static_cast<int>(result.candidates.size()) > shown) {
    fmt::print(out, "  ... {} more (--top N, or --json for all)\n", result.candidates.size() - static_cast<std::size_t>(shown));
  }
}

/// The report of FindRobustThinnestCovering, with the recommendation's probability when sampled.
void PrintRobustDesign(std::ostream& out, const Resolved& r, const optim::UncertaintyBox& box,
                       const optim::RobustDesignOptions& options, const optim::RobustThinnestCovering& result,
                       const std::optional<optim::InjuryProbability>& probability) {
  const optim::DesignRule rule = options.design.rule();
  fmt::print(out, "Scene      {} (nominal; the ranges below vary)\n", DesignSceneLine(r));
  fmt::print(out, "Criterion  {}\n", rule.Describe());
  fmt::print(out, "Robust design over {} uncertain input{}:\n", box.size(), box.size() == 1 ? "" : "s");
  for (const SceneRange& range : r.ranges) fmt::print(out, "  {:<20} {}  (from {})\n", range.name, range.text, range.source);
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

/// The recommendation of a deterministic design: its material, ratios, margin and thickness.
void PrintRecommendation(std::ostream& out, const Resolved& r, const optim::DesignResult& result) {
  const CandidateOutcome& c = result.candidates[*result.recommendation];
  const optim::DesignRule& rule = result.rule;
  const double sf = r.request.options.safety_factor;
  const optim::GoverningRatio governing = c.score.governing(rule);
  fmt::print(out, "  {} ({}), E {}, ν {:.2f}{}\n", c.material.name, c.material.family,
             MPa(c.material.youngs_modulus_Pa), c.material.poisson_ratio,
             c.material.poisson_assumed ? " (ν unknown, 0.25 assumed)" : "");
  fmt::print(out, "  laceration ratio {:.3f}, contusion ratio {:.3f}, compression ratio {:.3f}; {}\n",
             c.score.laceration_ratio, c.score.contusion_ratio, c.score.compression_ratio, CrushWords(c.score, c));
  fmt::print(out, "  governed by {} (ratio {:.3f}): margin {} of the {}; {}\n", optim::ToString(governing.criterion),
             governing.ratio, Percent(c.margin), sf > 1 ? "derated limit" : "limit", CompressionWords(c.score));
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
void PrintBareAndContinuous(std::ostream& out, const Resolved& r, const optim::DesignResult& result) {
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
  fmt::print(out, "Continuous {}  E_c* = {}, b_c* = {} (ν {:.2f}): laceration {:.3f}, contusion {:.3f}, {}{}\n",
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
    fmt::print(out, "                    the recommendation is {:.2f}x its modulus and {} {}\n",
               c.material.youngs_modulus_Pa / best.design.youngs_modulus_Pa, Mm(std::abs(extra)),
               extra >= 0 ? "thicker" : "thinner");
  }
}

/// The solver and oracle lines, the scope and the warnings.
void PrintSolverAndWarnings(std::ostream& out, const Resolved& r, const optim::DesignResult& result) {
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

/// The report of a deterministic design (optim::Design).
void PrintDesign(std::ostream& out, const Resolved& r, const optim::DesignResult& result) {
  const double sf = r.request.options.safety_factor;
  const double laceration_limit = r.request.options.limits.laceration_tensile_stress_Pa;
  const double contusion_limit = r.request.options.limits.contusion_energy_density_J_per_m2;
  fmt::print(out, "Scene      {}\n", DesignSceneLine(r));
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
  if (result.recommendation) PrintRecommendation(out, r, result);
  PrintBareAndContinuous(out, r, result);
  const std::vector<CandidateOutcome>& candidates = result.candidates;
  fmt::print(out, "\nCandidates ({})\n",
             candidates.empty()      ? "none: the catalog filter left nothing"
             : r.request.thickness_m ? "admissible first, then by margin at this thickness"
                                     : "admissible first, by stock thickness then margin; then the rest by margin at "
                                       "the maximum thickness");
  PrintCandidates(out, candidates, r.runners_up, r.request.thickness_m.has_value(), rule);
  fmt::print(out, "  ratios: laceration, contusion, compression (the covering's own travel used, 0.8 b_c beyond the "
                  "scalp's 0.8 b_s), crush (peak compressive stress / compressive strength); margin = 1 - SF x the "
                  "governing one\n");
  PrintSolverAndWarnings(out, r, result);
}

/// optimize with scene ranges (docs/model.md §11): the thinnest covering admissible for every
/// value in the box (FindRobustThinnestCovering), or with --max-injury-probability the
/// thinnest whose probability of failing the criterion is <= P (FindProbabilityDesign).
int RunRobustOptimize(const OptimizeOptions& o, const Resolved& r, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "optimize");
  std::optional<RobustInputs> inputs;
  try {
    inputs.emplace(ResolveRobust(o, r));
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(e.what());
  }
  if (inputs->max_probability) return RunProbabilityDesign(o, r, *inputs, out, err);

  optim::RobustDesignOptions options;
  options.design = r.request.options;
  optim::RobustThinnestCovering result;
  std::optional<optim::InjuryProbability> probability;
  try {
    result = optim::FindRobustThinnestCovering(inputs->box, r.request.materials, options);
    if (inputs->sampling && result.recommendation) {
      SamplingProgressBar bar(err, "sampling");
      optim::InjuryProbabilityOptions sampling = *inputs->sampling;
      sampling.progress = bar.Callback();
      probability = optim::EstimateRecommendationInjuryProbability(inputs->box, result, options, sampling);
    }
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(e.what());
  }
  if (o.json || o.report_file) {
    try {
      PrintAndReport(out, o.json,
                     report::RobustDesignJson(inputs->box, options, result, probability ? &*probability : nullptr,
                                              r.warnings),
                     o.run, o.report_file, report::ReportKind::kOptimize, nullptr);
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (!o.json) {
    PrintRobustDesign(out, r, inputs->box, options, result, probability);
  }
  return 0;
}

}  // namespace

void SetupOptimize(CLI::App* sub, OptimizeOptions& options) {
  sub->footer(std::string(kFooter));
  sub->add_option("--scene", options.scene_file, "TOML scene file; flags override it")->type_name("FILE.toml");
  for (const SceneField& field : SceneFields()) {
    if (IsCoveringField(field)) continue;
    const std::string key = field.dotted_name();
    sub->add_option_function<std::string>(
           std::string(field.flag), [&options, key](const std::string& v) { options.scene_values[key] = v; },
           std::string(field.help))
        ->type_name("VALUE")
        ->group("Scene");
  }
  sub->add_option("--thresholds", options.thresholds, "phase thresholds: cumulative (default) or literal")
      ->check(CLI::IsMember({"cumulative", "literal"}))
      ->group("Scene");
  sub->add_option("--head-area", options.head_area,
                  "the struck area of the head, whose lowest published fracture force the peak force is judged against: " +
                      HeadAreaChoices() + " (default frontal, the forehead; docs/model.md §7.1)")
      ->type_name("AREA")
      ->group("Scene");
  sub->add_option("--max-thickness", options.max_thickness, "thickest covering considered (default 50 mm)")
      ->type_name("LENGTH")->group("Design");
  sub->add_option("--min-modulus", options.min_modulus, "softest covering of the continuous search (default 0.1 MPa)")
      ->type_name("MODULUS")->group("Design");
  sub->add_option("--max-modulus", options.max_modulus, "stiffest covering of the continuous search (default 1 GPa)")
      ->type_name("MODULUS")->group("Design");
  sub->add_option("--safety-factor", options.safety_factor, "ratios must stay <= 1/factor (default 1)")
      ->type_name("X")->group("Design");
  sub->add_flag("--allow-full-compression", options.allow_full_compression,
                "the paper's criterion: a covering fully compressed at the peak may count as safe "
                "(default: it may not, the robot must never reach bone through it)")
      ->group("Design");
  sub->add_flag("--allow-crushing", options.allow_crushing,
                "a sacrificial liner: a material may be recommended although its peak compressive stress times the "
                "safety factor exceeds its compressive strength (default: it may not; it would crush at the first "
                "impact)")
      ->group("Design");
  sub->add_flag("--allow-unknown-strength", options.allow_unknown_strength,
                "materials whose compressive strength is unknown may be recommended, each with a warning (default: "
                "they are not, a design with them is unverified for crushing)")
      ->group("Design");
  sub->add_option("--laceration-limit", options.laceration_limit,
                  "tensile stress that lacerates the scalp (default 1MPa)")
      ->type_name("STRESS")->group("Design");
  sub->add_option("--contusion-limit", options.contusion_limit,
                  "energy density that bruises (default 2.52J/cm2)")
      ->type_name("ENERGY/AREA")->group("Design");
  sub->add_option("--thickness", options.thickness, "fixed thickness: find the least injury there instead")
      ->type_name("LENGTH")->group("Design");
  sub->add_option("--covering-poisson", options.covering_poisson, "ν of the continuous design (default 0.25)")
      ->type_name("RATIO")->group("Design");
  sub->add_option("--thickness-step", options.thickness_step,
                  "round recommended thicknesses up to a multiple of this (default 0.5 mm; 0 = exact)")
      ->type_name("LENGTH")->group("Design");
  AddRobotModelOptions(*sub, options.robot_model, true, "Robot model (instead of --robot-mass)");
  AddCatalogOptions(*sub, options.catalog);
  sub->add_option("--family", options.families, "only materials of this family (repeatable)")
      ->type_name("NAME")->group("Materials");
  sub->add_option("--material", options.materials, "only this catalog material (repeatable)")
      ->type_name("NAME")->group("Materials");
  sub->add_option("--global", options.global_algorithm, "global search: direct-l (default), isres or mlsl")
      ->group("Solver");
  sub->add_option("--seed", options.seed, "seed of the stochastic global searches")->type_name("N")->group("Solver");
  sub->add_option("--threads", options.threads,
                  "threads of the per-material catalog snap, 0-256, 0 = all cores (default 1); the answer does not "
                  "depend on it")
      ->type_name("N")->group("Solver");
  AddOracleOptions(*sub, options.oracle_flags, "the designs", "Solver");
  AddUncertaintyOptions(*sub, options.uncertainty, false);
  sub->add_option("--max-injury-probability", options.max_injury_probability,
                  "with scene ranges and --samples: the thinnest covering whose probability of failing the criterion "
                  "is shown to be at most P: the upper end of its 95 % interval, not just the estimate, must be <= P; "
                  "P in (0, 1) (--seed and --threads set the sampling)")
      ->type_name("P")
      ->group("Uncertainty");
  sub->add_option("--top", options.runners_up, "rows of the candidate table (default 8)")->type_name("N")->group("Output");
  AddBodyRegionOptions(*sub, options.body);
  sub->add_flag("--json", options.json, "print one JSON object (SI units) instead of the report")->group("Output");
  AddReportOption(*sub, options.report_file);
  sub->add_option("--csv", options.csv, "write every candidate to FILE as CSV (SI units in the header)")
      ->type_name("FILE")
      ->group("Output");
  sub->add_option("--plot", options.plot_file,
                  "chart with gnuplot: the design map, the governing ratio over thickness x modulus with each "
                  "criterion's limit and the chosen design (the head's design only)")
      ->type_name("FILE.png|FILE.svg")
      ->group("Output");
}

int RunOptimize(const OptimizeOptions& options, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "optimize");
  Resolved r;
  try {
    r = Resolve(options);
    Scene bare = r.request.scene;
    bare.covering.thickness_m = 0.0;
    (void)ImpactModel::FromScene(bare);  // scene range checks, naming the field
  } catch (const std::invalid_argument& e) {  // InputError and the library's checks
    return errors.BadInput(e.what());
  }
  if (options.plot_file) {
    const char* refused = options.body.any() ? "--body-region" : !r.ranges.empty() ? "scene ranges" : nullptr;
    if (refused != nullptr) {
      return errors.BadInput(fmt::format("--plot '{}': the design map is drawn for the head's design only, not with {}; "
                                         "drop --plot",
                                         *options.plot_file, refused));
    }
    if (!PlotFormatFor(*options.plot_file)) {
      return errors.BadInput(fmt::format("--plot: cannot tell the format of '{}'; name the file *.png or *.svg",
                                         *options.plot_file));
    }
  }
  if (options.body.any()) {  // ISO/TS 15066 body regions (body_region_commands.hpp)
    if (!r.ranges.empty()) {
      return errors.BadInput(fmt::format("{} '{}': scene ranges (uncertain inputs) are not taken with --body-region",
                                         r.ranges.front().source, r.ranges.front().text));
    }
    return RunWithBodyRegions(options.body, errors, [&](const BodyRegionPlan& regions) {
      return RunBodyRegionOptimize(options, r.request, r.warnings, regions, out, err);
    });
  }
  if (!r.ranges.empty()) return RunRobustOptimize(options, r, out, err);
  if (options.uncertainty.samples || !options.uncertainty.distributions.empty() || options.max_injury_probability) {
    return errors.BadInput(fmt::format("{} needs at least one scene input as a range LO..HI, e.g. --head-mass 3.7kg..5.8kg",
                                       options.uncertainty.samples           ? "--samples"
                                       : options.max_injury_probability ? "--max-injury-probability"
                                                                              : "--distribution"));
  }

  optim::DesignResult result;
  try {
    result = optim::Design(r.request);  // the whole computation: one library call
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(e.what());
  }
  if (!result.ok()) return errors.Failed(result.message);
  if ((options.plot_file || options.report_file) && !FindOnPath("gnuplot")) return errors.Failed(kGnuplotMissing);
  // The design map, computed once for --plot and --report.
  std::optional<report::GnuplotChart> design_map;
  const auto design_map_chart = [&]() -> const report::GnuplotChart& {
    if (!design_map) design_map = report::DesignMapChart(optim::ComputeDesignMap(r.request, result));
    return *design_map;
  };
  if (options.csv || options.plot_file) {
    try {
      if (options.csv) WriteFileAtomically(*options.csv, CandidatesCsv(result.candidates, result.rule));
      if (options.plot_file) RunGnuplot(*options.plot_file, design_map_chart());
    } catch (const OutputError& e) {
      return errors.Failed(e);
    } catch (const std::invalid_argument& e) {  // the map's oracle: as the design's, accepted above
      return errors.BadInput(e.what());
    }
  }
  if (options.json || options.report_file) {
    try {  // input's warnings, then the answer's
      PrintAndReport(out, options.json, report::DesignJson(r.request, result, r.warnings), options.run,
                     options.report_file, report::ReportKind::kOptimize, [&] { return std::vector{design_map_chart()}; });
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (options.json) return 0;
  if (options.csv) fmt::print(out, "Wrote {} ({} candidates)\n\n", *options.csv, result.candidates.size());
  if (options.plot_file) fmt::print(out, "Wrote {} (the design map)\n\n", *options.plot_file);

  PrintDesign(out, r, result);
  return 0;
}

}  // namespace covopt::cli
