#pragma once
// Private helper: numbers in error messages, shortest form that round-trips
// (covopt::FormatShortest, covopt/core/number_format.hpp).
#include <string>

#include "covopt/core/number_format.hpp"

namespace covopt::internal {

inline std::string FormatNumber(double value) { return FormatShortest(value); }

}  // namespace covopt::internal
