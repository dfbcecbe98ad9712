#pragma once
/// @file quantity.hpp
/// Values with units for the command line: covopt::ParseQuantity and its companions
/// (core/include/covopt/core/quantity.hpp, which documents the units and the plausible
/// ranges of bare numbers), with bad input reported as the CLI's InputError (exit 2).

#include <string_view>

#include "covopt/core/quantity.hpp"

namespace covopt::cli {

using covopt::CheckBareNumber;
using covopt::Describe;
using covopt::FormatQuantity;
using covopt::QuantityKind;
using covopt::QuantitySpec;
using covopt::SiUnit;
using covopt::UnitList;
namespace quantity_specs = covopt::quantity_specs;

/// covopt::ParseQuantity, throwing InputError instead of std::invalid_argument.
///
/// A function object rather than a function: an unqualified call `ParseQuantity(text, spec,
/// flag)` in covopt::cli then finds only this (lookup that finds an object skips
/// argument-dependent lookup), where a function of the same signature would be ambiguous
/// with covopt::ParseQuantity, which argument-dependent lookup finds through QuantitySpec.
struct ParseQuantityToInputError {
  /// @param name how messages call the value: a flag ("--speed") or a field ("robot.speed").
  /// @throws InputError "<name>: <problem> (got '<text>')", e.g.
  ///         "--speed: unit 'kg' is not a speed; use m/s, mm/s, cm/s or km/h (got '2kg')", or
  ///         "--robot-radius 40: a bare number is in metres (40 m); write 40mm or 40m".
  double operator()(std::string_view text, const QuantitySpec& spec,
                    std::string_view name) const;
};
inline constexpr ParseQuantityToInputError ParseQuantity{};

}  // namespace covopt::cli
