// ISO/TS 15066 body-region results as JSON text and CSV cells (covopt simulate, speed-limit
// and optimize with --body-region).
#include "covopt/report/body_contact_json.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include <covopt/core/number_format.hpp>
#include <nlohmann/json.hpp>

#include "covopt/optim/summaries.hpp"
#include "covopt/report/summary_json.hpp"
#include "json_number.hpp"
#include "summary_object.hpp"
#include "verdict_object.hpp"

namespace covopt::report {
namespace {

using internal::Number;
using nlohmann::ordered_json;

constexpr std::array<std::string_view, 13> kTableColumns = {
    "material", "robot_mass_kg", "region", "area", "contact", "force_limit_N", "pressure_limit_Pa", "bare_max_speed_m_per_s",
    "bare_limited_by", "covered_max_speed_m_per_s", "covered_limited_by", "gain", "criteria"};

ordered_json MassValue(double kg) { return std::isinf(kg) ? ordered_json("fixed") : Number(kg); }

ordered_json SceneObject(const BodyContactScene& scene, const std::optional<std::string>& material, bool without_robot) {
  ordered_json j;
  if (!without_robot) {
    j["robot_mass_kg"] = MassValue(scene.robot_mass_kg);
    j["speed_m_per_s"] = Number(scene.speed_m_per_s);
  }
  j["robot_radius_m"] = std::isinf(scene.robot_radius_m) ? ordered_json("flat") : Number(scene.robot_radius_m);
  if (scene.has_covering()) {
    j["covering"] = {{"youngs_modulus_Pa", Number(scene.covering.youngs_modulus_Pa)},
                     {"poisson_ratio", Number(scene.covering.poisson_ratio)},
                     {"thickness_m", Number(scene.covering.thickness_m)},
                     {"material", material ? ordered_json(*material) : ordered_json(nullptr)}};
  } else {
    j["covering"] = nullptr;
  }
  j["contact"] = ToString(scene.contact);
  j["contact_area_m2"] = scene.contact_area_m2 > 0.0 ? Number(scene.contact_area_m2) : ordered_json(nullptr);
  if (scene.robot_brakes()) {
    j["braking"] = {{"reaction_delay_s", Number(scene.reaction_delay_s)},
                    {"braking_m_per_s2", Number(scene.braking_m_per_s2)}};
  }
  return j;
}

ordered_json JudgementObject(const optim::BodyRegionJudgement& v, double safety_factor) {
  const BodyContactResult& c = v.contact;
  ordered_json j;
  j["region"] = v.limits.region->name;
  j["area"] = v.limits.area->name;
  j["area_title"] = v.limits.area->title;
  j["contact"] = ToString(v.limits.contact);
  j["criteria"] = v.scope;
  j["scope"] = v.limits.Describe();
  j["method"] = c.method;
  j["reduced_mass_kg"] = Number(c.reduced_mass_kg);
  j["energy_transferred_J"] = Number(c.energy_transferred_J);
  j["peak_force_N"] = Number(c.peak_force_N);
  j["peak_pressure_Pa"] = Number(c.peak_pressure_Pa);
  j["contact_radius_m"] = Number(c.contact_radius_m);
  j["covering_deflection_m"] = Number(c.covering_deflection_m);
  j["body_deflection_m"] = Number(c.body_deflection_m);
  j["compression_ratio"] = Number(v.compression_ratio);
  j["fully_compressed"] = c.fully_compressed;
  // The covering's law (null bare) and whether the peak is within what it describes.
  j["covering_law"] = c.covering_law ? ordered_json(ToString(*c.covering_law)) : ordered_json(nullptr);
  j["validity"] = {{"within", c.validity.within}, {"ratio", c.validity.ratio}, {"note", c.validity.note}};
  j["force"] = {{"value_N", Number(c.peak_force_N)},
                {"limit_N", Number(v.limits.force_N)},
                {"ratio", Number(v.force_ratio)}};
  j["pressure"] = {{"value_Pa", Number(c.peak_pressure_Pa)},
                   {"limit_Pa", Number(v.limits.pressure_Pa)},
                   {"ratio", Number(v.pressure_ratio)},
                   {"evaluated", v.pressure_ratio.has_value()}};
  j["crush"] = {{"check", optim::ToString(v.crush_check)},
                {"ratio", v.crush_check == optim::CrushCheck::kChecked ? Number(v.crush_ratio) : ordered_json(nullptr)}};
  j["governing"] = optim::ToString(v.governing);
  j["governing_ratio"] = Number(v.governing_ratio);
  j["safety_factor"] = Number(safety_factor);
  j["admissible"] = v.admissible;
  j["margin"] = Number(v.margin);
  j["verdict"] = internal::VerdictObject(v.verdict);
  return j;
}

ordered_json Strings(std::span<const std::string> lines) {
  ordered_json j = ordered_json::array();
  for (const std::string& line : lines) j.push_back(line);
  return j;
}

ordered_json HeadScore(const optim::DesignScore& score, const std::string& criteria) {
  return {{"laceration_ratio", Number(score.laceration_ratio)},
          {"contusion_ratio", Number(score.contusion_ratio)},
          {"compression_ratio", Number(score.compression_ratio)},
          {"criteria", criteria}};
}

ordered_json TableRowObject(const BodyRegionTableRow& row) {
  ordered_json j;
  j["material"] = row.material.empty() ? ordered_json(nullptr) : ordered_json(row.material);
  j["robot_mass_kg"] = MassValue(row.robot_mass_kg);
  j["region"] = row.region;
  j["area"] = row.area.empty() ? ordered_json(nullptr) : ordered_json(row.area);
  j["contact"] = row.contact;
  j["force_limit_N"] = Number(row.force_limit_N);
  j["pressure_limit_Pa"] = Number(row.pressure_limit_Pa);
  j["bare_max_speed_m_per_s"] = Number(row.bare_max_speed_m_per_s);
  j["bare_limited_by"] = row.bare_limited_by;
  j["covered_max_speed_m_per_s"] = Number(row.covered_max_speed_m_per_s);
  j["covered_limited_by"] = row.has_covering ? ordered_json(row.covered_limited_by) : ordered_json(nullptr);
  j["gain"] = Number(row.gain);
  j["criteria"] = row.criteria;
  j["bare_status"] = row.bare_status;
  j["covered_status"] = row.has_covering ? ordered_json(row.covered_status) : ordered_json(nullptr);
  j["covering_law"] = row.covering_law;
  j["covering_used_up_m_per_s"] = Number(row.covering_used_up_m_per_s);
  j["validity"] = {{"within", row.within_law}, {"note", row.validity_note}};
  return j;
}

std::string Cell(const std::optional<double>& value) { return value ? FormatShortest(*value) : std::string(); }

std::string RegionName(const BodyRegionTableRow& row) {
  return row.area.empty() ? row.region : row.region + " (" + row.area + ")";
}

/// One table row's limit: the covered one when there is a covering, else the bare one (the
/// row's own answer, mapped; nothing is judged here).
LimitRow TableLimit(const BodyRegionTableRow& row) {
  const bool covered = row.has_covering;
  const std::string& status = covered ? row.covered_status : row.bare_status;
  const std::optional<double>& speed = covered ? row.covered_max_speed_m_per_s : row.bare_max_speed_m_per_s;
  LimitRow limit{.target = RegionName(row) + (row.material.empty() ? "" : ", " + row.material) + ", robot mass " +
                           (std::isinf(row.robot_mass_kg) ? std::string("fixed") : FormatSignificant(row.robot_mass_kg, 4) + " kg"),
                 .quantity = "max safe speed",
                 .unit = "m/s",
                 .value = speed.value_or(0.0),
                 .binding_criterion = covered ? row.covered_limited_by : row.bare_limited_by,
                 .law = covered ? row.covering_law : std::string("bare"),
                 .validity = covered ? (row.within_law ? std::string("within") : row.validity_note) : std::string(),
                 .note = ""};
  if (status == optim::ToString(optim::SpeedLimitStatus::kSafeUpToSearchLimit)) {
    limit.value = std::numeric_limits<double>::infinity();
    limit.binding_criterion.clear();
    limit.note = "not limited below the search limit";
  } else if (status == optim::ToString(optim::SpeedLimitStatus::kNoSafeValue)) {
    limit.note = "no safe value";
  } else if (status == optim::ToString(optim::SpeedLimitStatus::kEvaluationFailed)) {
    limit.value = std::numeric_limits<double>::quiet_NaN();
    limit.note = "not evaluated";
  }
  return limit;
}

/// The limits summary of the all-regions table: one limit row per table row; the lowest governs.
ResultSummary TableSummary(std::span<const BodyRegionTableRow> rows, double safety_factor) {
  ResultSummary s;
  s.kind = ResultSummary::Kind::kLimits;
  s.command = "speed-limit --body-region";
  s.safety_factor = safety_factor;
  for (const BodyRegionTableRow& row : rows) {
    s.limits.push_back(TableLimit(row));
    s.evaluated = s.evaluated && !std::isnan(s.limits.back().value);
    if (std::find(s.targets.begin(), s.targets.end(), RegionName(row)) == s.targets.end()) s.targets.push_back(RegionName(row));
    if (std::find(s.scope.begin(), s.scope.end(), row.criteria) == s.scope.end()) s.scope.push_back(row.criteria);
    if (row.limit_table) s.AddLimitTable(*row.limit_table);
  }
  s.Finish();
  s.robot.speed_m_per_s = std::numeric_limits<double>::quiet_NaN();
  s.robot.reflected_mass_kg = std::numeric_limits<double>::quiet_NaN();
  return s;
}

}  // namespace

std::vector<std::string> TimePathWarnings(const optim::BodyRegionJudgement& judgement,
                                          const BodyContactResult* time_path) {
  std::vector<std::string> lines;
  for (const BodyContactResult* run : {&judgement.contact, time_path}) {
    if (!run) continue;
    for (const std::string& message : run->WarningMessages()) {
      lines.push_back(judgement.limits.region->name + " (" + judgement.limits.area->name + "): " + message);
    }
  }
  return lines;
}

std::string BodyContactSceneJson(const BodyContactScene& scene, const std::optional<std::string>& material,
                                 bool without_robot) {
  return SceneObject(scene, material, without_robot).dump(2);
}

std::string BodyRegionJudgementJson(const optim::BodyRegionJudgement& judgement, double safety_factor) {
  return JudgementObject(judgement, safety_factor).dump(2);
}

std::string BodyContactSimulationJson(const BodyContactScene& scene, const std::optional<std::string>& material,
                                      std::span<const optim::BodyRegionJudgement> regions, double safety_factor,
                                      const std::optional<std::string>& head_json,
                                      std::span<const std::string> warnings) {
  ordered_json j;
  j["scene"] = SceneObject(scene, material, false);
  j["safety_factor"] = Number(safety_factor);
  j["regions"] = ordered_json::array();
  bool safe = true;
  for (const optim::BodyRegionJudgement& v : regions) {
    j["regions"].push_back(JudgementObject(v, safety_factor));
    safe = safe && v.admissible;
  }
  if (head_json) {
    j["head"] = ordered_json::parse(*head_json);
    const auto& head_safe = j["head"]["safe"];
    safe = safe && head_safe.is_boolean() && head_safe.get<bool>();
  } else {
    j["head"] = nullptr;
  }
  j["safe"] = safe;
  const std::optional<ResultSummary> head = head_json ? std::optional(SummaryFromJson(*head_json)) : std::nullopt;
  j["summary"] = internal::SummaryObject(
      optim::SummarizeBodyContact(scene, material.value_or(std::string()), regions, head ? &*head : nullptr));
  j["warnings"] = Strings(warnings);
  return j.dump(2);
}

std::span<const std::string_view> BodyRegionTableColumns() noexcept { return kTableColumns; }

std::vector<std::string> BodyRegionTableCsvCells(const BodyRegionTableRow& row) {
  return {row.material,
          std::isinf(row.robot_mass_kg) ? std::string("fixed") : FormatShortest(row.robot_mass_kg),
          row.region,
          row.area,
          row.contact,
          Cell(row.force_limit_N),
          Cell(row.pressure_limit_Pa),
          Cell(row.bare_max_speed_m_per_s),
          row.bare_limited_by,
          Cell(row.covered_max_speed_m_per_s),
          row.covered_limited_by,
          Cell(row.gain),
          row.criteria};
}

std::string BodyRegionSpeedLimitJson(const BodyContactScene& scene, const std::optional<std::string>& material,
                                     std::string_view criterion, double safety_factor,
                                     std::span<const BodyRegionTableRow> rows,
                                     std::span<const std::string> warnings) {
  ordered_json j;
  j["solve_for"] = "speed";
  j["scene"] = SceneObject(scene, material, true);
  j["criterion"] = criterion;
  j["safety_factor"] = Number(safety_factor);
  j["rows"] = ordered_json::array();
  for (const BodyRegionTableRow& row : rows) j["rows"].push_back(TableRowObject(row));
  ResultSummary summary = TableSummary(rows, safety_factor);
  summary.covering = CoveringSummary{.present = scene.has_covering(),
                                     .material = material.value_or(std::string()),
                                     .thickness_m = scene.covering.thickness_m,
                                     .law = rows.empty() ? std::string() : rows.front().covering_law,
                                     .validity = "",
                                     .validity_ratio = std::numeric_limits<double>::quiet_NaN()};
  j["summary"] = internal::SummaryObject(summary);
  j["warnings"] = Strings(warnings);
  return j.dump(2);
}

std::string BodyRegionDesignJson(const optim::BodyRegionDesignRequest& request,
                                 const optim::BodyRegionDesignResult& result, std::string_view criterion,
                                 std::span<const std::string> warnings) {
  const double sf = request.rule.safety_factor;
  const std::string head_criteria = "skin injury, Park et al. 2011";
  const auto candidate_json = [&](const optim::BodyRegionDesignCandidate& c) {
    ordered_json j;
    j["material"] = c.material.name;
    j["youngs_modulus_Pa"] = Number(c.material.youngs_modulus_Pa);
    j["poisson_ratio"] = Number(c.material.poisson_ratio);
    j["thickness_m"] = Number(c.thickness_m);
    j["admissible"] = c.admissible();
    j["governing_ratio"] = Number(c.governing_ratio);
    j["governing_where"] = c.governing_where;
    j["regions"] = ordered_json::array();
    for (const optim::BodyRegionJudgement& v : c.regions) j["regions"].push_back(JudgementObject(v, sf));
    j["head"] = c.head ? HeadScore(*c.head, head_criteria) : ordered_json(nullptr);
    return j;
  };
  ordered_json j;
  j["message"] = result.message;
  j["summary"] = internal::SummaryObject(optim::SummarizeBodyRegionDesign(request, result));
  j["speed_m_per_s"] = Number(request.scene.speed_m_per_s);
  j["scene"] = SceneObject(request.scene, std::nullopt, false);
  j["safety_factor"] = Number(sf);
  j["criterion"] = criterion;
  j["recommendation"] =
      result.recommendation ? candidate_json(result.candidates.at(*result.recommendation)) : ordered_json(nullptr);
  ordered_json bare;
  bare["safe"] = result.bare_robot_safe;
  bare["regions"] = ordered_json::array();
  for (const optim::BodyRegionJudgement& v : result.bare_robot) bare["regions"].push_back(JudgementObject(v, sf));
  bare["head"] = result.bare_head ? HeadScore(*result.bare_head, head_criteria) : ordered_json(nullptr);
  j["bare_robot"] = std::move(bare);
  j["candidates"] = ordered_json::array();
  for (const optim::BodyRegionDesignCandidate& c : result.candidates) j["candidates"].push_back(candidate_json(c));
  j["scope"] = Strings(result.scope);
  std::vector<std::string> all_warnings(warnings.begin(), warnings.end());
  all_warnings.insert(all_warnings.end(), result.warnings.begin(), result.warnings.end());
  j["warnings"] = Strings(all_warnings);
  return j.dump(2);
}

std::string BodyRegionTrajectoryJson(const optim::BodyRegionTrajectoryCheck& check,
                                     std::span<const materials::BodyLimits> regions, const BodyContactScene& scene,
                                     const std::optional<HeadTrajectorySummary>& head, std::string_view criterion,
                                     double safety_factor, std::span<const std::string> warnings) {
  ordered_json j;
  j["status"] = optim::ToString(check.status);
  j["message"] = check.message;
  j["summary"] = internal::SummaryObject(optim::SummarizeBodyRegionTrajectory(check, regions, scene, safety_factor));
  j["safe_speed_scale"] = Number(check.safe_speed_scale);
  j["worst_sample"] = check.worst_sample ? ordered_json(*check.worst_sample) : ordered_json(nullptr);
  j["unsafe_sample_count"] = check.unsafe_sample_count;
  j["criterion"] = criterion;
  j["scene"] = SceneObject(scene, std::nullopt, true);
  j["regions"] = ordered_json::array();
  for (const materials::BodyLimits& limits : regions) {
    j["regions"].push_back({{"region", limits.region->name},
                            {"area", limits.area->name},
                            {"contact", ToString(limits.contact)},
                            {"scope", limits.Describe()}});
  }
  if (head) {
    j["head"] = {{"status", head->status},
                 {"safe_speed_scale", Number(head->safe_speed_scale)},
                 {"message", head->message}};
  } else {
    j["head"] = nullptr;
  }
  j["samples"] = ordered_json::array();
  for (const optim::BodyRegionSampleVerdict& v : check.samples) {
    ordered_json s;
    s["time_s"] = Number(v.time_s);
    s["speed_m_per_s"] = Number(v.speed_m_per_s);
    s["reflected_mass_kg"] = MassValue(v.reflected_mass_kg);
    s["moving"] = v.moving;
    s["worst_ratio"] = Number(v.worst_ratio);
    s["binding"] = optim::ToString(v.binding);
    s["worst_region"] = v.moving ? ordered_json(v.worst_region) : ordered_json(nullptr);
    s["safe"] = v.safe;
    s["max_safe_speed_m_per_s"] = v.moving ? Number(v.max_safe_speed_m_per_s) : ordered_json(nullptr);
    s["limiting_region"] = v.moving ? ordered_json(v.limiting_region) : ordered_json(nullptr);
    s["limited_by"] = optim::ToString(v.limited_by);
    s["speed_scale"] = Number(v.speed_scale);
    j["samples"].push_back(std::move(s));
  }
  j["warnings"] = Strings(warnings);
  return j.dump(2);
}

std::string BodyContactTimePathJson(const BodyContactResult& r) {
  nlohmann::ordered_json j;
  j["method"] = r.method;
  j["peak_force_N"] = Number(r.peak_force_N);
  j["peak_pressure_Pa"] = Number(r.peak_pressure_Pa);
  j["contact_radius_m"] = Number(r.contact_radius_m);
  j["covering_deflection_m"] = Number(r.covering_deflection_m);
  j["body_deflection_m"] = Number(r.body_deflection_m);
  j["max_approach_m"] = Number(r.max_approach_m);
  j["compression_ratio"] = Number(r.compression_ratio);
  j["fully_compressed"] = r.fully_compressed;
  j["energy_transferred_J"] = Number(r.energy_transferred_J);
  j["contact_duration_s"] = Number(r.contact_duration_s);
  j["rebound_speed_m_per_s"] = Number(r.rebound_speed_m_per_s);
  j["energy_residual"] = Number(r.energy_residual);
  j["warnings"] = r.WarningMessages();
  return j.dump(2);
}

std::vector<HistoryColumn> BodyContactHistoryColumns(std::span<const BodyContactSample> history) {
  using Field = double (*)(const BodyContactSample&);
  static constexpr std::pair<std::string_view, Field> kFields[] = {
      {"time_s", [](const BodyContactSample& s) { return s.time_s; }},
      {"approach_m", [](const BodyContactSample& s) { return s.approach_m; }},
      {"approach_rate_m_per_s", [](const BodyContactSample& s) { return s.approach_rate_m_per_s; }},
      {"force_N", [](const BodyContactSample& s) { return s.force_N; }},
      {"robot_speed_m_per_s", [](const BodyContactSample& s) { return s.robot_speed_m_per_s; }},
      {"braking_work_J", [](const BodyContactSample& s) { return s.braking_work_J; }},
  };
  std::vector<HistoryColumn> columns;
  for (const auto& [name, field] : kFields) {
    HistoryColumn& c = columns.emplace_back(HistoryColumn{name, {}});
    c.values.reserve(history.size());
    for (const BodyContactSample& s : history) c.values.push_back(field(s));
  }
  return columns;
}

}  // namespace covopt::report
