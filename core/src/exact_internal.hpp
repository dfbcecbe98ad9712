#pragma once
// Private: the pieces of the exact path (exact.cpp) that its damped extension
// (exact_damped.cpp) shares: Gauss-Legendre nodes, the segment holding δ_max and the energy
// balance inside it; and the damped path's entry points, which exact.cpp dispatches to.
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"

namespace covopt::internal {

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

/// Phase-local penetration x [m] at which U rises by `energy_gap_J` [J] above the start of
/// segment `seg`, i.e. U(origin + x) = U(start) + energy_gap_J.
inline double SolveEnergyBalance(const ForceLawSegment& seg, double energy_gap_J) noexcept {
  const double n = seg.exponent;
  const double p = n + 1.0;
  const double x0 = seg.start_m - seg.origin_m;
  const double k_over_p = seg.stiffness / p;
  if (seg.force_offset_N == 0.0 && x0 == 0.0) {
    return std::pow(energy_gap_J / k_over_p, 1.0 / p);  // closed form
  }
  // g(x) = F_off (x - x0) + K/p (x^p - x0^p) - ΔE is increasing and convex for x >= x0.
  // The power term alone reaching ΔE gives x_b >= root, where g, g' and g'' are known
  // without another pow (x_b^p = ΔE p/K + x0^p): the first Halley step is free. Each
  // further step costs one pow; Halley's cubic convergence means a step below 1e-6 (x - x0)
  // leaves an error of order 1e-18 (x - x0), so that step is the last one. The free step
  // is never the last: its g carries x_b's rounding, p times g's own.
  const double x0_pow_p = x0 > 0.0 ? std::pow(x0, p) : 0.0;
  const double x_b_pow_p = energy_gap_J / k_over_p + x0_pow_p;
  double x = std::pow(x_b_pow_p, 1.0 / p);
  double x_pow_n = x_b_pow_p / x;
  double g = seg.force_offset_N * (x - x0);
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
    if (!(next > x0)) next = x - g / slope;  // Newton stays above x0 from either side
    if (iteration > 0 && !(std::abs(step) > 1e-6 * (x - x0))) return next;
    x = next;
    x_pow_n = std::pow(x, n);
    g = seg.force_offset_N * (x - x0) + k_over_p * (x_pow_n * x - x0_pow_p) - energy_gap_J;
  }
  return x;
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
