#pragma once
/// @file integrators.hpp
/// The time integrators by the names a front end takes (Python's method=, the CLI's
/// --method): "cvode" (CVODE's Adams method) or a time-integration method's own name.

#include <optional>
#include <string>
#include <string_view>

#include "covopt/core/impact_result.hpp"

namespace covopt::scene_file {

/// The integrator `name` names: "cvode" is kCvodeAdams, else a time-integration method by its
/// name (ParseComputationMethod); nullopt for "exact" and anything else.
std::optional<ComputationMethod> ParseIntegrator(std::string_view name) noexcept;

/// The integrators' names for messages, comma-separated (TimeIntegrationMethods()' order).
std::string IntegratorNames();

}  // namespace covopt::scene_file
