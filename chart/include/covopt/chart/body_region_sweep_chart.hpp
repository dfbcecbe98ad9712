#pragma once
/// @file body_region_sweep_chart.hpp
/// The chart of `covopt sweep --body-region R --plot`: the governing ratio of
/// optim::SweepBodyRegion's grid, its axes in display units (a thickness in mm).

#include <cstddef>
#include <span>
#include <string>

#include "covopt/chart/charts.hpp"
#include "covopt/materials/body_regions.hpp"
#include "covopt/optim/body_region_sweep.hpp"
#include "covopt/report/sweep_axis.hpp"

namespace covopt::chart {

/// Two axes are drawn as lines (one per value of the axis with fewer values, over the other)
/// when either has at most this many values; as a map otherwise.
inline constexpr std::size_t kMaxLinesPerChart = 10;

/// How the grid is drawn.
enum class BodyRegionSweepChartKind {
  kLine,   ///< one axis: the ratio over it
  kLines,  ///< two axes, one with at most kMaxLinesPerChart values: a line per value
  kMap,    ///< two longer axes: a colour map with its contour at 1/SF
};

/// The kind of chart BodyRegionSweepChart draws for these axes.
BodyRegionSweepChartKind BodyRegionSweepChartKindOf(const report::SweepAxisArgument& x,
                                                    const report::SweepAxisArgument* y);

/// The gnuplot script of the governing ratio [-] over `grid` (optim::SweepBodyRegion's points
/// over `x` and, if given, `y`, x slowest), the limit 1/`safety_factor` dashed (or the map's
/// contour), titled with the region, its contact and its limits. A value "fixed" or "flat" is
/// left off a numeric axis, but names its line. 1000 x 700.
std::string BodyRegionSweepChart(std::span<const optim::BodyRegionSweepPoint> grid, const report::SweepAxisArgument& x,
                                 const report::SweepAxisArgument* y, const materials::BodyLimits& limits,
                                 double safety_factor, ChartFormat format, const std::string& output_path);

}  // namespace covopt::chart
