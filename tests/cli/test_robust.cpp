// covopt simulate / optimize / speed-limit with scene ranges (issue 14, docs/model.md §11):
// the worst case over the box, the probability of injury, sensitivities, bad input.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/core/exact.hpp"
#include "covopt/core/impact_model.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using covopt::cli::testing::TempDir;
using Json = nlohmann::json;

const std::vector<std::string> kPaperCovering = {"--covering-thickness", "16mm", "--material", "XPS Foamular 250"};

std::vector<std::string> Args(std::vector<std::string> head, const std::vector<std::string>& tail = kPaperCovering) {
  head.insert(head.end(), tail.begin(), tail.end());
  return head;
}

Json RunJson(const std::vector<std::string>& args) {
  const CliRun run = Run(args);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  REQUIRE(run.err.empty());
  return Json::parse(run.out);
}

/// Bad input: exit 2, one line on stderr naming `needle`, nothing on stdout.
void ExpectBadInput(const std::vector<std::string>& args, const std::string& needle) {
  const CliRun run = Run(args);
  INFO(run.err);
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK(run.err.find(needle) != std::string::npos);
  CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
}

}  // namespace

TEST_CASE("simulate with a head-mass range: the worst case is the heaviest head (a monotone input)", "[cli][robust]") {
  const Json j = RunJson(Args({"simulate", "--json", "--head-mass", "3.7kg..5.8kg"}));
  const Json& worst = j["worst_case"];
  CHECK(worst["inputs"]["head-mass"].get<double>() == Approx(5.8));
  CHECK(worst["units"]["head-mass"] == "kg");
  // XPS Foamular 250 crushes at every head mass (crush ratio ~19): crush binds (issue 34).
  CHECK(worst["binding"] == "crush");
  // The impact reported is the one at the worst case: its ratio is the worst case's.
  CHECK(j["scene"]["head"]["mass_kg"].get<double>() == Approx(5.8));
  CHECK(j["contusion"]["ratio"].get<double>() == Approx(worst["contusion_ratio"].get<double>()).epsilon(1e-12));
  CHECK(j["uncertain_inputs"][0]["field"] == "head-mass");
  CHECK(j["uncertain_inputs"][0]["low"].get<double>() == Approx(3.7));
  CHECK(j["injury_probability"].is_null());
  CHECK(j["sensitivities"].is_null());
}

TEST_CASE("simulate: a non-monotone input's worst case lies inside its range, beyond the corners", "[cli][robust]") {
  // Bare robot: the contusion ratio peaks at an interior scalp thickness (about 4.5 mm for the
  // heaviest head), so a corners-only check falls short.
  const Json j = RunJson(Args({"simulate", "--json", "--covering-thickness", "0", "--head-mass", "3.7kg..5.8kg",
                               "--scalp-thickness", "2mm..5mm"},
                              {}));
  const Json& worst = j["worst_case"];
  const double scalp = worst["inputs"]["scalp-thickness"].get<double>();
  CHECK(scalp > 2.1e-3);
  CHECK(scalp < 4.9e-3);
  CHECK(worst["governing_ratio"].get<double>() > worst["corner_governing_ratio"].get<double>());
  CHECK(worst["found_by"] != "corner");
  // It is a maximum: the exact path a little to either side is no worse.
  for (const double step : {-1e-4, 1e-4}) {
    covopt::Scene scene;
    scene.covering.thickness_m = 0.0;
    scene.head.mass_kg = 5.8;
    scene.scalp.thickness_m = scalp + step;
    const auto peaks = covopt::ExactPeaks(covopt::ImpactModel::FromScene(scene));
    CHECK(peaks.max_energy_density_J_per_m2 / covopt::InjuryLimits{}.contusion_energy_density_J_per_m2 <=
          worst["contusion_ratio"].get<double>() * (1 + 1e-9));
  }
}

TEST_CASE("simulate --samples: the probability is reproducible and identical for any --threads", "[cli][robust]") {
  const auto args = [](const std::string& threads) {
    return Args({"simulate", "--json", "--head-mass", "3.7kg..5.8kg", "--scalp-thickness", "2mm..5mm", "--samples",
                 "20000", "--seed", "7", "--threads", threads});
  };
  const Json one = RunJson(args("1"));
  const Json three = RunJson(args("3"));
  const Json& p = one["injury_probability"];
  CHECK(p == three["injury_probability"]);
  CHECK(p["samples"] == 20000);
  CHECK(p["seed"] == 7);
  for (const char* key : {"laceration", "contusion", "any", "fully_compressed", "inadmissible"}) {
    const double value = p[key].get<double>();
    CHECK(p["ci95"][key][0].get<double>() <= value);
    CHECK(p["ci95"][key][1].get<double>() >= value);
    CHECK(p["counts"][key].get<double>() == Approx(value * 20000));
  }
  CHECK(p["any"].get<double>() >= p["contusion"].get<double>());
  CHECK(p["contusion"].get<double>() > 0.3);  // the nominal design fails for heavy heads
  CHECK(p["contusion"].get<double>() < 0.9);
  const Json other_seed = RunJson(Args({"simulate", "--json", "--head-mass", "3.7kg..5.8kg", "--scalp-thickness",
                                        "2mm..5mm", "--samples", "20000", "--seed", "8"}));
  CHECK(other_seed["injury_probability"]["counts"] != p["counts"]);
}

TEST_CASE("simulate --samples against a closed form: a head-mass interval with one safe sub-interval", "[cli][robust]") {
  // Only the head mass varies, uniformly on [3 kg, 6 kg]; contusion is monotone in it, so the
  // injured set is [m*, 6 kg] with m* where the contusion ratio is 1 (found by bisection here).
  covopt::Scene scene;
  scene.covering.thickness_m = 0.016;
  scene.covering.youngs_modulus_Pa = 16.71e6;
  scene.covering.poisson_ratio = 0.25;
  const auto ratio = [&](double mass) {
    scene.head.mass_kg = mass;
    return covopt::ExactPeaks(covopt::ImpactModel::FromScene(scene)).max_energy_density_J_per_m2 /
           covopt::InjuryLimits{}.contusion_energy_density_J_per_m2;
  };
  double lo = 3.0, hi = 6.0;
  REQUIRE(ratio(lo) < 1.0);
  REQUIRE(ratio(hi) > 1.0);
  for (int i = 0; i < 80; ++i) (ratio(0.5 * (lo + hi)) > 1.0 ? hi : lo) = 0.5 * (lo + hi);
  const double expected = (6.0 - hi) / 3.0;
  const Json j = RunJson(Args({"simulate", "--json", "--head-mass", "3kg..6kg", "--samples", "200000", "--seed", "3"}));
  const Json& p = j["injury_probability"];
  CHECK(p["contusion"].get<double>() == Approx(expected).margin(4.0 * std::sqrt(expected * (1 - expected) / 200000)));
  CHECK(p["ci95"]["contusion"][0].get<double>() <= expected + 1e-3);
  CHECK(p["ci95"]["contusion"][1].get<double>() >= expected - 1e-3);
}

TEST_CASE("simulate --distribution: a normal head mass shifts the probability", "[cli][robust]") {
  const auto base = Args({"simulate", "--json", "--head-mass", "3.7kg..5.8kg", "--samples", "20000", "--seed", "1"});
  auto light = base;
  light.insert(light.end(), {"--distribution", "head-mass=normal:4kg:0.3kg"});
  auto heavy = base;
  heavy.insert(heavy.end(), {"--distribution", "head-mass=normal:5.5kg:0.3kg"});
  const Json l = RunJson(light), h = RunJson(heavy);
  CHECK(l["uncertain_inputs"][0]["distribution"] == "normal");
  CHECK(l["uncertain_inputs"][0]["mean"].get<double>() == Approx(4.0));
  CHECK(l["injury_probability"]["contusion"].get<double>() < h["injury_probability"]["contusion"].get<double>());
}

TEST_CASE("simulate --sensitivities: the elasticity table, sorted for a tornado chart", "[cli][robust]") {
  const Json j = RunJson(Args({"simulate", "--json", "--sensitivities"}));
  const Json& s = j["sensitivities"];
  REQUIRE(s["rows"].size() >= 10);
  CHECK(j["worst_case"].is_null());
  // The impact energy ½ μ v² enters r_C: its elasticity to the speed is positive and the largest.
  CHECK(s["rows"][0]["field"] == "speed");
  CHECK(s["rows"][0]["contusion"].get<double>() > 0.5);
  double previous = 1e300;
  for (const Json& row : s["rows"]) {
    const double larger = s["laceration_ratio"].get<double>() >= s["contusion_ratio"].get<double>()
                              ? std::abs(row["laceration"].get<double>())
                              : std::abs(row["contusion"].get<double>());
    CHECK(larger <= previous + 1e-12);
    previous = larger;
  }
  bool thickness_analytic = false;
  for (const Json& row : s["rows"]) {
    if (row["field"] == "covering-thickness") thickness_analytic = row["method"] == "analytic";
  }
  CHECK(thickness_analytic);
  const CliRun text = Run(Args({"simulate", "--sensitivities"}));
  CHECK(text.exit_code == 0);
  CHECK(text.out.find("Sensitivities") != std::string::npos);
}

TEST_CASE("optimize with ranges: the robust design and the worst case that sets it", "[cli][robust]") {
  const Json j = RunJson({"optimize", "--json", "--head-mass", "3.7kg..5.8kg", "--scalp-thickness", "2mm..5mm"});
  CHECK(j["problem"] == "robust-thinnest");
  CHECK(j["verdict"] == "covering-found");
  const Json& rec = j["recommendation"];
  REQUIRE(!rec.is_null());
  CHECK(j["worst_case"]["inputs"]["head-mass"].get<double>() == Approx(5.8));
  CHECK(j["worst_case"]["governing_ratio"].get<double>() == Approx(1.0).margin(1e-3));
  CHECK(rec["worst_case"]["admissible"] == true);
  // Thicker than the nominal head's design (16 mm), and the continuous optimum too (15.06 mm).
  CHECK(rec["thickness_m"].get<double>() > 0.016);
  CHECK(j["continuous_optimum"]["thickness_m"].get<double>() > 0.0151);
  CHECK(j["continuous_optimum"]["worst_case"]["admissible"] == true);
  CHECK(j["bare_robot"]["admissible"] == false);
  // The recommendation checked by simulate over the same box is admissible.
  const Json check = RunJson({"simulate", "--json", "--head-mass", "3.7kg..5.8kg", "--scalp-thickness", "2mm..5mm",
                              "--material", rec["material"].get<std::string>(), "--covering-thickness",
                              std::to_string(rec["thickness_m"].get<double>() * 1e3) + "mm"});
  CHECK(check["worst_case"]["admissible"] == true);
  const CliRun text = Run({"optimize", "--head-mass", "3.7kg..5.8kg", "--scalp-thickness", "2mm..5mm"});
  CHECK(text.out.find("What sets the design") != std::string::npos);
}

TEST_CASE("optimize --max-injury-probability: thinner for a looser target, with the sampling error", "[cli][robust]") {
  const auto design = [](const std::string& p) {
    // EPS39 crushes on this scene (issue 21): as a sacrificial liner the target's mechanics show.
    return RunJson({"optimize", "--json", "--head-mass", "3.7kg..5.8kg", "--samples", "4000", "--seed", "2",
                    "--max-injury-probability", p, "--material", "EPS geofoam EPS39", "--allow-crushing"});
  };
  const Json crushing = RunJson({"optimize", "--json", "--head-mass", "3.7kg..5.8kg", "--samples", "4000", "--seed",
                                 "2", "--max-injury-probability", "0.3", "--material", "EPS geofoam EPS39"});
  CHECK(crushing["recommendation"].is_null());
  const Json strict = design("0.001"), loose = design("0.3");
  // The target is met on the 95 % upper bound: 0 failures of 4000 (bound 0.096 %) for 0.1 %.
  CHECK(strict["allowed_failures"] == 0);
  CHECK(strict["recommendation"]["injury_probability"]["ci95"]["inadmissible"][1].get<double>() <= 0.001);
  CHECK(strict["problem"] == "probability");
  REQUIRE(!strict["recommendation"].is_null());
  REQUIRE(!loose["recommendation"].is_null());
  CHECK(loose["recommendation"]["thickness_m"].get<double>() < strict["recommendation"]["thickness_m"].get<double>());
  CHECK(loose["recommendation"]["injury_probability"]["inadmissible"].get<double>() <= 0.3);
  CHECK(loose["recommendation"]["sampling_error"].get<double>() > 0.0);
}

TEST_CASE("speed-limit with ranges: the speed safe for the whole box is below each corner's", "[cli][robust]") {
  const Json box = RunJson({"speed-limit", "--json", "--head-mass", "3.7kg..5.8kg"});
  const double over_box = box["rows"][0]["speed_limit_m_per_s"].get<double>();
  CHECK(box["rows"][0]["worst_case"]["inputs"]["head-mass"].get<double>() == Approx(5.8));
  for (const char* mass : {"3.7kg", "5.8kg"}) {
    const Json one = RunJson({"speed-limit", "--json", "--head-mass", mass});
    CHECK(over_box <= one["rows"][0]["max_safe_speed_m_per_s"].get<double>() * (1 + 1e-9));
  }
}

TEST_CASE("scene files take ranges as strings", "[cli][robust]") {
  TempDir dir;
  const auto file = dir.Write("scene.toml", "[head]\nmass = \"3.7kg..5.8kg\"\n");
  const Json j = RunJson(Args({"simulate", "--json", "--scene", file.string()}));
  CHECK(j["worst_case"]["inputs"]["head-mass"].get<double>() == Approx(5.8));
  ExpectBadInput({"sweep", "--x", "speed=1..3", "--scene", file.string()}, "a range (an uncertain input)");
}

TEST_CASE("bad ranges, distributions and sampling flags: exit 2 with one line", "[cli][robust]") {
  ExpectBadInput(Args({"simulate", "--head-mass", "5.8kg..3.7kg"}), "the lower end is above the upper end");
  ExpectBadInput(Args({"simulate", "--head-mass", "fixed..5kg"}), "a fixed body cannot be uncertain");
  ExpectBadInput(Args({"simulate", "--head-mass", "3.7kg.."}), "both ends");
  ExpectBadInput(Args({"simulate", "--head-mass", "3.7kg..5.8kg", "--samples", "10", "--distribution",
                       "scalp-thickness=normal:3mm:1mm"}),
                 "scalp-thickness has no range");
  ExpectBadInput(Args({"simulate", "--head-mass", "3.7kg..5.8kg", "--samples", "10", "--distribution",
                       "brain-mass=normal:3kg:1kg"}),
                 "unknown input 'brain-mass'");
  ExpectBadInput(Args({"simulate", "--head-mass", "3.7kg..5.8kg", "--samples", "10", "--distribution",
                       "head-mass=normal:4kg"}),
                 "expected NAME=normal:MEAN:SD");
  ExpectBadInput(Args({"simulate", "--head-mass", "3.7kg..5.8kg", "--samples", "10", "--distribution",
                       "head-mass=normal:7kg:1kg"}),
                 "head-mass");
  ExpectBadInput(Args({"simulate", "--head-mass", "3.7kg..5.8kg", "--samples", "0"}), "--samples");
  ExpectBadInput(Args({"simulate", "--samples", "100"}), "give at least one scene input as a range");
  ExpectBadInput(Args({"simulate", "--head-mass", "3.7kg..5.8kg", "--distribution", "head-mass=normal:4kg:1kg"}),
                 "applies with --samples");
  ExpectBadInput(Args({"simulate", "--head-mass", "3.7kg..5.8kg", "--damping", "0.2s/m"}),
                 "not supported with ranges");
  ExpectBadInput(Args({"simulate", "--damping", "0.1s/m..0.3s/m"}), "not supported with ranges");
  ExpectBadInput({"optimize", "--head-mass", "3.7kg..5.8kg", "--max-injury-probability", "0.01"}, "needs --samples");
  ExpectBadInput({"optimize", "--samples", "100"}, "range");
  ExpectBadInput({"workprecision", "--head-mass", "3.7kg..5.8kg"}, "a range (an uncertain input)");
}

TEST_CASE("a bad --distribution is blamed on --distribution, not on the range flag", "[robust][bad-input]") {
  // Issue 22: "head.mass: the normal mean must lie in the range ... (head-mass from
  // --head-mass '3.7kg..5.8kg')" blamed the range.
  struct Case {
    std::string distribution;
    std::string words;
  };
  for (const Case& c : {Case{"head-mass=normal:9kg:1kg", "the mean 9 kg lies outside head-mass's range"},
                        Case{"head-mass=normal:4.5kg:-1kg", "the standard deviation must be > 0"},
                        Case{"head-mass=lognormal:4.5kg:0kg", "the standard deviation must be > 0"}}) {
    for (const char* command : {"simulate", "optimize"}) {
      CAPTURE(c.distribution, command);
      const CliRun run = Run({command, "--head-mass", "3.7kg..5.8kg", "--samples", "100", "--distribution",
                              c.distribution});
      CHECK(run.exit_code == 2);
      CHECK(run.out.empty());
      CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
      CHECK(run.err.find(": error: --distribution: ") != std::string::npos);
      CHECK(run.err.find(c.words) != std::string::npos);
      CHECK(run.err.find("(got '" + c.distribution + "')") != std::string::npos);
      CHECK(run.err.find("=normal:MEAN:SD") != std::string::npos);
      CHECK(run.err.find("from --head-mass") == std::string::npos);
    }
  }
}

TEST_CASE("optimize with ranges and a braking robot: the time path, screened, checked by simulate", "[cli][robust][braking]") {
  // docs/guide/robust.md's example: the robot brakes at 20 m/s² from 10 ms after first contact.
  const std::vector<std::string> braking = {"--reaction-delay", "10ms", "--braking", "20m/s2"};
  const std::vector<std::string> box = {"--head-mass", "3.7kg..5.8kg", "--scalp-thickness", "2mm..5mm"};
  // A compressible Hertz covering (ν 0.25, no curve): the solid elastomers of before leave their
  // law's strain limit on this scene, and curve materials are left out with a brake.
  std::vector<std::string> args = {"optimize", "--json", "--material", "Park padding 30", "--allow-unknown-strength"};
  args.insert(args.end(), box.begin(), box.end());
  const Json free = RunJson(args);
  args.insert(args.end(), braking.begin(), braking.end());
  const Json j = RunJson(args);
  CHECK(j["verdict"] == "covering-found");
  const Json& rec = j["recommendation"];
  REQUIRE(!rec.is_null());
  CHECK(j["time_path"]["runs"].get<long>() > 0);
  CHECK(j["time_path"]["failed"].get<long>() == 0);
  CHECK(free["time_path"]["runs"].get<long>() == 0);
  // Braking makes the design no thicker.
  CHECK(rec["min_safe_thickness_m"].get<double>() <= free["recommendation"]["min_safe_thickness_m"].get<double>() + 1e-6);
  // simulate over the same box with the same brake finds the recommendation admissible.
  std::vector<std::string> check = {"simulate", "--json", "--material", "Park padding 30", "--covering-thickness",
                                    std::to_string(rec["thickness_m"].get<double>() * 1e3) + "mm"};
  check.insert(check.end(), box.begin(), box.end());
  check.insert(check.end(), braking.begin(), braking.end());
  const Json verified = RunJson(check);
  CHECK(verified["worst_case"]["admissible"] == true);
  CHECK(verified["worst_case"]["time_path"]["runs"].get<long>() +
            verified["worst_case"]["time_path"]["brake_after_peak"].get<long>() >
        0);
  // The text report says how the braking robot's impacts were judged.
  args.erase(args.begin() + 1);
  const CliRun text = Run(args);
  CHECK(text.out.find("Braking robot: ") != std::string::npos);
  // Contact damping and a neck stay refused with ranges.
  ExpectBadInput({"optimize", "--head-mass", "3.7kg..5.8kg", "--torso-mass", "30kg", "--neck-stiffness", "30kN/m"},
                 "not supported with ranges");
}
