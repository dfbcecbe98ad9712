// The exact path of docs/model.md §3: δ_max from energy balance, peaks, and the contact duration
// by a singularity-free Gauss-Legendre quadrature; with contact damping it hands over to
// exact_damped.cpp (docs/model.md §10.1).
#include "covopt/core/exact.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "exact_internal.hpp"
#include "numeric_format.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace covopt {
namespace {

using internal::GaussLegendre;
using internal::PeakSegment;
using internal::SolveEnergyBalance;

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
/// The foam law's pieces (between two points of its curve): U is a cubic there, the integrand
/// smooth, and 8 nodes per piece keep the duration within ~2e-9 of a brute-force quadrature.
constexpr int kFoamQuadratureOrder = 8;

template <int N = kQuadratureOrder>
const MappedRule<N>& Quadrature() {
  static const MappedRule<N> rule{GaussLegendre<N>()};
  return rule;
}

}  // namespace

ImpactPeaks ExactPeaks(const ImpactModel& model) noexcept {
  // The energy integral needs a two-body contact: SolveExact refuses the other scenes.
  assert(model.scene().has_energy_integral());
  if (model.scene().model.damping_s_per_m > 0.0) [[unlikely]] {
    return internal::DampedExactPeaks(model);
  }
  const std::size_t i = PeakSegment(model, model.impact_energy_J());
  const ForceLawSegment& seg = model.segment(i);
  const double delta_max =
      SolveEnergyBalance(seg, model.impact_energy_J() - seg.energy_at_start_J);
  return PeaksAtMaxPenetration(model, i, delta_max);
}

namespace {

/// One piece of the duration quadrature: ∫ 2s ds / v over s in [s_lower, s_upper], where the
/// piece's δ = δ_max − s² runs down from `upper` (s_lower) to its start (s_upper), v² = (2/m)
/// (energy_above + gap_below_upper(gap)) and gap = upper − δ. Adds the piece's energy,
/// U(upper) − U(start), to energy_above.
template <int N = kQuadratureOrder, class GapBelow>
double QuadraturePiece(double s_lower, double s_upper, double upper, double start, double two_over_mass,
                       const GapBelow& energy_below_upper, double& energy_above) noexcept {
  constexpr int kQuadratureOrder = N;
  const auto& rule = Quadrature<N>();
  const double width = s_upper - s_lower;
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
  energy_above += energy_below_upper(upper - start);
  return width * piece;
}

/// The foam segment j's share of the half duration (docs/model.md §16), split at the curve's
/// points, where σ has kinks (U is cubic between them, so each piece is smooth in s).
double FoamHalfDuration(const ImpactModel& model, std::size_t j, double delta_max, double upper,
                        double two_over_mass, double& s_lower, double& energy_above) noexcept {
  const ForceLawSegment& seg = model.segment(j);
  const auto points = seg.curve->points();
  double half_duration = 0.0;
  // The curve's points below `upper`, from the top down; the last piece starts at contact.
  std::size_t k = points.size();
  while (k > 0 && !(points[k - 1].strain * seg.foam_thickness_m < upper)) --k;
  double piece_upper = upper;
  for (;;) {
    const double piece_start = k > 0 ? points[k - 1].strain * seg.foam_thickness_m : seg.start_m;
    const double s_upper = std::sqrt(delta_max - piece_start);
    if (s_upper > s_lower) {
      const ImpactModel::EnergyGapBelow energy_below_upper(model, j, piece_upper);
      half_duration += QuadraturePiece<kFoamQuadratureOrder>(s_lower, s_upper, piece_upper, piece_start,
                                                             two_over_mass, energy_below_upper, energy_above);
    }
    s_lower = std::max(s_lower, s_upper);
    if (k == 0) break;
    piece_upper = piece_start;
    --k;
  }
  return half_duration;
}

}  // namespace

double ExactContactDuration(const ImpactModel& model, const ImpactPeaks& peaks) noexcept {
  // T/2 = ∫₀^δmax dδ / v(δ),  v = sqrt(2 (U(δ_max) - U(δ)) / m).  With δ = δ_max - s²:
  // T/2 = ∫₀^√δmax 2s ds / v(δ_max - s²), smooth at s = 0. Pieces end at the switches
  // s_j = sqrt(δ_max - t_j); each is mapped by s = a + (b - a) φ(u), φ = u²(3 - 2u).
  assert(model.scene().has_energy_integral());
  if (model.scene().model.damping_s_per_m > 0.0) [[unlikely]] {
    const internal::DampedContactTimes times = internal::DampedContactDurations(model, peaks);
    return times.loading_s + times.unloading_s;
  }
  const double delta_max = peaks.max_penetration_m;
  const double two_over_mass = 2.0 / model.effective_mass_kg();
  const std::size_t top = PeakSegment(model, model.impact_energy_J());

  double half_duration = 0.0;
  double s_lower = 0.0;  // piece start in s (toward δ_max)
  // Energy from the top of segment j up to δ_max: U(δ_max) - U(end_j), accumulated downward.
  double energy_above = 0.0;
  for (std::size_t j = top + 1; j-- > 0;) {
    const ForceLawSegment& seg = model.segment(j);
    const double upper = (j == top) ? delta_max : seg.end_m;  // δ at the piece's s_lower
    if (seg.curve) [[unlikely]] {
      half_duration += FoamHalfDuration(model, j, delta_max, upper, two_over_mass, s_lower, energy_above);
      continue;
    }
    const double s_upper = std::sqrt(delta_max - seg.start_m);
    const double width = s_upper - s_lower;
    if (!(width > 0.0)) {
      // δ_max exactly at the top segment's start: an empty piece (its nodes would be 0/0).
      s_lower = s_upper;
      continue;
    }
    const ImpactModel::EnergyGapBelow energy_below_upper(model, j, upper);
    half_duration +=
        QuadraturePiece(s_lower, s_upper, upper, seg.start_m, two_over_mass, energy_below_upper, energy_above);
    s_lower = s_upper;
  }
  return 2.0 * half_duration;
}

void internal::CheckExactPathApplies(const Scene& scene) {
  if (scene.has_energy_integral()) return;
  constexpr const char* kWhy =
      "the exact path needs the energy integral of a two-body contact (conservative or with "
      "contact damping): ";
  constexpr const char* kOnlyTimePath =
      " needs the time path (a scene with braking or a neck has only the time path)";
  if (scene.robot_brakes()) {
    throw std::invalid_argument(std::string(kWhy) + "robot.braking (" +
                                internal::FormatNumber(scene.robot.braking_m_per_s2) + " m/s2)" +
                                kOnlyTimePath);
  }
  throw std::invalid_argument(std::string(kWhy) + "a neck (head.torso_mass " +
                              internal::FormatNumber(scene.head.torso_mass_kg) + " kg)" +
                              kOnlyTimePath);
}

ImpactResult SolveExact(const ImpactModel& model, const ExactOptions& options) {
  internal::CheckExactPathApplies(model.scene());
  ImpactResult result;
  result.method = ComputationMethod::kExact;
  result.peaks = ExactPeaks(model);
  const double impact_speed = model.impact_speed_m_per_s();
  if (model.scene().is_damped()) {
    // Hunt-Crossley damping (docs/model.md §10.1): the loading and the unloading differ.
    if (options.compute_duration) {
      const internal::DampedContactTimes times =
          internal::DampedContactDurations(model, result.peaks);
      result.contact_duration_s = times.loading_s + times.unloading_s;
      result.time_of_max_compression_s = times.loading_s;
    }
    result.rebound_speed_m_per_s = internal::DampedReboundSpeed(model);
  } else {
    if (options.compute_duration) {
      result.contact_duration_s = ExactContactDuration(model, result.peaks);
      result.time_of_max_compression_s = 0.5 * *result.contact_duration_s;
    }
    // No dissipation: the bodies separate at the impact speed (docs/model.md §2).
    result.rebound_speed_m_per_s = impact_speed;
  }
  result.coefficient_of_restitution = *result.rebound_speed_m_per_s / impact_speed;
  for (ValidityWarning& warning : CheckValidity(model, result.peaks)) {
    result.AddWarning(warning.code, std::move(warning.message));
  }
  result.validity = CoveringLawValidity(model, result.peaks);
  return result;
}

}  // namespace covopt
