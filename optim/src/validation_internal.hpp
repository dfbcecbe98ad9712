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

/// Checks a design space: modulus in (0, 1e13] Pa and thickness in (0, 1] m, each range with
/// min < max. @throws std::invalid_argument naming the bound, its allowed range and the value.
void ValidateDesignSpace(const DesignSpace& space);

}  // namespace covopt::optim::internal
