// Benchmarks of ChainSampleKinematics (robot/link_kinematics.hpp) on the shipped Franka FR3
// along its pick trajectory (robot/models/franka_fr3_pick.csv): Update per sample, Point per
// point, and a whole-robot pass (Update + 40 surface points per sample; items = point-samples,
// so "items_per_second" is point-samples/s). The points are the FR3's surface
// (robot/surface.hpp, its URDF capsules at 0.05 m spacing), 40 of them spread over the links.
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

#include <covopt/robot/kinematic_chain.hpp>
#include <covopt/robot/link_kinematics.hpp>
#include <covopt/robot/surface.hpp>
#include <covopt/robot/trajectory.hpp>

#include "fr3_pick.hpp"

namespace {

/// (link index, point in the link frame) for every point of the FR3's surface.
std::vector<std::pair<std::size_t, Eigen::Vector3d>> SurfacePoints(const covopt::robot::ChainSampleKinematics& kin) {
  const covopt::robot::RobotSurface surface = covopt::robot::SurfaceFromUrdfFile(kFr3Urdf, Fr3());
  std::vector<std::pair<std::size_t, Eigen::Vector3d>> points;
  for (const auto& link : surface.links) {
    const std::size_t index = *kin.LinkIndex(link.link);
    for (const auto& point : link.points) points.emplace_back(index, point.position_m);
  }
  return points;
}

/// `count` of `all`, evenly spread.
std::vector<std::pair<std::size_t, Eigen::Vector3d>> Spread(
    const std::vector<std::pair<std::size_t, Eigen::Vector3d>>& all, std::size_t count) {
  std::vector<std::pair<std::size_t, Eigen::Vector3d>> some;
  for (std::size_t i = 0; i < count; ++i) some.push_back(all[i * all.size() / count]);
  return some;
}

void BM_LinkKinematicsUpdateFr3(benchmark::State& state) {
  const covopt::robot::JointTrajectory& pick = Pick();
  covopt::robot::ChainSampleKinematics kin(Fr3());
  std::size_t i = 0;
  for (auto _ : state) {
    kin.Update(pick.positions[i], pick.velocities[i]);
    i = (i + 1) % pick.size();
  }
}
BENCHMARK(BM_LinkKinematicsUpdateFr3);

void BM_LinkKinematicsPointFr3(benchmark::State& state) {
  const covopt::robot::JointTrajectory& pick = Pick();
  covopt::robot::ChainSampleKinematics kin(Fr3());
  kin.Update(pick.positions[50], pick.velocities[50]);
  const auto points = SurfacePoints(kin);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(kin.Point(points[i].first, points[i].second));
    i = (i + 1) % points.size();
  }
  state.counters["surface_points"] = static_cast<double>(points.size());
}
BENCHMARK(BM_LinkKinematicsPointFr3);

/// The whole pick trajectory: per sample Update and `range(0)` points (0: the whole surface).
void BM_LinkKinematicsPickFr3(benchmark::State& state) {
  const covopt::robot::JointTrajectory& pick = Pick();
  covopt::robot::ChainSampleKinematics kin(Fr3());
  const auto all = SurfacePoints(kin);
  const auto points = state.range(0) == 0 ? all : Spread(all, static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    double sum = 0.0;
    for (std::size_t i = 0; i < pick.size(); ++i) {
      kin.Update(pick.positions[i], pick.velocities[i]);
      for (const auto& [link, p] : points) sum += kin.Point(link, p).reflected_mass_kg;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() *
                          static_cast<benchmark::IterationCount>(pick.size() * points.size()));
  state.counters["points"] = static_cast<double>(points.size());
  state.counters["samples"] = static_cast<double>(pick.size());
}
BENCHMARK(BM_LinkKinematicsPickFr3)->Arg(40)->Arg(0)->Unit(benchmark::kMillisecond);

}  // namespace
