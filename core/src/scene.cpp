// String forms of the scene enums, and the check of the injury limits.
#include "covopt/core/scene.hpp"

#include "covopt/core/physical_floors.hpp"
#include "range_check.hpp"

namespace covopt {

std::string_view ToString(ThresholdReading reading) noexcept {
  switch (reading) {
    case ThresholdReading::kCumulative: return "cumulative";
    case ThresholdReading::kLiteral: return "literal";
  }
  return "unknown";
}

void CheckInjuryLimits(const InjuryLimits& limits) {
  internal::CheckInRange("limits.laceration_tensile_stress_Pa", limits.laceration_tensile_stress_Pa, kMinModulus_Pa,
                         1e13, "Pa");
  internal::CheckInRange("limits.contusion_energy_density_J_per_m2", limits.contusion_energy_density_J_per_m2,
                         kMinEnergyDensity_J_per_m2, 1e13, "J/m2");
  if (limits.fracture_force_N != 0.0) {
    internal::CheckInRange("limits.fracture_force_N", limits.fracture_force_N, 1.0, 1e13, "N (or 0: the struck area's)");
  }
}

double FractureLimit(const InjuryLimits& limits, HeadArea area) noexcept {
  return limits.fracture_force_N > 0.0 ? limits.fracture_force_N : FractureForceOf(area).force_N;
}

}  // namespace covopt
