// Validation helpers shared by the optimiser's sources (validation_internal.hpp).
#include "validation_internal.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <covopt/core/number_format.hpp>

namespace covopt::optim::internal {

std::string Number(double value) { return FormatSignificant(value); }

void Require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument(message);
}

void ValidateDesignSpace(const DesignSpace& s) {
  Require(std::isfinite(s.min_modulus_Pa) && s.min_modulus_Pa > 0,
          "min modulus must be > 0 Pa (got " + Number(s.min_modulus_Pa) + ")");
  Require(std::isfinite(s.max_modulus_Pa) && s.max_modulus_Pa > s.min_modulus_Pa && s.max_modulus_Pa <= 1e13,
          "max modulus must be in (min modulus " + Number(s.min_modulus_Pa) + " Pa, 1e13 Pa] (got " +
              Number(s.max_modulus_Pa) + ")");
  Require(std::isfinite(s.min_thickness_m) && s.min_thickness_m > 0,
          "min thickness must be > 0 m (got " + Number(s.min_thickness_m) + ")");
  Require(std::isfinite(s.max_thickness_m) && s.max_thickness_m > s.min_thickness_m && s.max_thickness_m <= 1.0,
          "max thickness must be in (min thickness " + Number(s.min_thickness_m) + " m, 1 m] (got " +
              Number(s.max_thickness_m) + ")");
}

}  // namespace covopt::optim::internal
