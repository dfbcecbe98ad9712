// libFuzzer target: the unit-value parser (covopt/core/quantity.hpp, through the CLI's
// forwarder cli/quantity.hpp). The first byte picks the spec: with bit 0x40 one of the named
// specs with a plausible range for bare numbers (quantity_specs::kWithPlausibleRange), else
// the quantity kind (low nibble) and whether "fixed"/"flat" are allowed (bits 0x10/0x20);
// the rest is the text. Bad input must end in covopt::cli::InputError; what parses must be
// finite (or +inf for fixed/flat), a bare positive number must lie in the spec's plausible
// range, and FormatQuantity's text must read back without a NaN.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "errors.hpp"
#include "quantity.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  using covopt::cli::QuantityKind;
  namespace specs = covopt::quantity_specs;
  constexpr int kKinds = static_cast<int>(QuantityKind::kEnergyDensity) + 1;
  covopt::cli::QuantitySpec spec;
  if ((data[0] & 0x40) != 0) {
    spec = *specs::kWithPlausibleRange[data[0] % specs::kWithPlausibleRange.size()];
  } else {
    spec.kind = static_cast<QuantityKind>((data[0] & 0x0F) % kKinds);
    spec.allow_fixed = (data[0] & 0x10) != 0;
    spec.allow_flat = (data[0] & 0x20) != 0;
  }
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  double value = 0.0;
  try {
    value = covopt::cli::ParseQuantity(text, spec, "--fuzz");
  } catch (const covopt::cli::InputError&) {
    return 0;
  }
  if (std::isnan(value)) std::abort();
  if (std::isinf(value)) {
    if (!(value > 0 && (spec.allow_fixed || spec.allow_flat))) std::abort();
    return 0;
  }
  // A bare number (only digits, sign, point, exponent and spaces: every unit has another
  // letter) that is positive must be plausible.
  const bool bare = text.find_first_not_of("0123456789+-.eE \t") == std::string_view::npos;
  if (bare && value > 0.0 && (value < spec.plausible_min || value > spec.plausible_max)) {
    std::abort();
  }
  const std::string shown = covopt::cli::FormatQuantity(value, spec.kind);
  double again = 0.0;
  try {
    again = covopt::cli::ParseQuantity(shown, spec, "--fuzz");
  } catch (const covopt::cli::InputError&) {
    // FormatQuantity of a tiny or huge value may not read back ("1e-320 mm" overflows
    // nothing, but a subnormal scaled by a unit can underflow to 0); only NaN is wrong.
    return 0;
  }
  if (std::isnan(again)) std::abort();
  return 0;
}
