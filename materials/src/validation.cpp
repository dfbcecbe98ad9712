#include "validation.hpp"

#include <cmath>
#include <cstdlib>
#include <string>

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

std::optional<double> ParseCurveRate(std::string_view text) {
  const std::string t(text);
  const char* begin = t.c_str();
  char* end = nullptr;
  const double value = std::strtod(begin, &end);
  if (end == begin) return std::nullopt;
  std::string_view unit(end);
  while (!unit.empty() && unit.front() == ' ') unit.remove_prefix(1);
  while (!unit.empty() && unit.back() == ' ') unit.remove_suffix(1);
  if (unit != "1/s" && unit != "/s" && unit != "s^-1" && unit != "s-1") return std::nullopt;
  return value;
}

std::optional<std::string> RateFactorProblem(double low, double high) {
  const auto in_range = [](double f) { return std::isfinite(f) && f >= kMinRateFactor && f <= kMaxRateFactor; };
  if (in_range(low) && in_range(high) && low <= high) return std::nullopt;
  return "must be [low, high] with " + FormatNumber(kMinRateFactor) + " <= low <= high <= " +
         FormatNumber(kMaxRateFactor) + " (a factor on the curve's stresses at impact rates) (got [" +
         FormatNumber(low) + ", " + FormatNumber(high) + "])";
}

std::optional<std::string> BandProblem(double low_Pa, double high_Pa, std::optional<double> stress_at_25_Pa) {
  if (!(std::isfinite(low_Pa) && std::isfinite(high_Pa) && low_Pa >= kMinCurveStress_Pa && low_Pa <= high_Pa &&
        high_Pa <= kMaxCurveStress_Pa)) {
    return "must be [low, high] stresses with " + FormatNumber(kMinCurveStress_Pa) + " Pa <= low <= high <= " +
           FormatNumber(kMaxCurveStress_Pa) + " Pa (got [" + FormatNumber(low_Pa) + ", " + FormatNumber(high_Pa) +
           "] Pa)";
  }
  if (!stress_at_25_Pa) {
    return std::string("needs a compressive_curve that reaches 25 % strain (the band rates the stress at 25 %)");
  }
  // A relative tolerance of 1e-6: the curve's points are the band's midpoint scaled, rounded.
  const double slack = 1e-6 * high_Pa;
  if (*stress_at_25_Pa < low_Pa - slack || *stress_at_25_Pa > high_Pa + slack) {
    std::string text = "[";  // built in steps: GCC 12's -Wrestrict misreads "[" + std::string
    text += FormatNumber(low_Pa);
    return text + ", " + FormatNumber(high_Pa) +
           "] Pa must contain the curve's stress at 25 % (got " + FormatNumber(*stress_at_25_Pa) +
           " Pa): the assumed shape's points must be scaled into the band";
  }
  return std::nullopt;
}

namespace {

bool HasText(const std::string& text) { return text.find_first_not_of(" \t\r\n") != std::string::npos; }

}  // namespace

std::optional<std::pair<std::string, std::string>> CurveFieldsProblem(const Material& m) {
  using Problem = std::pair<std::string, std::string>;
  if (!m.compressive_curve) {
    const std::pair<bool, std::string_view> extras[] = {
        {HasText(m.curve_source), kKeyCurveSource}, {HasText(m.curve_rate), kKeyCurveRate},
        {m.recovers.has_value(), kKeyRecovers},     {m.rate_factor.has_value(), kKeyRateFactor},
        {m.stress_at_25_band_Pa.has_value(), kKeyBand}, {HasText(m.curve_shape), kKeyShape}};
    for (const auto& [given, key] : extras) {
      if (given) return Problem(key, "is given but the material has no compressive_curve; give the curve or leave it out");
    }
    return std::nullopt;
  }
  if (!HasText(m.curve_source)) {
    return Problem(kKeyCurveSource, "must say where the compressive_curve comes from (a URL, DOI or citation)");
  }
  if (!HasText(m.curve_rate)) return Problem(kKeyCurveRate, "must be " + std::string(kCurveRateAllowed));
  if (!m.recovers) {
    return Problem(kKeyRecovers, "must be given with a compressive_curve: true (a flexible foam that recovers) or "
                                 "false (a crushable liner)");
  }
  if (m.rate_factor) {
    if (auto p = RateFactorProblem(m.rate_factor->low, m.rate_factor->high)) return Problem(kKeyRateFactor, *p);
  }
  if (m.stress_at_25_band_Pa && !HasText(m.curve_shape)) {
    return Problem(kKeyShape, "is required with a stress_at_25_band: a band stands in for a curve only with the "
                              "assumed shape named (which measured curve, scaled how)");
  }
  if (HasText(m.curve_shape) && !m.stress_at_25_band_Pa) {
    return Problem(kKeyBand, "is required with a curve_shape: the assumed shape stands for a grade band, given as "
                             "[low, high] stresses at 25 %");
  }
  if (m.stress_at_25_band_Pa) {
    if (auto p = BandProblem(m.stress_at_25_band_Pa->low, m.stress_at_25_band_Pa->high, StressAt25Pa(m))) {
      return Problem(kKeyBand, *p);
    }
  }
  return std::nullopt;
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
  if (auto p = StrengthFieldsProblem(m)) return p;
  return CurveFieldsProblem(m);
}

std::string Describe(const Material& material) { return "material '" + material.name + "'"; }

}  // namespace covopt::materials::internal
