// `covopt materials list|show|find` and `covopt simulate --material`, run in-process
// through RunCli. These tests check that list and find print exactly what the library's
// Catalog holds and filters (compared with covopt::materials, never with printed numbers),
// that --json has the documented keys with SI values and null for an unknown ν or density,
// that show prints every field and answers a miss with exit 2 and a "did you mean", that
// user catalogs (--catalog, --no-builtin) extend or replace the built-in one and that their
// errors (bad TOML, a name clash) are bad input naming file:line:column, that range
// filters read units and refuse ambiguous or inverted ranges, and that simulate --material
// computes the same impact as the library with the entry's E and ν (0.25 with a warning
// when ν is unknown) and names the material in the JSON. And the compressive strength:
// list's strength column, show's strength, method and source (or "does not crush" with the
// reason, or "unknown"), the JSON keys, find --strength and --crush, and a bare range end
// refused when implausible ("--modulus 10..100" is exit 2 with one line).

#include <algorithm>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/core.hpp"
#include "covopt/materials.hpp"
#include "errors.hpp"
#include "materials_command.hpp"

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using covopt::cli::testing::TempDir;
using covopt::materials::Catalog;
using covopt::materials::Material;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using Json = nlohmann::json;

namespace {

/// Bad input: exit 2, nothing on stdout, and stderr says `message`.
void CheckBadInput(const std::vector<std::string>& args, const std::string& message) {
  const CliRun run = Run(args);
  CAPTURE(args, run.err);
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Contains(message));
}

std::vector<std::string> NamesIn(const Json& array) {
  std::vector<std::string> names;
  for (const Json& m : array) names.push_back(m["name"].get<std::string>());
  return names;
}

std::vector<std::string> NamesOf(const std::vector<const Material*>& materials) {
  std::vector<std::string> names;
  for (const Material* m : materials) names.push_back(m->name);
  return names;
}

/// A user catalog with one foam of unknown ν and one elastomer.
const char* const kUserCatalog = R"(# my lab's coverings
[[material]]
name = "lab foam A"
family = "foam"
youngs_modulus_Pa = 12e6
density_kg_per_m3 = 45
modulus_basis = "compressive"
source = "own test, 2024"
note = "secant over 0-2 % strain"

[[material]]
name = "lab gel"
family = "elastomer"
youngs_modulus_Pa = 0.4e6
poisson_ratio = 0.45
modulus_basis = "tensile"
source = "own test, 2024"
)";

}  // namespace

TEST_CASE("materials list prints every catalog entry and exits 0", "[materials]") {
  const CliRun run = Run({"materials", "list"});
  REQUIRE(run.exit_code == 0);
  CHECK(run.err.empty());
  const Catalog& catalog = Catalog::BuiltIn();
  for (const Material& m : catalog.materials()) CHECK_THAT(run.out, Contains(m.name));
  CHECK_THAT(run.out, Contains(std::to_string(catalog.size()) + " materials (the built-in catalog)"));
  CHECK_THAT(run.out, Contains("0.25 is assumed"));
  CHECK_THAT(run.out, Contains("27.6 MPa") && Contains("as-printed") && Contains("compressive"));
}

TEST_CASE("materials list --json is an array with the documented keys in SI", "[materials][json]") {
  const CliRun run = Run({"materials", "list", "--json"});
  REQUIRE(run.exit_code == 0);
  const Json json = Json::parse(run.out);
  const Catalog& catalog = Catalog::BuiltIn();
  REQUIRE(json.is_array());
  REQUIRE(json.size() == catalog.size());
  for (std::size_t i = 0; i < json.size(); ++i) {
    const Json& j = json[i];
    const Material& m = catalog.materials()[i];
    CAPTURE(m.name);
    for (const char* key : {"name", "family", "youngs_modulus_Pa", "poisson_ratio",
                            "density_kg_per_m3", "modulus_basis", "source", "note",
                            "crush_behaviour", "compressive_strength_Pa", "strength_method",
                            "strength_source", "defined_at"}) {
      CAPTURE(key);
      CHECK(j.contains(key));
    }
    CHECK(j["name"] == m.name);
    CHECK(j["family"] == m.family);
    CHECK(j["youngs_modulus_Pa"].get<double>() == m.youngs_modulus_Pa);
    if (m.poisson_ratio) {
      CHECK(j["poisson_ratio"].get<double>() == *m.poisson_ratio);
    } else {
      CHECK(j["poisson_ratio"].is_null());
    }
    if (m.density_kg_per_m3) {
      CHECK(j["density_kg_per_m3"].get<double>() == *m.density_kg_per_m3);
    } else {
      CHECK(j["density_kg_per_m3"].is_null());
    }
    CHECK(j["modulus_basis"] == std::string(covopt::materials::ToString(m.modulus_basis)));
    CHECK(j["source"] == m.source);
    CHECK(j["crush_behaviour"] == std::string(covopt::materials::ToString(m.crush_behaviour)));
    if (m.compressive_strength_Pa) {
      CHECK(j["compressive_strength_Pa"].get<double>() == *m.compressive_strength_Pa);
    } else {
      CHECK(j["compressive_strength_Pa"].is_null());
    }
    if (m.strength_method.empty()) {
      CHECK(j["strength_method"].is_null());
    } else {
      CHECK(j["strength_method"] == m.strength_method);
    }
    if (m.strength_source.empty()) {
      CHECK(j["strength_source"].is_null());
    } else {
      CHECK(j["strength_source"] == m.strength_source);
    }
  }
  const auto ps = std::find_if(json.begin(), json.end(),
                               [](const Json& j) { return j["name"] == "polystyrene foam 27.6"; });
  REQUIRE(ps != json.end());
  CHECK((*ps)["youngs_modulus_Pa"].get<double>() == 27.6e6);
  CHECK((*ps)["poisson_ratio"].get<double>() == 0.22);
  CHECK((*ps)["density_kg_per_m3"].get<double>() == 50.0);
}

TEST_CASE("materials show prints every field of one entry", "[materials]") {
  const CliRun run = Run({"materials", "show", "polystyrene foam 27.6"});
  REQUIRE(run.exit_code == 0);
  CHECK(run.err.empty());
  const Material& m = *Catalog::BuiltIn().Find("polystyrene foam 27.6");
  for (const char* label : {"family", "Young's modulus", "E basis", "Poisson ratio", "density",
                            "source", "note", "defined at"}) {
    CHECK_THAT(run.out, Contains(label));
  }
  CHECK_THAT(run.out, StartsWith("polystyrene foam 27.6\n"));
  CHECK_THAT(run.out, Contains("27.6 MPa") && Contains("0.22") && Contains("50 kg/m³") &&
                          Contains(m.source) && Contains("as-printed") &&
                          Contains("built-in catalog.toml:"));
  // Case and quoting do not matter: the words may come as separate arguments.
  CHECK(Run({"materials", "show", "POLYSTYRENE", "foam", "27.6"}).out == run.out);
}

TEST_CASE("materials show says when nu is unknown and which value is assumed", "[materials]") {
  const CliRun run = Run({"materials", "show", "EPS geofoam EPS15"});
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("unknown (0.25 is assumed where one is needed)"));
  CHECK_THAT(run.out, Contains("0-1 % strain"));
}

TEST_CASE("materials show --json is the entry as one object", "[materials][json]") {
  const CliRun run = Run({"materials", "show", "eps geofoam eps39", "--json"});
  REQUIRE(run.exit_code == 0);
  const Json json = Json::parse(run.out);
  const Material& m = *Catalog::BuiltIn().Find("EPS geofoam EPS39");
  CHECK(covopt::cli::testing::WithoutProvenance(json) == Json::parse(covopt::cli::MaterialToJson(m).dump()));
  CHECK(json["poisson_ratio"].is_null());
  CHECK(json["youngs_modulus_Pa"].get<double>() == 10.3e6);
}

TEST_CASE("materials show of a name not in the catalog is exit 2 with a suggestion",
          "[materials][errors]") {
  CheckBadInput({"materials", "show", "polystyrene"},
                "covopt materials show: error: no material 'polystyrene' in the catalog; did "
                "you mean 'polystyrene foam 27.6' or 'polystyrene foam 48.3'?");
  CheckBadInput({"materials", "show", "Rohacel 51"}, "did you mean 'PMI foam Rohacell 51'");
  CheckBadInput({"materials", "show", "unobtainium"},
                "no material 'unobtainium' in the catalog; run 'covopt materials list'");
  CheckBadInput({"materials", "show"}, "name is required");
  CheckBadInput({"materials"}, "covopt materials: error: A subcommand is required");
}

TEST_CASE("materials find returns what Catalog::Filter returns", "[materials][find]") {
  const Catalog& catalog = Catalog::BuiltIn();
  SECTION("modulus, density and family") {
    const CliRun run = Run({"materials", "find", "--modulus", "10MPa..100MPa", "--density",
                            "..60kg/m3", "--family", "foam", "--json"});
    REQUIRE(run.exit_code == 0);
    covopt::materials::MaterialFilter filter;
    filter.youngs_modulus_Pa = {10e6, 100e6};
    filter.density_kg_per_m3 = {std::nullopt, 60.0};
    filter.families = {"foam"};
    const auto expected = NamesOf(catalog.Filter(filter));
    CHECK(expected.size() >= 5);
    CHECK(NamesIn(Json::parse(run.out)) == expected);
  }
  SECTION("a Poisson ratio range leaves unknown ν out unless asked") {
    const Json known = Json::parse(
        Run({"materials", "find", "--poisson", "0.2..0.3", "--json"}).out);
    for (const Json& m : known) {
      CHECK(m["poisson_ratio"].get<double>() >= 0.2);
      CHECK(m["poisson_ratio"].get<double>() <= 0.3);
    }
    const Json with_unknown = Json::parse(
        Run({"materials", "find", "--poisson", "0.2..0.3", "--include-unknown", "--json"}).out);
    CHECK(with_unknown.size() > known.size());
    CHECK(std::any_of(with_unknown.begin(), with_unknown.end(),
                      [](const Json& m) { return m["poisson_ratio"].is_null(); }));
  }
  SECTION("units: g/cm3, kPa, and one-sided ranges") {
    const Json soft = Json::parse(
        Run({"materials", "find", "--modulus", "..1MPa", "--json"}).out);
    covopt::materials::MaterialFilter filter;
    filter.youngs_modulus_Pa = {std::nullopt, 1e6};
    CHECK(NamesIn(soft) == NamesOf(catalog.Filter(filter)));
    const Json dense = Json::parse(
        Run({"materials", "find", "--density", "0.3g/cm3..", "--json"}).out);
    covopt::materials::MaterialFilter dense_filter;
    dense_filter.density_kg_per_m3 = {300.0, std::nullopt};
    CHECK(NamesIn(dense) == NamesOf(catalog.Filter(dense_filter)));
    CHECK(std::find(NamesIn(dense).begin(), NamesIn(dense).end(), "sponge rubber 1040") !=
          NamesIn(dense).end());
    const Json kpa = Json::parse(
        Run({"materials", "find", "--modulus", "100kPa..200kPa", "--json"}).out);
    covopt::materials::MaterialFilter kpa_filter;
    kpa_filter.youngs_modulus_Pa = {100e3, 200e3};
    CHECK(NamesIn(kpa) == NamesOf(catalog.Filter(kpa_filter)));
    CHECK(NamesIn(kpa).front() == "PE foam Plastazote LD33");
  }
  SECTION("basis, name and several families") {
    const Json fitted = Json::parse(Run({"materials", "find", "--basis", "fitted", "--json"}).out);
    CHECK(fitted.size() == 4);
    const Json named = Json::parse(Run({"materials", "find", "--name", "XPS", "--json"}).out);
    CHECK(named.size() == 5);  // Foamular 250/400/600, Dow blue, Styrofoam LB-X
    const Json two = Json::parse(Run({"materials", "find", "--family", "padding", "--family",
                                      "Thermoplastic", "--json"})
                                     .out);
    CHECK(two.size() == 9);  // 4 Park paddings, 2 helmet pads, 3 nylons
  }
}

TEST_CASE("materials find prints a table, or says that nothing matches", "[materials][find]") {
  const CliRun run = Run({"materials", "find", "--modulus", "20MPa..40MPa", "--family", "foam"});
  REQUIRE(run.exit_code == 0);
  const std::string total = std::to_string(Catalog::BuiltIn().size());
  CHECK_THAT(run.out, Contains("polystyrene foam 27.6") && Contains("XPS Foamular 600") &&
                          Contains("of " + total + " materials match E 20MPa..40MPa, family foam"));
  CHECK_THAT(run.out, !Contains("polystyrene foam 48.3"));

  const CliRun none = Run({"materials", "find", "--modulus", "1TPa.."});
  CHECK(none.exit_code == 2);  // TPa is no unit: bad input, not an empty answer
  const CliRun empty = Run({"materials", "find", "--modulus", "500GPa.."});
  REQUIRE(empty.exit_code == 0);
  CHECK_THAT(empty.out,
             StartsWith("No material of the built-in catalog (" + total + " materials) matches"));
  CHECK(Json::parse(Run({"materials", "find", "--modulus", "500GPa..", "--json"}).out).empty());
}

TEST_CASE("materials find refuses bad ranges, families and bases", "[materials][find][errors]") {
  CheckBadInput({"materials", "find", "--modulus", "10MPa"},
                "--modulus: expected a range LO..HI, LO.. or ..HI, e.g. 10MPa..100MPa (got '10MPa')");
  CheckBadInput({"materials", "find", "--modulus", "100MPa..10MPa"},
                "--modulus: the lower end is above the upper end (got '100MPa..10MPa')");
  CheckBadInput({"materials", "find", "--modulus", "10..100MPa"},
                "--modulus: give the unit on both ends, e.g. 10MPa..100MPa; a bare number is SI");
  CheckBadInput({"materials", "find", "--modulus", ".."}, "give at least one end");
  CheckBadInput({"materials", "find", "--density", "..60kg"},
                "--density: unit 'kg' is not a density; use kg/m3 or g/cm3");
  CheckBadInput({"materials", "find", "--poisson", "0.2...0.3"}, "malformed range");
  CheckBadInput({"materials", "find", "--family", "metal"},
                "--family: no family 'metal' in the catalog; the families are 'foam', 'padding'");
  CheckBadInput({"materials", "find", "--basis", "measured"},
                "--basis: expected 'compressive', 'tensile', 'bending', 'fitted', 'as-printed' "
                "or 'hardness' (got 'measured')");
}

TEST_CASE("ParseRange reads closed and one-sided ranges in SI", "[materials][find]") {
  using covopt::cli::ParseRange;
  using covopt::cli::QuantityKind;
  const covopt::cli::QuantitySpec modulus{QuantityKind::kModulus};
  const auto both = ParseRange("10MPa..100 MPa", modulus, "--modulus");
  CHECK(both.min == 10e6);
  CHECK(both.max == Approx(100e6));
  const auto low = ParseRange(" 1GPa.. ", modulus, "--modulus");
  CHECK(low.min == 1e9);
  CHECK_FALSE(low.max.has_value());
  CHECK(ParseRange("0..5MPa", modulus, "--modulus").min == 0.0);  // a bare 0 needs no unit
  CHECK(ParseRange("1e6..2e6", modulus, "--modulus").max == 2e6);  // both bare: SI
  const auto ratio = ParseRange(".2..0.3", {QuantityKind::kDimensionless}, "--poisson");
  CHECK(ratio.min == 0.2);
  CHECK(ratio.max == 0.3);
  // Three dots could be "0.2." and ".3" or "0.2" and "..3": refused.
  CHECK_THROWS_AS(ParseRange("0.2...3", {QuantityKind::kDimensionless}, "--poisson"),
                  covopt::cli::InputError);
}

TEST_CASE("a user catalog extends the built-in one", "[materials][catalog]") {
  TempDir dir;
  const std::string file = dir.Write("lab.toml", kUserCatalog).string();
  const CliRun run = Run({"materials", "list", "--catalog", file});
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("lab foam A") && Contains("polystyrene foam 27.6") &&
                          Contains(std::to_string(Catalog::BuiltIn().size() + 2) +
                                   " materials (the built-in catalog and " + file + ")"));

  const CliRun show = Run({"materials", "show", "lab foam a", "--catalog", file});
  REQUIRE(show.exit_code == 0);
  CHECK_THAT(show.out, Contains("defined at       " + file + ":2:1"));

  const Json only = Json::parse(
      Run({"materials", "list", "--json", "--no-builtin", "--catalog", file}).out);
  CHECK(NamesIn(only) == std::vector<std::string>{"lab foam A", "lab gel"});

  const Json found = Json::parse(Run({"materials", "find", "--modulus", "10MPa..13MPa",
                                      "--catalog", file, "--json"})
                                     .out);
  CHECK(NamesIn(found) == std::vector<std::string>{"EPS geofoam EPS39", "lab foam A"});
}

TEST_CASE("user catalog errors are bad input with file, line and column", "[materials][catalog][errors]") {
  TempDir dir;
  const std::string clash = dir.Write("clash.toml", std::string(kUserCatalog) + R"(
[[material]]
name = "Polystyrene Foam 27.6"
family = "foam"
youngs_modulus_Pa = 27e6
modulus_basis = "as-printed"
source = "elsewhere"
)")
                                .string();
  CheckBadInput({"materials", "list", "--catalog", clash},
                clash + ":19:1: duplicate material name 'Polystyrene Foam 27.6': already defined "
                        "at built-in catalog.toml:");
  // The same file alone is fine: the clash is with the built-in catalog.
  CHECK(Run({"materials", "list", "--no-builtin", "--catalog", clash}).exit_code == 0);

  const std::string broken = dir.Write("broken.toml", "[[material]]\nname = \"x\nfamily = 1\n").string();
  CheckBadInput({"materials", "list", "--catalog", broken}, broken + ":2:");
  CheckBadInput({"materials", "list", "--catalog", broken}, "TOML syntax error");

  const std::string bad_nu = dir.Write("nu.toml", "[[material]]\nname = \"x\"\nfamily = \"foam\"\n"
                                                  "youngs_modulus_Pa = 1e6\npoisson_ratio = 0.51\n"
                                                  "modulus_basis = \"fitted\"\nsource = \"s\"\n")
                                 .string();
  CheckBadInput({"materials", "show", "x", "--catalog", bad_nu},
                bad_nu + ":5:17: material 'x': poisson_ratio must be in (-1, 0.5]");
  CheckBadInput({"materials", "list", "--catalog", (dir / "missing.toml").string()},
                "cannot read catalog file");
  CheckBadInput({"materials", "list", "--no-builtin"}, "--no-builtin leaves no catalog");
}

TEST_CASE("simulate --material computes the impact with the entry's E and nu", "[materials][simulate]") {
  const CliRun run = Run({"simulate", "--material", "polystyrene foam 48.3", "--json"});
  REQUIRE(run.exit_code == 0);
  CHECK(run.err.empty());
  const Json json = Json::parse(run.out);
  covopt::Scene scene;
  scene.covering.youngs_modulus_Pa = 48.3e6;
  scene.covering.poisson_ratio = 0.25;
  const covopt::ImpactResult expected = covopt::SolveExact(covopt::ImpactModel::FromScene(scene));
  CHECK(json["max_energy_density_J_per_m2"].get<double>() ==
        expected.peaks.max_energy_density_J_per_m2);
  CHECK(json["peak_force_N"].get<double>() == expected.peaks.peak_force_N);
  CHECK(json["scene"]["covering"]["material"] == "polystyrene foam 48.3");
  CHECK(json["scene"]["covering"]["youngs_modulus_Pa"].get<double>() == 48.3e6);
  CHECK(json["warnings"].empty());

  // The paper's 27.6 MPa foam has its own ν, 0.22, not the default 0.25.
  const Json ps = Json::parse(Run({"simulate", "--material", "polystyrene foam 27.6", "--json"}).out);
  CHECK(ps["scene"]["covering"]["poisson_ratio"].get<double>() == 0.22);

  // Without --material the key is there, null.
  CHECK(Json::parse(Run({"simulate", "--json"}).out)["scene"]["covering"]["material"].is_null());

  const CliRun table = Run({"simulate", "--material", "polystyrene foam 48.3"});
  CHECK_THAT(table.out, Contains("covering 15 mm 'polystyrene foam 48.3', E 48.3 MPa, ν 0.25"));
}

TEST_CASE("simulate --material with unknown nu assumes 0.25 and says so", "[materials][simulate]") {
  const CliRun run = Run({"simulate", "--material", "XPS Foamular 250", "--json"});
  REQUIRE(run.exit_code == 0);
  const Json json = Json::parse(run.out);
  CHECK(json["scene"]["covering"]["poisson_ratio"].get<double>() == 0.25);
  const auto& warnings = json["warnings"];
  CHECK(std::any_of(warnings.begin(), warnings.end(), [](const Json& w) {
    return w.get<std::string>() ==
           "the catalog gives no Poisson ratio for 'XPS Foamular 250': ν unknown, 0.25 assumed";
  }));
  const CliRun table = Run({"simulate", "--material", "XPS Foamular 250"});
  CHECK_THAT(table.out, Contains("ν 0.25 (assumed)") && Contains("ν unknown, 0.25 assumed"));
}

TEST_CASE("simulate --material takes a user catalog and overrides the scene file",
          "[materials][simulate]") {
  TempDir dir;
  const std::string file = dir.Write("lab.toml", kUserCatalog).string();
  const std::string scene = dir.Write("scene.toml", "[covering]\nmodulus = \"5 MPa\"\n"
                                                    "thickness = \"20 mm\"\n")
                                .string();
  const CliRun run = Run({"simulate", "--scene", scene, "--material", "lab gel", "--catalog",
                          file, "--json"});
  REQUIRE(run.exit_code == 0);
  const Json json = Json::parse(run.out);
  CHECK(json["scene"]["covering"]["youngs_modulus_Pa"].get<double>() == 0.4e6);
  CHECK(json["scene"]["covering"]["poisson_ratio"].get<double>() == 0.45);
  CHECK(json["scene"]["covering"]["thickness_m"].get<double>() == Approx(0.02));
  CHECK(json["scene"]["covering"]["material"] == "lab gel");
}

TEST_CASE("simulate --material refuses what does not combine or does not exist",
          "[materials][simulate][errors]") {
  CheckBadInput({"simulate", "--material", "polystyrene foam 27.6", "--covering-modulus", "3MPa"},
                "--material 'polystyrene foam 27.6' sets the covering's modulus and Poisson "
                "ratio; give either --material or --covering-modulus, not both");
  CheckBadInput({"simulate", "--material", "polystyrene foam 27.6", "--covering-poisson", "0.3"},
                "give either --material or --covering-poisson, not both");
  CheckBadInput({"simulate", "--material", "EPS15"},
                "covopt simulate: error: --material: no material 'EPS15' in the catalog; did "
                "you mean 'EPS geofoam EPS15'?");
  CheckBadInput({"simulate", "--catalog", "lab.toml"}, "--catalog applies only with --material NAME");
  CheckBadInput({"simulate", "--no-builtin"}, "--no-builtin applies only with --material NAME");
  CheckBadInput({"simulate", "--material", "x", "--no-builtin"}, "--no-builtin leaves no catalog");
}

TEST_CASE("simulate --material without a covering is reported as ignored", "[materials][simulate]") {
  const CliRun run = Run({"simulate", "--material", "XPS Foamular 250", "--covering-thickness",
                          "0", "--json"});
  REQUIRE(run.exit_code == 0);
  const Json json = Json::parse(run.out);
  REQUIRE(json["warnings"].size() == 1);
  CHECK(json["warnings"][0] ==
        "no covering (covering.thickness = 0), so --material 'XPS Foamular 250' is ignored");
}

// ---- The compressive strength ---------------------------------------------------------------

TEST_CASE("materials list shows each material's strength", "[materials][strength]") {
  const CliRun run = Run({"materials", "list"});
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("strength") && Contains("E basis"));
  const auto row = [&](const std::string& name) {
    const auto at = run.out.find("\n" + name + " ");
    REQUIRE(at != std::string::npos);
    return run.out.substr(at + 1, run.out.find('\n', at + 1) - at - 1);
  };
  CHECK_THAT(row("XPS Foamular 250"), Contains("  172 kPa  "));
  CHECK_THAT(row("EPS geofoam EPS39"), Contains("  276 kPa  "));
  CHECK_THAT(row("nylon bumper cover Qolo"), Contains("  86.2 MPa  "));
  CHECK_THAT(row("silicone Sylgard 184"), Contains("  no crush  "));
  CHECK_THAT(row("polystyrene foam 27.6"), Contains("  unknown  "));
  CHECK_THAT(run.out, Contains("no crush = densifies instead"));
}

TEST_CASE("materials show prints the strength with its method and source", "[materials][strength]") {
  const CliRun xps = Run({"materials", "show", "XPS Foamular 250"});
  REQUIRE(xps.exit_code == 0);
  CHECK_THAT(xps.out, Contains("strength         172.369 kPa (172368.925 Pa)") &&
                          Contains("strength method  ASTM D1621") &&
                          Contains("strength source  https://studylib.net/doc/18458375"));
  const CliRun gel = Run({"materials", "show", "silicone Sylgard 184"});
  CHECK_THAT(gel.out, Contains("strength         does not crush: solid elastomer") &&
                          Contains("strength source  ASTM definition of an elastomer"));
  const CliRun paper = Run({"materials", "show", "polystyrene foam 27.6"});
  CHECK_THAT(paper.out, Contains("strength         unknown: a design with this material cannot "
                                 "be verified for crushing"));
  CHECK_THAT(paper.out, !Contains("strength method"));

  const Json json = Json::parse(Run({"materials", "show", "XPS Foamular 250", "--json"}).out);
  CHECK(json["crush_behaviour"] == "crushes");
  CHECK(json["compressive_strength_Pa"].get<double>() == Approx(172368.925));
  CHECK(json["strength_method"].get<std::string>().find("ASTM D1621") != std::string::npos);
  const Json soft = Json::parse(Run({"materials", "show", "PU foam HR 40/28", "--json"}).out);
  CHECK(soft["crush_behaviour"] == "does-not-crush");
  CHECK(soft["compressive_strength_Pa"].is_null());
  CHECK(soft["strength_method"].is_string());
  const Json paper_json = Json::parse(Run({"materials", "show", "Park padding 30", "--json"}).out);
  CHECK(paper_json["crush_behaviour"] == "unknown");
  CHECK(paper_json["strength_method"].is_null());
  CHECK(paper_json["strength_source"].is_null());
}

TEST_CASE("materials find filters by strength and crush behaviour", "[materials][find][strength]") {
  const Catalog& catalog = Catalog::BuiltIn();
  const Json strong = Json::parse(Run({"materials", "find", "--strength", "1MPa..", "--json"}).out);
  CHECK(NamesIn(strong) == std::vector<std::string>{"nylon bumper cover Qolo",
                                                    "nylon 101 PA66 extruded",
                                                    "nylon Nycast 6PA cast"});
  const Json band = Json::parse(
      Run({"materials", "find", "--strength", "150kPa..300kPa", "--json"}).out);
  covopt::materials::MaterialFilter filter;
  filter.compressive_strength_Pa = {150e3, 300e3};
  CHECK(NamesIn(band) == NamesOf(catalog.Filter(filter)));
  CHECK(band.size() == 6);  // 5 rigid foams and the hard helmet pad's FE card (yield 210 kPa)
  for (const Json& m : band) CHECK(m["crush_behaviour"] == "crushes");

  const Json soft = Json::parse(
      Run({"materials", "find", "--crush", "does-not-crush", "--family", "foam", "--json"}).out);
  CHECK(soft.size() >= 14);
  for (const Json& m : soft) CHECK(m["crush_behaviour"] == "does-not-crush");
  const Json two = Json::parse(
      Run({"materials", "find", "--crush", "crushes", "--crush", "unknown", "--json"}).out);
  CHECK(two.size() + Json::parse(Run({"materials", "find", "--crush", "does-not-crush", "--json"}).out).size() ==
        catalog.size());

  const CliRun table = Run({"materials", "find", "--strength", "1MPa.."});
  CHECK_THAT(table.out, Contains("3 of " + std::to_string(catalog.size()) +
                                 " materials match strength 1MPa.."));
}

TEST_CASE("a bare range end is refused when implausible, as a bare number is",
          "[materials][find][errors]") {
  // Issue 21: "--modulus 10..100" read as 10 Pa to 100 Pa and exited 0.
  const CliRun run = Run({"materials", "find", "--modulus", "10..100"});
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK(run.err == "covopt materials find: error: --modulus 10: a bare number is in pascals "
                   "(10 Pa); write 10MPa or 10Pa\n");
  CheckBadInput({"materials", "find", "--modulus", "..100"}, "--modulus 100: a bare number is in pascals");
  CheckBadInput({"materials", "find", "--density", "0.02..0.06"},
                "--density 0.02: a bare number is in kilograms per cubic metre");
  CheckBadInput({"materials", "find", "--strength", "100..500"},
                "--strength 100: a bare number is in pascals (100 Pa); write 100kPa or 100Pa");
  CheckBadInput({"materials", "find", "--strength", "1MPa"},
                "--strength: expected a range LO..HI, LO.. or ..HI, e.g. 100kPa..1MPa");
  CheckBadInput({"materials", "find", "--crush", "crush"},
                "--crush: expected 'crushes', 'does-not-crush' or 'unknown' (got 'crush')");
  // Plausible bare ends still pass, and a bare 0 needs no unit.
  CHECK(Run({"materials", "find", "--modulus", "1e6..1e8"}).exit_code == 0);
  CHECK(Run({"materials", "find", "--modulus", "0..1e8"}).exit_code == 0);
  CHECK(Run({"materials", "find", "--strength", "1e5..1e6"}).exit_code == 0);
}
