#pragma once
/// @file time_integration.hpp
/// The time path (docs/model.md §3): SUNDIALS integration (CVODE or ARKODE) of the impact with
/// events.
///
/// State y = (δ, δ', e) with δ'' = -F(δ)/m and e' = σ_c(δ) δ', from δ = 0, δ' = v0.
/// Root functions stop the integrator at every phase switch (δ = t1, t2, both ways), where
/// it is re-initialised (CVodeReInit / ERKStepReInit) because the force is only C⁰ there; at maximum
/// compression (δ' = 0 going down: δ_max, e_A,max, time of the peak; F_max and σ_c,max as
/// the largest over the loading branch, PeaksAtMaxPenetration); and at separation
/// (δ = 0 going down: duration and rebound speed). Where a phase's law starts at its own
/// x = 0 (x^n, singular derivatives), the first stretch upward is taken from the phase's
/// series solution, and unloading stops where that stretch ended and reaches x = 0 on the
/// same series run backwards (exit speed from the energy of the law). Inside a phase the right-hand side uses
/// that phase's formula continued past its ends with the phase-local penetration clamped
/// at 0, so an overshooting step never takes the pow of a negative base.
///
/// Scenes beyond the conservative two-mass model (Scene::is_conservative_two_mass() false:
/// contact damping, a braking robot, a head on a neck; docs/model.md §10.2, §10.3) take the
/// extended time path: robot, head and torso as bodies along the impact axis, the state
///     (δ, δ', v_b, x_b - x_t, ẋ_b - ẋ_t, e, W)
/// with the head speed v_b, the neck's stretch and rate, the energy density e and the work W
/// of the dampers, the brake and a fixed robot's support. Events: the phase switches (both
/// ways), the brake's start t = t_d, the robot stopping while it brakes, the damping force
/// reaching 0 (1 + d δ' = 0), each restarting the integrator; every maximum of δ (δ_max is the
/// largest); with damping the maxima of F and σ_c in time; separation, the first return to
/// δ = 0. No series openings there: the integrator takes the phase starts itself.
///
/// The integrators' memory, vectors and linear solvers live in a TimeIntegrator and are
/// reused across runs (ARKODE's memory is created anew for each run: its re-initialisation
/// keeps root-finding state). A run's output, solver counters included, does not depend on
/// what ran before on the same TimeIntegrator. A TimeIntegrator is not thread-safe: give each thread its own (or call
/// SimulateImpact, which keeps one per thread). SUNDIALS' messages are captured into
/// ImpactResult::message, never printed.

#include <memory>
#include <string_view>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"

namespace covopt {

/// Options of the time path. Defaults deliver peaks and duration within 1e-6 relative of
/// the exact path on the test scenes (tests/core/test_paths_agree.cpp).
struct TimeIntegrationOptions {
  /// The integrator (any ComputationMethod but kExact). Default: ARKODE's explicit
  /// Dormand-Prince 5(4). The problem is not stiff, and with the restarts and the series
  /// opening of each phase it is the fastest for a given accuracy on every scene measured,
  /// about half the time of CVODE Adams (docs/numerics.md, `covopt workprecision`).
  ComputationMethod method = ComputationMethod::kArkodeErk54;
  /// Relative tolerance of the integrator's local error test [-], in [1e-14, 1e-2].
  double relative_tolerance = 1e-8;
  /// Absolute tolerance [-], in (0, 1e-2], made dimensional per component by the scene's
  /// natural scales: δ by L = the phase-1 Hertz penetration estimate, δ' by v0, e by the
  /// matching energy density. Default: relative_tolerance.
  double absolute_tolerance = 0.0;
  /// Re-initialise at every phase switch (true, the correct way). False integrates
  /// straight through the C⁰ kinks with the full piecewise law, for the numerics study.
  bool restart_at_phase_switches = true;
  /// Record every internal step (and each event) into ImpactResult::history.
  bool record_history = false;
  /// With record_history: also insert samples interpolated by the integrator's dense
  /// output (CVodeGetDky, ERKStepGetDky) so that no two samples are further apart than this [s]; 0 = internal
  /// steps and events only. Smooth charts without tightening the tolerance.
  double history_max_interval_s = 0.0;
  /// Give up after this many internal steps in total (SolveStatus::kStepLimit), >= 10.
  long max_steps = 200000;
  /// Run the extended time path (bodies, damping, braking, neck; see the file comment) even
  /// on a conservative two-mass scene, which the δ-only path answers otherwise: for checking
  /// one path against the other. Scenes with damping, braking or a neck always take it.
  bool force_extended_dynamics = false;
};

/// Checks every field of `options`: a time integrator as method, relative_tolerance in
/// [1e-14, 1e-2], absolute_tolerance in (0, 1e-2] or 0, history_max_interval_s finite and
/// >= 0 s, max_steps >= 10. The one check of these options, behind the time path, the sweep,
/// the sensitivities and optim's oracles.
/// @throws std::invalid_argument naming the field (after `prefix`, e.g. "time_path."), the
///         value and the allowed range: "time_path.relative_tolerance must be in [1e-14, 1e-2]
///         (got 0)".
void ValidateTimeIntegrationOptions(const TimeIntegrationOptions& options,
                                    std::string_view prefix = "");

/// Reusable SUNDIALS workspace (one integrator per method, created on first use).
class TimeIntegrator {
 public:
  TimeIntegrator();
  ~TimeIntegrator();
  TimeIntegrator(TimeIntegrator&&) noexcept;
  TimeIntegrator& operator=(TimeIntegrator&&) noexcept;
  TimeIntegrator(const TimeIntegrator&) = delete;
  TimeIntegrator& operator=(const TimeIntegrator&) = delete;

  /// Integrates one impact: the δ-only path for a conservative two-mass scene, the extended
  /// path otherwise (or with force_extended_dynamics). Failures come back as a status with the
  /// integrator's message; a contact that does not end within the extended path's time bound
  /// (docs/model.md §10.2) is SolveStatus::kNoSeparation.
  /// @throws std::invalid_argument if an option is out of range (naming it).
  ImpactResult Simulate(const ImpactModel& model, const TimeIntegrationOptions& options = {});

 private:
  struct Workspace;
  std::unique_ptr<Workspace> workspace_;
};

/// Integrates one impact with a per-thread TimeIntegrator.
ImpactResult SimulateImpact(const ImpactModel& model, const TimeIntegrationOptions& options = {});

}  // namespace covopt
