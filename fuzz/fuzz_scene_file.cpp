// libFuzzer target: the scene-file parser (covopt::scene_file, with its [limits] and
// covering.material extras), then the model on what it accepts. Bad input must end in
// std::invalid_argument (the scene file, or ImpactModel::FromScene); a scene that validates must give finite,
// positive exact peaks and contact duration. Anything else (a crash, a sanitizer report,
// another exception, a NaN) is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "covopt/core/exact.hpp"
#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/scene_file/scene_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  covopt::Scene scene;
  covopt::scene_file::SceneFileExtras extras;
  try {
    covopt::scene_file::ApplySceneToml(text, "fuzz.toml", scene, &extras);
  } catch (const std::invalid_argument&) {
    return 0;
  }
  // Limits that pass must be usable: positive and finite, the safety factor in [1, 100].
  for (const auto& limit : {extras.laceration_limit_Pa, extras.contusion_limit_J_per_m2}) {
    if (limit && !(std::isfinite(*limit) && *limit > 0.0)) std::abort();
  }
  if (extras.safety_factor && !(*extras.safety_factor >= 1.0 && *extras.safety_factor <= 100.0)) {
    std::abort();
  }
  try {
    const covopt::ImpactModel model = covopt::ImpactModel::FromScene(scene);
    const covopt::ImpactResult result = covopt::SolveExact(model);
    const covopt::ImpactPeaks& peaks = result.peaks;
    if (!result.ok() || !std::isfinite(peaks.max_penetration_m) ||
        !std::isfinite(peaks.peak_force_N) || !std::isfinite(peaks.max_tensile_stress_Pa) ||
        !std::isfinite(peaks.max_energy_density_J_per_m2) ||
        !(peaks.max_penetration_m > 0.0) ||
        (result.contact_duration_s && !(std::isfinite(*result.contact_duration_s) &&
                                        *result.contact_duration_s > 0.0))) {
      std::abort();  // a validated scene gave a non-finite or empty result
    }
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
