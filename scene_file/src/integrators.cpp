#include "covopt/scene_file/integrators.hpp"

namespace covopt::scene_file {

std::optional<ComputationMethod> ParseIntegrator(std::string_view name) noexcept {
  if (name == "cvode") return ComputationMethod::kCvodeAdams;
  const std::optional<ComputationMethod> method = ParseComputationMethod(name);
  if (method == ComputationMethod::kExact) return std::nullopt;
  return method;
}

std::string IntegratorNames() {
  std::string names;
  for (const ComputationMethod method : TimeIntegrationMethods()) {
    if (!names.empty()) names += ", ";
    names += ToString(method);
  }
  return names;
}

}  // namespace covopt::scene_file
