#pragma once
/// @file rule_options.hpp
/// The rule group every judging command shares ("Limits" in its --help): the injury limits
/// (--laceration-limit, --contusion-limit), --safety-factor and the design rule's criteria
/// (--allow-full-compression, --allow-crushing, --allow-unknown-strength, --keep-travel), registered here once
/// for all of them. Each command stores them in its own options and offers those it takes.

#include <optional>
#include <string>
#include <string_view>

namespace CLI {
class App;
}

namespace covopt::cli {

/// Where the rule's flags are stored; a null member is a flag the command does not offer.
struct RuleFlagTargets {
  std::optional<std::string>* laceration_limit = nullptr;  ///< --laceration-limit (a stress)
  std::optional<std::string>* contusion_limit = nullptr;   ///< --contusion-limit (an energy density)
  std::optional<std::string>* safety_factor = nullptr;     ///< --safety-factor, 1-100
  bool* allow_full_compression = nullptr;                  ///< --allow-full-compression
  bool* allow_crushing = nullptr;                          ///< --allow-crushing
  bool* allow_unknown_strength = nullptr;                  ///< --allow-unknown-strength
  bool* keep_travel = nullptr;                             ///< --keep-travel
};

/// Adds the rule's flags `targets` names to `command`, in its "Limits" group (or `group`).
/// The targets must outlive the parse; the commands read and check the values.
void AddRuleOptions(CLI::App& command, const RuleFlagTargets& targets, std::string_view group = "Limits");

}  // namespace covopt::cli
