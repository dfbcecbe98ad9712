#include "covopt/report/speed_limit_text.hpp"

#include <cmath>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/core/quantity.hpp"
#include "covopt/report/body_contact_json.hpp"
#include "covopt/report/robust_text.hpp"

namespace covopt::report {
namespace {

std::string MassText(double kg) { return std::isinf(kg) ? std::string("fixed") : fmt::format("{:.4g} kg", kg); }

}  // namespace

void PrintSpeedLimitRows(std::ostream& out, optim::SpeedLimitQuantity quantity, bool several_materials,
                         std::span<const optim::SpeedLimitRow> rows) {
  const bool by_speed = quantity == optim::SpeedLimitQuantity::kSpeed;
  const bool materials = several_materials;
  if (materials) fmt::print(out, "  {:<28}", "material");
  fmt::print(out, "  {:>12}  {:>16}  {:<16}  {:>10}  {:>9}  {:>11}\n", by_speed ? "robot mass" : "speed",
             by_speed ? "max safe speed" : "max safe mass", "limited by", "laceration", "contusion", "compression");
  for (const optim::SpeedLimitRow& row : rows) {
    const optim::SpeedLimitStatus status = by_speed ? row.speed_limit.status : row.mass_limit.status;
    const optim::LimitRatios& r = by_speed ? row.speed_limit.at_limit : row.mass_limit.at_limit;
    const optim::LimitingCriterion by = by_speed ? row.speed_limit.limited_by : row.mass_limit.limited_by;
    std::string limit;
    if (status == optim::SpeedLimitStatus::kNoSafeValue) {
      limit = "none safe";
    } else if (by_speed) {
      limit = fmt::format("{}{:.4g} m/s", status == optim::SpeedLimitStatus::kSafeUpToSearchLimit ? ">= " : "",
                          row.speed_limit.max_safe_speed_m_per_s);
    } else {
      const double m = row.mass_limit.max_safe_mass_kg;
      limit = std::isinf(m) ? std::string("fixed")
                            : fmt::format("{}{:.4g} kg",
                                          status == optim::SpeedLimitStatus::kSafeUpToSearchLimit ? ">= " : "", m);
    }
    if (materials) fmt::print(out, "  {:<28}", row.material.value_or("(scene's covering)").substr(0, 28));
    const std::string compression =
        r.compression_ratio > 0.0 ? fmt::format("{:.3f}", r.compression_ratio) : std::string("-");
    fmt::print(out, "  {:>12}  {:>16}  {:<16}  {:>10.3f}  {:>9.3f}  {:>11}\n",
               by_speed ? MassText(row.robot_mass_kg) : fmt::format("{:g} m/s", row.speed_m_per_s), limit,
               optim::ToString(by), r.laceration_ratio, r.contusion_ratio, compression);
    // The covering's law and its validity at the limit, and where it is used up.
    const optim::LimitAnswer& answer = by_speed ? static_cast<const optim::LimitAnswer&>(row.speed_limit)
                                                : static_cast<const optim::LimitAnswer&>(row.mass_limit);
    if (answer.covering_law.empty()) continue;
    std::string law = fmt::format("    covering law {}, {}: {}", answer.covering_law,
                                  answer.validity.within ? "within its validity" : "OUT of its validity",
                                  answer.validity.note);
    const std::optional<double>& used_up = row.speed_limit.covering_used_up_m_per_s;
    if (by_speed && used_up && *used_up < row.speed_limit.max_safe_speed_m_per_s) {
      law += fmt::format("; covering used up at v = {:.4g} m/s", *used_up);
    }
    fmt::print(out, "{}\n", law);
  }
}

std::string RobustSpeedLimitRowText(const optim::UncertaintyBox& box, optim::SpeedLimitQuantity quantity,
                                    const optim::RobustSpeedLimitRow& row) {
  const std::string material = row.material.value_or("");
  std::string text;
  if (quantity == optim::SpeedLimitQuantity::kSpeed) {
    const double value = row.robot_mass_kg;
    const optim::RobustSpeedLimit& limit = row.speed_limit;
    text += fmt::format("{}{}robot {}: max safe speed {} for every value in the box ({}), limited by {}\n",
                        material, material.empty() ? "" : ", ", FormatQuantity(value, QuantityKind::kMass),
                        FormatQuantity(limit.limit.max_safe_speed_m_per_s, QuantityKind::kSpeed),
                        optim::ToString(limit.limit.status), optim::ToString(limit.limit.limited_by));
    text += fmt::format("  set at: {} (found by {}, {} evaluations)\n", DescribeValues(box, limit.values),
                        limit.found_by, limit.evaluations);
  } else {
    const double value = row.speed_m_per_s;
    const optim::RobustMassLimit& limit = row.mass_limit;
    text += fmt::format("{}{}at {}: max safe robot mass {} for every value in the box ({}), limited by {}\n",
                        material, material.empty() ? "" : ", ", FormatQuantity(value, QuantityKind::kSpeed),
                        FormatQuantity(limit.limit.max_safe_mass_kg, QuantityKind::kMass),
                        optim::ToString(limit.limit.status), optim::ToString(limit.limit.limited_by));
    text += fmt::format("  set at: {} (found by {}, {} evaluations)\n", DescribeValues(box, limit.values),
                        limit.found_by, limit.evaluations);
  }
  return text;
}

void PrintBodyRegionSpeedLimitRows(std::ostream& out, std::span<const BodyRegionTableRow> rows) {
  std::string block;
  for (const report::BodyRegionTableRow& row : rows) {
    const std::string key = fmt::format("{}|{}", row.material, row.robot_mass_kg);
    if (key != block) {
      block = key;
      fmt::print(out, "\n{}robot mass {}\n", row.material.empty() ? "" : "Material " + row.material + ", ",
                 MassText(row.robot_mass_kg));
      fmt::print(out, "  {:<18} {:<34} {:>7} {:>8}  {:>9}  {:<16} {:>11}  {:<16} {:>7}\n", "region", "area",
                 "F_lim N", "p_lim", "bare m/s", "bare binds", "covered m/s", "covered binds", "gain");
    }
    const auto speed = [](const std::optional<double>& v, const std::string& status) {
      if (!v) return std::string("none");
      return fmt::format("{}{:.4f}", status == "safe-up-to-search-limit" ? ">=" : "", *v);
    };
    fmt::print(out, "  {:<18} {:<34} {:>7} {:>8}  {:>9}  {:<16} {:>11}  {:<16} {:>7}\n", row.region,
               row.area.empty() ? "-" : row.area,
               row.force_limit_N ? fmt::format("{:.0f}", *row.force_limit_N) : std::string("-"),
               row.pressure_limit_Pa ? fmt::format("{:.0f}", *row.pressure_limit_Pa * 1e-4) : std::string("-"),
               speed(row.bare_max_speed_m_per_s, row.bare_status), row.bare_limited_by,
               row.has_covering ? speed(row.covered_max_speed_m_per_s, row.covered_status) : std::string("-"),
               row.has_covering ? row.covered_limited_by : std::string("-"),
               row.gain ? fmt::format("{:.2f}×", *row.gain) : std::string("-"));
    // The covering's law where it says something the row does not: out of its validity, or
    // used up below the limit.
    const bool used_up = row.covering_used_up_m_per_s && row.covered_max_speed_m_per_s &&
                         *row.covering_used_up_m_per_s < *row.covered_max_speed_m_per_s;
    if (row.has_covering && (used_up || !row.within_law)) {
      fmt::print(out, "  {:<18} covering law {}, {}{}\n", "", row.covering_law,
                 row.within_law ? "within its validity" : "OUT of its validity: " + row.validity_note,
                 used_up ? fmt::format("; covering used up at v = {:.4g} m/s", *row.covering_used_up_m_per_s) : "");
    }
  }
}

}  // namespace covopt::report
