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
#include "covopt/core/verdict.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/quantity.hpp"
#include "covopt/materials/catalog.hpp"
#include "covopt/optim/design.hpp"
#include "covopt/optim/design_map.hpp"
#include "covopt/report/design_csv.hpp"
#include "covopt/report/design_json.hpp"
#include "covopt/report/design_text.hpp"
#include "covopt/report/robust_json.hpp"
#include "design_flag_ranges.hpp"
#include "optimize_resolve.hpp"
#include "errors.hpp"
#include "catalog_options.hpp"
#include "oracle_options.hpp"
#include "output.hpp"
#include "plot.hpp"
#include "quantity.hpp"
#include "report_option.hpp"
#include "scene_fields.hpp"
#include "scene_file.hpp"
#include "simulation_plan.hpp"
#include "output_options.hpp"
#include "rule_options.hpp"

namespace covopt::cli {
namespace {


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


/// What the design's text (covopt/report/design_text.hpp) reads beside the result.
report::DesignText TextOf(const Resolved& r) {
  report::DesignText text{.request = r.request, .ranges = {}, .warnings = r.warnings, .runners_up = r.runners_up};
  for (const SceneRange& range : r.ranges) text.ranges.push_back({range.name, range.text, range.source});
  return text;
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
  if (o.json || o.report.file) {
    try {
      PrintAndReport(out, o.json, report::ProbabilityDesignJson(inputs.box, options, result, r.warnings), o.run,
                     o.report, r.inputs, report::ReportKind::kOptimize, nullptr);
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (!o.json) {
    report::PrintProbabilityDesign(out, TextOf(r), inputs.box, options, result);
  }
  return 0;
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
  if (o.json || o.report.file) {
    try {
      PrintAndReport(out, o.json,
                     report::RobustDesignJson(inputs->box, options, result, probability ? &*probability : nullptr,
                                              r.warnings),
                     o.run, o.report, r.inputs, report::ReportKind::kOptimize, nullptr);
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (!o.json) {
    report::PrintRobustDesign(out, TextOf(r), inputs->box, options, result, probability);
  }
  return 0;
}

}  // namespace

void SetupOptimize(CLI::App* sub, OptimizeOptions& options) {
  sub->footer(std::string(kFooter));
  AddSceneFieldOptions(*sub, options.scene_file, options.scene_values, options.choices, false);  // not the covering
  sub->add_option("--max-thickness", options.max_thickness, "thickest covering considered (default 50 mm)")
      ->type_name("LENGTH")->group("Design");
  sub->add_option("--min-modulus", options.min_modulus, "softest covering of the continuous search (default 0.1 MPa)")
      ->type_name("MODULUS")->group("Design");
  sub->add_option("--max-modulus", options.max_modulus, "stiffest covering of the continuous search (default 1 GPa)")
      ->type_name("MODULUS")->group("Design");
  AddRuleOptions(*sub, {.laceration_limit = &options.laceration_limit,
                        .contusion_limit = &options.contusion_limit,
                        .safety_factor = &options.safety_factor,
                        .allow_full_compression = &options.allow_full_compression,
                        .allow_crushing = &options.allow_crushing,
                        .allow_unknown_strength = &options.allow_unknown_strength});
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
  AddJsonFlag(*sub, options.json, "print one JSON object (SI units) instead of the report");
  AddReportOption(*sub, options.report);
  AddOutputFileOption(*sub, "--csv", options.csv, "write every candidate to FILE as CSV (SI units in the header)", "FILE");
  AddOutputFileOption(*sub, "--plot", options.plot_file, "chart with gnuplot: the design map, the governing ratio over thickness x modulus with each "
                  "criterion's limit and the chosen design (the head's design only)", "FILE.png|FILE.svg");
}

int RunOptimize(const OptimizeOptions& options, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "optimize");
  Resolved r;
  try {
    r = ResolveOptimize(options);
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
  if (options.body.any()) {  // ISO/TS 15066 body regions (optimize_body_region.cpp)
    if (!r.ranges.empty()) {
      return errors.BadInput(fmt::format("{} '{}': scene ranges (uncertain inputs) are not taken with --body-region",
                                         r.ranges.front().source, r.ranges.front().text));
    }
    return RunWithBodyRegions(options.body, errors, [&](const BodyRegionPlan& regions) {
      return RunBodyRegionOptimize(options, r.request, r.inputs, r.warnings, regions, out, err);
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
  if ((options.plot_file || options.report.file) && !FindOnPath("gnuplot")) return errors.Failed(kGnuplotMissing);
  // The design map, computed once for --plot and --report.
  std::optional<report::GnuplotChart> design_map;
  const auto design_map_chart = [&]() -> const report::GnuplotChart& {
    if (!design_map) design_map = report::DesignMapChart(optim::ComputeDesignMap(r.request, result));
    return *design_map;
  };
  if (options.csv || options.plot_file) {
    try {
      if (options.csv) WriteFileAtomically(*options.csv, report::DesignCandidatesCsv(result.candidates, result.rule));
      if (options.plot_file) RunGnuplot(*options.plot_file, design_map_chart());
    } catch (const OutputError& e) {
      return errors.Failed(e);
    } catch (const std::invalid_argument& e) {  // the map's oracle: as the design's, accepted above
      return errors.BadInput(e.what());
    }
  }
  if (options.json || options.report.file) {
    try {  // input's warnings, then the answer's
      PrintAndReport(out, options.json, report::DesignJson(r.request, result, r.warnings), options.run,
                     options.report, r.inputs, report::ReportKind::kOptimize, [&] { return std::vector{design_map_chart()}; });
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (options.json) return 0;
  if (options.csv) fmt::print(out, "Wrote {} ({} candidates)\n\n", *options.csv, result.candidates.size());
  if (options.plot_file) fmt::print(out, "Wrote {} (the design map)\n\n", *options.plot_file);

  report::PrintDesign(out, TextOf(r), result);
  return 0;
}

}  // namespace covopt::cli
