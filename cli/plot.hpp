#pragma once
/// @file plot.hpp
/// --plot FILE.png|FILE.svg of every command: the chart written to its file
/// (covopt/report/chart_file.hpp).

#include "covopt/report/chart_file.hpp"
#include "covopt/report/charts.hpp"
#include "output.hpp"

namespace covopt::cli {

using PlotFormat = report::ChartFormat;
using report::FindOnPath;
using report::GnuplotQuoted;
using report::GnuplotTerminal;
using report::kGnuplotMissing;

using report::PlotHistory;
using report::RunGnuplot;
using report::SignalSafeScratch;

/// The format for a file name's extension (.png or .svg, any case); empty otherwise.
inline std::optional<PlotFormat> PlotFormatFor(const std::filesystem::path& path) {
  return report::ChartFormatFor(path);
}

}  // namespace covopt::cli
