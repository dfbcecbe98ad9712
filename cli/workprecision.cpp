#include "workprecision.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <ctime>
#include <limits>
#include <map>
#include <stdexcept>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "covopt/core/exact.hpp"
#include "covopt/core/time_integration.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "plot.hpp"
#include "quantity.hpp"

namespace covopt::cli {
namespace {

using Json = nlohmann::ordered_json;

/// CPU time of this thread [s]: what one impact costs, whatever else the machine does.
double ThreadCpuSeconds() {
  timespec now{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

/// Runs `compute` `repeats` times, or automatically about 2 ms worth (at least 3) judged by
/// `first_seconds`, the time of a run just made (which also warmed caches and workspaces),
/// and returns the median time and the count.
template <class Compute>
std::pair<double, int> MedianCpuTime(Compute&& compute, double first_seconds, int repeats) {
  const int runs =
      repeats > 0 ? repeats
                  : std::clamp(static_cast<int>(std::ceil(2e-3 / std::max(first_seconds, 1e-9))),
                               3, 301);
  std::vector<double> times;
  times.reserve(static_cast<std::size_t>(runs));
  for (int i = 0; i < runs; ++i) {
    const double start = ThreadCpuSeconds();
    compute();
    times.push_back(ThreadCpuSeconds() - start);
  }
  const auto middle = times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2);
  std::nth_element(times.begin(), middle, times.end());
  return {*middle, runs};
}

double RelativeError(double value, double reference) {
  return reference != 0.0 ? std::abs(value / reference - 1.0) : std::abs(value);
}

void SetErrors(WorkPrecisionPoint& point, const ImpactResult& result, const ImpactResult& exact) {
  const ImpactPeaks& p = result.peaks;
  const ImpactPeaks& q = exact.peaks;
  point.error_max_penetration = RelativeError(p.max_penetration_m, q.max_penetration_m);
  point.error_peak_force = RelativeError(p.peak_force_N, q.peak_force_N);
  point.error_max_compressive_stress =
      RelativeError(p.max_compressive_stress_Pa, q.max_compressive_stress_Pa);
  point.error_max_energy_density =
      RelativeError(p.max_energy_density_J_per_m2, q.max_energy_density_J_per_m2);
  point.error_contact_duration = RelativeError(result.contact_duration_s.value_or(0.0),
                                               exact.contact_duration_s.value_or(0.0));
  point.worst_error = std::max({point.error_max_penetration, point.error_peak_force,
                                point.error_max_compressive_stress, point.error_max_energy_density,
                                point.error_contact_duration});
}

std::string SeriesName(ComputationMethod method, bool restart) {
  if (method == ComputationMethod::kExact) return "exact path";
  return fmt::format("{}{}", ToString(method), restart ? "" : ", no restart");
}

/// A number for CSV/JSON: shortest round-trip, empty/null when absent or not finite.
std::string CsvNumber(double value) { return std::isfinite(value) ? fmt::format("{}", value) : ""; }

/// The cheapest successful run whose worst error is at most `target`.
const WorkPrecisionPoint* Cheapest(const std::vector<WorkPrecisionPoint>& points, double target) {
  const WorkPrecisionPoint* best = nullptr;
  for (const WorkPrecisionPoint& p : points) {
    if (p.method == ComputationMethod::kExact || p.status != SolveStatus::kSuccess) continue;
    if (!(p.worst_error <= target)) continue;
    if (!best || p.seconds_per_impact < best->seconds_per_impact) best = &p;
  }
  return best;
}

/// Per series: the largest ratio of worst error to requested tolerance over the ladder.
struct SeriesSummary {
  ComputationMethod method;
  bool restart;
  double worst_ratio = 0.0;
  double at_tolerance = 0.0;
  int failures = 0;
};

std::vector<SeriesSummary> Summarise(const std::vector<WorkPrecisionPoint>& points) {
  std::vector<SeriesSummary> series;
  for (const WorkPrecisionPoint& p : points) {
    if (p.method == ComputationMethod::kExact) continue;
    auto it = std::find_if(series.begin(), series.end(), [&](const SeriesSummary& s) {
      return s.method == p.method && s.restart == p.restart;
    });
    if (it == series.end()) {
      series.push_back({p.method, p.restart});
      it = series.end() - 1;
    }
    if (p.status != SolveStatus::kSuccess) {
      ++it->failures;
      continue;
    }
    const double ratio = p.worst_error / p.relative_tolerance;
    if (ratio > it->worst_ratio) {
      it->worst_ratio = ratio;
      it->at_tolerance = p.relative_tolerance;
    }
  }
  return series;
}

/// A tolerance above which a series "does not keep its tolerance": the global error of a
/// well-behaved integrator stays within a few tens of its local tolerance here.
constexpr double kKeptRatio = 100.0;

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
std::string SeriesPlot(const std::vector<WorkPrecisionPoint>& points, bool time_on_y,
                       std::string& blocks) {
  std::vector<std::string> commands;
  int index = 0;
  for (const SeriesSummary& series : Summarise(points)) {
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

std::string WorkChart(const std::vector<WorkPrecisionPoint>& points, PlotFormat format,
                      const std::string& output_path, const std::string& title) {
  std::string s = ChartHeader(format, output_path,
                              "Work-precision: " + title);
  s += "set xlabel 'worst relative error of δmax, Fmax, σc,max, eA,max and T against the "
       "exact path [-]'\n";
  s += "set ylabel 'CPU time per impact [µs] (median)'\n";
  std::string blocks;
  std::string plot = SeriesPlot(points, true, blocks);
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

std::string ToleranceChart(const std::vector<WorkPrecisionPoint>& points, PlotFormat format,
                           const std::string& output_path, const std::string& title) {
  std::string s = ChartHeader(format, output_path,
                              "Does each method keep its promise? " + title);
  s += "set xlabel 'requested relative tolerance rtol (atol = rtol) [-]'\n";
  s += "set ylabel 'worst relative error against the exact path [-]'\n";
  s += "set xrange [*:*] reverse\n";
  std::string blocks;
  std::string plot = SeriesPlot(points, false, blocks);
  if (plot.empty()) plot = "plot NaN notitle";
  plot += ", \\\n     x with lines dashtype 3 linewidth 2 linecolor rgb '#444444' "
          "title 'error = rtol', \\\n     100*x with lines dashtype 4 linewidth 1 "
          "linecolor rgb '#999999' title 'error = 100 rtol'";
  return s + blocks + plot + "\nunset output\n";
}

// --- text, JSON -------------------------------------------------------------------

void PrintStudy(std::ostream& out, const std::vector<WorkPrecisionPoint>& points,
                const Scene& scene) {
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
  for (const double target : {1e-3, 1e-6, 1e-9}) {
    const WorkPrecisionPoint* best = Cheapest(points, target);
    if (best) {
      fmt::print(out, "  {:.0e}  {} at rtol {:.0e}: {:.1f} µs per impact (error {:.1e})\n", target,
                 SeriesName(best->method, best->restart), best->relative_tolerance,
                 best->seconds_per_impact * 1e6, best->worst_error);
    } else {
      fmt::print(out, "  {:.0e}  no run reached it\n", target);
    }
  }
  std::vector<std::string> broken;
  for (const SeriesSummary& s : Summarise(points)) {
    if (s.worst_ratio > kKeptRatio) {
      broken.push_back(fmt::format("{} (error {:.0f} x rtol at rtol {:.0e})",
                                   SeriesName(s.method, s.restart), s.worst_ratio, s.at_tolerance));
    }
    if (s.failures > 0) {
      broken.push_back(fmt::format("{} ({} failed run{})", SeriesName(s.method, s.restart),
                                   s.failures, s.failures == 1 ? "" : "s"));
    }
  }
  if (broken.empty()) {
    fmt::print(out, "Every series kept its error within {:g} x rtol.\n", kKeptRatio);
  } else {
    fmt::print(out, "Not keeping the tolerance (error > {:g} x rtol) or failing:\n", kKeptRatio);
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

std::vector<WorkPrecisionPoint> MeasureWorkPrecision(const ImpactModel& model,
                                                     const WorkPrecisionPlan& plan) {
  std::vector<WorkPrecisionPoint> points;
  double start = ThreadCpuSeconds();
  const ImpactResult exact = SolveExact(model);
  const double exact_seconds = ThreadCpuSeconds() - start;
  {
    WorkPrecisionPoint reference;
    reference.status = exact.status;
    reference.message = exact.message;
    reference.warning_count = exact.warnings.size();
    const auto [seconds, runs] =
        MedianCpuTime([&] { (void)SolveExact(model); }, exact_seconds, plan.repeats);
    reference.seconds_per_impact = seconds;
    reference.timed_runs = runs;
    points.push_back(reference);
  }
  TimeIntegrator integrator;
  for (const ComputationMethod method : plan.methods) {
    for (const bool restart : plan.restarts) {
      for (const double tolerance : plan.tolerances) {
        TimeIntegrationOptions options;
        options.method = method;
        options.relative_tolerance = tolerance;
        options.restart_at_phase_switches = restart;
        start = ThreadCpuSeconds();
        const ImpactResult result = integrator.Simulate(model, options);
        const double first_seconds = ThreadCpuSeconds() - start;
        WorkPrecisionPoint point;
        point.method = method;
        point.restart = restart;
        point.relative_tolerance = tolerance;
        point.status = result.status;
        point.message = result.message;
        point.statistics = result.statistics;
        point.warning_count = result.warnings.size();
        point.energy_residual = result.energy_residual;
        if (result.ok()) {
          SetErrors(point, result, exact);
        } else {
          point.worst_error = std::numeric_limits<double>::quiet_NaN();
        }
        const auto [seconds, runs] = MedianCpuTime(
            [&] { (void)integrator.Simulate(model, options); }, first_seconds, plan.repeats);
        point.seconds_per_impact = seconds;
        point.timed_runs = runs;
        points.push_back(std::move(point));
      }
    }
  }
  return points;
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

CLI::App* SetupWorkPrecision(CLI::App& app, WorkPrecisionOptions& options) {
  CLI::App* sub = app.add_subcommand(
      "workprecision",
      "Speed against accuracy: every time-integration method over a ladder of tolerances, "
      "measured against the exact path (table, CSV, charts)");
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
  return sub;
}

int RunWorkPrecision(const WorkPrecisionOptions& options, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "workprecision");

  SimulationPlan scene_plan;
  WorkPrecisionPlan plan;
  std::optional<ImpactModel> model;
  std::vector<std::pair<std::string, PlotFormat>> charts;
  try {
    scene_plan = ResolveSimulation(options.scene);
    plan.methods = ResolveMethods(options.methods);
    plan.tolerances = ParseToleranceLadder(options.tolerances);
    if (options.restart == "on" || options.restart == "both") plan.restarts.push_back(true);
    if (options.restart == "off" || options.restart == "both") plan.restarts.push_back(false);
    if (plan.restarts.empty()) {
      throw InputError(fmt::format("--restart: expected on, off or both (got '{}')", options.restart));
    }
    if (options.repeats < 0) {
      throw InputError(fmt::format("--repeats must be >= 0 (got {})", options.repeats));
    }
    plan.repeats = options.repeats;
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

  const std::vector<WorkPrecisionPoint> points = MeasureWorkPrecision(*model, plan);
  if (points.front().status != SolveStatus::kSuccess) {
    return errors.Failed("the exact path failed: " + points.front().message);
  }

  std::string title = options.title ? *options.title : SceneHeadline(scene_plan.scene);
  if (const auto details = SceneDetailsBeyondHeadline(scene_plan.scene);
      !options.title && !details.empty()) {
    title += fmt::format("; {}", fmt::join(details, ", "));
  }
  try {
    if (options.csv_file) WriteFileAtomically(*options.csv_file, WorkPrecisionCsv(points));
    if (options.plot_file) {
      RunGnuplot(*options.plot_file, [&](const std::string& path) {
        return WorkChart(points, *PlotFormatFor(*options.plot_file), path, title);
      });
    }
    if (options.tolerance_plot_file) {
      RunGnuplot(*options.tolerance_plot_file, [&](const std::string& path) {
        return ToleranceChart(points, *PlotFormatFor(*options.tolerance_plot_file), path, title);
      });
    }
  } catch (const OutputError& e) {
    return errors.Failed(e.what());
  }

  if (options.json) {
    Json j;
    j["scene"] = SceneToJson(scene_plan.scene);
    Json list = Json::array();
    for (const WorkPrecisionPoint& p : points) list.push_back(PointJson(p));
    j["points"] = std::move(list);
    Json cheapest = Json::object();
    for (const double target : {1e-3, 1e-6, 1e-9}) {
      const WorkPrecisionPoint* best = Cheapest(points, target);
      cheapest[fmt::format("{:.0e}", target)] = best ? PointJson(*best) : Json(nullptr);
    }
    j["cheapest_reaching_error"] = std::move(cheapest);
    out << j.dump(2) << '\n';
  } else {
    PrintStudy(out, points, scene_plan.scene);
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace covopt::cli
