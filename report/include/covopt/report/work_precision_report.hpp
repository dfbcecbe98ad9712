#pragma once
/// @file work_precision_report.hpp
/// The outputs of `covopt workprecision` (covopt::MeasureWorkPrecision, and with --design
/// optim::MeasureDesignWorkPrecision): the JSON object and the CSV (its charts are
/// covopt/chart/work_precision_chart.hpp). The CLI prints the table and writes these files.

#include <string>
#include <vector>

#include "covopt/core/scene.hpp"
#include "covopt/core/work_precision.hpp"
#include "covopt/optim/design_work_precision.hpp"

namespace covopt::report {

/// "cvode-adams", "cvode-adams, no restart" or "exact path": a series' name in tables and keys.
std::string WorkPrecisionSeriesName(ComputationMethod method, bool restart);

/// "exact path" or "time path, cvode-adams": a design-study point's series in tables.
std::string DesignWorkPrecisionSeriesName(const optim::DesignWorkPrecisionPoint& point);

/// The study as one JSON object (indented by 2): scene, points (one object per run: method,
/// restart_at_phase_switches, relative_tolerance, status, message, the errors, energy_residual,
/// seconds_per_impact, timed_runs, the solver statistics, warnings) and
/// cheapest_reaching_error (per target error "1e-06", the cheapest point or null).
std::string WorkPrecisionJson(const WorkPrecisionResult& study, const Scene& scene);

/// The optimiser-level study as one JSON object: study "design", scene, points, message.
std::string DesignWorkPrecisionJson(const optim::DesignWorkPrecisionResult& study, const Scene& scene);

/// The CSV of `covopt workprecision --csv`: a header, then one row per point.
std::string WorkPrecisionCsv(const std::vector<WorkPrecisionPoint>& points);

/// The CSV of `covopt workprecision --design --csv`: a header, then one row per search.
std::string DesignWorkPrecisionCsv(const optim::DesignWorkPrecisionResult& study);

}  // namespace covopt::report
