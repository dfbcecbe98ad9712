// `covopt body-regions list|show`, run in-process through RunCli. list must print one row
// per area of the library's table (BodyRegionTable::BuiltIn(), compared value for value,
// never with printed numbers) in the standard's units, with "not permitted" where A.3.2
// forbids transient contact; --json must hold the table in SI units named in the keys, with
// the sources; show must print one region's values, areas and sources, accept the names the
// library accepts, and answer an unknown name with exit 2 and one line naming the choices.

#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/materials/body_regions.hpp"

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using covopt::materials::BodyArea;
using covopt::materials::BodyRegion;
using covopt::materials::BodyRegionTable;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;
using Json = nlohmann::json;

namespace {

const BodyRegionTable& Table() { return BodyRegionTable::BuiltIn(); }

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> Words(const std::string& line) {
  std::vector<std::string> words;
  std::istringstream in(line);
  for (std::string word; in >> word;) words.push_back(word);
  return words;
}

/// Bad input: exit 2, nothing on stdout, one line on stderr containing `message`.
void CheckBadInput(const std::vector<std::string>& args, const std::string& message) {
  const CliRun run = Run(args);
  CAPTURE(args, run.err);
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Contains(message));
}

}  // namespace

TEST_CASE("cli body-regions list: one row per area with the library's values in the standard's units") {
  const CliRun run = Run({"body-regions", "list"});
  REQUIRE(run.exit_code == 0);
  CHECK(run.err.empty());
  const std::vector<std::string> lines = Lines(run.out);
  REQUIRE(lines.size() > 30);
  for (const char* header : {"F_qs [N]", "F_tr [N]", "p_qs [N/cm²]", "p_tr [N/cm²]", "k [N/mm]",
                             "m_H [kg]"}) {
    CHECK_THAT(lines[0], Contains(header));
  }
  std::size_t row = 1;
  for (const BodyRegion& r : Table().regions()) {
    for (const BodyArea& a : r.areas) {
      const std::vector<std::string> w = Words(lines.at(row++));
      CAPTURE(r.name, a.name, w);
      REQUIRE(w.size() >= 8);
      CHECK(w[0] == r.name);
      CHECK(w[1] == a.name);
      CHECK(std::stoi(w[2]) == a.number);
      CHECK(std::stod(w[3]) == r.quasi_static_force_N);
      if (r.transient_permitted()) {
        REQUIRE(w.size() == 9);
        CHECK(std::stod(w[4]) == 2 * r.quasi_static_force_N);
        CHECK(std::stod(w[5]) * 1e4 == a.quasi_static_pressure_Pa);
        CHECK(std::stod(w[6]) * 1e4 == 2 * a.quasi_static_pressure_Pa);
        CHECK(std::stod(w[7]) * 1e3 == r.stiffness_N_per_m);
        CHECK(std::stod(w[8]) == r.effective_mass_kg);
      } else {
        REQUIRE(w.size() == 10);
        CHECK(w[4] + " " + w[5] == "not permitted");
        CHECK(std::stod(w[6]) * 1e4 == a.quasi_static_pressure_Pa);
        CHECK(w[7] == "–");
        CHECK(std::stod(w[8]) * 1e3 == r.stiffness_N_per_m);
        CHECK(std::stod(w[9]) == r.effective_mass_kg);
      }
    }
  }
  CHECK(row == 30);
  CHECK(lines.at(row).empty());
  CHECK_THAT(run.out, Contains("12 regions, 29 areas: Biomechanical limits of the body model (ISO/TS 15066:2016 "
                               "Annex A, Tables A.2 and A.3) (ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M)"));
  CHECK_THAT(run.out, Contains("limit table: built-in, sha256 "));
  CHECK_THAT(run.out, Contains("A.3.2"));
}

TEST_CASE("cli body-regions list --json: the table in SI units, with the sources") {
  const CliRun run = Run({"body-regions", "list", "--json"});
  REQUIRE(run.exit_code == 0);
  CHECK(run.err.empty());
  const Json json = Json::parse(run.out);
  REQUIRE(json.is_array());
  REQUIRE(json.size() == Table().regions().size());
  std::size_t areas = 0;
  for (std::size_t i = 0; i < json.size(); ++i) {
    const Json& j = json[i];
    const BodyRegion& r = Table().regions()[i];
    CAPTURE(r.name);
    CHECK(j["name"] == r.name);
    CHECK(j["title"] == r.title);
    CHECK(j["quasi_static_force_N"].get<double>() == r.quasi_static_force_N);
    CHECK(j["stiffness_N_per_m"].get<double>() == r.stiffness_N_per_m);
    CHECK(j["effective_mass_kg"].get<double>() == r.effective_mass_kg);
    CHECK(j["transient_permitted"].get<bool>() == r.transient_permitted());
    CHECK(j["default_area"] == r.LowestPressureArea().name);
    CHECK(j["sources"].get<std::vector<std::string>>() == r.sources);
    if (r.transient_permitted()) {
      CHECK(j["transient_factor"].get<double>() == 2.0);
      CHECK(j["transient_force_N"].get<double>() == 2 * r.quasi_static_force_N);
    } else {
      CHECK(j["transient_factor"].is_null());
      CHECK(j["transient_force_N"].is_null());
      CHECK_THAT(j["transient_rule"].get<std::string>(), Contains("A.3.2"));
    }
    REQUIRE(j["areas"].size() == r.areas.size());
    for (std::size_t k = 0; k < r.areas.size(); ++k) {
      const Json& area = j["areas"][k];
      ++areas;
      CHECK(area["name"] == r.areas[k].name);
      CHECK(area["number"].get<int>() == static_cast<int>(areas));
      CHECK(area["quasi_static_pressure_Pa"].get<double>() == r.areas[k].quasi_static_pressure_Pa);
      if (r.transient_permitted()) {
        CHECK(area["transient_pressure_Pa"].get<double>() == 2 * r.areas[k].quasi_static_pressure_Pa);
      } else {
        CHECK(area["transient_pressure_Pa"].is_null());
      }
    }
  }
  CHECK(areas == 29);
}

TEST_CASE("cli body-regions show: one region's values, areas and sources") {
  const CliRun run = Run({"body-regions", "show", "chest"});
  REQUIRE(run.exit_code == 0);
  CHECK(run.err.empty());
  CHECK_THAT(run.out, StartsWith("chest: Chest (ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M)"));
  CHECK_THAT(run.out, Contains("F_qs = 140 N"));
  CHECK_THAT(run.out, Contains("2× the quasi-static limits: F_tr = 280 N"));
  CHECK_THAT(run.out, Contains("k = 25 N/mm (25000 N/m)"));
  CHECK_THAT(run.out, Contains("m_H = 40 kg"));
  CHECK_THAT(run.out, Contains("sternum (the lowest pressure)"));
  // Every area row: number, name, title, p_qs, p_tr; every source's first words.
  for (const BodyArea& a : Table().Region("chest").areas) {
    const std::string p = std::to_string(static_cast<int>(a.quasi_static_pressure_Pa / 1e4));
    const std::string p_tr = std::to_string(static_cast<int>(2 * a.quasi_static_pressure_Pa / 1e4));
    CHECK_THAT(run.out, Contains(a.title));
    bool found = false;
    for (const std::string& line : Lines(run.out)) {
      const std::vector<std::string> w = Words(line);
      if (w.size() >= 4 && w[1] == a.name) {
        found = true;
        CHECK(std::stoi(w[0]) == a.number);
        CHECK(w[w.size() - 2] == p);
        CHECK(w.back() == p_tr);
      }
    }
    CHECK(found);
  }
  for (const std::string& source : Table().Region("chest").sources) {
    CHECK_THAT(run.out, Contains(source.substr(0, 30)));
  }
}

TEST_CASE("cli body-regions show: the skull and face say transient contact is not permitted") {
  for (const char* name : {"skull-forehead", "face"}) {
    const CliRun run = Run({"body-regions", "show", name});
    REQUIRE(run.exit_code == 0);
    CHECK_THAT(run.out, Contains("not permitted (ISO/TS 15066:2016 A.3.2 (= ISO 10218-2:2025 Annex M))"));
    CHECK_THAT(run.out, !Contains("F_tr ="));
  }
}

TEST_CASE("cli body-regions show --json: the library's region, and names as the library reads them") {
  for (const std::vector<std::string>& name : std::vector<std::vector<std::string>>{
           {"hands-fingers"}, {"Hands/Fingers"}, {"hands_fingers"}, {"Hands and fingers"}}) {
    std::vector<std::string> args{"body-regions", "show"};
    args.insert(args.end(), name.begin(), name.end());
    args.emplace_back("--json");
    const CliRun run = Run(args);
    CAPTURE(args, run.err);
    REQUIRE(run.exit_code == 0);
    const Json j = Json::parse(run.out);
    CHECK(j["name"] == "hands-fingers");
    CHECK(j["areas"].size() == 9);
    CHECK(j["default_area"] == "back-of-hand-non-dominant");
    CHECK(j["stiffness_N_per_m"].get<double>() == 75e3);
    CHECK(j["effective_mass_kg"].get<double>() == 0.6);
  }
}

TEST_CASE("cli body-regions: bad input is exit 2 with one line") {
  CheckBadInput({"body-regions", "show", "chset"},
                "covopt body-regions show: error: body region 'chset' is not in ISO/TS "
                "15066:2016 Annex A = ISO 10218-2:2025 Annex M; did you mean 'chest'? (regions: skull-forehead, face, "
                "neck, back-shoulders, chest, abdomen, pelvis, upper-arms-elbows, "
                "lower-arms-wrists, hands-fingers, thighs-knees, lower-legs)");
  CheckBadInput({"body-regions", "show", "head"}, "Park et al.");
  CheckBadInput({"body-regions", "show", "kneecap", "--json"}, "it is an area of 'thighs-knees'");
  CheckBadInput({"body-regions", "show"}, "name is required");
  CheckBadInput({"body-regions"}, "covopt body-regions: error:");
  CheckBadInput({"body-regions", "list", "extra"}, "covopt body-regions list: error:");
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"body-regions", "show", "chset"}, {"body-regions", "show", "head"}}) {
    const CliRun run = Run(args);
    CHECK(run.err.find('\n') == run.err.size() - 1);
  }
}
