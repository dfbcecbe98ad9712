// `covopt audit --tool-surface/--payload-surface/--exposure` run in-process: the gripper is a
// row of its own ("tool"), the exposure file leaves out exactly the regions it does not expose
// (the other cells as without it), and bad specs and zone files are exit 2 naming the flag and
// the file:line:column.
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "audit_test_support.hpp"
#include "cli_test_support.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using covopt::cli::testing::TempDir;
using nlohmann::json;

const std::string kModels = COVOPT_ROBOT_MODELS_DIR;

std::vector<std::string> Fr3(std::vector<std::string> more) {
  more.insert(more.begin(), {"--surface-spacing", "80mm", "--body-region", "chest,lower-legs,hands-fingers", "--json"});
  return covopt::cli::testing::Fr3Command("audit", kModels + "/franka_fr3_pick.csv", more);
}

json JsonOf(const CliRun& run) { return covopt::cli::testing::JsonOfRun(run); }

void RequireBadInput(const CliRun& run, const std::string& names) { covopt::cli::testing::RequireRefused(run, names); }

}  // namespace

TEST_CASE("audit --exposure leaves out exactly the regions no zone exposes, the rest as without it", "[audit][exposure]") {
  const TempDir dir;
  const std::string zones = dir.Write("zones.toml", "title = \"no legs\"\n[[zone]]\nname = \"cell\"\n"
                                                    "min_m = [-5, -5, -5]\nmax_m = [5, 5, 5]\n"
                                                    "regions = [\"chest\", \"hands-fingers\"]\n")
                                .string();
  const json all = JsonOf(Run(Fr3({})));
  const json some = JsonOf(Run(Fr3({"--exposure", zones})));
  REQUIRE(all["cells"].size() == some["cells"].size());
  CHECK(all["exposure_zones"].is_null());
  REQUIRE(some["exposure_zones"].size() == 1);
  CHECK(some["exposure_zones"][0]["origin"].get<std::string>().find("zones.toml:2:1") != std::string::npos);
  std::size_t left_out = 0;
  for (std::size_t k = 0; k < all["cells"].size(); ++k) {
    const json &a = all["cells"][k], &b = some["cells"][k];
    if (a["region"].get<std::string>().rfind("lower-legs", 0) == 0) {
      CHECK(b["not_judged"] == "no exposure zone exposes the region");
      CHECK(b["sample"].is_null());
      ++left_out;
    } else {
      CHECK(b["governing_ratio"] == a["governing_ratio"]);
      CHECK(b["not_judged"].is_null());
    }
  }
  CHECK(left_out > 0);
  CHECK(some["not_judged_cells"] == left_out);
  // The zone file is an input of the run's provenance, under its role.
  bool listed = false;
  for (const json& f : some["provenance"]["inputs"]) listed |= f["role"] == "exposure" && f["path"] == zones;
  CHECK(listed);
}

TEST_CASE("audit --tool-surface: the gripper is the row 'tool' carried by the flange", "[audit][tool]") {
  const json j = JsonOf(Run(Fr3({"--tool-surface", "box:center=0,0,0.045;size=0.08,0.2,0.09;edge=10mm;rpy=0,0,-0.7854",
                                 "--payload-surface", "sphere:center=0,0,0.15;radius=30mm"})));
  const json& links = j["surface"]["links"];
  REQUIRE(links.size() >= 2);
  CHECK(links[links.size() - 2]["name"] == "tool");
  CHECK(links[links.size() - 2]["carried_by"] == "fr3_link8");
  CHECK(links.back()["name"] == "payload");
  bool tool_moves = false;
  for (const json& c : j["cells"]) tool_moves |= c["link"] == "tool" && !c["sample"].is_null();
  CHECK(tool_moves);
}

TEST_CASE("audit: a bad tool spec or zone file is exit 2 naming the flag and the place", "[audit][bad-input]") {
  const TempDir dir;
  RequireBadInput(Run(Fr3({"--tool-surface", "sphere:center=0,0,0.1;radius=2m"})),
                  "--tool-surface 'sphere:center=0,0,0.1;radius=2m': radius: must be in [0.1 mm, 1000 mm]");
  RequireBadInput(Run(Fr3({"--payload-surface", "box:center=0,0,0.1;size=0.1,0.1,0.1"})), "--payload-surface");
  const std::string bad = dir.Write("bad.toml", "[[zone]]\nname = \"z\"\nmin_m = [0, 0, 2]\nmax_m = [1, 1, 1]\n"
                                                "regions = [\"all\"]\n")
                              .string();
  RequireBadInput(Run(Fr3({"--exposure", bad})), "--exposure: " + bad + ":3:9: zone 'z' min_m [0, 0, 2] lies above");
  RequireBadInput(Run(Fr3({"--exposure", (dir / "none.toml").string()})), "--exposure");
}
