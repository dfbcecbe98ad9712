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
///
/// With Hunt-Crossley contact damping d > 0 (Scene::model.damping_s_per_m, docs/model.md
/// §10.1) the contact force is F_el(δ)(1 + d δ') and the speed v = δ' on either branch obeys
///
///     m (d v - ln(1 + d v)) / d² = U(δ_max) - U(δ),   v >= 0 loading, v <= 0 unloading,
///
/// so δ_max solves U(δ_max) = m (d v0 - ln(1 + d v0)) / d² with the same solver, F_max and
/// σ_c,max are maximised over the loading branch, e_A,max and the duration are quadratures and
/// the rebound speed is closed-form. A few µs per impact; the conservative scene's code and
/// cost are unchanged (one branch on d > 0).
///
/// A braking robot or a neck (Scene::robot_brakes(), HeadSpec::has_neck()) leaves no energy
/// integral: such a scene has only the time path. SolveExact refuses it; ExactPeaks and
/// ExactContactDuration must not be given one (they assert it in debug builds).

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"

namespace covopt {

/// Peaks only: δ_max, F_max, σ_c,max, σ_t,max, e_A,max (F and σ as their largest values over
/// the loading branch, see ImpactPeaks). About 0.1 µs, a few µs with contact damping;
/// allocation-free. Unchecked: not for a scene with braking or a neck (see SolveExact).
ImpactPeaks ExactPeaks(const ImpactModel& model) noexcept;

/// Contact duration T [s] for peaks previously computed by ExactPeaks(model): loading and
/// unloading, which differ with contact damping. Unchecked, as ExactPeaks.
double ExactContactDuration(const ImpactModel& model, const ImpactPeaks& peaks) noexcept;

/// Options of the exact path.
struct ExactOptions {
  /// Also compute the contact duration (a quadrature; a few µs). Default: true.
  bool compute_duration = true;
};

/// The full exact result: peaks, duration and time of maximum compression (if asked), rebound
/// speed and coefficient of restitution (v0 and 1 without damping), validity warnings.
/// @throws std::invalid_argument for a scene with braking or a neck, naming the input: the
///         exact path needs the energy integral of a two-body contact; use the time path.
ImpactResult SolveExact(const ImpactModel& model, const ExactOptions& options = {});

}  // namespace covopt
