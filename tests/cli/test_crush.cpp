// covopt's verdicts hold for the material (issue 21): the default recommendation does not
// crush, the criterion and the scope are stated, the governing criterion is named, the
// candidate table goes to CSV, the probability target is met on its 95 % bound, and the
// new user's small findings (conflicting flags, a dash range, --velocity, Wrote lines) are
// answered with one line.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/materials/catalog.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::ReadFile;
using covopt::cli::testing::Run;
using covopt::cli::testing::SplitLines;
using covopt::cli::testing::TempDir;
using json = nlohmann::json;

json JsonRun(const std::vector<std::string>& args) {
  const CliRun run = Run(args);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  return json::parse(run.out);
}

/// Exit 2, nothing on stdout, one line on stderr containing every `mention`.
void ExpectOneLine(const std::vector<std::string>& args, const std::vector<std::string>& mentions) {
  const CliRun run = Run(args);
  INFO(run.err);
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  REQUIRE_FALSE(run.err.empty());
  CHECK(run.err.find('\n') == run.err.size() - 1);
  for (const std::string& m : mentions) CHECK_THAT(run.err, Catch::Contains(m));
}

}  // namespace

TEST_CASE("optimize's default recommendation does not crush, and every candidate says why", "[optimize][crush]") {
  const json j = JsonRun({"optimize", "--json"});
  REQUIRE(j["recommendation"].is_object());
  const json& rec = j["recommendation"];
  // A material whose strength is known and not exceeded, or one that does not crush.
  if (rec["crush_behaviour"] == "crushes") {
    CHECK(rec["crush_ratio"].get<double>() <= 1.0);
  } else {
    CHECK(rec["crush_behaviour"] == "does-not-crush");
    CHECK(rec["crush_ratio"].is_null());
  }
  CHECK(rec["margin"].get<double>() == Approx(1.0 - rec["governing_ratio"].get<double>()).margin(1e-15));
  CHECK(j["criterion"]["parts"] == json::array({"laceration", "contusion", "fracture", "full-compression", "crush", "law-validity"}));
  REQUIRE(j["scope"].size() == 2);
  CHECK_THAT(j["scope"][1].get<std::string>(), Catch::Contains("A.3.2") && Catch::Contains("130 N"));
  // The old answer, XPS Foamular 250, crushes at every thickness: 25 psi against MPa stresses.
  bool xps_seen = false;
  for (const json& c : j["candidates"]) {
    CHECK(c.contains("crush_ratio"));
    CHECK(c.contains("governing_criterion"));
    if (c["material"] == "XPS Foamular 250") {
      xps_seen = true;
      CHECK(c["safe"] == false);
      CHECK(c["governing_criterion"] == "crush");
      CHECK(c["crush_ratio"].get<double>() > 10.0);
      CHECK(c["compressive_strength_Pa"].get<double>() == Approx(25 * 6894.757).epsilon(1e-6));
    }
    if (c["crush_behaviour"] == "unknown") CHECK(c["safe"] == false);  // refused by default
  }
  CHECK(xps_seen);
  // The continuous optimum is the one of before, and carries the strength it would need.
  const json& optimum = j["continuous_optimum"];
  CHECK(optimum["thickness_m"].get<double>() == Approx(15.0585e-3).margin(0.0001e-3));
  CHECK(optimum["required_compressive_strength_Pa"].get<double>() ==
        optimum["max_compressive_stress_Pa"].get<double>());
  // As a sacrificial liner, XPS is admissible again at the old 16 mm, with a warning.
  const json liner = JsonRun({"optimize", "--json", "--material", "XPS Foamular 250", "--allow-crushing"});
  CHECK(liner["recommendation"]["thickness_m"] == 0.016);
  CHECK(liner["criterion"]["crushing_allowed"] == true);
  bool warned = false;
  for (const json& w : liner["warnings"]) warned = warned || w.get<std::string>().find("crushes") != std::string::npos;
  CHECK(warned);
  // Unknown strengths: refused, then admitted with a warning.
  const json unknown = JsonRun({"optimize", "--json", "--material", "polystyrene foam 27.6"});
  CHECK(unknown["recommendation"].is_null());
  CHECK_THAT(unknown["message"].get<std::string>(), Catch::Contains("--allow-unknown-strength"));
  const json allowed =
      JsonRun({"optimize", "--json", "--material", "polystyrene foam 27.6", "--allow-unknown-strength"});
  REQUIRE(allowed["recommendation"].is_object());
  CHECK(allowed["recommendation"]["crush_check"] == "unknown-strength");
}

TEST_CASE("optimize's text names the governing criterion and the scope, and --csv writes every candidate",
          "[optimize][crush]") {
  TempDir dir;
  const std::string csv = (dir.path() / "candidates.csv").string();
  const CliRun run = Run({"optimize", "--csv", csv});
  REQUIRE(run.exit_code == 0);
  // The default answer is a foam layer (its measured curve), governed by its design rule.
  CHECK_THAT(run.out, Catch::Contains("governed by within-curve"));
  CHECK_THAT(run.out, Catch::Contains("Scope\n  Criteria: no laceration and no contusion"));
  CHECK_THAT(run.out, Catch::Contains("Wrote " + csv));
  const std::vector<std::string> lines = SplitLines(ReadFile(csv));
  CHECK(lines.size() == 1 + covopt::materials::Catalog::BuiltIn().size());
  CHECK(lines.front().rfind("rank,material,family,youngs_modulus_Pa", 0) == 0);
  CHECK_THAT(lines.front(), Catch::Contains("crush_ratio,governing_criterion,governing_ratio,margin"));
}

TEST_CASE("A safety factor reserves the covering's travel in optimize", "[optimize][crush]") {
  // A foam layer under the foam law: SF 2 keeps half of its measured curve's strain in reserve.
  const char* foam = "PE foam closed-cell (Kossa 2016)";
  const json once = JsonRun({"optimize", "--json", "--material", foam});
  const json twice =
      JsonRun({"optimize", "--json", "--material", foam, "--safety-factor", "2", "--max-thickness", "150mm"});
  REQUIRE(once["recommendation"].is_object());
  REQUIRE(twice["recommendation"].is_object());
  CHECK(twice["recommendation"]["compression_ratio"].get<double>() <= 0.5);
  CHECK(once["recommendation"]["compression_ratio"].get<double>() > 0.9);
  CHECK(twice["recommendation"]["thickness_m"].get<double>() > once["recommendation"]["thickness_m"].get<double>());
}

TEST_CASE("speed-limit applies a material's strength and says which covering it assumed", "[speed_limit][crush]") {
  const json xps = JsonRun({"speed-limit", "--json", "--covering-thickness", "16mm", "--material", "XPS Foamular 250"});
  CHECK(xps["rows"][0]["limited_by"] == "crush");
  const json liner = JsonRun(
      {"speed-limit", "--json", "--covering-thickness", "16mm", "--material", "XPS Foamular 250", "--allow-crushing"});
  CHECK(liner["rows"][0]["limited_by"] != "crush");
  CHECK(liner["rows"][0]["max_safe_speed_m_per_s"].get<double>() >
        10 * xps["rows"][0]["max_safe_speed_m_per_s"].get<double>());
  const CliRun assumed = Run({"speed-limit"});
  CHECK_THAT(assumed.out, Catch::Contains("Warning: no covering given: the default is assumed, 15 mm of 27.6 MPa"));
}

TEST_CASE("A probability design is refused when only its point estimate would meet the target", "[robust][crush]") {
  ExpectOneLine({"optimize", "--head-mass", "3.7kg..5.8kg", "--samples", "100", "--max-injury-probability", "0.01"},
                {"max injury probability 0.01", "needs at least 381 samples", "got 100"});
  ExpectOneLine({"optimize", "--head-mass", "3.7kg..5.8kg", "--samples", "100", "--max-injury-probability", "0"},
                {"--max-injury-probability", "(0, 1)"});
  const CliRun text = Run({"optimize", "--head-mass", "3.7kg..5.8kg", "--samples", "2000", "--max-injury-probability",
                           "0.2", "--material", "elastomer Shore A60"});
  REQUIRE(text.exit_code == 0);
  CHECK_THAT(text.out, Catch::Contains("Target     met when the upper end of the 95 % (Wilson) interval"));
  CHECK_THAT(text.out, Catch::Contains("Scene      10 kg at 2 m/s"));
  CHECK_THAT(text.out, Catch::Contains("over 1 input,"));
}

TEST_CASE("The new user's smaller findings: one line each", "[bad-input][crush]") {
  ExpectOneLine({"optimize", "--thickness", "16mm", "--max-thickness", "10mm"},
                {"--thickness 16mm and --max-thickness 10mm conflict"});
  ExpectOneLine({"simulate", "--velocity", "2"}, {"unknown option '--velocity'", "did you mean '--speed'?"});
  ExpectOneLine({"simulate", "--head-mass", "3.7kg-5.8kg"}, {"--head-mass", "LO..HI", "'3.7kg..5.8kg'"});
  // The range outputs print their Scene line; simulate says what it wrote.
  const CliRun robust = Run({"optimize", "--head-mass", "3.7kg..5.8kg", "--material", "elastomer Shore A60"});
  REQUIRE(robust.exit_code == 0);
  CHECK_THAT(robust.out, Catch::StartsWith("Scene      10 kg at 2 m/s"));
  CHECK_THAT(robust.out, Catch::Contains("Robust design over 1 uncertain input:"));
  TempDir dir;
  const std::string history = (dir.path() / "h.csv").string();
  const CliRun written = Run({"simulate", "--history", history});
  REQUIRE(written.exit_code == 0);
  CHECK_THAT(written.out, Catch::Contains("Wrote      " + history));
}
