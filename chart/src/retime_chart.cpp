// The charts of `covopt retime` (retime_charts.hpp).
#include "covopt/chart/retime_charts.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "chart_script.hpp"

namespace covopt::chart {
namespace {

/// A number for gnuplot's data: NaN (not drawn) when not finite.
std::string Datum(double value) { return std::isfinite(value) ? fmt::format("{}", value) : std::string("NaN"); }

constexpr const char* kColours[] = {"#1f5fa8", "#c0392b", "#27ae60", "#8e44ad", "#d35400", "#16a085", "#7f8c8d",
                                    "#2c3e50"};

}  // namespace

GnuplotChart RetimeSpeedChart(const audit::RetimeResult& r, const std::string& trajectory_name) {
  const std::size_t n = std::min({r.original_time_s.size(), r.safe_path_speed.size(), r.path_speed.size()});
  if (n == 0) throw std::invalid_argument("RetimeSpeedChart: the result has no samples");
  double top = 1.0;
  for (std::size_t i = 0; i < n; ++i) top = std::max(top, std::isfinite(r.path_speed[i]) ? r.path_speed[i] : 0.0);
  top *= 1.6;
  std::string s = "$data << EOD\n";
  for (std::size_t i = 0; i < n; ++i) {
    // An unbounded safe speed (nothing moves) is drawn clipped at the top of the chart.
    const double safe = std::isfinite(r.safe_path_speed[i]) ? r.safe_path_speed[i] : top;
    s += fmt::format("{} {} {}\n", r.original_time_s[i], Datum(std::min(safe, top)), Datum(r.path_speed[i]));
  }
  s += "EOD\n";
  s += fmt::format("set title {}\n",
                   GnuplotQuoted(fmt::format("covopt retime {}: cycle time {:.4g} s (original {:.4g} s, uniform "
                                             "slow-down {:.4g} s)",
                                             std::filesystem::path(trajectory_name).filename().string(),
                                             r.cycle_time_s, r.original_cycle_time_s, r.uniform_cycle_time_s)));
  s += "set grid linecolor rgb '#dddddd'\nset key below\nset autoscale xfix\n";
  s += fmt::format("set yrange [0:{}]\n", top);
  s += "set xlabel 'time of the original program [s]'\nset ylabel 'speed scale (path speed) [-]'\n";
  s += "plot $data using 1:2 with lines linewidth 2 linecolor rgb '#c0392b' title 'largest safe speed scale "
       "(audit, per sample)', "
       "$data using 1:3 with lines linewidth 2 linecolor rgb '#1f5fa8' title 're-timed program', ";
  s += fmt::format("{} with lines linewidth 2 dashtype 2 linecolor rgb '#7f8c8d' title {}, ",
                   Datum(r.uniform_speed_scale),
                   GnuplotQuoted(fmt::format("uniform slow-down {:.4g}", r.uniform_speed_scale)));
  s += "1 with lines linewidth 1 dashtype 3 linecolor rgb '#000000' title 'as programmed'\nunset output\n";
  return internal::MakeChart(
      "Speed scale over the program's time",
      fmt::format("The path speed of the re-timed program (1: as programmed) over the time of the original "
                  "program [s], under the largest safe speed scale of each sample (the audit's; unbounded where no "
                  "surface point moves, drawn at the top), and the uniform slow-down {:.4g} that the audit alone "
                  "would ask for. The re-timed program runs at {:.4g} s against {:.4g} s for the uniform slow-down.",
                  r.uniform_speed_scale, r.cycle_time_s, r.uniform_cycle_time_s),
      1000, 600, std::move(s));
}

GnuplotChart CycleTimeChart(const report::RetimeSweep& sweep, double original_cycle_time_s) {
  if (sweep.points.empty()) throw std::invalid_argument("CycleTimeChart: the sweep has no points");
  std::string s;
  std::string plots;
  double top = std::isfinite(original_cycle_time_s) ? original_cycle_time_s : 0.0;
  for (std::size_t d = 0; d < sweep.designs.size(); ++d) {
    const bool per_link = sweep.designs[d].design.has_value();
    std::string data;
    for (const audit::CycleTimePoint& p : sweep.points) {
      if (p.design != d) continue;
      data += fmt::format("{} {} {}\n", p.thickness_m * 1e3, Datum(p.cycle_time_s), Datum(p.uniform_cycle_time_s));
      for (const double t : {p.cycle_time_s, p.uniform_cycle_time_s}) top = std::isfinite(t) ? std::max(top, t) : top;
    }
    s += fmt::format("$d{} << EOD\n{}EOD\n", d, data);
    const char* colour = kColours[d % std::size(kColours)];
    if (per_link) {
      plots += fmt::format("$d{} using 1:2 with points pointtype 7 pointsize 1.6 linecolor rgb '{}' title {}, ", d,
                           colour, GnuplotQuoted(sweep.designs[d].name + " (its thickest link)"));
    } else {
      plots += fmt::format("$d{} using 1:2 with linespoints linewidth 2 pointtype 7 linecolor rgb '{}' title {}, ", d,
                           colour, GnuplotQuoted(sweep.designs[d].name + ", re-timed"));
      plots += fmt::format("$d{} using 1:3 with lines linewidth 1 dashtype 2 linecolor rgb '{}' title {}, ", d, colour,
                           GnuplotQuoted(sweep.designs[d].name + ", uniform slow-down"));
    }
  }
  s += "set grid linecolor rgb '#dddddd'\nset key below\n";
  s += fmt::format("set yrange [0:{}]\n", top > 0.0 ? 1.15 * top : 1.0);
  s += "set title 'covopt retime: cycle time against covering thickness'\n";
  s += "set xlabel 'covering thickness [mm]'\nset ylabel 'cycle time [s]'\n";
  s += "plot " + plots +
       fmt::format("{} with lines linewidth 1 dashtype 3 linecolor rgb '#000000' title {}\nunset output\n",
                   Datum(original_cycle_time_s),
                   GnuplotQuoted(fmt::format("original program {:.4g} s", original_cycle_time_s)));
  return internal::MakeChart(
      "Cycle time against covering thickness",
      "The cycle time [s] of the fastest safe timing of the program (solid) and of the uniform slow-down (dashed) "
      "per covering every link wears, against its thickness [mm]; the per-link design (each link's thinnest "
      "catalog covering safe at full speed) at its thickest link; the original program dotted. A missing point "
      "has no safe timing.",
      1000, 600, std::move(s));
}

}  // namespace covopt::chart
