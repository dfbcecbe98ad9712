// covopt::report::SimulationJson and SceneJson: the documented keys, numbers that read back as
// the doubles computed, null for what is unknown or not finite, and the words for infinity.

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "covopt/core/exact.hpp"
#include "covopt/core/impact_model.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/report/simulation_json.hpp"

namespace {

using Json = nlohmann::json;

/// The paper's scene (or `scene`) on the exact path, judged against the default limits.
covopt::report::SimulationReport ExactReport(const covopt::Scene& scene = {}) {
  covopt::report::SimulationReport report;
  report.scene = scene;
  report.result = covopt::SolveExact(covopt::ImpactModel::FromScene(scene));
  report.assessment = covopt::Assess(report.result.peaks);
  return report;
}

}  // namespace

TEST_CASE("SimulationJson has every documented key, in SI with the unit in its name", "[report][json]") {
  const Json j = Json::parse(covopt::report::SimulationJson(ExactReport()));
  for (const char* key :
       {"max_penetration_m", "peak_force_N", "contact_duration_s", "time_of_max_compression_s",
        "max_compressive_stress_Pa", "max_tensile_stress_Pa", "max_energy_density_J_per_m2",
        "rebound_speed_m_per_s", "coefficient_of_restitution", "phase_at_max", "phase_at_max_name",
        "scalp_fully_compressed", "fully_compressed", "laceration", "contusion", "fracture", "crush", "safe",
        "scope", "method", "solver", "scene", "warnings", "warning_codes"}) {
    INFO(key);
    CHECK(j.contains(key));
  }
  for (const char* key : {"value_Pa", "limit_Pa", "ratio", "safe", "derated_limit_Pa", "safety_factor"}) {
    INFO(key);
    CHECK(j["laceration"].contains(key));
  }
  for (const char* key :
       {"value_J_per_m2", "limit_J_per_m2", "ratio", "safe", "derated_limit_J_per_m2", "safety_factor"}) {
    INFO(key);
    CHECK(j["contusion"].contains(key));
  }
  for (const char* key : {"robot", "covering", "head", "scalp", "skull", "model"}) {
    INFO(key);
    CHECK(j["scene"].contains(key));
  }
  CHECK(j["method"] == "exact");
  CHECK(j["solver"]["status"] == "success");
  // The exact path has no integrator: no tolerances, no energy residual.
  CHECK_FALSE(j["solver"].contains("relative_tolerance"));
  CHECK_FALSE(j["solver"].contains("energy_residual"));
  CHECK(j["crush"].is_null());
  CHECK(j["laceration"]["limit_Pa"] == 1e6);
}

TEST_CASE("SimulationJson's numbers read back as the doubles computed, in their shortest form",
          "[report][json]") {
  covopt::Scene scene;
  scene.robot.speed_m_per_s = 2.2;
  scene.covering.thickness_m = 0.018;
  const auto report = ExactReport(scene);
  const std::string text = covopt::report::SimulationJson(report);
  // 2.2 and 0.018 are exact inputs; neither may print with 17 digits.
  CHECK_THAT(text, Catch::Contains("\"speed_m_per_s\": 2.2,") && Catch::Contains("\"thickness_m\": 0.018"));
  CHECK_THAT(text, !Catch::Contains("2.2000000000000002") && !Catch::Contains("0.018000000000000002"));
  const Json j = Json::parse(text);
  const auto& p = report.result.peaks;
  CHECK(j["max_penetration_m"].get<double>() == p.max_penetration_m);
  CHECK(j["peak_force_N"].get<double>() == p.peak_force_N);
  CHECK(j["max_compressive_stress_Pa"].get<double>() == p.max_compressive_stress_Pa);
  CHECK(j["max_tensile_stress_Pa"].get<double>() == p.max_tensile_stress_Pa);
  CHECK(j["max_energy_density_J_per_m2"].get<double>() == p.max_energy_density_J_per_m2);
  CHECK(j["contact_duration_s"].get<double>() == report.result.contact_duration_s);
  CHECK(j["contusion"]["ratio"].get<double>() == report.assessment.contusion.ratio);
  CHECK(j["laceration"]["ratio"].get<double>() == report.assessment.laceration.ratio);
  // One line with indent -1, the same values.
  const std::string line = covopt::report::SimulationJson(report, -1);
  CHECK(line.find('\n') == std::string::npos);
  CHECK(Json::parse(line) == j);
}

TEST_CASE("a value that is not finite is null, never NaN or Infinity", "[report][json]") {
  auto report = ExactReport();
  report.result.peaks.peak_force_N = std::numeric_limits<double>::quiet_NaN();
  report.result.contact_duration_s = std::numeric_limits<double>::infinity();
  const std::string text = covopt::report::SimulationJson(report);
  CHECK_THAT(text, !Catch::Contains("NaN") && !Catch::Contains("nan") && !Catch::Contains("Infinity") &&
                       !Catch::Contains("inf"));
  const Json j = Json::parse(text);
  CHECK(j["peak_force_N"].is_null());
  CHECK(j["contact_duration_s"].is_null());
  CHECK(j["max_penetration_m"].is_number());
  // No catalog material: the covering's material is null, not an empty string.
  CHECK(j["scene"]["covering"]["material"].is_null());
  report.covering_material = "polystyrene foam 27.6";
  CHECK(Json::parse(covopt::report::SimulationJson(report))["scene"]["covering"]["material"] ==
        "polystyrene foam 27.6");
}

TEST_CASE("SceneJson writes an infinite mass as 'fixed' and an infinite radius as 'flat'", "[report][json]") {
  covopt::Scene scene;
  scene.robot.mass_kg = covopt::kFixed;
  scene.robot.radius_m = std::numeric_limits<double>::infinity();
  scene.head.mass_kg = covopt::kFixed;
  const Json j = Json::parse(covopt::report::SceneJson(scene));
  CHECK(j["robot"]["mass_kg"] == "fixed");
  CHECK(j["robot"]["radius_m"] == "flat");
  CHECK(j["head"]["mass_kg"] == "fixed");
  CHECK(j["robot"]["speed_m_per_s"].get<double>() == scene.robot.speed_m_per_s);
  CHECK(j["covering"]["youngs_modulus_Pa"].get<double>() == scene.covering.youngs_modulus_Pa);
  CHECK(j["model"]["thresholds"].is_string());
  // The scene inside SimulationJson is the same object (plus the covering's material).
  Json inside = Json::parse(covopt::report::SimulationJson(ExactReport()))["scene"];
  inside["covering"].erase("material");
  CHECK(inside == Json::parse(covopt::report::SceneJson(covopt::Scene{})));
}
