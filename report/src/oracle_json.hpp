#pragma once
/// @file oracle_json.hpp
/// Which oracle answered, as JSON (private to covopt_report): `solver.oracle` of optimize and
/// `oracle` of speed-limit.

#include <nlohmann/json.hpp>

#include <covopt/core/impact_result.hpp>
#include <covopt/optim/oracle.hpp>

#include "json_number.hpp"

namespace covopt::report::internal {

/// {"name": "exact" | "time-path", "reason", "method" and "rtol" (null on the exact path),
/// "gradient" (with `gradient`), "evaluations", "failed_evaluations", "first_failure"}; with
/// central differences also their step disagreement.
inline nlohmann::ordered_json OracleJson(const optim::OracleReport& r, bool gradient) {
  const bool time_path = r.kind == optim::OracleKind::kTimePath;
  nlohmann::ordered_json j;
  j["name"] = optim::ToString(r.kind);
  j["reason"] = r.reason;
  j["method"] = time_path ? nlohmann::ordered_json(std::string(covopt::ToString(r.method))) : nullptr;
  j["rtol"] = time_path ? Number(r.relative_tolerance) : nullptr;
  if (gradient) {
    j["gradient"] = optim::ToString(r.gradient);
    j["gradient_evaluations"] = r.gradient_evaluations;
    if (r.gradient == optim::GradientSource::kCentralDifference) {
      j["gradient_step_disagreement"] = Number(r.gradient_step_disagreement);
    }
  }
  j["evaluations"] = r.evaluations;
  j["failed_evaluations"] = r.failed_evaluations;
  j["first_failure"] = r.first_failure.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r.first_failure);
  return j;
}

}  // namespace covopt::report::internal
