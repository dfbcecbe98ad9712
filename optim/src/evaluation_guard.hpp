#pragma once
// Private: counts evaluations and failures for a backend, and keeps an exception raised by
// the problem so that it never crosses the C boundary (rethrown after the solver returns).
#include <cmath>
#include <exception>
#include <span>

#include "covopt/optim/problem.hpp"

namespace covopt::optim::internal {

class EvaluationGuard {
 public:
  explicit EvaluationGuard(const Problem& problem) : problem_(problem) {}

  /// f and (optionally) ∇f; false on failure, exception or non-finite output.
  bool Objective(std::span<const double> x, double& value, std::span<double> gradient) {
    ++objective_evaluations;
    if (!gradient.empty()) ++gradient_evaluations;
    bool ok = false;
    try {
      ok = problem_.Objective(x, value, gradient) && std::isfinite(value);
      for (double g : gradient) ok = ok && std::isfinite(g);
    } catch (...) {
      Keep(std::current_exception());
    }
    if (!ok) ++failed_evaluations;
    return ok;
  }

  bool Constraints(std::span<const double> x, std::span<double> values, std::span<double> jacobian) {
    ++constraint_evaluations;
    bool ok = false;
    try {
      ok = problem_.Constraints(x, values, jacobian);
      for (double v : values) ok = ok && std::isfinite(v);
      for (double j : jacobian) ok = ok && std::isfinite(j);
    } catch (...) {
      Keep(std::current_exception());
    }
    if (!ok) ++failed_evaluations;
    return ok;
  }

  /// The Lagrangian's Hessian (Problem::LagrangianHessian); false as for Constraints.
  bool Hessian(std::span<const double> x, double objective_factor, std::span<const double> multipliers,
               std::span<double> lower_triangle) {
    bool ok = false;
    try {
      ok = problem_.LagrangianHessian(x, objective_factor, multipliers, lower_triangle);
      for (double h : lower_triangle) ok = ok && std::isfinite(h);
    } catch (...) {
      Keep(std::current_exception());
    }
    if (!ok) ++failed_evaluations;
    return ok;
  }

  bool has_exception() const { return static_cast<bool>(exception_); }
  void RethrowIfAny() const {
    if (exception_) std::rethrow_exception(exception_);
  }
  void CopyCounters(SolverReport& report) const {
    report.objective_evaluations = objective_evaluations;
    report.gradient_evaluations = gradient_evaluations;
    report.constraint_evaluations = constraint_evaluations;
    report.failed_evaluations = failed_evaluations;
  }

  long objective_evaluations = 0;
  long gradient_evaluations = 0;
  long constraint_evaluations = 0;
  long failed_evaluations = 0;

 private:
  void Keep(std::exception_ptr e) {
    if (!exception_) exception_ = e;
  }
  const Problem& problem_;
  std::exception_ptr exception_;
};

/// Fills objective, constraints and max_violation of `result` at result.x (not counted).
void FinishResult(const Problem& problem, SolveResult& result);

}  // namespace covopt::optim::internal
