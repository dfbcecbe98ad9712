#pragma once
// What the chart tests share: counting a script's parts, and a covered body contact.
#include <cstddef>
#include <string>

#include <covopt/core.hpp>

namespace covopt::chart::testing {

/// How many times `what` occurs in `text` (not overlapping).
inline std::size_t Count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

/// A 10 kg robot at 0.5 m/s, radius 50 mm, contact area 1 cm², a 10 mm covering of 2 MPa, ν 0.3.
inline BodyContactScene CoveredScene() {
  BodyContactScene scene;
  scene.robot_mass_kg = 10.0;
  scene.speed_m_per_s = 0.5;
  scene.robot_radius_m = 0.05;
  scene.contact_area_m2 = 1e-4;
  scene.covering = {2e6, 0.3, 0.01};
  return scene;
}

}  // namespace covopt::chart::testing
