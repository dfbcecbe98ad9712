#pragma once
/// @file materials_text.hpp
/// Catalog entries as readable text (`covopt materials list|find|show`; materials_json.hpp is
/// their JSON).

#include <ostream>
#include <string_view>
#include <vector>

#include "covopt/materials/material.hpp"

namespace covopt::report {

/// The materials as a table, one row each (name, family, E, ν, ρ, strength, E basis), then
/// `closing` and the legend of the "–", strength and basis columns.
void PrintMaterialTable(std::ostream& out, const std::vector<const materials::Material*>& rows,
                        std::string_view closing);

/// One material in full: every field, its sources, strength and note, long values wrapped,
/// then its compressive curve (PrintCurve).
void PrintMaterial(std::ostream& out, const materials::Material& m);

/// The compressive curve's rows (points and W at the last, σ(25 %) and its band, shape, rate,
/// recovers, rate factor, source) and its points as a table, or that it has none.
void PrintCurve(std::ostream& out, const materials::Material& m);

}  // namespace covopt::report
