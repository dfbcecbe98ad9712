#pragma once
/// @file sweep_axis_option.hpp
/// A swept quantity as typed on the command line, NAME=SPEC (`covopt sweep --x/--y`, the value
/// lists of `speed-limit --robot-mass` and `--speed`): the library's reader
/// (covopt/scene_file/sweep_axis.hpp, which has the grammar), throwing InputError. Shared by
/// those commands' files.

#include <string_view>

#include "covopt/report/sweep_axis.hpp"

namespace covopt::cli {

using report::kMaxFamilies;
using report::SweepAxisArgument;
using report::SweepAxisPart;

/// scene_file::ParseSweepAxis: reads "NAME=SPEC".
/// @param flag "--x" or "--y", for messages.
/// @throws InputError naming the flag, the value and what is allowed.
SweepAxisArgument ParseSweepAxis(std::string_view text, std::string_view flag);

/// scene_file::CheckGridSize: refuses a grid over the library's caps, before any point.
/// @throws InputError "the grid has 1000 x 2000 = 2000000 points; at most 1000000 are allowed".
void CheckGridSize(const SweepAxisArgument& x, const SweepAxisArgument* y);

}  // namespace covopt::cli
