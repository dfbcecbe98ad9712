// The braking robot of `covopt audit` (docs/model.md §14.4): the branch and bound that turns
// every cell's unbraked governing point-sample into the braked one, exactly.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <map>
#include <queue>
#include <utility>
#include <vector>

#include "audit_internal.hpp"

namespace covopt::audit::detail {
namespace {

/// Replaces every cell's unbraked governing point-sample by the braked one, exactly, judging
/// as few point-samples braked as it can.
/// Two upper bounds of a point-sample's braked ratio v/(SF v_b(m)): its unbraked ratio
/// (braking only takes energy out), and v/(SF v_b(m')) for any mass m' >= m judged braked at the
/// same radius (a heavier robot is no safer: v_b does not rise with the mass; where a cell's
/// judged masses contradict that, only the first bound is used there, and a warning says so).
/// Per cell: the braked ratio at the unbraked governing point-sample is a lower bound; a second
/// pass collects the point-samples whose unbraked ratio exceeds it; then, best bound first, a
/// point-sample is judged braked until the best bound is a judged ratio.
class BrakedSearch {
 public:
  BrakedSearch(const AuditSetup& setup, const robot::JointTrajectory& trajectory, const RegionLimits& regions,
               const std::vector<LinkPlan>& plans, std::vector<AuditCell>& cells)
      : setup_(setup), trajectory_(trajectory), regions_(regions), plans_(plans), cells_(cells),
        sf_(setup.rule.safety_factor), candidates_(cells.size()), lower_bound_(cells.size(), 0.0),
        judged_(cells.size()), monotone_(cells.size(), true) {}

  BrakingOutcome Run() {
    if (!FirstCandidates()) return outcome_;
    CollectCandidates();
    for (std::size_t k = 0; k < cells_.size(); ++k) {
      if (candidates_[k].empty()) continue;
      if (!ResolveCell(k)) return outcome_;
      if (!monotone_[k]) ++outcome_.non_monotone_cells;
    }
    return outcome_;
  }

 private:
  struct Judged {
    double max_safe_speed_m_per_s = 0.0;
    BodyLimitKind binding = BodyLimitKind::kNone;
    LimitingCriterion head_criterion = LimitingCriterion::kNone;
  };
  using Key = std::pair<std::uint32_t, double>;  // (radius index, mass [kg])
  struct Candidate {
    double unbraked_ratio = 0.0;
    std::uint32_t radius = 0;
    AuditCell cell;  ///< the point-sample, with its unbraked v_max, ratio and binding
  };

  /// The braked limit of cell k at (radius, mass), judged once; nullptr when the time path failed.
  const Judged* Judge(std::size_t k, std::uint32_t radius, double mass) {
    std::map<Key, Judged>& known = judged_[k];
    const Key key{radius, mass};
    if (const auto it = known.find(key); it != known.end()) return &it->second;
    ++outcome_.evaluations;
    const LinkPlan& plan = plans_[cells_[k].link];
    const BrakedLimit b = regions_.Braked(plan.covering, plan.radii[radius], cells_[k].region, mass);
    if (b.failed) {
      if (!outcome_.failure) outcome_.failure = b.message;
      return nullptr;
    }
    const auto it = known.emplace(key, Judged{b.max_safe_speed_m_per_s, b.binding, b.head_criterion}).first;
    // v_b must not rise with the mass (at one radius): check the neighbours.
    const auto rises = [](const Judged& lighter, const Judged& heavier) {
      return heavier.max_safe_speed_m_per_s > lighter.max_safe_speed_m_per_s * (1.0 + 1e-9);
    };
    if (it != known.begin() && std::prev(it)->first.first == radius && rises(std::prev(it)->second, it->second)) {
      monotone_[k] = false;
    }
    if (std::next(it) != known.end() && std::next(it)->first.first == radius && rises(it->second, std::next(it)->second)) {
      monotone_[k] = false;
    }
    return &it->second;
  }

  /// 1. Each cell's unbraked governing point-sample is the first candidate. false: the time
  /// path failed.
  bool FirstCandidates() {
    for (std::size_t k = 0; k < cells_.size(); ++k) {
      if (!cells_[k].sample) continue;
      const LinkPlan& plan = plans_[cells_[k].link];
      Candidate first{cells_[k].governing_ratio, plan.point_radius[cells_[k].point], cells_[k]};
      const double mass = cells_[k].reflected_mass_kg;
      if (std::isfinite(mass)) {
        const Judged* j = Judge(k, first.radius, mass);
        if (!j) return false;
        lower_bound_[k] = cells_[k].speed_m_per_s / (sf_ * j->max_safe_speed_m_per_s);
      } else {
        lower_bound_[k] = cells_[k].governing_ratio;  // a fixed direction cannot brake
      }
      candidates_[k].push_back(std::move(first));
    }
    return true;
  }

  /// 2. Every other point-sample whose unbraked ratio exceeds its cell's lower bound.
  void CollectCandidates() {
    const std::size_t n_regions = regions_.size();
    std::vector<double> inverse_body_mass(n_regions);
    for (std::size_t r = 0; r < n_regions; ++r) inverse_body_mass[r] = regions_.inverse_body_mass(r);
    const Exposure& exposure = regions_.exposure();
    std::vector<std::uint8_t> exposed(n_regions, 1);
    const auto on_point = [&](std::size_t i, std::size_t l, std::size_t p, const robot::PointMotion& m) {
      if (!exposure.everywhere() && !exposure.At(m.position_m, exposed)) return;  // in no zone: not judged
      const LinkPlan& plan = plans_[l];
      const double v = m.speed_m_per_s;
      const EnergyLimit* limits = &plan.limits[plan.point_radius[p] * n_regions];
      for (std::size_t r = 0; r < n_regions; ++r) {
        const std::size_t k = l * n_regions + r;
        if (!exposed[r]) continue;
        if (!cells_[k].sample || (i == *cells_[k].sample && p == cells_[k].point)) continue;  // judged in 1.
        const double v_max = MaxSpeed(limits[r], 1.0 / m.reflected_mass_kg + inverse_body_mass[r]);
        const double ratio = v / (sf_ * v_max);
        if (!(ratio > lower_bound_[k])) continue;
        Candidate c{ratio, plan.point_radius[p], cells_[k]};
        c.cell.governing_ratio = ratio;
        c.cell.speed_scale = v_max / v;
        c.cell.max_safe_speed_m_per_s = v_max;
        c.cell.binding = v_max < kModelMaxSpeed_m_per_s ? limits[r].binding : BodyLimitKind::kNone;
        c.cell.head_criterion = v_max < kModelMaxSpeed_m_per_s ? limits[r].head_criterion : LimitingCriterion::kNone;
        c.cell.sample = i;
        c.cell.time_s = trajectory_.time_s[i];
        c.cell.point = p;
        c.cell.point_in_link_m = plan.surface->points[p].position_m;
        c.cell.point_in_base_m = m.position_m;
        c.cell.speed_m_per_s = v;
        c.cell.reflected_mass_kg = m.reflected_mass_kg;
        candidates_[k].push_back(std::move(c));
      }
    };
    Walk(setup_, trajectory_, plans_, on_point, [](std::size_t, double) {});
  }

  /// A coarse mass grid per radius (4 per decade over the candidates' masses) tightens every
  /// bound of cell k at the cost of a few braked limits, when there are many candidates.
  /// false: the time path failed.
  bool JudgeMassGrid(std::size_t k) {
    const std::vector<Candidate>& list = candidates_[k];
    if (list.size() <= 16) return true;
    std::map<std::uint32_t, std::pair<double, double>> range;  // radius -> lightest, heaviest
    for (const Candidate& c : list) {
      const double m = c.cell.reflected_mass_kg;
      if (!std::isfinite(m)) continue;
      auto [it, inserted] = range.try_emplace(c.radius, m, m);
      if (!inserted) it->second = {std::min(it->second.first, m), std::max(it->second.second, m)};
    }
    for (const auto& [radius, masses] : range) {
      const int steps = static_cast<int>(std::ceil(4.0 * std::log10(masses.second / masses.first)));
      for (int j = 0; j <= steps; ++j) {
        const double m = j == steps ? masses.second : masses.first * std::pow(10.0, j / 4.0);
        if (!Judge(k, radius, m)) return false;
      }
    }
    return true;
  }

  /// The bound of candidate c of cell k, and whether it is its judged braked ratio.
  std::pair<double, bool> Bound(std::size_t k, const Candidate& c) const {
    const double m = c.cell.reflected_mass_kg;
    if (!std::isfinite(m)) return {c.unbraked_ratio, true};
    const std::map<Key, Judged>& known = judged_[k];
    const auto it = known.lower_bound(Key{c.radius, m});
    if (it == known.end() || it->first.first != c.radius) return {c.unbraked_ratio, false};
    const double ratio = c.cell.speed_m_per_s / (sf_ * it->second.max_safe_speed_m_per_s);
    if (it->first.second == m) return {ratio, true};
    if (!monotone_[k]) return {c.unbraked_ratio, false};
    return {std::min(c.unbraked_ratio, ratio), false};
  }

  /// 3. Cell k, best bound first. false: the time path failed.
  bool ResolveCell(std::size_t k) {
    if (!JudgeMassGrid(k)) return false;
    std::vector<Candidate>& list = candidates_[k];
    // Max-heap on the bound; ties: the earlier point-sample first.
    using Entry = std::pair<double, std::size_t>;
    const auto lower = [](const Entry& a, const Entry& b) {
      return a.first < b.first || (a.first == b.first && a.second > b.second);
    };
    std::priority_queue<Entry, std::vector<Entry>, decltype(lower)> heap(lower);
    const auto fill = [&] {
      while (!heap.empty()) heap.pop();
      for (std::size_t i = 0; i < list.size(); ++i) heap.emplace(Bound(k, list[i]).first, i);
    };
    fill();
    while (true) {
      const auto [top, i] = heap.top();
      heap.pop();
      const auto [now, exact] = Bound(k, list[i]);
      if (now < top) {  // tightened since it was pushed
        heap.emplace(now, i);
        continue;
      }
      if (exact) {  // no other bound is higher: this is the cell's braked governing ratio
        Candidate& c = list[i];
        if (!std::isfinite(c.cell.reflected_mass_kg)) {
          ++outcome_.fixed_direction_points;
        } else {
          const Judged& j = judged_[k].at(Key{c.radius, c.cell.reflected_mass_kg});
          c.cell.max_safe_speed_m_per_s = j.max_safe_speed_m_per_s;
          c.cell.governing_ratio = now;
          c.cell.speed_scale = j.max_safe_speed_m_per_s / c.cell.speed_m_per_s;
          c.cell.binding = j.binding;
          c.cell.head_criterion = j.head_criterion;
        }
        cells_[k] = c.cell;
        return true;
      }
      const bool was_monotone = monotone_[k];
      if (!Judge(k, list[i].radius, list[i].cell.reflected_mass_kg)) return false;
      if (was_monotone && !monotone_[k]) {
        fill();  // the mass bounds no longer hold: every key back to what stands without them
      } else {
        heap.emplace(Bound(k, list[i]).first, i);
      }
    }
  }

  const AuditSetup& setup_;
  const robot::JointTrajectory& trajectory_;
  const RegionLimits& regions_;
  const std::vector<LinkPlan>& plans_;
  std::vector<AuditCell>& cells_;
  const double sf_;
  BrakingOutcome outcome_;
  std::vector<std::vector<Candidate>> candidates_;
  std::vector<double> lower_bound_;
  std::vector<std::map<Key, Judged>> judged_;
  std::vector<bool> monotone_;
};

}  // namespace

BrakingOutcome ApplyBraking(const AuditSetup& setup, const robot::JointTrajectory& trajectory,
                            const RegionLimits& regions, const std::vector<LinkPlan>& plans,
                            std::vector<AuditCell>& cells) {
  return BrakedSearch(setup, trajectory, regions, plans, cells).Run();
}

}  // namespace covopt::audit::detail
