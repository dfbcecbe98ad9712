// A braking robot against the ISO/TS 15066 body regions (optim/body_region_check.hpp,
// docs/model.md §13.10): the verdict comes from the time path; the speed limit, bracketed on
// it from just below the unbraked limit, agrees with an independent scan and bisection on the
// verdict, is never below the unbraked limit, rises with the brake and falls with the delay;
// a failed time path is reported, never read as safe.
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/materials/body_regions.hpp>
#include <covopt/optim/body_region_check.hpp>

namespace {

using covopt::BodyContactScene;
using covopt::ContactType;
using covopt::materials::BodyLimits;
using covopt::materials::BodyRegionTable;
namespace co = covopt::optim;

BodyLimits Region(const char* name, ContactType contact = ContactType::kTransient) {
  return BodyRegionTable::BuiltIn().Limits(name, "", contact);
}

/// A robot of `mass` on a 20 mm radius, braking `a` after `t_d`, bare with a 1 cm² area or
/// under a covering.
BodyContactScene Robot(double mass, double delay_s, double braking, double modulus = 0.0, double thickness = 0.0) {
  BodyContactScene s;
  s.robot_mass_kg = mass;
  s.robot_radius_m = 0.02;
  s.contact_area_m2 = 1e-4;
  s.reaction_delay_s = delay_s;
  s.braking_m_per_s2 = braking;
  if (thickness > 0.0) s.covering = {modulus, 0.3, thickness};
  return s;
}

struct Case {
  const char* name;
  BodyContactScene scene;
  BodyLimits limits;
  co::BodyRegionOptions options;
};

std::vector<Case> Cases() {
  co::BodyRegionOptions sf2;
  sf2.rule.safety_factor = 2.0;
  co::BodyRegionOptions crushable;
  crushable.material = co::CandidateMaterial{};
  crushable.material->name = "weak foam";
  crushable.material->youngs_modulus_Pa = 3e6;
  crushable.material->poisson_ratio = 0.3;
  crushable.material->crush_behaviour = covopt::materials::CrushBehaviour::kCrushes;
  crushable.material->compressive_strength_Pa = 0.15e6;
  return {
      {"bare on the chest (pressure binds)", Robot(10.0, 5e-3, 200.0), Region("chest"), {}},
      {"bare on the chest, brake at contact, SF 2", Robot(10.0, 0.0, 50.0), Region("chest"), sf2},
      {"foam on the chest (force binds)", Robot(10.0, 5e-3, 500.0, 3e6, 10e-3), Region("chest"), {}},
      {"soft foam on the thigh (the travel binds)", Robot(20.0, 2e-3, 300.0, 0.1e6, 10e-3), Region("thighs-knees"), {}},
      {"weak crushable foam on the chest (crush binds)", Robot(10.0, 3e-3, 300.0, 3e6, 10e-3), Region("chest"), crushable},
      {"foam on the clamped hand", Robot(5.0, 1e-3, 100.0, 3e6, 5e-3), Region("hands-fingers", ContactType::kClamped), {}},
  };
}

co::BodyRegionJudgement JudgeAt(const Case& c, double speed) {
  BodyContactScene s = c.scene;
  s.speed_m_per_s = speed;
  return co::JudgeBodyContact(s, c.limits, c.options);
}

}  // namespace

TEST_CASE("a braking robot's contact is judged on the time path, below the unbraked ratios", "[body_region][braking]") {
  for (const Case& c : Cases()) {
    CAPTURE(c.name);
    const co::BodyRegionJudgement braked = JudgeAt(c, 1.0);
    BodyContactScene unbraked_scene = c.scene;
    unbraked_scene.braking_m_per_s2 = 0.0;
    unbraked_scene.speed_m_per_s = 1.0;
    const co::BodyRegionJudgement unbraked = co::JudgeBodyContact(unbraked_scene, c.limits, c.options);
    REQUIRE(braked.contact.ok());
    CHECK(braked.contact.method.starts_with("time path (arkode-erk54"));
    CHECK(unbraked.contact.method == "exact");
    CHECK(braked.force_ratio < unbraked.force_ratio);
    CHECK(braked.governing_ratio < unbraked.governing_ratio);
    CHECK(braked.force_ratio == Approx(braked.contact.peak_force_N / c.limits.force_N).epsilon(1e-15));
  }
}

TEST_CASE("a braking robot's speed limit agrees with a scan and bisection on its verdict", "[body_region][braking]") {
  const std::vector<Case> cases = Cases();
  const Case& c = cases[static_cast<std::size_t>(GENERATE(range(0, 6)))];
  CAPTURE(c.name);
  const co::BodyRegionSpeedLimit limit = co::MaxSafeSpeed(c.scene, c.limits, c.options);
  REQUIRE(limit.status == co::SpeedLimitStatus::kLimited);
  CHECK(limit.time_path_runs > 0);
  CHECK(limit.time_path_runs <= 20);  // regula falsi: not the ~40 runs of a bisection
  CHECK(limit.at_limit.admissible);
  CHECK(limit.at_limit.contact.ok());
  CHECK(limit.message.find("braking") != std::string::npos);
  CHECK(limit.message.find("(time path)") != std::string::npos);
  const double v = limit.max_safe_speed_m_per_s;

  // Independently: the first inadmissible speed of a scan 1e-3 .. 20 m/s (200 points per
  // decade), then a plain bisection on the verdict to 1e-9.
  double safe = 0.0, unsafe = 0.0;
  for (int i = 0; i <= 860; ++i) {
    const double speed = 1e-3 * std::pow(10.0, i / 200.0);
    if (!JudgeAt(c, speed).admissible) {
      unsafe = speed;
      break;
    }
    safe = speed;
  }
  REQUIRE(unsafe > 0.0);
  REQUIRE(safe > 0.0);
  while (unsafe / safe - 1.0 > 1e-9) {
    const double mid = std::sqrt(safe * unsafe);
    (JudgeAt(c, mid).admissible ? safe : unsafe) = mid;
  }
  CHECK(v == Approx(safe).epsilon(1e-8));
  CHECK_FALSE(JudgeAt(c, v * (1.0 + 1e-7)).admissible);
  // What binds there is the largest ratio just above the limit.
  CHECK(limit.limited_by == JudgeAt(c, v * (1.0 + 1e-7)).governing);

  // Never below the unbraked limit (braking only lowers the peaks), and the unbraked limit is
  // in closed form with no time-path run.
  BodyContactScene unbraked_scene = c.scene;
  unbraked_scene.braking_m_per_s2 = 0.0;
  const co::BodyRegionSpeedLimit unbraked = co::MaxSafeSpeed(unbraked_scene, c.limits, c.options);
  CHECK(unbraked.time_path_runs == 0);
  CHECK(v > unbraked.max_safe_speed_m_per_s);
}

TEST_CASE("a bare braking robot's speed limit is the closed form of a spring with a constant force from t_d",
          "[body_region][braking]") {
  // δ_max = sqrt((v s/ω + c)² + (v C/ω)²) - c with ω² = k_H/mu, c = a/ω², s, C = sin, cos ω t_d
  // (t_d before the maximum), so k_H δ_max = F* at v = ω (sqrt(s²c² + x² + 2cx) - s c), x = F*/k_H.
  const ContactType contact = GENERATE(ContactType::kTransient, ContactType::kClamped);
  const double braking = GENERATE(30.0, 100.0, 1000.0);
  const double delay_fraction = GENERATE(0.0, 0.2, 0.7);  // of the quarter period
  const BodyLimits chest = Region("chest", contact);
  const double robot_mass = 10.0;
  const double mu = contact == ContactType::kClamped ? robot_mass : 1.0 / (1.0 / robot_mass + 1.0 / 40.0);
  const double omega = std::sqrt(chest.stiffness_N_per_m() / mu);
  const double delay = delay_fraction * std::acos(-1.0) / (2.0 * omega);
  CAPTURE(covopt::ToString(contact), braking, delay);
  const double force = std::min(chest.force_N, chest.pressure_Pa * 1e-4);  // 1 cm²
  const double x = force / chest.stiffness_N_per_m(), c = braking / (omega * omega), s = std::sin(omega * delay);
  const double expected = omega * (std::sqrt(s * s * c * c + x * x + 2.0 * c * x) - s * c);
  const co::BodyRegionSpeedLimit limit = co::MaxSafeSpeed(Robot(robot_mass, delay, braking), chest, {});
  REQUIRE(limit.status == co::SpeedLimitStatus::kLimited);
  CHECK(limit.max_safe_speed_m_per_s == Approx(expected).epsilon(1e-7));
  CHECK(limit.limited_by == co::BodyLimitKind::kPressure);  // 240 N (120 N clamped) below 280 N (140 N)
}

TEST_CASE("a braking robot's speed limit rises with the brake and falls with the delay", "[body_region][braking]") {
  const std::vector<Case> cases = Cases();
  const Case& c = cases[static_cast<std::size_t>(GENERATE(0, 2, 3))];
  CAPTURE(c.name);
  BodyContactScene s = c.scene;
  s.braking_m_per_s2 = 0.0;
  const double unbraked = co::MaxSafeSpeed(s, c.limits, c.options).max_safe_speed_m_per_s;
  double previous = unbraked;
  for (const double braking : {1.0, 10.0, 30.0, 100.0, 300.0, 1000.0, 3000.0}) {
    s.braking_m_per_s2 = braking;
    const co::BodyRegionSpeedLimit limit = co::MaxSafeSpeed(s, c.limits, c.options);
    CAPTURE(braking);
    REQUIRE(limit.status == co::SpeedLimitStatus::kLimited);
    CHECK(limit.max_safe_speed_m_per_s >= previous * (1.0 - 1e-8));
    previous = limit.max_safe_speed_m_per_s;
  }
  s = c.scene;
  previous = std::numeric_limits<double>::infinity();
  for (const double delay : {0.0, 1e-3, 3e-3, 1e-2, 3e-2, 0.1, 1.0}) {
    s.reaction_delay_s = delay;
    const co::BodyRegionSpeedLimit limit = co::MaxSafeSpeed(s, c.limits, c.options);
    CAPTURE(delay);
    REQUIRE(limit.status == co::SpeedLimitStatus::kLimited);
    CHECK(limit.max_safe_speed_m_per_s <= previous * (1.0 + 1e-8));
    CHECK(limit.max_safe_speed_m_per_s >= unbraked * (1.0 - 1e-8));
    previous = limit.max_safe_speed_m_per_s;
  }
  // A brake that starts long after the contact has ended leaves the unbraked limit.
  CHECK(previous == Approx(unbraked).epsilon(1e-7));
}

TEST_CASE("a failed time path is reported by the verdict and the speed limit, never read as safe", "[body_region][braking]") {
  const Case c = Cases()[2];
  covopt::TimeIntegrationOptions time_path;
  time_path.max_steps = 10;
  BodyContactScene s = c.scene;
  s.speed_m_per_s = 0.01;  // safe, were it answered
  const co::BodyRegionJudgement j = co::JudgeBodyContact(s, c.limits, c.options, time_path);
  CHECK_FALSE(j.contact.ok());
  CHECK_FALSE(j.admissible);
  CHECK(j.governing == co::BodyLimitKind::kNone);
  CHECK(std::isinf(j.governing_ratio));
  CHECK(j.scope.find("no verdict: the time path failed (step-limit") != std::string::npos);

  const co::BodyRegionSpeedLimit limit = co::MaxSafeSpeed(c.scene, c.limits, c.options, time_path);
  CHECK(limit.status == co::SpeedLimitStatus::kEvaluationFailed);
  CHECK(limit.max_safe_speed_m_per_s == 0.0);
  CHECK(limit.limited_by == co::BodyLimitKind::kNone);
  CHECK(limit.message.find("no answer: the time path failed at") != std::string::npos);
  CHECK(limit.message.find("step limit of 10 steps") != std::string::npos);
  CHECK_FALSE(limit.at_limit.admissible);

  // The table carries it the same way.
  const std::vector<co::BodyRegionSpeedLimitRow> rows =
      co::BodyRegionSpeedLimitTable(c.scene, std::vector<BodyLimits>{c.limits}, c.options);
  REQUIRE(rows.size() == 1);
  CHECK(rows[0].bare.status == co::SpeedLimitStatus::kLimited);  // default options: answered
  // A bad time-path option is bad input, naming it.
  time_path.relative_tolerance = 1.0;
  CHECK_THROWS_WITH(co::MaxSafeSpeed(c.scene, c.limits, c.options, time_path), Catch::Contains("time_path."));
}

TEST_CASE("a fixed robot cannot brake: refused, naming the field", "[body_region][braking]") {
  BodyContactScene s = Robot(covopt::kFixed, 0.0, 100.0);
  CHECK_THROWS_WITH(co::MaxSafeSpeed(s, Region("chest"), {}), Catch::StartsWith("robot.braking needs a robot that moves"));
  s.robot_mass_kg = 10.0;
  s.reaction_delay_s = -1.0;
  CHECK_THROWS_WITH(co::JudgeBodyContact(s, Region("chest"), {}),
                    Catch::StartsWith("robot.reaction_delay must be 0 (brake at contact) or in [1e-06, 10] s"));
}
