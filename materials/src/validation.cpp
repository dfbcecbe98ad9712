#include "validation.hpp"

#include <cmath>

#include "covopt/core/physical_floors.hpp"

#include "text.hpp"

namespace covopt::materials::internal {

std::optional<std::string> ModulusProblem(double youngs_modulus_Pa) {
  // The floor kMinModulus_Pa (1 kPa): softer than any gel a covering is made of.
  if (youngs_modulus_Pa >= kMinModulus_Pa && youngs_modulus_Pa <= kMaxModulus_Pa) return std::nullopt;
  return "must be in [" + FormatNumber(kMinModulus_Pa) + ", " + FormatNumber(kMaxModulus_Pa) + "] Pa (got " +
         FormatNumber(youngs_modulus_Pa) + ")";
}

std::optional<std::string> PoissonProblem(double poisson_ratio) {
  if (std::isfinite(poisson_ratio) && poisson_ratio > -1.0 && poisson_ratio <= 0.5) {
    return std::nullopt;
  }
  return "must be in (-1, 0.5], or \"unknown\" (got " + FormatNumber(poisson_ratio) + ")";
}

std::optional<std::string> DensityProblem(double density_kg_per_m3) {
  if (std::isfinite(density_kg_per_m3) && density_kg_per_m3 > 0.0 &&
      density_kg_per_m3 <= kMaxDensity_kg_per_m3) {
    return std::nullopt;
  }
  return "must be > 0 and <= 1e5 (kg/m³) (got " + FormatNumber(density_kg_per_m3) + ")";
}

std::optional<std::string> StrengthProblem(double compressive_strength_Pa) {
  // The same floor as a modulus: a strength below 1 kPa made crush ratios of 1e300 and inf.
  if (compressive_strength_Pa >= kMinModulus_Pa && compressive_strength_Pa <= kMaxStrength_Pa) {
    return std::nullopt;
  }
  return "must be in [" + FormatNumber(kMinModulus_Pa) + ", " + FormatNumber(kMaxStrength_Pa) +
         "] Pa, or \"does not crush\" or \"unknown\" (got " + FormatNumber(compressive_strength_Pa) + ")";
}

std::optional<std::pair<std::string, std::string>> StrengthFieldsProblem(const Material& m) {
  using Problem = std::pair<std::string, std::string>;
  const bool has_method = m.strength_method.find_first_not_of(" \t\r\n") != std::string::npos;
  const bool has_source = m.strength_source.find_first_not_of(" \t\r\n") != std::string::npos;
  switch (m.crush_behaviour) {
    case CrushBehaviour::kCrushes:
      if (!m.compressive_strength_Pa) {
        return Problem(kKeyStrength, "is required when the material crushes (crush_behaviour "
                                     "crushes); give its compressive strength in Pa");
      }
      if (auto p = StrengthProblem(*m.compressive_strength_Pa)) return Problem(kKeyStrength, *p);
      if (!has_method) {
        return Problem(kKeyStrengthMethod,
                       "must name the test method of compressive_strength_Pa (e.g. \"ASTM D1621, "
                       "at yield or 10 % strain\")");
      }
      if (!has_source) {
        return Problem(kKeyStrengthSource,
                       "must say where compressive_strength_Pa comes from (a URL or a citation)");
      }
      return std::nullopt;
    case CrushBehaviour::kDoesNotCrush:
      if (m.compressive_strength_Pa) {
        return Problem(kKeyStrength, "must be empty for a material that does not crush (got " +
                                         FormatNumber(*m.compressive_strength_Pa) + ")");
      }
      if (!has_method) {
        return Problem(kKeyStrengthMethod,
                       "must say why the material does not crush (e.g. \"flexible open-cell "
                       "foam: densifies, no crush strength\")");
      }
      if (!has_source) {
        return Problem(kKeyStrengthSource,
                       "must say where \"does not crush\" comes from (a URL or a citation)");
      }
      return std::nullopt;
    case CrushBehaviour::kUnknown:
      if (m.compressive_strength_Pa) {
        return Problem(kKeyStrength, "must be empty when the crush behaviour is unknown (got " +
                                         FormatNumber(*m.compressive_strength_Pa) + ")");
      }
      if (has_method) {
        return Problem(kKeyStrengthMethod,
                       "must be empty when the strength is unknown (a note may say why)");
      }
      if (has_source) {
        return Problem(kKeyStrengthSource,
                       "must be empty when the strength is unknown (a note may say why)");
      }
      return std::nullopt;
  }
  return Problem(kKeyStrength, "has an invalid crush behaviour");
}

std::optional<std::string> TextProblem(std::string_view text, bool is_name) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    return std::string("must not be empty");
  }
  if (is_name && (text.front() == ' ' || text.back() == ' ' || text.front() == '\t' ||
                  text.back() == '\t')) {
    return "must not start or end with a space (got \"" + std::string(text) + "\")";
  }
  return std::nullopt;
}

std::optional<std::pair<std::string, std::string>> FirstProblem(const Material& m) {
  using Problem = std::pair<std::string, std::string>;
  if (auto p = TextProblem(m.name, true)) return Problem(kKeyName, *p);
  if (auto p = TextProblem(m.family, false)) return Problem(kKeyFamily, *p);
  if (auto p = ModulusProblem(m.youngs_modulus_Pa)) return Problem(kKeyModulus, *p);
  if (m.poisson_ratio) {
    if (auto p = PoissonProblem(*m.poisson_ratio)) return Problem(kKeyPoisson, *p);
  }
  if (m.density_kg_per_m3) {
    if (auto p = DensityProblem(*m.density_kg_per_m3)) return Problem(kKeyDensity, *p);
  }
  if (ToString(m.modulus_basis) == "unknown") {
    return Problem(kKeyBasis, "is not a known basis");
  }
  if (auto p = TextProblem(m.source, false)) return Problem(kKeySource, *p);
  return StrengthFieldsProblem(m);
}

std::string Describe(const Material& material) { return "material '" + material.name + "'"; }

}  // namespace covopt::materials::internal
