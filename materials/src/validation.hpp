#pragma once
// The value rules of a catalog entry (private), shared by the TOML loader (which knows
// where each value is) and Catalog::Add(Material) (which does not).

#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "covopt/materials/material.hpp"

namespace covopt::materials::internal {

inline constexpr double kMaxModulus_Pa = 1e12;
inline constexpr double kMaxDensity_kg_per_m3 = 1e5;

/// The keys of an entry, in the order of the file format's documentation.
inline constexpr std::string_view kKeyName = "name";
inline constexpr std::string_view kKeyFamily = "family";
inline constexpr std::string_view kKeyModulus = "youngs_modulus_Pa";
inline constexpr std::string_view kKeyPoisson = "poisson_ratio";
inline constexpr std::string_view kKeyDensity = "density_kg_per_m3";
inline constexpr std::string_view kKeyBasis = "modulus_basis";
inline constexpr std::string_view kKeySource = "source";
inline constexpr std::string_view kKeyNote = "note";
inline constexpr std::string_view kKeyStrength = "compressive_strength_Pa";
inline constexpr std::string_view kKeyStrengthMethod = "strength_method";
inline constexpr std::string_view kKeyStrengthSource = "strength_source";
inline constexpr std::string_view kKeyCurve = "compressive_curve";
inline constexpr std::string_view kKeyCurveSource = "curve_source";
inline constexpr std::string_view kKeyCurveRate = "curve_rate";
inline constexpr std::string_view kKeyRecovers = "recovers";
inline constexpr std::string_view kKeyRateFactor = "rate_factor";
inline constexpr std::string_view kKeyBand = "stress_at_25_band";
inline constexpr std::string_view kKeyShape = "curve_shape";

/// The words curve_rate may hold instead of a rate with its unit.
inline constexpr std::string_view kQuasiStatic = "quasi-static";
inline constexpr std::string_view kUnknownRate = "unknown";
/// What curve_rate may be, for messages.
inline constexpr std::string_view kCurveRateAllowed =
    "\"quasi-static\", \"unknown\", or a strain rate with its unit, e.g. \"20 1/s\" or \"0.01/s\"";
/// The largest strain rate a curve_rate may state [1/s].
inline constexpr double kMaxCurveRate_per_s = 1e6;

/// The words compressive_strength_Pa may hold instead of a stress.
inline constexpr std::string_view kDoesNotCrush = "does not crush";
inline constexpr std::string_view kUnknownStrength = "unknown";
/// What compressive_strength_Pa may be, for messages.
inline constexpr std::string_view kStrengthAllowed =
    "a stress with a unit (\"172 kPa\"), a number in Pa, \"does not crush\" or \"unknown\"";

/// What is wrong with a value, phrased to follow the key ("must be > 0 ... (got -1)"), or
/// nothing if it is fine.
std::optional<std::string> ModulusProblem(double youngs_modulus_Pa);
std::optional<std::string> PoissonProblem(double poisson_ratio);
std::optional<std::string> DensityProblem(double density_kg_per_m3);
std::optional<std::string> StrengthProblem(double compressive_strength_Pa);
/// Required text (name, family, source): not empty or blank; a name must also not start
/// or end with a space, since names are looked up exactly (ignoring case).
std::optional<std::string> TextProblem(std::string_view text, bool is_name);

/// The first rule the strength fields of an entry break (crush_behaviour,
/// compressive_strength_Pa, strength_method, strength_source), as {key, problem}.
std::optional<std::pair<std::string, std::string>> StrengthFieldsProblem(const Material& material);

/// The first rule the curve fields of an entry break (compressive_curve, curve_source,
/// curve_rate, recovers, rate_factor, stress_at_25_band, curve_shape), as {key, problem}.
std::optional<std::pair<std::string, std::string>> CurveFieldsProblem(const Material& material);

/// curve_rate's text as a rate [1/s] ("20 1/s", "20/s", "0.01 /s"); empty for other text.
std::optional<double> ParseCurveRate(std::string_view text);

/// What is wrong with a rate_factor [low, high], phrased to follow the key; nothing if fine.
std::optional<std::string> RateFactorProblem(double low, double high);

/// What is wrong with a stress_at_25_band [low, high] [Pa], or with the curve's σ(25 %) in
/// it, phrased to follow the key; nothing if fine. `stress_at_25_Pa` empty: the curve does not
/// reach 25 %.
std::optional<std::string> BandProblem(double low_Pa, double high_Pa, std::optional<double> stress_at_25_Pa);

/// The first rule a whole entry breaks, as {key, problem}; nothing if it is valid.
std::optional<std::pair<std::string, std::string>> FirstProblem(const Material& material);

/// "material 'NAME'" for messages.
std::string Describe(const Material& material);

}  // namespace covopt::materials::internal
