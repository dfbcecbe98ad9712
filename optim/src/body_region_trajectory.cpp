#include "covopt/optim/body_region_trajectory.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <covopt/core/number_format.hpp>

namespace covopt::optim {
namespace {

constexpr double kRestSpeed = 1e-6;  // [m/s] the model's lowest speed (as CheckTrajectory)

std::string RegionName(const materials::BodyLimits& limits) {
  return limits.region->name + " (" + limits.area->name + ")";
}

}  // namespace

BodyRegionTrajectoryCheck CheckTrajectoryForBodyRegions(const BodyContactScene& scene,
                                                        std::span<const materials::BodyLimits> regions,
                                                        std::span<const MotionSample> samples,
                                                        const BodyRegionOptions& options) {
  if (regions.empty()) throw std::invalid_argument("regions: at least one body region is needed");
  BodyRegionTrajectoryCheck check;
  check.safe_speed_scale = std::numeric_limits<double>::infinity();
  double previous_time = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const MotionSample& s = samples[i];
    if (!std::isfinite(s.time_s) || s.time_s < previous_time) {
      throw std::invalid_argument("sample " + std::to_string(i + 1) + ": time " + FormatShortest(s.time_s) +
                                  " s goes backwards or is not finite");
    }
    previous_time = s.time_s;
    if (!(s.speed_m_per_s >= 0.0) || s.speed_m_per_s > 100.0) {
      throw std::invalid_argument("sample " + std::to_string(i + 1) + ": speed must be in [0, 100] m/s (got " +
                                  FormatShortest(s.speed_m_per_s) + ")");
    }
    if (!(s.reflected_mass_kg > 0.0)) {
      throw std::invalid_argument("sample " + std::to_string(i + 1) + ": reflected mass must be > 0 kg (got " +
                                  FormatShortest(s.reflected_mass_kg) + ")");
    }
    BodyRegionSampleVerdict v;
    v.time_s = s.time_s;
    v.speed_m_per_s = s.speed_m_per_s;
    v.reflected_mass_kg = s.reflected_mass_kg;
    v.moving = s.speed_m_per_s >= kRestSpeed;
    if (!v.moving) {
      v.speed_scale = std::numeric_limits<double>::infinity();
      check.samples.push_back(v);
      continue;
    }
    BodyContactScene at = scene;
    at.robot_mass_kg = s.reflected_mass_kg;
    at.speed_m_per_s = s.speed_m_per_s;
    v.max_safe_speed_m_per_s = std::numeric_limits<double>::infinity();
    for (std::size_t r = 0; r < regions.size(); ++r) {
      const BodyRegionJudgement judged = JudgeBodyContact(at, regions[r], options);
      if (r == 0 || judged.governing_ratio > v.worst_ratio) {
        v.worst_ratio = judged.governing_ratio;
        v.binding = judged.governing;
        v.worst_region = r;
      }
      v.safe = v.safe && judged.admissible;
      const BodyRegionSpeedLimit limit = MaxSafeSpeed(at, regions[r], options);
      if (limit.max_safe_speed_m_per_s < v.max_safe_speed_m_per_s) {
        v.max_safe_speed_m_per_s = limit.max_safe_speed_m_per_s;
        v.limiting_region = r;
        v.limited_by = limit.limited_by;
      }
    }
    v.speed_scale = v.max_safe_speed_m_per_s / v.speed_m_per_s;
    if (!v.safe) ++check.unsafe_sample_count;
    if (!check.worst_sample || v.speed_scale < check.safe_speed_scale) {
      check.safe_speed_scale = v.speed_scale;
      check.worst_sample = i;
    }
    check.samples.push_back(v);
  }
  if (!check.worst_sample) {
    check.status = TrajectoryCheckStatus::kAtRest;
    check.message = "at rest: the contact point never moves";
    return check;
  }
  const BodyRegionSampleVerdict& w = check.samples[*check.worst_sample];
  const std::string where = "worst at t = " + FormatSignificant(w.time_s, 4) + " s: " +
                            RegionName(regions[w.limiting_region]) + ", " + std::string(ToString(w.limited_by));
  if (check.unsafe_sample_count == 0 && check.safe_speed_scale >= 1.0) {
    check.status = TrajectoryCheckStatus::kSafe;
    check.message = "safe: every sample within every region's limits; speed scale " +
                    FormatSignificant(check.safe_speed_scale, 4) + " (" + where + ")";
  } else {
    check.status = TrajectoryCheckStatus::kUnsafe;
    check.message = "unsafe: " + std::to_string(check.unsafe_sample_count) + " sample" +
                    (check.unsafe_sample_count == 1 ? " exceeds" : "s exceed") +
                    " a region's limits; slow the trajectory to " + FormatSignificant(check.safe_speed_scale, 4) +
                    "× (" + where + ")";
  }
  return check;
}

}  // namespace covopt::optim
