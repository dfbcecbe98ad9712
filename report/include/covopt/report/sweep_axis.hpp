#pragma once
/// @file sweep_axis.hpp
/// One swept quantity of `covopt sweep` as the CSV and the charts lay it out
/// (sweep_csv.hpp, sweep_charts.hpp): the typed axis of covopt/core/sweep_axis_text.hpp.

#include <cstddef>

#include "covopt/core/sweep_axis_text.hpp"

namespace covopt::report {

using covopt::SweepAxisPart;
/// One swept quantity (covopt::TypedSweepAxis).
using SweepAxisArgument = covopt::TypedSweepAxis;

/// An axis with at most this many values is drawn as a family of lines.
inline constexpr std::size_t kMaxFamilies = 8;
}  // namespace covopt::report
