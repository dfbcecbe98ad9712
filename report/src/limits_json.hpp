#pragma once
/// @file limits_json.hpp
/// The criterion, safety factor and injury limits of a limit search, as JSON (private to
/// covopt_report): one definition for `covopt speed-limit` and `covopt robot --trajectory`.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <covopt/optim/speed_limit.hpp>

namespace covopt::report::internal {

/// The rule behind a verdict: {name ("laceration+contusion+full-compression+crush"), parts,
/// safety_factor, crushing_allowed, unknown_strength_allowed, description}.
inline nlohmann::ordered_json CriterionJson(const optim::DesignRule& rule) {
  const std::vector<std::string> parts = rule.Parts();
  std::string name;
  for (const std::string& part : parts) name += (name.empty() ? "" : "+") + part;
  return {{"name", name},
          {"parts", parts},
          {"safety_factor", rule.safety_factor},
          {"crushing_allowed", rule.crushing_allowed},
          {"unknown_strength_allowed", rule.unknown_strength_allowed},
          {"description", rule.Describe()}};
}

/// A design's ratios under a rule: laceration, contusion, compression (the covering's travel
/// used) and crush (null unless the material's strength is known), the peak compressive
/// stress and the strength it needs (SF × σ_c,max), the governing criterion and ratio, and
/// fully_compressed.
inline nlohmann::ordered_json RatiosJson(const optim::DesignScore& s, const optim::DesignRule& rule) {
  const optim::GoverningRatio g = s.governing(rule);
  const bool checked = s.crush_check == optim::CrushCheck::kChecked;
  return {{"laceration_ratio", s.laceration_ratio},
          {"contusion_ratio", s.contusion_ratio},
          {"fracture_ratio", s.fracture_ratio},
          {"compression_ratio", s.compression_ratio},
          {"crush_ratio", checked ? nlohmann::ordered_json(s.crush_ratio) : nlohmann::ordered_json(nullptr)},
          {"crush_check", optim::ToString(s.crush_check)},
          {"max_tensile_stress_Pa", s.peaks.max_tensile_stress_Pa},
          {"max_energy_density_J_per_m2", s.peaks.max_energy_density_J_per_m2},
          {"max_compressive_stress_Pa", s.peaks.max_compressive_stress_Pa},
          {"required_compressive_strength_Pa", s.required_strength_Pa(rule.safety_factor)},
          {"fully_compressed", s.peaks.fully_compressed},
          {"governing_criterion", optim::ToString(g.criterion, s.peaks.covering_law)},
          {"governing_ratio", g.ratio}};
}

/// A covered design's law and validity: "covering_law" ("foam" | "hertz", "" bare) and
/// "validity" {"within", "ratio" (how far along its validity limits), "note"}.
inline nlohmann::ordered_json LawAndValidityJson(const optim::DesignScore& s) {
  return {{"covering_law", s.bare() ? std::string() : std::string(ToString(s.peaks.covering_law))},
          {"validity", {{"within", s.validity.within}, {"ratio", s.validity.ratio}, {"note", s.validity.note}}}};
}

/// Adds "criterion", "safety_factor" and "limits" {laceration_Pa, contusion_J_per_m2 and their
/// derated values, limit / safety factor} to `j`.
inline void AddCriterionAndLimits(nlohmann::ordered_json& j, const optim::SpeedLimitOptions& options) {
  const double sf = options.safety_factor;
  const double laceration = options.limits.laceration_tensile_stress_Pa;
  const double contusion = options.limits.contusion_energy_density_J_per_m2;
  j["criterion"] = CriterionJson(options.rule());
  j["scope"] = optim::HeadVerdictScope(options.rule());
  j["safety_factor"] = sf;
  j["limits"] = {{"laceration_Pa", laceration},
                 {"contusion_J_per_m2", contusion},
                 {"derated_laceration_Pa", laceration / sf},
                 {"derated_contusion_J_per_m2", contusion / sf}};
}

}  // namespace covopt::report::internal
