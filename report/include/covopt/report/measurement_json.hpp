#pragma once
/// @file measurement_json.hpp
/// `covopt measure --json` and covopt.predict_measurement(...).json() (optim/measurement.hpp):
/// what a measuring device reads beside the body model. SI values, units in the keys; a value
/// not evaluated is null.
///
///   {scene (BodyContactSceneJson), safety_factor,
///    device {name, spring_N_per_m, pad_shore_a, pad_modulus_Pa, pad_modulus_source,
///            pad_poisson_ratio, pad_thickness_m, pad_thickness_assumed, reduced_mass_kg,
///            peak_force_N, stiff_pad_force_N, peak_pressure_Pa, contact_radius_m, fully_compressed,
///            pad {share, deflection_m, strain, bottomed_out, within, note},
///            covering null | {the same}, validity {within, ratio, note},
///            force {value_N, limit_N, ratio}, pressure {value_Pa, limit_Pa, ratio}, admissible},
///    body_model (BodyRegionJudgementJson),
///    comparison {force_difference_N, force_ratio, pressure_difference_Pa, pressure_ratio},
///    safe (both verdicts), scope, summary, warnings}

#include <optional>
#include <span>
#include <string>

#include "covopt/core/body_contact.hpp"
#include "covopt/optim/measurement.hpp"

namespace covopt::report {

/// The JSON object above (indented text).
std::string MeasurementJson(const BodyContactScene& scene, const std::optional<std::string>& material,
                            const optim::MeasurementPrediction& prediction, double safety_factor,
                            std::span<const std::string> warnings);

/// The text `covopt measure` prints: the device, a small table (device against body model:
/// force N, pressure N/cm², each against the limit, and their ratio), the scope and the warnings.
std::string MeasurementText(const BodyContactScene& scene, const optim::MeasurementPrediction& prediction,
                            std::span<const std::string> warnings);

}  // namespace covopt::report
