#pragma once
/// @file exact.hpp
/// The exact path (docs/model.md §3): peaks from energy balance, duration by quadrature.
///
/// U(δ) is analytic and strictly increasing, so δ_max solves U(δ_max) = ½ m v0²: locate the
/// segment from U at the switches, then solve inside it (closed form in a segment without a
/// linear term, otherwise a Newton iteration from an upper bound, which converges
/// monotonically because U is convex in the phase-local penetration). The contact duration
///
///     T = 2 ∫₀^δmax dδ / sqrt(2 (U(δ_max) - U(δ)) / m)
///
/// is integrated in s with δ = δ_max - s², which removes the 1/sqrt singularity at δ_max,
/// split at the phase switches, each piece mapped by a smoothstep so that the algebraic
/// endpoint behaviour of the Hertz terms does not limit Gauss-Legendre's accuracy; the
/// energy gap is evaluated without cancellation (ImpactModel::EnergyDifferenceInSegment).

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"

namespace covopt {

/// Peaks only: δ_max, F_max, σ_c,max, σ_t,max, e_A,max (F and σ as their largest values over
/// the loading branch, see ImpactPeaks). About 0.1 µs; allocation-free.
ImpactPeaks ExactPeaks(const ImpactModel& model) noexcept;

/// Contact duration T [s] for peaks previously computed by ExactPeaks(model).
double ExactContactDuration(const ImpactModel& model, const ImpactPeaks& peaks) noexcept;

/// Options of the exact path.
struct ExactOptions {
  /// Also compute the contact duration (a quadrature; a few µs). Default: true.
  bool compute_duration = true;
};

/// The full exact result: peaks, duration (if asked), rebound speed, validity warnings.
ImpactResult SolveExact(const ImpactModel& model, const ExactOptions& options = {});

}  // namespace covopt
