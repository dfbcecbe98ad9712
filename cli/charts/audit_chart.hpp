#pragma once
/// @file audit_chart.hpp
/// The gnuplot script of `covopt audit --plot`: a heat map of the largest ratio per sample and
/// link (AuditResult::ratio_over_time), time across, links up, coloured as the sweep's map
/// (green below the limit 1/safety factor, red above), the limiting cell marked.

#include <string>

#include "covopt/optim/audit.hpp"
#include "plot.hpp"

namespace covopt::cli {

/// The heat map of `result` (its ratio_over_time must be kept) into `output`; the title names
/// the trajectory `trajectory_name`, the verdict and the limiting link and region.
std::string AuditHeatMapScript(const optim::AuditResult& result, double safety_factor,
                               const std::string& trajectory_name, PlotFormat format, const std::string& output);

}  // namespace covopt::cli
