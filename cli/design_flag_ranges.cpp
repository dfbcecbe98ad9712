#include "design_flag_ranges.hpp"

#include <fmt/format.h>

#include "covopt/core/quantity.hpp"
#include "errors.hpp"

namespace covopt::cli {

void RequireMaxThickness(double max_thickness_m, double min_thickness_m, const std::optional<std::string>& typed) {
  if (!(max_thickness_m > min_thickness_m && max_thickness_m <= 1.0)) {
    throw InputError(fmt::format("--max-thickness must be in ({}, 1 m] (got '{}')",
                                 FormatQuantity(min_thickness_m, QuantityKind::kLength),
                                 typed.value_or(FormatQuantity(max_thickness_m, QuantityKind::kLength))));
  }
}

void RequireThicknessStep(double thickness_step_m, const std::optional<std::string>& typed) {
  if (!(thickness_step_m >= 0.0 && thickness_step_m <= 0.01)) {
    throw InputError(fmt::format("--thickness-step must be in [0, 10 mm] (got '{}')",
                                 typed.value_or(FormatQuantity(thickness_step_m, QuantityKind::kLength))));
  }
}

}  // namespace covopt::cli
