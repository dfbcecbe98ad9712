#pragma once
/// @file work_precision_chart.hpp
/// The gnuplot scripts of `covopt workprecision --plot/--tolerance-plot` (the study:
/// covopt::MeasureWorkPrecision; with --design, optim::MeasureDesignWorkPrecision).

#include <string>

#include "covopt/chart/charts.hpp"
#include "covopt/core/work_precision.hpp"
#include "covopt/optim/design_work_precision.hpp"

namespace covopt::chart {

/// The gnuplot script of the work-precision chart: worst error against CPU time per impact
/// (log-log), one line per series, the exact path as one point.
std::string WorkPrecisionChart(const WorkPrecisionResult& study, ChartFormat format, const std::string& output_path,
                               const std::string& title);

/// The gnuplot script of the tolerance chart: worst error against the requested tolerance,
/// with the lines error = rtol and error = 100 rtol.
std::string WorkPrecisionToleranceChart(const WorkPrecisionResult& study, ChartFormat format,
                                        const std::string& output_path, const std::string& title);

/// One chart of the design study: for each method, the error of b_c* (solid) and of E_c*
/// (dashed) against the search's CPU time (`cost`) or against the requested rtol.
std::string DesignWorkPrecisionChart(const optim::DesignWorkPrecisionResult& study, bool cost, ChartFormat format,
                                     const std::string& output_path, const std::string& title);

}  // namespace covopt::chart
