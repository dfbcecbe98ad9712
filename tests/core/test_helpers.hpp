#pragma once
// Shared scene builders for the core tests.
#include <cmath>

#include <covopt/core.hpp>

namespace covopt::test {

/// The paper's Sec. IV scene: 10 kg robot, 2 m/s, R_r 15 mm, free 4.5 kg head.
inline Scene PaperScene(double covering_thickness_m = 0.0, double covering_modulus_Pa = 27.6e6,
                        double covering_poisson = 0.22) {
  Scene scene;
  scene.covering = {covering_modulus_Pa, covering_poisson, covering_thickness_m};
  return scene;
}

inline double RelativeError(double value, double reference) {
  return std::abs(value - reference) / std::abs(reference);
}

}  // namespace covopt::test
