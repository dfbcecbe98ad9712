#include "limit_search_output.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/optim/design.hpp"

namespace covopt::cli {

optim::DesignRule LimitRule(const optim::SpeedLimitOptions& options, const SimulationPlan& covering) {
  // Crushing is checked where the strength is known; the notes say when it is not.
  const bool unchecked = !CrushCheckOf(covering).notes.empty();
  return {options.safety_factor, options.criterion(), options.allow_crushing, unchecked};
}

void PrintLimitsAndCriterion(std::ostream& out, const optim::SpeedLimitOptions& options,
                             const SimulationPlan& covering) {
  const double sf = options.safety_factor;
  fmt::print(out, "Limits     laceration {:g} MPa, contusion {:g} J/cm², safety factor {:g}{}\n",
             options.limits.laceration_tensile_stress_Pa * 1e-6,
             options.limits.contusion_energy_density_J_per_m2 * 1e-4, sf,
             sf > 1 ? std::string(" on each limit (the criterion below derates them)") : std::string());
  const optim::DesignRule rule = LimitRule(options, covering);
  fmt::print(out, "Criterion  {}{}\n", rule.Describe(),
             rule.unknown_strength_allowed && !rule.crushing_allowed ? " (this covering has none known: see the warnings)"
                                                                      : "");
}

void PrintHeadScope(std::ostream& out, const optim::SpeedLimitOptions& options, const SimulationPlan& covering) {
  fmt::print(out, "\nScope\n");
  for (const std::string& line : optim::HeadVerdictScope(LimitRule(options, covering))) fmt::print(out, "  {}\n", line);
}

}  // namespace covopt::cli
