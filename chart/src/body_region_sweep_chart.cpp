// The chart of `covopt sweep --body-region R --plot`.
#include "covopt/chart/body_region_sweep_chart.hpp"

#include <string>

#include <fmt/format.h>

namespace covopt::chart {

using report::BodyRegionSweepTable;
using report::SweepAxisArgument;

std::string BodyRegionSweepChart(const BodyRegionSweepTable& table, const SweepAxisArgument& x,
                                 const SweepAxisArgument* y, const materials::BodyLimits& limits,
                                 double safety_factor, ChartFormat format, const std::string& output_path) {
  const double bound = 1.0 / safety_factor;
  std::string s = "set encoding utf8\n" + GnuplotTerminal(format, 1000, 700);
  s += fmt::format("set output {}\n$data << EOD\n{}EOD\n", GnuplotQuoted(output_path), table.chart_data);
  s += fmt::format("set title {}\n",
                   GnuplotQuoted(fmt::format("governing ratio (line: {:g}); {}", 1.0 / safety_factor, limits.Describe())));
  s += fmt::format("set xlabel {}\n", GnuplotQuoted(x.name + " [" + std::string(SiUnit(x.field->spec.kind)) + "]"));
  if (x.log) s += "set logscale x\n";
  if (y) {
    s += fmt::format("set ylabel {}\n", GnuplotQuoted(y->name + " [" + std::string(SiUnit(y->field->spec.kind)) + "]"));
    if (y->log) s += "set logscale y\n";
    s += "set view map\nset contour base\nunset surface\nset pm3d at b\nunset key\n";
    s += fmt::format("set cntrparam levels discrete {}\nset cblabel 'governing ratio'\n", bound);
    s += fmt::format("splot $data using 1:2:3 with pm3d notitle, $data using 1:2:3 with lines linewidth 2 "
                     "linecolor rgb '#000000' title 'ratio = {:g}'\n", bound);
  } else {
    s += "set ylabel 'governing ratio'\nset grid\n";
    s += fmt::format("plot $data using 1:2 with lines linewidth 2 title 'governing ratio', {:g} with lines "
                     "dashtype 2 linecolor rgb '#c0392b' title 'limit (1/SF)'\n", bound);
  }
  return s + "unset output\n";
}

}  // namespace covopt::chart
