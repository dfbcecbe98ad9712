#include "covopt/report/work_precision_report.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "covopt/report/charts.hpp"
#include "covopt/report/simulation_json.hpp"
#include "json_number.hpp"

namespace covopt::report {
namespace {

using internal::Number;
using Json = nlohmann::ordered_json;
using optim::DesignWorkPrecisionPoint;
using optim::DesignWorkPrecisionResult;

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

std::string ChartHeader(ChartFormat format, const std::string& output_path,
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
        GnuplotQuoted(WorkPrecisionSeriesName(series.method, series.restart))));
    ++index;
  }
  std::string plot;
  for (std::size_t i = 0; i < commands.size(); ++i) {
    plot += (i == 0 ? "plot " : ", \\\n     ") + commands[i];
  }
  return plot;
}


Json PointJson(const WorkPrecisionPoint& p) {
  Json j{{"method", ToString(p.method)},
         {"restart_at_phase_switches", p.restart},
         {"relative_tolerance", Number(p.relative_tolerance)},
         {"status", ToString(p.status)},
         {"message", p.message},
         {"worst_error", Number(p.worst_error)},
         {"error_max_penetration", Number(p.error_max_penetration)},
         {"error_peak_force", Number(p.error_peak_force)},
         {"error_max_compressive_stress", Number(p.error_max_compressive_stress)},
         {"error_max_energy_density", Number(p.error_max_energy_density)},
         {"error_contact_duration", Number(p.error_contact_duration)},
         {"energy_residual", p.energy_residual ? Number(*p.energy_residual) : Json(nullptr)},
         {"seconds_per_impact", Number(p.seconds_per_impact)},
         {"timed_runs", p.timed_runs}};
  j.update(Json::parse(SolverStatisticsJson(p.statistics)));
  j["warnings"] = p.warning_count;
  return j;
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

Json DesignPointJson(const DesignWorkPrecisionPoint& p) {
  const bool exact = p.oracle == optim::OracleKind::kExact;
  return Json{{"oracle", optim::ToString(p.oracle)},
              {"method", exact ? Json(nullptr) : Json(std::string(ToString(p.method)))},
              {"relative_tolerance", exact ? Json(nullptr) : Number(p.relative_tolerance)},
              {"feasible", p.feasible},
              {"thickness_m", Number(p.thickness_m)},
              {"youngs_modulus_Pa", Number(p.modulus_Pa)},
              {"error_thickness", Number(p.error_thickness)},
              {"error_modulus", Number(p.error_modulus)},
              {"contusion_ratio", Number(p.contusion_ratio)},
              {"seconds", Number(p.seconds)},
              {"evaluations", p.evaluations},
              {"gradient_evaluations", p.gradient_evaluations},
              {"failed_evaluations", p.failed_evaluations},
              {"local_termination", p.local_termination},
              {"source", p.source}};
}

}  // namespace

std::string WorkPrecisionSeriesName(ComputationMethod method, bool restart) {
  if (method == ComputationMethod::kExact) return "exact path";
  return fmt::format("{}{}", ToString(method), restart ? "" : ", no restart");
}

std::string DesignWorkPrecisionSeriesName(const DesignWorkPrecisionPoint& p) {
  return p.oracle == optim::OracleKind::kExact ? std::string("exact path")
                                                : fmt::format("time path, {}", ToString(p.method));
}

std::string WorkPrecisionChart(const WorkPrecisionResult& study, ChartFormat format,
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

std::string WorkPrecisionToleranceChart(const WorkPrecisionResult& study, ChartFormat format,
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

std::string DesignWorkPrecisionChart(const DesignWorkPrecisionResult& study, bool cost, ChartFormat format,
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

std::string DesignWorkPrecisionCsv(const DesignWorkPrecisionResult& study) {
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

std::string WorkPrecisionJson(const WorkPrecisionResult& study, const Scene& scene) {
  const std::vector<WorkPrecisionPoint>& points = study.points;
  Json j;
  j["scene"] = Json::parse(SceneJson(scene));
  Json list = Json::array();
  for (const WorkPrecisionPoint& p : points) list.push_back(PointJson(p));
  j["points"] = std::move(list);
  Json cheapest = Json::object();
  for (const CheapestRun& run : study.cheapest) {
    cheapest[fmt::format("{:.0e}", run.target_error)] = run.point ? PointJson(points[*run.point]) : Json(nullptr);
  }
  j["cheapest_reaching_error"] = std::move(cheapest);
  return j.dump(2);
}

std::string DesignWorkPrecisionJson(const DesignWorkPrecisionResult& study, const Scene& scene) {
  Json j;
  j["study"] = "design";
  j["scene"] = Json::parse(SceneJson(scene));
  Json list = Json::array();
  for (const DesignWorkPrecisionPoint& p : study.points) list.push_back(DesignPointJson(p));
  j["points"] = std::move(list);
  j["message"] = study.message;
  return j.dump(2);
}

}  // namespace covopt::report
