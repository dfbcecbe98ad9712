// Robust design over an uncertainty box as JSON text (docs/model.md §11).
#include "covopt/report/robust_json.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "covopt/core/quantity.hpp"
#include "covopt/optim/robust_summary.hpp"
#include "json_number.hpp"
#include "limits_json.hpp"
#include "summary_object.hpp"

namespace covopt::report {
namespace {

using internal::Number;
using nlohmann::ordered_json;

std::string Unit(const optim::UncertaintyBox& box, std::size_t i) {
  return std::string(SiUnit(box.field(i).spec.kind));
}

ordered_json InputsJson(const optim::UncertaintyBox& box) {
  ordered_json inputs = ordered_json::array();
  for (std::size_t i = 0; i < box.size(); ++i) {
    const optim::UncertainInput& input = box.inputs()[i];
    const bool shaped = input.distribution != optim::InputDistribution::kUniform;
    inputs.push_back({{"field", input.field},
                      {"unit", Unit(box, i)},
                      {"low", Number(input.low)},
                      {"high", Number(input.high)},
                      {"distribution", optim::ToString(input.distribution)},
                      {"mean", shaped ? Number(input.mean) : ordered_json(nullptr)},
                      {"standard_deviation", shaped ? Number(input.standard_deviation) : ordered_json(nullptr)}});
  }
  return inputs;
}

/// {inputs: {field: value}, units: {field: unit}} for values in the box's order.
ordered_json ValuesJson(const optim::UncertaintyBox& box, const std::vector<double>& values) {
  ordered_json inputs = ordered_json::object(), units = ordered_json::object();
  for (std::size_t i = 0; i < box.size() && i < values.size(); ++i) {
    inputs[box.inputs()[i].field] = Number(values[i]);
    units[box.inputs()[i].field] = Unit(box, i);
  }
  return {{"inputs", inputs}, {"units", units}};
}

ordered_json TimePathJson(const optim::TimePathUse& use) {
  ordered_json j;
  j["runs"] = use.runs;
  j["screened"] = use.screened;
  j["brake_after_peak"] = use.brake_after_peak;
  j["failed"] = use.failed;
  j["first_failure"] = use.first_failure;
  return j;
}

ordered_json WorstJson(const optim::UncertaintyBox& box, const optim::WorstCase& w) {
  ordered_json j = ValuesJson(box, w.values);
  j["laceration_ratio"] = Number(w.laceration_ratio);
  j["contusion_ratio"] = Number(w.contusion_ratio);
  j["compression_ratio"] = Number(w.compression_ratio);
  j["crush_ratio"] = Number(w.crush_ratio);
  j["fracture_ratio"] = Number(w.fracture_ratio);
  j["fully_compressed"] = w.fully_compressed;
  j["governing_ratio"] = Number(w.governing_ratio);
  j["binding"] = optim::ToString(w.binding);
  j["admissible"] = w.admissible;
  j["corner_governing_ratio"] = Number(w.corner_governing_ratio);
  j["found_by"] = w.found_by;
  j["evaluations"] = w.evaluations;
  j["time_path"] = TimePathJson(w.time_path);
  j["seconds"] = w.seconds;
  return j;
}

ordered_json Interval(const optim::ProbabilityEstimate& e) { return ordered_json::array({e.ci95_low, e.ci95_high}); }

ordered_json ProbabilityJson(const optim::InjuryProbability& p) {
  const std::pair<const char*, const optim::ProbabilityEstimate*> events[] = {
      {"laceration", &p.laceration}, {"contusion", &p.contusion},
      {"fracture", &p.fracture},     {"any", &p.any},
      {"fully_compressed", &p.fully_compressed}, {"crushed", &p.crushed},
      {"inadmissible", &p.inadmissible}};
  ordered_json j = {{"samples", p.any.samples}, {"seed", p.seed}};
  ordered_json ci = ordered_json::object(), counts = ordered_json::object();
  for (const auto& [name, estimate] : events) {
    j[name] = estimate->probability;
    ci[name] = Interval(*estimate);
    counts[name] = estimate->count;
  }
  j["ci95"] = ci;
  j["counts"] = counts;
  return j;
}

ordered_json ElasticityJson(const optim::ElasticityTable& t) {
  ordered_json rows = ordered_json::array();
  for (const optim::InputElasticity& r : t.rows) {
    const SceneField* field = FindSceneField(r.field);
    rows.push_back({{"field", r.field},
                    {"unit", field ? std::string(SiUnit(field->spec.kind)) : std::string()},
                    {"value", Number(r.value)},
                    {"laceration", Number(r.laceration)},
                    {"contusion", Number(r.contusion)},
                    {"compression", Number(r.compression)},
                    {"method", optim::ToString(r.method)},
                    {"reliable", r.reliable},
                    {"discrepancy", Number(r.discrepancy)}});
  }
  return {{"laceration_ratio", Number(t.laceration_ratio)},
          {"contusion_ratio", Number(t.contusion_ratio)},
          {"compression_ratio", Number(t.compression_ratio)},
          {"evaluations", t.evaluations},
          {"rows", rows}};
}

ordered_json LimitsJson(const InjuryLimits& limits, double safety_factor) {
  return {{"laceration_Pa", limits.laceration_tensile_stress_Pa},
          {"contusion_J_per_m2", limits.contusion_energy_density_J_per_m2},
          {"safety_factor", safety_factor}};
}

ordered_json MaterialJson(const optim::CandidateMaterial& m) {
  const bool crushes = m.crush_behaviour == materials::CrushBehaviour::kCrushes;
  return {{"material", m.name},
          {"family", m.family},
          {"youngs_modulus_Pa", m.youngs_modulus_Pa},
          {"poisson_ratio", m.poisson_ratio},
          {"poisson_assumed", m.poisson_assumed},
          {"crush_behaviour", materials::ToString(m.crush_behaviour)},
          {"compressive_strength_Pa", crushes ? ordered_json(m.compressive_strength_Pa) : ordered_json(nullptr)}};
}

std::string Dump(const ordered_json& j, int indent) { return j.dump(indent); }

/// What a limit over the box adds after its value: status, limited_by, message, worst_case
/// {inputs, units}, found_by, evaluations, seconds.
template <typename Limit>
void AddLimitOverBox(ordered_json& j, const optim::UncertaintyBox& box, const Limit& limit) {
  j["status"] = optim::ToString(limit.limit.status);
  j["limited_by"] = optim::ToString(limit.limit.limited_by);
  j["message"] = limit.limit.message;
  j["worst_case"] = ValuesJson(box, limit.values);
  j["found_by"] = limit.found_by;
  j["evaluations"] = limit.evaluations;
  j["seconds"] = limit.seconds;
}

ordered_json SpeedLimitOverBoxJson(const optim::UncertaintyBox& box, const optim::RobustSpeedLimit& limit) {
  ordered_json j;
  const bool limited = limit.limit.status != optim::SpeedLimitStatus::kNoSafeValue;
  j["speed_limit_m_per_s"] = limited ? Number(limit.limit.max_safe_speed_m_per_s) : ordered_json(nullptr);
  AddLimitOverBox(j, box, limit);
  return j;
}

ordered_json MassLimitOverBoxJson(const optim::UncertaintyBox& box, double speed_m_per_s,
                                  const optim::RobustMassLimit& limit) {
  ordered_json j;
  j["speed_m_per_s"] = speed_m_per_s;
  j["max_safe_mass_kg"] =
      std::isfinite(limit.limit.max_safe_mass_kg) ? ordered_json(limit.limit.max_safe_mass_kg) : ordered_json(nullptr);
  AddLimitOverBox(j, box, limit);
  return j;
}

}  // namespace

std::string UncertainInputsJson(const optim::UncertaintyBox& box, int indent) {
  return Dump(InputsJson(box), indent);
}

std::string WorstCaseJson(const optim::UncertaintyBox& box, const optim::WorstCase& worst, int indent) {
  return Dump(WorstJson(box, worst), indent);
}

std::string InjuryProbabilityJson(const optim::InjuryProbability& probability, int indent) {
  return Dump(ProbabilityJson(probability), indent);
}

std::string ElasticitiesJson(const optim::ElasticityTable& table, int indent) {
  return Dump(ElasticityJson(table), indent);
}

std::string UncertainSimulationJson(const SimulationReport& impact, const optim::UncertaintyBox* box,
                                    const optim::WorstCase* worst, const optim::InjuryProbability* probability,
                                    const optim::ElasticityTable* sensitivities, int indent) {
  ordered_json j = ordered_json::parse(SimulationJson(impact, -1));
  j["uncertain_inputs"] = box ? InputsJson(*box) : ordered_json(nullptr);
  j["worst_case"] = box && worst ? WorstJson(*box, *worst) : ordered_json(nullptr);
  j["injury_probability"] = probability ? ProbabilityJson(*probability) : ordered_json(nullptr);
  j["sensitivities"] = sensitivities ? ElasticityJson(*sensitivities) : ordered_json(nullptr);
  return Dump(j, indent);
}

std::string RobustDesignJson(const optim::UncertaintyBox& box, const optim::RobustDesignOptions& options,
                             const optim::RobustThinnestCovering& result,
                             const optim::InjuryProbability* recommended_probability,
                             std::span<const std::string> warnings, int indent) {
  ordered_json j;
  j["problem"] = "robust-thinnest";
  j["criterion"] = internal::CriterionJson(options.design.rule());
  j["scope"] = optim::HeadVerdictScope(options.design.rule());
  j["verdict"] = optim::ToString(result.verdict);
  ordered_json rec = nullptr, setting = nullptr;
  if (result.recommendation) {
    const optim::RobustCandidate& c = result.candidates[*result.recommendation];
    rec = MaterialJson(c.outcome.material);
    rec["thickness_m"] = Number(c.outcome.recommended_thickness_m);
    rec["min_safe_thickness_m"] = Number(c.outcome.min_safe_thickness_m);
    rec["laceration_ratio"] = c.worst_case.laceration_ratio;
    rec["contusion_ratio"] = c.worst_case.contusion_ratio;
    rec["crush_ratio"] = c.outcome.score.crush_check == optim::CrushCheck::kChecked
                             ? ordered_json(c.worst_case.crush_ratio)
                             : ordered_json(nullptr);
    rec["governing_criterion"] = optim::ToString(c.worst_case.binding, c.outcome.score.peaks.covering_law);
    rec["governing_ratio"] = c.worst_case.governing_ratio;
    rec["margin"] = c.outcome.margin;
    rec.update(internal::LawAndValidityJson(c.outcome.score));
    rec["worst_case"] = WorstJson(box, c.worst_case);
    rec["worst_case_at_thinnest"] =
        c.worst_case_at_thinnest ? WorstJson(box, *c.worst_case_at_thinnest) : ordered_json(nullptr);
    setting = c.worst_case_at_thinnest ? WorstJson(box, *c.worst_case_at_thinnest) : WorstJson(box, c.worst_case);
  }
  std::string summary;
  if (result.recommendation) {
    const optim::RobustCandidate& c = result.candidates[*result.recommendation];
    summary = "robust covering: " + c.outcome.material.name + ", admissible for every value in the box";
  } else if (result.verdict == optim::DesignVerdict::kBareRobotSafe) {
    summary = "no covering needed: the bare robot is admissible for every value in the box";
  } else {
    summary = "no catalog material is admissible for every value in the box within the maximum thickness";
  }
  j["message"] = summary;
  j["summary"] = internal::SummaryObject(optim::SummarizeRobustDesign(options, result, box.nominal().head.area));
  j["uncertain_inputs"] = InputsJson(box);
  j["recommendation"] = rec;
  j["worst_case"] = setting;
  if (result.continuous) {
    const optim::RobustContinuousOptimum& c = *result.continuous;
    j["continuous_optimum"] = {{"feasible", c.feasible},
                               {"youngs_modulus_Pa", c.design.youngs_modulus_Pa},
                               {"thickness_m", c.design.thickness_m},
                               {"worst_case", WorstJson(box, c.worst_case)},
                               {"scenario_rounds", c.scenario_rounds},
                               {"unconfirmed", c.unconfirmed}};
  } else {
    j["continuous_optimum"] = nullptr;
  }
  j["bare_robot"] = WorstJson(box, result.bare_robot);
  ordered_json candidates = ordered_json::array();
  for (const optim::RobustCandidate& c : result.candidates) {
    ordered_json row = MaterialJson(c.outcome.material);
    row["min_safe_thickness_m"] = Number(c.outcome.min_safe_thickness_m);
    row["thickness_m"] = Number(c.outcome.recommended_thickness_m);
    row["evaluated_thickness_m"] = c.outcome.score.design.thickness_m;
    row["safe"] = c.outcome.safe;
    row["governing_criterion"] = optim::ToString(c.worst_case.binding, c.outcome.score.peaks.covering_law);
    row["governing_ratio"] = c.worst_case.governing_ratio;
    row["margin"] = c.outcome.margin;
    row["scenario_rounds"] = c.scenario_rounds;
    row["unconfirmed"] = c.unconfirmed;
    row.update(internal::LawAndValidityJson(c.outcome.score));
    row["worst_case"] = WorstJson(box, c.worst_case);
    candidates.push_back(row);
  }
  j["candidates"] = candidates;
  ordered_json scenarios = ordered_json::array();
  for (const std::vector<double>& s : result.initial_scenarios) scenarios.push_back(ValuesJson(box, s)["inputs"]);
  j["initial_scenarios"] = scenarios;
  j["injury_probability"] = recommended_probability ? ProbabilityJson(*recommended_probability) : ordered_json(nullptr);
  j["limits"] = LimitsJson(options.design.limits, options.design.safety_factor);
  j["evaluations"] = result.evaluations;
  j["time_path"] = TimePathJson(result.time_path);
  j["seconds"] = result.seconds;
  j["warnings"] = std::vector<std::string>(warnings.begin(), warnings.end());
  return Dump(j, indent);
}

std::string ProbabilityDesignJson(const optim::UncertaintyBox& box, const optim::ProbabilityDesignOptions& options,
                                  const optim::ProbabilityDesign& result, std::span<const std::string> warnings,
                                  int indent) {
  const auto half_width = [](const optim::InjuryProbability& p) {
    return 0.5 * (p.inadmissible.ci95_high - p.inadmissible.ci95_low);
  };
  ordered_json j;
  j["problem"] = "probability";
  j["criterion"] = internal::CriterionJson(options.design.rule());
  j["scope"] = optim::HeadVerdictScope(options.design.rule());
  j["verdict"] = optim::ToString(result.verdict);
  j["summary"] = internal::SummaryObject(optim::SummarizeProbabilityDesign(options, result, box.nominal().head.area));
  ordered_json rec = nullptr;
  if (result.recommendation) {
    const optim::ProbabilityCandidate& c = result.candidates[*result.recommendation];
    rec = MaterialJson(c.material);
    rec["thickness_m"] = Number(c.recommended_thickness_m);
    rec["min_thickness_m"] = Number(c.min_thickness_m);
    rec["injury_probability"] = ProbabilityJson(c.at_design);
    rec["sampling_error"] = half_width(c.at_design);
    j["message"] = "covering with P(inadmissible) <= max_probability: " + c.material.name;
  } else {
    j["message"] = result.verdict == optim::DesignVerdict::kBareRobotSafe
                       ? "no covering needed: the bare robot meets the probability target"
                       : "no catalog material meets the probability target within the maximum thickness";
  }
  j["max_probability"] = result.max_probability;
  j["target_test"] = "the upper end of the Wilson 95 % interval of P(inadmissible) is at or below max_probability";
  j["allowed_failures"] = result.allowed_failures;
  j["samples"] = options.sampling.samples;
  j["seed"] = options.sampling.seed;
  j["uncertain_inputs"] = InputsJson(box);
  j["recommendation"] = rec;
  if (result.continuous) {
    j["continuous_optimum"] = {{"feasible", result.continuous->feasible},
                               {"youngs_modulus_Pa", result.continuous->design.youngs_modulus_Pa},
                               {"thickness_m", result.continuous->design.thickness_m},
                               {"injury_probability", ProbabilityJson(result.continuous->at_design)}};
  } else {
    j["continuous_optimum"] = nullptr;
  }
  j["bare_robot"] = {{"injury_probability", ProbabilityJson(result.bare_robot)}};
  ordered_json candidates = ordered_json::array();
  for (const optim::ProbabilityCandidate& c : result.candidates) {
    ordered_json row = MaterialJson(c.material);
    row["min_thickness_m"] = Number(c.min_thickness_m);
    row["thickness_m"] = Number(c.recommended_thickness_m);
    row["meets_target"] = c.meets_target;
    row["injury_probability"] = ProbabilityJson(c.at_design);
    row["sampling_error"] = half_width(c.at_design);
    candidates.push_back(row);
  }
  j["candidates"] = candidates;
  j["limits"] = LimitsJson(options.design.limits, options.design.safety_factor);
  j["sample_evaluations"] = result.sample_evaluations;
  j["time_path"] = TimePathJson(result.time_path);
  j["seconds"] = result.seconds;
  j["warnings"] = std::vector<std::string>(warnings.begin(), warnings.end());
  return Dump(j, indent);
}

std::string RobustSpeedLimitJson(const optim::UncertaintyBox& box, const optim::RobustSpeedLimit& limit, int indent) {
  return Dump(SpeedLimitOverBoxJson(box, limit), indent);
}

std::string RobustSpeedLimitTableJson(optim::SpeedLimitQuantity quantity, const optim::UncertaintyBox& box,
                                      std::span<const optim::RobustSpeedLimitRow> rows, int indent) {
  const bool by_speed = quantity == optim::SpeedLimitQuantity::kSpeed;
  ordered_json list = ordered_json::array();
  for (const optim::RobustSpeedLimitRow& row : rows) {
    ordered_json j;
    if (row.material) j["material"] = *row.material;
    if (by_speed) {
      j["robot_mass_kg"] = std::isfinite(row.robot_mass_kg) ? ordered_json(row.robot_mass_kg) : ordered_json(nullptr);
      j.update(SpeedLimitOverBoxJson(box, row.speed_limit));
    } else {
      j.update(MassLimitOverBoxJson(box, row.speed_m_per_s, row.mass_limit));
    }
    list.push_back(j);
  }
  ordered_json j;
  j["solve_for"] = optim::ToString(quantity);
  j["uncertain_inputs"] = InputsJson(box);
  j["rows"] = list;
  return Dump(j, indent);
}

}  // namespace covopt::report
