#pragma once
// Shared scene builders and path comparisons for the core tests.
#include <algorithm>
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

/// `scene` with the impact speed at which the exact δ_max is `max_penetration_m`: for the
/// conservative scene ½ m v0² = U(δ_max); with contact damping d (docs/model.md §10.1)
/// m (d v0 - ln(1 + d v0)) / d² = U(δ_max), solved by bisection. Only for a scene with an
/// energy integral (no braking, no neck).
inline Scene WithMaxPenetration(Scene scene, double max_penetration_m) {
  const ImpactModel model = ImpactModel::FromScene(scene);
  const double energy = model.StateAt(max_penetration_m).potential_energy_J;
  const double mass = model.effective_mass_kg();
  const double d = scene.model.damping_s_per_m;
  if (!(d > 0.0)) {
    scene.robot.speed_m_per_s = std::sqrt(2.0 * energy / mass);
    return scene;
  }
  double low = 0.0, high = 100.0;
  for (int i = 0; i < 200 && high - low > 0.0; ++i) {
    const double v = 0.5 * (low + high);
    (mass * (d * v - std::log1p(d * v)) / (d * d) < energy ? low : high) = v;
  }
  scene.robot.speed_m_per_s = 0.5 * (low + high);
  return scene;
}

/// The relative change of σ_c over `relative` of δ_max, the larger of both sides: how well
/// σ_c,max can be known from a δ_max known to `relative`. At the start of a phase with n < 2
/// (t1: covering on bone, n = 1.8) σ_c ~ x^(n-1) has an unbounded slope, so this is far above
/// `relative` where δ_max grazes the switch (docs/numerics.md, "σ_c grazing t1").
inline double StressChangeOver(const ImpactModel& model, const ImpactPeaks& exact, double relative) {
  const double at = exact.max_compressive_stress_Pa;
  const double above = model.StateAt(exact.max_penetration_m * (1.0 + relative)).compressive_stress_Pa;
  const double below = model.StateAt(exact.max_penetration_m * (1.0 - relative)).compressive_stress_Pa;
  return std::max(std::abs(above - at), std::abs(below - at)) / at;
}

}  // namespace covopt::test
