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
#include <nlohmann/json.hpp>

#include "covopt/core/work_precision.hpp"
#include "covopt/optim/design_work_precision.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "plot.hpp"
#include "progress.hpp"
#include "quantity.hpp"

namespace covopt::cli {
namespace {

using Json = nlohmann::ordered_json;

std::string SeriesName(ComputationMethod method, bool restart) {
  if (method == ComputationMethod::kExact) return "exact path";
  return fmt::format("{}{}", ToString(method), restart ? "" : ", no restart");
}

/// A number for CSV/JSON: shortest round-trip, empty/null when absent or not finite.
std::string CsvNumber(double value) { return std::isfinite(value) ? fmt::format("{}", value) : ""; }

// --- charts -------------------------------------------------------------------------

constexpr std::array<std::string_view, 8> kColors = {"#1f5fa8", "#c0392b", "#27ae60", "#8e44ad",
                                                      "#d35400", "#16a085", "#7f8c8d", "#b7950b"};

std::string_view ColorOf(ComputationMethod method) {
  const auto methods = TimeIntegrationMethods();
  const auto it = std::find(methods.begin(), methods.end(), method);
  const auto index = static_cast<std::size_t>(it - methods.begin());
  return kColors[index % kColors.size()];
}

std::string ChartHeader(PlotFormat format, const std::string& output_path,
                        const std::string& title) {
  std::string s = "set encoding utf8\n" + GnuplotTerminal(format, 1100, 900);
  s += fmt::format("set output {}\n", GnuplotQuoted(output_path));
  s += fmt::format("set title {}\n", GnuplotQuoted(title));
  s += "set logscale xy\nset format x '%.0e'\nset format y '%g'\n";
  s += "set grid xtics ytics mxtics mytics linecolor rgb '#e5e5e5'\n";
  s += "set key below horizontal maxcols 3 spacing 1.1 width -2\n";
  return s;
}

/// Floor for log axes: an error of exactly 0 is drawn here.
constexpr double kErrorFloor = 1e-16;

/// One inline data block per series (x y), the plot command drawing them.
std::string SeriesPlot(const WorkPrecisionResult& study, bool time_on_y, std::string& blocks) {
  const std::vector<WorkPrecisionPoint>& points = study.points;
  std::vector<std::string> commands;
  int index = 0;
  for (const WorkPrecisionSeries& series : study.series) {
    std::string data;
    for (const WorkPrecisionPoint& p : points) {
      if (p.method != series.method || p.restart != series.restart) continue;
      if (p.status != SolveStatus::kSuccess) continue;
      const double error = std::max(p.worst_error, kErrorFloor);
      data += time_on_y ? fmt::format("{} {}\n", error, p.seconds_per_impact * 1e6)
                        : fmt::format("{} {}\n", p.relative_tolerance, error);
    }
    if (data.empty()) continue;
    blocks += fmt::format("$s{} << EOD\n{}EOD\n", index, data);
    commands.push_back(fmt::format(
        "$s{} using 1:2 with linespoints linewidth 2 pointtype {} pointsize 0.9 dashtype {} "
        "linecolor rgb '{}' title {}",
        index, series.restart ? 7 : 6, series.restart ? 1 : 2, ColorOf(series.method),
        GnuplotQuoted(SeriesName(series.method, series.restart))));
    ++index;
  }
  std::string plot;
  for (std::size_t i = 0; i < commands.size(); ++i) {
    plot += (i == 0 ? "plot " : ", \\\n     ") + commands[i];
  }
  return plot;
}

std::string WorkChart(const WorkPrecisionResult& study, PlotFormat format,
                      const std::string& output_path, const std::string& title) {
  std::string s = ChartHeader(format, output_path,
                              "Work-precision: " + title);
  s += "set xlabel 'worst relative error of δmax, Fmax, σc,max, eA,max and T against the "
       "exact path [-]'\n";
  s += "set ylabel 'CPU time per impact [µs] (median)'\n";
  std::string blocks;
  std::string plot = SeriesPlot(study, true, blocks);
  const std::vector<WorkPrecisionPoint>& points = study.points;
  const auto exact = std::find_if(points.begin(), points.end(), [](const WorkPrecisionPoint& p) {
    return p.method == ComputationMethod::kExact;
  });
  if (exact != points.end()) {
    blocks += fmt::format("$exact << EOD\n{} {}\nEOD\n", kErrorFloor, exact->seconds_per_impact * 1e6);
    plot += fmt::format(
        "{}$exact using 1:2 with points pointtype 5 pointsize 1.6 linecolor rgb 'black' "
        "title 'exact path (the reference; error 0, drawn at 1e-16)'",
        plot.empty() ? "plot " : ", \\\n     ");
  }
  return s + blocks + plot + "\nunset output\n";
}

std::string ToleranceChart(const WorkPrecisionResult& study, PlotFormat format,
                           const std::string& output_path, const std::string& title) {
  std::string s = ChartHeader(format, output_path,
                              "Does each method keep its promise? " + title);
  s += "set xlabel 'requested relative tolerance rtol (atol = rtol) [-]'\n";
  s += "set ylabel 'worst relative error against the exact path [-]'\n";
  s += "set xrange [*:*] reverse\n";
  std::string blocks;
  std::string plot = SeriesPlot(study, false, blocks);
  if (plot.empty()) plot = "plot NaN notitle";
  plot += ", \\\n     x with lines dashtype 3 linewidth 2 linecolor rgb '#444444' "
          "title 'error = rtol', \\\n     100*x with lines dashtype 4 linewidth 1 "
          "linecolor rgb '#999999' title 'error = 100 rtol'";
  return s + blocks + plot + "\nunset output\n";
}

// --- text, JSON -------------------------------------------------------------------

void PrintStudy(std::ostream& out, const WorkPrecisionResult& study, const Scene& scene) {
  const std::vector<WorkPrecisionPoint>& points = study.points;
  fmt::print(out, "Scene   {}\n", SceneHeadline(scene));
  fmt::print(out, "Errors  relative to the exact path; time = median CPU time per impact\n\n");
  fmt::print(out, "{:<29} {:>7} {:>9} {:>8} {:>8} {:>8} {:>8} {:>8} {:>9} {:>10} {:>7} {:>7} {:>5} {:>5}\n",
             "method", "rtol", "worst", "δmax", "Fmax", "σc,max", "eA,max", "T", "residual",
             "µs/impact", "steps", "rhs", "jac", "fail");
  const ComputationMethod* last = nullptr;
  bool last_restart = true;
  for (const WorkPrecisionPoint& p : points) {
    if (last && (*last != p.method || last_restart != p.restart)) fmt::print(out, "\n");
    last = &p.method;
    last_restart = p.restart;
    const std::string name = SeriesName(p.method, p.restart);
    const std::string rtol =
        p.method == ComputationMethod::kExact ? std::string("-") : fmt::format("{:.0e}", p.relative_tolerance);
    if (p.status != SolveStatus::kSuccess) {
      fmt::print(out, "{:<29} {:>7} FAILED: {} after {} steps ({:.1f} µs): {}\n", name, rtol,
                 ToString(p.status), p.statistics.steps, p.seconds_per_impact * 1e6,
                 p.message.substr(0, 90));
      continue;
    }
    const std::string residual =
        p.energy_residual ? fmt::format("{:.1e}", *p.energy_residual) : std::string("-");
    fmt::print(out,
               "{:<29} {:>7} {:>9.2e} {:>8.1e} {:>8.1e} {:>8.1e} {:>8.1e} {:>8.1e} {:>9} {:>10.2f} "
               "{:>7} {:>7} {:>5} {:>5}\n",
               name, rtol, p.worst_error, p.error_max_penetration, p.error_peak_force,
               p.error_max_compressive_stress, p.error_max_energy_density,
               p.error_contact_duration, residual, p.seconds_per_impact * 1e6, p.statistics.steps,
               p.statistics.rhs_evaluations, p.statistics.jacobian_evaluations,
               p.statistics.error_test_failures + p.statistics.convergence_failures);
  }

  fmt::print(out, "\nCheapest run reaching a worst error of\n");
  for (const CheapestRun& cheapest : study.cheapest) {
    const double target = cheapest.target_error;
    if (cheapest.point) {
      const WorkPrecisionPoint* best = &points[*cheapest.point];
      fmt::print(out, "  {:.0e}  {} at rtol {:.0e}: {:.1f} µs per impact (error {:.1e})\n", target,
                 SeriesName(best->method, best->restart), best->relative_tolerance,
                 best->seconds_per_impact * 1e6, best->worst_error);
    } else {
      fmt::print(out, "  {:.0e}  no run reached it\n", target);
    }
  }
  std::vector<std::string> broken;
  const double kept_ratio = study.kept_tolerance_ratio;
  for (const WorkPrecisionSeries& s : study.series) {
    if (s.worst_error_to_tolerance > kept_ratio) {
      broken.push_back(fmt::format("{} (error {:.0f} x rtol at rtol {:.0e})",
                                   SeriesName(s.method, s.restart), s.worst_error_to_tolerance,
                                   s.at_tolerance));
    }
    if (s.failures > 0) {
      broken.push_back(fmt::format("{} ({} failed run{})", SeriesName(s.method, s.restart),
                                   s.failures, s.failures == 1 ? "" : "s"));
    }
  }
  if (broken.empty()) {
    fmt::print(out, "Every series kept its error within {:g} x rtol.\n", kept_ratio);
  } else {
    fmt::print(out, "Not keeping the tolerance (error > {:g} x rtol) or failing:\n", kept_ratio);
    for (const std::string& line : broken) fmt::print(out, "  {}\n", line);
  }
}

Json PointJson(const WorkPrecisionPoint& p) {
  Json j{{"method", ToString(p.method)},
         {"restart_at_phase_switches", p.restart},
         {"relative_tolerance", JsonNumber(p.relative_tolerance)},
         {"status", ToString(p.status)},
         {"message", p.message},
         {"worst_error", JsonNumber(p.worst_error)},
         {"error_max_penetration", JsonNumber(p.error_max_penetration)},
         {"error_peak_force", JsonNumber(p.error_peak_force)},
         {"error_max_compressive_stress", JsonNumber(p.error_max_compressive_stress)},
         {"error_max_energy_density", JsonNumber(p.error_max_energy_density)},
         {"error_contact_duration", JsonNumber(p.error_contact_duration)},
         {"energy_residual", p.energy_residual ? JsonNumber(*p.energy_residual) : Json(nullptr)},
         {"seconds_per_impact", JsonNumber(p.seconds_per_impact)},
         {"timed_runs", p.timed_runs}};
  j.update(StatisticsToJson(p.statistics));
  j["warnings"] = p.warning_count;
  return j;
}

// --- the optimiser-level study (--design) ----------------------------------------------

std::vector<ComputationMethod> ResolveMethods(const std::vector<std::string>& names);

using optim::DesignWorkPrecisionPoint;
using optim::DesignWorkPrecisionResult;

std::string DesignSeriesName(const DesignWorkPrecisionPoint& p) {
  return p.oracle == optim::OracleKind::kExact ? std::string("exact path")
                                                : fmt::format("time path, {}", ToString(p.method));
}

/// The methods of the study, in the order measured.
std::vector<ComputationMethod> DesignMethods(const DesignWorkPrecisionResult& study) {
  std::vector<ComputationMethod> methods;
  for (const DesignWorkPrecisionPoint& p : study.points) {
    if (p.oracle == optim::OracleKind::kTimePath &&
        std::find(methods.begin(), methods.end(), p.method) == methods.end()) {
      methods.push_back(p.method);
    }
  }
  return methods;
}

/// One chart of the design study: for each method, the error of b_c* (solid) and of E_c*
/// (dashed) against the search's CPU time (`cost`) or against the requested rtol.
std::string DesignChart(const DesignWorkPrecisionResult& study, bool cost, PlotFormat format,
                        const std::string& output_path, const std::string& title) {
  std::string s = ChartHeader(format, output_path,
                              cost ? "Optimiser work-precision: " + title
                                   : "Does the time-path optimum keep its tolerance? " + title);
  if (cost) {
    s += "set xlabel 'relative error of the optimum against the exact path [-] (b_c*: solid, E_c*: dashed)'\n";
    s += "set ylabel 'CPU time of the thinnest-safe-covering search [s]'\n";
  } else {
    s += "set xlabel 'requested relative tolerance rtol of the time path [-]'\n";
    s += "set ylabel 'relative error of the optimum against the exact path [-] (b_c*: solid, E_c*: dashed)'\n";
    s += "set xrange [*:*] reverse\n";
  }
  std::string blocks;
  std::vector<std::string> commands;
  int index = 0;
  for (const ComputationMethod method : DesignMethods(study)) {
    for (const bool modulus : {false, true}) {
      std::string data;
      for (const DesignWorkPrecisionPoint& p : study.points) {
        if (p.oracle != optim::OracleKind::kTimePath || p.method != method) continue;
        const double error = modulus ? p.error_modulus : p.error_thickness;
        if (!std::isfinite(error)) continue;
        const double shown = std::max(error, kErrorFloor);
        data += cost ? fmt::format("{} {}\n", shown, p.seconds) : fmt::format("{} {}\n", p.relative_tolerance, shown);
      }
      if (data.empty()) continue;
      blocks += fmt::format("$d{} << EOD\n{}EOD\n", index, data);
      commands.push_back(fmt::format(
          "$d{} using 1:2 with linespoints linewidth 2 pointtype {} pointsize 0.9 dashtype {} linecolor rgb '{}' "
          "title {}",
          index, modulus ? 6 : 7, modulus ? 2 : 1, ColorOf(method),
          GnuplotQuoted(fmt::format("{}: {}", ToString(method), modulus ? "E_c*" : "b_c*"))));
      ++index;
    }
  }
  if (cost && !study.points.empty()) {
    blocks += fmt::format("$exact << EOD\n{} {}\nEOD\n", kErrorFloor, study.points.front().seconds);
    commands.push_back(
        "$exact using 1:2 with points pointtype 5 pointsize 1.6 linecolor rgb 'black' "
        "title 'exact path (the reference; error 0, drawn at 1e-16)'");
  }
  if (!cost) {
    commands.push_back("x with lines dashtype 3 linewidth 2 linecolor rgb '#444444' title 'error = rtol'");
    commands.push_back("100*x with lines dashtype 4 linewidth 1 linecolor rgb '#999999' title 'error = 100 rtol'");
  }
  std::string plot;
  for (std::size_t i = 0; i < commands.size(); ++i) plot += (i == 0 ? "plot " : ", \\\n     ") + commands[i];
  if (plot.empty()) plot = "plot NaN notitle";
  return s + blocks + plot + "\nunset output\n";
}

std::string DesignCsv(const DesignWorkPrecisionResult& study) {
  std::string csv =
      "oracle,method,relative_tolerance,feasible,thickness_m,youngs_modulus_Pa,error_thickness,error_modulus,"
      "contusion_ratio,seconds,evaluations,gradient_evaluations,failed_evaluations,local_termination,source\n";
  for (const DesignWorkPrecisionPoint& p : study.points) {
    const bool exact = p.oracle == optim::OracleKind::kExact;
    std::string source = p.source;
    std::replace(source.begin(), source.end(), '"', '\'');
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},\"{}\"\n", optim::ToString(p.oracle),
                       ToString(p.method), exact ? "" : CsvNumber(p.relative_tolerance), p.feasible ? 1 : 0,
                       CsvNumber(p.thickness_m), CsvNumber(p.modulus_Pa), CsvNumber(p.error_thickness),
                       CsvNumber(p.error_modulus), CsvNumber(p.contusion_ratio), CsvNumber(p.seconds), p.evaluations,
                       p.gradient_evaluations, p.failed_evaluations, p.local_termination, source);
  }
  return csv;
}

Json DesignPointJson(const DesignWorkPrecisionPoint& p) {
  const bool exact = p.oracle == optim::OracleKind::kExact;
  return Json{{"oracle", optim::ToString(p.oracle)},
              {"method", exact ? Json(nullptr) : Json(std::string(ToString(p.method)))},
              {"relative_tolerance", exact ? Json(nullptr) : JsonNumber(p.relative_tolerance)},
              {"feasible", p.feasible},
              {"thickness_m", JsonNumber(p.thickness_m)},
              {"youngs_modulus_Pa", JsonNumber(p.modulus_Pa)},
              {"error_thickness", JsonNumber(p.error_thickness)},
              {"error_modulus", JsonNumber(p.error_modulus)},
              {"contusion_ratio", JsonNumber(p.contusion_ratio)},
              {"seconds", JsonNumber(p.seconds)},
              {"evaluations", p.evaluations},
              {"gradient_evaluations", p.gradient_evaluations},
              {"failed_evaluations", p.failed_evaluations},
              {"local_termination", p.local_termination},
              {"source", p.source}};
}

/// The scene line of the design study: the covering is what the search designs.
std::string DesignedSceneHeadline(const Scene& scene) {
  std::string headline = SceneHeadline(scene);
  if (const auto at = headline.find("no covering"); at != std::string::npos) {
    headline.replace(at, 11, "covering to be designed");
  }
  return headline;
}

void PrintDesignStudy(std::ostream& out, const DesignWorkPrecisionResult& study, const Scene& scene) {
  fmt::print(out, "Scene   {}\n", DesignedSceneHeadline(scene));
  fmt::print(out,
             "Study   the thinnest admissible covering (continuous optimum) on each oracle; errors relative to "
             "the exact path's optimum; time = CPU time of the whole search\n\n");
  fmt::print(out, "{:<26} {:>7} {:>12} {:>10} {:>9} {:>9} {:>9} {:>8} {:>6} {:>6} {:>9}  {}\n", "oracle", "rtol",
             "b_c* [mm]", "E_c* [MPa]", "err b_c*", "err E_c*", "contusion", "evals", "grads", "failed", "seconds",
             "kept");
  for (const DesignWorkPrecisionPoint& p : study.points) {
    const bool exact = p.oracle == optim::OracleKind::kExact;
    const auto error = [&](double e) { return exact ? std::string("-") : fmt::format("{:.1e}", e); };
    fmt::print(out, "{:<26} {:>7} {:>12.6f} {:>10.4f} {:>9} {:>9} {:>9.6f} {:>8} {:>6} {:>6} {:>9.3f}  {}\n",
               DesignSeriesName(p), exact ? std::string("-") : fmt::format("{:.0e}", p.relative_tolerance),
               p.thickness_m * 1e3, p.modulus_Pa * 1e-6, error(p.error_thickness), error(p.error_modulus),
               p.contusion_ratio, p.evaluations, p.gradient_evaluations, p.failed_evaluations, p.seconds,
               p.feasible ? p.source : "no admissible design");
  }
  fmt::print(out, "\n{}\n", study.message);
}

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
  const std::string title = options.title ? *options.title : DesignedSceneHeadline(shown);
  try {
    if (options.csv_file) WriteFileAtomically(*options.csv_file, DesignCsv(study));
    if (options.plot_file) {
      RunGnuplot(*options.plot_file, [&](const std::string& path) {
        return DesignChart(study, true, *PlotFormatFor(*options.plot_file), path, title);
      });
    }
    if (options.tolerance_plot_file) {
      RunGnuplot(*options.tolerance_plot_file, [&](const std::string& path) {
        return DesignChart(study, false, *PlotFormatFor(*options.tolerance_plot_file), path, title);
      });
    }
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }
  if (options.json) {
    Json j;
    j["study"] = "design";
    j["scene"] = SceneToJson(shown);
    Json list = Json::array();
    for (const DesignWorkPrecisionPoint& p : study.points) list.push_back(DesignPointJson(p));
    j["points"] = std::move(list);
    j["message"] = study.message;
    out << WithRunProvenance(j.dump(2), options.run) << '\n';
  } else {
    PrintDesignStudy(out, study, shown);
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

std::string WorkPrecisionCsv(const std::vector<WorkPrecisionPoint>& points) {
  std::string csv =
      "method,restart_at_phase_switches,relative_tolerance,status,worst_error,"
      "error_max_penetration,error_peak_force,error_max_compressive_stress,"
      "error_max_energy_density,error_contact_duration,energy_residual,seconds_per_impact,"
      "timed_runs,steps,rhs_evaluations,root_evaluations,jacobian_evaluations,"
      "nonlinear_iterations,error_test_failures,convergence_failures,restarts,warnings\n";
  for (const WorkPrecisionPoint& p : points) {
    const bool ok = p.status == SolveStatus::kSuccess;
    const auto error = [&](double value) { return ok ? CsvNumber(value) : std::string(); };
    const SolverStatistics& st = p.statistics;
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
                       ToString(p.method), p.restart ? 1 : 0,
                       p.method == ComputationMethod::kExact ? "" : CsvNumber(p.relative_tolerance),
                       ToString(p.status), error(p.worst_error), error(p.error_max_penetration),
                       error(p.error_peak_force), error(p.error_max_compressive_stress),
                       error(p.error_max_energy_density), error(p.error_contact_duration),
                       p.energy_residual ? CsvNumber(*p.energy_residual) : "",
                       CsvNumber(p.seconds_per_impact), p.timed_runs, st.steps,
                       st.rhs_evaluations, st.root_evaluations, st.jacobian_evaluations,
                       st.nonlinear_iterations, st.error_test_failures, st.convergence_failures,
                       st.restarts, p.warning_count);
  }
  return csv;
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
  sub->add_flag("--json", options.json, "print one JSON object instead of the table")
      ->group("Output");
  sub->add_option("--csv", options.csv_file, "write every run as a CSV row")
      ->type_name("FILE.csv")
      ->group("Output");
  sub->add_option("--plot", options.plot_file,
                  "chart worst error against CPU time per impact (log-log), gnuplot")
      ->type_name("FILE.png|FILE.svg")
      ->group("Output");
  sub->add_option("--tolerance-plot", options.tolerance_plot_file,
                  "chart worst error against the requested tolerance, gnuplot")
      ->type_name("FILE.png|FILE.svg")
      ->group("Output");
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
    if (options.csv_file) WriteFileAtomically(*options.csv_file, WorkPrecisionCsv(points));
    if (options.plot_file) {
      RunGnuplot(*options.plot_file, [&](const std::string& path) {
        return WorkChart(study, *PlotFormatFor(*options.plot_file), path, title);
      });
    }
    if (options.tolerance_plot_file) {
      RunGnuplot(*options.tolerance_plot_file, [&](const std::string& path) {
        return ToleranceChart(study, *PlotFormatFor(*options.tolerance_plot_file), path, title);
      });
    }
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }

  if (options.json) {
    Json j;
    j["scene"] = SceneToJson(scene_plan.scene);
    Json list = Json::array();
    for (const WorkPrecisionPoint& p : points) list.push_back(PointJson(p));
    j["points"] = std::move(list);
    Json cheapest = Json::object();
    for (const CheapestRun& run : study.cheapest) {
      cheapest[fmt::format("{:.0e}", run.target_error)] =
          run.point ? PointJson(points[*run.point]) : Json(nullptr);
    }
    j["cheapest_reaching_error"] = std::move(cheapest);
    out << WithRunProvenance(j.dump(2), options.run) << '\n';
  } else {
    PrintStudy(out, study, scene_plan.scene);
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace covopt::cli
