// Catalog files that are wrong. Every error must be a CatalogError whose message starts
// with "file:line:column:" pointing at the offending value (or key, or [[material]] header
// for a missing key), names the key, and says what is allowed. These tests check malformed
// TOML, unknown keys (with "did you mean"), missing required keys, wrong types, values out
// of range (E <= 0, E too large or not finite, nu > 0.5 or <= -1, density <= 0), values with
// units as in scene files (a bad unit, or a bare number implausible in SI: 27.6 for E is
// 27.6 Pa), unknown modulus bases, duplicate names within a file and across catalogs (both
// places named), files that cannot be read, and entries added in code; and the strength
// keys: a known strength needs its method and source, "does not crush" its reason and
// source, "unknown" neither; a bare strength must be plausible; negative, zero, NaN and
// infinite strengths, strengths mixed with words, and wrong types are refused; Catalog::Add
// checks the same rules (a strength is set exactly when the material crushes).

#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <utility>

#include <catch2/catch.hpp>
#include <unistd.h>

#include "catalog_test_support.hpp"
#include "covopt/materials.hpp"

using covopt::materials::Catalog;
using covopt::materials::CatalogError;
using covopt::materials::Material;
using covopt::materials::ModulusBasis;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

/// A valid entry, line by line; tests replace or drop lines.
const std::string kGood = R"([[material]]
name = "soft foam"
family = "foam"
youngs_modulus_Pa = 2.5e6
poisson_ratio = 0.3
density_kg_per_m3 = 30
modulus_basis = "compressive"
source = "a datasheet"
note = "secant over 0-10 % strain"
)";

using covopt::materials::testing::ErrorFor;

/// kGood with the line starting with `key =` replaced by `line` (dropped if empty).
std::string With(const std::string& key, const std::string& line) {
  return covopt::materials::testing::WithLine(kGood, key, line);
}

}  // namespace

TEST_CASE("the valid sample loads with every field", "[errors]") {
  const Catalog catalog = Catalog::FromTomlString(kGood, "mine.toml");
  REQUIRE(catalog.size() == 1);
  const Material& m = catalog.materials()[0];
  CHECK(m.name == "soft foam");
  CHECK(m.family == "foam");
  CHECK(m.youngs_modulus_Pa == 2.5e6);
  CHECK(m.poisson_ratio == 0.3);
  CHECK(m.density_kg_per_m3 == 30.0);
  CHECK(m.modulus_basis == ModulusBasis::kCompressive);
  CHECK(m.source == "a datasheet");
  CHECK(m.note == "secant over 0-10 % strain");
  CHECK(m.origin == "mine.toml:1:1");
}

TEST_CASE("an empty file is an empty catalog", "[errors]") {
  CHECK(Catalog::FromTomlString("", "mine.toml").empty());
  CHECK(Catalog::FromTomlString("# nothing yet\n", "mine.toml").empty());
}

TEST_CASE("malformed TOML gives file, line and column", "[errors]") {
  const CatalogError e = ErrorFor("[[material]]\nname = \"a\nfamily = \"foam\"\n");
  CHECK_THAT(e.what(), StartsWith("mine.toml:2:") && Contains("TOML syntax error"));
  CHECK(e.location().rfind("mine.toml:2:", 0) == 0);
  CHECK(e.key().empty());

  const CatalogError unclosed = ErrorFor(kGood + "[[material]\n");
  CHECK_THAT(unclosed.what(), StartsWith("mine.toml:10:") && Contains("TOML syntax error"));
}

TEST_CASE("an unknown key is named with its position and a suggestion", "[errors]") {
  SECTION("a typo") {
    const CatalogError e = ErrorFor(With("density_kg_per_m3", "density_kg_per_m = 30"));
    CHECK_THAT(e.what(), StartsWith("mine.toml:6:1: material #1: unknown key 'density_kg_per_m'") &&
                             Contains("did you mean 'density_kg_per_m3'?"));
    CHECK(e.key() == "density_kg_per_m");
  }
  SECTION("a common other name") {
    CHECK_THAT(ErrorFor(With("youngs_modulus_Pa", "E = 2.5e6")).what(),
               StartsWith("mine.toml:4:1:") && Contains("unknown key 'E'") &&
                   Contains("did you mean 'youngs_modulus_Pa'?"));
    CHECK_THAT(ErrorFor(With("poisson_ratio", "nu = 0.3")).what(),
               Contains("did you mean 'poisson_ratio'?"));
    CHECK_THAT(ErrorFor(With("density_kg_per_m3", "density = 30")).what(),
               Contains("did you mean 'density_kg_per_m3'?"));
  }
  SECTION("nothing close: the keys are listed") {
    CHECK_THAT(ErrorFor(kGood + "colour = \"blue\"\n").what(),
               StartsWith("mine.toml:10:1:") && Contains("unknown key 'colour'") &&
                   Contains("the keys are name, family, youngs_modulus_Pa"));
  }
  SECTION("the first unknown key in the file is reported") {
    CHECK_THAT(ErrorFor(With("name", "zzz = 1\nname = \"x\"") + "aaa = 2\n").what(),
               Contains("unknown key 'zzz'"));
  }
  SECTION("a top-level key") {
    CHECK_THAT(ErrorFor("materials = 1\n").what(),
               StartsWith("mine.toml:1:1: unknown top-level key 'materials'") &&
                   Contains("did you mean 'material'"));
    CHECK_THAT(ErrorFor("name = \"x\"\n" + kGood).what(),
               StartsWith("mine.toml:1:1:") && Contains("put it under a [[material]] header"));
  }
  SECTION("a single [material] table instead of [[material]]") {
    CHECK_THAT(ErrorFor("[material]\nname = \"x\"\n").what(),
               StartsWith("mine.toml:1:") && Contains("write [[material]]"));
  }
}

TEST_CASE("a missing required key points at the entry's header", "[errors]") {
  for (const char* key : {"name", "family", "youngs_modulus_Pa", "modulus_basis", "source"}) {
    CAPTURE(key);
    const CatalogError e = ErrorFor("\n\n" + With(key, ""));
    CHECK_THAT(e.what(), StartsWith("mine.toml:3:1: material ") &&
                             Contains(std::string("has no '") + key + "'") &&
                             Contains("required keys: name, family, youngs_modulus_Pa"));
    CHECK(e.key() == key);
  }
  // Once the name is known, the message uses it.
  CHECK_THAT(ErrorFor(With("source", "")).what(), Contains("material 'soft foam' has no 'source'"));
  // Optional keys may be left out: nu and density are then unknown.
  const Catalog catalog = Catalog::FromTomlString(With("note", ""), "mine.toml");
  CHECK(catalog.materials()[0].note.empty());
  const Material m = Catalog::FromTomlString(With("poisson_ratio", ""), "mine.toml").materials()[0];
  CHECK_FALSE(m.poisson_ratio.has_value());
  CHECK_FALSE(Catalog::FromTomlString(With("density_kg_per_m3", ""), "mine.toml")
                  .materials()[0]
                  .density_kg_per_m3.has_value());
}

TEST_CASE("poisson_ratio may be the string unknown", "[errors]") {
  const Catalog catalog =
      Catalog::FromTomlString(With("poisson_ratio", "poisson_ratio = \"unknown\""), "mine.toml");
  CHECK_FALSE(catalog.materials()[0].poisson_ratio.has_value());
  CHECK_THAT(ErrorFor(With("poisson_ratio", "poisson_ratio = \"unknwn\"")).what(),
             StartsWith("mine.toml:5:17: material 'soft foam': poisson_ratio") &&
                 Contains("or \"unknown\""));
}

TEST_CASE("values out of range are errors at the value, with the allowed range", "[errors]") {
  struct Case {
    const char* key;
    const char* line;
    const char* expected;
  };
  const auto c = GENERATE(values<Case>({
      {"youngs_modulus_Pa", "youngs_modulus_Pa = 0", "mine.toml:4:21: material 'soft foam': youngs_modulus_Pa must be in [1000, 1e+12] Pa (got 0)"},
      {"youngs_modulus_Pa", "youngs_modulus_Pa = -2.5e6", "youngs_modulus_Pa must be in [1000, 1e+12] Pa (got -2500000)"},
      {"youngs_modulus_Pa", "youngs_modulus_Pa = \"2000 GPa\"", "(got 2e+12)"},
      {"youngs_modulus_Pa", "youngs_modulus_Pa = inf", "youngs_modulus_Pa must be in [1000, 1e+12] Pa"},
      {"youngs_modulus_Pa", "youngs_modulus_Pa = nan", "youngs_modulus_Pa must be in [1000, 1e+12] Pa"},
      // The floor (physical_floors.hpp): a denormal modulus with a unit passes the bare-number check.
      {"youngs_modulus_Pa", "youngs_modulus_Pa = \"5e-324 Pa\"", "youngs_modulus_Pa must be in [1000, 1e+12] Pa (got 5e-324)"},
      {"youngs_modulus_Pa", "youngs_modulus_Pa = \"0.5 kPa\"", "(got 500)"},
      {"poisson_ratio", "poisson_ratio = 0.51", "mine.toml:5:17: material 'soft foam': poisson_ratio must be in (-1, 0.5], or \"unknown\" (got 0.51)"},
      {"poisson_ratio", "poisson_ratio = 0.7", "poisson_ratio must be in (-1, 0.5]"},
      {"poisson_ratio", "poisson_ratio = -1", "poisson_ratio must be in (-1, 0.5], or \"unknown\" (got -1)"},
      {"density_kg_per_m3", "density_kg_per_m3 = 0", "mine.toml:6:21: material 'soft foam': density_kg_per_m3 must be > 0 and <= 1e5 (kg/m³) (got 0)"},
      {"density_kg_per_m3", "density_kg_per_m3 = -30", "density_kg_per_m3 must be > 0"},
  }));
  CAPTURE(c.line);
  const CatalogError e = ErrorFor(With(c.key, c.line));
  CHECK_THAT(e.what(), Contains(c.expected));
  CHECK_THAT(e.what(), StartsWith("mine.toml:"));
  CHECK(e.key() == c.key);
}

TEST_CASE("values may carry units, as in scene files", "[errors][units]") {
  const auto load = [](const std::string& key, const std::string& line) {
    return Catalog::FromTomlString(With(key, line), "mine.toml").materials().front();
  };
  CHECK(load("youngs_modulus_Pa", "youngs_modulus_Pa = \"27.6MPa\"").youngs_modulus_Pa == 27.6e6);
  CHECK(load("youngs_modulus_Pa", "youngs_modulus_Pa = \"96.2 kPa\"").youngs_modulus_Pa == 96.2e3);
  CHECK(load("youngs_modulus_Pa", "youngs_modulus_Pa = \"3.3GPa\"").youngs_modulus_Pa == 3.3e9);
  CHECK(load("density_kg_per_m3", "density_kg_per_m3 = \"0.05 g/cm3\"").density_kg_per_m3 == 50.0);
  CHECK(load("density_kg_per_m3", "density_kg_per_m3 = \"38.4kg/m3\"").density_kg_per_m3 == 38.4);
  // ν = 0.5 (incompressible) is allowed, as in scenes: the range is (-1, 0.5].
  CHECK(load("poisson_ratio", "poisson_ratio = 0.5").poisson_ratio == 0.5);
}

TEST_CASE("a bare number is SI and must be plausible, a unit must fit", "[errors][units]") {
  CHECK(std::string(ErrorFor(With("youngs_modulus_Pa", "youngs_modulus_Pa = 27.6")).what()) ==
        "mine.toml:4:21: material 'soft foam': youngs_modulus_Pa 27.6: a bare number is in "
        "pascals (27.6 Pa); write \"27.6MPa\" or \"27.6Pa\"");
  CHECK(std::string(ErrorFor(With("density_kg_per_m3", "density_kg_per_m3 = 1.05")).what()) ==
        "mine.toml:6:21: material 'soft foam': density_kg_per_m3 1.05: a bare number is in "
        "kilograms per cubic metre (1.05 kg/m3); write \"1.05g/cm3\" or \"1.05kg/m3\"");
  const CatalogError unit = ErrorFor(With("youngs_modulus_Pa", "youngs_modulus_Pa = \"2 kg\""));
  CHECK(std::string(unit.what()) ==
        "mine.toml:4:21: material 'soft foam': youngs_modulus_Pa: unit 'kg' is not a modulus or "
        "pressure; use Pa, kPa, MPa, GPa, N/m2 or N/mm2 (got '2 kg')");
  CHECK(unit.key() == "youngs_modulus_Pa");
  CHECK_THAT(ErrorFor(With("density_kg_per_m3", "density_kg_per_m3 = \"50 kg/m2\"")).what(),
             StartsWith("mine.toml:6:21:") && Contains("unknown unit 'kg/m2' for a density"));
  CHECK_THAT(ErrorFor(With("youngs_modulus_Pa", "youngs_modulus_Pa = \"-2MPa\"")).what(),
             Contains("youngs_modulus_Pa must be in [1000, 1e+12] Pa"));
  // With a unit, the value is taken as written; only the catalog's range applies (from the
  // floor of 1 kPa).
  CHECK(Catalog::FromTomlString(With("youngs_modulus_Pa", "youngs_modulus_Pa = \"1.5kPa\""),
                                "mine.toml")
            .materials()
            .front()
            .youngs_modulus_Pa == 1500.0);
  CHECK_THAT(ErrorFor(With("youngs_modulus_Pa", "youngs_modulus_Pa = \"27.6Pa\"")).what(),
             Contains("youngs_modulus_Pa must be in [1000, 1e+12] Pa (got 27.6)"));
}

TEST_CASE("values of the wrong type are errors that show what to write", "[errors]") {
  CHECK_THAT(ErrorFor(With("youngs_modulus_Pa", "youngs_modulus_Pa = true")).what(),
             StartsWith("mine.toml:4:21:") &&
                 Contains("youngs_modulus_Pa must be a number in Pa or a string with a unit, "
                          "e.g. 27.6e6 or \"27.6MPa\" (got a boolean)"));
  CHECK_THAT(ErrorFor(With("name", "name = 42")).what(),
             StartsWith("mine.toml:2:8: material #1: name must be a string, got 42"));
  CHECK_THAT(ErrorFor(With("name", "name = \"\"")).what(), Contains("name must not be empty"));
  CHECK_THAT(ErrorFor(With("name", "name = \" soft\"")).what(),
             Contains("must not start or end with a space"));
  CHECK_THAT(ErrorFor(With("family", "family = \"  \"")).what(),
             Contains("family must not be empty"));
  CHECK_THAT(ErrorFor(With("density_kg_per_m3", "density_kg_per_m3 = \"unknown\"")).what(),
             Contains("density_kg_per_m3 must be a number in kg/m³ or a string with a unit") &&
                 Contains("leave it out if unknown (got \"unknown\")"));
  CHECK_THAT(ErrorFor(With("note", "note = 3")).what(), Contains("note must be a string"));
  CHECK_THAT(ErrorFor("material = 3\n").what(),
             StartsWith("mine.toml:1:") && Contains("must be a list of [[material]] tables"));
  CHECK_THAT(ErrorFor("material = [1]\n").what(),
             Contains("material #1 must be a table"));
}

TEST_CASE("an unknown modulus basis lists the bases and suggests one", "[errors]") {
  const CatalogError e = ErrorFor(With("modulus_basis", "modulus_basis = \"compresive\""));
  CHECK_THAT(e.what(),
             StartsWith("mine.toml:7:17: material 'soft foam': modulus_basis must be "
                        "compressive, tensile, bending, fitted, as-printed or hardness "
                        "(got \"compresive\"); did you mean 'compressive'?"));
  CHECK(e.key() == "modulus_basis");
}

TEST_CASE("duplicate names in one file are errors naming both places", "[errors]") {
  const std::string second = With("name", "name = \"Soft Foam\"");
  const CatalogError e = ErrorFor(kGood + "\n" + second);
  CHECK_THAT(e.what(), StartsWith("mine.toml:12:8: duplicate material name 'Soft Foam': "
                                  "already defined at mine.toml:1:1 as 'soft foam'") &&
                           Contains("ignoring case"));
  CHECK(e.key() == "name");
}

TEST_CASE("adding a catalog with a name already present names both places", "[errors]") {
  Catalog catalog = Catalog::BuiltIn();
  const std::size_t before = catalog.size();
  const Catalog mine = Catalog::FromTomlString(
      kGood + "\n" + With("name", "name = \"EPS GEOFOAM EPS15\""), "mine.toml");
  try {
    catalog.Add(mine);
    FAIL("no error");
  } catch (const CatalogError& e) {
    CHECK_THAT(e.what(), StartsWith("mine.toml:11:1: duplicate material name 'EPS GEOFOAM EPS15'") &&
                             Contains("already defined at built-in catalog.toml:") &&
                             Contains("as 'EPS geofoam EPS15'"));
  }
  CHECK(catalog.size() == before);  // all or nothing
  catalog.Add(Catalog::FromTomlString(kGood, "mine.toml"));
  CHECK(catalog.size() == before + 1);
  CHECK(catalog.Find("soft foam") != nullptr);
}

TEST_CASE("entries added in code are validated like file entries", "[errors]") {
  Catalog catalog;
  Material m;
  m.name = "gel pad";
  m.family = "elastomer";
  m.youngs_modulus_Pa = 0.2e6;
  m.modulus_basis = ModulusBasis::kTensile;
  m.source = "own measurement";
  catalog.Add(m);
  CHECK(catalog.size() == 1);

  const auto error_for = [&](Material bad) -> std::string {
    try {
      Catalog().Add(std::move(bad));
    } catch (const CatalogError& e) {
      return e.what();
    }
    return "";
  };
  Material bad = m;
  bad.poisson_ratio = 0.5;  // incompressible: allowed, as in scenes
  CHECK(error_for(bad).empty());
  bad.poisson_ratio = 0.55;
  CHECK_THAT(error_for(bad), StartsWith("material 'gel pad': poisson_ratio must be in (-1, 0.5]"));
  bad = m;
  bad.youngs_modulus_Pa = -1.0;
  CHECK_THAT(error_for(bad), Contains("youngs_modulus_Pa must be in [1000, 1e+12] Pa"));
  bad = m;
  bad.source.clear();
  CHECK_THAT(error_for(bad), Contains("source must not be empty"));
  bad = m;
  bad.name = "";
  CHECK_THAT(error_for(bad), StartsWith("material: name must not be empty"));

  bad = m;
  bad.name = "GEL PAD";
  try {
    catalog.Add(bad);
    FAIL("no error");
  } catch (const CatalogError& e) {
    CHECK_THAT(e.what(), StartsWith("duplicate material name 'GEL PAD': already defined at "
                                    "(added in code) as 'gel pad'"));
  }
}

TEST_CASE("a catalog file that cannot be read is an error naming it", "[errors]") {
  const auto missing = std::filesystem::temp_directory_path() / "covopt-no-such-catalog.toml";
  try {
    Catalog::FromTomlFile(missing);
    FAIL("no error");
  } catch (const CatalogError& e) {
    CHECK_THAT(e.what(), StartsWith("cannot read catalog file '" + missing.string() + "'") &&
                             Contains("No such file"));
  }
  try {
    Catalog::FromTomlFile(std::filesystem::temp_directory_path());
    FAIL("no error");
  } catch (const CatalogError& e) {
    CHECK_THAT(e.what(), Contains("it is a directory"));
  }
  // A real file names itself in every location.
  const auto path = std::filesystem::temp_directory_path() /
                    ("covopt-test-catalog-" + std::to_string(::getpid()) + ".toml");
  std::ofstream(path) << With("poisson_ratio", "poisson_ratio = 0.6");
  try {
    Catalog::FromTomlFile(path);
    FAIL("no error");
  } catch (const CatalogError& e) {
    CHECK_THAT(e.what(), StartsWith(path.string() + ":5:17: "));
  }
  std::filesystem::remove(path);
}

// ---- compressive_strength_Pa, strength_method, strength_source ------------------------------

namespace {

/// kGood with a known strength, its method and source (lines 10-12).
std::string WithStrength(const std::string& strength, bool method = true, bool source = true) {
  std::string text = kGood + "compressive_strength_Pa = " + strength + "\n";
  if (method) text += "strength_method = \"ASTM D1621, at yield or 10 % strain\"\n";
  if (source) text += "strength_source = \"a datasheet\"\n";
  return text;
}

}  // namespace

TEST_CASE("a compressive strength loads with its method and source", "[errors][strength]") {
  using covopt::materials::CrushBehaviour;
  const Material known =
      Catalog::FromTomlString(WithStrength("\"172 kPa\""), "mine.toml").materials()[0];
  CHECK(known.crush_behaviour == CrushBehaviour::kCrushes);
  CHECK(known.compressive_strength_Pa == 172e3);
  CHECK(known.strength_method == "ASTM D1621, at yield or 10 % strain");
  CHECK(known.strength_source == "a datasheet");
  CHECK(Catalog::FromTomlString(WithStrength("172e3"), "mine.toml")
            .materials()[0]
            .compressive_strength_Pa == 172e3);  // a plausible bare number is Pa

  const Material soft =
      Catalog::FromTomlString(WithStrength("\"does not crush\""), "mine.toml").materials()[0];
  CHECK(soft.crush_behaviour == CrushBehaviour::kDoesNotCrush);
  CHECK_FALSE(soft.compressive_strength_Pa.has_value());

  const Material unknown = Catalog::FromTomlString(
      kGood + "compressive_strength_Pa = \"unknown\"\n", "mine.toml").materials()[0];
  CHECK(unknown.crush_behaviour == CrushBehaviour::kUnknown);
  CHECK(unknown.strength_method.empty());
  // Absent: unknown (catalogs written before the key existed still load).
  const Material old = Catalog::FromTomlString(kGood, "mine.toml").materials()[0];
  CHECK(old.crush_behaviour == CrushBehaviour::kUnknown);
  CHECK_FALSE(old.compressive_strength_Pa.has_value());
}

TEST_CASE("strength errors are one line naming the key, the value and what is allowed",
          "[errors][strength]") {
  SECTION("a known strength without its method") {
    const CatalogError e = ErrorFor(WithStrength("\"172 kPa\"", false, true));
    CHECK(std::string(e.what()) ==
          "mine.toml:10:27: material 'soft foam': compressive_strength_Pa \"172 kPa\" needs a "
          "strength_method: the test method and what it measures, e.g. \"ASTM D1621, at yield "
          "or 10 % strain\"");
    CHECK(e.key() == "compressive_strength_Pa");
  }
  SECTION("a known strength without its source") {
    CHECK(std::string(ErrorFor(WithStrength("\"172 kPa\"", true, false)).what()) ==
          "mine.toml:10:27: material 'soft foam': compressive_strength_Pa \"172 kPa\" needs a "
          "strength_source: a URL or a citation for the strength");
  }
  SECTION("does not crush without the reason") {
    CHECK(std::string(ErrorFor(WithStrength("\"does not crush\"", false, true)).what()) ==
          "mine.toml:10:27: material 'soft foam': compressive_strength_Pa \"does not crush\" "
          "needs a strength_method: why it does not crush, e.g. \"flexible open-cell foam: "
          "densifies, no crush strength\"");
  }
  SECTION("unknown with a method") {
    const CatalogError e = ErrorFor(WithStrength("\"unknown\"", true, false));
    CHECK(std::string(e.what()) ==
          "mine.toml:11:19: material 'soft foam': strength_method is given but "
          "compressive_strength_Pa is \"unknown\"; give the strength (with a unit) or \"does "
          "not crush\", or leave strength_method out (a note may say why it is unknown)");
    CHECK(e.key() == "strength_method");
  }
  SECTION("a method without any strength") {
    CHECK_THAT(ErrorFor(kGood + "strength_method = \"ASTM D1621\"\n").what(),
               StartsWith("mine.toml:10:19: material 'soft foam': strength_method is given but "
                          "compressive_strength_Pa is missing (unknown)"));
  }
  SECTION("a strength mixed with does not crush") {
    const CatalogError e = ErrorFor(WithStrength("\"does not crush, 172 kPa\""));
    CHECK_THAT(e.what(), StartsWith("mine.toml:10:27: material 'soft foam': "
                                    "compressive_strength_Pa must be a stress with a unit "
                                    "(\"172 kPa\"), a number in Pa, \"does not crush\" or "
                                    "\"unknown\" (got \"does not crush, 172 kPa\")"));
    CHECK_THAT(ErrorFor(WithStrength("\"172 kPa does not crush\"")).what(),
               StartsWith("mine.toml:10:27: material 'soft foam': compressive_strength_Pa:"));
    CHECK_THAT(ErrorFor(WithStrength("\"does-not-crush\"")).what(),
               Contains("(got \"does-not-crush\"); did you mean 'does not crush'?"));
  }
  SECTION("an implausible bare number, with the likely unit") {
    CHECK(std::string(ErrorFor(WithStrength("172")).what()) ==
          "mine.toml:10:27: material 'soft foam': compressive_strength_Pa 172: a bare number is "
          "in pascals (172 Pa); write \"172kPa\" or \"172Pa\"");
  }
  SECTION("negative, zero, NaN, infinite") {
    CHECK(std::string(ErrorFor(WithStrength("\"-172 kPa\"")).what()) ==
          "mine.toml:10:27: material 'soft foam': compressive_strength_Pa must be in [1000, "
          "1e+12] Pa, or \"does not crush\" or \"unknown\" (got -172000)");
    CHECK_THAT(ErrorFor(WithStrength("-172e3")).what(),
               Contains("compressive_strength_Pa must be in [1000, 1e+12] Pa") && Contains("(got -172000)"));
    CHECK_THAT(ErrorFor(WithStrength("0")).what(), Contains("(got 0)"));
    CHECK_THAT(ErrorFor(WithStrength("nan")).what(),
               StartsWith("mine.toml:10:27: material 'soft foam': compressive_strength_Pa must "
                          "be in [1000, 1e+12] Pa") && Contains("(got nan)"));
    CHECK_THAT(ErrorFor(WithStrength("inf")).what(), Contains("compressive_strength_Pa must be in [1000, 1e+12] Pa"));
    CHECK_THAT(ErrorFor(WithStrength("\"nan kPa\"")).what(), Contains("not a finite number"));
  }
  SECTION("below the floor of 1 kPa: a denormal strength once gave crush ratios of inf") {
    const CatalogError e = ErrorFor(WithStrength("\"5e-324 Pa\""));
    CHECK(std::string(e.what()) ==
          "mine.toml:10:27: material 'soft foam': compressive_strength_Pa must be in [1000, "
          "1e+12] Pa, or \"does not crush\" or \"unknown\" (got 5e-324)");
    CHECK(e.key() == "compressive_strength_Pa");
    CHECK_THAT(ErrorFor(WithStrength("\"0.9 kPa\"")).what(), Contains("(got 900)"));
  }
  SECTION("wrong types and a blank method") {
    CHECK_THAT(ErrorFor(WithStrength("true")).what(),
               Contains("compressive_strength_Pa must be a stress with a unit") &&
                   Contains("(got a boolean)"));
    CHECK_THAT(ErrorFor(kGood + "compressive_strength_Pa = \"1 MPa\"\nstrength_method = 3\n").what(),
               StartsWith("mine.toml:11:19:") && Contains("strength_method must be a string"));
    CHECK_THAT(ErrorFor(kGood + "compressive_strength_Pa = \"1 MPa\"\nstrength_method = \" \"\n"
                                "strength_source = \"s\"\n")
                   .what(),
               Contains("strength_method must not be empty"));
  }
  SECTION("a unit that is no stress") {
    CHECK_THAT(ErrorFor(WithStrength("\"172 kg\"")).what(),
               StartsWith("mine.toml:10:27: material 'soft foam': compressive_strength_Pa: unit "
                          "'kg' is not a modulus or pressure"));
  }
  SECTION("unknown keys near the new ones get a suggestion") {
    CHECK_THAT(ErrorFor(kGood + "compressive_strength = \"1 MPa\"\n").what(),
               Contains("unknown key 'compressive_strength'; did you mean "
                        "'compressive_strength_Pa'?"));
    CHECK_THAT(ErrorFor(kGood + "strength_metod = \"x\"\n").what(),
               Contains("did you mean 'strength_method'?"));
    CHECK_THAT(ErrorFor(kGood + "strength_src = \"x\"\n").what(),
               Contains("did you mean 'strength_source'?"));
  }
}

TEST_CASE("Catalog::Add checks the strength fields as a file would", "[errors][strength]") {
  using covopt::materials::CrushBehaviour;
  Material m;
  m.name = "rigid foam";
  m.family = "foam";
  m.youngs_modulus_Pa = 20e6;
  m.modulus_basis = ModulusBasis::kCompressive;
  m.source = "a datasheet";
  const auto error_for = [](Material bad) -> std::string {
    try {
      Catalog().Add(std::move(bad));
    } catch (const CatalogError& e) {
      return e.what();
    }
    return "";
  };
  CHECK(error_for(m).empty());  // unknown, with nothing else: fine

  Material crushes = m;
  crushes.crush_behaviour = CrushBehaviour::kCrushes;
  crushes.compressive_strength_Pa = 0.3e6;
  crushes.strength_method = "EN 826, at 10 % strain";
  crushes.strength_source = "a datasheet";
  CHECK(error_for(crushes).empty());

  Material bad = crushes;
  bad.compressive_strength_Pa.reset();
  CHECK_THAT(error_for(bad), StartsWith("material 'rigid foam': compressive_strength_Pa is "
                                        "required when the material crushes"));
  bad = crushes;
  bad.compressive_strength_Pa = -1.0;
  CHECK_THAT(error_for(bad), StartsWith("material 'rigid foam': compressive_strength_Pa must be "
                                        "in [1000, 1e+12] Pa"));
  bad.compressive_strength_Pa = std::numeric_limits<double>::quiet_NaN();
  CHECK_THAT(error_for(bad), Contains("compressive_strength_Pa must be in [1000, 1e+12] Pa"));
  bad.compressive_strength_Pa = std::numeric_limits<double>::infinity();
  CHECK_THAT(error_for(bad), Contains("compressive_strength_Pa must be in [1000, 1e+12] Pa"));
  bad = crushes;
  bad.strength_method.clear();
  CHECK_THAT(error_for(bad), StartsWith("material 'rigid foam': strength_method must name the "
                                        "test method"));
  bad = crushes;
  bad.strength_source = "  ";
  CHECK_THAT(error_for(bad), StartsWith("material 'rigid foam': strength_source must say where"));

  // Set exactly when the material crushes.
  bad = crushes;
  bad.crush_behaviour = CrushBehaviour::kDoesNotCrush;
  CHECK_THAT(error_for(bad), StartsWith("material 'rigid foam': compressive_strength_Pa must be "
                                        "empty for a material that does not crush (got 3e+05)"));
  bad.compressive_strength_Pa.reset();
  CHECK(error_for(bad).empty());
  bad.strength_method.clear();
  CHECK_THAT(error_for(bad), Contains("strength_method must say why the material does not crush"));
  bad = crushes;
  bad.crush_behaviour = CrushBehaviour::kUnknown;
  CHECK_THAT(error_for(bad), Contains("compressive_strength_Pa must be empty when the crush "
                                      "behaviour is unknown"));
  bad.compressive_strength_Pa.reset();
  CHECK_THAT(error_for(bad), Contains("strength_method must be empty when the strength is unknown"));
  bad = m;
  bad.crush_behaviour = static_cast<CrushBehaviour>(7);
  CHECK_THAT(error_for(bad), Contains("invalid crush behaviour"));
}

TEST_CASE("a catalog file larger than 1 MiB, or an endless device, is refused at once", "[errors]") {
  // /dev/zero would be read forever: reading stops one byte past the limit.
  CHECK_THROWS_WITH(covopt::materials::Catalog::FromTomlFile("/dev/zero"),
                    Catch::Contains("'/dev/zero' is larger than 1 MiB"));
  // A regular file just over the limit: refused by size, not by its (valid) contents.
  const std::filesystem::path big =
      std::filesystem::temp_directory_path() / ("covopt-big-catalog-" + std::to_string(::getpid()) + ".toml");
  {
    std::ofstream out(big);
    out << std::string(covopt::materials::kMaxCatalogFileBytes, '#') << "\n";
  }
  CHECK_THROWS_WITH(covopt::materials::Catalog::FromTomlFile(big), Catch::Contains("larger than 1 MiB"));
  // At the limit it is read (a file of comments is an empty catalog).
  std::filesystem::resize_file(big, covopt::materials::kMaxCatalogFileBytes);
  CHECK(covopt::materials::Catalog::FromTomlFile(big).empty());
  std::filesystem::remove(big);
}

// toml++ 3.3.0 reached __builtin_unreachable() (undefined behaviour: UBSan aborts, an optimised
// build may do anything) when it asked whether a code point of U+00A1-U+0499, U+2C5E-U+3057 or
// U+FB26-U+FEFE is whitespace (covopt/internal/toml.hpp). Each such character where whitespace
// may stand is now an ordinary syntax error at its place.
TEST_CASE("A non-ASCII character where whitespace may stand is a syntax error, not undefined behaviour",
          "[catalog][errors]") {
  for (const char* character : {"\xd0\x80" /* U+0400 */, "\xc2\xa1" /* U+00A1 */,
                                "\xe3\x80\x81" /* U+3001 */, "\xef\xbc\x80" /* U+FF00 */,
                                "\xef\xac\xa6" /* U+FB26 */}) {
    const std::string c(character);
    for (const std::string& text : {"[[material]]" + c + "\n", "[[material]]\nname =" + c + " \"x\"\n",
                                    c + "[[material]]\n"}) {
      CAPTURE(text);
      const CatalogError error = ErrorFor(text);
      CHECK_THAT(error.what(), StartsWith("mine.toml:"));
    }
  }
  // Upstream's own case: a line-ending backslash in a multi-line string skips the whitespace
  // that follows, and asks of U+00A7 whether it is some.
  const Catalog catalog =
      Catalog::FromTomlString(With("name", "name = \"\"\"\\\n\xc2\xa7 foam\"\"\""), "mine.toml");
  REQUIRE(catalog.size() == 1);
  CHECK(catalog.materials().front().name == "\xc2\xa7 foam");
}
