#include "covopt/report/materials_text.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/core/quantity.hpp"
#include "covopt/report/wrap_words.hpp"

namespace covopt::report {
namespace {

using materials::Material;

std::string ModulusText(double pa) { return FormatQuantity(pa, QuantityKind::kModulus); }

/// A stress in 3 significant digits for the table: "172 kPa", "86.2 MPa".
std::string ShortStress(double pa) {
  const std::array<std::pair<double, const char*>, 3> units{
      {{1e9, "GPa"}, {1e6, "MPa"}, {1e3, "kPa"}}};
  for (const auto& [scale, unit] : units) {
    if (pa >= scale) return fmt::format("{:.3g} {}", pa / scale, unit);
  }
  return fmt::format("{:.3g} Pa", pa);
}

/// The table's strength column: the strength, "no crush" or "unknown".
std::string StrengthText(const Material& m) {
  switch (m.crush_behaviour) {
    case materials::CrushBehaviour::kCrushes:
      return m.compressive_strength_Pa ? ShortStress(*m.compressive_strength_Pa) : "unknown";
    case materials::CrushBehaviour::kDoesNotCrush: return "no crush";
    case materials::CrushBehaviour::kUnknown: break;
  }
  return "unknown";
}

std::string PoissonText(const Material& m) {
  return m.poisson_ratio ? fmt::format("{:g}", *m.poisson_ratio) : std::string("–");
}

std::string DensityText(const Material& m) {
  return m.density_kg_per_m3 ? fmt::format("{:g}", *m.density_kg_per_m3) : std::string("–");
}

/// The table's σ(25 %) column: the curve's stress at 25 %, "–" without a curve through 25 %.
std::string StressAt25Text(const Material& m) {
  const auto stress = materials::StressAt25Pa(m);
  return stress ? ShortStress(*stress) : std::string("–");
}

/// The materials as a table, one row each, and a closing line.
}  // namespace

void PrintMaterialTable(std::ostream& out, const std::vector<const Material*>& rows,
                        std::string_view closing) {
  std::size_t name_width = 4;
  std::size_t family_width = 6;
  for (const Material* m : rows) {
    name_width = std::max(name_width, m->name.size());
    family_width = std::max(family_width, m->family.size());
  }
  fmt::print(out, "{:<{}}  {:<{}}  {:>11}  {:>5}  {:>9}  {:>9}  {:>9}  {}\n", "name", name_width,
             "family", family_width, "E", "ν", "ρ [kg/m³]", "strength", "σ(25 %)", "E basis");
  bool unknown = false;
  for (const Material* m : rows) {
    fmt::print(out, "{:<{}}  {:<{}}  {:>11}  {:>5}  {:>9}  {:>9}  {:>9}  {}\n", m->name, name_width,
               m->family, family_width, ModulusText(m->youngs_modulus_Pa), PoissonText(*m),
               DensityText(*m), StrengthText(*m), StressAt25Text(*m), materials::ToString(m->modulus_basis));
    unknown = unknown || !m->poisson_ratio || !m->density_kg_per_m3;
  }
  fmt::print(out, "\n{}\n", closing);
  if (unknown) {
    fmt::print(out, "– = not given by the source; where ν is needed, {:g} is assumed.\n",
               materials::kDefaultPoissonRatio);
  }
  fmt::print(out,
             "strength = compressive strength (at yield or 10 % strain, by its test method); "
             "no crush = densifies instead, full compression is its limit; unknown = a design "
             "with it cannot be verified for crushing.\n");
  fmt::print(out,
             "σ(25 %) = the compressive curve's stress at 25 % strain; – = no curve through 25 %.\n");
  fmt::print(out, "Sources, notes, curves and how E was obtained: covopt materials show NAME\n");
}

namespace {

void ShowRow(std::ostream& out, std::string_view label, std::string_view value) {
  PrintWrappedRow(out, label, 16, value, 76);
}

/// "2nd", "3rd", "7th" point: every k-th.
std::string OrdinalEvery(std::size_t k) {
  const std::size_t last = k % 10, tens = k % 100;
  const char* suffix = (last == 1 && tens != 11) ? "st" : (last == 2 && tens != 12) ? "nd" : (last == 3 && tens != 13) ? "rd" : "th";
  return fmt::format("{}{}", k, suffix);
}

}  // namespace

namespace {

/// "2 kPa" for a band or a stress, with 4 significant digits.
std::string StressText(double pa) { return FormatQuantity(pa, QuantityKind::kModulus); }

/// The points of a curve as a table (strain, stress, W); a long record is thinned to about
/// 25 rows (every k-th point and the last), and the table says so.
void PrintCurvePoints(std::ostream& out, const CompressiveCurve& curve) {
  constexpr std::size_t kRows = 25;
  const auto points = curve.points();
  const std::size_t step = points.size() <= kRows + 5 ? 1 : (points.size() + kRows - 1) / kRows;
  fmt::print(out, "\n  {:>10}  {:>14}  {:>12}\n", "strain [%]", "stress [kPa]", "W [kJ/m³]");
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i % step != step - 1 && i + 1 != points.size()) continue;
    fmt::print(out, "  {:>10.4g}  {:>14.5g}  {:>12.5g}\n", 100.0 * points[i].strain, points[i].stress_Pa / 1e3,
               curve.EnergyDensityAt(points[i].strain) / 1e3);
  }
  if (step > 1) {
    fmt::print(out, "  (every {} of the {} points shown, and the last; --json has them all)\n", OrdinalEvery(step),
               points.size());
  }
}

}  // namespace

void PrintCurve(std::ostream& out, const Material& m) {
  const CompressiveCurve* curve = m.compressive_curve.get();
  if (curve == nullptr) {
    ShowRow(out, "curve", "none: only E describes this material (the Hertz law)");
    return;
  }
  ShowRow(out, "curve",
          fmt::format("{} points to {:.4g} % strain ({}), piecewise linear from the origin; W at the last point "
                      "{:.4g} kJ/m³; past it the layer is a rigid stop",
                      curve->points().size(), 100.0 * curve->last_strain(), StressText(curve->last_stress_Pa()),
                      curve->total_energy_density_J_per_m3() / 1e3));
  const auto stress_at_25 = materials::StressAt25Pa(m);
  std::string rated = stress_at_25 ? StressText(*stress_at_25) : std::string("none (the curve ends before 25 %)");
  if (m.stress_at_25_band_Pa) {
    rated += fmt::format(" (a grade band {} to {} stands in for a measured curve)",
                         StressText(m.stress_at_25_band_Pa->low), StressText(m.stress_at_25_band_Pa->high));
  }
  ShowRow(out, "σ(25 %)", rated);
  if (!m.curve_shape.empty()) ShowRow(out, "curve shape", "assumed: " + m.curve_shape);
  ShowRow(out, "curve rate", m.curve_rate);
  if (m.recovers) {
    ShowRow(out, "recovers", *m.recovers ? "yes: a flexible foam that recovers after an impact"
                                         : "no: a crushable liner, spent by one impact");
  }
  ShowRow(out, "rate factor",
          m.rate_factor ? fmt::format("{:g} to {:g} (the curve's stresses at impact rates)", m.rate_factor->low,
                                      m.rate_factor->high)
                        : std::string("not given"));
  ShowRow(out, "curve source", m.curve_source);
  PrintCurvePoints(out, *curve);
}

void PrintMaterial(std::ostream& out, const Material& m) {
  fmt::print(out, "{}\n", m.name);
  ShowRow(out, "family", m.family);
  ShowRow(out, "Young's modulus", fmt::format("{} ({:.10g} Pa)", ModulusText(m.youngs_modulus_Pa),
                                               m.youngs_modulus_Pa));
  ShowRow(out, "E basis", fmt::format("{}: {}", materials::ToString(m.modulus_basis),
                                      materials::Describe(m.modulus_basis)));
  ShowRow(out, "Poisson ratio",
          m.poisson_ratio ? fmt::format("{:g}", *m.poisson_ratio)
                          : fmt::format("unknown ({:g} is assumed where one is needed)",
                                        materials::kDefaultPoissonRatio));
  ShowRow(out, "density", m.density_kg_per_m3
                              ? FormatQuantity(*m.density_kg_per_m3, QuantityKind::kDensity)
                              : std::string("unknown"));
  ShowRow(out, "source", m.source);
  switch (m.crush_behaviour) {
    case materials::CrushBehaviour::kCrushes:
      ShowRow(out, "strength",
              m.compressive_strength_Pa
                  ? fmt::format("{} ({:.10g} Pa), compressive: the material crushes above it",
                                ModulusText(*m.compressive_strength_Pa), *m.compressive_strength_Pa)
                  : std::string("unknown"));
      ShowRow(out, "strength method", m.strength_method);
      ShowRow(out, "strength source", m.strength_source);
      break;
    case materials::CrushBehaviour::kDoesNotCrush:
      ShowRow(out, "strength", "does not crush: " + m.strength_method);
      ShowRow(out, "strength source", m.strength_source);
      break;
    case materials::CrushBehaviour::kUnknown:
      ShowRow(out, "strength",
              "unknown: a design with this material cannot be verified for crushing");
      break;
  }
  if (!m.note.empty()) ShowRow(out, "note", m.note);
  if (!m.origin.empty()) ShowRow(out, "defined at", m.origin);
  PrintCurve(out, m);
}

}  // namespace covopt::report
