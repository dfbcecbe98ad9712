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
  fmt::print(out, "{:<{}}  {:<{}}  {:>11}  {:>5}  {:>9}  {:>9}  {}\n", "name", name_width,
             "family", family_width, "E", "ν", "ρ [kg/m³]", "strength", "E basis");
  bool unknown = false;
  for (const Material* m : rows) {
    fmt::print(out, "{:<{}}  {:<{}}  {:>11}  {:>5}  {:>9}  {:>9}  {}\n", m->name, name_width,
               m->family, family_width, ModulusText(m->youngs_modulus_Pa), PoissonText(*m),
               DensityText(*m), StrengthText(*m), materials::ToString(m->modulus_basis));
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
  fmt::print(out, "Sources, notes and how E was obtained: covopt materials show NAME\n");
}

namespace {

void ShowRow(std::ostream& out, std::string_view label, std::string_view value) {
  PrintWrappedRow(out, label, 16, value, 76);
}

}  // namespace

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
}

}  // namespace covopt::report
