// A design answer as JSON text (covopt optimize --json, covopt.optimize()).
#include "covopt/report/design_json.hpp"

#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "covopt/report/simulation_json.hpp"
#include "oracle_json.hpp"

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

ordered_json ScoreJson(const DesignScore& s) {
  return {{"laceration_ratio", s.laceration_ratio},
          {"contusion_ratio", s.contusion_ratio},
          {"max_tensile_stress_Pa", s.peaks.max_tensile_stress_Pa},
          {"max_energy_density_J_per_m2", s.peaks.max_energy_density_J_per_m2},
          {"fully_compressed", s.peaks.fully_compressed},
          {"compression_ratio", s.compression_ratio}};
}


ordered_json CandidateJson(const CandidateOutcome& c) {
  ordered_json j = {{"material", c.material.name},
                    {"family", c.material.family},
                    {"youngs_modulus_Pa", c.material.youngs_modulus_Pa},
                    {"poisson_ratio", c.material.poisson_ratio},
                    {"poisson_assumed", c.material.poisson_assumed},
                    {"min_safe_thickness_m", Nullable(c.min_safe_thickness_m)},
                    {"thickness_m", Nullable(c.recommended_thickness_m)},
                    {"evaluated_thickness_m", c.score.design.thickness_m},
                    {"stock_thickness_beyond_max_m", Nullable(c.stock_thickness_beyond_max_m)},
                    {"safe", c.safe},
                    {"margin", c.margin}};
  j.update(ScoreJson(c.score));
  return j;
}

}  // namespace

std::string DesignJson(const optim::DesignRequest& request, const optim::DesignResult& result,
                       std::span<const std::string> input_warnings, int indent) {
  const double sf = request.options.safety_factor;
  const optim::DesignCriterion criterion = result.criterion;
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
  j["criterion"] = optim::ToString(criterion);
  j["verdict"] = optim::ToString(verdict);
  j["summary"] = headline;
  if (recommended) {
    const CandidateOutcome& c = *recommended;
    ordered_json rec = {{"material", c.material.name},
                        {"family", c.material.family},
                        {"thickness_m", *c.recommended_thickness_m},
                        {"min_safe_thickness_m", Nullable(c.min_safe_thickness_m)},
                        {"stock_thickness_beyond_max_m", Nullable(c.stock_thickness_beyond_max_m)},
                        {"youngs_modulus_Pa", c.material.youngs_modulus_Pa},
                        {"poisson_ratio", c.material.poisson_ratio},
                        {"poisson_assumed", c.material.poisson_assumed},
                        {"laceration_ratio", c.score.laceration_ratio},
                        {"contusion_ratio", c.score.contusion_ratio},
                        {"margin", c.margin},
                        {"safe", c.safe},
                        {"fully_compressed", c.score.peaks.fully_compressed},
                        {"compression_ratio", c.score.compression_ratio}};
    j["recommendation"] = rec;
  } else {
    j["recommendation"] = nullptr;
  }
  j["continuous_optimum"] = {{"youngs_modulus_Pa", continuous.score.design.youngs_modulus_Pa},
                             {"thickness_m", continuous.score.design.thickness_m},
                             {"poisson_ratio", continuous.score.poisson_ratio},
                             {"laceration_ratio", continuous.score.laceration_ratio},
                             {"contusion_ratio", continuous.score.contusion_ratio},
                             {"safe", continuous.score.safe(sf)},
                             {"admissible", continuous.score.admissible(sf, criterion)},
                             {"fully_compressed", continuous.score.peaks.fully_compressed},
                             {"compression_ratio", continuous.score.compression_ratio},
                             {"every_modulus_fully_compressed", continuous.every_modulus_fully_compressed},
                             {"needed", !bare_safe},
                             {"source", continuous.source}};
  j["bare_robot"] = {{"laceration_ratio", bare.laceration_ratio},
                     {"contusion_ratio", bare.contusion_ratio},
                     {"safe", bare_safe}};
  ordered_json list = ordered_json::array();
  for (const CandidateOutcome& c : candidates) list.push_back(CandidateJson(c));
  j["candidates"] = list;
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
