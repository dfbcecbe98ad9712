// The re-timed program as JSON text (covopt retime --json, covopt.retime()).
#include "covopt/report/retime_json.hpp"

#include <cmath>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "covopt/audit/summary.hpp"
#include "covopt/report/audit_json.hpp"
#include "json_number.hpp"
#include "summary_object.hpp"

namespace covopt::report {
namespace {

using nlohmann::ordered_json;

ordered_json Numbers(const std::vector<double>& values) {
  ordered_json array = ordered_json::array();
  for (const double v : values) array.push_back(internal::Number(v));
  return array;
}

ordered_json Numbers(const Eigen::VectorXd& values) {
  ordered_json array = ordered_json::array();
  for (const double v : values) array.push_back(internal::Number(v));
  return array;
}

/// The per-sample arrays, one entry per sample of the original program.
ordered_json SamplesJson(const audit::RetimeResult& r) {
  const std::size_t n = r.original_time_s.size();
  ordered_json samples;
  samples["original_time_s"] = Numbers(r.original_time_s);
  samples["time_s"] = r.trajectory.time_s.size() == n ? Numbers(r.trajectory.time_s) : ordered_json(nullptr);
  samples["safe_path_speed"] = Numbers(r.safe_path_speed);
  samples["path_speed"] = Numbers(r.path_speed);
  ordered_json bound = ordered_json::array();
  for (const optim::PathSpeedBound b : r.bound) bound.push_back(optim::ToString(b));
  samples["bound"] = std::move(bound);
  ordered_json links = ordered_json::array();
  ordered_json regions = ordered_json::array();
  for (std::size_t i = 0; i < n; ++i) {
    const bool limited = i < r.safe_path_speed.size() && std::isfinite(r.safe_path_speed[i]);
    const bool link = limited && i < r.limiting_link.size() && r.limiting_link[i] < r.before.links.size();
    const bool region = limited && i < r.limiting_region.size() && r.limiting_region[i] < r.before.regions.size();
    links.push_back(link ? ordered_json(r.before.links[r.limiting_link[i]]) : ordered_json(nullptr));
    regions.push_back(region ? ordered_json(r.before.regions[r.limiting_region[i]]) : ordered_json(nullptr));
  }
  samples["limiting_link"] = std::move(links);
  samples["limiting_region"] = std::move(regions);
  return samples;
}

ordered_json SlowdownsJson(const audit::RetimeResult& r) {
  ordered_json slowdowns = ordered_json::array();
  for (const audit::RetimeSlowdown& d : audit::RetimeSlowdowns(r)) {
    ordered_json j;
    j["start_time_s"] = internal::Number(d.start_time_s);
    j["end_time_s"] = internal::Number(d.end_time_s);
    j["first_sample"] = d.first_sample;
    j["last_sample"] = d.last_sample;
    j["min_path_speed"] = internal::Number(d.min_path_speed);
    j["bound"] = d.bound;
    j["link"] = d.link.empty() ? ordered_json(nullptr) : ordered_json(d.link);
    j["region"] = d.region.empty() ? ordered_json(nullptr) : ordered_json(d.region);
    slowdowns.push_back(std::move(j));
  }
  return slowdowns;
}

ordered_json SweepJson(const RetimeSweep& sweep) {
  ordered_json j;
  ordered_json names = ordered_json::array();
  for (const audit::CycleTimeDesign& d : sweep.designs) names.push_back(d.name);
  j["designs"] = std::move(names);
  j["thicknesses_m"] = Numbers(sweep.thicknesses_m);
  ordered_json points = ordered_json::array();
  for (const audit::CycleTimePoint& p : sweep.points) {
    ordered_json point;
    point["design"] = p.design < sweep.designs.size() ? ordered_json(sweep.designs[p.design].name) : ordered_json(nullptr);
    point["thickness_m"] = internal::Number(p.thickness_m);
    point["status"] = audit::ToString(p.status);
    point["cycle_time_s"] = internal::Number(p.cycle_time_s);
    point["uniform_cycle_time_s"] = internal::Number(p.uniform_cycle_time_s);
    point["safe_speed_scale"] = internal::Number(p.safe_speed_scale);
    point["message"] = p.message;
    points.push_back(std::move(point));
  }
  j["points"] = std::move(points);
  return j;
}

/// The original program's audit, its key parts.
ordered_json BeforeJson(const ordered_json& audit) {
  ordered_json j;
  for (const char* key : {"status", "message", "safe_speed_scale", "limiting"}) j[key] = audit.at(key);
  return j;
}

}  // namespace

std::string RetimeJson(const audit::AuditSetup& setup, const audit::RetimeResult& result,
                       const audit::RetimeOptions& options, const RetimeSweep* sweep,
                       std::span<const std::string> input_warnings, int indent) {
  const bool answer = result.status == audit::RetimeStatus::kSafe || result.status == audit::RetimeStatus::kAtRest;
  const ordered_json before = ordered_json::parse(AuditJson(setup, result.before, {}, -1));
  ordered_json j;
  j["status"] = audit::ToString(result.status);
  j["message"] = result.message;
  j["summary"] = internal::SummaryObject(audit::SummarizeRetime(setup, result, options.tolerance));
  j["cycle_time_s"] = answer ? internal::Number(result.cycle_time_s) : ordered_json(nullptr);
  j["original_cycle_time_s"] = internal::Number(result.original_cycle_time_s);
  j["uniform_cycle_time_s"] = internal::Number(result.uniform_cycle_time_s);
  j["uniform_speed_scale"] = internal::Number(result.uniform_speed_scale);
  j["max_speed_scale"] = internal::Number(options.max_speed_scale);
  j["tolerance"] = internal::Number(options.tolerance);
  j["joint_names"] = setup.chain.joint_names();
  j["joint_speed_limits_rad_per_s"] = Numbers(result.joint_speed_limits);
  j["joint_acceleration_limits_rad_per_s2"] = Numbers(result.joint_acceleration_limits);
  j["profile"] = ordered_json{{"status", optim::ToString(result.profile.status)}, {"message", result.profile.message}};
  j["slowdowns"] = SlowdownsJson(result);
  j["samples"] = SamplesJson(result);
  j["before"] = BeforeJson(before);
  j["after"] = result.status == audit::RetimeStatus::kSafe ? ordered_json::parse(AuditJson(setup, result.after, {}, -1)) : ordered_json(nullptr);
  j["thickness_sweep"] = sweep != nullptr ? SweepJson(*sweep) : ordered_json(nullptr);
  for (const char* key : {"criterion", "safety_factor", "contact_area_m2", "reaction_delay_s", "braking_m_per_s2",
                          "robot", "surface", "sample_count", "regions", "coverings"}) {
    j[key] = before.at(key);
  }
  j["scope"] = result.scope;
  j["notes"] = std::vector<std::string>{
      "null stands for infinity: a safe path speed where no surface point moves, a joint without a speed limit, a "
      "sweep point without a safe timing"};
  std::vector<std::string> warnings(input_warnings.begin(), input_warnings.end());
  warnings.insert(warnings.end(), result.warnings.begin(), result.warnings.end());
  j["warnings"] = std::move(warnings);
  return j.dump(indent);
}

}  // namespace covopt::report
