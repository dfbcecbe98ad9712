// Speed (or mass) limits as JSON text (covopt speed-limit --json, covopt.speed_limit()).
#include "covopt/report/speed_limit_json.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include <covopt/core/number_format.hpp>
#include <nlohmann/json.hpp>

#include "covopt/optim/summaries.hpp"
#include "covopt/report/simulation_json.hpp"
#include "json_number.hpp"
#include "limits_json.hpp"
#include "summary_object.hpp"
#include "oracle_json.hpp"

namespace covopt::report {
namespace {

using nlohmann::ordered_json;

constexpr std::array<std::string_view, 12> kSpeedColumns = {
    "material", "robot_mass_kg", "max_safe_speed_m_per_s", "limited_by", "laceration_ratio",
    "contusion_ratio", "fracture_ratio", "compression_ratio", "status", "covering_law",
    "within_law", "covering_used_up_m_per_s"};
constexpr std::array<std::string_view, 11> kMassColumns = {
    "material", "speed_m_per_s", "max_safe_mass_kg", "limited_by", "laceration_ratio",
    "contusion_ratio", "fracture_ratio", "compression_ratio", "status", "covering_law", "within_law"};

/// The parts every row shares, whichever quantity it solves for.
struct RowAnswer {
  optim::SpeedLimitStatus status;
  double limit;  ///< the max safe speed [m/s] or mass [kg]
  optim::LimitingCriterion limited_by;
  const optim::LimitRatios* ratios;
  const std::string* message;
  const optim::LimitAnswer* answer;
};

RowAnswer Answer(SpeedLimitQuantity quantity, const SpeedLimitRow& row) {
  if (quantity == SpeedLimitQuantity::kSpeed) {
    const optim::SpeedLimit& l = row.speed_limit;
    return {l.status, l.max_safe_speed_m_per_s, l.limited_by, &l.at_limit, &l.message, &l};
  }
  const optim::MassLimit& l = row.mass_limit;
  return {l.status, l.max_safe_mass_kg, l.limited_by, &l.at_limit, &l.message, &l};
}

ordered_json MassValue(double kg) { return std::isinf(kg) ? ordered_json("fixed") : internal::Number(kg); }

ordered_json RowJson(SpeedLimitQuantity quantity, const SpeedLimitRow& row) {
  const RowAnswer a = Answer(quantity, row);
  // No safe value, or no answer at all (a failed evaluation): null, never the 0 the status carries.
  const bool none = a.status == optim::SpeedLimitStatus::kNoSafeValue ||
                    a.status == optim::SpeedLimitStatus::kEvaluationFailed;
  ordered_json j;
  j["material"] = row.material ? ordered_json(*row.material) : ordered_json(nullptr);
  if (quantity == SpeedLimitQuantity::kSpeed) {
    j["robot_mass_kg"] = MassValue(row.robot_mass_kg);
    j["max_safe_speed_m_per_s"] = none ? ordered_json(nullptr) : internal::Number(a.limit);
  } else {
    j["speed_m_per_s"] = internal::Number(row.speed_m_per_s);
    j["max_safe_mass_kg"] = none ? ordered_json(nullptr) : MassValue(a.limit);
  }
  j["limited_by"] = optim::ToString(a.limited_by);
  j["laceration_ratio"] = internal::Number(a.ratios->laceration_ratio);
  j["contusion_ratio"] = internal::Number(a.ratios->contusion_ratio);
  j["fracture_ratio"] = internal::Number(a.ratios->fracture_ratio);
  j["compression_ratio"] = internal::Number(a.ratios->compression_ratio);
  j["status"] = optim::ToString(a.status);
  // The covering's law and whether it is within its validity at the limit (the
  // note is the JSON's "validity" object); "" and within bare.
  j["covering_law"] = a.answer->covering_law;
  j["within_law"] = a.answer->validity.within ? "true" : "false";
  if (quantity == SpeedLimitQuantity::kSpeed) {
    const std::optional<double>& used_up = row.speed_limit.covering_used_up_m_per_s;
    j["covering_used_up_m_per_s"] = used_up ? internal::Number(*used_up) : ordered_json(nullptr);
  }
  return j;
}

std::string RowName(SpeedLimitQuantity quantity, const SpeedLimitRow& row) {
  std::string name = quantity == SpeedLimitQuantity::kSpeed
                         ? "robot mass " + (std::isinf(row.robot_mass_kg) ? std::string("fixed")
                                                                           : FormatSignificant(row.robot_mass_kg, 6) + " kg")
                         : "speed " + FormatSignificant(row.speed_m_per_s, 6) + " m/s";
  if (row.material) name += " (" + *row.material + ")";
  return name;
}

}  // namespace

std::span<const std::string_view> SpeedLimitColumns(SpeedLimitQuantity quantity) noexcept {
  return quantity == SpeedLimitQuantity::kSpeed ? std::span<const std::string_view>(kSpeedColumns)
                                                : std::span<const std::string_view>(kMassColumns);
}

std::vector<std::string> SpeedLimitCsvCells(SpeedLimitQuantity quantity, const SpeedLimitRow& row) {
  const ordered_json j = RowJson(quantity, row);
  std::vector<std::string> cells;
  for (const auto& [key, value] : j.items()) {
    if (value.is_null()) cells.emplace_back();
    else if (value.is_string()) cells.push_back(value.get<std::string>());
    else cells.push_back(FormatShortest(value.get<double>()));
  }
  return cells;
}

std::vector<std::string> SpeedLimitRowWarnings(SpeedLimitQuantity quantity, std::span<const SpeedLimitRow> rows) {
  std::vector<std::string> warnings;
  for (const SpeedLimitRow& row : rows) {
    const RowAnswer a = Answer(quantity, row);
    if (a.status == optim::SpeedLimitStatus::kSafeUpToSearchLimit) {
      const bool unlimited = quantity == SpeedLimitQuantity::kMass && std::isinf(a.limit);
      warnings.push_back(RowName(quantity, row) + ": " + *a.message +
                         (unlimited ? "" : "; the true limit is higher (limited_by \"none\")"));
    } else if (a.status == optim::SpeedLimitStatus::kNoSafeValue ||
               a.status == optim::SpeedLimitStatus::kEvaluationFailed) {
      warnings.push_back(RowName(quantity, row) + ": " + *a.message);
    }
  }
  return warnings;
}

std::string SpeedLimitJson(SpeedLimitQuantity quantity, const Scene& scene, const optim::SpeedLimitOptions& options,
                           std::span<const SpeedLimitRow> rows, std::span<const std::string> input_warnings,
                           int indent) {
  ordered_json j;
  j["solve_for"] = optim::ToString(quantity);
  internal::AddCriterionAndLimits(j, options);
  if (quantity == SpeedLimitQuantity::kSpeed) {
    j["search_limit"] = {{"max_speed_m_per_s", options.max_speed_m_per_s}};
  } else {
    j["search_limit"] = {{"max_mass_kg", options.max_mass_kg}};
  }
  if (!rows.empty()) {
    ordered_json oracle = internal::OracleJson(optim::SpeedLimitOracle(quantity, rows), false);
    const SpeedLimitRow& first = rows.front();
    const bool bracketed = quantity == SpeedLimitQuantity::kSpeed ? first.speed_limit.bracketed : first.mass_limit.bracketed;
    oracle["search"] = bracketed ? "bracketed-bisection" : "penetration-axis";
    j["oracle"] = oracle;
  }
  ordered_json list = ordered_json::array();
  for (const SpeedLimitRow& row : rows) {
    ordered_json r = RowJson(quantity, row);
    const optim::LimitAnswer& answer = *Answer(quantity, row).answer;
    r["within_law"] = answer.validity.within;  // a boolean in JSON (a word in the CSV)
    r["validity"] = {{"within", answer.validity.within}, {"note", answer.validity.note}};
    list.push_back(std::move(r));
  }
  j["rows"] = list;
  j["summary"] = internal::SummaryObject(optim::SummarizeSpeedLimits(quantity, scene, options, rows));

  ordered_json shown = ordered_json::parse(SceneJson(scene));
  const bool by_speed = quantity == SpeedLimitQuantity::kSpeed;
  bool shared = !rows.empty();
  for (const SpeedLimitRow& row : rows) {
    const SpeedLimitRow& first = rows.front();
    shared = shared && (by_speed ? row.robot_mass_kg == first.robot_mass_kg : row.speed_m_per_s == first.speed_m_per_s);
  }
  if (by_speed) {
    shown["robot"].erase("speed_m_per_s");
    if (shared) shown["robot"]["mass_kg"] = MassValue(rows.front().robot_mass_kg);
    else shown["robot"].erase("mass_kg");
  } else {
    shown["robot"].erase("mass_kg");
    if (shared) shown["robot"]["speed_m_per_s"] = internal::Number(rows.front().speed_m_per_s);
    else shown["robot"].erase("speed_m_per_s");
  }
  // Rows of several materials: the covering's modulus and Poisson ratio are the rows' own.
  const bool several_materials = std::any_of(rows.begin(), rows.end(), [&](const SpeedLimitRow& row) {
    return row.material != rows.front().material;
  });
  if (several_materials) {
    shown["covering"].erase("youngs_modulus_Pa");
    shown["covering"].erase("poisson_ratio");
  }
  j["scene"] = shown;
  std::vector<std::string> warnings(input_warnings.begin(), input_warnings.end());
  for (std::string& w : SpeedLimitRowWarnings(quantity, rows)) warnings.push_back(std::move(w));
  j["warnings"] = warnings;
  return j.dump(indent);
}

}  // namespace covopt::report
