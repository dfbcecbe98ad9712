// The catalog shipped with covopt (materials/data/catalog.toml, compiled into the library).
// These tests check that it loads without any file at run time, that it is the data file
// byte for byte (the embedded copy and the file give the same entries), that it holds at
// least 20 materials with a modulus, the paper's Table IV coverings with exactly the
// printed values and Table III's fitted paddings, and that every entry obeys the rules a
// user file must obey: a source, a basis, a note where E was derived, ν unknown only as
// "no value" (then 0.25 is the default).

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include <catch2/catch.hpp>

#include "covopt/materials.hpp"

using covopt::materials::Catalog;
using covopt::materials::Material;
using covopt::materials::ModulusBasis;

namespace {

const Material& Get(const Catalog& catalog, const std::string& name) {
  const Material* material = catalog.Find(name);
  INFO("material " << name);
  REQUIRE(material != nullptr);
  return *material;
}

}  // namespace

TEST_CASE("the built-in catalog loads with at least 20 materials", "[builtin]") {
  const Catalog& catalog = Catalog::BuiltIn();
  CHECK(catalog.size() >= 20);
  // Every entry has a modulus (the loader requires one; this is the count that matters).
  CHECK(std::count_if(catalog.materials().begin(), catalog.materials().end(),
                      [](const Material& m) { return m.youngs_modulus_Pa > 0.0; }) >= 20);
  // Parsed once: every call gives the same object.
  CHECK(&Catalog::BuiltIn() == &Catalog::BuiltIn());
}

TEST_CASE("the paper's Table IV coverings have exactly the printed values", "[builtin][paper]") {
  const Catalog& catalog = Catalog::BuiltIn();
  struct Row {
    const char* name;
    double youngs_modulus_Pa;
    double poisson_ratio;
    double density_kg_per_m3;
  };
  for (const Row& row : {Row{"polystyrene foam 27.6", 27.6e6, 0.22, 50.0},
                         Row{"polystyrene foam 48.3", 48.3e6, 0.25, 100.0},
                         Row{"polyurethane foam 62.1", 62.1e6, 0.20, 100.0},
                         Row{"polyurethane foam 137.9", 137.9e6, 0.29, 200.0}}) {
    CAPTURE(row.name);
    const Material& m = Get(catalog, row.name);
    CHECK(m.youngs_modulus_Pa == row.youngs_modulus_Pa);
    REQUIRE(m.poisson_ratio.has_value());
    CHECK(*m.poisson_ratio == row.poisson_ratio);
    REQUIRE(m.density_kg_per_m3.has_value());
    CHECK(*m.density_kg_per_m3 == row.density_kg_per_m3);  // kg/m³, not the printed kg/cm2
    CHECK(m.family == "foam");
    CHECK(m.modulus_basis == ModulusBasis::kAsPrinted);
    CHECK(m.source.find("Table IV") != std::string::npos);
  }
}

TEST_CASE("the paper's Table III paddings are fitted entries with nu = 0.25", "[builtin][paper]") {
  const Catalog& catalog = Catalog::BuiltIn();
  for (const auto& [name, modulus] : {std::pair{"Park padding 30", 30e6},
                                      std::pair{"Park padding 70", 70e6},
                                      std::pair{"Park padding 100", 100e6},
                                      std::pair{"Park padding 130", 130e6}}) {
    CAPTURE(name);
    const Material& m = Get(catalog, name);
    CHECK(m.youngs_modulus_Pa == modulus);
    CHECK(m.poisson_ratio == 0.25);
    CHECK(m.modulus_basis == ModulusBasis::kFitted);
    CHECK(m.source.find("Table III") != std::string::npos);
  }
}

TEST_CASE("the embedded catalog is the data file's catalog", "[builtin]") {
  const Catalog& built_in = Catalog::BuiltIn();
  const Catalog from_file = Catalog::FromTomlFile(COVOPT_CATALOG_TOML);
  REQUIRE(from_file.size() == built_in.size());
  for (std::size_t i = 0; i < built_in.size(); ++i) {
    const Material& a = built_in.materials()[i];
    const Material& b = from_file.materials()[i];
    CAPTURE(a.name);
    CHECK(a.name == b.name);
    CHECK(a.family == b.family);
    CHECK(a.youngs_modulus_Pa == b.youngs_modulus_Pa);
    CHECK(a.poisson_ratio == b.poisson_ratio);
    CHECK(a.density_kg_per_m3 == b.density_kg_per_m3);
    CHECK(a.modulus_basis == b.modulus_basis);
    CHECK(a.source == b.source);
    CHECK(a.note == b.note);
    // Same place in the file, named differently.
    CHECK(a.origin.substr(a.origin.find(':')) == b.origin.substr(b.origin.rfind(".toml:") + 5));
  }
}

TEST_CASE("every built-in entry is sourced and says how its modulus was obtained", "[builtin]") {
  const Catalog& catalog = Catalog::BuiltIn();
  std::set<std::string> families;
  for (const Material& m : catalog.materials()) {
    CAPTURE(m.name);
    CHECK(!m.source.empty());
    CHECK(!m.family.empty());
    CHECK(std::isfinite(m.youngs_modulus_Pa));
    CHECK(m.youngs_modulus_Pa > 0.0);
    if (m.poisson_ratio) {
      CHECK(*m.poisson_ratio > -1.0);
      CHECK(*m.poisson_ratio < 0.5);
    }
    if (m.density_kg_per_m3) CHECK(*m.density_kg_per_m3 > 0.0);
    // A derived modulus says how it was derived.
    if (m.modulus_basis == ModulusBasis::kCompressive || m.modulus_basis == ModulusBasis::kBending ||
        m.modulus_basis == ModulusBasis::kHardness) {
      CHECK(!m.note.empty());
    }
    if (m.modulus_basis == ModulusBasis::kCompressive) {
      CHECK(m.note.find("strain") != std::string::npos);
    }
    CHECK(m.origin.rfind("built-in catalog.toml:", 0) == 0);
    families.insert(m.family);
  }
  CHECK(families == std::set<std::string>{"foam", "elastomer", "padding", "thermoplastic"});
}

TEST_CASE("an entry without nu reads as unknown and defaults to 0.25", "[builtin]") {
  const Catalog& catalog = Catalog::BuiltIn();
  const Material& eps = Get(catalog, "EPS geofoam EPS15");
  CHECK_FALSE(eps.poisson_ratio.has_value());
  CHECK(covopt::materials::PoissonRatioOrDefault(eps) == 0.25);
  CHECK(covopt::materials::kDefaultPoissonRatio == 0.25);
  const Material& ps = Get(catalog, "polystyrene foam 27.6");
  CHECK(covopt::materials::PoissonRatioOrDefault(ps) == 0.22);
}

TEST_CASE("modulus bases read and print in the catalog spelling", "[builtin]") {
  using covopt::materials::ParseModulusBasis;
  for (const ModulusBasis basis :
       {ModulusBasis::kCompressive, ModulusBasis::kTensile, ModulusBasis::kBending,
        ModulusBasis::kFitted, ModulusBasis::kAsPrinted, ModulusBasis::kHardness}) {
    const auto name = covopt::materials::ToString(basis);
    CAPTURE(name);
    CHECK(ParseModulusBasis(name) == basis);
    CHECK(!covopt::materials::Describe(basis).empty());
  }
  CHECK(covopt::materials::ToString(ModulusBasis::kAsPrinted) == "as-printed");
  CHECK_FALSE(ParseModulusBasis("Compressive").has_value());
  CHECK_FALSE(ParseModulusBasis("").has_value());
}
