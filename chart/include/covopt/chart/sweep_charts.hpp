#pragma once
/// @file sweep_charts.hpp
/// The gnuplot scripts of `covopt sweep --plot`: the 2-D map (worst ratio in colour, the
/// ratio-1 contours, the full-compression boundary) and the families of lines, from the few
/// numbers of each grid point a chart needs (ChartPoint), and the axes in display units.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "covopt/core/scene.hpp"
#include "covopt/core/sweep.hpp"
#include "covopt/chart/charts.hpp"
#include "covopt/report/sweep_axis.hpp"
#include "covopt/report/sweep_csv.hpp"

namespace covopt::chart {

/// An axis's label: "covering-thickness [mm]" ("[-]" for a pure number).
std::string AxisLabel(const report::SweepAxisArgument& axis);

/// The axis's display unit as a scale: a value shown on a chart is SI / scale (1e-3 for mm).
double DisplayScale(const report::SweepAxisArgument& axis);

/// A value of the axis for people: "15 mm", "fixed".
std::string Display(const report::SweepAxisArgument& axis, double si);

/// A result column's label: "peak_force_N [N]".
std::string ColumnLabel(const report::ResultColumn& column);

/// What a chart needs of one grid point: the rest of its row is not kept.
struct ChartPoint {
  bool valid = false;             ///< SweepRow::valid; nothing else means anything if false
  bool fully_compressed = false;  ///< ImpactPeaks::fully_compressed
  double laceration_ratio = 0.0;  ///< [-]
  double contusion_ratio = 0.0;   ///< [-]
  double worst_ratio = 0.0;       ///< [-]
  double quantity = 0.0;          ///< the --plot-quantity column [SI], if any
  double compression_ratio = 0.0; ///< δ_max / t2 [-]
};

/// The numbers of `row` a chart draws (`quantity`: the --plot-quantity column, or null).
ChartPoint ChartPointOf(const covopt::SweepRow& row, const report::ResultColumn* quantity);

/// What the sweep's charts draw.
struct PlotInput {
  const report::ResultColumn* quantity = nullptr;  ///< --plot-quantity; null: the injury ratios
  const report::SweepAxisArgument* x = nullptr;
  const report::SweepAxisArgument* y = nullptr;
  std::span<const ChartPoint> points;  ///< every grid point, in grid order
  InjuryLimits limits;                 ///< the limits the ratios are taken against
  std::string scene_line;         ///< the quantities not swept, one line
  /// A point is safe when safety_factor x ratio <= 1: the limit lines sit at ratio
  /// 1/safety_factor (the derated limits).
  double safety_factor = 1.0;
  ChartFormat format = ChartFormat::kPng;
};

/// The 2-D map of a two-axis sweep into `output` (gnuplot script).
std::string SweepMapScript(const PlotInput& in, const std::string& output);

/// The families of lines (one per value of the shorter axis, at most kMaxFamilies) into
/// `output` (gnuplot script).
std::string SweepFamiliesScript(const PlotInput& in, const std::string& output);

}  // namespace covopt::chart
