#include "covopt/report/history_csv.hpp"

#include <cmath>

#include <fmt/format.h>

namespace covopt::report {

std::string HistoryCsv(const ImpactModel& model, const std::vector<HistorySample>& history) {
  const auto field = [](double v) { return std::isfinite(v) ? fmt::format("{}", v) : std::string(); };
  const bool extended = !model.scene().is_conservative_two_mass();
  std::string csv(kHistoryCsvHeader);
  if (extended) csv += kHistoryCsvExtendedColumns;
  csv += '\n';
  for (const HistorySample& h : history) {
    csv += fmt::format("{},{},{},{},{},{},{}", field(h.time_s), field(h.penetration_m),
                       field(h.penetration_rate_m_per_s), field(h.force_N),
                       field(h.compressive_stress_Pa),
                       field(model.TensileFromCompressive(h.compressive_stress_Pa)),
                       field(h.energy_density_J_per_m2));
    if (extended) {
      csv += fmt::format(",{},{},{},{}", field(h.robot_speed_m_per_s), field(h.head_speed_m_per_s),
                         field(h.neck_force_N), field(h.dissipated_work_J));
    }
    csv += '\n';
  }
  return csv;
}

}  // namespace covopt::report
