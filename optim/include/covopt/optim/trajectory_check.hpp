#pragma once
/// @file trajectory_check.hpp
/// Is a robot motion safe, and by how much may it be sped up or must it be slowed down?
///
/// A motion is a sequence of samples, each the speed of the contact point and the robot's
/// reflected mass along its direction of motion (covopt::robot::ContactMotion computes them
/// from a URDF and a joint trajectory; any other source will do). At each sample the check
/// asks two questions of the scene's covering and head:
///   - the impact of the point at that speed and mass: its injury ratios (JudgeImpact: the
///     exact path, or the time path on a scene with braking or a neck);
///   - the largest safe speed at that mass (MaxSafeSpeed, same criterion and safety factor).
/// safe_speed_scale = min over moving samples of (max safe speed / speed). Running the whole
/// trajectory k times faster multiplies every joint velocity, hence every contact speed, by k
/// and leaves every configuration, direction and reflected mass as it is; so the trajectory is
/// safe exactly when k <= safe_speed_scale (> 1: it may be sped up; < 1: it must be slowed).

#include <cstddef>
#include <iterator>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <covopt/core/scene.hpp>
#include <covopt/core/verdict.hpp>

#include "covopt/optim/speed_limit.hpp"

namespace covopt::optim {

/// One sample of a contact point's motion.
struct MotionSample {
  double time_s = 0.0;             ///< [s]
  double speed_m_per_s = 0.0;      ///< contact speed [m/s], in [0, 100]; 0 (or < 1e-6) = at rest
  double reflected_mass_kg = 0.0;  ///< along the motion [kg], > 0; kFixed (+inf) allowed
};

/// The MotionSamples of any sequence of samples that carry time_s, speed_m_per_s and
/// reflected_mass_kg, such as covopt::robot::ContactMotionResult::samples (robot::ContactMotion):
/// `CheckTrajectory(scene, MotionSamples(motion.samples))`. The one adapter from the robot
/// library's motion to the check; a template, so that optim does not depend on covopt::robot.
template <typename Samples>
std::vector<MotionSample> MotionSamples(const Samples& samples) {
  std::vector<MotionSample> motion;
  motion.reserve(std::size(samples));
  for (const auto& s : samples) motion.push_back({s.time_s, s.speed_m_per_s, s.reflected_mass_kg});
  return motion;
}

/// Options of CheckTrajectory.
struct TrajectoryCheckOptions {
  /// The criterion, safety factor and limits of every sample's verdict and speed limit.
  /// Default: SpeedLimitOptions{} (no full compression, safety factor 1, 1 MPa, 2.52 J/cm²).
  SpeedLimitOptions limit;
};

/// The verdict at one sample.
struct SampleVerdict {
  double time_s = 0.0;             ///< [s]
  double speed_m_per_s = 0.0;      ///< [m/s]
  double reflected_mass_kg = 0.0;  ///< [kg] (+inf: fixed)
  /// False when the point is at rest (speed < 1e-6 m/s, the model's lowest): no impact, the
  /// ratios are 0 and the sample does not limit the scale.
  bool moving = false;
  /// The impact at this speed and mass (JudgeImpact); 0 at rest or when the evaluation failed.
  double laceration_ratio = 0.0;   ///< σ_t,max / laceration limit [-]
  double contusion_ratio = 0.0;    ///< e_A,max / contusion limit [-]
  double fracture_ratio = 0.0;     ///< F_max / the struck area's fracture force [-] (docs/model.md §7.1)
  double compression_ratio = 0.0;  ///< δ_max / t2 [-]; 0 without a covering
  /// The impact's verdict (HeadVerdict(scene at this speed and mass, peaks, options.limit)):
  /// injury criteria and the covering's design rules; empty at rest or when it failed.
  Verdict verdict;
  /// The covering's law's validity at this impact (JudgedValidity; within at rest and bare).
  CoveringValidity validity;
  /// verdict.safe(): ratios within 1/safety factor, not crushed and, under the default
  /// criterion, not fully compressed. True at rest.
  bool safe = true;
  /// The time path failed on this sample's impact or on its speed-limit search (a scene with
  /// braking or a neck): the sample has no verdict, its ratios are 0 and safe is false.
  bool evaluation_failed = false;
  /// The largest safe speed at this reflected mass.
  SpeedLimit speed_limit;
  /// max safe speed / speed [-]; +inf at rest.
  double speed_scale = 0.0;
};

/// How a trajectory check ended.
enum class TrajectoryCheckStatus {
  kSafe,    ///< every sample is safe: safe_speed_scale >= 1
  kUnsafe,  ///< some sample is not: the trajectory must be slowed by safe_speed_scale
  kAtRest,  ///< the contact point never moves: nothing to judge
  /// The time path failed at some moving sample: no verdict on the trajectory (message names
  /// the first such sample and the failure; safe_speed_scale is 0, worst_sample empty).
  kEvaluationFailed,
};
/// "safe", "unsafe", "at-rest", "evaluation-failed".
std::string_view ToString(TrajectoryCheckStatus status) noexcept;

/// The answer of CheckTrajectory.
struct TrajectoryCheck {
  TrajectoryCheckStatus status = TrajectoryCheckStatus::kAtRest;
  std::vector<SampleVerdict> samples;
  /// min over moving samples of max safe speed / speed [-]; +inf when at rest throughout.
  /// A lower bound when the sample that sets it is safe up to the search ceiling (100 m/s).
  double safe_speed_scale = 0.0;
  /// The sample that sets safe_speed_scale; empty when at rest throughout.
  std::optional<std::size_t> worst_sample;
  /// The number of moving samples that are not safe as they are.
  std::size_t unsafe_sample_count = 0;
  /// The number of moving samples whose evaluation failed (status kEvaluationFailed).
  std::size_t failed_sample_count = 0;
  /// One sentence: "unsafe: slow the trajectory to 0.73× (worst at t = 0.42 s, ...)".
  std::string message;
  /// What a reader must know (a ceiling-limited scale, samples with no safe speed at all).
  std::vector<std::string> warnings;
  /// The law that describes the covering ("foam", "hertz"; empty bare) and its validity over
  /// the samples: the first moving sample out of it, else the worst sample's (within).
  std::string covering_law;
  CoveringValidity validity;
  /// The message and the worst sample's numbers.
  std::string BriefReport() const;
};

/// Judges every sample of a motion against the scene's covering and head. The scene's robot
/// mass and speed are ignored: each sample brings its own.
/// @throws std::invalid_argument naming the sample (counted from 1) and the value: a non-finite or negative
///         speed, a speed above 100 m/s, a reflected mass that is not > 0, a fixed robot
///         against a fixed head, time going backwards; or as MaxSafeSpeed for the scene and
///         options.
TrajectoryCheck CheckTrajectory(const Scene& scene, std::span<const MotionSample> samples,
                                const TrajectoryCheckOptions& options = {});

}  // namespace covopt::optim
