#pragma once
// What the chart definitions (report/src/*_chart.cpp) share.

#include <string>
#include <string_view>

#include "covopt/chart/charts.hpp"

namespace covopt::chart::internal {

/// A chart whose script is "set encoding utf8", the terminal (width x height pixels), `set
/// output` to the file, then `body` (the data and the plot commands).
GnuplotChart MakeChart(std::string title, std::string caption, int width_px, int height_px, std::string body);

/// A gnuplot double-quoted string, in which a line break becomes \n.
std::string GnuplotDoubleQuoted(std::string_view text);

}  // namespace covopt::chart::internal
