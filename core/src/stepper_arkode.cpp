// ARKODE: explicit RK tables with ERKStep (the lean explicit module), diagonally implicit RK
// with ARKStep and Newton on the analytic Jacobian.
#include <arkode/arkode_arkstep.h>
#include <arkode/arkode_erkstep.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "stepper.hpp"

namespace covopt::internal {
namespace {

bool IsImplicit(ComputationMethod method) {
  return method == ComputationMethod::kArkodeSdirk43 || method == ComputationMethod::kArkodeEsdirk54;
}

ARKODE_ERKTableID ExplicitTable(ComputationMethod method) {
  switch (method) {
    case ComputationMethod::kArkodeErk32: return ARKODE_BOGACKI_SHAMPINE_4_2_3;
    case ComputationMethod::kArkodeErk54: return ARKODE_DORMAND_PRINCE_7_4_5;
    case ComputationMethod::kArkodeErk65: return ARKODE_VERNER_8_5_6;
    case ComputationMethod::kArkodeErk87: return ARKODE_FEHLBERG_13_7_8;
    default: return ARKODE_ERK_NONE;
  }
}

ARKODE_DIRKTableID ImplicitTable(ComputationMethod method) {
  switch (method) {
    case ComputationMethod::kArkodeSdirk43: return ARKODE_SDIRK_5_3_4;
    case ComputationMethod::kArkodeEsdirk54: return ARKODE_ARK548L2SA_DIRK_8_4_5;
    default: return ARKODE_DIRK_NONE;
  }
}

/// A diagonally implicit table on ARKStep (the right-hand side is all implicit), Newton on
/// the analytic Jacobian.
class DirkStepper final : public Stepper {
 public:
  DirkStepper(ComputationMethod method, const StepperResources& r)
      : table_(ImplicitTable(method)), resources_(r),
        root_directions_(r.root_directions.begin(), r.root_directions.end()) {
    resources_.root_directions = root_directions_;  // this stepper's own copy
    const sunindextype size = N_VGetLength(r.state);
    matrix_ = SUNDenseMatrix(size, size, r.context);
    linear_solver_ = SUNLinSol_Dense(r.state, matrix_, r.context);
    if (!matrix_ || !linear_solver_) {
      Release();
      throw std::runtime_error("SUNDenseMatrix/SUNLinSol_Dense failed");
    }
    N_VConst(0.0, r.state);
    if (Create(0.0, r.state) != ARK_SUCCESS) {
      Release();
      throw std::runtime_error("ARKStepCreate failed: " + *r.log);
    }
  }
  ~DirkStepper() override { Release(); }
  DirkStepper(const DirkStepper&) = delete;
  DirkStepper& operator=(const DirkStepper&) = delete;

  int BeginRun(double t0, N_Vector y0) override {
    ARKStepFree(&mem_);
    return Create(t0, y0);
  }
  int ReInit(double t0, N_Vector y0) override {
    return ARKStepReInit(mem_, nullptr, resources_.rhs, t0, y0);
  }
  int SetTolerances(double relative, N_Vector absolute) override {
    return ARKStepSVtolerances(mem_, relative, absolute);
  }
  int SetInitStep(double step) override { return ARKStepSetInitStep(mem_, step); }
  int Step(double tout, N_Vector y, double* t) override {
    return ARKStepEvolve(mem_, tout, y, t, ARK_ONE_STEP);
  }
  void RootInfo(int* found) override { ARKStepGetRootInfo(mem_, found); }
  int Interpolate(double t, N_Vector out) override { return ARKStepGetDky(mem_, t, 0, out); }
  void AddStatistics(SolverStatistics& stats) override {
    long steps = 0, fe = 0, fi = 0, roots = 0, error_fails = 0;
    ARKStepGetNumSteps(mem_, &steps);
    ARKStepGetNumRhsEvals(mem_, &fe, &fi);
    ARKStepGetNumGEvals(mem_, &roots);
    ARKStepGetNumErrTestFails(mem_, &error_fails);
    stats.steps += steps;
    stats.rhs_evaluations += fe + fi;
    stats.root_evaluations += roots;
    stats.error_test_failures += error_fails;
    long iterations = 0, convergence_fails = 0, jacobians = 0, ls_rhs = 0;
    ARKStepGetNumNonlinSolvIters(mem_, &iterations);
    ARKStepGetNumNonlinSolvConvFails(mem_, &convergence_fails);
    ARKStepGetNumJacEvals(mem_, &jacobians);
    ARKStepGetNumLinRhsEvals(mem_, &ls_rhs);
    stats.nonlinear_iterations += iterations;
    stats.convergence_failures += convergence_fails;
    stats.jacobian_evaluations += jacobians;
    stats.rhs_evaluations += ls_rhs;
  }
  std::string FlagName(int flag) override { return TakeFlagName(ARKStepGetReturnFlagName(flag), flag); }
  double LastStep() override {
    double step = 0.0;
    ARKStepGetLastStep(mem_, &step);
    return std::abs(step);
  }

 private:
  /// A new ARKStep memory at (t0, y0), configured; the matrix and linear solver are reused.
  int Create(double t0, N_Vector y0) {
    mem_ = ARKStepCreate(nullptr, resources_.rhs, t0, y0, resources_.context);
    if (!mem_) return ARK_MEM_FAIL;
    ARKStepSetErrHandlerFn(mem_, CaptureMessage, resources_.log);
    ARKStepSetUserData(mem_, resources_.user_data);
    int flag = ARKStepSetTableNum(mem_, table_, ARKODE_ERK_NONE);
    if (flag == ARK_SUCCESS) {
      flag = ARKStepRootInit(mem_, static_cast<int>(root_directions_.size()), resources_.roots);
    }
    if (flag == ARK_SUCCESS) flag = ARKStepSetRootDirection(mem_, root_directions_.data());
    if (flag == ARK_SUCCESS) flag = ARKStepSetNoInactiveRootWarn(mem_);
    if (flag == ARK_SUCCESS) flag = ARKStepSetMaxHnilWarns(mem_, -1);
    if (flag == ARK_SUCCESS) flag = ARKStepSetLinearSolver(mem_, linear_solver_, matrix_);
    // Without an analytic Jacobian, difference quotients.
    if (flag == ARK_SUCCESS && resources_.jacobian) flag = ARKStepSetJacFn(mem_, resources_.jacobian);
    if (flag == ARK_SUCCESS && resources_.jacobian_at_every_setup) flag = ARKStepSetJacEvalFrequency(mem_, 1);
    return flag;
  }
  void Release() noexcept {
    ARKStepFree(&mem_);
    if (linear_solver_) SUNLinSolFree(linear_solver_);
    if (matrix_) SUNMatDestroy(matrix_);
    linear_solver_ = nullptr;
    matrix_ = nullptr;
  }

  ARKODE_DIRKTableID table_;
  StepperResources resources_;
  std::vector<int> root_directions_;
  void* mem_ = nullptr;
  SUNMatrix matrix_ = nullptr;
  SUNLinearSolver linear_solver_ = nullptr;
};

/// An explicit table on ERKStep, the lean explicit module.
class ErkStepper final : public Stepper {
 public:
  ErkStepper(ComputationMethod method, const StepperResources& r)
      : table_(ExplicitTable(method)), resources_(r),
        root_directions_(r.root_directions.begin(), r.root_directions.end()),
        trusts_reentry_step_(method != ComputationMethod::kArkodeErk87) {
    resources_.root_directions = root_directions_;  // this stepper's own copy
    N_VConst(0.0, r.state);
    if (Create(0.0, r.state) != ARK_SUCCESS) {
      ERKStepFree(&mem_);
      throw std::runtime_error("ERKStepCreate failed: " + *r.log);
    }
  }
  ~ErkStepper() override { ERKStepFree(&mem_); }
  ErkStepper(const ErkStepper&) = delete;
  ErkStepper& operator=(const ErkStepper&) = delete;

  int BeginRun(double t0, N_Vector y0) override {
    ERKStepFree(&mem_);
    return Create(t0, y0);
  }
  int ReInit(double t0, N_Vector y0) override { return ERKStepReInit(mem_, resources_.rhs, t0, y0); }
  int SetTolerances(double relative, N_Vector absolute) override {
    return ERKStepSVtolerances(mem_, relative, absolute);
  }
  int SetInitStep(double step) override { return ERKStepSetInitStep(mem_, step); }
  int Step(double tout, N_Vector y, double* t) override {
    return ERKStepEvolve(mem_, tout, y, t, ARK_ONE_STEP);
  }
  void RootInfo(int* found) override { ERKStepGetRootInfo(mem_, found); }
  int Interpolate(double t, N_Vector out) override { return ERKStepGetDky(mem_, t, 0, out); }
  void AddStatistics(SolverStatistics& stats) override {
    long steps = 0, rhs = 0, roots = 0, error_fails = 0;
    ERKStepGetNumSteps(mem_, &steps);
    ERKStepGetNumRhsEvals(mem_, &rhs);
    ERKStepGetNumGEvals(mem_, &roots);
    ERKStepGetNumErrTestFails(mem_, &error_fails);
    stats.steps += steps;
    stats.rhs_evaluations += rhs;
    stats.root_evaluations += roots;
    stats.error_test_failures += error_fails;
  }
  std::string FlagName(int flag) override { return TakeFlagName(ERKStepGetReturnFlagName(flag), flag); }
  double LastStep() override {
    double step = 0.0;
    ERKStepGetLastStep(mem_, &step);
    return std::abs(step);
  }
  double ReentryStep(double step) override { return trusts_reentry_step_ ? step : 0.0; }

 private:
  /// A new ERKStep memory at (t0, y0), configured.
  int Create(double t0, N_Vector y0) {
    mem_ = ERKStepCreate(resources_.rhs, t0, y0, resources_.context);
    if (!mem_) return ARK_MEM_FAIL;
    ERKStepSetErrHandlerFn(mem_, CaptureMessage, resources_.log);
    ERKStepSetUserData(mem_, resources_.user_data);
    int flag = ERKStepSetTableNum(mem_, table_);
    if (flag == ARK_SUCCESS) {
      flag = ERKStepRootInit(mem_, static_cast<int>(root_directions_.size()), resources_.roots);
    }
    if (flag == ARK_SUCCESS) flag = ERKStepSetRootDirection(mem_, root_directions_.data());
    if (flag == ARK_SUCCESS) flag = ERKStepSetNoInactiveRootWarn(mem_);
    if (flag == ARK_SUCCESS) flag = ERKStepSetMaxHnilWarns(mem_, -1);
    return flag;
  }

  ARKODE_ERKTableID table_;
  StepperResources resources_;
  std::vector<int> root_directions_;
  void* mem_ = nullptr;
  /// Fehlberg 7(8)'s embedded error estimate misses the error of a large first step after a
  /// restart (measured: 9e-7 at rtol 1e-9 when re-entering with the loading step), so it
  /// keeps ARKODE's own cautious first step.
  bool trusts_reentry_step_ = true;
};

}  // namespace

std::unique_ptr<Stepper> MakeArkodeStepper(ComputationMethod method, const StepperResources& r) {
  if (IsImplicit(method)) return std::make_unique<DirkStepper>(method, r);
  return std::make_unique<ErkStepper>(method, r);
}

}  // namespace covopt::internal
