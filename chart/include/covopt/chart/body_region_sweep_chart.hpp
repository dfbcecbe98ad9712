#pragma once
/// @file body_region_sweep_chart.hpp
/// The chart of `covopt sweep --body-region R --plot` (the grid laid out by
/// report::LayOutBodyRegionSweep).

#include <string>

#include "covopt/chart/charts.hpp"
#include "covopt/materials/body_regions.hpp"
#include "covopt/report/body_region_sweep_output.hpp"
#include "covopt/report/sweep_axis.hpp"

namespace covopt::chart {

/// The gnuplot script of the governing ratio over the grid (`table.chart_data`): a line with the
/// limit 1/`safety_factor` dashed (one axis), or a map with its contour at 1/`safety_factor`.
std::string BodyRegionSweepChart(const report::BodyRegionSweepTable& table, const report::SweepAxisArgument& x,
                                 const report::SweepAxisArgument* y, const materials::BodyLimits& limits,
                                 double safety_factor, ChartFormat format, const std::string& output_path);

}  // namespace covopt::chart
