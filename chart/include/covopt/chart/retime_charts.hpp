#pragma once
/// @file retime_charts.hpp
/// The charts of `covopt retime` (its report, and the SVG files --speed-plot and
/// --thickness-plot write): the speed scale over the program's time, and the cycle time
/// against the covering's thickness.

#include <string>

#include "covopt/audit/retime.hpp"
#include "covopt/chart/charts.hpp"
#include "covopt/report/retime_json.hpp"

namespace covopt::chart {

/// The speed scale over the original program's time [s]: the largest safe path speed ṡ_max
/// (the audit's safe speed scale of each sample alone; where nothing moves it is unbounded and
/// not drawn), the re-timed program's path speed ṡ (1: as programmed), the uniform slow-down c
/// (dashed) and 1 (dotted). `trajectory_name` names the program in the title. 1000 x 600.
/// @throws std::invalid_argument without samples.
GnuplotChart RetimeSpeedChart(const audit::RetimeResult& result, const std::string& trajectory_name);

/// The cycle time [s] against the covering's thickness [mm], one line per material design (the
/// re-timed program's, solid, and the uniform slow-down's, dashed, in the same colour), the
/// per-link design as one marked point each, the original program's cycle time dotted; points
/// without a safe timing are left out (their gap shows). 1000 x 600.
/// @throws std::invalid_argument without points.
GnuplotChart CycleTimeChart(const report::RetimeSweep& sweep, double original_cycle_time_s);

}  // namespace covopt::chart
