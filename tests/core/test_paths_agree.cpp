// The two paths agree: on generated scenes spanning no covering, thin (fully compressed) and
// thick coverings, flat and curved robots, fixed head, fixed robot, slow and fast impacts,
// soft and very stiff coverings, literal thresholds whose force drops at a switch (the peak
// then lies before δ_max), the time path reproduces the exact path's δ_max,
// F_max, σ_c,max, σ_t,max, e_A,max and contact duration within 1e-6 relative at the default
// tolerances and within 1e-9 at tight ones, with the default ARKODE Dormand-Prince 5(4) and
// both CVODE methods.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "test_helpers.hpp"

using namespace covopt;
using covopt::test::AddVariant;
using covopt::test::CheckPeaksAgainstExact;
using covopt::test::NamedScene;
using covopt::test::PaperScene;

namespace {

std::vector<NamedScene> GeneratedScenes() {
  std::vector<NamedScene> scenes;
  const Scene base = PaperScene(0.015, 27.6e6, 0.22);
  auto add = [&](std::string name, auto&& edit) { AddVariant(scenes, base, std::move(name), edit); };
  add("paper scene, 15 mm polystyrene", [](Scene&) {});
  add("no covering", [](Scene& s) { s.covering.thickness_m = 0; });
  add("thin, fully compressed covering", [](Scene& s) { s.covering.thickness_m = 0.002; });
  add("thick soft covering", [](Scene& s) { s.covering = {2e6, 0.3, 0.05}; });
  add("flat robot", [](Scene& s) { s.robot.radius_m = kFlat; });
  add("flat robot, no covering", [](Scene& s) {
    s.robot.radius_m = kFlat;
    s.covering.thickness_m = 0;
  });
  add("fixed head", [](Scene& s) { s.head.mass_kg = kFixed; });
  add("fixed robot (head drop)", [](Scene& s) {
    s.robot.mass_kg = kFixed;
    s.robot.speed_m_per_s = 2.2;
  });
  add("slow impact", [](Scene& s) { s.robot.speed_m_per_s = 0.05; });
  add("fast impact", [](Scene& s) { s.robot.speed_m_per_s = 8.0; });
  add("very soft covering", [](Scene& s) { s.covering = {0.15e6, 0.25, 0.02}; });
  add("very stiff covering", [](Scene& s) { s.covering = {1e9, 0.25, 0.005}; });
  add("heavy robot, large radius", [](Scene& s) {
    s.robot.mass_kg = 80;
    s.robot.radius_m = 0.08;
  });
  add("literal thresholds", [](Scene& s) { s.model.thresholds = ThresholdReading::kLiteral; });
  add("literal thresholds, ill-ordered (the force jumps at t1)", [](Scene& s) {
    s.model.thresholds = ThresholdReading::kLiteral;
    s.covering.thickness_m = 0.001;
  });
  add("literal thresholds, the force drops at t1 (peak before δ_max)", [](Scene& s) {
    s.model.thresholds = ThresholdReading::kLiteral;
    s.scalp.thickness_m = 0.010;
    s.covering = {100e6, 0.25, 0.0065};
    s.robot.speed_m_per_s = 1.5;
  });
  add("literal thresholds, no covering (phase 3 from δ = 0, F and σ drop at t1)", [](Scene& s) {
    s.model.thresholds = ThresholdReading::kLiteral;
    s.covering.thickness_m = 0;
    s.robot.speed_m_per_s = 0.3;
  });
  return scenes;
}

void CheckAgreement(const NamedScene& named, ComputationMethod method, double rtol, double limit) {
  const ImpactModel model = ImpactModel::FromScene(named.scene);
  const ImpactResult exact = SolveExact(model);
  TimeIntegrationOptions options;
  options.method = method;
  if (rtol > 0) options.relative_tolerance = rtol;
  const ImpactResult simulated = SimulateImpact(model, options);
  INFO(named.name << ", " << ToString(method) << ", rtol "
                  << options.relative_tolerance << ": " << simulated.message);
  REQUIRE(simulated.ok());
  REQUIRE(simulated.contact_duration_s.has_value());
  CHECK(simulated.peaks.phase_at_max == exact.peaks.phase_at_max);
  CheckPeaksAgainstExact(simulated, exact, limit);
}

}  // namespace

TEST_CASE("Time path agrees with the exact path to 1e-6 at default tolerances", "[agree]") {
  const auto method = GENERATE(ComputationMethod::kArkodeErk54, ComputationMethod::kCvodeAdams,
                               ComputationMethod::kCvodeBdf);
  for (const NamedScene& named : GeneratedScenes()) CheckAgreement(named, method, 0.0, 1e-6);
}

TEST_CASE("Time path agrees with the exact path to 1e-9 at tight tolerances", "[agree]") {
  const auto method = GENERATE(ComputationMethod::kArkodeErk54, ComputationMethod::kCvodeAdams,
                               ComputationMethod::kCvodeBdf);
  for (const NamedScene& named : GeneratedScenes()) CheckAgreement(named, method, 1e-12, 1e-9);
}
