#pragma once
/// @file problem.hpp
/// A small nonlinear program behind one interface, and what solving it returns.
///
///     minimise f(x)  subject to  c_i(x) <= 0 (inequalities),  h_j(x) = 0 (equalities),
///                                lower <= x <= upper (finite bounds fix the dimension)
///
/// The same Problem runs on NLopt (global or local) and on Ipopt (local, interior point).
/// An evaluation that fails (returns false, or yields a non-finite value) is counted and
/// survived: NLopt sees a large finite penalty, Ipopt is told the evaluation failed and backs
/// off. An exception thrown by an evaluation is caught at the C boundary, the solver is
/// stopped, and the exception is rethrown after it returns.

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace covopt::optim {

class Problem {
 public:
  virtual ~Problem() = default;
  virtual std::size_t dimension() const = 0;
  virtual std::size_t inequality_count() const { return 0; }
  virtual std::size_t equality_count() const { return 0; }
  virtual std::vector<double> lower_bounds() const = 0;  ///< finite, size dimension()
  virtual std::vector<double> upper_bounds() const = 0;  ///< finite, size dimension()

  /// f(x); fills `gradient` (size dimension()) when it is not empty.
  /// @return false if f cannot be evaluated at x.
  virtual bool Objective(std::span<const double> x, double& value,
                         std::span<double> gradient) const = 0;

  /// Inequalities then equalities into `values`; when `jacobian` is not empty, fills it
  /// row-major (one row per constraint, dimension() columns).
  /// @return false if the constraints cannot be evaluated at x.
  virtual bool Constraints(std::span<const double> /*x*/, std::span<double> /*values*/,
                           std::span<double> /*jacobian*/) const {
    return true;
  }

  /// This problem gives the Hessian of its Lagrangian (LagrangianHessian). Default: no, and
  /// Ipopt then approximates it by limited-memory BFGS.
  virtual bool provides_lagrangian_hessian() const { return false; }
  /// σ ∇²f(x) + Σ_i λ_i ∇²g_i(x) (g: the inequalities then the equalities, λ = `multipliers`,
  /// σ = `objective_factor`), its lower triangle by rows ((0,0), (1,0), (1,1), (2,0), ...:
  /// dimension() (dimension() + 1) / 2 entries) into `lower_triangle`.
  /// @return false if it cannot be evaluated at x (and always when not provided).
  virtual bool LagrangianHessian(std::span<const double> /*x*/, double /*objective_factor*/,
                                 std::span<const double> /*multipliers*/,
                                 std::span<double> /*lower_triangle*/) const {
    return false;
  }
};

/// The Hessian of `problem`'s Lagrangian (as Problem::LagrangianHessian) by central
/// differences of its analytic gradients (Objective's gradient and Constraints' Jacobian):
/// column j from x ± h_j e_j, h_j = `relative_step` × max(1, |x_j|), then symmetrised. Its
/// error is O(h²) in the third derivatives plus O(ε/h) rounding (~1e-10 relative for the
/// default step with gradients exact to the last bits). Four gradient evaluations per variable.
/// @return false if an evaluation fails or gives a non-finite value.
bool CentralDifferenceLagrangianHessian(const Problem& problem, std::span<const double> x,
                                        double objective_factor, std::span<const double> multipliers,
                                        std::span<double> lower_triangle, double relative_step = 1e-5);

/// One termination enum for every backend; the backend's raw code is kept alongside.
enum class Termination {
  kConverged,           ///< the backend's convergence test passed
  kAcceptable,          ///< Ipopt: converged to its "acceptable" tolerances only
  kEvaluationLimit,     ///< stopped at the evaluation / iteration budget (the usual end of a global search)
  kTimeLimit,           ///< stopped at the time budget
  kRoundoffLimited,     ///< NLopt: roundoff limited progress; the point may still be fine
  kInfeasible,          ///< the backend found no feasible point
  kEvaluationFailure,   ///< too many failed evaluations, or the backend gave up on them
  kInvalidProblem,      ///< bad bounds, sizes or options
  kSolverError,         ///< any other failure inside the backend
};

/// "converged", "evaluation-limit", ...
std::string_view ToString(Termination termination) noexcept;

/// The backend ended normally: converged, acceptable, a budget, or roundoff (its point may
/// be used); false for infeasible, failed evaluations, invalid problems and solver errors.
bool EndedNormally(Termination termination) noexcept;

/// How a solve ended and what it cost.
struct SolverReport {
  std::string backend;          ///< "nlopt:GN_DIRECT_L", "ipopt", ...
  Termination termination = Termination::kSolverError;
  int raw_code = 0;             ///< nlopt_result or Ipopt ApplicationReturnStatus
  std::string raw_name;         ///< the backend's name for raw_code
  long objective_evaluations = 0;
  long gradient_evaluations = 0;
  long constraint_evaluations = 0;
  long failed_evaluations = 0;  ///< evaluations that returned false or non-finite values
  double seconds = 0.0;         ///< wall time of the solve
};

/// The solution point and its report.
struct SolveResult {
  std::vector<double> x;              ///< best point found
  double objective = 0.0;             ///< f(x)
  std::vector<double> constraints;    ///< c(x) then h(x) at x
  double max_violation = 0.0;         ///< max(0, c_i(x), |h_j(x)|)
  SolverReport report;
  /// The point can be used: the backend ended normally (converged, acceptable, a budget, or
  /// roundoff) and x is finite.
  bool is_usable() const noexcept;
};

}  // namespace covopt::optim
