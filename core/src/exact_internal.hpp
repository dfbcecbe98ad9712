#pragma once
// Private: the pieces of the exact path (exact.cpp) that its damped extension
// (exact_damped.cpp) shares: Gauss-Legendre nodes, the segment holding δ_max and the energy
// balance inside it; and the damped path's entry points, which exact.cpp dispatches to.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"

namespace covopt::internal {

/// Refuses a scene without the energy integral of a two-body contact (Scene::has_energy_integral,
/// docs/model.md §10), naming the input that removes it.
/// @throws std::invalid_argument for a braking robot or a neck.
void CheckExactPathApplies(const Scene& scene);

/// Gauss-Legendre nodes and weights on [0, 1], computed once by Newton on P_N.
template <int N>
struct GaussLegendre {
  std::array<double, N> node{};
  std::array<double, N> weight{};
  GaussLegendre() {
    for (int i = 0; i < N; ++i) {
      double x = std::cos(std::numbers::pi * (i + 0.75) / (N + 0.5));
      double derivative = 0.0;
      for (int iteration = 0; iteration < 100; ++iteration) {
        double p0 = 1.0, p1 = x;
        for (int k = 2; k <= N; ++k) {
          const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        derivative = N * (x * p1 - p0) / (x * x - 1.0);
        const double step = p1 / derivative;
        x -= step;
        if (std::abs(step) < 1e-16) break;
      }
      node[i] = 0.5 * (1.0 - x);
      weight[i] = 1.0 / ((1.0 - x * x) * derivative * derivative);  // (2/...)/2 on [0,1]
    }
  }
};

/// Index of the segment containing δ_max for a contact that stores `energy_J` [J] at its
/// maximum compression: the last segment whose start energy is below it.
inline std::size_t PeakSegment(const ImpactModel& model, double energy_J) noexcept {
  std::size_t i = model.segment_count() - 1;
  while (i > 0 && !(model.segment(i).energy_at_start_J < energy_J)) --i;
  return i;
}

/// Distance d = δ - start [m] past the start of a literal segment whose origin lies before
/// its start (x0 = start - origin > 0) at which U rises by `energy_gap_J` [J] > 0:
/// F_off d + K/p ((x0 + d)^p - x0^p) = ΔE. Written with the ratio r = d/x0 as
/// F_off d + K x0^p/p expm1(p log1p(r)) it has no cancellation however small d is beside x0
/// (solved in x, the difference x^p - x0^p and x itself lose d to the rounding of x0: δ_max
/// up to 8 ulps off, and U(δ_max) off by F(δ_max) times that, F being the jumped force).
inline double SolveEnergyBalancePastStart(const ForceLawSegment& seg,
                                          double energy_gap_J) noexcept {
  const double n = seg.exponent;
  const double p = n + 1.0;
  const double x0 = seg.start_m - seg.origin_m;
  const double force_at_start = seg.stiffness * std::pow(x0, n);  // K x0^n, F jumps by it
  const double energy_scale = force_at_start * x0 / p;            // K x0^p / p
  // The power term alone reaching ΔE gives d_b >= root (F_off >= 0), where g = F_off d_b.
  const double log_growth_b = std::log1p(energy_gap_J / energy_scale) / p;  // log1p(r_b)
  double d = x0 * std::expm1(log_growth_b);
  double power_growth = energy_gap_J / energy_scale;  // expm1(p log1p(r)) = (1 + r)^p - 1
  double g = seg.force_offset_N * d;
  for (int iteration = 0; iteration < 60; ++iteration) {
    // g' = F_off + K x0^n (1 + r)^n and g'' = n K x0^n (1 + r)^n / (x0 + d).
    const double one_plus_r = 1.0 + d / x0;
    const double power_force = force_at_start * ((1.0 + power_growth) / one_plus_r);
    const double slope = seg.force_offset_N + power_force;
    const double curvature = n * power_force / (x0 + d);
    // Halley with the correction to Newton's step capped at a factor 2, as in the
    // well-ordered solve below.
    const double slope_squared = slope * slope;
    const double g_curvature = g * curvature;
    const double denominator =
        g_curvature > slope_squared ? slope_squared : 2.0 * slope_squared - g_curvature;
    const double step = 2.0 * g * slope / denominator;
    double next = d - step;
    if (!(next > 0.0)) next = d - g / slope;  // Newton stays above 0 from either side
    if (!(next > 0.0)) next = 0.5 * d;
    if (iteration > 0 && !(std::abs(step) > 1e-6 * d)) return next;
    d = next;
    power_growth = std::expm1(p * std::log1p(d / x0));
    g = seg.force_offset_N * d + energy_scale * power_growth - energy_gap_J;
  }
  return d;
}

/// Phase-local penetration x = δ - origin [m] at which U rises by `energy_gap_J` [J] > 0
/// above the start of a segment whose origin is its start (the cumulative reading's, and
/// the literal reading's well-ordered ones): F_off x + K/p x^p = ΔE.
inline double SolveEnergyBalanceFromStart(const ForceLawSegment& seg,
                                          double energy_gap_J) noexcept {
  const double n = seg.exponent;
  const double p = n + 1.0;
  const double k_over_p = seg.stiffness / p;
  if (seg.force_offset_N == 0.0) {
    return std::pow(energy_gap_J / k_over_p, 1.0 / p);  // closed form
  }
  // g(x) = F_off x + K/p x^p - ΔE is increasing and convex for x >= 0.
  // The power term alone reaching ΔE gives x_b >= root, where g, g' and g'' are known
  // without another pow (x_b^p = ΔE p/K): the first Halley step is free. Each
  // further step costs one pow; Halley's cubic convergence means a step below 1e-6 x
  // leaves an error of order 1e-18 x, so that step is the last one. The free step
  // is never the last: its g carries x_b's rounding, p times g's own.
  const double x_b_pow_p = energy_gap_J / k_over_p;
  double x = std::pow(x_b_pow_p, 1.0 / p);
  double x_pow_n = x_b_pow_p / x;
  double g = seg.force_offset_N * x;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double slope = seg.force_offset_N + seg.stiffness * x_pow_n;
    // Halley, x - 2 g g' / (2 g'^2 - g g''), with g'' x = n K x^n and one division; the
    // correction to Newton's step g/g' is capped at a factor 2 (g g'' <= g'^2).
    const double slope_squared_x = slope * slope * x;
    const double g_curvature_x = g * n * seg.stiffness * x_pow_n;
    const double denominator = g_curvature_x > slope_squared_x
                                   ? slope_squared_x
                                   : 2.0 * slope_squared_x - g_curvature_x;
    const double step = 2.0 * g * slope * x / denominator;
    double next = x - step;
    if (!(next > 0.0)) next = x - g / slope;  // Newton stays above 0 from either side
    if (iteration > 0 && !(std::abs(step) > 1e-6 * x)) return next;
    x = next;
    x_pow_n = std::pow(x, n);
    g = seg.force_offset_N * x + k_over_p * (x_pow_n * x) - energy_gap_J;
  }
  return x;
}

/// Penetration δ [m] inside segment `seg` at which U rises by `energy_gap_J` [J] > 0 above
/// U(start), i.e. U(δ) = U(start) + energy_gap_J, and at most the segment's end.
/// PeakSegment picks the segment whose end stores at least the energy, but U(end) is the
/// next segment's U(start) as rounded: this segment's inverse can land a few ulps past
/// its end, where a literal law's jumped force would put U(δ) off by F times those ulps.
inline double SolveEnergyBalance(const ForceLawSegment& seg, double energy_gap_J) noexcept {
  if (seg.curve) [[unlikely]] {
    // The foam law (docs/model.md §16), always the first segment: U = A h V(δ/h), V cubic on
    // each piece of the curve, one root (CompressiveCurve::StrainAtSecondIntegral).
    const double h = seg.foam_thickness_m;
    const std::optional<double> strain =
        seg.curve->StrainAtSecondIntegral(energy_gap_J / (seg.foam_area_m2 * h));
    return strain ? std::min(*strain * h, seg.end_m) : seg.end_m;
  }
  const double delta = seg.start_m > seg.origin_m
                           ? seg.start_m + SolveEnergyBalancePastStart(seg, energy_gap_J)
                           : seg.origin_m + SolveEnergyBalanceFromStart(seg, energy_gap_J);
  return std::min(delta, seg.end_m);
}

/// The damped exact path (exact_damped.cpp, docs/model.md §10.1), for a model with
/// model.damping > 0: ExactPeaks's answer.
ImpactPeaks DampedExactPeaks(const ImpactModel& model) noexcept;

/// The two halves of a damped contact [s]: first contact to maximum compression, and
/// maximum compression to separation.
struct DampedContactTimes {
  double loading_s = 0.0;
  double unloading_s = 0.0;
};

/// The damped contact's loading and unloading times for peaks from DampedExactPeaks.
DampedContactTimes DampedContactDurations(const ImpactModel& model,
                                          const ImpactPeaks& peaks) noexcept;

/// The relative speed at separation of a damped contact [m/s] (< v0).
double DampedReboundSpeed(const ImpactModel& model) noexcept;

}  // namespace covopt::internal
