// Scene validation: every out-of-range input is rejected by ImpactModel::FromScene with a
// std::invalid_argument whose message names the field, shows the value and the allowed range;
// valid corner cases (fixed robot, fixed head, flat robot, no covering) are accepted.
#include <catch2/catch.hpp>

#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

#include "test_helpers.hpp"

using covopt::ImpactModel;
using covopt::Scene;

namespace {

struct BadInput {
  const char* field;       // must appear in the message
  const char* value_text;  // must appear in the message
  std::function<void(Scene&)> spoil;
};

std::string RejectionMessage(const Scene& scene) {
  try {
    (void)ImpactModel::FromScene(scene);
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return {};
}

}  // namespace

TEST_CASE("Every out-of-range scene input is rejected with field, value and range", "[scene]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const BadInput cases[] = {
      {"robot.mass", "-1", [](Scene& s) { s.robot.mass_kg = -1.0; }},
      {"robot.mass", "0", [](Scene& s) { s.robot.mass_kg = 0.0; }},
      {"robot.mass", "nan", [&](Scene& s) { s.robot.mass_kg = nan; }},
      {"robot.mass", "1e+07", [](Scene& s) { s.robot.mass_kg = 1e7; }},
      {"robot.speed", "0", [](Scene& s) { s.robot.speed_m_per_s = 0.0; }},
      {"robot.speed", "-2", [](Scene& s) { s.robot.speed_m_per_s = -2.0; }},
      {"robot.speed", "inf", [&](Scene& s) { s.robot.speed_m_per_s = inf; }},
      {"robot.speed", "nan", [&](Scene& s) { s.robot.speed_m_per_s = nan; }},
      {"robot.radius", "0", [](Scene& s) { s.robot.radius_m = 0.0; }},
      {"robot.radius", "-inf", [&](Scene& s) { s.robot.radius_m = -inf; }},
      {"robot.modulus", "-7", [](Scene& s) { s.robot.youngs_modulus_Pa = -7.0; }},
      {"robot.poisson", "0.6", [](Scene& s) { s.robot.poisson_ratio = 0.6; }},
      {"robot.poisson", "-1", [](Scene& s) { s.robot.poisson_ratio = -1.0; }},
      {"covering.thickness", "-0.001", [](Scene& s) { s.covering.thickness_m = -0.001; }},
      {"covering.thickness", "2", [](Scene& s) { s.covering.thickness_m = 2.0; }},
      {"covering.thickness", "nan", [&](Scene& s) { s.covering.thickness_m = nan; }},
      {"covering.modulus", "0", [](Scene& s) { s.covering.youngs_modulus_Pa = 0.0; }},
      {"covering.modulus", "inf", [&](Scene& s) { s.covering.youngs_modulus_Pa = inf; }},
      {"covering.poisson", "0.51", [](Scene& s) { s.covering.poisson_ratio = 0.51; }},
      {"head.mass", "-4.5", [](Scene& s) { s.head.mass_kg = -4.5; }},
      {"head.radius", "0", [](Scene& s) { s.head.radius_m = 0.0; }},
      {"head.radius", "0.002", [](Scene& s) { s.head.radius_m = 0.002; }},
      {"scalp.modulus", "nan", [&](Scene& s) { s.scalp.youngs_modulus_Pa = nan; }},
      {"scalp.poisson", "-3", [](Scene& s) { s.scalp.poisson_ratio = -3.0; }},
      {"scalp.thickness", "0", [](Scene& s) { s.scalp.thickness_m = 0.0; }},
      {"skull.modulus", "-1", [](Scene& s) { s.skull.youngs_modulus_Pa = -1.0; }},
      {"skull.poisson", "0.7", [](Scene& s) { s.skull.poisson_ratio = 0.7; }},
      {"model.exponent_robot_bone", "0.5", [](Scene& s) { s.model.exponent_robot_bone = 0.5; }},
      {"model.tensile_poisson", "0.9", [](Scene& s) { s.model.tensile_poisson_ratio = 0.9; }},
      {"model.full_compression_fraction", "0",
       [](Scene& s) { s.model.full_compression_fraction = 0.0; }},
  };
  for (const BadInput& bad : cases) {
    Scene scene;
    bad.spoil(scene);
    const std::string message = RejectionMessage(scene);
    INFO("field " << bad.field << ": message '" << message << "'");
    CHECK_THAT(message, Catch::Contains(bad.field));
    CHECK_THAT(message, Catch::Contains("(got " + std::string(bad.value_text)));
    CHECK_THAT(message, Catch::Contains(" must be "));
  }
}

TEST_CASE("Both bodies fixed is rejected, naming both masses", "[scene]") {
  Scene scene;
  scene.robot.mass_kg = covopt::kFixed;
  scene.head.mass_kg = covopt::kFixed;
  const std::string message = RejectionMessage(scene);
  CHECK_THAT(message, Catch::Contains("robot.mass"));
  CHECK_THAT(message, Catch::Contains("head.mass"));
  CHECK_THAT(message, Catch::Contains("fixed"));
}

TEST_CASE("A fixed robot with a fixed torso is rejected, naming both masses", "[scene][extended]") {
  // The robot would push the head into the torso for ever: the contact could never end.
  Scene scene;
  scene.robot.mass_kg = covopt::kFixed;
  scene.head.torso_mass_kg = covopt::kFixed;
  scene.head.neck_stiffness_N_per_m = 3e4;
  const std::string message = RejectionMessage(scene);
  CHECK_THAT(message, Catch::Contains("robot.mass"));
  CHECK_THAT(message, Catch::Contains("head.torso_mass"));
  CHECK_THAT(message, Catch::Contains("both fixed"));
  CHECK_THAT(message, Catch::Contains("never end"));
  // Either one fixed is a scene that ends.
  Scene free_robot = scene;
  free_robot.robot.mass_kg = 10.0;
  CHECK_NOTHROW(ImpactModel::FromScene(free_robot));
  Scene free_torso = scene;
  free_torso.head.torso_mass_kg = 30.0;
  CHECK_NOTHROW(ImpactModel::FromScene(free_torso));
}

TEST_CASE("Covering material is not checked when there is no covering", "[scene]") {
  Scene scene;
  scene.covering = {-1.0, 0.9, 0.0};  // ignored: thickness 0 means no covering
  CHECK_NOTHROW(ImpactModel::FromScene(scene));
}

TEST_CASE("Fixed robot, fixed head and flat robot are valid scenes", "[scene]") {
  Scene fixed_robot;
  fixed_robot.robot.mass_kg = covopt::kFixed;
  CHECK(ImpactModel::FromScene(fixed_robot).effective_mass_kg() == Approx(4.5));
  Scene fixed_head;
  fixed_head.head.mass_kg = covopt::kFixed;
  CHECK(ImpactModel::FromScene(fixed_head).effective_mass_kg() == Approx(10.0));
  Scene flat;
  flat.robot.radius_m = covopt::kFlat;
  CHECK_NOTHROW(ImpactModel::FromScene(flat));
}
