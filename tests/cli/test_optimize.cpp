// `covopt optimize` end to end, in-process: the default scene gives a recommendation whose
// JSON matches the library's own answer for the same inputs (no hard-coded numbers), the
// paper's four materials rank as the library ranks them, --thickness switches to the
// least-injury problem, infeasible scenes are answers (exit 0), and bad input is exit 2 with
// one message naming the flag and nothing on stdout.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <covopt/optim/covering_design.hpp>

#include "cli_test_support.hpp"

using covopt::cli::testing::Run;
using nlohmann::json;

namespace {

const std::vector<std::string> kTableIv = {"--material", "polystyrene foam 27.6", "--material",
                                           "polystyrene foam 48.3", "--material",
                                           "polyurethane foam 62.1", "--material",
                                           "polyurethane foam 137.9"};

std::vector<std::string> With(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

TEST_CASE("optimize on the default scene recommends a material, with every JSON key", "[optimize]") {
  const auto run = Run({"optimize", "--json"});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const json j = json::parse(run.out);
  for (const char* key : {"recommendation", "continuous_optimum", "candidates", "solver", "bare_robot", "scene"}) {
    CHECK(j.contains(key));
  }
  const json& rec = j["recommendation"];
  REQUIRE(rec.is_object());
  for (const char* key : {"material", "thickness_m", "youngs_modulus_Pa", "poisson_ratio",
                          "laceration_ratio", "contusion_ratio", "safe"}) {
    CHECK(rec.contains(key));
  }
  CHECK(rec["safe"] == true);
  CHECK(rec["contusion_ratio"].get<double>() <= 1.0);
  CHECK(rec["laceration_ratio"].get<double>() <= 1.0);
  for (const char* key : {"youngs_modulus_Pa", "thickness_m", "laceration_ratio", "contusion_ratio"}) {
    CHECK(j["continuous_optimum"].contains(key));
  }
  for (const char* key : {"termination", "evaluations", "seconds"}) CHECK(j["solver"].contains(key));
  CHECK(j["candidates"].size() >= 20);
  for (const json& c : j["candidates"]) CHECK(c.contains("min_safe_thickness_m"));
  // No candidate is thinner and safe: the recommendation is the first of the ranking.
  CHECK(j["candidates"][0]["material"] == rec["material"]);

  // The same answer as the library for the same scene and the continuous design.
  const auto library = covopt::optim::FindThinnestSafeCovering(covopt::Scene{}, {});
  CHECK(j["continuous_optimum"]["thickness_m"].get<double>() ==
        Approx(library.continuous.score.design.thickness_m).epsilon(1e-12));
}

TEST_CASE("optimize ranks the paper's Table IV materials as the library does", "[optimize]") {
  const auto run = Run(With({"optimize", "--json"}, kTableIv));
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const json j = json::parse(run.out);
  REQUIRE(j["candidates"].size() == 4);
  const std::vector<covopt::optim::CandidateMaterial> table = {
      {"polystyrene foam 27.6", 27.6e6, 0.22}, {"polystyrene foam 48.3", 48.3e6, 0.25},
      {"polyurethane foam 62.1", 62.1e6, 0.20}, {"polyurethane foam 137.9", 137.9e6, 0.29}};
  const auto library = covopt::optim::FindThinnestSafeCovering(covopt::Scene{}, table);
  for (std::size_t i = 0; i < 4; ++i) {
    CHECK(j["candidates"][i]["material"] == library.candidates[i].material.name);
    if (library.candidates[i].min_safe_thickness_m) {
      CHECK(j["candidates"][i]["min_safe_thickness_m"].get<double>() ==
            Approx(*library.candidates[i].min_safe_thickness_m).epsilon(1e-12));
    } else {
      CHECK(j["candidates"][i]["min_safe_thickness_m"].is_null());
    }
  }
}

TEST_CASE("optimize --thickness answers the least-injury question", "[optimize]") {
  const auto run = Run(With({"optimize", "--json", "--thickness", "10mm"}, kTableIv));
  REQUIRE(run.exit_code == 0);
  const json j = json::parse(run.out);
  CHECK(j["problem"] == "least-injury-at-thickness");
  CHECK(j["recommendation"].is_null());  // at 10 mm nothing prevents contusion (Fig. 13)
  CHECK(j["continuous_optimum"]["contusion_ratio"].get<double>() > 1.0);
  CHECK(j["continuous_optimum"]["laceration_ratio"].get<double>() < 1.0);
}

TEST_CASE("an impossible scene is an answer with exit 0", "[optimize]") {
  const auto run = Run({"optimize", "--speed", "8m/s"});
  INFO(run.err);
  CHECK(run.exit_code == 0);
  CHECK_THAT(run.out, Catch::Contains("Nothing is safe"));
  const auto gentle = Run({"optimize", "--speed", "0.2m/s"});
  CHECK(gentle.exit_code == 0);
  CHECK_THAT(gentle.out, Catch::Contains("no covering is needed"));
}

TEST_CASE("optimize rejects bad input with exit 2, naming the flag", "[optimize]") {
  struct Case {
    std::vector<std::string> args;
    const char* mention;
  };
  const Case cases[] = {
      {{"optimize", "--safety-factor", "0.5"}, "--safety-factor"},
      {{"optimize", "--max-thickness", "-3mm"}, "--max-thickness"},
      {{"optimize", "--max-thickness", "3kg"}, "--max-thickness"},
      {{"optimize", "--thickness", "0"}, "--thickness"},
      {{"optimize", "--material", "polystyrene"}, "did you mean"},
      {{"optimize", "--family", "cheese"}, "--family"},
      {{"optimize", "--global", "simplex"}, "--global"},
      {{"optimize", "--speed", "-2m/s"}, "robot.speed"},
      {{"optimize", "--catalog", "/no/such/file.toml"}, "--catalog"},
      {{"optimize", "--covering-thickness", "15mm"}, "covering-thickness"},
  };
  for (const Case& c : cases) {
    const auto run = Run(c.args);
    INFO(c.args.back() << ": " << run.err);
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK_THAT(run.err, Catch::Contains(c.mention));
  }
}
