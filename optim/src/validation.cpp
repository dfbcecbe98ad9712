// Validation helpers shared by the optimiser's sources (validation_internal.hpp).
#include "validation_internal.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <covopt/core/number_format.hpp>
#include <covopt/core/physical_floors.hpp>

namespace covopt::optim::internal {

std::string Number(double value) { return FormatSignificant(value); }

void Require(bool condition, const std::string& message) {
  if (!condition) throw std::invalid_argument(message);
}

void ValidateDesignSpace(const DesignSpace& s) {
  // The floors (physical_floors.hpp): every design the search visits is a scene the library takes.
  Require(std::isfinite(s.min_modulus_Pa) && s.min_modulus_Pa >= kMinModulus_Pa,
          "min modulus must be >= " + Number(kMinModulus_Pa) + " Pa (got " + Number(s.min_modulus_Pa) + ")");
  Require(std::isfinite(s.max_modulus_Pa) && s.max_modulus_Pa > s.min_modulus_Pa && s.max_modulus_Pa <= 1e13,
          "max modulus must be in (min modulus " + Number(s.min_modulus_Pa) + " Pa, 1e13 Pa] (got " +
              Number(s.max_modulus_Pa) + ")");
  Require(std::isfinite(s.min_thickness_m) && s.min_thickness_m >= kMinLayerThickness_m,
          "min thickness must be >= " + Number(kMinLayerThickness_m) + " m (got " + Number(s.min_thickness_m) + ")");
  Require(std::isfinite(s.max_thickness_m) && s.max_thickness_m > s.min_thickness_m && s.max_thickness_m <= 1.0,
          "max thickness must be in (min thickness " + Number(s.min_thickness_m) + " m, 1 m] (got " +
              Number(s.max_thickness_m) + ")");
}

void CheckCompressiveStrength(double strength_Pa, const std::string& who) {
  // The modulus floor (a strength below 1 kPa gave crush ratios of 1e300 and inf).
  Require(strength_Pa >= kMinModulus_Pa && strength_Pa <= 1e13,
          who + "compressive strength must be in [" + Number(kMinModulus_Pa) +
              ", 1e13] Pa for a material that crushes (got " + FormatShortest(strength_Pa) + ")");
}

void ValidateCandidateMaterial(const CandidateMaterial& m, const std::string& prefix) {
  const std::string who = prefix + "'" + m.name + "': ";
  Require(m.youngs_modulus_Pa >= kMinModulus_Pa && m.youngs_modulus_Pa <= 1e13,
          who + "modulus must be in [" + Number(kMinModulus_Pa) + ", 1e13] Pa (got " + Number(m.youngs_modulus_Pa) + ")");
  Require(m.poisson_ratio > -1.0 && m.poisson_ratio <= 0.5,
          who + "poisson ratio must be in (-1, 0.5] (got " + Number(m.poisson_ratio) + ")");
  if (m.crush_behaviour == materials::CrushBehaviour::kCrushes) CheckCompressiveStrength(m.compressive_strength_Pa, who);
}

void ValidateThicknessScan(double min_thickness_m, double max_thickness_m, int scan_points, double resolution_m,
                           double step_m, const std::string& prefix) {
  Require(std::isfinite(min_thickness_m) && min_thickness_m >= kMinLayerThickness_m && min_thickness_m < max_thickness_m,
          prefix + "min_thickness_m must be in [" + Number(kMinLayerThickness_m) + ", max_thickness_m) m (got " +
              Number(min_thickness_m) + ")");
  Require(std::isfinite(max_thickness_m) && max_thickness_m <= 1.0,
          prefix + "max_thickness_m must be in (min_thickness_m, 1] m (got " + Number(max_thickness_m) + ")");
  Require(scan_points >= 10 && scan_points <= 100000,
          prefix + "thickness_scan_points must be in [10, 100000] (got " + std::to_string(scan_points) + ")");
  Require(std::isfinite(resolution_m) && resolution_m > 0.0,
          prefix + "thickness_resolution_m must be > 0 m (got " + Number(resolution_m) + ")");
  Require(std::isfinite(step_m) && step_m >= 0.0, prefix + "thickness_step_m must be >= 0 m (got " + Number(step_m) + ")");
}

}  // namespace covopt::optim::internal
