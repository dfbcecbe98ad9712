// A speed-limit table: MaxSafeSpeed / MaxSafeMass per covering and value (speed_limit_table.hpp).
#include "covopt/optim/speed_limit_table.hpp"

namespace covopt::optim {

std::string_view ToString(SpeedLimitQuantity quantity) noexcept {
  return quantity == SpeedLimitQuantity::kSpeed ? "speed" : "mass";
}

std::vector<SpeedLimitRow> SpeedLimitTable(SpeedLimitQuantity quantity, std::span<const SpeedLimitCovering> coverings,
                                           std::span<const double> values) {
  std::vector<SpeedLimitRow> rows;
  rows.reserve(coverings.size() * values.size());
  for (std::size_t index = 0; index < coverings.size(); ++index) {
    const SpeedLimitCovering& covering = coverings[index];
    for (const double value : values) {
      SpeedLimitRow row;
      if (covering.material && covering.scene.covering.thickness_m > 0.0) row.material = covering.material;
      Scene scene = covering.scene;
      try {
        if (quantity == SpeedLimitQuantity::kSpeed) {
          scene.robot.mass_kg = value;
          row.robot_mass_kg = value;
          row.speed_limit = MaxSafeSpeed(scene, covering.options);
        } else {
          scene.robot.speed_m_per_s = value;
          row.speed_m_per_s = value;
          row.mass_limit = MaxSafeMass(scene, covering.options);
        }
      } catch (const std::invalid_argument& e) {
        throw SpeedLimitTableError(e.what(), index);
      }
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

SpeedLimitStatus RowStatus(SpeedLimitQuantity quantity, const SpeedLimitRow& row) noexcept {
  return quantity == SpeedLimitQuantity::kSpeed ? row.speed_limit.status : row.mass_limit.status;
}

const std::string& RowMessage(SpeedLimitQuantity quantity, const SpeedLimitRow& row) noexcept {
  return quantity == SpeedLimitQuantity::kSpeed ? row.speed_limit.message : row.mass_limit.message;
}

const SpeedLimitRow* FirstFailedRow(SpeedLimitQuantity quantity, std::span<const SpeedLimitRow> rows) noexcept {
  for (const SpeedLimitRow& row : rows) {
    if (RowStatus(quantity, row) == SpeedLimitStatus::kEvaluationFailed) return &row;
  }
  return nullptr;
}

OracleReport SpeedLimitOracle(SpeedLimitQuantity quantity, std::span<const SpeedLimitRow> rows) {
  const auto of = [quantity](const SpeedLimitRow& row) -> const OracleReport& {
    return quantity == SpeedLimitQuantity::kSpeed ? row.speed_limit.oracle : row.mass_limit.oracle;
  };
  OracleReport merged = rows.empty() ? OracleReport{} : of(rows.front());
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const OracleReport& r = of(rows[i]);
    merged.evaluations += r.evaluations;
    merged.failed_evaluations += r.failed_evaluations;
    if (merged.first_failure.empty()) merged.first_failure = r.first_failure;
  }
  return merged;
}

}  // namespace covopt::optim
