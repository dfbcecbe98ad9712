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
/// strength_source (null if none), defined_at (null if not known).
std::string MaterialJson(const materials::Material& material, int indent = 2);

/// Catalog entries as a JSON array of MaterialJson objects, in the given order.
std::string MaterialsJson(std::span<const materials::Material* const> materials, int indent = 2);

}  // namespace covopt::report
