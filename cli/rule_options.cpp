#include "rule_options.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "covopt/core/quantity.hpp"
#include "scene_fields.hpp"

namespace covopt::cli {

void AddRuleOptions(CLI::App& command, const RuleFlagTargets& targets, std::string_view group_name) {
  const std::string group(group_name);
  const InjuryLimits defaults;
  for (const LimitField& field : LimitFields()) {
    const bool laceration = field.key == "laceration";
    std::optional<std::string>* target = laceration ? targets.laceration_limit
                                         : field.key == "contusion" ? targets.contusion_limit
                                                                    : nullptr;
    if (target == nullptr) continue;  // the safety factor: below
    const double value =
        laceration ? defaults.laceration_tensile_stress_Pa : defaults.contusion_energy_density_J_per_m2;
    command
        .add_option(std::string(field.flag), *target,
                    fmt::format("{} (default {})", field.help, FormatQuantity(value, field.spec.kind)))
        ->type_name(laceration ? "STRESS" : "ENERGY_DENSITY")
        ->group(group);
  }
  if (targets.safety_factor) {
    command
        .add_option("--safety-factor", *targets.safety_factor,
                    "judge each verdict against its limit divided by this factor: the ratios must stay <= 1/factor, "
                    "1-100 (default 1)")
        ->type_name("RATIO")
        ->group(group);
  }
  if (targets.allow_full_compression) {
    command
        .add_flag("--allow-full-compression", *targets.allow_full_compression,
                  "the paper's criterion: a covering fully compressed at the peak may count as safe (default: it "
                  "may not, the robot must never reach bone through it)")
        ->group(group);
  }
  if (targets.keep_travel) {
    command
        .add_flag("--keep-travel", *targets.keep_travel,
                  "the covering's travel rule as a limit: it stays within its travel (Hertz: not fully compressed; "
                  "foam: within its measured curve), the safety factor as a reserve (default: the travel is "
                  "reported, not a limit: a foam used up is within its law, its stop modelled, and is reported at "
                  "its own speed; the law's validity counts always)")
        ->group(group);
  }
  if (targets.allow_crushing) {
    command
        .add_flag("--allow-crushing", *targets.allow_crushing,
                  "a sacrificial liner: the covering's crushing is reported, not applied (default: a material of "
                  "known strength must not crush, SF x peak compressive stress <= its strength)")
        ->group(group);
  }
  if (targets.allow_unknown_strength) {
    command
        .add_flag("--allow-unknown-strength", *targets.allow_unknown_strength,
                  "materials of unknown compressive strength may be recommended, each with a warning (default: "
                  "they are not, a design with them is unverified for crushing)")
        ->group(group);
  }
}

}  // namespace covopt::cli
