#include "covopt/report/history_csv.hpp"

#include <cmath>
#include <cstddef>
#include <iterator>
#include <utility>

#include <fmt/format.h>

namespace covopt::report {

std::vector<HistoryColumn> ImpactHistoryColumns(const ImpactModel& model, const std::vector<HistorySample>& history) {
  using Field = double (*)(const ImpactModel&, const HistorySample&);
  // clang-format off
  static constexpr std::pair<std::string_view, Field> kFields[] = {
    {"time_s", [](const ImpactModel&, const HistorySample& s) { return s.time_s; }},
    {"penetration_m", [](const ImpactModel&, const HistorySample& s) { return s.penetration_m; }},
    {"penetration_rate_m_per_s", [](const ImpactModel&, const HistorySample& s) { return s.penetration_rate_m_per_s; }},
    {"force_N", [](const ImpactModel&, const HistorySample& s) { return s.force_N; }},
    {"compressive_stress_Pa", [](const ImpactModel&, const HistorySample& s) { return s.compressive_stress_Pa; }},
    {"tensile_stress_Pa", [](const ImpactModel& m, const HistorySample& s) { return TensileStressOf(m, s); }},
    {"energy_density_J_per_m2", [](const ImpactModel&, const HistorySample& s) { return s.energy_density_J_per_m2; }},
    // the extended scene's (damping, braking, a neck)
    {"robot_speed_m_per_s", [](const ImpactModel&, const HistorySample& s) { return s.robot_speed_m_per_s; }},
    {"head_speed_m_per_s", [](const ImpactModel&, const HistorySample& s) { return s.head_speed_m_per_s; }},
    {"neck_force_N", [](const ImpactModel&, const HistorySample& s) { return s.neck_force_N; }},
    {"dissipated_work_J", [](const ImpactModel&, const HistorySample& s) { return s.dissipated_work_J; }},
  };
  // clang-format on
  constexpr std::size_t kTwoMassColumns = 7;
  const std::size_t count = model.scene().is_conservative_two_mass() ? kTwoMassColumns : std::size(kFields);
  std::vector<HistoryColumn> columns;
  for (std::size_t c = 0; c < count; ++c) {
    HistoryColumn& column = columns.emplace_back(HistoryColumn{kFields[c].first, {}});
    column.values.reserve(history.size());
    for (const HistorySample& h : history) column.values.push_back(kFields[c].second(model, h));
  }
  return columns;
}

std::string HistoryCsv(const ImpactModel& model, const std::vector<HistorySample>& history) {
  const auto field = [](double v) { return std::isfinite(v) ? fmt::format("{}", v) : std::string(); };
  const std::vector<HistoryColumn> columns = ImpactHistoryColumns(model, history);
  std::string csv;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (c > 0) csv += ',';
    csv.append(columns[c].name);
  }
  csv += '\n';
  for (std::size_t i = 0; i < history.size(); ++i) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c > 0) csv += ',';
      csv += field(columns[c].values[i]);
    }
    csv += '\n';
  }
  return csv;
}

}  // namespace covopt::report
