#pragma once
/// @file body_region_sweep_output.hpp
/// The outputs of `covopt sweep --body-region R` (optim::SweepBodyRegion over one ISO region):
/// the CSV, the numbers of the summary and the data of its chart
/// (covopt/chart/body_region_sweep_chart.hpp).

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/materials/body_regions.hpp"
#include "covopt/optim/body_region_sweep.hpp"
#include "covopt/report/sweep_axis.hpp"

namespace covopt::report {

/// The grid laid out: its CSV and what the summary and the chart need.
struct BodyRegionSweepTable {
  /// The CSV: the axes' names with their SI units ("speed [m/s]", x then y), then peak_force_N, peak_pressure_Pa,
  /// covering_deflection_m, fully_compressed, force_ratio, pressure_ratio, compression_ratio,
  /// crush_ratio, governing, governing_ratio, admissible, error; one row per point, x slowest
  /// within each y block (an infinite mass "fixed", an infinite radius "flat").
  std::string csv;
  std::size_t points = 0;      ///< grid points
  std::size_t admissible = 0;  ///< points within every limit
  std::size_t invalid = 0;     ///< points outside the model's range (the CSV's error column)
  /// The largest governing ratio and where: "robot-mass = 10 kg, speed = 1.5 m/s, force"; -1 and ""
  /// when no point has a verdict.
  double worst = -1.0;
  std::string worst_at;
};

/// Lays out `grid` (optim::SweepBodyRegion's points over `x` and, if given, `y`, in its order).
BodyRegionSweepTable LayOutBodyRegionSweep(std::span<const optim::BodyRegionSweepPoint> grid,
                                           const SweepAxisArgument& x, const SweepAxisArgument* y);

/// One column of the grid as values per point (Python's covopt.sweep with body_region):
/// a number, NaN where the point is invalid or the quantity not evaluated; or a flag (`flag`),
/// 1 or 0, 0 where the point is invalid.
struct BodyRegionSweepColumn {
  std::string_view name;  ///< peak_force_N, ..., admissible: the CSV's names
  bool flag = false;
  std::vector<double> values;
};

/// The grid as columns, in the grid's order.
struct BodyRegionSweepColumns {
  /// peak_force_N, peak_pressure_Pa, covering_deflection_m, fully_compressed (flag),
  /// force_ratio, pressure_ratio, compression_ratio, crush_ratio (NaN where not checked),
  /// governing_ratio, admissible (flag).
  std::vector<BodyRegionSweepColumn> columns;
  std::vector<bool> valid;             ///< the point has a verdict
  std::vector<std::string> governing;  ///< "force", ...; "" where invalid
  std::vector<std::string> errors;     ///< the library's message where invalid, else ""
  /// "chest (sternum) (transient contact): 12 points, 3 within every limit, 0 outside the
  /// model's range".
  std::string message;
};

/// Lays out `grid` (optim::SweepBodyRegion's points for `limits`) as columns.
BodyRegionSweepColumns BodyRegionSweepColumnsOf(std::span<const optim::BodyRegionSweepPoint> grid,
                                                const materials::BodyLimits& limits);

}  // namespace covopt::report
