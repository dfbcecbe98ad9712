#pragma once
// Shared scene builders and path comparisons for the core tests.
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/core.hpp>

namespace covopt::test {

/// The paper's Sec. IV scene: 10 kg robot, 2 m/s, R_r 15 mm, free 4.5 kg head.
inline Scene PaperScene(double covering_thickness_m = 0.0, double covering_modulus_Pa = 27.6e6,
                        double covering_poisson = 0.22) {
  Scene scene;
  scene.covering = {covering_modulus_Pa, covering_poisson, covering_thickness_m};
  return scene;
}

/// Sets every pair's contact-law exponent (covering-scalp, covering-bone, robot-bone) to
/// `exponent` [-].
inline void SetEveryExponent(Scene& scene, double exponent) {
  scene.model.exponent_covering_scalp = exponent;
  scene.model.exponent_covering_bone = exponent;
  scene.model.exponent_robot_bone = exponent;
}

/// A scene with a name for test messages.
struct NamedScene {
  std::string name;
  Scene scene;
};

/// Appends `base` edited by `edit` (a callable taking Scene&) under `name`.
template <class Edit>
void AddVariant(std::vector<NamedScene>& scenes, const Scene& base, std::string name, Edit&& edit) {
  Scene scene = base;
  edit(scene);
  scenes.push_back({std::move(name), scene});
}

inline double RelativeError(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

/// Checks every peak, the contact duration and the rebound speed of `result` within `limit`
/// (relative) of the exact path's `exact`.
inline void CheckPeaksAgainstExact(const ImpactResult& result, const ImpactResult& exact, double limit) {
  CHECK(RelativeError(result.peaks.max_penetration_m, exact.peaks.max_penetration_m) < limit);
  CHECK(RelativeError(result.peaks.peak_force_N, exact.peaks.peak_force_N) < limit);
  CHECK(RelativeError(result.peaks.max_compressive_stress_Pa, exact.peaks.max_compressive_stress_Pa) < limit);
  CHECK(RelativeError(result.peaks.max_tensile_stress_Pa, exact.peaks.max_tensile_stress_Pa) < limit);
  CHECK(RelativeError(result.peaks.max_energy_density_J_per_m2, exact.peaks.max_energy_density_J_per_m2) <
        limit);
  CHECK(RelativeError(*result.contact_duration_s, *exact.contact_duration_s) < limit);
  CHECK(RelativeError(*result.rebound_speed_m_per_s, *exact.rebound_speed_m_per_s) < limit);
}

}  // namespace covopt::test
