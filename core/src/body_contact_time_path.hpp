#pragma once
// Private: the time path of the body-region contact (docs/model.md §13), and the peaks of a
// contact at a given peak force, shared by both paths.
#include "covopt/core/body_contact.hpp"
#include "covopt/core/solve.hpp"

namespace covopt::internal {

/// Every peak quantity of `model`'s contact when its peak force is `force_N` [N] (status,
/// method, duration and rebound speed are left for the caller).
BodyContactResult PeaksAtForce(const BodyContactModel& model, double force_N);

/// The covering's law, resolved: kAuto -> kFoam with a compressive curve, else kHertz.
/// @throws std::invalid_argument for kFoam without a curve ("covering.law: ...").
CoveringLaw ResolveCoveringLaw(const CoveringSpec& covering);

/// A foam layer's peaks (body_contact_foam.cpp) when the springs hold `energy_J` [J]: below the
/// bottoming out at the root d of the energy balance, past it at the stop with the body
/// spring's force from the energy left (status, method, duration and rebound speed are left
/// for the caller).
BodyContactResult FoamPeaksAtEnergy(const BodyContactModel& model, double energy_J);
/// A foam layer's peaks at its state (within the curve), or used up at the stop with the state's
/// force (>= F(d_end)).
BodyContactResult FoamPeaksAt(const BodyContactModel& model, const BodyContactModel::FoamState& state, bool used_up);
/// The state at compression `deflection_m` (d_end when `used_up`) with force `force_N`: the
/// time path's reading of its state.
BodyContactModel::FoamState FoamStateAt(const BodyContactModel& model, double deflection_m, double force_N,
                                        bool used_up);
/// Fills the covering's law, validity, peak strain and energy past the stop of `r` from its
/// peaks (both laws, both paths); nothing bare.
void FinishCoveringFields(const BodyContactModel& model, BodyContactResult& r) noexcept;
/// A foam result's validity (docs/model.md §15.5).
CoveringValidity FoamValidity(const BodyContactModel& model, const BodyContactResult& r) noexcept;

/// Integrates mu δ'' = -F with the covering (Hertz, K_c) and the body spring k_H in series,
/// by SUNDIALS (options.time_path: method, tolerances, max_steps), without inverting F(δ):
///   phase 1 (the covering not bottomed out): q = δ_c,  q' = δ' / (1 + 1.5 K_c sqrt(q)/k_H),
///            (δ')' = -K_c q^1.5 / mu;
///   phase 2 (bottomed out at q = 0.8 b_c, or the bare robot): q = δ_b,  q' = δ',
///            (δ')' = -k_H q / mu,
/// with events at the phase switch (both ways: a restart), maximum compression (δ' = 0: the
/// peaks, read from the state) and separation (δ = 0: duration and rebound speed). A braking
/// robot (docs/model.md §13.10) adds -a to (δ')' while the brake is on, and integrates its own
/// speed, v_R' = -F/m_R - a, and the brake's work, W' = m_R a v_R; the brake starts at
/// t = t_d (an event, a restart) if the robot still moves forward and stops when v_R falls
/// through 0 (an event, a restart). With
/// options.record_history, (t, δ, δ', F, v_R, W) at every step and event and, by dense output, at
/// least options.history_samples_per_contact samples over the contact. Failures (step limit,
/// integrator errors, an event not located) come back as the result's status and message,
/// with no peaks. `options` are validated by the caller (Solve). `to_peak`: stop at maximum
/// compression (SolveBodyContactPeaks: no duration, no rebound speed).
BodyContactResult SolveBodyContactTimePath(const BodyContactModel& model, const SolveOptions& options,
                                           bool to_peak = false);

}  // namespace covopt::internal
