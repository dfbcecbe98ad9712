#include "covopt/report/work_precision_report.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "covopt/report/simulation_json.hpp"
#include "json_number.hpp"

namespace covopt::report {
namespace {

using internal::Number;
using Json = nlohmann::ordered_json;
using optim::DesignWorkPrecisionPoint;
using optim::DesignWorkPrecisionResult;

/// A number for CSV/JSON: shortest round-trip, empty/null when absent or not finite.
std::string CsvNumber(double value) { return std::isfinite(value) ? fmt::format("{}", value) : ""; }


Json PointJson(const WorkPrecisionPoint& p) {
  Json j{{"method", ToString(p.method)},
         {"restart_at_phase_switches", p.restart},
         {"relative_tolerance", Number(p.relative_tolerance)},
         {"status", ToString(p.status)},
         {"message", p.message},
         {"worst_error", Number(p.worst_error)},
         {"error_max_penetration", Number(p.error_max_penetration)},
         {"error_peak_force", Number(p.error_peak_force)},
         {"error_max_compressive_stress", Number(p.error_max_compressive_stress)},
         {"error_max_energy_density", Number(p.error_max_energy_density)},
         {"error_contact_duration", Number(p.error_contact_duration)},
         {"energy_residual", p.energy_residual ? Number(*p.energy_residual) : Json(nullptr)},
         {"seconds_per_impact", Number(p.seconds_per_impact)},
         {"timed_runs", p.timed_runs}};
  j.update(Json::parse(SolverStatisticsJson(p.statistics)));
  j["warnings"] = p.warning_count;
  return j;
}


Json DesignPointJson(const DesignWorkPrecisionPoint& p) {
  const bool exact = p.oracle == optim::OracleKind::kExact;
  return Json{{"oracle", optim::ToString(p.oracle)},
              {"method", exact ? Json(nullptr) : Json(std::string(ToString(p.method)))},
              {"relative_tolerance", exact ? Json(nullptr) : Number(p.relative_tolerance)},
              {"feasible", p.feasible},
              {"thickness_m", Number(p.thickness_m)},
              {"youngs_modulus_Pa", Number(p.modulus_Pa)},
              {"error_thickness", Number(p.error_thickness)},
              {"error_modulus", Number(p.error_modulus)},
              {"contusion_ratio", Number(p.contusion_ratio)},
              {"seconds", Number(p.seconds)},
              {"evaluations", p.evaluations},
              {"gradient_evaluations", p.gradient_evaluations},
              {"failed_evaluations", p.failed_evaluations},
              {"local_termination", p.local_termination},
              {"source", p.source}};
}

}  // namespace

std::string WorkPrecisionSeriesName(ComputationMethod method, bool restart) {
  if (method == ComputationMethod::kExact) return "exact path";
  return fmt::format("{}{}", ToString(method), restart ? "" : ", no restart");
}

std::string DesignWorkPrecisionSeriesName(const DesignWorkPrecisionPoint& p) {
  return p.oracle == optim::OracleKind::kExact ? std::string("exact path")
                                                : fmt::format("time path, {}", ToString(p.method));
}

std::string DesignWorkPrecisionCsv(const DesignWorkPrecisionResult& study) {
  std::string csv =
      "oracle,method,relative_tolerance,feasible,thickness_m,youngs_modulus_Pa,error_thickness,error_modulus,"
      "contusion_ratio,seconds,evaluations,gradient_evaluations,failed_evaluations,local_termination,source\n";
  for (const DesignWorkPrecisionPoint& p : study.points) {
    const bool exact = p.oracle == optim::OracleKind::kExact;
    std::string source = p.source;
    std::replace(source.begin(), source.end(), '"', '\'');
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},\"{}\"\n", optim::ToString(p.oracle),
                       ToString(p.method), exact ? "" : CsvNumber(p.relative_tolerance), p.feasible ? 1 : 0,
                       CsvNumber(p.thickness_m), CsvNumber(p.modulus_Pa), CsvNumber(p.error_thickness),
                       CsvNumber(p.error_modulus), CsvNumber(p.contusion_ratio), CsvNumber(p.seconds), p.evaluations,
                       p.gradient_evaluations, p.failed_evaluations, p.local_termination, source);
  }
  return csv;
}


std::string WorkPrecisionCsv(const std::vector<WorkPrecisionPoint>& points) {
  std::string csv =
      "method,restart_at_phase_switches,relative_tolerance,status,worst_error,"
      "error_max_penetration,error_peak_force,error_max_compressive_stress,"
      "error_max_energy_density,error_contact_duration,energy_residual,seconds_per_impact,"
      "timed_runs,steps,rhs_evaluations,root_evaluations,jacobian_evaluations,"
      "nonlinear_iterations,error_test_failures,convergence_failures,restarts,warnings\n";
  for (const WorkPrecisionPoint& p : points) {
    const bool ok = p.status == SolveStatus::kSuccess;
    const auto error = [&](double value) { return ok ? CsvNumber(value) : std::string(); };
    const SolverStatistics& st = p.statistics;
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
                       ToString(p.method), p.restart ? 1 : 0,
                       p.method == ComputationMethod::kExact ? "" : CsvNumber(p.relative_tolerance),
                       ToString(p.status), error(p.worst_error), error(p.error_max_penetration),
                       error(p.error_peak_force), error(p.error_max_compressive_stress),
                       error(p.error_max_energy_density), error(p.error_contact_duration),
                       p.energy_residual ? CsvNumber(*p.energy_residual) : "",
                       CsvNumber(p.seconds_per_impact), p.timed_runs, st.steps,
                       st.rhs_evaluations, st.root_evaluations, st.jacobian_evaluations,
                       st.nonlinear_iterations, st.error_test_failures, st.convergence_failures,
                       st.restarts, p.warning_count);
  }
  return csv;
}

std::string WorkPrecisionJson(const WorkPrecisionResult& study, const Scene& scene) {
  const std::vector<WorkPrecisionPoint>& points = study.points;
  Json j;
  j["scene"] = Json::parse(SceneJson(scene));
  Json list = Json::array();
  for (const WorkPrecisionPoint& p : points) list.push_back(PointJson(p));
  j["points"] = std::move(list);
  Json cheapest = Json::object();
  for (const CheapestRun& run : study.cheapest) {
    cheapest[fmt::format("{:.0e}", run.target_error)] = run.point ? PointJson(points[*run.point]) : Json(nullptr);
  }
  j["cheapest_reaching_error"] = std::move(cheapest);
  return j.dump(2);
}

std::string DesignWorkPrecisionJson(const DesignWorkPrecisionResult& study, const Scene& scene) {
  Json j;
  j["study"] = "design";
  j["scene"] = Json::parse(SceneJson(scene));
  Json list = Json::array();
  for (const DesignWorkPrecisionPoint& p : study.points) list.push_back(DesignPointJson(p));
  j["points"] = std::move(list);
  j["message"] = study.message;
  return j.dump(2);
}

}  // namespace covopt::report
