#pragma once
/// @file materials_json.hpp
/// Catalog entries as JSON text (`covopt materials list|show --json`, `covopt.materials()`)
/// (the message for a name the catalog does not hold is materials::Catalog::MissingMaterialMessage).

#include <span>
#include <string>
#include <string_view>

#include "covopt/materials/catalog.hpp"
#include "covopt/materials/material.hpp"

namespace covopt::report {

/// One catalog entry as a JSON object: name, family, youngs_modulus_Pa, poisson_ratio (null
/// if unknown), density_kg_per_m3 [kg/m³] (null if unknown), modulus_basis, source, note
/// (null if none), crush_behaviour ("crushes", "does-not-crush" or "unknown"),
/// compressive_strength_Pa (null unless the material crushes), strength_method and
/// strength_source (null if none), defined_at (null if not known); then the compressive curve
/// (all null without one): compressive_curve ([[strain, stress_Pa], ...], the origin implied),
/// stress_at_25_Pa (σ(25 %), null when the curve ends before 25 %),
/// curve_energy_density_J_per_m3 (W at the curve's last point), curve_source, curve_rate
/// ("quasi-static", "unknown" or a rate as written), curve_rate_per_s (null unless a rate),
/// recovers, rate_factor ([low, high] or null), stress_at_25_band_Pa ([low, high] or null),
/// curve_shape (null unless a band).
std::string MaterialJson(const materials::Material& material, int indent = 2);

/// Catalog entries as a JSON array of MaterialJson objects, in the given order.
std::string MaterialsJson(std::span<const materials::Material* const> materials, int indent = 2);

}  // namespace covopt::report
