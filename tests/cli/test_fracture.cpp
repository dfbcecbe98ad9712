// The head's fracture check on the command line (docs/model.md §7.1): `--head-area` and a scene
// file's `[head] area` choose the struck area, the text and the JSON carry the fracture verdict
// with its limit and source, a force over the area's fracture force is not SAFE, and a bad
// area is refused naming the flag and the choices.

#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/core.hpp"

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using covopt::cli::testing::TempDir;
using Catch::Matchers::Contains;
using Json = nlohmann::json;

namespace {

/// The trial: a bare 5.145 kg robot of radius 60 mm at 2.3 m/s.
std::vector<std::string> Trial(std::vector<std::string> more = {}) {
  std::vector<std::string> args = {"simulate",         "--robot-mass", "5.145kg", "--robot-radius", "60mm", "--speed",
                                   "2.3m/s",           "--covering-thickness",   "0"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

double TrialForce() {
  covopt::Scene scene;
  scene.robot.mass_kg = 5.145;
  scene.robot.radius_m = 0.060;
  scene.robot.speed_m_per_s = 2.3;
  scene.covering.thickness_m = 0.0;
  return covopt::ExactPeaks(covopt::ImpactModel::FromScene(scene)).peak_force_N;
}

}  // namespace

TEST_CASE("simulate: the trial's 2.8 kN hit is judged against the forehead's fracture force", "[run][fracture]") {
  const CliRun run = Run(Trial({"--json"}));
  REQUIRE(run.exit_code == 0);
  const Json j = Json::parse(run.out);
  const Json& f = j.at("fracture");
  CHECK(f.at("area") == "frontal");
  CHECK(f.at("value_N").get<double>() == TrialForce());
  CHECK(f.at("limit_N").get<double>() == covopt::FractureForceOf(covopt::HeadArea::kFrontal).force_N);
  CHECK(f.at("ratio").get<double>() == Approx(TrialForce() / f.at("limit_N").get<double>()));
  CHECK(f.at("safe") == true);
  CHECK_THAT(f.at("source").get<std::string>(), Contains("Hodgson"));
  CHECK(j.at("scene").at("head").at("area") == "frontal");
  CHECK(j.at("safe") == true);
  // A safety factor of 1.2 derates 3114 N below the 2.8 kN: not safe.
  const Json derated = Json::parse(Run(Trial({"--json", "--safety-factor", "1.2"})).out);
  CHECK(derated.at("fracture").at("safe") == false);
  CHECK(derated.at("fracture").at("derated_limit_N").get<double>() == Approx(3113.755 / 1.2).epsilon(1e-4));
  CHECK(derated.at("safe") == false);
}

TEST_CASE("simulate --covering-law puts the law asked for in the scene and a bad one is exit 2", "[run][covering_law]") {
  const CliRun hertz = Run(Trial({"--covering-law", "hertz", "--json"}));
  REQUIRE(hertz.exit_code == 0);
  CHECK(Json::parse(hertz.out).at("scene").at("covering").at("law") == "hertz");
  CHECK(Json::parse(Run(Trial({"--json"})).out).at("scene").at("covering").at("law") == "auto");
  const CliRun bad = Run(Trial({"--covering-law", "soft"}));
  CHECK(bad.exit_code == 2);
  CHECK_THAT(bad.err, Contains("--covering-law") && Contains("soft"));
}

TEST_CASE("simulate --covering-law foam --material with a measured curve names the law and its validity", "[run][covering_law]") {
  const std::vector<std::string> vn600 = {"simulate", "--material", "vinyl-nitrile foam VN600", "--covering-law", "foam",
                                          "--covering-thickness", "20mm", "--speed", "0.3m/s", "--json"};
  const CliRun foam = Run(vn600);
  REQUIRE(foam.exit_code == 0);
  const Json j = Json::parse(foam.out);
  CHECK(j.at("covering_law") == "foam");
  CHECK(j.at("validity").at("within") == true);
  CHECK_THAT(j.at("validity").at("note").get<std::string>(), Contains("foam law"));
  // Faster, the 20 mm layer is used up (0.459 m/s on the paper's head): modelled (within the
  // law: a rigid stop, then the bare robot's chain), and said.
  std::vector<std::string> faster = vn600;
  faster[8] = "1m/s";
  const Json used_up = Json::parse(Run(faster).out);
  CHECK(used_up.at("validity").at("within") == true);
  CHECK(used_up.at("fully_compressed") == true);
  CHECK_THAT(used_up.at("validity").at("note").get<std::string>(), Contains("used up"));
  // The same covering read by Hertz's law when asked for; under auto (the default) a material
  // with a measured curve takes the foam law, the same answer as --covering-law foam exactly.
  std::vector<std::string> hertz = vn600;
  hertz[4] = "hertz";
  CHECK(Json::parse(Run(hertz).out).at("covering_law") == "hertz");
  hertz[4] = "auto";
  const Json automatic = Json::parse(Run(hertz).out);
  CHECK(automatic.at("covering_law") == "foam");
  CHECK(automatic.at("peak_force_N") == j.at("peak_force_N"));
  CHECK(automatic.at("laceration").at("ratio") == j.at("laceration").at("ratio"));
  // A body region names its law too.
  const Json hand = Json::parse(Run({"simulate", "--body-region", "hands-fingers", "--material", "vinyl-nitrile foam VN600",
                                     "--covering-law", "foam", "--covering-thickness", "10mm", "--speed", "1m/s", "--json"})
                                    .out);
  CHECK(hand.at("regions").at(0).at("covering_law") == "foam");
  CHECK(hand.at("regions").at(0).at("validity").at("within") == true);
  // optimize designs with the foam law; a material named without a curve is refused (exit 2).
  const CliRun optimize = Run({"optimize", "--covering-law", "foam", "--material", "elastomer Shore A40"});
  CHECK(optimize.exit_code == 2);
  CHECK_THAT(optimize.err, Contains("material 'elastomer Shore A40' has no compressive_curve"));
  // Without a curve, the foam law is refused (exit 2, naming the field).
  const CliRun no_curve = Run({"simulate", "--covering-thickness", "10mm", "--covering-law", "foam"});
  CHECK(no_curve.exit_code == 2);
  CHECK_THAT(no_curve.err, Contains("covering.law") || Contains("--covering-law"));
}

TEST_CASE("simulate --head-area nasal: the same hit breaks the nose and is UNSAFE", "[run][fracture]") {
  const CliRun json_run = Run(Trial({"--head-area", "nasal", "--json"}));
  REQUIRE(json_run.exit_code == 0);
  const Json j = Json::parse(json_run.out);
  CHECK(j.at("laceration").at("safe") == true);
  CHECK(j.at("contusion").at("safe") == true);
  CHECK(j.at("fracture").at("area") == "nasal");
  CHECK(j.at("fracture").at("limit_N").get<double>() == 450.0);
  CHECK(j.at("fracture").at("safe") == false);
  CHECK(j.at("safe") == false);
  const CliRun text = Run(Trial({"--head-area", "nasal"}));
  REQUIRE(text.exit_code == 0);
  CHECK_THAT(text.out, Contains("fracture          UNSAFE  peak force 2773 N, limit 450 N") &&
                           Contains("source: Cormier et al. 2010") && Contains("\nVerdict\n  UNSAFE, margin ") &&
                           Contains(": head (nasal) fracture ratio "));
}

TEST_CASE("a scene file's [head] area sets the struck area, the flag wins", "[run][fracture]") {
  const TempDir dir;
  const auto file = dir.Write("jaw.toml", "[head]\narea = \"mandible-side\"\n");
  const Json j = Json::parse(Run(Trial({"--scene", file.string(), "--json"})).out);
  CHECK(j.at("fracture").at("area") == "mandible-side");
  CHECK(j.at("fracture").at("limit_N").get<double>() == 600.0);
  const Json flag = Json::parse(Run(Trial({"--scene", file.string(), "--head-area", "temporo-parietal", "--json"})).out);
  CHECK(flag.at("fracture").at("area") == "temporo-parietal");
  const auto bad = dir.Write("bad.toml", "[head]\narea = \"cheek\"\n");
  const CliRun refused = Run(Trial({"--scene", bad.string()}));
  CHECK(refused.exit_code == 2);
  CHECK_THAT(refused.err, Contains("head.area must be one of frontal, temporo-parietal, nasal, maxilla") &&
                              Contains("\"cheek\""));
}

TEST_CASE("simulate --head-area: a bad area is refused with the choices, exit 2", "[run][fracture]") {
  const CliRun run = Run(Trial({"--head-area", "cheek"}));
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Contains("--head-area must be one of frontal, temporo-parietal, nasal, maxilla, "
                               "mandible-front, mandible-side (got \"cheek\")"));
}

TEST_CASE("the ranged worst case and probability count crush (the issue's XPS trial)", "[run][fracture][robust]") {
  const CliRun run = Run({"simulate", "--covering-thickness", "16mm", "--material", "XPS Foamular 250", "--head-mass",
                          "3.7kg..5.8kg", "--scalp-thickness", "2mm..5mm", "--samples", "2000", "--json"});
  REQUIRE(run.exit_code == 0);
  const Json j = Json::parse(run.out);
  CHECK(j.at("worst_case").at("binding") == "crush");
  CHECK(j.at("worst_case").at("crush_ratio").get<double>() > 15.0);
  CHECK(j.at("worst_case").at("admissible") == false);
  CHECK(j.at("injury_probability").at("inadmissible").get<double>() == 1.0);
  CHECK(j.at("injury_probability").at("crushed").get<double>() == 1.0);
  CHECK(j.at("injury_probability").at("contusion").get<double>() < 1.0);
}
