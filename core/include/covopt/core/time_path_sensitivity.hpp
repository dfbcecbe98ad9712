#pragma once
/// @file time_path_sensitivity.hpp
/// Design derivatives of the peaks from the time path: CVODES forward sensitivities of the
/// loading branch (docs/model.md §10.4), the time path's counterpart of ExactPeakSensitivities.
///
/// The state y = (δ, δ', e) obeys, inside force-law segment j (cumulative or literal
/// thresholds, with Hunt–Crossley damping d >= 0, h = 1 + d δ'),
///
///     δ'' = -F_j(δ; θ) h / m        e' = σ_j(δ; θ) h δ'
///
/// and its sensitivity s = dy/dθ (θ = E_c or b_c, integrated as d/d ln θ so that s has the
/// state's scale) obeys s' = (∂f/∂y) s + ∂f/∂θ with the analytic partials of the force law
/// at fixed δ (the exact path's segment derivatives, sensitivity.cpp). The energy density's
/// sensitivity is integrated as w = s_e - σ_j(δ) h s_δ, whose equation
///
///     w' = σ_j d (δ' s_v - δ'' s_δ) + (∂σ_j/∂θ)|δ h δ'
///
/// has no dσ/dδ term: σ's slope is unbounded at the start of a phase (x^(n-2), n < 2), and it
/// cancels exactly. Events, each with its correction:
///  - a phase switch δ = t_j(θ) (stop, restart): s⁺ = s⁻ + (f⁻ - f⁺) dτ/dθ with
///    dτ/dθ = -(s_δ - dt_j/dθ)/δ'. With the default cumulative thresholds f is continuous
///    there (f⁻ = f⁺: no jump, though t2 moves with b_c); the literal reading's force and
///    stress jumps are corrected by the formula.
///  - maximum compression δ' = 0 (the end of the integration): dδ_max/dθ = s_δ(t*) and
///    de_A/dθ = s_e(t*) (δ_max's time moves, but δ' = e' = 0 there).
///  - F_max and σ_c,max are the largest of the candidates over the loading branch: the law at
///    δ_max, at each switch passed (its left value, whose derivative includes the switch's
///    motion), and with damping the interior maxima where dF/dt = 0 (dσ/dt = 0), located by
///    root functions; at an interior maximum the time's motion drops out (envelope theorem).
///
/// Integrated by CVODES Adams–Moulton with fixed-point iteration, the sensitivities in the
/// local error test (staggered corrector), at the options' rtol and the time path's scaled
/// absolute tolerances, whatever integrator the options name: sensitivities are a CVODES
/// feature. Defined for the two-mass contact (conservative or damped) with a covering; a
/// braking robot or a neck is outside this system (optim uses a central difference there).

#include <string>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/sensitivity.hpp"
#include "covopt/core/time_integration.hpp"

namespace covopt {

/// The peaks of one impact and their design derivatives, from the time path.
struct TimePathSensitivities {
  SolveStatus status = SolveStatus::kSuccess;
  /// What failed, with CVODES' own messages; empty on success.
  std::string message;
  int raw_code = 0;  ///< CVODES' return flag on failure
  /// The peaks of this integration (δ_max, F_max, σ_c,max, σ_t,max, e_A,max and the phase
  /// flags); the contact duration is not computed (the integration stops at δ_max).
  ImpactPeaks peaks;
  /// d/dE_c [per Pa] and d/db_c [per m] of the peaks.
  PeakSensitivities sensitivities;
  SolverStatistics statistics;  ///< steps, right-hand sides (state and sensitivities), roots
  bool ok() const noexcept { return status == SolveStatus::kSuccess; }
};

/// The peaks and their derivatives with respect to the covering's modulus and thickness, by
/// CVODES forward sensitivities at options.relative_tolerance (and absolute_tolerance,
/// max_steps; method, restarts and history are not used: CVODES Adams, restarting at every
/// switch). Failures come back as a status.
/// @throws std::invalid_argument if the model has no covering, or the scene has a braking
///         robot or a neck, or an option is out of range.
TimePathSensitivities TimePathPeakSensitivities(const ImpactModel& model,
                                                const TimeIntegrationOptions& options = {});

}  // namespace covopt
