// The catalog shipped with covopt (materials/data/catalog.toml, compiled into the library).
// These tests check that it loads without any file at run time, that it is the data file
// byte for byte (the embedded copy and the file give the same entries), that it holds at
// least 20 materials with a modulus, the paper's Table IV coverings with exactly the
// printed values and Table III's fitted paddings, and that every entry obeys the rules a
// user file must obey: a source, a basis, a note where E was derived, ν unknown only as
// "no value" (then 0.25 is the default). And that every entry states its compressive
// strength explicitly (in the raw file), with a method and a source, or "does not crush"
// with the reason, or "unknown" with the reason in its note; at least 45 entries.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

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
    CHECK(a.crush_behaviour == b.crush_behaviour);
    CHECK(a.compressive_strength_Pa == b.compressive_strength_Pa);
    CHECK(a.strength_method == b.strength_method);
    CHECK(a.strength_source == b.strength_source);
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

// ---- The compressive strength (the crush criterion) -----------------------------------------

namespace {

/// The text of the data file, and the [[material]] tables in it, each as its raw text.
std::vector<std::string> RawEntries() {
  std::ifstream in(COVOPT_CATALOG_TOML);
  REQUIRE(in);
  std::stringstream text;
  text << in.rdbuf();
  const std::string all = text.str();
  std::vector<std::string> entries;
  const std::string header = "\n[[material]]";
  std::size_t at = all.find(header);
  while (at != std::string::npos) {
    const std::size_t next = all.find(header, at + header.size());
    entries.push_back(all.substr(at, next == std::string::npos ? std::string::npos : next - at));
    at = next;
  }
  return entries;
}

}  // namespace

TEST_CASE("the built-in catalog holds at least 45 materials", "[builtin][strength]") {
  CHECK(Catalog::BuiltIn().size() >= 45);
  CHECK(RawEntries().size() == Catalog::BuiltIn().size());
}

TEST_CASE("every built-in entry states its compressive strength explicitly", "[builtin][strength]") {
  // Absent means unknown in a user file; the built-in catalog must say so per entry.
  for (const std::string& entry : RawEntries()) {
    const std::size_t name_at = entry.find("name = \"");
    const std::string name = entry.substr(name_at + 8, entry.find('"', name_at + 8) - name_at - 8);
    CAPTURE(name);
    CHECK(entry.find("\ncompressive_strength_Pa = ") != std::string::npos);
  }
}

TEST_CASE("every known strength is positive, with a method and a source", "[builtin][strength]") {
  using covopt::materials::CrushBehaviour;
  std::size_t crushes = 0;
  std::size_t no_crush = 0;
  std::size_t unknown = 0;
  for (const Material& m : Catalog::BuiltIn().materials()) {
    CAPTURE(m.name);
    switch (m.crush_behaviour) {
      case CrushBehaviour::kCrushes:
        ++crushes;
        REQUIRE(m.compressive_strength_Pa.has_value());
        CHECK(std::isfinite(*m.compressive_strength_Pa));
        CHECK(*m.compressive_strength_Pa > 0.0);
        // Every strength here is below the material's modulus (a strain under 100 %).
        CHECK(*m.compressive_strength_Pa < m.youngs_modulus_Pa);
        CHECK(!m.strength_method.empty());
        CHECK(!m.strength_source.empty());
        break;
      case CrushBehaviour::kDoesNotCrush:
        ++no_crush;
        CHECK_FALSE(m.compressive_strength_Pa.has_value());
        CHECK(!m.strength_method.empty());  // why
        CHECK(!m.strength_source.empty());
        break;
      case CrushBehaviour::kUnknown:
        ++unknown;
        CHECK_FALSE(m.compressive_strength_Pa.has_value());
        CHECK(m.strength_method.empty());
        CHECK(m.strength_source.empty());
        CHECK(m.note.find("Strength unknown") != std::string::npos);  // the note says why
        break;
    }
  }
  CHECK(crushes >= 12);
  CHECK(no_crush >= 20);
  CHECK(unknown >= 8);
}

TEST_CASE("rigid foams crush, elastomers and flexible foams do not", "[builtin][strength]") {
  using covopt::materials::CrushBehaviour;
  for (const Material& m : Catalog::BuiltIn().materials()) {
    CAPTURE(m.name);
    const auto has = [&](const char* part) { return m.name.find(part) != std::string::npos; };
    if (has("EPS") || has("XPS") || has("PMI") || has("polystyrene")) {
      // A rigid foam: a known strength, or an explicit unknown; never "does not crush".
      CHECK(m.crush_behaviour != CrushBehaviour::kDoesNotCrush);
    }
    if (m.family == "elastomer" || has("sponge") || has("PORON") || has("PU foam") ||
        has("Plastazote")) {
      CHECK(m.crush_behaviour == CrushBehaviour::kDoesNotCrush);
    }
    if (m.modulus_basis == ModulusBasis::kFitted) {
      CHECK(m.crush_behaviour == CrushBehaviour::kUnknown);  // the material is not known
    }
  }
}

TEST_CASE("the rated strengths are the datasheets' values", "[builtin][strength]") {
  const Catalog& catalog = Catalog::BuiltIn();
  constexpr double kPsi = 6894.757;
  // FOAMULAR grade number = rated strength in psi x 10, ASTM D1621.
  for (const auto& [name, psi] : {std::pair{"XPS Foamular 250", 25.0},
                                  std::pair{"XPS Foamular 400", 40.0},
                                  std::pair{"XPS Foamular 600", 60.0}}) {
    CAPTURE(name);
    const Material& m = Get(catalog, name);
    REQUIRE(m.compressive_strength_Pa.has_value());
    CHECK(*m.compressive_strength_Pa == Approx(psi * kPsi).epsilon(1e-9));
    CHECK(m.strength_method.find("ASTM D1621") != std::string::npos);
  }
  CHECK(*Get(catalog, "XPS Foamular 250").compressive_strength_Pa == Approx(172.37e3).epsilon(1e-4));
  // EPS geofoam: ASTM D6817 compressive resistance at 10 % deformation.
  for (const auto& [name, kpa] :
       {std::pair{"EPS geofoam EPS12", 40.0}, std::pair{"EPS geofoam EPS15", 70.0},
        std::pair{"EPS geofoam EPS19", 110.0}, std::pair{"EPS geofoam EPS22", 135.0},
        std::pair{"EPS geofoam EPS29", 200.0}, std::pair{"EPS geofoam EPS39", 276.0}}) {
    CAPTURE(name);
    const Material& m = Get(catalog, name);
    CHECK(m.compressive_strength_Pa == kpa * 1e3);
    CHECK(m.strength_method.find("10 %") != std::string::npos);
  }
  CHECK(Get(catalog, "XPS Styrofoam LB-X").compressive_strength_Pa == 0.3e6);
  CHECK(Get(catalog, "nylon bumper cover Qolo").compressive_strength_Pa == 86.2e6);
  CHECK_FALSE(Get(catalog, "polystyrene foam 27.6").compressive_strength_Pa.has_value());
  CHECK(Get(catalog, "PE foam Plastazote LD33").crush_behaviour ==
        covopt::materials::CrushBehaviour::kDoesNotCrush);
}

TEST_CASE("new soft paddings have their derived secant moduli", "[builtin]") {
  const Catalog& catalog = Catalog::BuiltIn();
  // CFD 34 kPa at 25 % -> 136 kPa; 2.8 kPa at 40 % -> 7 kPa; D1056 grade 2: 7 psi at 25 %.
  CHECK(Get(catalog, "PU foam PORON 4701-30 320").youngs_modulus_Pa == Approx(34e3 / 0.25));
  CHECK(Get(catalog, "PU foam HR 40/28").youngs_modulus_Pa == Approx(2.8e3 / 0.40));
  CHECK(Get(catalog, "neoprene sponge D1056 2C2").youngs_modulus_Pa ==
        Approx(7 * 6894.757 / 0.25));
  CHECK(Get(catalog, "XPS Styrofoam LB-X").youngs_modulus_Pa == 15e6);
}

TEST_CASE("crush behaviours read and print in the catalog spelling", "[strength]") {
  using covopt::materials::CrushBehaviour;
  using covopt::materials::ParseCrushBehaviour;
  for (const CrushBehaviour b :
       {CrushBehaviour::kCrushes, CrushBehaviour::kDoesNotCrush, CrushBehaviour::kUnknown}) {
    CHECK(ParseCrushBehaviour(covopt::materials::ToString(b)) == b);
  }
  CHECK(covopt::materials::ToString(CrushBehaviour::kDoesNotCrush) == "does-not-crush");
  CHECK_FALSE(ParseCrushBehaviour("does not crush").has_value());
}
