#pragma once
/// @file body_regions_json.hpp
/// ISO/TS 15066's body regions as JSON text (`covopt body-regions list|show --json`,
/// `covopt.body_regions()`), in SI units named in the keys.

#include <span>
#include <string>

#include "covopt/materials/body_regions.hpp"

namespace covopt::report {

/// One region as a JSON object: name, title, quasi_static_force_N [N], transient_permitted,
/// transient_factor (null when not permitted), transient_force_N [N] (null when not
/// permitted), transient_rule (the factor, or the clause that forbids it), stiffness_N_per_m
/// [N/m], effective_mass_kg [kg], default_area (the lowest pressure), areas (name, title,
/// number, quasi_static_pressure_Pa [Pa], transient_pressure_Pa [Pa] or null), sources.
std::string BodyRegionJson(const materials::BodyRegion& region, int indent = 2);

/// The regions as a JSON array of BodyRegionJson objects, in the given order.
std::string BodyRegionsJson(std::span<const materials::BodyRegion> regions, int indent = 2);

/// How a region's transient limits follow from its quasi-static ones, in words: "2× the
/// quasi-static limits" or "not permitted (ISO/TS 15066:2016 A.3.2)".
std::string TransientRule(const materials::BodyRegion& region);

}  // namespace covopt::report
