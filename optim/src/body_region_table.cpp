#include "covopt/optim/body_region_table.hpp"

#include <utility>

#include "covopt/optim/summaries.hpp"

namespace covopt::optim {
namespace {

std::optional<double> SpeedOrNone(SpeedLimitStatus status, double speed) {
  if (status == SpeedLimitStatus::kNoSafeValue || status == SpeedLimitStatus::kEvaluationFailed) {
    return std::nullopt;
  }
  return speed;
}

}  // namespace

BodyRegionTableRow TableRow(double robot_mass_kg, const BodyRegionSpeedLimitRow& row) {
  BodyRegionTableRow r;
  r.robot_mass_kg = robot_mass_kg;
  r.region = row.limits.region->name;
  r.area = row.limits.area->name;
  r.contact = std::string(ToString(row.limits.contact));
  r.force_limit_N = row.limits.force_N;
  r.pressure_limit_Pa = row.limits.pressure_Pa;
  r.bare_max_speed_m_per_s = SpeedOrNone(row.bare.status, row.bare.max_safe_speed_m_per_s);
  r.bare_limited_by = std::string(ToString(row.bare.limited_by));
  r.bare_status = std::string(ToString(row.bare.status));
  if (row.covered) {
    r.has_covering = true;
    r.covered_max_speed_m_per_s = SpeedOrNone(row.covered->status, row.covered->max_safe_speed_m_per_s);
    r.covered_limited_by = std::string(ToString(row.covered->limited_by));
    r.covered_status = std::string(ToString(row.covered->status));
    const BodyContactResult& at = row.covered->at_limit.contact;
    r.covering_law = at.covering_law ? std::string(ToString(*at.covering_law)) : std::string();
    r.within_law = at.validity.within;
    r.validity_note = at.validity.note;
    r.covering_used_up_m_per_s = row.covered->covering_used_up_m_per_s;
  }
  r.gain = row.gain();
  r.criteria = row.bare.at_limit.scope.empty() ? row.limits.Describe() : row.bare.at_limit.scope;
  r.limit_table = LimitTableOf(row.limits);
  return r;
}

BodyRegionTableRow TableRow(const TargetSpeedLimit& row, const std::string& material) {
  BodyRegionTableRow r = row.region ? TableRow(row.robot_mass_kg, *row.region)
                                    : HeadTableRow(row.robot_mass_kg, row.head_bare.value(), row.head_covered,
                                                   std::string(HeadCriteriaName()));
  r.material = material;
  return r;
}

BodyRegionTableRow HeadTableRow(double robot_mass_kg, const SpeedLimit& bare,
                                const std::optional<SpeedLimit>& covered, std::string criteria) {
  BodyRegionTableRow r;
  r.robot_mass_kg = robot_mass_kg;
  r.region = "head";
  r.contact = std::string(ToString(ContactType::kTransient));
  r.bare_max_speed_m_per_s = SpeedOrNone(bare.status, bare.max_safe_speed_m_per_s);
  r.bare_limited_by = std::string(ToString(bare.limited_by));
  r.bare_status = std::string(ToString(bare.status));
  if (covered) {
    r.has_covering = true;
    r.covered_max_speed_m_per_s = SpeedOrNone(covered->status, covered->max_safe_speed_m_per_s);
    r.covered_limited_by = std::string(ToString(covered->limited_by));
    r.covered_status = std::string(ToString(covered->status));
    r.covering_law = covered->covering_law;
    r.within_law = covered->validity.within;
    r.validity_note = covered->validity.note;
    r.covering_used_up_m_per_s = covered->covering_used_up_m_per_s;
    if (r.bare_max_speed_m_per_s && *r.bare_max_speed_m_per_s > 0.0 && r.covered_max_speed_m_per_s) {
      r.gain = *r.covered_max_speed_m_per_s / *r.bare_max_speed_m_per_s;
    }
  }
  r.criteria = std::move(criteria);
  return r;
}

}  // namespace covopt::optim
