#pragma once
/// @file limits_json.hpp
/// The criterion, safety factor and injury limits of a limit search, as JSON (private to
/// covopt_report): one definition for `covopt speed-limit` and `covopt robot --trajectory`.

#include <nlohmann/json.hpp>

#include <covopt/optim/speed_limit.hpp>

namespace covopt::report::internal {

/// Adds "criterion", "safety_factor" and "limits" {laceration_Pa, contusion_J_per_m2 and their
/// derated values, limit / safety factor} to `j`.
inline void AddCriterionAndLimits(nlohmann::ordered_json& j, const optim::SpeedLimitOptions& options) {
  const double sf = options.safety_factor;
  const double laceration = options.limits.laceration_tensile_stress_Pa;
  const double contusion = options.limits.contusion_energy_density_J_per_m2;
  j["criterion"] = optim::ToString(options.criterion());
  j["safety_factor"] = sf;
  j["limits"] = {{"laceration_Pa", laceration},
                 {"contusion_J_per_m2", contusion},
                 {"derated_laceration_Pa", laceration / sf},
                 {"derated_contusion_J_per_m2", contusion / sf}};
}

}  // namespace covopt::report::internal
