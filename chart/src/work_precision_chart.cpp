// The charts of `covopt workprecision`: worst error against CPU time per impact, and against
// the requested tolerance; the design study's errors of the optimum.
#include "covopt/chart/work_precision_chart.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "covopt/report/work_precision_report.hpp"

namespace covopt::chart {
namespace {

using optim::DesignWorkPrecisionPoint;
using optim::DesignWorkPrecisionResult;
using report::WorkPrecisionSeriesName;

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

}  // namespace

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

}  // namespace covopt::chart
