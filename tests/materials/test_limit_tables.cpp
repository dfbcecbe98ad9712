// Limit tables as data (issue 38): the built-in table names both editions (ISO/TS 15066:2016
// Annex A = ISO 10218-2:2025 Annex M) and every limit cites it; a user's table file carries
// its own title and edition, is read once per content (the limits point into it), names the
// SHA-256 of its bytes, and is refused with file:line:column for each kind of error: an unknown
// key, a missing value, a negative, zero or NaN limit, a transient factor out of range, a
// duplicate region or area.

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include <catch2/catch.hpp>

#include "covopt/core/sha256.hpp"
#include "covopt/materials/body_regions.hpp"

using covopt::ContactType;
using covopt::materials::BodyRegionTable;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

constexpr const char* kBothEditions = "ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M";

std::string Bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The example table (every limit × 0.8) with the first `from` replaced by `to`.
std::string Example(const std::string& from = "", const std::string& to = "") {
  std::string text = Bytes(COVOPT_COMPANY_LIMITS_TOML);
  if (!from.empty()) {
    const auto at = text.find(from);
    REQUIRE(at != std::string::npos);
    text.replace(at, from.size(), to);
  }
  return text;
}

int LineOf(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  REQUIRE(at != std::string::npos);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

/// The message loading `text` as "own.toml" throws, which must start "own.toml:LINE:".
std::string Refusal(const std::string& text, int line) {
  try {
    BodyRegionTable::FromTomlText(text, "own.toml");
  } catch (const std::runtime_error& e) {
    CHECK_THAT(std::string(e.what()), StartsWith("own.toml:" + std::to_string(line) + ":"));
    return e.what();
  }
  FAIL("no error");
  return {};
}

}  // namespace

TEST_CASE("limit tables: SHA-256 is the FIPS 180-2 test vector") {
  CHECK(covopt::Sha256Hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(covopt::Sha256Hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
}

TEST_CASE("limit tables: the built-in table names both editions, and every limit cites them") {
  const BodyRegionTable& table = BodyRegionTable::BuiltIn();
  CHECK(table.info().edition == kBothEditions);
  CHECK(covopt::materials::BuiltInEdition() == kBothEditions);
  CHECK(table.info().built_in());
  CHECK(table.info().sha256 == covopt::Sha256Hex(Bytes(COVOPT_BODY_REGIONS_TOML)));
  for (const auto& limits : table.AllLimits(ContactType::kClamped)) {
    CHECK(limits.Citation() == kBothEditions);
    CHECK_THAT(limits.Describe(), StartsWith(std::string(kBothEditions) + ", quasi-static, "));
  }
}

TEST_CASE("limit tables: the example file is the built-in table with every force and pressure x 0.8") {
  const BodyRegionTable& own = BodyRegionTable::Load(COVOPT_COMPANY_LIMITS_TOML);
  const BodyRegionTable& iso = BodyRegionTable::BuiltIn();
  CHECK(own.info().source == COVOPT_COMPANY_LIMITS_TOML);
  CHECK_FALSE(own.info().built_in());
  CHECK(own.info().sha256 == covopt::Sha256Hex(Bytes(COVOPT_COMPANY_LIMITS_TOML)));
  CHECK_THAT(own.info().edition, Contains("0.8"));
  CHECK_THAT(own.info().edition, Contains(kBothEditions));
  // Read once: the same file is the same table (its limits point into it).
  CHECK(&BodyRegionTable::Load(COVOPT_COMPANY_LIMITS_TOML) == &own);
  for (const ContactType contact : {ContactType::kTransient, ContactType::kClamped}) {
    const auto a = iso.AllLimits(contact);
    const auto b = own.AllLimits(contact);
    REQUIRE(a.size() == b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      CAPTURE(a[i].Describe());
      CHECK(b[i].force_N == Approx(0.8 * a[i].force_N).epsilon(1e-12));
      CHECK(b[i].pressure_Pa == Approx(0.8 * a[i].pressure_Pa).epsilon(1e-12));
      CHECK(b[i].stiffness_N_per_m() == a[i].stiffness_N_per_m());
      CHECK(b[i].effective_mass_kg() == a[i].effective_mass_kg());
      CHECK(b[i].Citation() == own.info().edition);
      CHECK_THAT(b[i].Describe(), StartsWith(own.info().edition));
    }
  }
  CHECK_THROWS_WITH(own.Limits("face", "", ContactType::kTransient), Contains(own.info().edition));
  CHECK_THROWS_WITH(BodyRegionTable::Load("/nonexistent/own.toml"), Contains("/nonexistent/own.toml"));
}

TEST_CASE("limit tables: a table of its own regions and areas, with its own transient factor") {
  const std::string text = R"(title = "Two regions"
edition = "Example 1"
[sources]
X = "a measurement campaign"
[[region]]
name = "wrist"
title = "Wrist"
quasi_static_force_N = 100
transient_factor = 1.5
stiffness_N_per_mm = 40
effective_mass_kg = 2
sources = ["X"]
  [[region.area]]
  name = "wrist-back"
  title = "Back of the wrist"
  number = 1
  quasi_static_pressure_N_per_cm2 = 150
)";
  const BodyRegionTable t = BodyRegionTable::FromTomlText(text, "two.toml");
  const auto limits = t.Limits("wrist", "", ContactType::kTransient);
  CHECK(limits.force_N == 150.0);
  CHECK(limits.pressure_Pa == 1.5 * 150e4);
  CHECK(limits.Citation() == "Example 1");
  CHECK(t.info().title == "Two regions");
  CHECK_THROWS_WITH(t.Region("chest"), Contains("is not in Example 1"));
}

TEST_CASE("limit tables: each kind of bad table is refused with file:line:column naming the key") {
  SECTION("an unknown key") {
    const std::string text = Example("quasi_static_force_N = 112", "quasi_static_forse_N = 112");
    CHECK_THAT(Refusal(text, LineOf(text, "forse")), Contains("did you mean 'quasi_static_force_N'?"));
  }
  SECTION("a missing value") {
    const std::string text = Example("effective_mass_kg = 40\n", "");
    CHECK_THAT(Refusal(text, LineOf(text, "name = \"back-shoulders\"") - 1), Contains("has no 'effective_mass_kg'"));
  }
  SECTION("a missing edition or title") {
    const std::string text = Example("\nedition = ", "\nedition_ = ");
    CHECK_THAT(Refusal(text, LineOf(text, "edition_")), Contains("unknown key 'edition_'"));
    CHECK_THAT(Refusal(Example("\ntitle = ", "\n# title = "), 1), Contains("has no top-level 'title'"));
    const std::string blank = Example("\nedition = \"", "\nedition = \" \" # \"");
    CHECK_THAT(Refusal(blank, LineOf(blank, "\nedition") + 1), Contains("edition must be a non-blank string"));
  }
  SECTION("a negative, zero or NaN limit") {
    for (const std::string value : {"-112", "0", "nan"}) {
      CAPTURE(value);
      const std::string text = Example("quasi_static_force_N = 112", "quasi_static_force_N = " + value);
      CHECK_THAT(Refusal(text, LineOf(text, "quasi_static_force_N = " + value)),
                 Contains("region 'chest': quasi_static_force_N must be a number > 0"));
    }
    const std::string text = Example("quasi_static_pressure_N_per_cm2 = 96", "quasi_static_pressure_N_per_cm2 = -inf");
    CHECK_THAT(Refusal(text, LineOf(text, "-inf")), Contains("quasi_static_pressure_N_per_cm2 must be a number > 0"));
  }
  SECTION("a transient factor out of range") {
    for (const std::string value : {"0.5", "11", "0"}) {
      CAPTURE(value);
      const std::string text = Example("transient_factor = 2", "transient_factor = " + value);
      CHECK_THAT(Refusal(text, LineOf(text, "transient_factor = " + value)),
                 Contains("transient_factor must be a number >= 1 and <= 10, or \"not permitted\""));
    }
  }
  SECTION("a duplicate region or area") {
    const std::string region = Example("name = \"abdomen\"", "name = \"chest\"");
    CHECK_THAT(Refusal(region, LineOf(region, "title = \"Abdomen\"") - 1), Contains("name is defined twice"));
    const std::string area = Example("name = \"abdominal-muscle\"", "name = \"sternum\"");
    CHECK_THAT(Refusal(area, LineOf(area, "title = \"Abdominal muscle\"") - 1),
               Contains("area 'sternum' of region 'abdomen': name is defined twice"));
  }
}
