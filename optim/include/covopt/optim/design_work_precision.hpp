#pragma once
/// @file design_work_precision.hpp
/// The optimiser-level work-precision study: how accurately the thinnest-safe-covering search
/// reproduces its optimum when the time path is its oracle, against what it costs.
///
/// The search (FindThinnestSafeCovering, continuous optimum only, no catalog) runs once on the
/// exact path, the reference, and once per (integrator, rtol) on the time path
/// (OracleChoice::kTimePath). Each point reports the relative errors of b_c* and E_c* against
/// the exact path's optimum, the CPU time of the whole search (CLOCK_THREAD_CPUTIME_ID, one
/// run: a search is long enough to time), and the oracle's evaluations. On the paper's scene
/// the thickness is sharp (set where contusion and full compression bind together) and the
/// modulus flat (defined to ~1e-3, docs/model.md §5), so b_c*'s error measures the oracle's
/// accuracy and E_c*'s mostly the flatness. `covopt workprecision --design` prints it.
///
///     covopt::optim::DesignWorkPrecisionOptions options;
///     options.relative_tolerances = {1e-6, 1e-8};
///     const auto study = covopt::optim::MeasureDesignWorkPrecision(covopt::Scene{}, options);

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <covopt/core/impact_result.hpp>
#include <covopt/core/scene.hpp>

#include "covopt/optim/covering_design.hpp"

namespace covopt::optim {

/// Progress of a running study.
struct DesignWorkPrecisionProgress {
  std::size_t completed_searches = 0;  ///< searches done (the exact path's is the first)
  std::size_t total_searches = 0;      ///< 1 + methods x tolerances
};

/// What to measure.
struct DesignWorkPrecisionOptions {
  /// The time path's integrators, in this order: any ComputationMethod but kExact, each at
  /// most once, at least one. Default: ARKODE ERK 5(4), CVODE Adams, CVODE BDF.
  std::vector<ComputationMethod> methods = {ComputationMethod::kArkodeErk54, ComputationMethod::kCvodeAdams,
                                            ComputationMethod::kCvodeBdf};
  /// Relative tolerances [-], each in [1e-14, 1e-2], at least one. Default: every decade
  /// from 1e-4 to 1e-10.
  std::vector<double> relative_tolerances = {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};
  /// The search's options (box, criterion, limits, stages); its oracle is set per point and
  /// its thread count to 1. Default: DesignOptions{}.
  DesignOptions design;
  /// Called after each search, on the calling thread. Default: none.
  std::function<void(const DesignWorkPrecisionProgress&)> progress;
};

/// One search: the exact path's (the reference) or the time path's at one (method, rtol).
struct DesignWorkPrecisionPoint {
  OracleKind oracle = OracleKind::kExact;
  ComputationMethod method = ComputationMethod::kExact;  ///< kExact for the exact path
  double relative_tolerance = 0.0;                       ///< 0 for the exact path
  /// The search found an admissible continuous optimum (its errors are then defined).
  bool feasible = false;
  std::string source;                   ///< the stage whose point was kept ("ipopt", "bracket ...")
  double modulus_Pa = 0.0;              ///< E_c* [Pa]
  double thickness_m = 0.0;             ///< b_c* [m]
  double contusion_ratio = 0.0;         ///< at the optimum, as the oracle scored it [-]
  /// |b_c*/b_c*,exact - 1| and |E_c*/E_c*,exact - 1| [-] (0 for the exact path; NaN when
  /// either search found no admissible optimum).
  double error_thickness = 0.0;
  double error_modulus = 0.0;
  double seconds = 0.0;                 ///< CPU time of the search [s]
  long evaluations = 0;                 ///< oracle evaluations
  long gradient_evaluations = 0;        ///< of which with a gradient (the Ipopt polish)
  long failed_evaluations = 0;          ///< time-path integrations that failed
  std::string local_termination;        ///< the Ipopt polish's end ("converged", ...)
};

/// The study: the exact path's search first, then per method, per tolerance.
struct DesignWorkPrecisionResult {
  std::vector<DesignWorkPrecisionPoint> points;
  /// One line: searches, the worst thickness error per rtol decade, failures.
  std::string message;
  /// The exact path found an admissible optimum: the errors have a reference.
  bool IsUsable() const noexcept { return !points.empty() && points.front().feasible; }
};

/// Runs the study on `scene` (its covering is what is designed).
/// @throws std::invalid_argument naming the option or scene field for bad input, or for a
///         scene the exact path cannot answer (it is the reference).
DesignWorkPrecisionResult MeasureDesignWorkPrecision(const Scene& scene, const DesignWorkPrecisionOptions& options = {});

}  // namespace covopt::optim
