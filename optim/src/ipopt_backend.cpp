// Ipopt through its TNLP interface: silent, no options file, exact first derivatives, and the
// problem's Hessian of the Lagrangian when it gives one (else L-BFGS). Built as the plugin
// libcovopt_ipopt.so, opened by SolveWithIpopt (backend_plugins.cpp) when first needed.
#include <IpIpoptApplication.hpp>
#include <IpTNLP.hpp>

#include <mutex>
#include <vector>

#include "backend_plugins.hpp"
#include "covopt/optim/backends.hpp"
#include "evaluation_guard.hpp"

namespace covopt::optim {
namespace {

using Ipopt::Index;
using Ipopt::Number;

/// Problem -> Ipopt::TNLP. c(x) <= 0 becomes g in [-inf, 0]; h(x) = 0 becomes g in [0, 0].
class TnlpAdapter : public Ipopt::TNLP {
 public:
  TnlpAdapter(const Problem& problem, std::span<const double> x0, internal::EvaluationGuard& guard,
              bool exact_hessian)
      : problem_(problem), x0_(x0.begin(), x0.end()), guard_(guard), exact_hessian_(exact_hessian),
        n_(problem.dimension()), m_(problem.inequality_count() + problem.equality_count()),
        values_(m_), jacobian_(m_ * n_) {}

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag,
                    IndexStyleEnum& index_style) override {
    n = static_cast<Index>(n_);
    m = static_cast<Index>(m_);
    nnz_jac_g = static_cast<Index>(m_ * n_);
    nnz_h_lag = exact_hessian_ ? static_cast<Index>(n_ * (n_ + 1) / 2) : 0;
    index_style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index, Number* x_l, Number* x_u, Index, Number* g_l, Number* g_u) override {
    const std::vector<double> lower = problem_.lower_bounds();
    const std::vector<double> upper = problem_.upper_bounds();
    for (std::size_t i = 0; i < n_; ++i) {
      x_l[i] = lower[i];
      x_u[i] = upper[i];
    }
    for (std::size_t i = 0; i < m_; ++i) {
      g_l[i] = i < problem_.inequality_count() ? -1e19 : 0.0;  // -1e19: Ipopt's -infinity
      g_u[i] = 0.0;
    }
    return true;
  }

  bool get_starting_point(Index, bool init_x, Number* x, bool init_z, Number*, Number*, Index,
                          bool init_lambda, Number*) override {
    if (!init_x || init_z || init_lambda) return false;
    for (std::size_t i = 0; i < n_; ++i) x[i] = x0_[i];
    return true;
  }

  bool eval_f(Index n, const Number* x, bool, Number& obj_value) override {
    return guard_.Objective(Point(n, x), obj_value, {});
  }

  bool eval_grad_f(Index n, const Number* x, bool, Number* grad_f) override {
    double value = 0.0;
    return guard_.Objective(Point(n, x), value, std::span<double>(grad_f, n_));
  }

  bool eval_g(Index n, const Number* x, bool, Index, Number* g) override {
    if (!guard_.Constraints(Point(n, x), std::span<double>(g, m_), {})) return false;
    return true;
  }

  bool eval_jac_g(Index n, const Number* x, bool, Index, Index, Index* i_row, Index* j_col,
                  Number* values) override {
    if (values == nullptr) {  // the (dense) structure
      for (std::size_t i = 0, k = 0; i < m_; ++i) {
        for (std::size_t j = 0; j < n_; ++j, ++k) {
          i_row[k] = static_cast<Index>(i);
          j_col[k] = static_cast<Index>(j);
        }
      }
      return true;
    }
    return guard_.Constraints(Point(n, x), values_, std::span<double>(values, m_ * n_));
  }

  bool eval_h(Index n, const Number* x, bool, Number obj_factor, Index m, const Number* lambda, bool,
              Index, Index* i_row, Index* j_col, Number* values) override {
    if (!exact_hessian_) return false;
    if (values == nullptr) {  // the (dense) lower triangle, by rows
      for (std::size_t i = 0, k = 0; i < n_; ++i) {
        for (std::size_t j = 0; j <= i; ++j, ++k) {
          i_row[k] = static_cast<Index>(i);
          j_col[k] = static_cast<Index>(j);
        }
      }
      return true;
    }
    return guard_.Hessian(Point(n, x), obj_factor, std::span<const double>(lambda, static_cast<std::size_t>(m)),
                          std::span<double>(values, n_ * (n_ + 1) / 2));
  }

  void finalize_solution(Ipopt::SolverReturn, Index n, const Number* x, const Number*,
                         const Number*, Index, const Number*, const Number*, Number,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    solution_.assign(x, x + n);
  }

  const std::vector<double>& solution() const { return solution_; }

 private:
  std::span<const double> Point(Index n, const Number* x) const {
    return std::span<const double>(x, static_cast<std::size_t>(n));
  }

  const Problem& problem_;
  std::vector<double> x0_;
  internal::EvaluationGuard& guard_;
  bool exact_hessian_;
  std::size_t n_, m_;
  std::vector<double> values_, jacobian_;
  std::vector<double> solution_;
};

Termination MapStatus(Ipopt::ApplicationReturnStatus status) {
  switch (status) {
    case Ipopt::Solve_Succeeded: return Termination::kConverged;
    case Ipopt::Solved_To_Acceptable_Level:
    case Ipopt::Feasible_Point_Found: return Termination::kAcceptable;
    case Ipopt::Infeasible_Problem_Detected: return Termination::kInfeasible;
    case Ipopt::Maximum_Iterations_Exceeded: return Termination::kEvaluationLimit;
    case Ipopt::Maximum_CpuTime_Exceeded: return Termination::kTimeLimit;
    case Ipopt::Invalid_Number_Detected: return Termination::kEvaluationFailure;
    case Ipopt::Not_Enough_Degrees_Of_Freedom:
    case Ipopt::Invalid_Problem_Definition:
    case Ipopt::Invalid_Option: return Termination::kInvalidProblem;
    default: return Termination::kSolverError;
  }
}

const char* StatusName(Ipopt::ApplicationReturnStatus status) {
  switch (status) {
    case Ipopt::Solve_Succeeded: return "Solve_Succeeded";
    case Ipopt::Solved_To_Acceptable_Level: return "Solved_To_Acceptable_Level";
    case Ipopt::Infeasible_Problem_Detected: return "Infeasible_Problem_Detected";
    case Ipopt::Search_Direction_Becomes_Too_Small: return "Search_Direction_Becomes_Too_Small";
    case Ipopt::Diverging_Iterates: return "Diverging_Iterates";
    case Ipopt::User_Requested_Stop: return "User_Requested_Stop";
    case Ipopt::Feasible_Point_Found: return "Feasible_Point_Found";
    case Ipopt::Maximum_Iterations_Exceeded: return "Maximum_Iterations_Exceeded";
    case Ipopt::Restoration_Failed: return "Restoration_Failed";
    case Ipopt::Error_In_Step_Computation: return "Error_In_Step_Computation";
    case Ipopt::Maximum_CpuTime_Exceeded: return "Maximum_CpuTime_Exceeded";
    case Ipopt::Not_Enough_Degrees_Of_Freedom: return "Not_Enough_Degrees_Of_Freedom";
    case Ipopt::Invalid_Problem_Definition: return "Invalid_Problem_Definition";
    case Ipopt::Invalid_Option: return "Invalid_Option";
    case Ipopt::Invalid_Number_Detected: return "Invalid_Number_Detected";
    case Ipopt::Unrecoverable_Exception: return "Unrecoverable_Exception";
    case Ipopt::NonIpopt_Exception_Thrown: return "NonIpopt_Exception_Thrown";
    case Ipopt::Insufficient_Memory: return "Insufficient_Memory";
    case Ipopt::Internal_Error: return "Internal_Error";
  }
  return "unknown";
}

/// Warm start (IpoptOptions::warm_start): Ipopt's initial barrier parameter "mu_init" (its
/// default 0.1) and its bound and slack pushes "bound_push", "bound_frac", "slack_bound_push",
/// "slack_bound_frac" (default 1e-2); "constr_mult_init_max" 0 (default 1000).
constexpr double kWarmStartBarrier = 1e-11;
constexpr double kWarmStartPush = 1e-12;

std::mutex& IpoptMutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace

// The plugin's entry (backend_plugins.hpp): SolveWithIpopt names the backend and finishes the result.
COVOPT_PLUGIN_ENTRY bool covopt_ipopt_solve_v1(const Problem& problem, std::span<const double> x0,
                                               const IpoptOptions& options, SolveResult& result) {
  const std::size_t n = problem.dimension();
  if (n == 0 || x0.size() != n) {
    result.report.termination = Termination::kInvalidProblem;
    result.report.raw_code = Ipopt::Invalid_Problem_Definition;
    result.report.raw_name = StatusName(Ipopt::Invalid_Problem_Definition);
    return false;
  }
  internal::EvaluationGuard guard(problem);
  Ipopt::ApplicationReturnStatus status = Ipopt::Internal_Error;
  std::vector<double> solution;
  {
    std::lock_guard<std::mutex> lock(IpoptMutex());
    const bool exact_hessian = problem.provides_lagrangian_hessian() && !options.limited_memory_hessian;
    Ipopt::SmartPtr<TnlpAdapter> nlp = new TnlpAdapter(problem, x0, guard, exact_hessian);
    // No console journal at all: Ipopt reports a rejected option on its console as soon as
    // it is set (before print_level applies), and the library never prints.
    Ipopt::SmartPtr<Ipopt::IpoptApplication> app =
        new Ipopt::IpoptApplication(/*create_console_out=*/false);
    app->RethrowNonIpoptException(false);
    Ipopt::SmartPtr<Ipopt::OptionsList> o = app->Options();
    // Every option must be accepted: an ignored one (say a tolerance <= 0) would silently
    // run Ipopt with its default instead. A rejected option is Ipopt's Invalid_Option.
    bool accepted = o->SetIntegerValue("print_level", 0);
    accepted = o->SetStringValue("sb", "yes") && accepted;  // no banner
    accepted = o->SetNumericValue("tol", options.tolerance) && accepted;
    accepted = o->SetNumericValue("constr_viol_tol", options.constraint_tolerance) && accepted;
    accepted = o->SetNumericValue("bound_relax_factor", options.bound_relax_factor) && accepted;
    accepted = o->SetIntegerValue("max_iter", options.max_iterations) && accepted;
    accepted = o->SetNumericValue("max_cpu_time", options.max_seconds) && accepted;
    if (!exact_hessian) {
      accepted = o->SetStringValue("hessian_approximation", "limited-memory") && accepted;
    }
    accepted = options.derivative_test != nullptr &&
               o->SetStringValue("derivative_test", options.derivative_test) && accepted;
    if (options.warm_start) {
      // x0 is (nearly) the solution: start with a barrier parameter near the tolerance and
      // the variables and slacks where they are, not pushed 1% into the interior.
      accepted = o->SetNumericValue("mu_init", kWarmStartBarrier) && accepted;
      accepted = o->SetStringValue("mu_strategy", "monotone") && accepted;
      // Multipliers from 0, not a least-squares estimate (a factorization and solve less).
      accepted = o->SetNumericValue("constr_mult_init_max", 0.0) && accepted;
      for (const char* push : {"bound_push", "bound_frac", "slack_bound_push", "slack_bound_frac"}) {
        accepted = o->SetNumericValue(push, kWarmStartPush) && accepted;
      }
    }
    if (accepted) {
      status = app->Initialize("");  // "" : read no ipopt.opt from the working directory
      if (status == Ipopt::Solve_Succeeded) status = app->OptimizeTNLP(nlp);
    } else {
      status = Ipopt::Invalid_Option;
    }
    solution = nlp->solution();
  }
  guard.RethrowIfAny();
  result.x = solution.empty() ? std::vector<double>(x0.begin(), x0.end()) : solution;
  result.report.raw_code = static_cast<int>(status);
  result.report.raw_name = StatusName(status);
  result.report.termination = MapStatus(status);
  guard.CopyCounters(result.report);
  return true;
}

}  // namespace covopt::optim
