// A design answer as JSON text (covopt optimize --json, covopt.optimize()).
#include "covopt/report/design_json.hpp"

#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "covopt/optim/summaries.hpp"
#include "covopt/report/simulation_json.hpp"
#include "design_answer_json.hpp"
#include "limits_json.hpp"
#include "oracle_json.hpp"
#include "summary_object.hpp"

namespace covopt::report {
namespace {

using nlohmann::ordered_json;
using optim::CandidateOutcome;
using optim::DesignScore;

ordered_json Nullable(const std::optional<double>& v) { return v ? ordered_json(*v) : ordered_json(nullptr); }

ordered_json SolverJson(const optim::SolverReport& r) {
  if (r.backend.empty()) return nullptr;
  return {{"backend", r.backend},
          {"termination", optim::ToString(r.termination)},
          {"raw_code", r.raw_code},
          {"raw_name", r.raw_name},
          {"objective_evaluations", r.objective_evaluations},
          {"constraint_evaluations", r.constraint_evaluations},
          {"failed_evaluations", r.failed_evaluations},
          {"seconds", r.seconds}};
}

ordered_json CandidateJson(const CandidateOutcome& c, const optim::DesignRule& rule) {
  ordered_json j = {{"material", c.material.name},
                    {"family", c.material.family},
                    {"youngs_modulus_Pa", c.material.youngs_modulus_Pa},
                    {"poisson_ratio", c.material.poisson_ratio},
                    {"poisson_assumed", c.material.poisson_assumed},
                    {"crush_behaviour", materials::ToString(c.material.crush_behaviour)},
                    {"compressive_strength_Pa",
                     c.material.crush_behaviour == materials::CrushBehaviour::kCrushes
                         ? ordered_json(c.material.compressive_strength_Pa)
                         : ordered_json(nullptr)},
                    {"min_safe_thickness_m", Nullable(c.min_safe_thickness_m)},
                    {"thickness_m", Nullable(c.recommended_thickness_m)},
                    {"evaluated_thickness_m", c.score.design.thickness_m},
                    {"stock_thickness_beyond_max_m", Nullable(c.stock_thickness_beyond_max_m)},
                    {"safe", c.safe},
                    {"margin", c.margin}};
  j.update(internal::RatiosJson(c.score, rule));
  j["has_compressive_curve"] = c.material.compressive_curve != nullptr;
  j.update(internal::LawAndValidityJson(c.score));
  return j;
}

}  // namespace

std::string DesignJson(const optim::DesignRequest& request, const optim::DesignResult& result,
                       std::span<const std::string> input_warnings, int indent) {
  const double sf = request.options.safety_factor;
  const optim::DesignCriterion criterion = result.criterion;
  const optim::DesignRule& rule = result.rule;
  const std::string& headline = result.message;
  const std::vector<CandidateOutcome>& candidates = result.candidates;
  const optim::ContinuousOptimum& continuous = result.continuous;
  const DesignScore& bare = result.bare_robot;
  const optim::DesignVerdict verdict = result.verdict;
  const bool bare_safe = !result.covering_needed();
  const optim::SolverReport& global = continuous.global;
  const optim::SolverReport& local = continuous.local;
  const optim::Termination termination =
      continuous.source == "ipopt" ? local.termination : continuous.bracket.termination;
  const long evaluations = result.evaluations;
  const double seconds = result.seconds;
  const double laceration_limit = request.options.limits.laceration_tensile_stress_Pa;
  const double contusion_limit = request.options.limits.contusion_energy_density_J_per_m2;
  std::optional<CandidateOutcome> recommended;
  if (result.recommendation) recommended = candidates[*result.recommendation];
  std::vector<std::string> warnings(input_warnings.begin(), input_warnings.end());
  warnings.insert(warnings.end(), result.warnings.begin(), result.warnings.end());
  ordered_json j;
  j["problem"] = optim::ToString(result.problem);
  j["criterion"] = internal::CriterionJson(rule);
  j["verdict"] = optim::ToString(verdict);
  j["message"] = headline;
  j["summary"] = internal::SummaryObject(optim::SummarizeDesign(request, result));
  j["scope"] = result.scope;
  if (recommended) {
    j["recommendation"] = CandidateJson(*recommended, rule);
  } else {
    j["recommendation"] = nullptr;
  }
  ordered_json optimum = {{"youngs_modulus_Pa", continuous.score.design.youngs_modulus_Pa},
                          {"thickness_m", continuous.score.design.thickness_m},
                          {"poisson_ratio", continuous.score.poisson_ratio},
                          {"safe", continuous.score.safe(sf)},
                          {"admissible", continuous.score.admissible(sf, criterion)},
                          {"margin", continuous.score.margin(rule)}};
  optimum.update(internal::RatiosJson(continuous.score, rule));
  optimum.update(internal::LawAndValidityJson(continuous.score));
  optimum["note"] = "a Hertz ideal: a modulus and a thickness, no measured curve";
  optimum["every_modulus_fully_compressed"] = continuous.every_modulus_fully_compressed;
  optimum["needed"] = !bare_safe;
  optimum["source"] = continuous.source;
  j["continuous_optimum"] = optimum;
  j["bare_robot"] = {{"laceration_ratio", bare.laceration_ratio},
                     {"contusion_ratio", bare.contusion_ratio},
                     {"max_compressive_stress_Pa", bare.peaks.max_compressive_stress_Pa},
                     {"peak_force_N", bare.peaks.peak_force_N},
                     {"safe", bare_safe}};
  ordered_json list = ordered_json::array();
  for (const CandidateOutcome& c : candidates) list.push_back(CandidateJson(c, rule));
  j["candidates"] = list;
  internal::AddDesignAnswerJson(j, result);  // material_range, nearest_changes, range_note
  j["solver"] = {{"termination", optim::ToString(termination)},
                 {"evaluations", evaluations},
                 {"seconds", seconds},
                 {"global", SolverJson(global)},
                 {"bracket", SolverJson(continuous.bracket)},
                 {"local", SolverJson(local)},
                 {"oracle", internal::OracleJson(result.oracle, true)}};
  j["safety_factor"] = sf;
  j["limits"] = {{"laceration_Pa", laceration_limit},
                 {"contusion_J_per_m2", contusion_limit},
                 {"derated_laceration_Pa", laceration_limit / sf},
                 {"derated_contusion_J_per_m2", contusion_limit / sf}};
  j["design_space"] = {{"min_modulus_Pa", request.options.space.min_modulus_Pa},
                       {"max_modulus_Pa", request.options.space.max_modulus_Pa},
                       {"min_thickness_m", request.options.space.min_thickness_m},
                       {"max_thickness_m", request.options.space.max_thickness_m},
                       {"thickness_step_m", request.options.thickness_step_m}};
  if (request.thickness_m) j["thickness_m"] = *request.thickness_m;
  Scene shown = request.scene;
  shown.covering.thickness_m = 0.0;
  ordered_json scene = ordered_json::parse(SceneJson(shown));
  scene.erase("covering");
  j["scene"] = scene;
  j["warnings"] = warnings;
  return j.dump(indent);
}

}  // namespace covopt::report
