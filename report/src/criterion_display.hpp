#pragma once
/// @file criterion_display.hpp
/// How a criterion's numbers are shown in text (private to covopt_report): what the value is,
/// its display unit and scale (MPa, J/cm², N/cm², N, a share), for the verdict's text and the
/// summary's.

#include <cmath>
#include <string>
#include <string_view>

#include <fmt/format.h>

namespace covopt::report::internal {

/// What a criterion's value is, its display unit and scale.
struct Display {
  std::string_view label;
  std::string_view unit;
  double per_si = 1.0;  ///< display value = SI value × per_si
};

/// The display of the criterion `name` whose SI unit is `unit` ("Pa", "J/m2", "N", "1").
inline Display DisplayOf(std::string_view name, std::string_view unit) {
  if (name == "laceration") return {"tensile stress", "MPa", 1e-6};
  if (name == "contusion") return {"energy density", "J/cm²", 1e-4};
  if (name == "crush") return {"compressive stress", "MPa", 1e-6};
  if (name == "pressure") return {"pressure", "N/cm²", 1e-4};
  if (name == "full-compression") return {"travel used", "", 1.0};
  if (name == "within-curve") return {"curve used (peak strain / last strain)", "", 1.0};
  if (name == "fracture") return {"peak force", "N", 1.0};
  if (unit == "N") return {"force", "N", 1.0};
  return {"value", unit, 1.0};
}

/// An SI value in the display's unit, 4 significant digits: "2.52 J/cm²"; "unknown" when not finite.
inline std::string Amount(double si, const Display& d) {
  if (!std::isfinite(si)) return "unknown";
  return d.unit.empty() ? fmt::format("{:.4g}", si * d.per_si) : fmt::format("{:.4g} {}", si * d.per_si, d.unit);
}

}  // namespace covopt::report::internal
