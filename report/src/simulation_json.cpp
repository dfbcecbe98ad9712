#include "covopt/report/simulation_json.hpp"

#include <cmath>
#include <string_view>
#include <utility>

#include <nlohmann/json.hpp>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/result_summary.hpp"
#include "json_number.hpp"
#include "summary_object.hpp"
#include "verdict_object.hpp"

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
                   {"thickness_m", Number(s.covering.thickness_m)},
                   {"law", ToString(s.covering.law)}};
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

/// One criterion of the verdict as the simulation's flat keys (value<unit>, limit<unit>,
/// ratio, safe, derated_limit<unit>, safety_factor); null when the verdict has no such
/// criterion or its limit is unknown.
Json CriterionObject(const Criterion* c, std::string_view unit, double safety_factor) {
  if (c == nullptr || !std::isfinite(c->limit)) return Json(nullptr);
  const std::string u(unit);
  return Json{{"value" + u, Number(c->value)},         {"limit" + u, Number(c->limit)},
              {"ratio", Number(c->ratio)},             {"safe", c->passed},
              {"derated_limit" + u, Number(c->derated_limit)}, {"safety_factor", safety_factor}};
}

/// The fracture criterion of the verdict (docs/model.md §7.1) with the struck area, the
/// published range and the source; null when absent.
Json FractureObject(const Verdict& v, HeadArea area) {
  const Criterion* c = v.Find("fracture");
  if (c == nullptr) return Json(nullptr);
  const FractureForce& row = FractureForceOf(area);
  // The criterion's source is the area's citation, unless the caller gave the force
  // (optim::HeadVerdict decides which, once).
  const bool published = c->source == row.source;
  Json j = {{"area", row.name}};
  j.update(CriterionObject(c, "_N", v.safety_factor));
  j["published_range"] = published ? Json(row.range) : Json(nullptr);
  j["source"] = std::string(c->source);
  return j;
}

}  // namespace

std::string SimulationJson(const SimulationReport& report, int indent) {
  const ImpactResult& r = report.result;
  const ImpactPeaks& p = r.peaks;
  const Verdict& v = report.verdict;

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
  // The covering's law ("" bare) and whether the peak is within what it describes.
  j["covering_law"] = report.scene.covering.thickness_m > 0.0 ? std::string(ToString(p.covering_law)) : std::string();
  j["validity"] = {{"within", r.validity.within}, {"note", r.validity.note}};
  // The limits stay the limits; the derated ones and the factor join each criterion.
  j["laceration"] = CriterionObject(v.Find("laceration"), "_Pa", v.safety_factor);
  j["contusion"] = CriterionObject(v.Find("contusion"), "_J_per_m2", v.safety_factor);
  j["fracture"] = FractureObject(v, report.scene.head.area);
  j["crush"] = CriterionObject(v.Find("crush"), "_Pa", v.safety_factor);
  j["safe"] = report.safe();
  j["verdict"] = internal::VerdictObject(v);
  j["summary"] = internal::SummaryObject(
      SummarizeImpact(report.scene, r, v, report.covering_material.value_or(std::string())));
  j["scope"] = v.scope;
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
