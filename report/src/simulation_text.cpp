#include "covopt/report/simulation_text.hpp"

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/quantity.hpp"
#include "covopt/core/time_integration.hpp"
#include "covopt/core/result_summary.hpp"
#include "covopt/report/summary_json.hpp"
#include "covopt/report/verdict_text.hpp"

namespace covopt::report {
namespace {

std::string_view YesNo(bool b) { return b ? "yes" : "no"; }

std::string Mass(double kg) { return FormatQuantity(kg, QuantityKind::kMass); }
std::string Length(double m) { return FormatQuantity(m, QuantityKind::kLength); }
std::string Modulus(double pa) { return FormatQuantity(pa, QuantityKind::kModulus); }

/// One "label   value unit" row; only the ASCII label is padded.
void Row(std::ostream& out, std::string_view label, std::string_view value) {
  fmt::print(out, "  {:<24} {}\n", label, value);
}

/// The scene: two lines, and one more with the inputs beyond the paper's two-mass scene.
void PrintScene(std::ostream& out, const SimulationReport& report) {
  const Scene& s = report.scene;
  const std::string covering =
      s.covering.thickness_m > 0.0
          ? fmt::format("covering {}{}, E {}, ν {:g}{}", Length(s.covering.thickness_m),
                        report.covering_material
                            ? fmt::format(" '{}'", *report.covering_material)
                            : std::string(),
                        Modulus(s.covering.youngs_modulus_Pa), s.covering.poisson_ratio,
                        report.covering_poisson_assumed ? " (assumed)" : "")
          : std::string("no covering");
  // The speed belongs to the body that moves: a fixed robot has the head dropped onto it.
  const bool robot_fixed = std::isinf(s.robot.mass_kg);
  const bool head_fixed = std::isinf(s.head.mass_kg);
  const std::string robot =
      robot_fixed ? std::string("fixed robot")
                  : fmt::format("robot {} at {:g} m/s", Mass(s.robot.mass_kg), s.robot.speed_m_per_s);
  const std::string head =
      head_fixed    ? std::string(robot_fixed ? "head fixed" : "head fixed (hit by the robot)")
      : robot_fixed ? fmt::format("head {} dropped onto the robot at {:g} m/s", Mass(s.head.mass_kg),
                                  s.robot.speed_m_per_s)
                    : fmt::format("head {}", Mass(s.head.mass_kg));
  fmt::print(out, "Scene   {}, R {}, E {}, ν {:g}; {}\n", robot, Length(s.robot.radius_m),
             Modulus(s.robot.youngs_modulus_Pa), s.robot.poisson_ratio, covering);
  fmt::print(out,
             "        {}, R {}; scalp {}, E {}, ν {:g}; skull E {}, ν {:g}; {} thresholds\n",
             head, Length(s.head.radius_m), Length(s.scalp.thickness_m),
             Modulus(s.scalp.youngs_modulus_Pa), s.scalp.poisson_ratio,
             Modulus(s.skull.youngs_modulus_Pa), s.skull.poisson_ratio,
             ToString(s.model.thresholds));
  // The inputs beyond the paper's conservative two-mass scene (docs/model.md §10), when set.
  std::vector<std::string> extended;
  if (s.is_damped()) {
    extended.push_back(fmt::format(
        "contact damping {}", FormatQuantity(s.model.damping_s_per_m, QuantityKind::kDampingCoefficient)));
  }
  if (s.robot_brakes()) {
    extended.push_back(fmt::format(
        "the robot brakes at {} from {} after first contact",
        FormatQuantity(s.robot.braking_m_per_s2, QuantityKind::kAcceleration),
        FormatQuantity(s.robot.reaction_delay_s, QuantityKind::kTime)));
  } else if (s.robot.reaction_delay_s > 0.0) {
    extended.push_back(fmt::format("reaction delay {} (no braking)",
                                   FormatQuantity(s.robot.reaction_delay_s, QuantityKind::kTime)));
  }
  if (s.head.has_neck()) {
    extended.push_back(fmt::format(
        "neck to a torso {}: stiffness {}, damping {}",
        std::isinf(s.head.torso_mass_kg) ? std::string("held fixed") : Mass(s.head.torso_mass_kg),
        FormatQuantity(s.head.neck_stiffness_N_per_m, QuantityKind::kStiffness),
        FormatQuantity(s.head.neck_damping_N_s_per_m, QuantityKind::kViscousDamping)));
  }
  if (!extended.empty()) fmt::print(out, "        {}\n", fmt::join(extended, "; "));
}

/// The peaks of the contact.
void PrintPeaks(std::ostream& out, const SimulationReport& report) {
  const Scene& s = report.scene;
  const ImpactResult& r = report.result;
  const ImpactPeaks& p = r.peaks;
  fmt::print(out, "\nPeaks\n");
  Row(out, "max penetration", fmt::format("{:.6g} mm", p.max_penetration_m * 1e3));
  Row(out, "peak force", fmt::format("{:.6g} N", p.peak_force_N));
  if (r.contact_duration_s) {
    Row(out, "contact duration", fmt::format("{:.6g} ms", *r.contact_duration_s * 1e3));
  }
  if (r.time_of_max_compression_s) {
    Row(out, "time of max compression",
        fmt::format("{:.6g} ms", *r.time_of_max_compression_s * 1e3));
  }
  Row(out, "max compressive stress", fmt::format("{:.6g} MPa", p.max_compressive_stress_Pa / 1e6));
  Row(out, "max tensile stress", fmt::format("{:.6g} MPa", p.max_tensile_stress_Pa / 1e6));
  Row(out, "max energy density",
      fmt::format("{:.6g} J/cm²", p.max_energy_density_J_per_m2 / 1e4));
  if (r.rebound_speed_m_per_s) {
    // The coefficient of restitution is 1 in the conservative model; it is shown where
    // damping, braking or a neck make it differ.
    const bool restitution = r.coefficient_of_restitution && !s.is_conservative_two_mass();
    Row(out, "rebound speed",
        fmt::format("{:.6g} m/s{}", *r.rebound_speed_m_per_s,
                    restitution ? fmt::format(" (coefficient of restitution {:.6g})",
                                              *r.coefficient_of_restitution)
                                : std::string()));
  }
  Row(out, "phase at max",
      fmt::format("{} ({})", PhaseNumber(p.phase_at_max), ToString(p.phase_at_max)));
  Row(out, "scalp fully compressed", YesNo(p.scalp_fully_compressed));
  Row(out, "fully compressed", YesNo(p.fully_compressed));
  Row(out, "covering law", r.validity.note);
}

/// The method, and the integrator's statistics on the time path.
void PrintMethod(std::ostream& out, const SimulationReport& report) {
  const ImpactResult& r = report.result;
  fmt::print(out, "\nMethod  {}", ToString(r.method));
  if (report.time_options) {
    const TimeIntegrationOptions& o = *report.time_options;
    fmt::print(out, ", rtol {:g}, atol {:g}", o.relative_tolerance,
               o.absolute_tolerance > 0.0 ? o.absolute_tolerance : o.relative_tolerance);
    const SolverStatistics& st = r.statistics;
    fmt::print(out, "\nSolver  {}: {} steps, {} rhs evaluations, {} root evaluations, "
                    "{} Jacobian evaluations,\n        {} nonlinear iterations, "
                    "{} error-test failures, {} convergence failures, {} restarts",
               ToString(r.status), st.steps, st.rhs_evaluations, st.root_evaluations,
               st.jacobian_evaluations, st.nonlinear_iterations, st.error_test_failures,
               st.convergence_failures, st.restarts);
    if (r.energy_residual) fmt::print(out, ";\n        energy residual {:.2g} (self-check)", *r.energy_residual);
    if (!r.history.empty()) fmt::print(out, "; {} history samples", r.history.size());
  } else {
    fmt::print(out, " (energy balance and quadrature, no time integration)");
  }
  fmt::print(out, "\n");
}

}  // namespace

void PrintTable(std::ostream& out, const SimulationReport& report) {
  PrintScene(out, report);
  PrintPeaks(out, report);
  const ResultSummary summary = SummarizeImpact(report.scene, report.result, report.verdict,
                                                report.covering_material.value_or(std::string()));
  // The summary, then each criterion in detail (VerdictLines without its overall line, which
  // the summary's first line replaces).
  fmt::print(out, "\nVerdict\n{}", SummaryText(summary, 2, false));
  std::vector<std::string> lines = VerdictLines(report.verdict);
  lines.pop_back();
  for (const std::string& line : lines) fmt::print(out, "{}\n", line);
  PrintMethod(out, report);
  const ImpactResult& r = report.result;
  if (!report.verdict.scope.empty()) {
    fmt::print(out, "\nScope\n");
    for (const std::string& line : report.verdict.scope) fmt::print(out, "  {}\n", line);
  }
  if (r.warnings.empty() && report.input_warnings.empty()) {
    fmt::print(out, "\nWarnings: none\n");
  } else {
    fmt::print(out, "\nWarnings\n");
    for (const ValidityWarning& warning : r.warnings) fmt::print(out, "  - {}\n", warning.message);
    for (const std::string& warning : report.input_warnings) fmt::print(out, "  - {}\n", warning);
  }
}

}  // namespace covopt::report
