#pragma once
/// @file material.hpp
/// One covering material of the catalog: its elastic constants in SI units, how the
/// modulus was obtained, and where the numbers come from.
///
/// Foams and elastomers are nonlinear: a compressive secant modulus, a bending modulus and
/// a tensile modulus of the same foam can differ several-fold. Every entry therefore
/// carries the basis of its E, and a note saying how it was derived where it was (e.g. a
/// secant from a stress at a strain).

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "covopt/core/compressive_curve.hpp"
#include "covopt/core/scene.hpp"

namespace covopt::materials {

/// The Poisson ratio used for a material whose ν is unknown: 0.25, the paper's Fig. 9 and
/// Table III value (docs/model.md §1). Consumers that fall back on it should say so
/// ("ν unknown, 0.25 assumed").
inline constexpr double kDefaultPoissonRatio = 0.25;

/// How the Young's modulus of an entry was obtained.
enum class ModulusBasis {
  kCompressive,  ///< "compressive": compression test, usually a secant over a strain range
  kTensile,      ///< "tensile": tension test
  kBending,      ///< "bending": flexural (e.g. 3-point bending) test
  kFitted,       ///< "fitted": identified by fitting an impact model to measured forces
  kAsPrinted,    ///< "as-printed": the source states E without saying how it was measured
  kHardness,     ///< "hardness": estimated from a Shore hardness by an empirical correlation
};

/// The catalog spelling: "compressive", "tensile", "bending", "fitted", "as-printed",
/// "hardness".
std::string_view ToString(ModulusBasis basis) noexcept;

/// What the basis means, for people, e.g. "compression test (secant or tangent modulus)".
std::string_view Describe(ModulusBasis basis) noexcept;

/// Reads the catalog spelling (exactly as ToString writes it); empty if unknown.
std::optional<ModulusBasis> ParseModulusBasis(std::string_view text) noexcept;

/// How a material behaves when compressed past its elastic range: what the no-crush
/// criterion (docs/model.md §12) can say about it.
enum class CrushBehaviour {
  /// A rigid or semi-rigid foam (EPS, XPS, rigid PU, PMI) or a solid that yields: it stays
  /// elastic only up to its compressive strength (compressive_strength_Pa, known).
  kCrushes,
  /// An elastomer, gel or flexible foam: it densifies instead of crushing; full compression
  /// (the not-fully-compressed criterion) is its limit.
  kDoesNotCrush,
  /// Not known from the sources at hand: a design with it cannot be verified for crushing.
  kUnknown,
};

/// The catalog spelling: "crushes", "does-not-crush", "unknown".
std::string_view ToString(CrushBehaviour behaviour) noexcept;

/// Reads the spelling ToString writes; empty if it is none of them.
std::optional<CrushBehaviour> ParseCrushBehaviour(std::string_view text) noexcept;

/// Where a compressive strength written without a unit is believable [Pa]: 1 kPa (the
/// softest crushable foams are rated at tens of kPa) to 10 GPa (beyond any polymer). A bare
/// number outside it is refused as a likely unit slip ("172" meant in kPa), as for E.
inline constexpr double kPlausibleStrengthMin_Pa = 1e3;
inline constexpr double kPlausibleStrengthMax_Pa = 1e10;
/// The largest compressive strength an entry may have [Pa] (as for E).
inline constexpr double kMaxStrength_Pa = 1e12;

/// The strain at which a compressive curve is rated and filtered (`materials find
/// --stress-at-25`): 25 %, the compression-deflection strain of ASTM D1056 and D3574.
inline constexpr double kRatingStrain = 0.25;

/// The range a rate_factor's bounds must lie in [-]: 0.1 to 10 (a tenth to ten times the
/// measured stresses). low <= high.
inline constexpr double kMinRateFactor = 0.1;
inline constexpr double kMaxRateFactor = 10.0;

/// A closed range [low, high] of a quantity (a stress band [Pa], a rate factor [-]).
struct Bounds {
  double low = 0.0;
  double high = 0.0;
};

/// One catalog entry. Plain data; Catalog validates entries when it loads or adds them.
struct Material {
  /// Unique within a catalog, compared ignoring case, e.g. "polystyrene foam 27.6".
  std::string name;
  /// A coarse group for filtering: "foam", "elastomer", "padding", "thermoplastic", ...
  std::string family;
  /// Young's modulus E [Pa], in [1e3, 1e12] (the floor kMinModulus_Pa, covopt/core/physical_floors.hpp).
  double youngs_modulus_Pa = 0.0;
  /// Poisson ratio ν [-], in (-1, 0.5]; empty when the source gives none (use
  /// PoissonRatioOrDefault and say that the default was used).
  std::optional<double> poisson_ratio;
  /// Density [kg/m³], > 0; empty when the source gives none.
  std::optional<double> density_kg_per_m3;
  /// How E was obtained.
  ModulusBasis modulus_basis = ModulusBasis::kAsPrinted;
  /// Where the numbers come from: a URL or a citation.
  std::string source;
  /// How E was derived (strain range, representative value of a range, conversions);
  /// may be empty.
  std::string note;
  /// Whether the material crushes, and so whether compressive_strength_Pa applies.
  CrushBehaviour crush_behaviour = CrushBehaviour::kUnknown;
  /// Compressive strength [Pa]: the stress at yield or at 10 % strain, whichever comes
  /// first, as the test method defines it; set exactly when crush_behaviour is kCrushes.
  std::optional<double> compressive_strength_Pa;
  /// The strength's test method ("ASTM D1621, at yield or 10 % strain") or, for a material
  /// that does not crush, why ("flexible foam: densifies"); empty when unknown.
  std::string strength_method;
  /// Where the strength (or the does-not-crush statement) comes from: a URL or a citation;
  /// empty when unknown.
  std::string strength_source;
  /// Where the entry was defined, "file:line:column" of its [[material]] header; empty
  /// for entries added in code.
  std::string origin;

  // ---- The compressive curve (docs/model.md, "the foam layer"); all empty without one. ----
  /// The measured (or fitted, or assumed-shape) loading curve σ(ε), piecewise linear through
  /// the origin; null when the entry has none (then only its E describes it).
  std::shared_ptr<const CompressiveCurve> compressive_curve;
  /// Where the curve's points come from (a URL, DOI or citation); set exactly with a curve.
  std::string curve_source;
  /// The test's strain rate as the catalog states it: "quasi-static", "unknown", or a rate
  /// with its unit ("20 1/s"); set exactly with a curve.
  std::string curve_rate;
  /// curve_rate as a number [1/s] when it is a rate; empty for "quasi-static" and "unknown".
  std::optional<double> curve_rate_per_s;
  /// true: a flexible foam that recovers after the impact; false: a crushable liner (spent
  /// after one impact). Set exactly with a curve.
  std::optional<bool> recovers;
  /// The range of the factor the stresses may be multiplied by at impact rates [-] (e.g.
  /// [1, 3] for a quasi-static curve), kMinRateFactor <= low <= high <= kMaxRateFactor;
  /// empty when the catalog gives none. Only with a curve.
  std::optional<Bounds> rate_factor;
  /// A grade band standing in for a measured curve: the range of σ(25 %) [Pa] the grade
  /// allows (e.g. ASTM D1056 grade 2: 34.5-62.1 kPa), carried as an uncertainty. Only with
  /// curve_shape and a curve whose σ(25 %) lies in the band.
  std::optional<Bounds> stress_at_25_band_Pa;
  /// With a band: the assumed shape the curve's points follow, named (which measured curve,
  /// scaled how), e.g. "VN600 (NIST), scaled to the band's midpoint at 25 %". Empty otherwise.
  std::string curve_shape;
};

/// σ(25 %) of the material's curve [Pa]; empty without a curve or when the curve ends before
/// 25 % (past its end the layer is a rigid stop: no stress of the foam there).
std::optional<double> StressAt25Pa(const Material& material) noexcept;

/// The covering a layer of `thickness_m` of this material makes: its E, its ν (or
/// kDefaultPoissonRatio when unknown), the thickness and its compressive curve (null without
/// one); the law is left at kAuto. Every caller that turns a catalog material into a covering
/// takes the curve from here.
CoveringSpec CoveringOf(const Material& material, double thickness_m);

/// ν of the material, or kDefaultPoissonRatio when it is unknown.
double PoissonRatioOrDefault(const Material& material) noexcept;

}  // namespace covopt::materials
