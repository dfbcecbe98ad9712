#include "covopt/report/simulation_json.hpp"

#include <cmath>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

#include "covopt/core/impact_model.hpp"
#include "json_number.hpp"
#include "limits_json.hpp"

namespace covopt::report {
namespace {

using Json = nlohmann::ordered_json;
using internal::Number;

/// A mass or radius that may be infinite: the word the CLI accepts for it.
Json MaybeInfinite(double value, std::string_view word) {
  if (std::isinf(value) && value > 0) return Json(word);
  return Number(value);
}

Json SceneObject(const Scene& s) {
  Json j;
  j["robot"] = {{"mass_kg", MaybeInfinite(s.robot.mass_kg, "fixed")},
                {"speed_m_per_s", Number(s.robot.speed_m_per_s)},
                {"radius_m", MaybeInfinite(s.robot.radius_m, "flat")},
                {"youngs_modulus_Pa", Number(s.robot.youngs_modulus_Pa)},
                {"poisson_ratio", Number(s.robot.poisson_ratio)},
                {"reaction_delay_s", Number(s.robot.reaction_delay_s)},
                {"braking_m_per_s2", Number(s.robot.braking_m_per_s2)}};
  j["covering"] = {{"youngs_modulus_Pa", Number(s.covering.youngs_modulus_Pa)},
                   {"poisson_ratio", Number(s.covering.poisson_ratio)},
                   {"thickness_m", Number(s.covering.thickness_m)}};
  j["head"] = {{"mass_kg", MaybeInfinite(s.head.mass_kg, "fixed")},
               {"radius_m", Number(s.head.radius_m)},
               {"torso_mass_kg", MaybeInfinite(s.head.torso_mass_kg, "fixed")},
               {"neck_stiffness_N_per_m", Number(s.head.neck_stiffness_N_per_m)},
               {"neck_damping_N_s_per_m", Number(s.head.neck_damping_N_s_per_m)},
               {"area", ToString(s.head.area)}};
  j["scalp"] = {{"youngs_modulus_Pa", Number(s.scalp.youngs_modulus_Pa)},
                {"poisson_ratio", Number(s.scalp.poisson_ratio)},
                {"thickness_m", Number(s.scalp.thickness_m)}};
  j["skull"] = {{"youngs_modulus_Pa", Number(s.skull.youngs_modulus_Pa)},
                {"poisson_ratio", Number(s.skull.poisson_ratio)}};
  j["model"] = {{"thresholds", ToString(s.model.thresholds)},
                {"exponent_covering_scalp", Number(s.model.exponent_covering_scalp)},
                {"exponent_covering_bone", Number(s.model.exponent_covering_bone)},
                {"exponent_robot_bone", Number(s.model.exponent_robot_bone)},
                {"tensile_poisson_ratio", Number(s.model.tensile_poisson_ratio)},
                {"full_compression_fraction", Number(s.model.full_compression_fraction)},
                {"damping_s_per_m", Number(s.model.damping_s_per_m)}};
  return j;
}

Json StatisticsObject(const SolverStatistics& st) {
  return Json{{"steps", st.steps},
              {"rhs_evaluations", st.rhs_evaluations},
              {"root_evaluations", st.root_evaluations},
              {"jacobian_evaluations", st.jacobian_evaluations},
              {"nonlinear_iterations", st.nonlinear_iterations},
              {"error_test_failures", st.error_test_failures},
              {"convergence_failures", st.convergence_failures},
              {"restarts", st.restarts}};
}

}  // namespace

InjuryAssessment JudgeInjuries(const ImpactPeaks& peaks, const InjuryLimits& limits, double safety_factor,
                               HeadArea area) noexcept {
  InjuryAssessment assessment = Assess(peaks, limits, area);
  for (InjuryVerdict* verdict : {&assessment.laceration, &assessment.contusion, &assessment.fracture}) {
    verdict->safe = safety_factor * verdict->ratio <= 1.0;
  }
  return assessment;
}

std::string SimulationJson(const SimulationReport& report, int indent) {
  const ImpactResult& r = report.result;
  const ImpactPeaks& p = r.peaks;
  const InjuryVerdict& lac = report.assessment.laceration;
  const InjuryVerdict& con = report.assessment.contusion;

  Json j;
  j["max_penetration_m"] = Number(p.max_penetration_m);
  j["peak_force_N"] = Number(p.peak_force_N);
  j["contact_duration_s"] = Number(r.contact_duration_s);
  j["time_of_max_compression_s"] = Number(r.time_of_max_compression_s);
  j["max_compressive_stress_Pa"] = Number(p.max_compressive_stress_Pa);
  j["max_tensile_stress_Pa"] = Number(p.max_tensile_stress_Pa);
  j["max_energy_density_J_per_m2"] = Number(p.max_energy_density_J_per_m2);
  j["rebound_speed_m_per_s"] = Number(r.rebound_speed_m_per_s);
  j["coefficient_of_restitution"] = Number(r.coefficient_of_restitution);
  j["phase_at_max"] = PhaseNumber(p.phase_at_max);
  j["phase_at_max_name"] = ToString(p.phase_at_max);
  j["scalp_fully_compressed"] = p.scalp_fully_compressed;
  j["fully_compressed"] = p.fully_compressed;
  // The limits stay the limits; the derated ones and the factor join each verdict.
  j["laceration"] = {{"value_Pa", Number(lac.value)},
                     {"limit_Pa", Number(lac.limit)},
                     {"ratio", Number(lac.ratio)},
                     {"safe", lac.safe},
                     {"derated_limit_Pa", Number(lac.limit / report.safety_factor)},
                     {"safety_factor", report.safety_factor}};
  j["contusion"] = {{"value_J_per_m2", Number(con.value)},
                    {"limit_J_per_m2", Number(con.limit)},
                    {"ratio", Number(con.ratio)},
                    {"safe", con.safe},
                    {"derated_limit_J_per_m2", Number(con.limit / report.safety_factor)},
                    {"safety_factor", report.safety_factor}};
  j["fracture"] = internal::FractureJson(report.assessment, report.safety_factor);
  j["crush"] = report.crush ? Json{{"value_Pa", Number(report.crush->value)},
                                    {"limit_Pa", Number(report.crush->limit)},
                                    {"ratio", Number(report.crush->ratio)},
                                    {"safe", report.crush->safe},
                                    {"derated_limit_Pa", Number(report.crush->limit / report.safety_factor)},
                                    {"safety_factor", report.safety_factor}}
                             : Json(nullptr);
  j["safe"] = report.safe();
  j["scope"] = report.scope;
  j["method"] = ToString(r.method);

  Json solver = {{"status", ToString(r.status)}, {"message", r.message}, {"raw_code", r.raw_code}};
  solver.update(StatisticsObject(r.statistics));
  if (report.time_options) {
    const TimeIntegrationOptions& o = *report.time_options;
    solver["relative_tolerance"] = Number(o.relative_tolerance);
    solver["absolute_tolerance"] =
        Number(o.absolute_tolerance > 0.0 ? o.absolute_tolerance : o.relative_tolerance);
    solver["history_samples"] = r.history.size();
    if (r.energy_residual) solver["energy_residual"] = Number(*r.energy_residual);
  }
  j["solver"] = std::move(solver);
  j["scene"] = SceneObject(report.scene);
  j["scene"]["covering"]["material"] =
      report.covering_material ? Json(*report.covering_material) : Json(nullptr);
  Json warnings = Json::array();  // the result's, then the input's
  Json codes = Json::array();     // the stable code of each of the result's warnings (core's list)
  for (const ValidityWarning& w : r.warnings) {
    warnings.push_back(w.message);
    codes.push_back(std::string(ToString(w.code)));
  }
  for (const std::string& w : report.input_warnings) warnings.push_back(w);
  j["warnings"] = std::move(warnings);
  j["warning_codes"] = std::move(codes);
  return j.dump(indent);
}

std::string SceneJson(const Scene& scene, int indent) { return SceneObject(scene).dump(indent); }

std::string SolverStatisticsJson(const SolverStatistics& statistics, int indent) {
  return StatisticsObject(statistics).dump(indent);
}

}  // namespace covopt::report
