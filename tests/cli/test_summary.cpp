// The result summary ("summary" of every reportable --json, summary_json.hpp) says what the
// result itself says: its safe is the result's safe or status, its governing ratio and margin
// the ones the result reports, and it reads back through SummaryFromJson.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/report/summary_json.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using nlohmann::json;

const std::string kFr3 = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3.urdf";
const std::string kPick = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3_pick.csv";

json JsonOf(const CliRun& run) {
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  return json::parse(run.out);
}

/// The summary of `j`, checked to read back (SummaryFromJson) with the same state and rows.
json SummaryOf(const json& j) {
  REQUIRE(j.contains("summary"));
  const json& s = j["summary"];
  const covopt::ResultSummary back = covopt::report::SummaryFromJson(j.dump());
  CHECK(covopt::ToString(back.state) == s["state"].get<std::string>());
  CHECK(back.rows.size() == s["rows"].size());
  CHECK(back.limits.size() == s["limits"].size());
  return s;
}

/// The binding rows of a summary: exactly one when any row counts.
int BindingRows(const json& s) {
  int n = 0;
  for (const json& row : s["rows"]) n += row["binding"].get<bool>() ? 1 : 0;
  return n;
}

}  // namespace

TEST_CASE("simulate: the summary is the head's verdict, SAFE, MARGINAL or UNSAFE by its margin", "[summary]") {
  for (const char* speed : {"0.5m/s", "1.8m/s", "3m/s"}) {
    INFO(speed);
    const json j = JsonOf(Run({"simulate", "--speed", speed, "--json"}));
    const json s = SummaryOf(j);
    CHECK(s["command"] == "simulate");
    CHECK(s["safe"] == j["safe"]);
    CHECK(s["governing"]["ratio"] == j["verdict"]["governing_ratio"]);
    CHECK(s["governing"]["criterion"] == j["verdict"]["governing"]);
    CHECK(s["margin"] == j["verdict"]["margin"]);
    CHECK(s["rows"].size() == j["verdict"]["criteria"].size());
    CHECK(BindingRows(s) == 1);
    const double margin = j["verdict"]["margin"].get<double>();
    const std::string state = !j["safe"].get<bool>() ? "unsafe" : margin >= 0.10 ? "safe" : "marginal";
    CHECK(s["state"] == state);
    CHECK(s["targets"] == json::array({"head (frontal)"}));
    CHECK(s["covering"]["thickness_m"] == j["scene"]["covering"]["thickness_m"]);
  }
}

TEST_CASE("optimize: the summary is the recommended design's verdict, or the bare robot's", "[summary]") {
  const json j = JsonOf(Run({"optimize", "--json"}));
  const json s = SummaryOf(j);
  REQUIRE(j["recommendation"].is_object());
  CHECK(s["safe"] == j["recommendation"]["safe"]);
  CHECK(s["margin"].get<double>() == Approx(j["recommendation"]["margin"].get<double>()).epsilon(1e-12));
  CHECK(s["covering"]["material"] == j["recommendation"]["material"]);
  CHECK(s["covering"]["thickness_m"] == j["recommendation"]["thickness_m"]);
  CHECK(BindingRows(s) == 1);

  // Too fast for any covering: the bare robot's rows, not safe.
  const json none = JsonOf(Run({"optimize", "--speed", "8m/s", "--json"}));
  const json n = SummaryOf(none);
  CHECK(none["recommendation"].is_null());
  CHECK(n["safe"] == false);
  CHECK(n["state"] == "unsafe");
  CHECK(n["covering"].is_null());

  // Slow enough for the bare robot: its rows, safe.
  const json bare = JsonOf(Run({"optimize", "--speed", "0.2m/s", "--json"}));
  CHECK(bare["verdict"] == "bare-robot-safe");
  CHECK(SummaryOf(bare)["safe"] == true);
}

TEST_CASE("speed-limit: one limit row per row, the value the row's", "[summary]") {
  const json j = JsonOf(Run({"speed-limit", "--robot-mass", "2kg,20kg,fixed", "--json"}));
  const json s = SummaryOf(j);
  CHECK(s["kind"] == "limits");
  REQUIRE(s["limits"].size() == j["rows"].size());
  for (std::size_t i = 0; i < j["rows"].size(); ++i) {
    const json& row = j["rows"][i];
    const json& limit = s["limits"][i];
    CHECK(limit["unit"] == "m/s");
    if (row["status"] == "limited") {
      CHECK(limit["value"] == row["max_safe_speed_m_per_s"]);
      CHECK(limit["binding_criterion"] == row["limited_by"]);
    }
  }
  CHECK(s["state"] == "limits");
  CHECK(s["safe"] == true);
  // A mass table reads the masses.
  const json mass = JsonOf(Run({"speed-limit", "--solve-for", "mass", "--speed", "0.5m/s,2m/s", "--json"}));
  const json m = SummaryOf(mass);
  REQUIRE(m["limits"].size() == 2);
  CHECK(m["limits"][0]["unit"] == "kg");
}

TEST_CASE("robot --trajectory: the summary is the worst sample's verdict", "[summary]") {
  for (const char* thickness : {"2mm", "40mm"}) {
    INFO(thickness);
    const json j = JsonOf(Run({"robot", "--urdf", kFr3, "--tip", "fr3_link8", "--trajectory", kPick,
                               "--covering-thickness", thickness, "--json"}));
    const json s = SummaryOf(j);
    CHECK(s["safe"] == (j["status"] == "safe"));
    REQUIRE(j["worst_sample"].is_object());
    CHECK(s["safe"] == j["worst_sample"]["safe"]);
    CHECK(s["robot"]["speed_m_per_s"] == j["worst_sample"]["speed_m_per_s"]);
    CHECK(s["robot"]["joints"] == j["joint_names"]);
    CHECK(s["governing"]["case"].get<std::string>().find(
              "sample " + std::to_string(j["worst_sample"]["index"].get<int>()) + " ") == 0);
  }
}

TEST_CASE("audit: the summary's binding row is the limiting cell", "[summary]") {
  const json j = JsonOf(Run({"audit", "--urdf", kFr3, "--tip", "fr3_link8", "--trajectory", kPick,
                             "--covering-thickness", "10mm", "--covering-modulus", "0.5MPa", "--covering-poisson", "0.45",
                             "--contact-area", "1cm2", "--flat-face-radius", "20mm", "--json"}));
  const json s = SummaryOf(j);
  CHECK(s["safe"] == (j["status"] == "safe"));
  REQUIRE(j["limiting"].is_object());
  CHECK(s["governing"]["ratio"] == j["limiting"]["governing_ratio"]);
  CHECK(s["governing"]["target"] ==
        j["limiting"]["link"].get<std::string>() + " × " + j["limiting"]["region"].get<std::string>());
  CHECK(s["governing"]["criterion"] == j["limiting"]["binding"]);
  CHECK(s["robot"]["model_file"] == "franka_fr3.urdf");
  CHECK(BindingRows(s) == 1);
}

TEST_CASE("the body-region modes: every region's rows, the verdict the result's", "[summary]") {
  // simulate: the regions' rows, then the head's.
  const json sim = JsonOf(Run({"simulate", "--body-region", "chest,head", "--speed", "0.5m/s", "--robot-mass", "10kg",
                               "--covering-thickness", "10mm", "--json"}));
  const json s = SummaryOf(sim);
  CHECK(s["safe"] == sim["safe"]);
  CHECK(s["targets"][0].get<std::string>().rfind("chest (", 0) == 0);
  CHECK(s["targets"].back() == "head (frontal)");
  CHECK(BindingRows(s) == 1);
  double worst = 0.0;
  for (const json& region : sim["regions"]) worst = std::max(worst, region["governing_ratio"].get<double>());
  worst = std::max(worst, sim["head"]["verdict"]["governing_ratio"].get<double>());
  CHECK(s["governing"]["ratio"].get<double>() == worst);

  // optimize: the recommendation's verdicts.
  const json design = JsonOf(Run({"optimize", "--body-region", "chest,head", "--speed", "1m/s", "--json"}));
  const json d = SummaryOf(design);
  REQUIRE(design["recommendation"].is_object());
  CHECK(d["safe"] == true);
  CHECK(d["covering"]["material"] == design["recommendation"]["material"]);

  // speed-limit: one limit row per table row, the covered speed.
  const json table = JsonOf(Run({"speed-limit", "--body-region", "chest,hands-fingers", "--robot-mass", "5kg,20kg",
                                 "--json"}));
  const json t = SummaryOf(table);
  REQUIRE(t["limits"].size() == table["rows"].size());
  for (std::size_t i = 0; i < table["rows"].size(); ++i) {
    const json& speed = table["rows"][i]["covered_max_speed_m_per_s"];
    if (speed.is_number()) CHECK(t["limits"][i]["value"] == speed);
  }

  // robot --trajectory: the worst sample's worst region.
  const json trajectory = JsonOf(Run({"robot", "--urdf", kFr3, "--tip", "fr3_link8", "--trajectory", kPick, "--body-region",
                                      "chest", "--covering-thickness", "0", "--contact-area", "10cm2", "--json"}));
  const json r = SummaryOf(trajectory);
  CHECK(r["safe"] == (trajectory["status"] == "safe"));
  REQUIRE(trajectory["worst_sample"].is_number());
  const json& sample = trajectory["samples"][trajectory["worst_sample"].get<std::size_t>()];
  CHECK(r["governing"]["ratio"] == sample["worst_ratio"]);
  CHECK(r["governing"]["criterion"] == sample["binding"]);
}

TEST_CASE("optimize with ranges: the summary is the recommendation's worst case over the box", "[summary]") {
  const json j = JsonOf(Run({"optimize", "--json", "--head-mass", "3.7kg..5.8kg", "--scalp-thickness", "2mm..5mm"}));
  const json s = SummaryOf(j);
  REQUIRE(j["recommendation"].is_object());
  CHECK(s["safe"] == j["recommendation"]["worst_case"]["admissible"]);
  CHECK(s["governing"]["ratio"] == j["recommendation"]["governing_ratio"]);
  CHECK(s["governing"]["criterion"] == j["recommendation"]["governing_criterion"]);
  CHECK(s["covering"]["material"] == j["recommendation"]["material"]);
}
