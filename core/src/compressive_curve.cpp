#include "covopt/core/compressive_curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "numeric_format.hpp"

namespace covopt {
namespace {

using internal::FormatNumber;

[[noreturn]] void Refuse(std::string_view name, std::size_t index, const std::string& problem) {
  throw std::invalid_argument(std::string(name) + ": point " + std::to_string(index + 1) + ": " + problem);
}

/// The root x in [0, length] of a + b x + c x²/2 = 0 with a <= 0, b >= 0, c >= 0 and the
/// function non-decreasing on the piece, without cancellation.
double PieceRoot(double a, double b, double c, double length) noexcept {
  if (a >= 0.0) return 0.0;
  double x = 0.0;
  if (c == 0.0) {
    x = b > 0.0 ? -a / b : length;
  } else {
    // x = (-b + sqrt(b² - 2 a c)) / c = -2a / (b + sqrt(b² - 2ac))
    const double disc = b * b - 2.0 * a * c;
    x = -2.0 * a / (b + std::sqrt(std::max(disc, 0.0)));
  }
  return std::clamp(x, 0.0, length);
}

}  // namespace

CompressiveCurve CompressiveCurve::FromPoints(std::span<const StrainStressPoint> points, std::string_view name) {
  if (points.empty() || points.size() > kMaxCurvePoints) {
    throw std::invalid_argument(std::string(name) + ": a curve needs 1 to " + std::to_string(kMaxCurvePoints) +
                                " points (strain, stress) after the implied origin (got " +
                                std::to_string(points.size()) + ")");
  }
  CompressiveCurve curve;
  curve.points_.assign(points.begin(), points.end());
  double previous_strain = 0.0, previous_stress = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto [strain, stress] = points[i];
    if (!std::isfinite(strain) || !(strain > 0.0 && strain < 1.0)) {
      Refuse(name, i, "strain must be in (0, 1) (got " + FormatNumber(strain) + ")");
    }
    if (i > 0 && !(strain > previous_strain)) {
      Refuse(name, i, "strain " + FormatNumber(strain) + " must exceed the previous point's " +
                          FormatNumber(previous_strain) + " (strains increase)");
    }
    if (!std::isfinite(stress) || !(stress >= kMinCurveStress_Pa && stress <= kMaxCurveStress_Pa)) {
      Refuse(name, i, "stress must be in [1, 1e10] Pa (got " + FormatNumber(stress) + " Pa)");
    }
    if (stress < previous_stress) {
      Refuse(name, i, "stress " + FormatNumber(stress) + " Pa falls below the previous point's " +
                          FormatNumber(previous_stress) + " Pa; give the loading envelope (stresses never decrease)");
    }
    previous_strain = strain;
    previous_stress = stress;
  }
  curve.energy_.assign(points.size() + 1, 0.0);
  curve.second_.assign(points.size() + 1, 0.0);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double length = curve.StrainOf(k + 1) - curve.StrainOf(k);
    const double s0 = curve.StressOf(k), s1 = curve.StressOf(k + 1);
    const double slope = (s1 - s0) / length;
    curve.energy_[k + 1] = curve.energy_[k] + s0 * length + slope * length * length / 2.0;
    curve.second_[k + 1] = curve.second_[k] + curve.energy_[k] * length + s0 * length * length / 2.0 +
                           slope * length * length * length / 6.0;
  }
  return curve;
}

std::size_t CompressiveCurve::PieceOf(double strain) const noexcept {
  // The first given point whose strain is >= `strain`: piece k = its index (0-based) ends there.
  const auto it = std::lower_bound(points_.begin(), points_.end(), strain,
                                   [](const StrainStressPoint& p, double e) { return p.strain < e; });
  const auto k = static_cast<std::size_t>(it - points_.begin());
  return std::min(k, points_.size() - 1);
}

double CompressiveCurve::StressAt(double strain) const noexcept {
  const double e = std::clamp(strain, 0.0, last_strain());
  const std::size_t k = PieceOf(e);
  const double e0 = StrainOf(k), e1 = StrainOf(k + 1);
  const double s0 = StressOf(k), s1 = StressOf(k + 1);
  return s0 + (s1 - s0) * (e - e0) / (e1 - e0);
}

double CompressiveCurve::EnergyDensityAt(double strain) const noexcept {
  const double e = std::clamp(strain, 0.0, last_strain());
  const std::size_t k = PieceOf(e);
  const double e0 = StrainOf(k), x = e - e0;
  const double s0 = StressOf(k), slope = (StressOf(k + 1) - s0) / (StrainOf(k + 1) - e0);
  return energy_[k] + s0 * x + slope * x * x / 2.0;
}

double CompressiveCurve::SecondIntegralAt(double strain) const noexcept {
  const double e = std::clamp(strain, 0.0, last_strain());
  const std::size_t k = PieceOf(e);
  const double e0 = StrainOf(k), x = e - e0;
  const double s0 = StressOf(k), slope = (StressOf(k + 1) - s0) / (StrainOf(k + 1) - e0);
  return second_[k] + energy_[k] * x + s0 * x * x / 2.0 + slope * x * x * x / 6.0;
}

std::optional<double> CompressiveCurve::StrainAtEnergyDensity(double energy_density_J_per_m3) const noexcept {
  const double w = energy_density_J_per_m3;
  if (!(w >= 0.0)) return std::nullopt;
  if (w > energy_.back()) return std::nullopt;
  if (w == 0.0) return 0.0;
  // The piece whose end energy first reaches w (energy_ is non-decreasing; strictly after 0).
  const auto it = std::lower_bound(energy_.begin() + 1, energy_.end(), w);
  const auto k = static_cast<std::size_t>(it - energy_.begin()) - 1;
  const double e0 = StrainOf(k), length = StrainOf(k + 1) - e0;
  const double s0 = StressOf(k), slope = (StressOf(k + 1) - s0) / length;
  return e0 + PieceRoot(energy_[k] - w, s0, slope, length);
}

std::optional<double> CompressiveCurve::StrainAtSecondIntegral(double second_integral_J_per_m3) const noexcept {
  const double v = second_integral_J_per_m3;
  if (!(v >= 0.0) || v > second_.back()) return std::nullopt;
  if (v == 0.0) return 0.0;
  const auto it = std::lower_bound(second_.begin() + 1, second_.end(), v);
  const auto k = static_cast<std::size_t>(it - second_.begin()) - 1;
  const double e0 = StrainOf(k), length = StrainOf(k + 1) - e0;
  const double s0 = StressOf(k), slope = (StressOf(k + 1) - s0) / length;
  // g(x) = V_k + W_k x + s0 x²/2 + slope x³/6 - v on [0, length]: increasing and convex, so
  // Newton from the piece's end (g >= 0 there) descends monotonically onto the root.
  double x = length;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double g = second_[k] - v + x * (energy_[k] + x * (s0 / 2.0 + x * slope / 6.0));
    const double dg = energy_[k] + x * (s0 + x * slope / 2.0);
    if (!(dg > 0.0)) break;
    const double next = std::max(x - g / dg, 0.0);
    if (!(next < x)) break;  // the monotone sequence stopped decreasing: converged
    x = next;
  }
  return e0 + x;
}

double CompressiveCurve::SecondIntegralDrop(double strain, double gap) const noexcept {
  const double e = std::clamp(strain, 0.0, last_strain());
  const double g = std::clamp(gap, 0.0, e);
  const std::size_t k = PieceOf(e);
  const double e0 = StrainOf(k);
  if (e - g < e0) return SecondIntegralAt(e) - SecondIntegralAt(e - g);  // across points: no cancellation to fear
  const double slope = (StressOf(k + 1) - StressOf(k)) / (StrainOf(k + 1) - e0);
  return g * (EnergyDensityAt(e) - g * (StressAt(e) / 2.0 - g * slope / 6.0));
}

double CompressiveCurve::SlopeAt(double strain) const noexcept {
  const std::size_t k = PieceOf(std::clamp(strain, 0.0, last_strain()));
  return (StressOf(k + 1) - StressOf(k)) / (StrainOf(k + 1) - StrainOf(k));
}

std::optional<double> CompressiveCurve::StrainAtStress(double stress_Pa) const noexcept {
  if (!(stress_Pa >= 0.0) || stress_Pa > last_stress_Pa()) return std::nullopt;
  if (stress_Pa == 0.0) return 0.0;
  const auto it = std::lower_bound(points_.begin(), points_.end(), stress_Pa,
                                   [](const StrainStressPoint& p, double s) { return p.stress_Pa < s; });
  const auto k = static_cast<std::size_t>(it - points_.begin());  // piece k ends at point k
  const double e0 = StrainOf(k), e1 = StrainOf(k + 1), s0 = StressOf(k), s1 = StressOf(k + 1);
  if (s1 == s0) return e0;
  return std::clamp(e0 + (stress_Pa - s0) * (e1 - e0) / (s1 - s0), e0, e1);
}

CompressiveCurve CompressiveCurve::Scaled(double factor) const {
  if (!std::isfinite(factor) || !(factor > 0.0)) {
    throw std::invalid_argument("rate factor must be finite and above 0 (got " + FormatNumber(factor) + ")");
  }
  std::vector<StrainStressPoint> scaled = points_;
  for (StrainStressPoint& p : scaled) p.stress_Pa *= factor;
  return FromPoints(scaled, "compressive_curve (scaled by the rate factor)");
}

std::string_view ToString(CoveringLaw law) noexcept {
  switch (law) {
    case CoveringLaw::kAuto: return "auto";
    case CoveringLaw::kFoam: return "foam";
    case CoveringLaw::kHertz: return "hertz";
  }
  return "auto";
}

std::optional<CoveringLaw> ParseCoveringLaw(std::string_view text) noexcept {
  for (CoveringLaw law : {CoveringLaw::kAuto, CoveringLaw::kFoam, CoveringLaw::kHertz}) {
    if (text == ToString(law)) return law;
  }
  return std::nullopt;
}

}  // namespace covopt
