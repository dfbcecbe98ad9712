// CheckTrajectory (optim/trajectory_check.hpp): each sample's verdict is the exact path's at
// that speed and mass, computed here independently; the speed scale is exact (the trajectory
// scaled by it is safe everywhere, a hair faster is not); rest, edges and bad input.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/optim/trajectory_check.hpp>

namespace {

using covopt::kFixed;
using covopt::Scene;
using covopt::optim::CheckTrajectory;
using covopt::optim::MotionSample;
using covopt::optim::TrajectoryCheck;
using covopt::optim::TrajectoryCheckOptions;
using covopt::optim::TrajectoryCheckStatus;

constexpr double kInf = std::numeric_limits<double>::infinity();

/// A motion that accelerates, peaks at 1.5 m/s with a heavy configuration, and stops; the
/// reflected mass changes along it.
std::vector<MotionSample> SampleMotion() {
  std::vector<MotionSample> samples;
  for (int i = 0; i <= 40; ++i) {
    const double t = 0.025 * i;
    const double speed = 1.5 * std::sin(3.14159265358979 * t);  // 0 at both ends
    const double mass = 3.0 + 9.0 * t * (1.0 - t) * 4.0 * (0.5 + 0.5 * std::cos(5.0 * t));
    samples.push_back({t, std::max(speed, 0.0), mass});
  }
  return samples;
}

/// Every moving sample scaled by `factor` is admissible (both ratios <= 1, not bottomed out),
/// judged by the exact path directly.
bool AllAdmissible(const Scene& scene, const std::vector<MotionSample>& samples, double factor) {
  for (const MotionSample& s : samples) {
    if (s.speed_m_per_s * factor < 1e-6) continue;
    Scene at = scene;
    at.robot.mass_kg = s.reflected_mass_kg;
    at.robot.speed_m_per_s = s.speed_m_per_s * factor;
    const covopt::ImpactModel model = covopt::ImpactModel::FromScene(at);
    const covopt::ImpactPeaks peaks = covopt::ExactPeaks(model);
    const covopt::InjuryLimits limits;
    if (peaks.max_tensile_stress_Pa > limits.laceration_tensile_stress_Pa) return false;
    if (peaks.max_energy_density_J_per_m2 > limits.contusion_energy_density_J_per_m2) return false;
    if (peaks.fully_compressed) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("trajectory check: every verdict is the exact path's at the sample's speed and mass",
          "[trajectory]") {
  const Scene scene;  // the paper's covering on the paper's head
  const std::vector<MotionSample> samples = SampleMotion();
  const TrajectoryCheck check = CheckTrajectory(scene, samples);
  REQUIRE(check.samples.size() == samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const auto& v = check.samples[i];
    CHECK(v.time_s == samples[i].time_s);
    if (!v.moving) {
      CHECK(samples[i].speed_m_per_s < 1e-6);
      CHECK(v.laceration_ratio == 0.0);
      CHECK(std::isinf(v.speed_scale));
      continue;
    }
    Scene at = scene;
    at.robot.mass_kg = samples[i].reflected_mass_kg;
    at.robot.speed_m_per_s = samples[i].speed_m_per_s;
    const covopt::ImpactPeaks peaks = covopt::ExactPeaks(covopt::ImpactModel::FromScene(at));
    CHECK(v.laceration_ratio == Approx(peaks.max_tensile_stress_Pa / 1e6).epsilon(1e-14));
    CHECK(v.contusion_ratio == Approx(peaks.max_energy_density_J_per_m2 / 25200.0).epsilon(1e-14));
    CHECK(v.speed_scale == Approx(v.speed_limit.max_safe_speed_m_per_s / v.speed_m_per_s).epsilon(1e-15));
    // A sample is safe exactly when its speed is within its limit.
    CHECK(v.safe == (v.speed_m_per_s <= v.speed_limit.max_safe_speed_m_per_s));
  }
}

TEST_CASE("trajectory check: the speed scale is exact", "[trajectory]") {
  const Scene scene;
  for (const double peak_scale : {0.5, 1.0, 2.0}) {
    std::vector<MotionSample> samples = SampleMotion();
    for (auto& s : samples) s.speed_m_per_s *= peak_scale;
    const TrajectoryCheck check = CheckTrajectory(scene, samples);
    INFO("peak speed scaled by " << peak_scale << ": " << check.BriefReport());
    REQUIRE(check.worst_sample.has_value());
    const double k = check.safe_speed_scale;
    REQUIRE(std::isfinite(k));
    CHECK(check.status == (k >= 1.0 ? TrajectoryCheckStatus::kSafe : TrajectoryCheckStatus::kUnsafe));
    CHECK(AllAdmissible(scene, samples, k));
    CHECK_FALSE(AllAdmissible(scene, samples, k * (1.0 + 1e-9)));
    // The worst sample is the one whose own limit is closest to its speed.
    for (const auto& v : check.samples) {
      if (v.moving) CHECK(v.speed_scale >= k);
    }
  }
}

TEST_CASE("trajectory check: a slower trajectory has a proportionally larger scale", "[trajectory]") {
  const Scene scene;
  std::vector<MotionSample> samples = SampleMotion();
  const double k1 = CheckTrajectory(scene, samples).safe_speed_scale;
  for (auto& s : samples) s.speed_m_per_s *= 0.5;
  const double k2 = CheckTrajectory(scene, samples).safe_speed_scale;
  CHECK(k2 == Approx(2.0 * k1).epsilon(1e-12));
}

TEST_CASE("trajectory check: heavier samples lower the scale", "[trajectory]") {
  const Scene scene;
  std::vector<MotionSample> light = SampleMotion();
  std::vector<MotionSample> heavy = light;
  for (auto& s : heavy) s.reflected_mass_kg *= 3.0;
  CHECK(CheckTrajectory(scene, heavy).safe_speed_scale < CheckTrajectory(scene, light).safe_speed_scale);
}

TEST_CASE("trajectory check: a point at rest has nothing to judge", "[trajectory]") {
  const std::vector<MotionSample> samples = {{0.0, 0.0, 5.0}, {0.1, 0.0, 5.0}, {0.2, 1e-9, 5.0}};
  const TrajectoryCheck check = CheckTrajectory(Scene{}, samples);
  CHECK(check.status == TrajectoryCheckStatus::kAtRest);
  CHECK(std::isinf(check.safe_speed_scale));
  CHECK_FALSE(check.worst_sample.has_value());
}

TEST_CASE("trajectory check: a fixed reflected mass (a singular direction) is judged as a fixed robot",
          "[trajectory]") {
  const std::vector<MotionSample> samples = {{0.0, 0.5, 4.0}, {0.1, 0.5, kFixed}};
  const TrajectoryCheck check = CheckTrajectory(Scene{}, samples);
  REQUIRE(check.worst_sample.has_value());
  CHECK(*check.worst_sample == 1);
  CHECK(check.samples[1].speed_limit.max_safe_speed_m_per_s <
        check.samples[0].speed_limit.max_safe_speed_m_per_s);
}

TEST_CASE("trajectory check: limits nothing meets give no safe speed, and say so", "[trajectory]") {
  TrajectoryCheckOptions options;
  options.limit.limits.laceration_tensile_stress_Pa = 1e3;  // the floor, 1 kPa, with SF 100: nothing is safe
  options.limit.safety_factor = 100.0;
  const TrajectoryCheck check = CheckTrajectory(Scene{}, SampleMotion(), options);
  CHECK(check.status == TrajectoryCheckStatus::kUnsafe);
  CHECK(check.safe_speed_scale == 0.0);
  REQUIRE(check.warnings.size() == 1);
  CHECK_THAT(check.warnings[0], Catch::Contains("no safe speed"));
}

TEST_CASE("trajectory check: a scale set by the 100 m/s ceiling is flagged as a lower bound",
          "[trajectory]") {
  TrajectoryCheckOptions options;
  options.limit.allow_full_compression = true;
  options.limit.limits.laceration_tensile_stress_Pa = 1e12;
  options.limit.limits.contusion_energy_density_J_per_m2 = 1e12;
  options.limit.limits.fracture_force_N = 1e12;  // no fracture either (docs/model.md §7.1)
  const TrajectoryCheck check = CheckTrajectory(Scene{}, SampleMotion(), options);
  CHECK(check.status == TrajectoryCheckStatus::kSafe);
  REQUIRE(check.warnings.size() == 1);
  CHECK_THAT(check.warnings[0], Catch::Contains("lower bound"));
}

TEST_CASE("trajectory check: a failed time-path evaluation leaves the trajectory without a verdict",
          "[trajectory][failure]") {
  Scene braking;  // a braking robot: only the time path answers
  braking.robot.braking_m_per_s2 = 200.0;
  const std::vector<MotionSample> samples = {{0.0, 0.0, 5.0}, {0.1, 0.8, 6.0}, {0.2, 1.2, 7.0}};
  const TrajectoryCheck answered = CheckTrajectory(braking, samples);
  INFO(answered.message);
  REQUIRE(answered.status == TrajectoryCheckStatus::kSafe);  // the scene itself is answerable
  CHECK(answered.failed_sample_count == 0);

  TrajectoryCheckOptions starved;
  starved.limit.oracle.time_path.max_steps = 10;  // the smallest allowed: too few to separate
  const TrajectoryCheck check = CheckTrajectory(braking, samples, starved);
  INFO(check.message);
  CHECK(check.status == TrajectoryCheckStatus::kEvaluationFailed);
  CHECK(std::string(covopt::optim::ToString(check.status)) == "evaluation-failed");
  CHECK(check.failed_sample_count == 2);  // the two moving samples; the one at rest is not judged
  CHECK(check.unsafe_sample_count == 0);  // a failure is not counted as unsafe
  CHECK(check.safe_speed_scale == 0.0);
  CHECK_FALSE(check.worst_sample.has_value());
  CHECK_FALSE(check.samples[0].evaluation_failed);
  for (std::size_t i : {1, 2}) {
    CHECK(check.samples[i].evaluation_failed);
    CHECK_FALSE(check.samples[i].safe);
  }
  CHECK_THAT(check.message, Catch::StartsWith("evaluation failed at 2 of 3 samples"));
  CHECK_THAT(check.message, Catch::Contains("trajectory sample 2 (t = 0.1 s"));
  CHECK_THAT(check.message, Catch::Contains("step-limit"));
}

TEST_CASE("trajectory check: bad samples are rejected naming the sample and the value", "[trajectory]") {
  const auto rejects = [](std::vector<MotionSample> samples, const char* text) {
    INFO(text);
    CHECK_THROWS_WITH(CheckTrajectory(Scene{}, samples), Catch::Contains(text));
  };
  rejects({}, "no samples");
  rejects({{0.0, 1.0, 5.0}, {-0.1, 1.0, 5.0}}, "sample 2: time_s");
  rejects({{0.0, -1.0, 5.0}}, "sample 1: speed_m_per_s");
  rejects({{0.0, std::nan(""), 5.0}}, "speed_m_per_s");
  rejects({{0.0, 101.0, 5.0}}, "in [0, 100] m/s");
  rejects({{0.0, 1.0, 0.0}}, "reflected_mass_kg");
  rejects({{std::nan(""), 1.0, 5.0}}, "time_s");
  Scene fixed_head;
  fixed_head.head.mass_kg = kFixed;
  CHECK_THROWS_WITH(CheckTrajectory(fixed_head, std::vector<MotionSample>{{0.0, 1.0, kInf}}),
                    Catch::Contains("fixed head"));
}
