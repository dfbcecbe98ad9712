// The chart of `covopt sweep --body-region R --plot`: the governing ratio over one axis (a line),
// over two (a family of lines when an axis has few values, else a map), in display units.
#include "covopt/chart/body_region_sweep_chart.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "covopt/chart/sweep_charts.hpp"

namespace covopt::chart {

using report::SweepAxisArgument;

namespace {

constexpr std::string_view kLimitColour = "#c0392b";

/// The indices of an axis's values in ascending order (the finite ones only when `finite`).
std::vector<std::size_t> Ascending(const SweepAxisArgument& axis, bool finite) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < axis.values.size(); ++i) {
    if (!finite || std::isfinite(axis.values[i])) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return axis.values[a] < axis.values[b]; });
  return order;
}

/// An axis value in the axis's display unit (mm for a thickness), as AxisLabel names it.
double Shown(const SweepAxisArgument& axis, double si) { return si / DisplayScale(axis); }

/// The ratio of a grid point (x index, y index), NaN where it has no verdict.
double RatioAt(std::span<const optim::BodyRegionSweepPoint> grid, std::size_t ny, std::size_t ix, std::size_t iy) {
  const optim::BodyRegionSweepPoint& p = grid[ix * ny + iy];
  return p.judgement ? p.judgement->governing_ratio : std::nan("");
}

std::string Ratio(double r) { return std::isfinite(r) ? fmt::format("{}", r) : "NaN"; }

}  // namespace

BodyRegionSweepChartKind BodyRegionSweepChartKindOf(const SweepAxisArgument& x, const SweepAxisArgument* y) {
  if (y == nullptr) return BodyRegionSweepChartKind::kLine;
  return x.values.size() <= kMaxLinesPerChart || y->values.size() <= kMaxLinesPerChart ? BodyRegionSweepChartKind::kLines
                                                                                        : BodyRegionSweepChartKind::kMap;
}

std::string BodyRegionSweepChart(std::span<const optim::BodyRegionSweepPoint> grid, const SweepAxisArgument& x,
                                 const SweepAxisArgument* y, const materials::BodyLimits& limits,
                                 double safety_factor, ChartFormat format, const std::string& output_path) {
  const double bound = 1.0 / safety_factor;
  const std::size_t ny = y ? y->values.size() : 1;
  const BodyRegionSweepChartKind kind = BodyRegionSweepChartKindOf(x, y);
  // The lines run over the axis with more values, one line per value of the other.
  const bool lines_over_y = kind == BodyRegionSweepChartKind::kLines && y->values.size() > x.values.size();
  const SweepAxisArgument& along = lines_over_y ? *y : x;
  const SweepAxisArgument* across = kind == BodyRegionSweepChartKind::kLine ? nullptr : lines_over_y ? &x : y;
  std::string s = "set encoding utf8\n" + GnuplotTerminal(format, 1000, 700);
  s += fmt::format("set output {}\n", GnuplotQuoted(output_path));
  s += fmt::format("set title {} . \"\\n\" . {}\n",
                   GnuplotQuoted(fmt::format("The governing ratio, {} contact: safe where ratio <= 1/SF = {:g}",
                                             ToString(limits.contact), bound)),
                   GnuplotQuoted(limits.Describe()));
  s += "set tmargin 4\n";
  s += fmt::format("set xlabel {}\n", GnuplotQuoted(AxisLabel(along)));
  if (along.log) s += "set logscale x\n";
  if (kind == BodyRegionSweepChartKind::kMap) {
    s += "$data << EOD\n";
    for (const std::size_t iy : Ascending(*y, true)) {
      for (const std::size_t ix : Ascending(x, true)) {
        s += fmt::format("{} {} {}\n", Shown(x, x.values[ix]), Shown(*y, y->values[iy]), Ratio(RatioAt(grid, ny, ix, iy)));
      }
      s += "\n";
    }
    s += "EOD\n";
    s += fmt::format("set ylabel {}\n", GnuplotQuoted(AxisLabel(*y)));
    if (y->log) s += "set logscale y\n";
    s += "set view map\nset contour base\nunset surface\nset pm3d at b\nset key below\n";
    s += fmt::format("set cntrparam levels discrete {}\nset cblabel 'governing ratio [-]'\n", bound);
    s += fmt::format("splot $data using 1:2:3 with pm3d notitle, $data using 1:2:3 with lines linewidth 2 "
                     "linecolor rgb '#000000' title 'ratio = 1/SF = {:g}'\n", bound);
    return s + "unset output\n";
  }
  s += "set ylabel 'governing ratio [-]'\nset grid\nset key below horizontal\n";
  std::string plot = "plot ";
  const std::vector<std::size_t> families = across ? Ascending(*across, false) : std::vector<std::size_t>{0};
  for (std::size_t f = 0; f < families.size(); ++f) {
    s += fmt::format("$line{} << EOD\n", f);
    for (const std::size_t i : Ascending(along, true)) {
      const std::size_t ix = lines_over_y ? families[f] : i;
      const std::size_t iy = !across ? 0 : lines_over_y ? i : families[f];
      s += fmt::format("{} {}\n", Shown(along, along.values[i]), Ratio(RatioAt(grid, ny, ix, iy)));
    }
    s += "EOD\n";
    const std::string title =
        across ? fmt::format("{} = {}", across->name, Display(*across, across->values[families[f]])) : "governing ratio";
    plot += fmt::format("$line{} using 1:2 with linespoints linewidth 2 pointtype 7 pointsize 0.6 title {}, ", f,
                        GnuplotQuoted(title));
  }
  plot += fmt::format("{:g} with lines dashtype 2 linewidth 2 linecolor rgb '{}' title 'limit 1/SF = {:g}'\n", bound,
                      kLimitColour, bound);
  return s + plot + "unset output\n";
}

}  // namespace covopt::chart
