// `covopt optimize`'s default answer end to end (optim/design_answer.hpp): a band material's
// recommendation names the range it holds over, and a scene no material can serve answers
// "No catalog material works for this scene" with the nearest changes, in text and JSON, the
// JSON's numbers those of the library's own search.
#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <covopt/materials/catalog.hpp>
#include <covopt/optim/material_range.hpp>

#include "cli_test_support.hpp"

using covopt::cli::testing::Run;
using nlohmann::json;

TEST_CASE("optimize names the range a band material's recommendation holds over", "[optimize][answer]") {
  const auto run = Run({"optimize", "--material", "neoprene sponge D1056 2C3", "--speed", "1.2m/s", "--json"});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const json j = json::parse(run.out);
  REQUIRE(j["recommendation"].is_object());
  const json& range = j["material_range"];
  REQUIRE(range.is_object());
  CHECK(range["admissible"] == true);
  CHECK(range["thickness_m"] == j["recommendation"]["thickness_m"]);
  CHECK(range["range"]["stated"] == true);
  CHECK(range["range"]["stress_at_25_band_Pa"][0].get<double>() == Approx(62052.8));
  CHECK(range["verdicts"].size() == 2);
  CHECK(range["worst_margin"].get<double>() >= 0.0);
  CHECK(j["nearest_changes"].is_null());
  const auto text = Run({"optimize", "--material", "neoprene sponge D1056 2C3", "--speed", "1.2m/s"});
  REQUIRE(text.exit_code == 0);
  CHECK(text.out.find("robust over σ(25 %) band 62.1–89.6 kPa") != std::string::npos);
  CHECK(text.out.find("worst margin") != std::string::npos);
}

TEST_CASE("optimize says plainly when no material works, with the nearest changes", "[optimize][answer]") {
  const std::vector<std::string> args{"optimize", "--material", "neoprene sponge D1056 2C3", "--material",
                                      "vinyl-nitrile foam VN600", "--speed", "3m/s"};
  std::vector<std::string> with_json = args;
  with_json.push_back("--json");
  const auto run = Run(with_json);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);  // an answer, not an error
  const json j = json::parse(run.out);
  CHECK(j["recommendation"].is_null());
  CHECK(j["material_range"].is_null());
  CHECK(j["message"].get<std::string>().find(" No catalog material works for this scene; nearest changes for ") !=
        std::string::npos);
  const json& n = j["nearest_changes"];
  REQUIRE(n.is_object());
  // The library's own nearest changes for the same scene and materials.
  covopt::Scene scene;
  scene.robot.speed_m_per_s = 3.0;
  const auto& catalog = covopt::materials::Catalog::BuiltIn();
  const std::vector<covopt::optim::RangedMaterial> materials{
      covopt::optim::RangedMaterialOf(*catalog.Find("neoprene sponge D1056 2C3")),
      covopt::optim::RangedMaterialOf(*catalog.Find("vinyl-nitrile foam VN600"))};
  const auto ours = covopt::optim::FindNearestChanges(scene, materials, covopt::optim::DesignOptions{});
  REQUIRE(ours.has_value());
  CHECK(n["material"] == ours->material);
  REQUIRE(n["speed_m_per_s"]["reachable"] == ours->speed.reachable);
  if (ours->speed.reachable) CHECK(n["speed_m_per_s"]["value"].get<double>() == ours->speed.value);
  REQUIRE(n["thickness_m"]["reachable"] == ours->thickness.reachable);
  if (ours->thickness.reachable) CHECK(n["thickness_m"]["value"].get<double>() == ours->thickness.value);
  REQUIRE(n["robot_radius_m"]["reachable"] == ours->radius.reachable);
  if (ours->radius.reachable) CHECK(n["robot_radius_m"]["value"].get<double>() == ours->radius.value);
  for (const json& c : j["candidates"]) CHECK_FALSE(c["range_note"].get<std::string>().empty());
  const auto text = Run(args);
  REQUIRE(text.exit_code == 0);
  CHECK(text.out.find("No catalog material works for this scene; nearest changes for ") != std::string::npos);
  CHECK(text.out.find("Nearest changes (for ") != std::string::npos);
  CHECK(text.out.find("  slower     ") != std::string::npos);
}
