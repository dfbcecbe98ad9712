// Termination names, result usability, and the final bookkeeping shared by the backends.
#include "covopt/optim/problem.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "evaluation_guard.hpp"

namespace covopt::optim {

std::string_view ToString(Termination termination) noexcept {
  switch (termination) {
    case Termination::kConverged: return "converged";
    case Termination::kAcceptable: return "acceptable";
    case Termination::kEvaluationLimit: return "evaluation-limit";
    case Termination::kTimeLimit: return "time-limit";
    case Termination::kRoundoffLimited: return "roundoff-limited";
    case Termination::kInfeasible: return "infeasible";
    case Termination::kEvaluationFailure: return "evaluation-failure";
    case Termination::kInvalidProblem: return "invalid-problem";
    case Termination::kSolverError: return "solver-error";
  }
  return "unknown";
}

bool EndedNormally(Termination termination) noexcept {
  return termination == Termination::kConverged || termination == Termination::kAcceptable ||
         termination == Termination::kEvaluationLimit || termination == Termination::kTimeLimit ||
         termination == Termination::kRoundoffLimited;
}

bool SolveResult::is_usable() const noexcept {
  return EndedNormally(report.termination) && !x.empty() &&
         std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); }) &&
         std::isfinite(objective);
}

bool CentralDifferenceLagrangianHessian(const Problem& problem, std::span<const double> x,
                                        double objective_factor, std::span<const double> multipliers,
                                        std::span<double> lower_triangle, double relative_step) {
  const std::size_t n = problem.dimension();
  const std::size_t m = problem.inequality_count() + problem.equality_count();
  if (x.size() != n || multipliers.size() != m || lower_triangle.size() != n * (n + 1) / 2) return false;
  // ∇L at a point: σ ∇f + Σ λ_i ∇g_i.
  std::vector<double> point(x.begin(), x.end()), gradient(n), values(m), jacobian(m * n);
  auto lagrangian_gradient = [&](std::vector<double>& out) {
    double value = 0.0;
    if (!problem.Objective(point, value, gradient)) return false;
    if (m > 0 && !problem.Constraints(point, values, jacobian)) return false;
    for (std::size_t j = 0; j < n; ++j) {
      double sum = objective_factor * gradient[j];
      for (std::size_t i = 0; i < m; ++i) sum += multipliers[i] * jacobian[i * n + j];
      if (!std::isfinite(sum)) return false;
      out[j] = sum;
    }
    return true;
  };
  // The points stay inside the bounds, where every scene is one the library takes (a design
  // space begins at the physical floors, physical_floors.hpp): at a bound the difference is
  // one-sided, from the centre.
  const std::vector<double> lower = problem.lower_bounds(), upper = problem.upper_bounds();
  std::vector<double> full(n * n), plus(n), minus(n), centre;  // full[j * n + k] = ∂²L/∂x_j∂x_k
  for (std::size_t j = 0; j < n; ++j) {
    const double h = relative_step * std::max(1.0, std::abs(x[j]));
    const double up = j < upper.size() ? std::clamp(upper[j] - x[j], 0.0, h) : h;
    const double down = j < lower.size() ? std::clamp(x[j] - lower[j], 0.0, h) : h;
    if (!(up + down > 0.0)) return false;  // a box of zero width: nothing to difference
    if (up == 0.0 || down == 0.0) {
      if (centre.empty()) {
        centre.resize(n);
        if (!lagrangian_gradient(centre)) return false;
      }
    }
    point[j] = x[j] + up;
    if (up == 0.0) plus = centre;
    else if (!lagrangian_gradient(plus)) return false;
    point[j] = x[j] - down;
    if (down == 0.0) minus = centre;
    else if (!lagrangian_gradient(minus)) return false;
    point[j] = x[j];
    for (std::size_t k = 0; k < n; ++k) full[j * n + k] = (plus[k] - minus[k]) / (up + down);
  }
  for (std::size_t r = 0, e = 0; r < n; ++r) {
    for (std::size_t c = 0; c <= r; ++c, ++e) lower_triangle[e] = 0.5 * (full[r * n + c] + full[c * n + r]);
  }
  return true;
}

namespace internal {

void FinishResult(const Problem& problem, SolveResult& result) {
  if (result.x.empty()) return;
  double value = 0.0;
  if (problem.Objective(result.x, value, {})) result.objective = value;
  const std::size_t m = problem.inequality_count() + problem.equality_count();
  result.constraints.assign(m, 0.0);
  result.max_violation = 0.0;
  if (m > 0 && problem.Constraints(result.x, result.constraints, {})) {
    for (std::size_t i = 0; i < m; ++i) {
      const double c = result.constraints[i];
      const double violation = i < problem.inequality_count() ? std::max(0.0, c) : std::abs(c);
      result.max_violation = std::max(result.max_violation, violation);
    }
  }
}

}  // namespace internal
}  // namespace covopt::optim
