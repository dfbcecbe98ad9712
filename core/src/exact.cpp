// The exact path of docs/model.md §3: δ_max from energy balance, peaks, and the contact duration
// by a singularity-free Gauss-Legendre quadrature.
#include "covopt/core/exact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace covopt {
namespace {

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

/// The duration quadrature's fixed factors per node: the map φ(u) = u²(3 - 2u) at the
/// Gauss-Legendre nodes and 2 w φ'(u), computed once, the same arithmetic as per call.
template <int N>
struct MappedRule {
  std::array<double, N> phi{};
  std::array<double, N> two_weight_dphi{};
  explicit MappedRule(const GaussLegendre<N>& rule) {
    for (int q = 0; q < N; ++q) {
      const double u = rule.node[q];
      phi[q] = u * u * (3.0 - 2.0 * u);
      const double dphi = 6.0 * u * (1.0 - u);
      two_weight_dphi[q] = rule.weight[q] * dphi * 2.0;
    }
  }
};

constexpr int kQuadratureOrder = 20;

const MappedRule<kQuadratureOrder>& Quadrature() {
  static const MappedRule<kQuadratureOrder> rule{GaussLegendre<kQuadratureOrder>()};
  return rule;
}

/// Index of the segment containing δ_max: the last one whose start energy is below ½ m v0².
std::size_t PeakSegment(const ImpactModel& model) noexcept {
  std::size_t i = model.segment_count() - 1;
  while (i > 0 && !(model.segment(i).energy_at_start_J < model.impact_energy_J())) --i;
  return i;
}

/// Phase-local penetration x solving U = ½ m v0² inside segment `seg`.
double SolveEnergyBalance(const ForceLawSegment& seg, double energy_gap_J) noexcept {
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

}  // namespace

ImpactPeaks ExactPeaks(const ImpactModel& model) noexcept {
  const std::size_t i = PeakSegment(model);
  const ForceLawSegment& seg = model.segment(i);
  const double x = SolveEnergyBalance(seg, model.impact_energy_J() - seg.energy_at_start_J);
  return PeaksAtMaxPenetration(model, i, seg.origin_m + x);
}

double ExactContactDuration(const ImpactModel& model, const ImpactPeaks& peaks) noexcept {
  // T/2 = ∫₀^δmax dδ / v(δ),  v = sqrt(2 (U(δ_max) - U(δ)) / m).  With δ = δ_max - s²:
  // T/2 = ∫₀^√δmax 2s ds / v(δ_max - s²), smooth at s = 0. Pieces end at the switches
  // s_j = sqrt(δ_max - t_j); each is mapped by s = a + (b - a) φ(u), φ = u²(3 - 2u).
  const double delta_max = peaks.max_penetration_m;
  const double two_over_mass = 2.0 / model.effective_mass_kg();
  const std::size_t top = PeakSegment(model);
  const auto& rule = Quadrature();

  double half_duration = 0.0;
  double s_lower = 0.0;  // piece start in s (toward δ_max)
  // Energy from the top of segment j up to δ_max: U(δ_max) - U(end_j), accumulated downward.
  double energy_above = 0.0;
  for (std::size_t j = top + 1; j-- > 0;) {
    const ForceLawSegment& seg = model.segment(j);
    const double upper = (j == top) ? delta_max : seg.end_m;  // δ at the piece's s_lower
    const double s_upper = std::sqrt(delta_max - seg.start_m);
    const double width = s_upper - s_lower;
    const ImpactModel::EnergyGapBelow energy_below_upper(model, j, upper);
    // The energies first (one call each), then the square roots and divisions in a loop
    // of their own; the sum keeps its order.
    std::array<double, kQuadratureOrder> numerator;
    std::array<double, kQuadratureOrder> energy_gap;
    for (int q = 0; q < kQuadratureOrder; ++q) {
      const double s = s_lower + width * rule.phi[q];
      // Gap below `upper`: δ_max - s² = upper - gap.
      const double gap = (s - s_lower) * (s + s_lower);
      energy_gap[q] = energy_above + energy_below_upper(gap);
      numerator[q] = rule.two_weight_dphi[q] * s;
    }
    std::array<double, kQuadratureOrder> term;
#if defined(__SSE2__)
    // Two nodes per instruction (std::sqrt's errno check keeps the compiler from doing it);
    // IEEE square root and division round the same in both forms.
    static_assert(kQuadratureOrder % 2 == 0);
    const __m128d scale = _mm_set1_pd(two_over_mass);
    for (int q = 0; q < kQuadratureOrder; q += 2) {
      const __m128d speed = _mm_sqrt_pd(_mm_mul_pd(scale, _mm_loadu_pd(&energy_gap[q])));
      _mm_storeu_pd(&term[q], _mm_div_pd(_mm_loadu_pd(&numerator[q]), speed));
    }
#else
    for (int q = 0; q < kQuadratureOrder; ++q) {
      term[q] = numerator[q] / std::sqrt(two_over_mass * energy_gap[q]);
    }
#endif
    double piece = 0.0;
    for (int q = 0; q < kQuadratureOrder; ++q) piece += term[q];
    half_duration += width * piece;
    energy_above += energy_below_upper(upper - seg.start_m);
    s_lower = s_upper;
  }
  return 2.0 * half_duration;
}

ImpactResult SolveExact(const ImpactModel& model, const ExactOptions& options) {
  ImpactResult result;
  result.method = ComputationMethod::kExact;
  result.peaks = ExactPeaks(model);
  if (options.compute_duration) {
    result.contact_duration_s = ExactContactDuration(model, result.peaks);
    result.time_of_max_compression_s = 0.5 * *result.contact_duration_s;
  }
  // No dissipation: the bodies separate at the impact speed (docs/model.md §2).
  result.rebound_speed_m_per_s = model.impact_speed_m_per_s();
  for (ValidityWarning& warning : CheckValidity(model, result.peaks)) {
    result.AddWarning(warning.code, std::move(warning.message));
  }
  return result;
}

}  // namespace covopt
