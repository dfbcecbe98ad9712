// A trajectory safety check as JSON text (covopt robot --trajectory --json,
// covopt.check_trajectory()).
#include "covopt/report/trajectory_json.hpp"

#include <array>
#include <cmath>

#include <covopt/core/number_format.hpp>
#include <nlohmann/json.hpp>

#include "covopt/optim/summaries.hpp"
#include "covopt/report/simulation_json.hpp"
#include "json_number.hpp"
#include "limits_json.hpp"
#include "summary_object.hpp"

namespace covopt::report {
namespace {

using nlohmann::ordered_json;

constexpr std::array<std::string_view, 13> kSampleColumns = {
    "time_s",      "speed_m_per_s", "reflected_mass_kg", "moving",         "max_safe_speed_m_per_s",
    "speed_scale", "limited_by",    "laceration_ratio",  "contusion_ratio", "fracture_ratio",
    "compression_ratio", "safe",    "within_law"};

ordered_json MassValue(double kg) { return std::isinf(kg) ? ordered_json("fixed") : internal::Number(kg); }

ordered_json SampleJson(const optim::SampleVerdict& v) {
  // A failed evaluation has no answer: its limit, scale, ratios and verdict are null.
  const bool failed = v.evaluation_failed;
  const bool none_safe = v.speed_limit.status == optim::SpeedLimitStatus::kNoSafeValue ||
                         v.speed_limit.status == optim::SpeedLimitStatus::kEvaluationFailed;
  const auto ratio = [failed](double value) { return failed ? ordered_json(nullptr) : internal::Number(value); };
  ordered_json j;
  j["time_s"] = internal::Number(v.time_s);
  j["speed_m_per_s"] = internal::Number(v.speed_m_per_s);
  j["reflected_mass_kg"] = MassValue(v.reflected_mass_kg);
  j["moving"] = v.moving;
  j["max_safe_speed_m_per_s"] =
      none_safe ? ordered_json(nullptr) : internal::Number(v.speed_limit.max_safe_speed_m_per_s);
  j["speed_scale"] = v.moving && !failed ? internal::Number(v.speed_scale) : ordered_json(nullptr);
  j["limited_by"] = optim::ToString(v.speed_limit.limited_by);
  j["laceration_ratio"] = ratio(v.laceration_ratio);
  j["contusion_ratio"] = ratio(v.contusion_ratio);
  j["fracture_ratio"] = ratio(v.fracture_ratio);
  j["compression_ratio"] = ratio(v.compression_ratio);
  j["safe"] = failed ? ordered_json(nullptr) : ordered_json(v.safe);
  j["within_law"] = v.validity.within;  // the covering's law at this impact
  return j;
}

}  // namespace

std::span<const std::string_view> TrajectorySampleColumns() noexcept { return kSampleColumns; }

std::vector<std::string> TrajectorySampleCsvCells(const optim::SampleVerdict& sample) {
  const ordered_json j = SampleJson(sample);
  std::vector<std::string> cells;
  for (const auto& [key, value] : j.items()) {
    if (value.is_null()) cells.emplace_back();
    else if (value.is_string()) cells.push_back(value.get<std::string>());
    else if (value.is_boolean()) cells.emplace_back(value.get<bool>() ? "true" : "false");
    else cells.push_back(FormatShortest(value.get<double>()));
  }
  return cells;
}

std::string TrajectoryCheckJson(const optim::TrajectoryCheck& check, const robot::ContactMotionResult& motion,
                                const Scene& scene, const std::optional<std::string>& covering_material,
                                const optim::SpeedLimitOptions& options,
                                std::span<const std::string> input_warnings, int indent) {
  ordered_json j;
  j["status"] = optim::ToString(check.status);
  j["message"] = check.message;
  ResultSummary summary = optim::SummarizeTrajectory(check, scene, covering_material.value_or(std::string()));
  summary.robot.joints = motion.joint_names;
  j["summary"] = internal::SummaryObject(summary);
  j["safe_speed_scale"] = check.status == optim::TrajectoryCheckStatus::kEvaluationFailed
                              ? ordered_json(nullptr)  // no verdict
                              : internal::Number(check.safe_speed_scale);  // +inf (at rest): null
  if (check.worst_sample) {
    ordered_json worst;
    worst["index"] = *check.worst_sample;
    const ordered_json sample = SampleJson(check.samples[*check.worst_sample]);
    for (const auto& [key, value] : sample.items()) worst[key] = value;
    j["worst_sample"] = worst;
  } else {
    j["worst_sample"] = nullptr;
  }
  // The covering's law and its validity over the samples.
  j["covering_law"] = check.covering_law;
  j["validity"] = {{"within", check.validity.within}, {"note", check.validity.note}};
  j["sample_count"] = check.samples.size();
  j["unsafe_sample_count"] = check.unsafe_sample_count;
  j["failed_sample_count"] = check.failed_sample_count;
  internal::AddCriterionAndLimits(j, options);
  j["search_limit"] = {{"max_speed_m_per_s", options.max_speed_m_per_s}};
  ordered_json shown = ordered_json::parse(SceneJson(scene));
  shown["robot"].erase("mass_kg");  // each sample's own
  shown["robot"].erase("speed_m_per_s");
  shown["covering"]["material"] = covering_material ? ordered_json(*covering_material) : ordered_json(nullptr);
  j["scene"] = shown;
  j["joint_names"] = motion.joint_names;
  ordered_json samples = ordered_json::array();
  for (const optim::SampleVerdict& v : check.samples) samples.push_back(SampleJson(v));
  j["samples"] = samples;
  std::vector<std::string> warnings(input_warnings.begin(), input_warnings.end());
  warnings.insert(warnings.end(), motion.warnings.begin(), motion.warnings.end());
  warnings.insert(warnings.end(), check.warnings.begin(), check.warnings.end());
  j["warnings"] = warnings;
  return j.dump(indent);
}

}  // namespace covopt::report
