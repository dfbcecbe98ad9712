// The judging commands and the covering's law (issue 35), run in-process:
// under `auto` a catalog material with a measured curve takes the foam law (the same answer as
// --covering-law foam, to the bit); the travel rule limits only with --keep-travel, which gives
// the library's answer with the travel kept; a foam used up is reported at its own speed, the
// limit being injury's; a fully compressed Hertz covering is limited by "law-validity"; every
// JSON result names its law and validity.
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using nlohmann::json;

const std::string kVn600 = "vinyl-nitrile foam VN600";

json JsonOf(const CliRun& run) {
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  return json::parse(run.out);
}

std::vector<std::string> With(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

bool IsInjury(const json& name) { return name == "laceration" || name == "contusion" || name == "fracture"; }

}  // namespace

TEST_CASE("speed-limit: auto takes the foam law for a material with a curve, as --covering-law foam",
          "[run][covering_law_judging]") {
  const std::vector<std::string> base = {"speed-limit", "--material", kVn600, "--covering-thickness", "10mm",
                                         "--robot-mass", "10kg", "--json"};
  const json automatic = JsonOf(Run(base));
  const json foam = JsonOf(Run(With(base, {"--covering-law", "foam"})));
  const json& row = automatic["rows"][0];
  CHECK(row["covering_law"] == "foam");
  CHECK(row["max_safe_speed_m_per_s"] == foam["rows"][0]["max_safe_speed_m_per_s"]);
  CHECK(row["limited_by"] == foam["rows"][0]["limited_by"]);
  // Judged on injury: the layer is used up well below the limit, said with its own speed.
  CHECK(IsInjury(row["limited_by"]));
  CHECK(row["validity"]["within"] == true);
  CHECK(row["within_law"] == true);
  REQUIRE(row["covering_used_up_m_per_s"].is_number());
  CHECK(row["covering_used_up_m_per_s"].get<double>() < row["max_safe_speed_m_per_s"].get<double>());
  CHECK(automatic["criterion"]["parts"] ==
        json::array({"laceration", "contusion", "fracture", "crush", "law-validity"}));  // the travel rule reported, not a limit
  const CliRun text = Run({"speed-limit", "--material", kVn600, "--covering-thickness", "10mm", "--robot-mass", "10kg"});
  REQUIRE(text.exit_code == 0);
  CHECK_THAT(text.out, Catch::Contains("covering law foam, within its validity") &&
                           Catch::Contains("covering used up at v = "));
  // --covering-law hertz reads the same material by Hertz's law.
  CHECK(JsonOf(Run(With(base, {"--covering-law", "hertz"})))["rows"][0]["covering_law"] == "hertz");

  // --keep-travel: the curve's end is a limit again (the design rule), below the used-up speed.
  const json kept = JsonOf(Run(With(base, {"--keep-travel"})));
  CHECK(kept["rows"][0]["limited_by"] == "full-compression");
  CHECK(kept["rows"][0]["max_safe_speed_m_per_s"].get<double>() <=
        row["covering_used_up_m_per_s"].get<double>() * (1.0 + 1e-12));
  CHECK(kept["criterion"]["parts"] == json::array({"laceration", "contusion", "fracture", "full-compression", "crush", "law-validity"}));
}

TEST_CASE("speed-limit: a fully compressed Hertz covering is limited by law-validity and --keep-travel keeps today's limit",
          "[run][covering_law_judging]") {
  // README's elastomer rows (limited by full compression on main) with a compressible ν.
  const std::vector<std::string> base = {"speed-limit", "--covering-modulus", "5.884MPa", "--covering-poisson", "0.3",
                                         "--covering-thickness", "20mm", "--robot-mass", "1kg,5kg", "--json"};
  const json judged = JsonOf(Run(base));
  const json kept = JsonOf(Run(With(base, {"--keep-travel"})));
  const json paper = JsonOf(Run(With(base, {"--allow-full-compression"})));
  for (std::size_t i = 0; i < 2; ++i) {
    CAPTURE(i);
    CHECK(kept["rows"][i]["limited_by"] == "full-compression");
    CHECK(judged["rows"][i]["limited_by"] == "law-validity");
    CHECK(judged["rows"][i]["covering_law"] == "hertz");
    // At SF 1 both end where the covering bottoms out.
    CHECK(judged["rows"][i]["max_safe_speed_m_per_s"].get<double>() ==
          Approx(kept["rows"][i]["max_safe_speed_m_per_s"].get<double>()).epsilon(1e-12));
    // The paper's criterion accepts full compression: a higher limit, within the law.
    CHECK(paper["rows"][i]["max_safe_speed_m_per_s"].get<double>() >
          judged["rows"][i]["max_safe_speed_m_per_s"].get<double>());
    CHECK(paper["rows"][i]["validity"]["within"] == true);
  }
  // With a safety factor the travel rule reserves travel, the law's validity does not.
  const json reserved = JsonOf(Run(With(base, {"--keep-travel", "--safety-factor", "1.5"})));
  const json derated = JsonOf(Run(With(base, {"--safety-factor", "1.5"})));
  CHECK(reserved["rows"][0]["max_safe_speed_m_per_s"].get<double>() <
        derated["rows"][0]["max_safe_speed_m_per_s"].get<double>());
}

TEST_CASE("simulate: law-validity in the verdict, the travel rule only with --keep-travel", "[run][covering_law_judging]") {
  const std::vector<std::string> base = {"simulate", "--material", kVn600, "--covering-thickness", "10mm",
                                         "--speed", "0.5m/s", "--json"};
  const json used_up = JsonOf(Run(base));
  CHECK(used_up["covering_law"] == "foam");
  CHECK(used_up["fully_compressed"] == true);
  CHECK(used_up["validity"]["within"] == true);
  CHECK(used_up["safe"] == true);  // injury within its limits; the layer's stop is modelled
  CHECK(JsonOf(Run(With(base, {"--keep-travel"})))["safe"] == false);
  const json bottomed = JsonOf(Run({"simulate", "--covering-modulus", "5.884MPa", "--covering-poisson", "0.3",
                                    "--covering-thickness", "20mm", "--robot-mass", "1kg", "--speed", "6m/s", "--json"}));
  CHECK(bottomed["covering_law"] == "hertz");
  CHECK(bottomed["validity"]["within"] == false);
  CHECK(bottomed["safe"] == false);
}

TEST_CASE("the FR3 head row: a covering with a curve is not below the bare robot unless an injury criterion says so",
          "[run][covering_law_judging]") {
  // README's all-regions table: bare 2.69 m/s against covered 0.82 m/s on the head under Hertz's
  // full compression; the sponge's curve now takes the foam law and the travel is reported.
  const json table = JsonOf(Run({"speed-limit", "--robot-mass", "1.861kg", "--robot-radius", "40mm", "--material",
                                 "neoprene sponge D1056 2C4", "--covering-thickness", "20mm", "--contact-area", "4cm2",
                                 "--body-region", "all", "--json"}));
  bool head_seen = false;
  for (const json& row : table["rows"]) {
    if (row["region"] != "head") continue;
    head_seen = true;
    INFO(row.dump());
    const double bare = row["bare_max_speed_m_per_s"].get<double>();
    const double covered = row["covered_max_speed_m_per_s"].get<double>();
    CHECK((covered >= bare || IsInjury(row["covered_limited_by"])));
    CHECK(covered > 0.8242);
  }
  CHECK(head_seen);
}
