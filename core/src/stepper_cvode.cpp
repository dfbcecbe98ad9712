// CVODE (Adams with fixed-point iteration, or BDF with Newton on the analytic Jacobian).
// CVODES, not CVODE: CVODES is CVODE plus forward/adjoint sensitivities with the same API,
// and a program must not link both (they define the same symbols).
#include <cvodes/cvodes.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "stepper.hpp"

namespace covopt::internal {
namespace {

class CvodeStepper final : public Stepper {
 public:
  CvodeStepper(ComputationMethod method, const StepperResources& r) : bdf_(method == ComputationMethod::kCvodeBdf) {
    mem_ = CVodeCreate(bdf_ ? CV_BDF : CV_ADAMS, r.context);
    if (!mem_) throw std::runtime_error("CVodeCreate failed");
    CVodeSetErrHandlerFn(mem_, CaptureMessage, r.log);
    N_VConst(0.0, r.state);
    if (CVodeInit(mem_, r.rhs, 0.0, r.state) != CV_SUCCESS) {
      throw std::runtime_error("CVodeInit failed: " + *r.log);
    }
    CVodeSetUserData(mem_, r.user_data);
    std::vector<int> directions(r.root_directions.begin(), r.root_directions.end());
    CVodeRootInit(mem_, static_cast<int>(directions.size()), r.roots);
    CVodeSetRootDirection(mem_, directions.data());
    CVodeSetNoInactiveRootWarn(mem_);
    CVodeSetMaxHnilWarns(mem_, -1);
    if (bdf_) {
      const sunindextype size = N_VGetLength(r.state);
      matrix_ = SUNDenseMatrix(size, size, r.context);
      linear_solver_ = SUNLinSol_Dense(r.state, matrix_, r.context);
      CVodeSetLinearSolver(mem_, linear_solver_, matrix_);
      if (r.jacobian) CVodeSetJacFn(mem_, r.jacobian);  // else difference quotients
      if (r.jacobian_at_every_setup) CVodeSetJacEvalFrequency(mem_, 1);
    } else {
      fixed_point_ = SUNNonlinSol_FixedPoint(r.state, 0, r.context);
      CVodeSetNonlinearSolver(mem_, fixed_point_);
    }
  }
  ~CvodeStepper() override {
    CVodeFree(&mem_);
    if (fixed_point_) SUNNonlinSolFree(fixed_point_);
    if (linear_solver_) SUNLinSolFree(linear_solver_);
    if (matrix_) SUNMatDestroy(matrix_);
  }
  CvodeStepper(const CvodeStepper&) = delete;
  CvodeStepper& operator=(const CvodeStepper&) = delete;

  int BeginRun(double t0, N_Vector y0) override { return CVodeReInit(mem_, t0, y0); }
  int ReInit(double t0, N_Vector y0) override { return CVodeReInit(mem_, t0, y0); }
  int SetTolerances(double relative, N_Vector absolute) override {
    return CVodeSVtolerances(mem_, relative, absolute);
  }
  int SetInitStep(double step) override { return CVodeSetInitStep(mem_, step); }
  int Step(double tout, N_Vector y, double* t) override { return CVode(mem_, tout, y, t, CV_ONE_STEP); }
  void RootInfo(int* found) override { CVodeGetRootInfo(mem_, found); }
  int Interpolate(double t, N_Vector out) override { return CVodeGetDky(mem_, t, 0, out); }
  void AddStatistics(SolverStatistics& stats) override {
    long steps = 0, rhs = 0, roots = 0, iterations = 0, error_fails = 0, convergence_fails = 0;
    CVodeGetNumSteps(mem_, &steps);
    CVodeGetNumRhsEvals(mem_, &rhs);
    CVodeGetNumGEvals(mem_, &roots);
    CVodeGetNumNonlinSolvIters(mem_, &iterations);
    CVodeGetNumErrTestFails(mem_, &error_fails);
    CVodeGetNumNonlinSolvConvFails(mem_, &convergence_fails);
    stats.steps += steps;
    stats.rhs_evaluations += rhs;
    stats.root_evaluations += roots;
    stats.nonlinear_iterations += iterations;
    stats.error_test_failures += error_fails;
    stats.convergence_failures += convergence_fails;
    if (bdf_) {
      long jacobians = 0, ls_rhs = 0;
      CVodeGetNumJacEvals(mem_, &jacobians);
      CVodeGetNumLinRhsEvals(mem_, &ls_rhs);
      stats.jacobian_evaluations += jacobians;
      stats.rhs_evaluations += ls_rhs;
    }
  }
  std::string FlagName(int flag) override { return TakeFlagName(CVodeGetReturnFlagName(flag), flag); }
  double ReentryStep(double /*step*/) override { return 0.0; }  // order 1 after a restart
  double LastStep() override {
    double step = 0.0;
    CVodeGetLastStep(mem_, &step);
    return std::abs(step);
  }

 private:
  bool bdf_ = false;
  void* mem_ = nullptr;
  SUNNonlinearSolver fixed_point_ = nullptr;
  SUNMatrix matrix_ = nullptr;
  SUNLinearSolver linear_solver_ = nullptr;
};

}  // namespace

std::unique_ptr<Stepper> MakeCvodeStepper(ComputationMethod method, const StepperResources& r) {
  return std::make_unique<CvodeStepper>(method, r);
}

}  // namespace covopt::internal
