// covopt::scene_file reads exposure files (covopt audit --exposure): the shipped example reads,
// and every bad zone is refused at the file:line:column of the value, naming the key and value.

#include <stdexcept>
#include <string>

#include <catch2/catch.hpp>

#include "covopt/scene_file/exposure_file.hpp"

using covopt::scene_file::ParseExposureFile;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

std::string ErrorFor(const std::string& text) {
  try {
    ParseExposureFile(text, "zones.toml");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

/// One zone with the given lines after its name.
std::string Zone(const std::string& lines) { return "[[zone]]\nname = \"table\"\n" + lines; }
const std::string kBox = "min_m = [0, 0, 0.75]\nmax_m = [1, 1, 1.4]\n";

}  // namespace

TEST_CASE("exposure files: the example reads, with its zones in order", "[exposure_file]") {
  const auto file = covopt::scene_file::ReadExposureFile(std::string(COVOPT_ROBOT_MODELS_DIR) + "/exposure_table_cell.toml");
  REQUIRE(file.zones.size() == 4);
  CHECK(file.zones[2].name == "head height");
  CHECK(file.zones[2].min_m[2] == 0.65);
  CHECK(file.zones[2].regions.front() == "head");
  CHECK_THAT(file.zones[0].where, Contains("exposure_table_cell.toml:17:1"));
  const auto one = ParseExposureFile(Zone(kBox + "regions = [\"chest (sternum)\", \"Lower-Legs\", \"all\"]"), "z");
  CHECK(one.zones[0].max_m[1] == 1.0);
  CHECK(one.zones[0].regions.size() == 3);
}

TEST_CASE("exposure files: bad zones are refused at file:line:column naming the key and value", "[exposure_file]") {
  CHECK_THAT(ErrorFor(Zone(kBox + "regions = [\"elbows\"]")),
             StartsWith("zones.toml:5:12: zone 'table' regions: 'elbows' is not a body region"));
  CHECK_THAT(ErrorFor(Zone(kBox + "regions = [\"chest (belly)\"]")),
             Contains("chest has no area 'belly' (its areas: sternum, pectoral-muscle)"));
  CHECK_THAT(ErrorFor(Zone(kBox + "regions = []")), StartsWith("zones.toml:5:11: zone 'table' regions: expected a non-empty"));
  CHECK_THAT(ErrorFor(Zone("min_m = [0, 0, 2]\nmax_m = [1, 1, 1.4]\nregions = [\"all\"]")),
             StartsWith("zones.toml:3:9: zone 'table' min_m [0, 0, 2] lies above max_m [1, 1, 1.4] along z"));
  CHECK_THAT(ErrorFor(Zone("min_m = [0, nan, 0]\nmax_m = [1, 1, 1.4]\nregions = [\"all\"]")),
             StartsWith("zones.toml:3:13: zone 'table' min_m[1]: expected a finite number"));
  CHECK_THAT(ErrorFor(Zone("min_m = [0, 0]\nmax_m = [1, 1, 1.4]\nregions = [\"all\"]")),
             Contains("min_m: expected three numbers [x, y, z] in m, got 2 values"));
  CHECK_THAT(ErrorFor(Zone(kBox + "region = [\"all\"]")),
             StartsWith("zones.toml:5:1: unknown key 'region' in [[zone]] 1; did you mean 'regions'?"));
  CHECK_THAT(ErrorFor(Zone(kBox)), Contains("[[zone]] 1 needs regions"));
  CHECK_THAT(ErrorFor(Zone(kBox + "regions = [\"all\"]\n") + Zone(kBox + "regions = [\"head\"]")),
             StartsWith("zones.toml:6:1: zone 'table' is named twice (first at zones.toml:1:1)"));
  CHECK_THAT(ErrorFor("titel = \"x\"\n"), StartsWith("zones.toml:1:1: unknown key 'titel' at the top; did you mean 'title'?"));
  CHECK_THAT(ErrorFor("title = \"x\"\n"), Contains("zone: expected [[zone]] tables"));
  CHECK_THAT(ErrorFor("[[zone]\n"), StartsWith("zones.toml:1:"));
}
