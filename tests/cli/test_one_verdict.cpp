// One target, one verdict (issue 34), end to end: the trial's commands give one verdict each.
// `simulate` counts the covering's design rules (not fully compressed, not crushed) as
// `speed-limit` does at that speed; every EXCEEDED names the standard's and the derated limit;
// `optimize --body-region` recommends a stock thickness with a percentage margin; the audit's
// head row never binds on "pressure" (the head model has none).

#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using Catch::Matchers::Contains;
using Json = nlohmann::json;

namespace {

Json JsonOf(const std::vector<std::string>& args) {
  const CliRun run = Run(args);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  return Json::parse(run.out);
}

/// `speed-limit` on the same scene flags: the max safe speed [m/s], 0 when there is none.
double SpeedLimitOf(std::vector<std::string> scene) {
  scene.erase(scene.begin());  // "simulate"
  std::vector<std::string> args = {"speed-limit"};
  for (std::size_t i = 0; i < scene.size(); ++i) {
    if (scene[i] == "--speed") {  // speed-limit solves for the speed
      ++i;
      continue;
    }
    args.push_back(scene[i]);
  }
  args.push_back("--json");
  const Json j = JsonOf(args);
  const Json& v = j["rows"].at(0)["max_safe_speed_m_per_s"];
  return v.is_null() ? 0.0 : v.get<double>();
}

/// simulate's verdict on `args`, checked against speed-limit's answer at that speed; returns it.
Json OneVerdict(std::vector<std::string> args, double speed_m_per_s) {
  std::vector<std::string> with_json = args;
  with_json.push_back("--json");
  const Json j = JsonOf(with_json);
  const bool safe = j["safe"].get<bool>();
  CHECK(j["verdict"]["safe"] == safe);
  const double limit = SpeedLimitOf(args);
  INFO("speed " << speed_m_per_s << " m/s, speed-limit " << limit << " m/s");
  CHECK(safe == (speed_m_per_s <= limit));
  // The text's verdict line says the same (SAFE or MARGINAL when safe, by the margin).
  const CliRun text = Run(args);
  REQUIRE(text.exit_code == 0);
  const std::string word = safe ? (j["verdict"]["margin"].get<double>() >= 0.10 ? "SAFE" : "MARGINAL") : "UNSAFE";
  CHECK_THAT(text.out, Contains("\nVerdict\n  " + word + ", margin "));
  return j;
}

}  // namespace

TEST_CASE("simulate: a crushed covering is not SAFE, as speed-limit says at that speed", "[verdict][cli]") {
  const Json j = OneVerdict(
      {"simulate", "--covering-thickness", "16mm", "--material", "XPS Foamular 250", "--head-mass", "4.5kg"}, 2.0);
  CHECK(j["safe"] == false);
  CHECK(j["verdict"]["injury_safe"].is_boolean());
  CHECK(j["verdict"]["design_rules_met"] == false);
  CHECK(j["verdict"]["governing"] == "crush");
  CHECK(j["crush"]["ratio"].get<double>() > 10.0);
}

TEST_CASE("simulate: a bottomed-out Hertz covering fails the design rule 'law-validity'", "[verdict][cli]") {
  const Json j = OneVerdict({"simulate", "--covering-thickness", "3mm", "--covering-modulus", "1MPa"}, 2.0);
  CHECK(j["fully_compressed"] == true);
  CHECK(j["safe"] == false);
  CHECK(j["verdict"]["design_rules_met"] == false);
  CHECK(j["validity"]["within"] == false);
  int found = 0;
  for (const Json& c : j["verdict"]["criteria"]) {
    if (c["name"] == "law-validity") {  // counted always: out of the Hertz law's validity
      ++found;
      CHECK(c["part"] == "design-rule");
      CHECK(c["counted"] == true);
      CHECK(c["passed"] == false);
    }
    if (c["name"] == "full-compression") {  // the travel rule: reported, a limit only with --keep-travel
      ++found;
      CHECK(c["counted"] == false);
      CHECK(c["passed"] == false);
    }
  }
  CHECK(found == 2);
  const CliRun text = Run({"simulate", "--covering-thickness", "3mm", "--covering-modulus", "1MPa"});
  CHECK_THAT(text.out, Contains("design rules UNSAFE"));
  CHECK_THAT(text.out, Contains("law-validity      UNSAFE  OUT of the covering law's validity"));
  CHECK_THAT(text.out, Contains("EXCEEDED (limit 1, derated 1 at SF 1: fully compressed); not counted"));
  const Json kept = JsonOf({"simulate", "--covering-thickness", "3mm", "--covering-modulus", "1MPa", "--keep-travel",
                            "--json"});
  for (const Json& c : kept["verdict"]["criteria"]) {
    if (c["name"] == "full-compression") CHECK(c["counted"] == true);
  }
}

TEST_CASE("simulate: the bare hit of the trial and the default scene give speed-limit's verdict", "[verdict][cli]") {
  OneVerdict({"simulate", "--robot-mass", "5.145kg", "--robot-radius", "60mm", "--speed", "2.3m/s",
              "--covering-thickness", "0"},
             2.3);
  OneVerdict({"simulate"}, 2.0);
  OneVerdict({"simulate", "--speed", "1m/s", "--material", "elastomer Shore A40", "--covering-thickness", "20mm"}, 1.0);
}

TEST_CASE("simulate: EXCEEDED shows the standard's and the derated limit", "[verdict][cli]") {
  const CliRun run = Run({"simulate", "--safety-factor", "1.2"});
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("ratio 1.151 EXCEEDED (limit 2.52 J/cm², derated 2.1 J/cm² at SF 1.2)"));
}

TEST_CASE("optimize --body-region: a stock thickness, a percentage margin, EXCEEDED with the derated limit",
          "[verdict][cli]") {
  const std::vector<std::string> args = {"optimize", "--body-region", "chest,hands-fingers", "--speed", "0.8m/s",
                                         "--safety-factor", "1.2"};
  const CliRun run = Run(args);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  std::vector<std::string> with_json = args;
  with_json.push_back("--json");
  const Json j = JsonOf(with_json);
  REQUIRE(j["recommendation"].is_object());
  const double thickness_mm = j["recommendation"]["thickness_m"].get<double>() * 1e3;
  CHECK(std::abs(thickness_mm * 2.0 - std::round(thickness_mm * 2.0)) < 1e-9);  // 0.5 mm stock
  // The recommendation's margin is a percentage, as the head's optimize prints it.
  const std::size_t at = run.out.find("Recommended: ");
  REQUIRE(at != std::string::npos);
  const std::string line = run.out.substr(at, run.out.find('\n', at) - at);
  CHECK_THAT(line, Contains(", margin ") && Contains(" %)") && !Contains("e-0"));
  CHECK_THAT(run.out, Contains("EXCEEDED (limit"));
  CHECK_THAT(run.out, Contains("at SF 1.2)"));
}

TEST_CASE("audit: the bare head row binds on the head's own criterion, never on pressure", "[verdict][cli][audit]") {
  const std::string urdf = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3.urdf";
  const std::string pick = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3_pick.csv";
  const std::vector<std::string> args = {"audit", "--urdf", urdf, "--tip", "fr3_link8", "--trajectory", pick,
                                         "--covering-thickness", "0", "--contact-area", "1cm2", "--flat-face-radius",
                                         "20mm", "--body-region", "chest,head"};
  std::vector<std::string> with_json = args;
  with_json.push_back("--json");
  const Json j = JsonOf(with_json);
  int head_cells = 0;
  for (const Json& cell : j["cells"]) {
    if (cell["region"] != "head (Park et al. 2011)" || cell["binding"].is_null()) continue;
    ++head_cells;
    CHECK(cell["binding"] != "pressure");
    CHECK(cell["binding"] == cell["head_criterion"]);
    // The cell's verdict is its speed against its limit: SF × ratio <= 1 iff v <= v_max.
    const double ratio = cell["governing_ratio"].get<double>();
    CHECK((ratio <= 1.0) == (cell["speed_m_per_s"].get<double>() <= cell["max_safe_speed_m_per_s"].get<double>()));
  }
  CHECK(head_cells > 0);
  if (j["limiting"].is_object() && j["limiting"]["region"] == "head (Park et al. 2011)") {
    CHECK(j["limiting"]["binding"] != "pressure");
  }
  const CliRun text = Run(args);
  REQUIRE(text.exit_code == 0);
  for (std::size_t at = text.out.find("head (Park et al. 2011)"); at != std::string::npos;
       at = text.out.find("head (Park et al. 2011)", at + 1)) {
    const std::string line = text.out.substr(at, text.out.find('\n', at) - at);
    CHECK_THAT(line, !Contains("pressure"));
  }
}
