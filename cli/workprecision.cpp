#include "workprecision.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include "covopt/chart/work_precision_chart.hpp"
#include "covopt/core/work_precision.hpp"
#include "covopt/optim/design_work_precision.hpp"
#include "covopt/report/work_precision_report.hpp"
#include "covopt/report/work_precision_text.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "plot.hpp"
#include "progress.hpp"
#include "quantity.hpp"
#include "output_options.hpp"

namespace covopt::cli {
namespace {



// --- the optimiser-level study (--design) ----------------------------------------------

std::vector<ComputationMethod> ResolveMethods(const std::vector<std::string>& names);

using optim::DesignWorkPrecisionResult;

/// `covopt workprecision --design`.
int RunDesignStudy(const WorkPrecisionOptions& options, std::ostream& out, std::ostream& err,
                   const CommandErrors& errors) {
  SimulationPlan scene_plan;
  optim::DesignWorkPrecisionOptions study_options;
  std::vector<std::pair<std::string, PlotFormat>> charts;
  try {
    if (options.restart != "both") throw InputError("--restart applies to the integrator study, not to --design");
    if (options.repeats != 0) throw InputError("--repeats applies to the integrator study, not to --design");
    scene_plan = ResolveSimulation(options.scene);
    if (!options.methods.empty()) study_options.methods = ResolveMethods(options.methods);
    study_options.relative_tolerances =
        ParseToleranceLadder(options.tolerances == WorkPrecisionOptions{}.tolerances ? "1e-4..1e-10" : options.tolerances);
    for (const auto& [flag, file] : {std::pair{"--plot", options.plot_file},
                                     std::pair{"--tolerance-plot", options.tolerance_plot_file}}) {
      if (!file) continue;
      const auto format = PlotFormatFor(*file);
      if (!format) {
        throw InputError(fmt::format("{}: cannot tell the format of '{}'; name the file *.png or *.svg", flag, *file));
      }
      charts.emplace_back(*file, *format);
    }
    if (options.csv_file && options.csv_file->empty()) throw InputError("--csv: empty file name");
  } catch (const InputError& e) {
    return errors.BadInput(e.what());
  }
  if (!charts.empty() && !FindOnPath("gnuplot")) return errors.Failed(std::string(kGnuplotMissing));
  ProgressBar bar(err, "workprecision --design");
  if (bar.enabled()) {
    study_options.progress = [&bar](const optim::DesignWorkPrecisionProgress& progress) {
      bar.Update(progress.completed_searches, progress.total_searches);
    };
  }
  DesignWorkPrecisionResult study;
  try {
    study = optim::MeasureDesignWorkPrecision(scene_plan.scene, study_options);
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(AttributeError(e.what(), scene_plan));
  }
  bar.Finish();
  if (!study.IsUsable()) return errors.Failed(study.message);
  Scene shown = scene_plan.scene;
  shown.covering.thickness_m = 0.0;
  const std::string title = options.title ? *options.title : report::DesignedSceneHeadline(shown);
  try {
    if (options.csv_file) WriteFileAtomically(*options.csv_file, report::DesignWorkPrecisionCsv(study));
    if (options.plot_file) {
      RunGnuplot(*options.plot_file, [&](const std::string& path) {
        return chart::DesignWorkPrecisionChart(study, true, *PlotFormatFor(*options.plot_file), path, title);
      });
    }
    if (options.tolerance_plot_file) {
      RunGnuplot(*options.tolerance_plot_file, [&](const std::string& path) {
        return chart::DesignWorkPrecisionChart(study, false, *PlotFormatFor(*options.tolerance_plot_file), path, title);
      });
    }
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }
  if (options.json) {
    out << WithRunProvenance(report::DesignWorkPrecisionJson(study, shown), options.run) << '\n';
  } else {
    report::PrintDesignWorkPrecision(out, study, shown);
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

std::vector<ComputationMethod> ResolveMethods(const std::vector<std::string>& names) {
  if (names.empty()) return TimeIntegrationMethods();
  std::vector<ComputationMethod> methods;
  for (const std::string& name : names) {
    const auto method = ParseComputationMethod(name);
    if (!method || *method == ComputationMethod::kExact) {
      throw InputError(fmt::format("--methods: unknown integrator '{}'; expected some of {}",
                                   name, IntegratorNames()));
    }
    if (std::find(methods.begin(), methods.end(), *method) == methods.end()) {
      methods.push_back(*method);
    }
  }
  return methods;
}

RestartSeries ResolveRestart(const std::string& restart) {
  if (restart == "on") return RestartSeries::kOn;
  if (restart == "off") return RestartSeries::kOff;
  if (restart == "both") return RestartSeries::kBoth;
  throw InputError(fmt::format("--restart: expected on, off or both (got '{}')", restart));
}

}  // namespace

std::vector<double> ParseToleranceLadder(const std::string& text) {
  const QuantitySpec ratio{QuantityKind::kDimensionless};
  std::vector<double> tolerances;
  const auto check = [&](double value, std::string_view typed) {
    if (!(value >= 1e-14 && value <= 1e-2)) {
      throw InputError(fmt::format("--tolerances: each tolerance must be in [1e-14, 1e-2] "
                                   "(got '{}')",
                                   typed));
    }
    return value;
  };
  if (const auto dots = text.find(".."); dots != std::string::npos) {
    const std::string first_text = text.substr(0, dots);
    const std::string last_text = text.substr(dots + 2);
    const double first = check(ParseQuantity(first_text, ratio, "--tolerances"), first_text);
    const double last = check(ParseQuantity(last_text, ratio, "--tolerances"), last_text);
    const double from = std::log10(std::max(first, last));
    const double to = std::log10(std::min(first, last));
    // Every decade from the larger to the smaller, both ends included.
    for (double exponent = from; exponent >= to - 1e-9; exponent -= 1.0) {
      tolerances.push_back(std::pow(10.0, exponent));
    }
    if (std::abs(std::log10(tolerances.back()) - to) > 1e-9) tolerances.push_back(std::min(first, last));
  } else {
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t comma = text.find(',', start);
      const std::string item =
          text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      tolerances.push_back(check(ParseQuantity(item, ratio, "--tolerances"), item));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  if (tolerances.empty()) {
    throw InputError(fmt::format("--tolerances: no tolerance in '{}'", text));
  }
  return tolerances;
}


void SetupWorkPrecision(CLI::App* sub, WorkPrecisionOptions& options) {
  sub->footer(
      "Each run's errors are relative to the exact path (the reference for every peak);\n"
      "time is the median CPU time per impact of repeated runs. Scene flags as in\n"
      "'covopt simulate' (default: the paper's scene, 15 mm covering of 27.6 MPa).\n\n"
      "Exit codes: 0 done (failed runs are reported as data); 1 an output could not be\n"
      "written; 2 bad input.");
  AddSceneOptions(*sub, options.scene);
  sub->add_option("--methods", options.methods,
                  "integrators to measure, comma-separated (default: all): " + IntegratorNames())
      ->delimiter(',')
      ->type_name("NAME,...")
      ->group("Study");
  sub->add_option("--tolerances", options.tolerances,
                  "relative tolerances: a decade ladder 'A..B' or a list 'a,b,c', each in "
                  "[1e-14, 1e-2] (default 1e-3..1e-12)")
      ->type_name("LADDER")
      ->group("Study");
  sub->add_option("--restart", options.restart,
                  "restart at the phase switches: on, off (straight through the kinks), or "
                  "both as separate series (default both)")
      ->check(CLI::IsMember({"on", "off", "both"}))
      ->group("Study");
  sub->add_option("--repeats", options.repeats,
                  "timed runs per point, the median reported (default 0: automatic, >= 3)")
      ->check(CLI::Range(0, 100000))
      ->type_name("N")
      ->group("Study");
  AddJsonFlag(*sub, options.json, "print one JSON object instead of the table");
  AddOutputFileOption(*sub, "--csv", options.csv_file, "write every run as a CSV row", "FILE.csv");
  AddOutputFileOption(*sub, "--plot", options.plot_file, "chart worst error against CPU time per impact (log-log), gnuplot", "FILE.png|FILE.svg");
  AddOutputFileOption(*sub, "--tolerance-plot", options.tolerance_plot_file, "chart worst error against the requested tolerance, gnuplot", "FILE.png|FILE.svg");
  sub->add_option("--title", options.title, "scene name for the chart titles")
      ->type_name("TEXT")
      ->group("Output");
  sub->add_flag("--design", options.design,
                "the optimiser-level study instead: the thinnest-safe-covering search on the exact path and on "
                "the time path per --methods (default arkode-erk54, cvode-adams, cvode-bdf) and --tolerances "
                "(default 1e-4..1e-10); errors of b_c* and E_c* against the exact optimum, CPU time per search")
      ->group("Study");
}

int RunWorkPrecision(const WorkPrecisionOptions& options, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "workprecision");
  if (options.design) return RunDesignStudy(options, out, err, errors);

  SimulationPlan scene_plan;
  covopt::WorkPrecisionOptions study_options;
  std::optional<ImpactModel> model;
  std::vector<std::pair<std::string, PlotFormat>> charts;
  try {
    scene_plan = ResolveSimulation(options.scene);
    study_options.methods = ResolveMethods(options.methods);
    study_options.relative_tolerances = ParseToleranceLadder(options.tolerances);
    study_options.restart = ResolveRestart(options.restart);
    if (options.repeats < 0 || options.repeats > 100000) {
      throw InputError(
          fmt::format("--repeats must be in [0, 100000] (got {})", options.repeats));
    }
    study_options.repetitions = options.repeats;
    for (const auto& [flag, file] : {std::pair{"--plot", options.plot_file},
                                     std::pair{"--tolerance-plot", options.tolerance_plot_file}}) {
      if (!file) continue;
      const auto format = PlotFormatFor(*file);
      if (!format) {
        throw InputError(fmt::format("{}: cannot tell the format of '{}'; name the file *.png "
                                     "or *.svg",
                                     flag, *file));
      }
      charts.emplace_back(*file, *format);
    }
    if (options.csv_file && options.csv_file->empty()) throw InputError("--csv: empty file name");
  } catch (const InputError& e) {
    return errors.BadInput(e.what());
  }
  try {
    model.emplace(ImpactModel::FromScene(scene_plan.scene));
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(AttributeError(e.what(), scene_plan));
  }
  if (!charts.empty() && !FindOnPath("gnuplot")) return errors.Failed(std::string(kGnuplotMissing));

  // A progress bar on an interactive terminal only: pipes and tests see nothing.
  ProgressBar bar(err, "workprecision");
  if (bar.enabled()) {
    study_options.progress = [&bar](const WorkPrecisionProgress& progress) {
      bar.Update(progress.completed_runs, progress.total_runs);
    };
  }
  const WorkPrecisionResult study = MeasureWorkPrecision(*model, study_options);
  bar.Finish();
  if (!study.IsUsable()) return errors.Failed(study.message);
  const std::vector<WorkPrecisionPoint>& points = study.points;

  std::string title = options.title ? *options.title : SceneHeadline(scene_plan.scene);
  if (const auto details = SceneDetailsBeyondHeadline(scene_plan.scene);
      !options.title && !details.empty()) {
    title += fmt::format("; {}", fmt::join(details, ", "));
  }
  try {
    if (options.csv_file) WriteFileAtomically(*options.csv_file, report::WorkPrecisionCsv(points));
    if (options.plot_file) {
      RunGnuplot(*options.plot_file, [&](const std::string& path) {
        return chart::WorkPrecisionChart(study, *PlotFormatFor(*options.plot_file), path, title);
      });
    }
    if (options.tolerance_plot_file) {
      RunGnuplot(*options.tolerance_plot_file, [&](const std::string& path) {
        return chart::WorkPrecisionToleranceChart(study, *PlotFormatFor(*options.tolerance_plot_file), path, title);
      });
    }
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }

  if (options.json) {
    out << WithRunProvenance(report::WorkPrecisionJson(study, scene_plan.scene), options.run) << '\n';
  } else {
    report::PrintWorkPrecision(out, study, scene_plan.scene);
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace covopt::cli
