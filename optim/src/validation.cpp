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

void ValidateCandidateMaterial(const CandidateMaterial& m, const std::string& prefix) {
  const std::string who = prefix + "'" + m.name + "': ";
  Require(std::isfinite(m.youngs_modulus_Pa) && m.youngs_modulus_Pa > 0.0 && m.youngs_modulus_Pa <= 1e13,
          who + "modulus must be in (0, 1e13] Pa (got " + Number(m.youngs_modulus_Pa) + ")");
  Require(m.poisson_ratio > -1.0 && m.poisson_ratio <= 0.5,
          who + "poisson ratio must be in (-1, 0.5] (got " + Number(m.poisson_ratio) + ")");
  if (m.crush_behaviour == materials::CrushBehaviour::kCrushes) {
    Require(std::isfinite(m.compressive_strength_Pa) && m.compressive_strength_Pa > 0.0,
            who + "compressive strength must be finite and > 0 Pa for a material that crushes (got " +
                Number(m.compressive_strength_Pa) + ")");
  }
}

void ValidateThicknessScan(double min_thickness_m, double max_thickness_m, int scan_points, double resolution_m,
                           double step_m, const std::string& prefix) {
  Require(std::isfinite(min_thickness_m) && min_thickness_m > 0.0 && min_thickness_m < max_thickness_m,
          prefix + "min_thickness_m must be in (0, max_thickness_m) m (got " + Number(min_thickness_m) + ")");
  Require(std::isfinite(max_thickness_m) && max_thickness_m <= 1.0,
          prefix + "max_thickness_m must be in (min_thickness_m, 1] m (got " + Number(max_thickness_m) + ")");
  Require(scan_points >= 10 && scan_points <= 100000,
          prefix + "thickness_scan_points must be in [10, 100000] (got " + std::to_string(scan_points) + ")");
  Require(std::isfinite(resolution_m) && resolution_m > 0.0,
          prefix + "thickness_resolution_m must be > 0 m (got " + Number(resolution_m) + ")");
  Require(std::isfinite(step_m) && step_m >= 0.0, prefix + "thickness_step_m must be >= 0 m (got " + Number(step_m) + ")");
}

}  // namespace covopt::optim::internal
