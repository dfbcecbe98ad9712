// A motion judged sample by sample (optim/trajectory_check.hpp): the impact at each sample's
// speed and reflected mass, and the largest safe speed there.
#include "covopt/optim/trajectory_check.hpp"
#include "covopt/optim/verdicts.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <covopt/core/number_format.hpp>

namespace covopt::optim {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
/// The model's lowest and highest impact speeds [m/s] (docs/model.md §7).
constexpr double kLowestSpeed_m_per_s = 1e-6;
constexpr double kHighestSpeed_m_per_s = 100.0;

[[noreturn]] void RejectSample(std::size_t index, const std::string& what, double value,
                               const std::string& requirement) {
  throw std::invalid_argument("trajectory sample " + std::to_string(index + 1) + ": " + what + " " +
                              FormatSignificant(value, 17) + " must be " + requirement);
}

void CheckSample(const MotionSample& sample, std::size_t index, const MotionSample* previous,
                 const Scene& scene) {
  if (!std::isfinite(sample.time_s)) RejectSample(index, "time_s", sample.time_s, "finite");
  if (previous != nullptr && sample.time_s < previous->time_s) {
    RejectSample(index, "time_s", sample.time_s,
                 ">= the previous sample's " + FormatSignificant(previous->time_s, 17) + " s");
  }
  if (!(sample.speed_m_per_s >= 0.0 && sample.speed_m_per_s <= kHighestSpeed_m_per_s)) {
    RejectSample(index, "speed_m_per_s", sample.speed_m_per_s, "in [0, 100] m/s");
  }
  if (!(sample.reflected_mass_kg > 0.0)) {
    RejectSample(index, "reflected_mass_kg", sample.reflected_mass_kg, "> 0 kg (or +inf: fixed)");
  }
  if (std::isinf(sample.reflected_mass_kg) && std::isinf(scene.head.mass_kg)) {
    throw std::invalid_argument("trajectory sample " + std::to_string(index + 1) +
                                ": a fixed reflected mass against a fixed head (head.mass_kg) has no "
                                "impact model: give the head a finite mass");
  }
}

std::string TimeText(double time_s) { return "t = " + FormatSignificant(time_s, 6) + " s"; }

}  // namespace

std::string_view ToString(TrajectoryCheckStatus status) noexcept {
  switch (status) {
    case TrajectoryCheckStatus::kSafe: return "safe";
    case TrajectoryCheckStatus::kUnsafe: return "unsafe";
    case TrajectoryCheckStatus::kAtRest: return "at-rest";
    case TrajectoryCheckStatus::kEvaluationFailed: return "evaluation-failed";
  }
  return "unknown";
}

std::string TrajectoryCheck::BriefReport() const {
  std::string report = message;
  if (worst_sample) {
    const SampleVerdict& worst = samples[*worst_sample];
    report += "\nworst sample: " + std::to_string(*worst_sample + 1) + " of " + std::to_string(samples.size()) +
              " (" + TimeText(worst.time_s) + "): speed " + FormatSignificant(worst.speed_m_per_s, 4) + " m/s, reflected mass " +
              (std::isinf(worst.reflected_mass_kg) ? std::string("fixed")
                                                   : FormatSignificant(worst.reflected_mass_kg, 4) + " kg") +
              ", " + worst.speed_limit.message + ", laceration ratio " +
              FormatSignificant(worst.laceration_ratio, 4) + ", contusion ratio " +
              FormatSignificant(worst.contusion_ratio, 4);
  }
  return report;
}

namespace {

/// A moving sample's ratios, validity and verdict from its impact's judgement.
void SetJudgement(const Scene& at, const ImpactJudgement& judgement, const SpeedLimitOptions& options,
                  SampleVerdict& verdict) {
  verdict.laceration_ratio = judgement.ratios.laceration_ratio;
  verdict.contusion_ratio = judgement.ratios.contusion_ratio;
  verdict.fracture_ratio = judgement.ratios.fracture_ratio;
  verdict.compression_ratio = judgement.ratios.compression_ratio;
  verdict.validity = judgement.validity;
  verdict.verdict = HeadVerdict(at, judgement.peaks, options, &judgement.validity);
}

/// The check's covering law and its validity over the samples (TrajectoryCheck::validity).
void SetCoveringLaw(const Scene& scene, TrajectoryCheck& check) {
  if (!(scene.covering.thickness_m > 0.0)) return;
  check.covering_law = std::string(covopt::ToString(ImpactModel::FromScene(scene).covering_law()));
  const auto out = std::find_if(check.samples.begin(), check.samples.end(),
                                [](const SampleVerdict& s) { return s.moving && !s.validity.within; });
  if (out != check.samples.end()) {
    check.validity = out->validity;
  } else if (check.worst_sample) {
    check.validity = check.samples[*check.worst_sample].validity;
  }
}

}  // namespace

TrajectoryCheck CheckTrajectory(const Scene& scene, std::span<const MotionSample> samples,
                                const TrajectoryCheckOptions& options) {
  if (samples.empty()) throw std::invalid_argument("trajectory: no samples");
  for (std::size_t i = 0; i < samples.size(); ++i) {
    CheckSample(samples[i], i, i > 0 ? &samples[i - 1] : nullptr, scene);
  }

  TrajectoryCheck check;
  check.samples.reserve(samples.size());
  check.safe_speed_scale = kInfinity;
  bool scale_set_by_ceiling = false;
  std::size_t no_safe_speed_count = 0;
  std::string first_failure;  ///< what failed at the first failed sample
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const MotionSample& sample = samples[i];
    SampleVerdict verdict;
    verdict.time_s = sample.time_s;
    verdict.speed_m_per_s = sample.speed_m_per_s;
    verdict.reflected_mass_kg = sample.reflected_mass_kg;
    verdict.moving = sample.speed_m_per_s >= kLowestSpeed_m_per_s;

    Scene at = scene;
    at.robot.mass_kg = sample.reflected_mass_kg;
    verdict.speed_limit = MaxSafeSpeed(at, options.limit);
    if (verdict.moving) {
      at.robot.speed_m_per_s = sample.speed_m_per_s;
      const ImpactJudgement judgement = JudgeImpact(at, options.limit);
      if (judgement.failed || verdict.speed_limit.status == SpeedLimitStatus::kEvaluationFailed) {
        // No verdict: neither "unsafe" nor a speed scale of 0 may stand for a failed run.
        verdict.evaluation_failed = true;
        verdict.safe = false;
        verdict.speed_scale = 0.0;
        if (check.failed_sample_count++ == 0) {
          first_failure = "trajectory sample " + std::to_string(i + 1) + " (" + TimeText(sample.time_s) +
                          ", speed " + FormatSignificant(sample.speed_m_per_s, 4) + " m/s): " +
                          (verdict.speed_limit.status == SpeedLimitStatus::kEvaluationFailed
                               ? verdict.speed_limit.message
                               : std::string("the time path failed on the impact at this speed"));
        }
        check.samples.push_back(verdict);
        continue;
      }
      SetJudgement(at, judgement, options.limit, verdict);
      verdict.safe = verdict.verdict.safe();
      verdict.speed_scale = verdict.speed_limit.max_safe_speed_m_per_s / sample.speed_m_per_s;
      if (!verdict.safe) ++check.unsafe_sample_count;
      if (verdict.speed_limit.status == SpeedLimitStatus::kNoSafeValue) ++no_safe_speed_count;
      if (verdict.speed_scale < check.safe_speed_scale || !check.worst_sample) {
        check.safe_speed_scale = verdict.speed_scale;
        check.worst_sample = i;
        scale_set_by_ceiling = verdict.speed_limit.status == SpeedLimitStatus::kSafeUpToSearchLimit;
      }
    } else {
      verdict.speed_scale = kInfinity;
    }
    check.samples.push_back(verdict);
  }

  SetCoveringLaw(scene, check);
  if (check.failed_sample_count > 0) {
    check.status = TrajectoryCheckStatus::kEvaluationFailed;
    check.safe_speed_scale = 0.0;
    check.worst_sample.reset();
    check.message = "evaluation failed at " + std::to_string(check.failed_sample_count) + " of " +
                    std::to_string(check.samples.size()) + " samples, no verdict on the trajectory; first: " +
                    first_failure;
    return check;
  }
  if (!check.worst_sample) {
    check.status = TrajectoryCheckStatus::kAtRest;
    check.message = "the contact point never moves (every speed < 1e-06 m/s): no impact to judge";
    return check;
  }
  const SampleVerdict& worst = check.samples[*check.worst_sample];
  check.status = check.unsafe_sample_count == 0 ? TrajectoryCheckStatus::kSafe : TrajectoryCheckStatus::kUnsafe;
  const std::string scale = FormatSignificant(check.safe_speed_scale, 4);
  if (check.status == TrajectoryCheckStatus::kSafe) {
    check.message = "safe: the trajectory may run up to " + scale + "x faster (set by " +
                    TimeText(worst.time_s) + ", " + std::string(ToString(worst.speed_limit.limited_by)) + ")";
  } else {
    check.message = "unsafe at " + std::to_string(check.unsafe_sample_count) + " of " +
                    std::to_string(check.samples.size()) + " samples: slow the trajectory to " + scale +
                    "x (set by " + TimeText(worst.time_s) + ", " + std::string(ToString(worst.speed_limit.limited_by)) + ")";
  }
  if (scale_set_by_ceiling) {
    check.warnings.push_back("the speed scale " + scale + " is a lower bound: at " + TimeText(worst.time_s) +
                             " the impact is safe up to the model's " +
                             FormatSignificant(worst.speed_limit.max_safe_speed_m_per_s, 6) +
                             " m/s ceiling, the search limit");
  }
  if (no_safe_speed_count > 0) {
    check.warnings.push_back(std::to_string(no_safe_speed_count) +
                             " moving sample(s) have no safe speed at all at their reflected mass: "
                             "no slowing makes them safe; change the covering");
  }
  return check;
}

}  // namespace covopt::optim
