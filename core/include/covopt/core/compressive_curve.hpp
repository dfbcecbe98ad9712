#pragma once
/// @file compressive_curve.hpp
/// A covering material's measured compressive curve σ(ε) (docs/model.md, "the foam layer"):
/// nominal compressive stress against nominal strain on the loading branch, as measured points,
/// piecewise linear between them and through (0, 0). Its integrals are exact:
///
///     W(ε) = ∫₀^ε σ dε'   [J/m³]   (quadratic on each piece: the energy a unit volume stores)
///     V(ε) = ∫₀^ε W dε'   [J/m³]   (cubic on each piece: what a curved layer's energy needs)
///
/// so a foam layer's force and energy (F = 2π R_c h W(d/h), U = 2π R_c h² V(d/h) on a curved
/// face; F = A σ(d/h), U = A h W(d/h) on a flat one) stay closed form, and the exact path keeps
/// one root. Past the last point the layer is densified: a rigid stop (the callers model it);
/// the functions here are defined on [0, last_strain()].
///
/// Plain SI; validated on construction. A CoveringSpec carries one (shared, immutable) when the
/// material has a measured curve (covopt/core/scene.hpp).

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

namespace covopt {

/// One measured point: nominal strain [-] and nominal compressive stress [Pa].
struct StrainStressPoint {
  double strain = 0.0;     ///< [-], in (0, 1)
  double stress_Pa = 0.0;  ///< [Pa], > 0
};

/// The most points a curve may have (a digitised test record has a few hundred).
inline constexpr std::size_t kMaxCurvePoints = 10000;
/// The range of a measured stress [Pa]: 1 Pa (below it a foam is no covering) to 10 GPa.
inline constexpr double kMinCurveStress_Pa = 1.0;
inline constexpr double kMaxCurveStress_Pa = 1e10;

/// A loading curve through (0, 0) and the given points, piecewise linear.
class CompressiveCurve {
 public:
  /// Checks and keeps `points` (the origin is implied; do not list it).
  /// Allowed: 1 to kMaxCurvePoints points; strains strictly increasing in (0, 1); stresses
  /// finite, in [kMinCurveStress_Pa, kMaxCurveStress_Pa] (1 Pa to 10 GPa) and non-decreasing (a loading
  /// envelope: a measured dip, such as a rigid foam's yield drop, must be given as its
  /// envelope, so that force, pressure and strain all grow with the compression).
  /// @param name how messages call the curve ("compressive_curve", "catalog.toml:12:1: ...").
  /// @throws std::invalid_argument naming the point, its value and the allowed range, e.g.
  ///   "compressive_curve: point 3: strain 0.25 must exceed the previous point's 0.3".
  static CompressiveCurve FromPoints(std::span<const StrainStressPoint> points,
                                     std::string_view name = "compressive_curve");

  /// The points as given (without the implied origin).
  std::span<const StrainStressPoint> points() const noexcept { return points_; }
  /// The last measured strain ε_end [-]: past it the layer is a rigid stop.
  double last_strain() const noexcept { return points_.back().strain; }
  /// σ(ε_end) [Pa].
  double last_stress_Pa() const noexcept { return points_.back().stress_Pa; }

  /// σ(ε) [Pa] for ε in [0, ε_end]; ε outside is clamped to it (the caller handles the stop).
  double StressAt(double strain) const noexcept;
  /// W(ε) = ∫₀^ε σ [J/m³], exact, ε clamped to [0, ε_end].
  double EnergyDensityAt(double strain) const noexcept;
  /// V(ε) = ∫₀^ε W [J/m³], exact, ε clamped to [0, ε_end].
  double SecondIntegralAt(double strain) const noexcept;
  /// W(ε_end), V(ε_end) [J/m³].
  double total_energy_density_J_per_m3() const noexcept { return energy_.back(); }
  double total_second_integral_J_per_m3() const noexcept { return second_.back(); }
  /// W and V [J/m³] at the strain of the given point i (0-based, i < points().size()), exact,
  /// without a search (for callers that walk the pieces).
  double EnergyDensityAtPoint(std::size_t i) const noexcept { return energy_[i + 1]; }
  double SecondIntegralAtPoint(std::size_t i) const noexcept { return second_[i + 1]; }

  /// The strain at which W(ε) = w [-], w in [0, W(ε_end)] (one root per piece, closed form);
  /// empty for w above W(ε_end) (the layer is used up).
  std::optional<double> StrainAtEnergyDensity(double energy_density_J_per_m3) const noexcept;
  /// The strain at which V(ε) = v [-], v in [0, V(ε_end)] (the cubic piece's one root, by a
  /// Newton iteration that descends monotonically onto it: V is increasing and convex); empty
  /// for v above V(ε_end).
  std::optional<double> StrainAtSecondIntegral(double second_integral_J_per_m3) const noexcept;
  /// V(ε) − V(ε − γ) [J/m³] for 0 <= γ <= ε <= ε_end without cancellation: within the piece
  /// holding ε it is the cubic's exact expansion W(ε) γ − σ(ε) γ²/2 + σ' γ³/6, so it keeps its
  /// relative accuracy however small γ is (the exact path's duration quadrature needs it).
  double SecondIntegralDrop(double strain, double gap) const noexcept;
  /// dσ/dε [Pa] on the piece holding ε (the lower piece at a point), ε clamped to [0, ε_end].
  double SlopeAt(double strain) const noexcept;
  /// The strain at which σ(ε) = s [-] (the smallest, on a plateau); empty above σ(ε_end).
  std::optional<double> StrainAtStress(double stress_Pa) const noexcept;

  /// The initial (first-piece) modulus σ₁/ε₁ [Pa].
  double initial_modulus_Pa() const noexcept { return points_.front().stress_Pa / points_.front().strain; }
  /// The same curve with every stress multiplied by `factor` (a rate factor, > 0).
  /// @throws std::invalid_argument when the scaled stresses leave the allowed range.
  CompressiveCurve Scaled(double factor) const;

 private:
  std::vector<StrainStressPoint> points_;
  // Per point i (index 0 is the origin, i ≥ 1 the i-th given point): the integrals at its strain.
  std::vector<double> energy_;  // W
  std::vector<double> second_;  // V
  std::size_t PieceOf(double strain) const noexcept;  // k: the piece [ε_k, ε_{k+1}] (ε_0 = 0)
  double StrainOf(std::size_t k) const noexcept { return k == 0 ? 0.0 : points_[k - 1].strain; }
  double StressOf(std::size_t k) const noexcept { return k == 0 ? 0.0 : points_[k - 1].stress_Pa; }
};

/// Which law describes the covering (docs/model.md, "which law").
enum class CoveringLaw {
  /// The foam law where the covering has a measured curve, else Hertz. The default.
  kAuto,
  /// The elastic-foundation law of a foam layer with its measured curve (needs one).
  kFoam,
  /// The Hertz half-space law of Park et al. (a small-strain elastic solid thicker than its
  /// contact): stiff, thin-contact coverings and the paper's reproduction.
  kHertz,
};

/// "auto", "foam" or "hertz".
std::string_view ToString(CoveringLaw law) noexcept;
/// The inverse of ToString; empty for other text.
std::optional<CoveringLaw> ParseCoveringLaw(std::string_view text) noexcept;

}  // namespace covopt
