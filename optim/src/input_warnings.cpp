// The warnings about a scene's inputs (input_warnings.hpp), shared by the CLI and Python.
#include "covopt/optim/input_warnings.hpp"

#include <algorithm>

#include <covopt/core/number_format.hpp>
#include <covopt/optim/speed_limit.hpp>
#include <covopt/core/quantity.hpp>

namespace covopt::optim {
std::vector<std::string> SceneInputWarnings(const Scene& scene, const InjuryLimits& limits,
                                            double safety_factor,
                                            const materials::Material* covering_material,
                                            const InputSource& source_of) {
  std::vector<std::string> warnings;
  if (safety_factor != 1.0) {
    const std::optional<std::string> source = source_of("limits.safety_factor");
    warnings.push_back(
        "safety factor " + FormatSignificant(safety_factor) + (source ? " (from " + *source + ")" : std::string()) +
        ": each verdict is judged against its limit divided by " + FormatSignificant(safety_factor) + ", laceration " +
        FormatQuantity(limits.laceration_tensile_stress_Pa / safety_factor, QuantityKind::kModulus) +
        " and contusion " +
        FormatQuantity(limits.contusion_energy_density_J_per_m2 / safety_factor, QuantityKind::kEnergyDensity) +
        " (the ratios are to the limits themselves; safe needs a ratio <= " + FormatSignificant(1.0 / safety_factor, 4) +
        ")");
  }
  const bool covered = scene.covering.thickness_m > 0.0;
  if (covering_material) {
    if (!covered) {
      warnings.push_back("no covering (covering.thickness = 0), so " +
                         source_of("covering.material").value_or("the material") + " is ignored");
      return warnings;
    }
    if (!covering_material->poisson_ratio) {  // the ν assumed
      warnings.push_back("the catalog gives no Poisson ratio for '" + covering_material->name + "': ν unknown, " +
                         FormatSignificant(materials::kDefaultPoissonRatio) + " assumed");
    }
  }
  const bool covering_given = covering_material != nullptr ||
                              source_of("covering.thickness") || source_of("covering.modulus") ||
                              source_of("covering.poisson");
  if (covered && !covering_given) warnings.push_back(DefaultCoveringNote(scene));  // the covering assumed
  if (!covered) {
    std::vector<std::string> ignored;
    for (const char* name : {"covering.modulus", "covering.poisson"}) {
      if (const std::optional<std::string> source = source_of(name)) {
        ignored.push_back(std::string(name) + " (from " + *source + ")");
      }
    }
    if (!ignored.empty()) {
      warnings.push_back("no covering (covering.thickness = 0), so " + ignored.front() +
                         (ignored.size() == 2 ? " and " + ignored.back() + " are" : std::string(" is")) +
                         " ignored");
    }
  }
  return warnings;
}

void AppendNewWarnings(std::vector<std::string>& warnings, const std::vector<std::string>& more) {
  for (const std::string& warning : more) {
    if (std::find(warnings.begin(), warnings.end(), warning) == warnings.end()) warnings.push_back(warning);
  }
}

}  // namespace covopt::optim
