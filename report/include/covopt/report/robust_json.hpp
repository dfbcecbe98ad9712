#pragma once
/// @file robust_json.hpp
/// Robust design over an uncertainty box (docs/model.md §11) as JSON text: the objects
/// `covopt simulate/optimize/speed-limit` print with scene ranges, and the dicts covopt's
/// Python functions worst_case(), robust_optimize(), injury_probability() and sensitivities()
/// return; both call these functions, so keys and values agree by construction. SI values;
/// an input's unit is given beside it (inputs are keyed by scene field name, "head-mass").

#include <optional>
#include <span>
#include <string>

#include "covopt/optim/robust_design.hpp"
#include "covopt/optim/speed_limit_table.hpp"
#include "covopt/report/simulation_json.hpp"

namespace covopt::report {

/// The box's inputs: [{field, unit, low, high, distribution, mean, standard_deviation}]
/// (mean and standard_deviation null for uniform).
std::string UncertainInputsJson(const optim::UncertaintyBox& box, int indent = 2);

/// A worst case: {inputs: {field: value [SI]}, units: {field: unit}, laceration_ratio,
/// contusion_ratio, compression_ratio, fully_compressed, governing_ratio, binding
/// ("laceration", "contusion", "full-compression"), admissible, corner_governing_ratio (null
/// when the corners were not enumerated), found_by, evaluations, seconds}.
std::string WorstCaseJson(const optim::UncertaintyBox& box, const optim::WorstCase& worst, int indent = 2);

/// A Monte Carlo estimate: {samples, seed, laceration, contusion, any, fully_compressed,
/// inadmissible (probabilities), ci95: {laceration: [low, high], ... the same five}, counts:
/// {laceration, ... the same five}}. No timing and no thread count, so that the object is
/// identical for any --threads.
std::string InjuryProbabilityJson(const optim::InjuryProbability& probability, int indent = 2);

/// An elasticity table: {laceration_ratio, contusion_ratio, compression_ratio (null without
/// a covering), evaluations, rows: [{field, unit, value, laceration, contusion, compression,
/// method, reliable, discrepancy}]} in the table's (tornado) order.
std::string ElasticitiesJson(const optim::ElasticityTable& table, int indent = 2);

/// What `covopt simulate` prints with ranges: SimulationJson of the impact at the worst case
/// (or at the nominal scene when no worst case is given), plus uncertain_inputs, worst_case,
/// and, when given, injury_probability and sensitivities (each null when absent).
std::string UncertainSimulationJson(const SimulationReport& impact, const optim::UncertaintyBox* box,
                                    const optim::WorstCase* worst, const optim::InjuryProbability* probability,
                                    const optim::ElasticityTable* sensitivities, int indent = 2);

/// What `covopt optimize` prints with ranges: {problem "robust-thinnest", criterion, verdict,
/// message, uncertain_inputs, recommendation (null when none: material, family, thickness_m,
/// min_safe_thickness_m, youngs_modulus_Pa, poisson_ratio, laceration_ratio, contusion_ratio,
/// margin, worst_case (at the recommended thickness), worst_case_at_thinnest),
/// worst_case (the recommendation's worst case at its thinnest admissible thickness: what sets
/// the design; null when none), continuous_optimum (null when not asked: feasible,
/// youngs_modulus_Pa, thickness_m, worst_case, scenario_rounds, unconfirmed), bare_robot
/// (worst case without a covering), candidates [...], initial_scenarios, injury_probability
/// (of the recommendation, when sampled; else null), safety_factor, limits, evaluations,
/// seconds, warnings}.
std::string RobustDesignJson(const optim::UncertaintyBox& box, const optim::RobustDesignOptions& options,
                             const optim::RobustThinnestCovering& result,
                             const optim::InjuryProbability* recommended_probability,
                             std::span<const std::string> warnings = {}, int indent = 2);

/// What `covopt optimize --max-injury-probability P` prints: {problem "probability",
/// criterion, verdict, message, max_probability, samples, seed, uncertain_inputs,
/// recommendation (null when none: material, family, thickness_m, min_thickness_m,
/// youngs_modulus_Pa, poisson_ratio, injury_probability, sampling_error (half the width of
/// the inadmissible CI)), continuous_optimum, bare_robot (injury_probability), candidates,
/// safety_factor, limits, sample_evaluations, seconds, warnings}.
std::string ProbabilityDesignJson(const optim::UncertaintyBox& box, const optim::ProbabilityDesignOptions& options,
                                  const optim::ProbabilityDesign& result, std::span<const std::string> warnings = {},
                                  int indent = 2);

/// What `covopt speed-limit` prints with ranges for one covering: {speed_limit_m_per_s (null
/// when none), limited_by, worst_case: {inputs, units}, found_by, evaluations, seconds}.
std::string RobustSpeedLimitJson(const optim::UncertaintyBox& box, const optim::RobustSpeedLimit& limit,
                                 int indent = 2);

/// What `covopt speed-limit` prints with ranges: {solve_for ("speed" or "mass"),
/// uncertain_inputs (UncertainInputsJson of `box`), rows}. Each row: material (only when
/// from the catalog), then solving for the speed robot_mass_kg (null: fixed) and
/// RobustSpeedLimitJson's keys; solving for the mass speed_m_per_s, max_safe_mass_kg (null:
/// fixed), status, limited_by, message, worst_case {inputs, units}, found_by, evaluations,
/// seconds. `box`: the box of the rows (they share its inputs; its field names and units).
std::string RobustSpeedLimitTableJson(optim::SpeedLimitQuantity quantity, const optim::UncertaintyBox& box,
                                      std::span<const optim::RobustSpeedLimitRow> rows, int indent = 2);

}  // namespace covopt::report
