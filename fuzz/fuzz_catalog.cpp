// libFuzzer target: the material-catalog parser (materials/src/catalog_toml.cpp). Bad
// input must end in covopt::materials::CatalogError; what parses must be a valid catalog
// (finite E > 0, ν in (-1, 0.5]) whose names can be looked up. Values may carry units
// ("27.6MPa"), read by covopt::ParseQuantity.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "covopt/materials/catalog.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const covopt::materials::Catalog catalog =
        covopt::materials::Catalog::FromTomlString(text, "fuzz.toml");
    for (const covopt::materials::Material& m : catalog.materials()) {
      if (!(m.youngs_modulus_Pa > 0.0) || !std::isfinite(m.youngs_modulus_Pa)) std::abort();
      if (m.poisson_ratio && !(*m.poisson_ratio > -1.0 && *m.poisson_ratio <= 0.5)) std::abort();
      if (catalog.Find(m.name) == nullptr) std::abort();
      (void)catalog.Suggest(m.name);
    }
    covopt::materials::Catalog merged = covopt::materials::Catalog::BuiltIn();
    try {
      merged.Add(catalog);
    } catch (const covopt::materials::CatalogError&) {
    }
  } catch (const covopt::materials::CatalogError&) {
  }
  return 0;
}
