#include "simulate.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fmt/ostream.h>

#include "covopt/core/exact.hpp"
#include "covopt/core/solve.hpp"
#include "covopt/core/impact_model.hpp"
#include "covopt/materials/catalog.hpp"
#include "covopt/optim/input_warnings.hpp"
#include "covopt/optim/robust_design.hpp"
#include "covopt/report/robust_json.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "quantity.hpp"
#include "report_option.hpp"
#include "scene_fields.hpp"
#include "scene_file.hpp"
#include "simulation_plan.hpp"
#include "output_options.hpp"
#include "rule_options.hpp"

namespace covopt::cli {
namespace {

constexpr std::string_view kFooter = R"(Values take a unit: 10kg, 2m/s, 15mm, "15 mm", 27.6MPa, 6.5GPa, 0.3.
A bare number is SI, and must be plausible: --robot-radius 40 would be 40 m
and is refused (write 40mm, or 40m if you mean it). Units: mass kg, g, t
('fixed' for an immovable body); length m, cm, mm, um ('flat' for the robot
radius); speed m/s, mm/s, cm/s, km/h; modulus and stress Pa, kPa, MPa, GPa,
N/m2, N/mm2; energy density J/m2, J/cm2, kJ/m2; time s, ms; acceleration m/s2;
contact damping s/m; stiffness N/m, kN/m; viscous damping N*s/m, Ns/m; Poisson
ratios, tolerances and the safety factor are plain numbers. Unset values come from --scene, else the
paper's scene (limits 1 MPa and 2.52 J/cm2, safety factor 1).
--material NAME takes the covering's E and ν from the catalog (built-in, plus
--catalog files); it overrides --scene and excludes --covering-modulus/-poisson.

Exit codes: 0 done; 1 the computation failed or an output could not be
written (e.g. gnuplot missing); 2 bad input.)";

}  // namespace

void SetupSimulate(CLI::App* sub, SimulateOptions& options) {
  sub->footer(std::string(kFooter));
  AddSceneOptions(*sub, options);
  AddRuleOptions(*sub, {.safety_factor = &options.safety_factor, .keep_travel = &options.keep_travel});

  sub->add_option("--method", options.method,
                  "auto (default: the exact energy balance where the scene admits it, else "
                  "the time path), exact, cvode (CVODE, see --cvode-method), or one "
                  "integrator: " + IntegratorNames() + fmt::format(". --history/--plot, "
                  "--braking and a neck need a time path: {} unless given",
                  ToString(TimeIntegrationOptions{}.method)))
      ->type_name("METHOD")
      ->group("Computation");
  sub->add_option("--cvode-method", options.cvode_method,
                  "CVODE family: adams (default) or bdf")
      ->check(CLI::IsMember({"adams", "bdf"}))
      ->group("Computation");
  sub->add_option("--rtol", options.rtol,
                  fmt::format("time-path relative tolerance (default {:g})",
                              TimeIntegrationOptions{}.relative_tolerance))
      ->type_name("RATIO")
      ->group("Computation");
  sub->add_option("--atol", options.atol,
                  "time-path absolute tolerance, scaled per component (default: rtol)")
      ->type_name("RATIO")
      ->group("Computation");

  sub->add_option("--max-steps", options.max_steps,
                  fmt::format("time-path limit on internal steps; reaching it fails the run "
                              "(default {})",
                              TimeIntegrationOptions{}.max_steps))
      ->type_name("N")
      ->group("Computation");

  AddRobotModelOptions(*sub, options.robot_model, true, "Robot model (instead of --robot-mass)");
  AddBodyRegionOptions(*sub, options.body);
  options.accept_ranges = true;
  AddUncertaintyOptions(*sub, options.uncertainty, true);
  sub->add_flag("--sensitivities", options.sensitivities,
                "the elasticity d ln r / d ln x of each injury ratio and the compression ratio to every scene "
                "input (at the worst case with ranges); with --plot, a tornado chart")
      ->group("Uncertainty");
  AddJsonFlag(*sub, options.json);
  AddOutputFileOption(*sub, "--history", options.history_file, "write the time history as CSV (uses the time path)", "FILE.csv");
  AddOutputFileOption(*sub, "--plot", options.plot_file, "draw force and stress against time with gnuplot (uses the time path)", "FILE.png|FILE.svg");
  AddReportOption(*sub, options.report);
}

namespace {

/// The tables of an uncertain simulation: the ranges and the worst case (with ranges), the
/// impact there, the probability of injury and the elasticities (when computed).
void PrintUncertainSimulation(std::ostream& out, const SimulationPlan& plan, const SimulationReport& report,
                              const optim::UncertaintyBox* box, const optim::WorstCase& worst,
                              const optim::InjuryProbability* probability,
                              const optim::ElasticityTable* elasticities) {
  if (box) {
    fmt::print(out, "Scene ranges: {} inputs; the impact below is the worst case over the box\n", box->size());
    for (const SceneRange& range : plan.ranges) {
      fmt::print(out, "  {:<20} {} .. {}  (from {})\n", range.name,
                 FormatQuantity(range.low, FindSceneField(range.name)->spec.kind),
                 FormatQuantity(range.high, FindSceneField(range.name)->spec.kind), range.source);
    }
    PrintWorstCase(out, *box, worst);
    PrintTimePathUse(out, *box, worst.time_path);
    out << '\n';
  }
  PrintTable(out, report);
  if (probability) {
    out << '\n';
    PrintInjuryProbability(out, *probability);
    if (box) PrintTimePathUse(out, *box, probability->time_path);
  }
  if (elasticities) {
    out << '\n';
    PrintElasticities(out, *elasticities);
  }
}

/// simulate with scene ranges, --samples or --sensitivities (docs/model.md §11): the worst
/// case over the box reported as an impact at that scene, the probability of injury and the
/// elasticities. Everything runs on the exact path.
int RunUncertainSimulate(const SimulateOptions& options, const SimulationPlan& plan,
                         const std::optional<std::string>& tornado_file, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "simulate");
  std::optional<optim::UncertaintyBox> box;
  std::optional<optim::InjuryProbabilityOptions> sampling;
  try {
    sampling = ResolveSampling(options.uncertainty, plan.ranges);
    if (!plan.ranges.empty()) {
      box.emplace(MakeUncertaintyBox(plan.scene, ResolveUncertainInputs(plan.ranges, options.uncertainty.distributions),
                                     plan.ranges));
      // A braking robot takes the time path by itself (screened by the exact path's bound,
      // docs/model.md §11); a time path asked for by a flag is refused.
      if (plan.time_path && (options.method || plan.history_file || plan.plot_file)) {
        throw InputError(fmt::format("{} with scene ranges: the worst case and the probability are computed on the "
                                     "exact path (the time path for a braking robot); drop it",
                                     plan.history_file ? "--history" : plan.plot_file ? "--plot" : "--method"));
      }
    } else if (plan.time_path && options.sensitivities && (options.method || plan.history_file)) {
      throw InputError(fmt::format("--sensitivities are computed on the exact path; {} does not apply",
                                   plan.history_file ? "--history" : "--method"));
    }
  } catch (const InputError& e) {
    return errors.BadInput(e.what());
  }

  SimulationReport report;
  optim::WorstCase worst;
  std::optional<optim::InjuryProbability> probability;
  std::optional<optim::ElasticityTable> elasticities;
  try {
    report.scene = plan.scene;
    if (box) {
      optim::WorstCaseOptions worst_options;
      worst_options.safety_factor = plan.safety_factor;
      worst_options.limits = plan.limits;
      // The material's strength: a crushed covering fails the worst case (docs/model.md §12).
      worst_options.compressive_strength_Pa = CrushCheckOf(plan).compressive_strength_Pa;
      worst = optim::FindWorstCase(*box, worst_options);
      report.scene = worst.scene;
    }
    if (plan.covering_material) {
      report.covering_material = plan.covering_material->name;
      report.covering_poisson_assumed = !plan.covering_material->poisson_ratio.has_value();
    }
    const ImpactModel model = ImpactModel::FromScene(report.scene);
    report.result = report.scene.robot_brakes() ? Solve(model, plan.solve) : SolveExact(model);
    if (sampling && box) {
      SamplingProgressBar bar(err, "sampling");
      sampling->safety_factor = plan.safety_factor;
      sampling->limits = plan.limits;
      sampling->compressive_strength_Pa = CrushCheckOf(plan).compressive_strength_Pa;
      sampling->progress = bar.Callback();
      probability = optim::EstimateInjuryProbability(*box, *sampling);
    }
    if (options.sensitivities) {
      optim::ElasticityOptions elasticity_options;
      elasticity_options.limits = plan.limits;
      elasticities = optim::ComputeElasticities(report.scene, elasticity_options);
    }
  } catch (const InputError& e) {
    return errors.BadInput(e.what());
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(AttributeError(e.what(), plan));
  } catch (const std::runtime_error& e) {  // a braking robot's time path failed at the scene
    return errors.Failed(e.what());
  }
  if (!report.result.ok()) {
    return errors.Failed(fmt::format("the computation failed: {} ({})", ToString(report.result.status),
                                     report.result.message));
  }
  Judge(report, plan);
  report.input_warnings = InputWarnings(plan);
  try {
    if (tornado_file) {
      if (!FindOnPath("gnuplot")) return errors.Failed(kGnuplotMissing);
      PlotTornado(*tornado_file, *elasticities, PlotFormatFor(*tornado_file) == PlotFormat::kSvg);
    }
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }

  if (plan.json || options.report.file) {
    try {
      PrintAndReport(out, plan.json,
                     report::UncertainSimulationJson(report, box ? &*box : nullptr, box ? &worst : nullptr,
                                                     probability ? &*probability : nullptr,
                                                     elasticities ? &*elasticities : nullptr),
                     options.run, options.report, plan.inputs, report::ReportKind::kSimulate, nullptr);
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (!plan.json) {
    PrintUncertainSimulation(out, plan, report, box ? &*box : nullptr, worst, probability ? &*probability : nullptr,
                             elasticities ? &*elasticities : nullptr);
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace

int RunSimulate(const SimulateOptions& options, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "simulate");
  if (options.body.any()) {  // ISO/TS 15066 body regions (simulate_body_region.cpp)
    return RunWithBodyRegions(options.body, errors, [&](const BodyRegionPlan& regions) {
      return RunBodyRegionSimulate(options, regions, out, err);
    });
  }

  SimulationPlan plan;
  std::optional<ImpactModel> model;
  SimulationReport report;
  // With --sensitivities, --plot draws the tornado chart (no time path for it).
  std::optional<std::string> tornado_file;
  try {
    if (options.sensitivities && options.plot_file) {
      if (!PlotFormatFor(*options.plot_file)) {
        throw InputError(fmt::format("--plot: cannot tell the format of '{}'; name the file *.png or *.svg",
                                     *options.plot_file));
      }
      SimulateOptions without_plot = options;
      without_plot.plot_file.reset();
      tornado_file = options.plot_file;
      plan = ResolveSimulation(without_plot);
    } else {
      plan = ResolveSimulation(options);
    }
  } catch (const InputError& e) {
    return errors.BadInput(e.what());
  }
  if (!plan.ranges.empty() || options.sensitivities || options.uncertainty.samples ||
      !options.uncertainty.distributions.empty() || options.uncertainty.seed || options.uncertainty.threads) {
    if ((options.uncertainty.seed || options.uncertainty.threads) && !options.uncertainty.samples) {
      return errors.BadInput(fmt::format("{} applies with --samples N", options.uncertainty.seed ? "--seed" : "--threads"));
    }
    return RunUncertainSimulate(options, plan, tornado_file, out, err);
  }
  try {
    model.emplace(ImpactModel::FromScene(plan.scene));
  } catch (const std::invalid_argument& e) {  // the library's range checks
    return errors.BadInput(AttributeError(e.what(), plan));
  }
  try {
    report.scene = plan.scene;
    if (plan.covering_material) {
      report.covering_material = plan.covering_material->name;
      report.covering_poisson_assumed = !plan.covering_material->poisson_ratio.has_value();
    }
    if (plan.time_path) report.time_options = plan.solve.time_path;
    report.result = Solve(*model, plan.solve);  // smooth histories: ~400 samples over the contact
  } catch (const std::invalid_argument& e) {  // the integrator's option checks
    return errors.BadInput(e.what());
  }

  const ImpactResult& result = report.result;
  if (!result.ok()) {
    return errors.Failed(fmt::format("the computation failed: {} ({}, code {}){}{}", ToString(result.status),
                              ToString(result.method), result.raw_code,
                              result.message.empty() ? "" : ": ", result.message));
  }
  Judge(report, plan);  // the chart draws the derated limits
  report.input_warnings = InputWarnings(plan);

  try {
    // Check for gnuplot before writing anything, so that a missing tool leaves no files.
    if ((plan.plot_file || options.report.file) && !FindOnPath("gnuplot")) return errors.Failed(kGnuplotMissing);
    if (plan.history_file) WriteFileAtomically(*plan.history_file, HistoryCsv(*model, result.history));
    if (plan.plot_file) PlotHistory(*plan.plot_file, report);
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }

  if (plan.json || options.report.file) {
    try {  // the object covopt.simulate() returns
      PrintAndReport(out, plan.json, report::SimulationJson(report), options.run, options.report, plan.inputs,
                     report::ReportKind::kSimulate, [&] { return std::vector{report::HistoryChart(report)}; });
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (!plan.json) {
    PrintTable(out, report);
    if (plan.history_file || plan.plot_file) {
      fmt::print(out, "Wrote      {}{}{}\n", plan.history_file.value_or(""),
                 plan.history_file && plan.plot_file ? ", " : "", plan.plot_file.value_or(""));
    }
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace covopt::cli
