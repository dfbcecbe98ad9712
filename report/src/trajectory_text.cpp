#include "covopt/report/trajectory_text.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ostream.h>

namespace covopt::report {
namespace {

/// The table lists every sample of a trajectory this short; a longer one, its worst ones.
constexpr std::size_t kListAllUpTo = 20;
/// How many of the worst samples the table shows at least, and at most (unsafe ones).
constexpr std::size_t kWorstShown = 10;
constexpr std::size_t kMostShown = 30;

std::string MassText(double kg) { return std::isinf(kg) ? std::string("fixed") : fmt::format("{:.4g}", kg); }

/// The samples the table shows: all of a short trajectory; else the kWorstShown moving
/// samples with the smallest speed scale and every unsafe one, at most kMostShown, in time
/// order.
std::vector<std::size_t> ShownSamples(const optim::TrajectoryCheck& check) {
  std::vector<std::size_t> shown(check.samples.size());
  std::iota(shown.begin(), shown.end(), std::size_t{0});
  if (check.samples.size() <= kListAllUpTo) return shown;
  std::erase_if(shown, [&](std::size_t i) { return !check.samples[i].moving; });
  std::stable_sort(shown.begin(), shown.end(), [&](std::size_t a, std::size_t b) {
    return check.samples[a].speed_scale < check.samples[b].speed_scale;
  });
  shown.resize(std::min(shown.size(), std::max(kWorstShown, std::min(check.unsafe_sample_count, kMostShown))));
  std::sort(shown.begin(), shown.end());
  return shown;
}

std::string MaxSafeText(const optim::SampleVerdict& v) {
  switch (v.speed_limit.status) {
    case optim::SpeedLimitStatus::kNoSafeValue: return "none safe";
    case optim::SpeedLimitStatus::kEvaluationFailed: return "evaluation failed";
    case optim::SpeedLimitStatus::kSafeUpToSearchLimit:
      return fmt::format(">= {:.4g}", v.speed_limit.max_safe_speed_m_per_s);
    case optim::SpeedLimitStatus::kLimited: break;
  }
  return fmt::format("{:.4g}", v.speed_limit.max_safe_speed_m_per_s);
}

}  // namespace

void PrintTrajectorySamples(std::ostream& out, const optim::TrajectoryCheck& check) {
  const std::vector<std::size_t> shown = ShownSamples(check);
  fmt::print(out, "  {:>5}  {:>9}  {:>11}  {:>9}  {:>14}  {:>8}  {:<16}  {:>10}  {:>9}  {:>11}  {}\n", "index",
             "time [s]", "speed [m/s]", "mass [kg]", "max safe [m/s]", "scale", "limited by", "laceration",
             "contusion", "compression", "safe");
  for (const std::size_t i : shown) {
    const optim::SampleVerdict& v = check.samples[i];
    const std::string scale = v.moving ? fmt::format("{:.4g}", v.speed_scale) : std::string("-");
    const std::string compression =
        v.compression_ratio > 0.0 ? fmt::format("{:.3f}", v.compression_ratio) : std::string("-");
    fmt::print(out, "  {:>5}  {:>9.4g}  {:>11.4g}  {:>9}  {:>14}  {:>8}  {:<16}  {:>10.3f}  {:>9.3f}  {:>11}  {}\n", i,
               v.time_s, v.speed_m_per_s, MassText(v.reflected_mass_kg), MaxSafeText(v), scale,
               optim::ToString(v.speed_limit.limited_by), v.laceration_ratio, v.contusion_ratio, compression,
               !v.moving ? "at rest" : v.safe ? "yes" : "NO");
  }
  if (shown.size() < check.samples.size()) {
    fmt::print(out,
               "  ({} of {} samples: the {} moving ones with the smallest speed scale, every unsafe one up to {}, "
               "in time order; all in --json and --csv)\n",
               shown.size(), check.samples.size(), kWorstShown, kMostShown);
  }
}

void PrintWorstSample(std::ostream& out, const optim::TrajectoryCheck& check) {
  if (check.worst_sample) {
    const optim::SampleVerdict& w = check.samples[*check.worst_sample];
    fmt::print(out,
               "Worst      sample {} at t = {:.4g} s: speed {:.4g} m/s, reflected mass {}{}, max safe speed {}{}\n",
               *check.worst_sample, w.time_s, w.speed_m_per_s, MassText(w.reflected_mass_kg),
               std::isinf(w.reflected_mass_kg) ? "" : " kg", MaxSafeText(w),
               w.speed_limit.status == optim::SpeedLimitStatus::kNoSafeValue ? "" : " m/s");
  }
  if (!check.covering_law.empty()) {
    fmt::print(out, "Law        covering law {}, {}: {}\n", check.covering_law,
               check.validity.within ? "within its validity" : "OUT of its validity", check.validity.note);
  }
}

void PrintBodyRegionSamples(std::ostream& out, const optim::BodyRegionTrajectoryCheck& check,
                            const std::vector<materials::BodyLimits>& iso) {
  fmt::print(out, "\n  {:>9} {:>10} {:>10} {:>8}  {:<16} {:<34} {:>11} {:>8}\n", "t [s]", "speed m/s", "mass kg",
             "worst", "binds", "where", "max safe", "scale");
  // Up to 20 samples: all; else the 10 moving samples with the smallest scale, in time order.
  std::vector<std::size_t> shown(check.samples.size());
  std::iota(shown.begin(), shown.end(), std::size_t{0});
  if (shown.size() > 20) {
    std::erase_if(shown, [&](std::size_t i) { return !check.samples[i].moving; });
    std::sort(shown.begin(), shown.end(), [&](std::size_t a, std::size_t b) {
      return check.samples[a].speed_scale < check.samples[b].speed_scale;
    });
    if (shown.size() > 10) shown.resize(10);
    std::sort(shown.begin(), shown.end());
  }
  for (const std::size_t i : shown) {
    const optim::BodyRegionSampleVerdict& v = check.samples[i];
    const materials::BodyLimits& worst = iso[v.worst_region];
    fmt::print(out, "  {:>9.4g} {:>10.4g} {:>10} {:>8.3f}  {:<16} {:<34} {:>11} {:>8}\n", v.time_s, v.speed_m_per_s,
               MassText(v.reflected_mass_kg), v.worst_ratio, v.moving ? optim::ToString(v.binding) : "-",
               v.moving ? worst.region->name + " (" + worst.area->name + ")" : "at rest",
               v.moving ? fmt::format("{:.4g}", v.max_safe_speed_m_per_s) : "-",
               v.moving ? fmt::format("{:.3f}", v.speed_scale) : "-");
  }
}

}  // namespace covopt::report
