#pragma once
// Validation helpers shared by the optimiser's sources (the covering design, the robust
// design): formatting a value for a message, throwing on a failed check, and the checks of a
// design space. Not installed.

#include <string>

#include "covopt/optim/covering_design.hpp"

namespace covopt::optim::internal {

/// "%g" of a value.
std::string Number(double value);
/// throw std::invalid_argument(message) unless `condition`.
void Require(bool condition, const std::string& message);

/// Checks a design space: modulus in [1e3, 1e13] Pa and thickness in [1e-4, 1] m (the floors), each range with
/// min < max. @throws std::invalid_argument naming the bound, its allowed range and the value.
void ValidateDesignSpace(const DesignSpace& space);

/// A crushing material's compressive strength: in [1e3, 1e13] Pa (the floor kMinModulus_Pa).
/// @throws std::invalid_argument beginning with `who` ("material 'x': ").
void CheckCompressiveStrength(double strength_Pa, const std::string& who);

/// Checks a candidate material: modulus in [1e3, 1e13] Pa, Poisson ratio in (-1, 0.5], and for a
/// material that crushes a compressive strength in [1e3, 1e13] Pa (the floors, physical_floors.hpp). Messages begin
/// "<prefix>'<name>': ". @throws std::invalid_argument naming the field, its range and the value.
void ValidateCandidateMaterial(const CandidateMaterial& material, const std::string& prefix = "material ");

/// Checks a thickness scan of the catalog designs: min in [1e-4, max) m, max <= 1 m, points in
/// [10, 100000], resolution > 0 m, step >= 0 m. Field names are prefixed with `prefix`.
/// @throws std::invalid_argument naming the field, its range and the value.
void ValidateThicknessScan(double min_thickness_m, double max_thickness_m, int scan_points, double resolution_m,
                           double step_m, const std::string& prefix = "");

}  // namespace covopt::optim::internal
