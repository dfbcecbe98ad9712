#pragma once
// Private: one SUNDIALS integrator (CVODE or ARKODE's ARKStep) behind the few calls the
// event loop of time_integration.cpp needs. Both packages share their return-code
// conventions (0 success, 2 root found, negative failure; -1 too much work).
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include <array>
#include <memory>
#include <span>
#include <string>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"

namespace covopt::internal {

inline constexpr int kRootCount = 3;
inline constexpr int kRootUpperSwitch = 0;  // δ - end of the current segment, crossing upward
inline constexpr int kRootLowerSwitch = 1;  // δ - start of the current segment, crossing downward
inline constexpr int kRootTurn = 2;         // δ' = 0 going down: maximum compression
inline constexpr long kWholeLaw = -1;       // segment index meaning "the full piecewise law"
inline constexpr int kStepTaken = 0;        // CV_SUCCESS == ARK_SUCCESS
inline constexpr int kRootFound = 2;        // CV_ROOT_RETURN == ARK_ROOT_RETURN
inline constexpr int kTooMuchWork = -1;     // CV_TOO_MUCH_WORK == ARK_TOO_MUCH_WORK
/// Crossing directions of the three root functions above (+1 rising, -1 falling).
inline constexpr std::array<int, kRootCount> kRootDirections{+1, -1, -1};

/// What the C callbacks see: the model and where the integration is.
struct RunState {
  const ImpactModel* model = nullptr;
  long segment = 0;  // index into the law, or kWholeLaw when not restarting at switches
  double inverse_mass = 0.0;
  /// Per segment, the phase-local penetration [m] at which unloading stops for the series
  /// closing of the phase (time_integration.cpp, ClosePhase); 0: none, down to the start.
  std::array<double, 3> closing_m{};
};

// The callbacks' C signatures, the same in CVODE and ARKODE (CVRhsFn == ARKRhsFn, ...).
using RhsFunction = int (*)(sunrealtype t, N_Vector y, N_Vector ydot, void* user_data);
using RootFunction = int (*)(sunrealtype t, N_Vector y, sunrealtype* g, void* user_data);
using JacobianFunction = int (*)(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix jac,
                                 void* user_data, N_Vector, N_Vector, N_Vector);

// The conservative path's callbacks, shared by every integrator (time_integration.cpp).
int RightHandSide(sunrealtype t, N_Vector y, N_Vector ydot, void* user_data);
int RootFunctions(sunrealtype t, N_Vector y, sunrealtype* g, void* user_data);
int Jacobian(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix jac, void* user_data, N_Vector,
             N_Vector, N_Vector);
void CaptureMessage(int error_code, const char* module, const char* function, char* message,
                    void* user_data);

/// One configured integrator. Created once per method and workspace, re-initialised for every
/// run and at every phase switch.
class Stepper {
 public:
  virtual ~Stepper() = default;
  /// Start a new run at (t0, y0) in the state of a newly created integrator, so that a run's
  /// results and counters never depend on what ran before on this stepper. CVODE: CVodeReInit
  /// resets everything. ARKODE (6.4): ERKStepReInit/ARKStepReInit keep the root-finding flag
  /// "a root was returned at the last call" (irfnd), so after a run that ended on a root
  /// (separation) every step of the next interval re-checks that root: one more root-function
  /// evaluation and one more right-hand side per step than on a fresh integrator (measured:
  /// ERK 5(4) on the paper scene at 3 m/s, 493 against 489 right-hand sides, peaks equal).
  /// ARKODE's memory is therefore created anew for every run (about 2 us of a 37 us run of
  /// ERK 5(4) on the paper scene); the DIRK methods keep their matrix and linear solver.
  virtual int BeginRun(double t0, N_Vector y0) = 0;
  /// Restart at (t0, y0) inside a run (at an event) with the same right-hand side; the step
  /// history is dropped.
  virtual int ReInit(double t0, N_Vector y0) = 0;
  virtual int SetTolerances(double relative, N_Vector absolute) = 0;
  /// First step of the next integration interval; 0 lets the integrator estimate it.
  virtual int SetInitStep(double step) = 0;
  /// One internal step towards tout (one-step mode); y and t receive the new state.
  virtual int Step(double tout, N_Vector y, double* t) = 0;
  virtual void RootInfo(int* found) = 0;
  /// The dense-output state at time t inside the last step.
  virtual int Interpolate(double t, N_Vector out) = 0;
  /// Adds this interval's counters (they are reset by ReInit).
  virtual void AddStatistics(SolverStatistics& stats) = 0;
  virtual std::string FlagName(int flag) = 0;
  /// A first step [s] for a re-entry into a region this stepper already crossed with steps of
  /// `step` [s]: a one-step method can take such a step at once; 0 where the integrator
  /// should estimate its own (CVODE restarts at order 1).
  virtual double ReentryStep(double step) { return step; }
  /// |size| of the last step taken [s].
  virtual double LastStep() = 0;
};

/// "NAME (flag)" from a return-flag name SUNDIALS malloc'ed (freed here; null: unknown).
std::string TakeFlagName(char* malloced_name, int flag);

/// Shared SUNDIALS objects a stepper is built on, and the problem it integrates. The problem
/// defaults to the conservative path's (δ, δ', e) with its three root functions; the extended
/// time path (extended_time_path.cpp) passes its own callbacks and a longer vector.
struct StepperResources {
  SUNContext context = nullptr;
  N_Vector state = nullptr;  // template for the integrator's vectors; its length is the problem's
  void* user_data = nullptr;  // what the callbacks receive (a RunState for the defaults)
  std::string* log = nullptr;
  RhsFunction rhs = RightHandSide;
  RootFunction roots = RootFunctions;
  /// One crossing direction per root function; its size is the number of root functions.
  std::span<const int> root_directions = kRootDirections;
  /// The Jacobian for the implicit methods; null: SUNDIALS' difference quotients.
  JacobianFunction jacobian = Jacobian;
  /// The implicit methods evaluate the Jacobian at every setup of Newton's matrix instead of
  /// SUNDIALS' default of once per 51 steps. For a Jacobian that is far off where it was last
  /// evaluated: the body-region path's phase 1 is singular at first contact (d δ_c'/d δ_c
  /// unbounded), and a Jacobian from there, kept for the whole contact, made Newton's
  /// corrections vanish and its "converged" stages the predictor's (docs/numerics.md).
  bool jacobian_at_every_setup = false;
};

std::unique_ptr<Stepper> MakeCvodeStepper(ComputationMethod method, const StepperResources& r);
std::unique_ptr<Stepper> MakeArkodeStepper(ComputationMethod method, const StepperResources& r);

}  // namespace covopt::internal
