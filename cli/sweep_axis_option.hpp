#pragma once
/// @file sweep_axis_option.hpp
/// A swept quantity as typed on the command line, NAME=SPEC (`covopt sweep --x/--y`, the value
/// lists of `speed-limit --robot-mass` and `--speed`): its grammar is in sweep.hpp. Shared by
/// those commands' files.

#include <string_view>

#include "covopt/report/sweep_axis.hpp"
#include "scene_fields.hpp"

namespace covopt::cli {

using report::kMaxFamilies;
using report::SweepAxisArgument;
using report::SweepAxisPart;

/// Reads "NAME=SPEC".
/// @param flag "--x" or "--y", for messages.
/// @throws InputError naming the flag, the value and what is allowed.
SweepAxisArgument ParseSweepAxis(std::string_view text, std::string_view flag);

/// Refuses a grid over the library's caps (covopt::CheckSweepSize), before any point.
/// @throws InputError "the grid has 1000 x 2000 = 2000000 points; at most 1000000 are allowed".
void CheckGridSize(const SweepAxisArgument& x, const SweepAxisArgument* y);

}  // namespace covopt::cli
