#pragma once
/// @file plot.hpp
/// --plot FILE.png|FILE.svg of every command: the chart written to its file
/// (covopt/chart/chart_file.hpp).

#include "covopt/chart/chart_file.hpp"
#include "covopt/chart/charts.hpp"
#include "output.hpp"

namespace covopt::cli {

using PlotFormat = chart::ChartFormat;
using report::FindOnPath;
using chart::GnuplotQuoted;
using chart::GnuplotTerminal;
using chart::kGnuplotMissing;

using chart::PlotHistory;
using chart::RunGnuplot;
using chart::SignalSafeScratch;

/// The format for a file name's extension (.png or .svg, any case); empty otherwise.
inline std::optional<PlotFormat> PlotFormatFor(const std::filesystem::path& path) {
  return chart::ChartFormatFor(path);
}

}  // namespace covopt::cli
