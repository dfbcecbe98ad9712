// NLopt through its C API (no exceptions: every outcome is an nlopt_result we map). Built as
// the plugin libcovopt_nlopt.so, opened by SolveWithNlopt (backend_plugins.cpp) when first needed.
#include <nlopt.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "backend_plugins.hpp"
#include "covopt/optim/backends.hpp"
#include "evaluation_guard.hpp"

namespace covopt::optim {
namespace {

struct NloptDeleter {
  void operator()(nlopt_opt opt) const { nlopt_destroy(opt); }
};
using NloptHandle = std::unique_ptr<std::remove_pointer_t<nlopt_opt>, NloptDeleter>;

nlopt_algorithm ToNlopt(NloptAlgorithm algorithm) {
  switch (algorithm) {
    case NloptAlgorithm::kDirectL: return NLOPT_GN_DIRECT_L;
    case NloptAlgorithm::kIsres: return NLOPT_GN_ISRES;
    case NloptAlgorithm::kMlsl: return NLOPT_G_MLSL_LDS;
    case NloptAlgorithm::kCobyla: return NLOPT_LN_COBYLA;
    case NloptAlgorithm::kSlsqp: return NLOPT_LD_SLSQP;
    case NloptAlgorithm::kLbfgs: return NLOPT_LD_LBFGS;
  }
  return NLOPT_GN_DIRECT_L;
}

bool HasNativeConstraints(NloptAlgorithm algorithm) {
  return algorithm == NloptAlgorithm::kIsres || algorithm == NloptAlgorithm::kCobyla ||
         algorithm == NloptAlgorithm::kSlsqp;
}

Termination MapResult(nlopt_result code) {
  switch (code) {
    case NLOPT_SUCCESS:
    case NLOPT_STOPVAL_REACHED:
    case NLOPT_FTOL_REACHED:
    case NLOPT_XTOL_REACHED: return Termination::kConverged;
    case NLOPT_MAXEVAL_REACHED: return Termination::kEvaluationLimit;
    case NLOPT_MAXTIME_REACHED: return Termination::kTimeLimit;
    case NLOPT_ROUNDOFF_LIMITED: return Termination::kRoundoffLimited;
    case NLOPT_INVALID_ARGS: return Termination::kInvalidProblem;
    default: return Termination::kSolverError;  // FAILURE, OUT_OF_MEMORY, FORCED_STOP
  }
}

/// What the C callbacks see.
struct Context {
  const Problem* problem = nullptr;
  internal::EvaluationGuard* guard = nullptr;
  const NloptOptions* options = nullptr;
  nlopt_opt opt = nullptr;
  bool penalise = false;  // fold the constraints into the objective
  std::vector<double> constraint_values;
  std::vector<double> constraint_jacobian;
};

double Objective(unsigned n, const double* x, double* gradient, void* data) {
  auto& ctx = *static_cast<Context*>(data);
  const std::span<const double> point(x, n);
  std::span<double> grad = gradient ? std::span<double>(gradient, n) : std::span<double>();
  double value = 0.0;
  bool ok = ctx.guard->Objective(point, value, grad);
  if (ok && ctx.penalise) {
    const std::size_t inequalities = ctx.problem->inequality_count();
    const std::size_t m = inequalities + ctx.problem->equality_count();
    std::span<double> jac = gradient ? std::span<double>(ctx.constraint_jacobian) : std::span<double>();
    ok = ctx.guard->Constraints(point, ctx.constraint_values, jac);
    const double w = ctx.options->penalty_weight;
    for (std::size_t i = 0; ok && i < m; ++i) {
      const double c = ctx.constraint_values[i];
      double slope = 0.0;
      if (i < inequalities) {
        if (c > 0.0) {
          value += w * c;
          slope = w;
        }
      } else {
        value += w * std::abs(c);
        slope = c > 0.0 ? w : (c < 0.0 ? -w : 0.0);
      }
      for (unsigned j = 0; gradient && slope != 0.0 && j < n; ++j) {
        gradient[j] += slope * ctx.constraint_jacobian[i * n + j];
      }
    }
  }
  if (ctx.guard->has_exception()) nlopt_force_stop(ctx.opt);
  if (!ok) {
    for (unsigned j = 0; gradient && j < n; ++j) gradient[j] = 0.0;
    return ctx.options->failure_value;
  }
  return value;
}

/// NLopt's vector-valued constraint: inequalities (offset 0) or equalities (offset ni).
struct ConstraintBlock {
  Context* ctx = nullptr;
  std::size_t offset = 0;
};

void ConstraintBlockFunction(unsigned m, double* result, unsigned n, const double* x,
                             double* gradient, void* data) {
  auto& block = *static_cast<ConstraintBlock*>(data);
  Context& ctx = *block.ctx;
  std::span<double> jac = gradient ? std::span<double>(ctx.constraint_jacobian) : std::span<double>();
  const bool ok = ctx.guard->Constraints(std::span<const double>(x, n), ctx.constraint_values, jac);
  for (unsigned i = 0; i < m; ++i) {
    // A failed evaluation is reported as badly violated, so the point is avoided.
    result[i] = ok ? ctx.constraint_values[block.offset + i] : ctx.options->failure_value;
    for (unsigned j = 0; gradient && j < n; ++j) {
      gradient[i * n + j] = ok ? ctx.constraint_jacobian[(block.offset + i) * n + j] : 0.0;
    }
  }
  if (ctx.guard->has_exception()) nlopt_force_stop(ctx.opt);
}

}  // namespace

// The plugin's entry (backend_plugins.hpp): SolveWithNlopt names the backend and finishes the result.
COVOPT_PLUGIN_ENTRY bool covopt_nlopt_solve_v1(const Problem& problem, std::span<const double> x0,
                                               const NloptOptions& options, SolveResult& result) {
  const std::size_t n = problem.dimension();
  const std::vector<double> lower = problem.lower_bounds();
  const std::vector<double> upper = problem.upper_bounds();
  if (n == 0 || x0.size() != n || lower.size() != n || upper.size() != n ||
      options.max_evaluations <= 0) {
    result.report.termination = Termination::kInvalidProblem;
    result.report.raw_code = NLOPT_INVALID_ARGS;
    result.report.raw_name = nlopt_result_to_string(NLOPT_INVALID_ARGS);
    return false;
  }

  internal::EvaluationGuard guard(problem);
  Context ctx;
  ctx.problem = &problem;
  ctx.guard = &guard;
  ctx.options = &options;
  const std::size_t inequalities = problem.inequality_count();
  const std::size_t equalities = problem.equality_count();
  ctx.constraint_values.assign(inequalities + equalities, 0.0);
  ctx.constraint_jacobian.assign((inequalities + equalities) * n, 0.0);
  ctx.penalise = !HasNativeConstraints(options.algorithm) && inequalities + equalities > 0;

  NloptHandle opt(nlopt_create(ToNlopt(options.algorithm), static_cast<unsigned>(n)));
  NloptHandle local;
  ctx.opt = opt.get();
  nlopt_set_lower_bounds(opt.get(), lower.data());
  nlopt_set_upper_bounds(opt.get(), upper.data());
  nlopt_set_min_objective(opt.get(), Objective, &ctx);
  nlopt_set_maxeval(opt.get(), static_cast<int>(options.max_evaluations));
  if (options.relative_x_tolerance > 0) nlopt_set_xtol_rel(opt.get(), options.relative_x_tolerance);
  if (options.max_seconds > 0) nlopt_set_maxtime(opt.get(), options.max_seconds);
  ConstraintBlock inequality_block{&ctx, 0};
  ConstraintBlock equality_block{&ctx, inequalities};
  if (!ctx.penalise && inequalities > 0) {
    const std::vector<double> tol(inequalities, options.constraint_tolerance);
    nlopt_add_inequality_mconstraint(opt.get(), static_cast<unsigned>(inequalities),
                                     ConstraintBlockFunction, &inequality_block, tol.data());
  }
  if (!ctx.penalise && equalities > 0) {
    const std::vector<double> tol(equalities, options.constraint_tolerance);
    nlopt_add_equality_mconstraint(opt.get(), static_cast<unsigned>(equalities),
                                   ConstraintBlockFunction, &equality_block, tol.data());
  }
  if (options.algorithm == NloptAlgorithm::kMlsl) {
    local.reset(nlopt_create(NLOPT_LD_LBFGS, static_cast<unsigned>(n)));
    nlopt_set_xtol_rel(local.get(), 1e-10);
    nlopt_set_maxeval(local.get(), 200);
    nlopt_set_local_optimizer(opt.get(), local.get());
  }
  nlopt_srand(options.seed);

  std::vector<double> x(x0.begin(), x0.end());
  for (std::size_t i = 0; i < n; ++i) x[i] = std::min(std::max(x[i], lower[i]), upper[i]);
  double best = 0.0;
  const nlopt_result code = nlopt_optimize(opt.get(), x.data(), &best);
  guard.RethrowIfAny();

  result.x = x;
  result.report.raw_code = static_cast<int>(code);
  result.report.raw_name = nlopt_result_to_string(code);
  result.report.termination = MapResult(code);
  if (guard.failed_evaluations > 0 && guard.failed_evaluations == guard.objective_evaluations) {
    result.report.termination = Termination::kEvaluationFailure;
  }
  guard.CopyCounters(result.report);
  return true;
}

}  // namespace covopt::optim
