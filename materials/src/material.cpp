#include "covopt/materials/material.hpp"

#include <array>
#include <utility>

namespace covopt::materials {
namespace {

constexpr std::array<std::pair<ModulusBasis, std::string_view>, 6> kBasisNames{{
    {ModulusBasis::kCompressive, "compressive"},
    {ModulusBasis::kTensile, "tensile"},
    {ModulusBasis::kBending, "bending"},
    {ModulusBasis::kFitted, "fitted"},
    {ModulusBasis::kAsPrinted, "as-printed"},
    {ModulusBasis::kHardness, "hardness"},
}};

}  // namespace

std::string_view ToString(ModulusBasis basis) noexcept {
  for (const auto& [value, name] : kBasisNames) {
    if (value == basis) return name;
  }
  return "unknown";
}

std::string_view ToString(CrushBehaviour behaviour) noexcept {
  switch (behaviour) {
    case CrushBehaviour::kCrushes: return "crushes";
    case CrushBehaviour::kDoesNotCrush: return "does-not-crush";
    case CrushBehaviour::kUnknown: return "unknown";
  }
  return "unknown";
}

std::optional<CrushBehaviour> ParseCrushBehaviour(std::string_view text) noexcept {
  for (const CrushBehaviour b :
       {CrushBehaviour::kCrushes, CrushBehaviour::kDoesNotCrush, CrushBehaviour::kUnknown}) {
    if (ToString(b) == text) return b;
  }
  return std::nullopt;
}

std::string_view Describe(ModulusBasis basis) noexcept {
  switch (basis) {
    case ModulusBasis::kCompressive: return "compression test (secant or tangent modulus)";
    case ModulusBasis::kTensile: return "tension test";
    case ModulusBasis::kBending: return "flexural (bending) test";
    case ModulusBasis::kFitted: return "identified by fitting an impact model to measured forces";
    case ModulusBasis::kAsPrinted: return "stated by the source without its test method";
    case ModulusBasis::kHardness: return "estimated from Shore hardness by an empirical correlation";
  }
  return "unknown";
}

std::optional<ModulusBasis> ParseModulusBasis(std::string_view text) noexcept {
  for (const auto& [value, name] : kBasisNames) {
    if (name == text) return value;
  }
  return std::nullopt;
}

double PoissonRatioOrDefault(const Material& material) noexcept {
  return material.poisson_ratio.value_or(kDefaultPoissonRatio);
}

std::optional<double> StressAt25Pa(const Material& material) noexcept {
  const CompressiveCurve* curve = material.compressive_curve.get();
  if (curve == nullptr || curve->last_strain() < kRatingStrain) return std::nullopt;
  return curve->StressAt(kRatingStrain);
}

CoveringSpec CoveringOf(const Material& material, double thickness_m) {
  return CoveringSpec{.youngs_modulus_Pa = material.youngs_modulus_Pa,
                      .poisson_ratio = PoissonRatioOrDefault(material),
                      .thickness_m = thickness_m,
                      .compressive_curve = material.compressive_curve,
                      .law = CoveringLaw::kAuto};
}

}  // namespace covopt::materials
