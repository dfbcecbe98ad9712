// Benchmarks of the whole-robot audit (audit/audit.hpp) on the shipped Franka FR3 along its pick
// move (robot/models/franka_fr3_pick.csv, 101 samples), against every transient body region of
// ISO/TS 15066 (29 areas) and the head (Park et al.): 30 regions, each point wearing a 10 mm
// PORON foam on its capsule's radius. Every run is a whole Audit call (validation, the E*
// precompute per link, radius and region, the pass over the samples).
//   BM_AuditSamplePointFr3    one surface point (on fr3_link7): items = its 101 point-samples,
//                             so the time per item is one audit sample for one point (kinematics,
//                             reflected mass, every region's check), the setup amortised over 101.
//   BM_AuditPickFr3/<n>       <n> surface points spread over every link (0: the whole surface at
//                             0.05 m spacing); the target is 40 points in <= 0.2 s.
//   BM_AuditPickBrakingFr3    the same at 40 points for a robot braking at 200 m/s² 2 ms after
//                             contact: the branch and bound's braked limits on the time path.
//   BM_AuditPickDesignFr3     the same at 40 points with the per-link design over the whole
//                             catalog, and its re-check audit.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

#include <covopt/materials/body_regions.hpp>
#include <covopt/materials/catalog.hpp>
#include <covopt/audit/audit.hpp>
#include <covopt/optim/design.hpp>
#include <covopt/robot/kinematic_chain.hpp>
#include <covopt/robot/surface.hpp>
#include <covopt/robot/trajectory.hpp>

#include "fr3_pick.hpp"

namespace {

/// The FR3's surface at 0.05 m spacing, thinned to `count` points spread evenly over all of
/// them (0: every point); links left without points are dropped.
covopt::robot::RobotSurface Surface(std::size_t count) {
  covopt::robot::RobotSurface surface = covopt::robot::SurfaceFromUrdfFile(kFr3Urdf, Fr3());
  if (count == 0) return surface;
  std::vector<std::pair<std::size_t, std::size_t>> all;
  for (std::size_t l = 0; l < surface.links.size(); ++l) {
    for (std::size_t p = 0; p < surface.links[l].points.size(); ++p) all.emplace_back(l, p);
  }
  std::vector<std::vector<covopt::robot::SurfacePoint>> kept(surface.links.size());
  for (std::size_t i = 0; i < count; ++i) {
    const auto [l, p] = all[i * all.size() / count];
    kept[l].push_back(surface.links[l].points[p]);
  }
  covopt::robot::RobotSurface thinned = surface;
  thinned.links.clear();
  for (std::size_t l = 0; l < surface.links.size(); ++l) {
    if (kept[l].empty()) continue;
    thinned.links.push_back(surface.links[l]);
    thinned.links.back().points = std::move(kept[l]);
  }
  return thinned;
}

void BM_AuditSamplePointFr3(benchmark::State& state) {
  covopt::robot::RobotSurface surface = covopt::robot::SurfaceFromUrdfFile(kFr3Urdf, Fr3());
  covopt::robot::LinkSurface link7 = surface.links.back();
  link7.points = {link7.points.front()};
  surface.links = {link7};
  const covopt::audit::AuditSetup setup = Fr3AuditSetup(surface);
  covopt::audit::AuditOptions options;
  options.keep_ratio_over_time = false;
  for (auto _ : state) benchmark::DoNotOptimize(covopt::audit::Audit(setup, Pick(), options));
  state.SetItemsProcessed(state.iterations() * static_cast<benchmark::IterationCount>(Pick().size()));
  state.counters["regions"] = static_cast<double>(setup.regions.size() + 1);
}
BENCHMARK(BM_AuditSamplePointFr3)->Unit(benchmark::kMicrosecond);

void BM_AuditPickFr3(benchmark::State& state) {
  const covopt::audit::AuditSetup setup = Fr3AuditSetup(Surface(static_cast<std::size_t>(state.range(0))));
  covopt::audit::AuditOptions options;
  options.keep_ratio_over_time = false;
  for (auto _ : state) benchmark::DoNotOptimize(covopt::audit::Audit(setup, Pick(), options));
  state.counters["points"] = static_cast<double>(setup.surface.point_count());
  state.counters["samples"] = static_cast<double>(Pick().size());
  state.counters["regions"] = static_cast<double>(setup.regions.size() + 1);
}
BENCHMARK(BM_AuditPickFr3)->Arg(40)->Arg(0)->Unit(benchmark::kMillisecond);

void BM_AuditPickBrakingFr3(benchmark::State& state) {
  covopt::audit::AuditSetup setup = Fr3AuditSetup(Surface(40));
  setup.reaction_delay_s = 0.002;
  setup.braking_m_per_s2 = 200.0;
  covopt::audit::AuditOptions options;
  options.keep_ratio_over_time = false;
  std::string evaluations;
  for (auto _ : state) {
    const covopt::audit::AuditResult result = covopt::audit::Audit(setup, Pick(), options);
    for (const std::string& w : result.warnings) {
      if (w.find("braked limits") != std::string::npos) evaluations = w.substr(w.find('(') + 1);
      if (w.find("rose with the reflected mass") != std::string::npos) state.SkipWithError(w.c_str());
    }
  }
  state.counters["braked_limits"] = std::stod(evaluations);
}
BENCHMARK(BM_AuditPickBrakingFr3)->Unit(benchmark::kMillisecond);

void BM_AuditPickDesignFr3(benchmark::State& state) {
  const covopt::audit::AuditSetup setup = Fr3AuditSetup(Surface(40));
  covopt::audit::AuditOptions options;
  options.keep_ratio_over_time = false;
  options.design.materials = covopt::optim::SelectCandidates(covopt::materials::Catalog::BuiltIn());
  for (auto _ : state) benchmark::DoNotOptimize(covopt::audit::Audit(setup, Pick(), options));
  state.counters["materials"] = static_cast<double>(options.design.materials.size());
}
BENCHMARK(BM_AuditPickDesignFr3)->Unit(benchmark::kMillisecond);

}  // namespace
