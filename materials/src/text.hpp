#pragma once
// Small text helpers of covopt::materials (private): number formatting and word lists for
// messages. Case folding, the edit distance and "did you mean" candidates are covopt's shared
// ones (covopt/internal/text.hpp, also used by scene files and the CLI).

#include <string>
#include <vector>

#include "covopt/internal/text.hpp"

namespace covopt::materials::internal {

using covopt::internal::Closest;
using covopt::internal::EditDistance;
using covopt::internal::EqualsIgnoringCase;
using covopt::internal::Lower;
using covopt::internal::TypoTolerance;

/// A number for messages: shortest form that reads back the same (e.g. 0.5, 2.76e+07).
std::string FormatNumber(double value);

/// "a, b or c" (each quoted with 'q' when quote is true).
std::string JoinAlternatives(const std::vector<std::string>& words, bool quote);

}  // namespace covopt::materials::internal
