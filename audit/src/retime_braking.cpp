// The braking robot's per-sample safe path speed for Retime (docs/model.md, "Re-timing"): a
// sample's braked scale is the minimum over its point-samples and regions of v_b(m)/v, found by
// branch and bound as the audit's braked cells are (audit_braking.cpp), over the regions each
// point's exposure zone exposes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <functional>
#include <map>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

#include "retime_internal.hpp"

namespace covopt::audit::detail {
namespace {

/// Per sample, the braked robot's safe speed scale, exactly, judging as few point-samples braked
/// as it can. Two lower bounds of a point-sample's braked scale v_b(m)/v: its unbraked scale
/// v_max(m)/v (braking only takes energy out), and v_b(m')/v for a mass m' >= m judged braked at
/// the same link, radius and region (a heavier robot is no safer; a grid of 16 masses per decade,
/// judged once for all samples; where judged masses contradict it, only the first bound is used
/// there). Per sample, best bound first: the point-sample on top has its bound tightened (the
/// grid's, then its own braked judgement) until the one on top is judged: no other can be lower.
class SampleBrakedSearch {
 public:
  SampleBrakedSearch(const AuditSetup& setup, const RegionLimits& regions, const std::vector<LinkPlan>& plans)
      : setup_(setup), regions_(regions), plans_(plans) {}

  /// Raises `safe` (the unbraked per-sample limits) to the braked ones.
  void Run(const robot::JointTrajectory& trajectory, SafePathSpeed& safe) {
    const std::size_t n_regions = regions_.size();
    const Exposure& exposure = regions_.exposure();
    std::vector<std::uint8_t> exposed(n_regions, 1);
    const auto on_point = [&](std::size_t, std::size_t l, std::size_t p, const robot::PointMotion& m) {
      if (!exposure.everywhere() && !exposure.At(m.position_m, exposed)) return;  // in no zone: not judged
      const LinkPlan& plan = plans_[l];
      const EnergyLimit* limits = &plan.limits[plan.point_radius[p] * n_regions];
      for (std::size_t r = 0; r < n_regions; ++r) {
        if (!exposed[r]) continue;
        const double v_max = MaxSpeed(limits[r], 1.0 / m.reflected_mass_kg + regions_.inverse_body_mass(r));
        candidates_.push_back(
            Candidate{v_max / m.speed_m_per_s, m.speed_m_per_s, m.reflected_mass_kg, l, plan.point_radius[p], r});
      }
    };
    const auto on_sample = [&](std::size_t i, double) {
      if (!failure_) Resolve(i, safe);
      candidates_.clear();
    };
    Walk(setup_, trajectory, plans_, on_point, on_sample);
    safe.failure = failure_;
    safe.warnings.push_back("braking: each sample's safe path speed is the braked robot's (" +
                            std::to_string(evaluations_) + " braked limits on the time path)");
  }

 private:
  struct Candidate {
    double unbraked_scale = 0.0;
    double speed_m_per_s = 0.0;
    double mass_kg = 0.0;
    std::size_t link = 0;
    std::uint32_t radius = 0;
    std::size_t region = 0;
  };
  using Key = std::tuple<std::size_t, std::uint32_t, std::size_t>;  // link, radius, region
  static constexpr double kGridPerDecade = 16.0;

  /// v_b at (key, mass), judged once; nullopt when the time path failed.
  std::optional<double> Braked(const Key& key, double mass_kg) {
    std::map<double, double>& known = judged_[key];
    if (const auto it = known.find(mass_kg); it != known.end()) return it->second;
    const auto [l, radius, r] = key;
    ++evaluations_;
    const BrakedLimit b = regions_.Braked(plans_[l].covering, plans_[l].radii[radius], r, mass_kg);
    if (b.failed) {
      if (!failure_) failure_ = "the time path of the braking robot did not answer (" + b.message + ")";
      return std::nullopt;
    }
    const auto it = known.emplace(mass_kg, b.max_safe_speed_m_per_s).first;
    // v_b must not rise with the mass: check the neighbours.
    const auto rises = [](double lighter, double heavier) { return heavier > lighter * (1.0 + 1e-9); };
    if ((it != known.begin() && rises(std::prev(it)->second, it->second)) ||
        (std::next(it) != known.end() && rises(it->second, std::next(it)->second))) {
      non_monotone_[key] = true;
    }
    return it->second;
  }

  /// The grid's lower bound of a candidate's braked scale (its unbraked scale where none holds).
  std::optional<double> LowerBound(const Candidate& c) {
    const Key key{c.link, c.radius, c.region};
    if (non_monotone_[key]) return c.unbraked_scale;
    const double heavier = std::pow(10.0, std::ceil(kGridPerDecade * std::log10(c.mass_kg)) / kGridPerDecade);
    const std::optional<double> v_b = Braked(key, std::max(heavier, c.mass_kg));
    if (!v_b) return std::nullopt;
    if (non_monotone_[key]) return c.unbraked_scale;
    return std::max(c.unbraked_scale, *v_b / c.speed_m_per_s);
  }

  /// Sample i's braked scale, best bound first: a candidate's bound goes from its unbraked scale
  /// to the grid's bound to its judged braked scale; the first judged one on top is the minimum.
  void Resolve(std::size_t i, SafePathSpeed& safe) {
    enum Stage : int { kUnbraked = 0, kGrid = 1, kJudged = 2 };
    std::vector<std::pair<double, int>> state(candidates_.size());  // bound, stage
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap;
    const auto fill = [&] {
      heap = {};
      for (std::size_t k = 0; k < state.size(); ++k) heap.emplace(state[k].first, k);
    };
    for (std::size_t k = 0; k < candidates_.size(); ++k) {
      const Candidate& c = candidates_[k];
      state[k] = {c.unbraked_scale, std::isfinite(c.mass_kg) ? kUnbraked : kJudged};  // a fixed direction cannot brake
    }
    fill();
    while (!heap.empty()) {
      const auto [bound, k] = heap.top();
      heap.pop();
      if (bound != state[k].first) continue;  // superseded
      const Candidate& c = candidates_[k];
      const Key key{c.link, c.radius, c.region};
      if (state[k].second == kJudged) {
        // v_b/v is the scale (v_b carries the safety factor, as the cells' speed_scale); at least
        // the unbraked bound.
        safe.speed[i] = std::max(safe.speed[i], bound);
        safe.link[i] = c.link;
        safe.region[i] = c.region;
        return;
      }
      const bool was_monotone = !non_monotone_[key];
      std::optional<double> next;
      if (state[k].second == kUnbraked) {
        next = LowerBound(c);
      } else if (const std::optional<double> v_b = Braked(key, c.mass_kg)) {
        next = *v_b / c.speed_m_per_s;
      }
      if (!next) return;  // the time path failed
      state[k] = {std::max(*next, c.unbraked_scale), state[k].second + 1};
      if (was_monotone && non_monotone_[key]) {
        // The grid's bounds of this key no longer hold: back to the unbraked ones.
        for (std::size_t j = 0; j < state.size(); ++j) {
          const Candidate& o = candidates_[j];
          if (state[j].second == kGrid && Key{o.link, o.radius, o.region} == key) {
            state[j] = {o.unbraked_scale, kUnbraked};
          }
        }
        fill();
      } else {
        heap.emplace(state[k].first, k);
      }
    }
  }

  const AuditSetup& setup_;
  const RegionLimits& regions_;
  const std::vector<LinkPlan>& plans_;
  std::vector<Candidate> candidates_;
  std::map<Key, std::map<double, double>> judged_;
  std::map<Key, bool> non_monotone_;
  std::size_t evaluations_ = 0;
  std::optional<std::string> failure_;
};

}  // namespace

SafePathSpeed SafePathSpeedFor(const AuditSetup& setup, const robot::JointTrajectory& trajectory,
                               bool keep_ratio_over_time, AuditResult& audit) {
  SafePathSpeed safe = SafePathSpeedOf(setup, trajectory, keep_ratio_over_time, audit);
  if (!(setup.braking_m_per_s2 > 0.0) || audit.status == optim::TrajectoryCheckStatus::kEvaluationFailed) {
    return safe;
  }
  const RegionLimits regions(setup);
  AuditResult names;
  const std::vector<LinkPlan> plans = PlanLinks(setup, regions, names);
  SampleBrakedSearch(setup, regions, plans).Run(trajectory, safe);
  return safe;
}

}  // namespace covopt::audit::detail
