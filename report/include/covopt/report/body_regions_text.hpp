#pragma once
/// @file body_regions_text.hpp
/// ISO/TS 15066's body-region table as readable text (`covopt body-regions list|show`;
/// body_regions_json.hpp is its JSON).

#include <ostream>

#include "covopt/materials/body_regions.hpp"

namespace covopt::report {

/// Every region and area: F_qs, F_tr, p_qs, p_tr, k and m_H in the standard's units, and the
/// legend of the table.
void PrintBodyRegionTable(std::ostream& out, const materials::BodyRegionTable& table);

/// One region in full: its limits, transient rule, spring constant, effective mass, default
/// area, its areas' pressures and the sources, long values wrapped.
void PrintBodyRegion(std::ostream& out, const materials::BodyRegion& region);

}  // namespace covopt::report
