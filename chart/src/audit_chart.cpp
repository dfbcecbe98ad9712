// The heat map of `covopt audit` (--plot and the report).
#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "covopt/chart/charts.hpp"

#include "chart_script.hpp"

namespace covopt::chart {

GnuplotChart AuditHeatMap(const audit::AuditResult& result, double safety_factor,
                          const std::string& trajectory_name) {
  const std::size_t links = result.links.size();
  const std::size_t samples = links > 0 ? result.ratio_over_time.size() / links : 0;
  const double at_limit = 1.0 / safety_factor;
  std::string s;
  std::string verdict = std::string(optim::ToString(result.status));
  if (result.limiting_cell) {
    const audit::AuditCell& c = result.cells[*result.limiting_cell];
    verdict += fmt::format(", safe speed scale {:.4g} ({}, {}, t = {:.4g} s)", result.safe_speed_scale,
                           result.links[c.link], result.regions[c.region], c.time_s);
  }
  s += fmt::format("set title {} . \"\\n\" . {}\n",
                   GnuplotQuoted(fmt::format("covopt audit {}: {}", trajectory_name, verdict)),
                   GnuplotQuoted(fmt::format("largest ratio over each link's points and {} regions (safe: safety factor x "
                                             "ratio <= 1, here {:.4g})",
                                             result.regions.size(), at_limit)));
  // Cells centred on (time, link index); the time of a cell is its sample's.
  s += "$map << EOD\n";
  for (std::size_t l = 0; l < links; ++l) {
    for (std::size_t i = 0; i < samples; ++i) {
      const double ratio = result.ratio_over_time[i * links + l];
      s += fmt::format("{} {} {}\n", result.time_s[i], l, std::isfinite(ratio) ? fmt::format("{}", ratio) : "NaN");
    }
    s += "\n";
  }
  s += "EOD\n";
  s += fmt::format("set cbrange [0:{}]\n", 2.0 * at_limit);
  s += "set palette defined (0 '#1a7f3c', 0.5 '#8fd18b', 0.98 '#f4f1bb', 1.02 '#fdd49e', 1.5 '#f0793d', 2 '#a50f15')\n";
  s += "set cblabel 'ratio (limit at the middle)'\n";
  s += "set xlabel 'time [s]'\nset ylabel 'link'\n";
  s += fmt::format("set yrange [-0.5:{}]\n", static_cast<double>(links) - 0.5);
  s += "set ytics (";
  for (std::size_t l = 0; l < links; ++l) {
    s += fmt::format("{}{} {}", l ? ", " : "", GnuplotQuoted(result.links[l]), l);
  }
  s += ")\nset autoscale xfix\nset key below\nset bmargin 5\n";
  s += "plot $map using 1:2:3 with image notitle";
  if (result.limiting_cell) {
    const audit::AuditCell& c = result.cells[*result.limiting_cell];
    s += fmt::format(", '-' using 1:2 with points pointtype 6 pointsize 2 linewidth 2 linecolor rgb '#000000' "
                     "title {}\n{} {}\ne",
                     GnuplotQuoted(fmt::format("sets the scale: {} against {}", result.links[c.link],
                                               result.regions[c.region])),
                     c.time_s, c.link);
  }
  s += "\nunset output\n";
  return internal::MakeChart(
      "Ratio over time, per link",
      fmt::format("The largest injury ratio of each link over time (over its surface points and the {} regions "
                  "judged), green below the limit 1/safety factor = {:.4g}, red above{}.",
                  result.regions.size(), at_limit,
                  result.limiting_cell ? "; the circle marks the cell that sets the safe speed scale" : ""),
      1100, 250 + 45 * static_cast<int>(std::max<std::size_t>(links, 3)), std::move(s));
}

}  // namespace covopt::chart
