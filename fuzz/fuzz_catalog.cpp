// libFuzzer target: the material-catalog parser (materials/src/catalog_toml.cpp). Bad
// input must end in covopt::materials::CatalogError; what parses must be a valid catalog
// (finite E > 0, ν in (-1, 0.5]) whose names can be looked up. Values may carry units
// ("27.6MPa"), read by covopt::ParseQuantity; a compressive curve that loads has finite,
// positive integrals and its source and recovers.
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
      // A curve that loads is a valid loading envelope with finite integrals.
      if (m.compressive_curve) {
        const double w = m.compressive_curve->total_energy_density_J_per_m3();
        if (!(w > 0.0) || !std::isfinite(w) || !m.recovers || m.curve_source.empty()) std::abort();
        if (const auto s25 = covopt::materials::StressAt25Pa(m); s25 && !(*s25 > 0.0 && std::isfinite(*s25))) {
          std::abort();
        }
      }
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
