// ISO/TS 15066's body-region table (BodyRegionTable). The built-in table must hold Tables A.2
// and A.3 exactly: the expected values below are an independent transcription of the
// standard's tables (in the standard's units, N, N/cm², N/mm, kg), compared with the loaded
// SI values after conversion. Then the lookups: transient limits are twice the quasi-static
// ones, transient contact with the skull/forehead and the face is refused naming A.3.2,
// clamped contact has m_H = inf, an empty area is the region's lowest pressure, names are
// normalised, unknown names are answered with the choices; and table files that are wrong
// give "file:line:column:" errors naming the key.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "covopt/materials/body_regions.hpp"

using covopt::ContactType;
using covopt::materials::BodyArea;
using covopt::materials::BodyLimits;
using covopt::materials::BodyRegion;
using covopt::materials::BodyRegionError;
using covopt::materials::BodyRegionTable;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

struct ExpectedArea {
  const char* name;
  double pressure_N_per_cm2;
};

struct ExpectedRegion {
  const char* name;
  double force_N;
  bool transient_permitted;
  double k_N_per_mm;
  double mass_kg;
  std::vector<ExpectedArea> areas;
};

// ISO/TS 15066:2016 Table A.2 (F_qs, p_qs, transient ×2 or not permitted) and Table A.3
// (k, m_H), in the standard's order; the areas are numbered 1..29 in this order.
const std::vector<ExpectedRegion> kStandard = {
    {"skull-forehead", 130, false, 150, 4.4, {{"forehead", 130}, {"temple", 110}}},
    {"face", 65, false, 75, 4.4, {{"masticatory-muscle", 110}}},
    {"neck", 150, true, 50, 1.2, {{"neck-muscle", 140}, {"seventh-neck-muscle", 210}}},
    {"back-shoulders", 210, true, 35, 40, {{"shoulder-joint", 160}, {"fifth-lumbar-vertebra", 210}}},
    {"chest", 140, true, 25, 40, {{"sternum", 120}, {"pectoral-muscle", 170}}},
    {"abdomen", 110, true, 10, 40, {{"abdominal-muscle", 140}}},
    {"pelvis", 180, true, 25, 40, {{"pelvic-bone", 210}}},
    {"upper-arms-elbows", 150, true, 30, 3, {{"deltoid-muscle", 190}, {"humerus", 220}}},
    {"lower-arms-wrists", 160, true, 40, 2,
     {{"radial-bone", 190}, {"forearm-muscle", 180}, {"arm-nerve", 180}}},
    {"hands-fingers", 140, true, 75, 0.6,
     {{"forefinger-pad-dominant", 300},
      {"forefinger-pad-non-dominant", 270},
      {"forefinger-end-joint-dominant", 280},
      {"forefinger-end-joint-non-dominant", 220},
      {"thenar-eminence", 200},
      {"palm-dominant", 260},
      {"palm-non-dominant", 260},
      {"back-of-hand-dominant", 200},
      {"back-of-hand-non-dominant", 190}}},
    {"thighs-knees", 220, true, 50, 75, {{"thigh-muscle", 250}, {"kneecap", 220}}},
    {"lower-legs", 130, true, 60, 75, {{"middle-of-shin", 220}, {"calf-muscle", 210}}},
};

const BodyRegionTable& Table() { return BodyRegionTable::BuiltIn(); }

/// The message of the BodyRegionError that `f` throws; fails the test if none.
template <class F>
std::string BodyRegionErrorOf(F&& f) {
  try {
    f();
  } catch (const BodyRegionError& e) {
    return e.what();
  }
  FAIL("no BodyRegionError");
  return {};
}

/// A valid one-region table; tests replace lines.
const std::string kGood = R"(title = "My limits"
edition = "Mine 2026"
[sources]
A = "a copy of the standard"

[[region]]
name = "chest"
title = "Chest"
quasi_static_force_N = 140
transient_factor = 2
stiffness_N_per_mm = 25
effective_mass_kg = 40
sources = ["A"]

  [[region.area]]
  name = "sternum"
  title = "Sternum"
  number = 1
  quasi_static_pressure_N_per_cm2 = 120

  [[region.area]]
  name = "pectoral-muscle"
  title = "Pectoral muscle"
  number = 2
  quasi_static_pressure_N_per_cm2 = 170
)";

/// kGood with the first occurrence of `from` replaced by `to`.
std::string Replaced(const std::string& from, const std::string& to) {
  std::string text = kGood;
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
  return text;
}

/// The message of the std::runtime_error that loading `text` as "mine.toml" throws.
std::string LoadError(const std::string& text) {
  try {
    BodyRegionTable::FromTomlText(text, "mine.toml");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  FAIL("no error for:\n" << text);
  return {};
}

/// The 1-based line of `text` on which `needle` first occurs.
int LineOf(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  REQUIRE(at != std::string::npos);
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

}  // namespace

TEST_CASE("body regions: the built-in table is ISO/TS 15066 Tables A.2 and A.3, value for value") {
  const auto& regions = Table().regions();
  REQUIRE(regions.size() == 12);
  REQUIRE(kStandard.size() == 12);
  CHECK(Table().area_count() == 29);
  int number = 0;
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const BodyRegion& r = regions[i];
    const ExpectedRegion& e = kStandard[i];
    CAPTURE(e.name);
    CHECK(r.name == e.name);
    CHECK_FALSE(r.title.empty());
    CHECK(r.quasi_static_force_N == e.force_N);
    CHECK(r.transient_permitted() == e.transient_permitted);
    CHECK(r.transient_factor == (e.transient_permitted ? 2.0 : 0.0));
    CHECK(r.stiffness_N_per_m == e.k_N_per_mm * 1e3);
    CHECK(r.effective_mass_kg == e.mass_kg);
    CHECK_FALSE(r.sources.empty());
    REQUIRE(r.areas.size() == e.areas.size());
    for (std::size_t j = 0; j < r.areas.size(); ++j) {
      CAPTURE(e.areas[j].name);
      ++number;
      CHECK(r.areas[j].name == e.areas[j].name);
      CHECK(r.areas[j].number == number);
      CHECK(r.areas[j].quasi_static_pressure_Pa == e.areas[j].pressure_N_per_cm2 * 1e4);
      CHECK_FALSE(r.areas[j].title.empty());
    }
  }
  CHECK(number == 29);
}

TEST_CASE("body regions: every region cites at least two sources, in full") {
  for (const BodyRegion& r : Table().regions()) {
    CAPTURE(r.name);
    CHECK(r.sources.size() >= 2);
    CHECK(std::set<std::string>(r.sources.begin(), r.sources.end()).size() == r.sources.size());
    for (const std::string& s : r.sources) CHECK(s.size() > 40);  // a citation, not a letter
  }
}

TEST_CASE("body regions: the embedded table is the data file") {
  std::ifstream in(COVOPT_BODY_REGIONS_TOML, std::ios::binary);
  REQUIRE(in);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const BodyRegionTable file = BodyRegionTable::FromTomlText(text, "iso_ts_15066.toml");
  REQUIRE(file.regions().size() == Table().regions().size());
  for (std::size_t i = 0; i < file.regions().size(); ++i) {
    CHECK(file.regions()[i].name == Table().regions()[i].name);
    CHECK(file.regions()[i].areas.size() == Table().regions()[i].areas.size());
  }
}

TEST_CASE("body regions: transient limits are twice the quasi-static ones, area by area") {
  for (const ExpectedRegion& e : kStandard) {
    if (!e.transient_permitted) continue;
    for (const ExpectedArea& a : e.areas) {
      CAPTURE(e.name, a.name);
      const BodyLimits transient = Table().Limits(e.name, a.name, ContactType::kTransient);
      const BodyLimits clamped = Table().Limits(e.name, a.name, ContactType::kClamped);
      CHECK(clamped.force_N == e.force_N);
      CHECK(clamped.pressure_Pa == a.pressure_N_per_cm2 * 1e4);
      CHECK(transient.force_N == 2 * e.force_N);
      CHECK(transient.pressure_Pa == 2 * a.pressure_N_per_cm2 * 1e4);
      CHECK(transient.area->name == a.name);
      CHECK(transient.stiffness_N_per_m() == e.k_N_per_mm * 1e3);
      CHECK(transient.effective_mass_kg() == e.mass_kg);
      CHECK(std::isinf(clamped.effective_mass_kg()));
      CHECK(clamped.effective_mass_kg() == covopt::kFixed);
    }
  }
}

TEST_CASE("body regions: Describe names the standard, the contact, the region, the area and the limits") {
  CHECK(Table().Limits("chest", "sternum", ContactType::kTransient).Describe() ==
        "ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M, transient (2× quasi-static), chest (sternum): 280 N, "
        "240 N/cm²");
  CHECK(Table().Limits("chest", "sternum", ContactType::kClamped).Describe() ==
        "ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M, quasi-static, chest (sternum): 140 N, 120 N/cm²");
  CHECK(Table().Limits("face", "", ContactType::kClamped).Describe() ==
        "ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M, quasi-static, face (masticatory-muscle): 65 N, "
        "110 N/cm²");
  CHECK(BodyLimits{}.Describe() == "no body region");
}

TEST_CASE("body regions: transient contact with the skull, forehead and face is not permitted (A.3.2)") {
  for (const char* region : {"skull-forehead", "face"}) {
    CAPTURE(region);
    const std::string message =
        BodyRegionErrorOf([&] { Table().Limits(region, "", ContactType::kTransient); });
    CHECK_THAT(message, Contains("ISO/TS 15066:2016 A.3.2 (= ISO 10218-2:2025 Annex M) does not permit"));
    CHECK_THAT(message, Contains("transient contact with the " + std::string(region)));
    CHECK_THAT(message, Contains("body.contact=clamped"));
    CHECK_THAT(message, Contains("body.region=head"));
    CHECK(message.find('\n') == std::string::npos);
    // Clamped is allowed, at the quasi-static limits.
    CHECK_NOTHROW(Table().Limits(region, "", ContactType::kClamped));
  }
  // AllLimits leaves them out under transient contact only.
  const auto transient = Table().AllLimits(ContactType::kTransient);
  const auto clamped = Table().AllLimits(ContactType::kClamped);
  CHECK(transient.size() == 26);
  CHECK(clamped.size() == 29);
  for (const BodyLimits& l : transient) {
    CHECK(l.region->transient_permitted());
    CHECK(l.contact == ContactType::kTransient);
    CHECK(l.force_N == 2 * l.region->quasi_static_force_N);
  }
  for (std::size_t i = 0; i < clamped.size(); ++i) {
    CHECK(clamped[i].area->number == static_cast<int>(i) + 1);
    CHECK(clamped[i].pressure_Pa == clamped[i].area->quasi_static_pressure_Pa);
  }
}

TEST_CASE("body regions: the default area is the lowest quasi-static pressure") {
  CHECK(Table().Limits("chest", "", ContactType::kTransient).area->name == "sternum");
  CHECK(Table().Limits("chest", "", ContactType::kTransient).pressure_Pa == 2 * 120e4);
  CHECK(Table().Limits("hands-fingers", "", ContactType::kClamped).area->name ==
        "back-of-hand-non-dominant");
  CHECK(Table().Limits("lower-arms-wrists", "", ContactType::kClamped).area->name ==
        "forearm-muscle");  // 180 twice: the first
  for (const BodyRegion& r : Table().regions()) {
    const double lowest = r.LowestPressureArea().quasi_static_pressure_Pa;
    for (const BodyArea& a : r.areas) CHECK(lowest <= a.quasi_static_pressure_Pa);
  }
}

TEST_CASE("body regions: names ignore case and read _, / and space as -") {
  const BodyRegion& hands = Table().Region("hands-fingers");
  CHECK(&Table().Region("Hands_Fingers") == &hands);
  CHECK(&Table().Region("hands/fingers") == &hands);
  CHECK(&Table().Region("HANDS FINGERS") == &hands);
  CHECK(&Table().Region("  hands-fingers ") == &hands);
  CHECK(&Table().Region("Hands and fingers") == &hands);  // the standard's title
  CHECK(&Table().Region("skull/forehead") == &Table().Region("skull-forehead"));
  CHECK(Table().Limits("Hands/Fingers", "Palm_Non Dominant", ContactType::kClamped).area->name ==
        "palm-non-dominant");
  CHECK(Table().Limits("chest", "Pectoral muscle", ContactType::kClamped).area->name ==
        "pectoral-muscle");
}

TEST_CASE("body regions: an unknown region is one line with the closest name and every choice") {
  const std::string message = BodyRegionErrorOf([] { Table().Region("chset"); });
  CHECK_THAT(message, StartsWith("body region 'chset' is not in ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M"));
  CHECK_THAT(message, Contains("did you mean 'chest'?"));
  for (const ExpectedRegion& e : kStandard) CHECK_THAT(message, Contains(e.name));
  CHECK(message.find('\n') == std::string::npos);

  const std::string nothing_close = BodyRegionErrorOf([] { Table().Region("elbowxyz-abc"); });
  CHECK_THAT(nothing_close, !Contains("did you mean"));
  CHECK_THAT(nothing_close, Contains("(regions: skull-forehead, face, neck"));

  CHECK_THAT(BodyRegionErrorOf([] { Table().Region("head"); }), Contains("Park et al."));
  CHECK_THAT(BodyRegionErrorOf([] { Table().Region("sternum"); }),
             Contains("it is an area of 'chest'"));
  CHECK_THAT(BodyRegionErrorOf([] { Table().Region(""); }), Contains("(regions: "));
  // A BodyRegionError is bad input.
  CHECK_THROWS_AS(Table().Region("nowhere"), std::invalid_argument);
}

TEST_CASE("body regions: an unknown area names the region's areas") {
  const std::string message =
      BodyRegionErrorOf([] { Table().Limits("chest", "sternun", ContactType::kTransient); });
  CHECK_THAT(message, StartsWith("body area 'sternun' is not an area of 'chest'"));
  CHECK_THAT(message, Contains("did you mean 'sternum'?"));
  CHECK_THAT(message, Contains("(areas of chest: sternum, pectoral-muscle)"));
  const std::string elsewhere =
      BodyRegionErrorOf([] { Table().Limits("chest", "kneecap", ContactType::kClamped); });
  CHECK_THAT(elsewhere, Contains("it is an area of 'thighs-knees'"));
  // An unknown area on a forbidden region is still an unknown area.
  CHECK_THAT(BodyRegionErrorOf([] { Table().Limits("face", "nose", ContactType::kTransient); }),
             Contains("(areas of face: masticatory-muscle)"));
}

TEST_CASE("body regions: a valid table file loads, in SI") {
  const BodyRegionTable t = BodyRegionTable::FromTomlText(kGood, "mine.toml");
  REQUIRE(t.regions().size() == 1);
  CHECK(t.area_count() == 2);
  CHECK(t.regions()[0].stiffness_N_per_m == 25e3);
  CHECK(t.regions()[0].areas[1].quasi_static_pressure_Pa == 170e4);
  CHECK(t.regions()[0].sources == std::vector<std::string>{"a copy of the standard"});
  const BodyRegionTable forbidden = BodyRegionTable::FromTomlText(
      Replaced("transient_factor = 2", "transient_factor = \"not permitted\""), "mine.toml");
  CHECK_FALSE(forbidden.regions()[0].transient_permitted());
}

TEST_CASE("body regions: malformed table files give file:line:column errors naming the key") {
  SECTION("a missing key points at the [[region]] header") {
    const std::string text = Replaced("effective_mass_kg = 40\n", "");
    const std::string message = LoadError(text);
    CHECK_THAT(message, StartsWith("mine.toml:" + std::to_string(LineOf(text, "[[region]]")) + ":"));
    CHECK_THAT(message, Contains("region 'chest' has no 'effective_mass_kg'"));
    CHECK_THAT(message, Contains("required keys:"));
  }
  SECTION("a negative k") {
    const std::string text = Replaced("stiffness_N_per_mm = 25", "stiffness_N_per_mm = -25");
    const std::string message = LoadError(text);
    CHECK_THAT(message, StartsWith("mine.toml:" + std::to_string(LineOf(text, "stiffness")) + ":22:"));
    CHECK_THAT(message, Contains("region 'chest': stiffness_N_per_mm must be a number > 0"));
    CHECK_THAT(message, Contains("N/mm (got -25)"));
  }
  SECTION("a duplicate area names both places") {
    const std::string text = Replaced("name = \"pectoral-muscle\"", "name = \"sternum\"");
    const std::string message = LoadError(text);
    const int second = LineOf(text, "number = 2") - 2;
    CHECK_THAT(message, StartsWith("mine.toml:" + std::to_string(second) + ":"));
    CHECK_THAT(message, Contains("area 'sternum' of region 'chest': name is defined twice: already at mine.toml:" +
                                 std::to_string(LineOf(text, "\"sternum\"")) + ":"));
  }
  SECTION("an unknown key, with the closest known one") {
    const std::string text = Replaced("stiffness_N_per_mm", "stifness_N_per_mm");
    const std::string message = LoadError(text);
    CHECK_THAT(message, StartsWith("mine.toml:" + std::to_string(LineOf(text, "stifness")) + ":1:"));
    CHECK_THAT(message, Contains("region 'chest': unknown key 'stifness_N_per_mm'"));
    CHECK_THAT(message, Contains("did you mean 'stiffness_N_per_mm'?"));
    CHECK_THAT(LoadError(Replaced("number = 1", "number = 1\n  colour = \"red\"")),
               Contains("area 'sternum' of region 'chest': unknown key 'colour' in a [[region.area]]; the keys are name, title, number"));
    CHECK_THAT(LoadError("table = 1\n" + kGood), StartsWith("mine.toml:1:1: unknown key 'table'"));
  }
  SECTION("other values") {
    CHECK_THAT(LoadError(Replaced("transient_factor = 2", "transient_factor = \"forbidden\"")),
               Contains("transient_factor must be a number >= 1 and <= 10, or \"not permitted\""));
    CHECK_THAT(LoadError(Replaced("quasi_static_force_N = 140", "quasi_static_force_N = nan")),
               Contains("quasi_static_force_N must be a number > 0"));
    CHECK_THAT(LoadError(Replaced("quasi_static_pressure_N_per_cm2 = 120",
                                  "quasi_static_pressure_N_per_cm2 = \"120 N/cm2\"")),
               Contains("quasi_static_pressure_N_per_cm2 must be a number > 0"));
    CHECK_THAT(LoadError(Replaced("number = 2", "number = 3")),
               Contains("number must be 2 (the areas are numbered 1, 2, ... in table order), got 3"));
    CHECK_THAT(LoadError(Replaced("name = \"chest\"", "name = \"Chest Region\"")),
               Contains("name must be lower-case letters and digits joined by single hyphens"));
    CHECK_THAT(LoadError(Replaced("sources = [\"A\"]", "sources = [\"B\"]")),
               Contains("sources must be a non-empty list of the [sources] keys (A); \"B\" is not one of them"));
    CHECK_THAT(LoadError(Replaced("[sources]\nA = \"a copy of the standard\"\n", "")),
               Contains("has no [sources]"));
    CHECK_THAT(LoadError(kGood + "[[region]]\n"), Contains("region #2 has no 'name'"));
    CHECK_THAT(LoadError(kGood + "x = ["), StartsWith("mine.toml:"));
    CHECK_THAT(LoadError(kGood + "x = ["), Contains("TOML syntax error"));
  }
  SECTION("a duplicate region") {
    std::string text = kGood;
    std::string second = kGood.substr(kGood.find("[[region]]"));
    second.replace(second.find("\"sternum\""), 9, "\"sternum-2\"");
    second.replace(second.find("\"pectoral-muscle\""), 17, "\"pectoral-2\"");
    second.replace(second.find("number = 1"), 10, "number = 3");
    second.replace(second.find("number = 2"), 10, "number = 4");
    const std::string message = LoadError(text + "\n" + second);
    CHECK_THAT(message, Contains("region 'chest': name is defined twice: already at mine.toml:7:"));
  }
}
