#pragma once
/// @file design_flag_ranges.hpp
/// The covering design's thickness flags, shared by `optimize` and `audit --design`, checked
/// against their ranges by the flag's name (the library would name its own fields). Here, not in
/// optimize.hpp, so that no command's file includes another's.

#include <optional>
#include <string>

namespace covopt::cli {

/// --max-thickness in (min_thickness_m, 1 m] [m].
/// @param typed the value as the user wrote it, echoed in the message (nullopt: the default).
/// @throws InputError "--max-thickness must be in (0.1 mm, 1 m] (got '0')".
void RequireMaxThickness(double max_thickness_m, double min_thickness_m, const std::optional<std::string>& typed);
/// --thickness-step in [0, 10 mm] [m]; `typed` as above.
void RequireThicknessStep(double thickness_step_m, const std::optional<std::string>& typed);

}  // namespace covopt::cli
