#pragma once
/// @file history_csv.hpp
/// `simulate --history FILE.csv`: an impact's time history as CSV.

#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"

namespace covopt::report {

/// The CSV header of a history file.
inline constexpr std::string_view kHistoryCsvHeader =
    "time_s,penetration_m,penetration_rate_m_per_s,force_N,compressive_stress_Pa,"
    "tensile_stress_Pa,energy_density_J_per_m2";
/// The columns a scene with damping, braking or a neck (docs/model.md §10) adds after
/// kHistoryCsvHeader's: the bodies' speeds, the neck force and the work taken out
/// (HistorySample).
inline constexpr std::string_view kHistoryCsvExtendedColumns =
    ",robot_speed_m_per_s,head_speed_m_per_s,neck_force_N,dissipated_work_J";

/// One column of a time history: its name (a CSV header's) and its value per sample.
struct HistoryColumn {
  std::string_view name;
  std::vector<double> values;
};

/// The head impact's history as columns (Python's simulate(history=True)): kHistoryCsvHeader's,
/// then kHistoryCsvExtendedColumns' for a scene beyond the conservative two-mass model.
std::vector<HistoryColumn> ImpactHistoryColumns(const ImpactModel& model, const std::vector<HistorySample>& history);

/// The history as CSV text: kHistoryCsvHeader (and kHistoryCsvExtendedColumns for a scene
/// beyond the conservative two-mass model), then one row per sample (shortest
/// round-trip decimal numbers; a non-finite value is an empty field). tensile_stress_Pa is
/// σ_t = σ_c (1 - 2ν_t)/3 from the sample's compressive stress
/// (model.TensileFromCompressive), the stress the laceration limit judges.
std::string HistoryCsv(const ImpactModel& model, const std::vector<HistorySample>& history);

}  // namespace covopt::report
