// Termination names, result usability, and the final bookkeeping shared by the backends.
#include "covopt/optim/problem.hpp"

#include <algorithm>
#include <cmath>

#include "evaluation_guard.hpp"

namespace covopt::optim {

const char* ToString(Termination termination) noexcept {
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
