#include "covopt/report/work_precision_text.hpp"

#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/report/scene_headline.hpp"
#include "covopt/report/work_precision_report.hpp"

namespace covopt::report {

void PrintWorkPrecision(std::ostream& out, const WorkPrecisionResult& study, const Scene& scene) {
  const std::vector<WorkPrecisionPoint>& points = study.points;
  fmt::print(out, "Scene   {}\n", SceneHeadline(scene));
  fmt::print(out, "Errors  relative to the exact path; time = median CPU time per impact\n\n");
  fmt::print(out, "{:<29} {:>7} {:>9} {:>8} {:>8} {:>8} {:>8} {:>8} {:>9} {:>10} {:>7} {:>7} {:>5} {:>5}\n",
             "method", "rtol", "worst", "δmax", "Fmax", "σc,max", "eA,max", "T", "residual",
             "µs/impact", "steps", "rhs", "jac", "fail");
  const ComputationMethod* last = nullptr;
  bool last_restart = true;
  for (const WorkPrecisionPoint& p : points) {
    if (last && (*last != p.method || last_restart != p.restart)) fmt::print(out, "\n");
    last = &p.method;
    last_restart = p.restart;
    const std::string name = WorkPrecisionSeriesName(p.method, p.restart);
    const std::string rtol =
        p.method == ComputationMethod::kExact ? std::string("-") : fmt::format("{:.0e}", p.relative_tolerance);
    if (p.status != SolveStatus::kSuccess) {
      fmt::print(out, "{:<29} {:>7} FAILED: {} after {} steps ({:.1f} µs): {}\n", name, rtol,
                 ToString(p.status), p.statistics.steps, p.seconds_per_impact * 1e6,
                 p.message.substr(0, 90));
      continue;
    }
    const std::string residual =
        p.energy_residual ? fmt::format("{:.1e}", *p.energy_residual) : std::string("-");
    fmt::print(out,
               "{:<29} {:>7} {:>9.2e} {:>8.1e} {:>8.1e} {:>8.1e} {:>8.1e} {:>8.1e} {:>9} {:>10.2f} "
               "{:>7} {:>7} {:>5} {:>5}\n",
               name, rtol, p.worst_error, p.error_max_penetration, p.error_peak_force,
               p.error_max_compressive_stress, p.error_max_energy_density,
               p.error_contact_duration, residual, p.seconds_per_impact * 1e6, p.statistics.steps,
               p.statistics.rhs_evaluations, p.statistics.jacobian_evaluations,
               p.statistics.error_test_failures + p.statistics.convergence_failures);
  }

  fmt::print(out, "\nCheapest run reaching a worst error of\n");
  for (const CheapestRun& cheapest : study.cheapest) {
    const double target = cheapest.target_error;
    if (cheapest.point) {
      const WorkPrecisionPoint* best = &points[*cheapest.point];
      fmt::print(out, "  {:.0e}  {} at rtol {:.0e}: {:.1f} µs per impact (error {:.1e})\n", target,
                 WorkPrecisionSeriesName(best->method, best->restart), best->relative_tolerance,
                 best->seconds_per_impact * 1e6, best->worst_error);
    } else {
      fmt::print(out, "  {:.0e}  no run reached it\n", target);
    }
  }
  std::vector<std::string> broken;
  const double kept_ratio = study.kept_tolerance_ratio;
  for (const WorkPrecisionSeries& s : study.series) {
    if (s.worst_error_to_tolerance > kept_ratio) {
      broken.push_back(fmt::format("{} (error {:.0f} x rtol at rtol {:.0e})",
                                   WorkPrecisionSeriesName(s.method, s.restart), s.worst_error_to_tolerance,
                                   s.at_tolerance));
    }
    if (s.failures > 0) {
      broken.push_back(fmt::format("{} ({} failed run{})", WorkPrecisionSeriesName(s.method, s.restart),
                                   s.failures, s.failures == 1 ? "" : "s"));
    }
  }
  if (broken.empty()) {
    fmt::print(out, "Every series kept its error within {:g} x rtol.\n", kept_ratio);
  } else {
    fmt::print(out, "Not keeping the tolerance (error > {:g} x rtol) or failing:\n", kept_ratio);
    for (const std::string& line : broken) fmt::print(out, "  {}\n", line);
  }
}

void PrintDesignWorkPrecision(std::ostream& out, const optim::DesignWorkPrecisionResult& study, const Scene& scene) {
  fmt::print(out, "Scene   {}\n", DesignedSceneHeadline(scene));
  fmt::print(out,
             "Study   the thinnest admissible covering (continuous optimum) on each oracle; errors relative to "
             "the exact path's optimum; time = CPU time of the whole search\n\n");
  fmt::print(out, "{:<26} {:>7} {:>12} {:>10} {:>9} {:>9} {:>9} {:>8} {:>6} {:>6} {:>9}  {}\n", "oracle", "rtol",
             "b_c* [mm]", "E_c* [MPa]", "err b_c*", "err E_c*", "contusion", "evals", "grads", "failed", "seconds",
             "kept");
  for (const optim::DesignWorkPrecisionPoint& p : study.points) {
    const bool exact = p.oracle == optim::OracleKind::kExact;
    const auto error = [&](double e) { return exact ? std::string("-") : fmt::format("{:.1e}", e); };
    fmt::print(out, "{:<26} {:>7} {:>12.6f} {:>10.4f} {:>9} {:>9} {:>9.6f} {:>8} {:>6} {:>6} {:>9.3f}  {}\n",
               DesignWorkPrecisionSeriesName(p), exact ? std::string("-") : fmt::format("{:.0e}", p.relative_tolerance),
               p.thickness_m * 1e3, p.modulus_Pa * 1e-6, error(p.error_thickness), error(p.error_modulus),
               p.contusion_ratio, p.evaluations, p.gradient_evaluations, p.failed_evaluations, p.seconds,
               p.feasible ? p.source : "no admissible design");
  }
  fmt::print(out, "\n{}\n", study.message);
}

}  // namespace covopt::report
