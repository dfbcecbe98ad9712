// The optimiser-level work-precision study (design_work_precision.hpp).
#include "covopt/optim/design_work_precision.hpp"

#include <time.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <covopt/core/number_format.hpp>

namespace covopt::optim {
namespace {

double ThreadCpuSeconds() {
  timespec now{};
  ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

void Validate(const Scene& scene, const DesignWorkPrecisionOptions& o) {
  if (!scene.has_energy_integral()) {
    throw std::invalid_argument(
        "the design study needs the exact path's optimum as its reference; this scene has only the time path "
        "(a braking robot, a neck, or contact damping)");
  }
  if (o.methods.empty()) throw std::invalid_argument("methods: give at least one time integrator");
  for (std::size_t i = 0; i < o.methods.size(); ++i) {
    if (o.methods[i] == ComputationMethod::kExact || covopt::ToString(o.methods[i]) == "unknown") {
      throw std::invalid_argument("methods[" + std::to_string(i) + "] must be a time integrator (got " +
                                  std::string(covopt::ToString(o.methods[i])) + ")");
    }
    if (std::count(o.methods.begin(), o.methods.end(), o.methods[i]) > 1) {
      throw std::invalid_argument("methods: " + std::string(covopt::ToString(o.methods[i])) + " is listed twice");
    }
  }
  if (o.relative_tolerances.empty()) throw std::invalid_argument("relative_tolerances: give at least one");
  for (std::size_t i = 0; i < o.relative_tolerances.size(); ++i) {
    const double rtol = o.relative_tolerances[i];
    if (!(rtol >= 1e-14 && rtol <= 1e-2)) {
      throw std::invalid_argument("relative_tolerances[" + std::to_string(i) + "] must be in [1e-14, 1e-2] (got " +
                                  FormatSignificant(rtol) + ")");
    }
  }
}

DesignWorkPrecisionPoint Search(const Scene& scene, DesignOptions design, OracleChoice choice,
                                ComputationMethod method, double rtol) {
  design.oracle.choice = choice;
  if (choice == OracleChoice::kTimePath) {
    design.oracle.time_path.method = method;
    design.oracle.time_path.relative_tolerance = rtol;
  }
  design.threads = 1;
  const double started = ThreadCpuSeconds();
  const ThinnestSafeCovering found = FindThinnestSafeCovering(scene, {}, design);
  DesignWorkPrecisionPoint p;
  p.seconds = ThreadCpuSeconds() - started;
  p.oracle = found.oracle.kind;
  p.method = choice == OracleChoice::kTimePath ? method : ComputationMethod::kExact;
  p.relative_tolerance = choice == OracleChoice::kTimePath ? rtol : 0.0;
  p.feasible = found.continuous.feasible;
  p.source = found.continuous.source;
  p.modulus_Pa = found.continuous.score.design.youngs_modulus_Pa;
  p.thickness_m = found.continuous.score.design.thickness_m;
  p.contusion_ratio = found.continuous.score.contusion_ratio;
  p.evaluations = found.oracle.evaluations;
  p.gradient_evaluations = found.oracle.gradient_evaluations;
  p.failed_evaluations = found.oracle.failed_evaluations;
  p.local_termination = found.continuous.local.backend.empty() ? "not run" : ToString(found.continuous.local.termination);
  return p;
}

}  // namespace

DesignWorkPrecisionResult MeasureDesignWorkPrecision(const Scene& scene, const DesignWorkPrecisionOptions& options) {
  Validate(scene, options);
  DesignWorkPrecisionResult study;
  DesignWorkPrecisionProgress progress;
  progress.total_searches = 1 + options.methods.size() * options.relative_tolerances.size();
  auto done = [&] {
    ++progress.completed_searches;
    if (options.progress) options.progress(progress);
  };
  const DesignWorkPrecisionPoint exact =
      Search(scene, options.design, OracleChoice::kExact, ComputationMethod::kExact, 0.0);
  study.points.push_back(exact);
  done();
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  long failed = 0;
  double worst = 0.0;
  for (const ComputationMethod method : options.methods) {
    for (const double rtol : options.relative_tolerances) {
      DesignWorkPrecisionPoint p = Search(scene, options.design, OracleChoice::kTimePath, method, rtol);
      const bool comparable = exact.feasible && p.feasible;
      p.error_thickness = comparable ? std::abs(p.thickness_m / exact.thickness_m - 1.0) : kNaN;
      p.error_modulus = comparable ? std::abs(p.modulus_Pa / exact.modulus_Pa - 1.0) : kNaN;
      failed += p.failed_evaluations;
      if (comparable) worst = std::max(worst, p.error_thickness / rtol);
      study.points.push_back(p);
      done();
    }
  }
  study.message = exact.feasible
                      ? std::to_string(study.points.size()) + " searches (the exact path's and " +
                            std::to_string(study.points.size() - 1) + " on the time path); b_c* within " +
                            FormatSignificant(worst, 3) + " x rtol of the exact path's at worst; " +
                            std::to_string(failed) + " failed time-path evaluations"
                      : "the exact path found no admissible optimum: no reference";
  return study;
}

}  // namespace covopt::optim
