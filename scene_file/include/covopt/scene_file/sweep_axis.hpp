#pragma once
/// @file sweep_axis.hpp
/// The reader of a swept quantity typed as NAME=SPEC (`covopt sweep --x/--y`, the value lists
/// of `speed-limit --robot-mass` and `--speed`):
///
///     NAME=LO..HI[:lin|:log][:N]     N values (default 50, 2..kMaxSweepAxisValues) from LO to HI
///     NAME=V1,V2,...                 single values; items may mix ranges and values
///
/// NAME is a scene field's name or dotted name (covopt::SceneFields()); values take units as
/// covopt::ParseQuantity reads them, and a bare number is SI and must be plausible.

#include <optional>
#include <string_view>

#include "covopt/core/sweep_axis_text.hpp"

namespace covopt::scene_file {

/// Reads "NAME=SPEC".
/// @param name how messages call the input: "--x", "--y", "--speed".
/// @throws std::invalid_argument naming `name`, the problem and the text, e.g.
///   "--x: unknown quantity 'speeed'; the quantities are ... (got 'speeed=1..2')".
TypedSweepAxis ParseSweepAxis(std::string_view text, std::string_view name);

/// Refuses a grid over the library's caps (covopt::CheckSweepSize), before any point.
/// @throws std::invalid_argument "the grid has 1000 x 2000 = 2000000 points; at most 1000000 ...".
void CheckGridSize(const TypedSweepAxis& x, const TypedSweepAxis* y);

}  // namespace covopt::scene_file
