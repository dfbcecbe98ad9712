#pragma once
/// @file tornado_chart.hpp
/// `simulate --sensitivities --plot`: the tornado chart of the elasticities d ln r / d ln x of
/// each injury ratio to every scene input (optim::ElasticityTable, docs/model.md §11).

#include <string>

#include "covopt/optim/robust_sensitivity.hpp"
#include "covopt/chart/charts.hpp"

namespace covopt::chart {

/// The gnuplot script of the tornado chart: one row per input, a laceration and a contusion bar.
std::string TornadoChart(const optim::ElasticityTable& table, ChartFormat format, const std::string& output_path);

}  // namespace covopt::chart
