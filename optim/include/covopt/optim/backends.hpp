#pragma once
/// @file backends.hpp
/// NLopt and Ipopt behind covopt::optim::Problem.

#include <span>
#include <string_view>

#include "covopt/optim/problem.hpp"

namespace covopt::optim {

/// The NLopt algorithms covopt uses.
enum class NloptAlgorithm {
  kDirectL,  ///< GN_DIRECT_L: deterministic global search on the bounded box
  kIsres,    ///< GN_ISRES: evolutionary global search with native constraints (seeded)
  kMlsl,     ///< G_MLSL_LDS with a local LD_LBFGS: multistart quasi-Newton (seeded)
  kCobyla,   ///< LN_COBYLA: local, derivative-free, native constraints
  kSlsqp,    ///< LD_SLSQP: local, gradient-based, native constraints
  kLbfgs,    ///< LD_LBFGS: local, gradient-based, bounds only
};
std::string_view ToString(NloptAlgorithm algorithm) noexcept;

struct NloptOptions {
  NloptAlgorithm algorithm = NloptAlgorithm::kDirectL;
  /// Stop after this many objective evaluations (> 0).
  long max_evaluations = 2000;
  /// Stop when a step changes every x_i by less than this fraction of x_i (0 = off).
  double relative_x_tolerance = 0.0;
  /// Stop after this many seconds (0 = off).
  double max_seconds = 0.0;
  /// Seed of NLopt's random numbers (ISRES, MLSL), for reproducible runs.
  unsigned long seed = 20110509;
  /// Constraint tolerance for algorithms with native constraints.
  double constraint_tolerance = 1e-9;
  /// Algorithms without native constraints (DIRECT-L, MLSL, L-BFGS) minimise the exact
  /// penalty f + w (Σ max(0, c_i) + Σ |h_j|) with this weight w.
  double penalty_weight = 1e3;
  /// Objective value handed to NLopt when an evaluation fails (large but finite).
  double failure_value = 1e30;
};

/// Runs NLopt from x0 (used by local algorithms and as the first point of global ones).
/// Never throws for a numerical failure (see SolveResult::report); rethrows an exception
/// raised by the problem's evaluations after NLopt has returned.
SolveResult SolveWithNlopt(const Problem& problem, std::span<const double> x0,
                           const NloptOptions& options = {});

struct IpoptOptions {
  double tolerance = 1e-10;             ///< Ipopt "tol"
  double constraint_tolerance = 1e-10;  ///< Ipopt "constr_viol_tol"
  /// Ipopt "bound_relax_factor": Ipopt relaxes bounds and inequalities by this relative
  /// amount (its default 1e-8 lets a converged point violate a constraint by ~1e-8, which the
  /// exact re-check of a design then rejects). 0: constraints as posed.
  double bound_relax_factor = 0.0;
  int max_iterations = 200;             ///< Ipopt "max_iter"
  double max_seconds = 10.0;            ///< Ipopt "max_cpu_time"
  /// Ipopt's L-BFGS Hessian approximation even when the problem gives its Lagrangian's
  /// Hessian (Problem::provides_lagrangian_hessian); a problem that gives none always gets the
  /// approximation. Default: false (the problem's Hessian when it has one).
  bool limited_memory_hessian = false;
  /// x0 is (nearly) the solution, as a polish from another method's answer: Ipopt starts with
  /// its barrier parameter at 1e-11 (not 0.1), monotone, and keeps x0 and the constraint
  /// slacks within 1e-12 of where they are (not pushed 1% into the interior), multipliers
  /// from 0 (no least-squares estimate), so it confirms
  /// the point in a few iterations instead of leaving and re-approaching it. Default: false.
  bool warm_start = false;
  /// Scale of the derivative check Ipopt may run: "none", "first-order" or "second-order".
  const char* derivative_test = "none";
};

/// Runs Ipopt from x0 with exact first derivatives (and the problem's second derivatives when
/// it gives them), silently (no console output at all, no
/// options file read). An option Ipopt rejects (e.g. a tolerance <= 0) is not ignored: the
/// solve ends at once with Termination::kInvalidProblem and raw name "Invalid_Option". Ipopt is serialised by a process-wide mutex: its MUMPS linear solver is not
/// thread-safe.
SolveResult SolveWithIpopt(const Problem& problem, std::span<const double> x0,
                           const IpoptOptions& options = {});

}  // namespace covopt::optim
