#pragma once
// Private: the time path of the body-contact model (covopt/core/body_contact.hpp), which
// Solve(BodyContactModel) calls for PathChoice::kTimePath and for a history.
#include "covopt/core/body_contact.hpp"
#include "covopt/core/solve.hpp"

namespace covopt::internal {

/// Integrates mu δ'' = -F with the covering (Hertz, K_c) and the body spring k_H in series,
/// by SUNDIALS (options.time_path: method, tolerances, max_steps), without inverting F(δ):
///   phase 1 (the covering not bottomed out): q = δ_c,  q' = δ' / (1 + 1.5 K_c sqrt(q)/k_H),
///            (δ')' = -K_c q^1.5 / mu;
///   phase 2 (bottomed out at q = travel, or the bare robot): q = δ_b,  q' = δ',
///            (δ')' = -k_H q / mu,
/// with events at the phase switch (both ways: restart), maximum compression (δ' = 0: the
/// peaks) and separation (δ = 0: duration and rebound speed). With options.record_history,
/// (t, δ, δ', F) at every step and event, and by dense output at least
/// options.history_samples_per_contact samples over the contact. Failures (step limit,
/// integrator errors, an event not located) come back as the result's status and message,
/// with no peaks. `options` are validated by the caller (Solve).
BodyContactResult SolveBodyContactTimePath(const BodyContactModel& model, const SolveOptions& options);

}  // namespace covopt::internal
