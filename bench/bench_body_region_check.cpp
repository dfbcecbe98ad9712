// Benchmarks of the body-region verdicts (optim/body_region_check.hpp): one contact judged
// against one region, its closed-form speed limit, and the all-regions table for one covering
// (every area ISO/TS 15066 permits under transient contact, bare and covered). Targets: one
// impact <= 0.2 µs (core's exact path), the table <= 50 µs. And a braking robot (100 m/s²
// after 5 ms, docs/model.md §13.10): one verdict on the time path, and its speed limit
// bracketed there (target < 1 ms, the audit's per point-sample budget where braking counts).
#include <benchmark/benchmark.h>

#include <vector>

#include <covopt/core/body_contact.hpp>
#include <covopt/materials/body_regions.hpp>
#include <covopt/optim/body_region_check.hpp>

namespace {

/// 10 kg, R 20 mm; argument 0: bare, 1: 10 mm of a 2 MPa foam.
covopt::BodyContactScene BenchScene(int which) {
  covopt::BodyContactScene scene;
  scene.robot_mass_kg = 10.0;
  scene.robot_radius_m = 0.02;
  scene.speed_m_per_s = 0.5;
  if (which == 1) scene.covering = {2e6, 0.3, 0.01};
  return scene;
}

const covopt::materials::BodyLimits& Chest() {
  static const covopt::materials::BodyLimits limits =
      covopt::materials::BodyRegionTable::BuiltIn().Limits("chest", "", covopt::ContactType::kTransient);
  return limits;
}

void BM_SolveBodyContact(benchmark::State& state) {
  const covopt::BodyContactScene scene =
      covopt::optim::WithRegion(BenchScene(static_cast<int>(state.range(0))), Chest());
  for (auto _ : state) benchmark::DoNotOptimize(covopt::Solve(scene));
}
BENCHMARK(BM_SolveBodyContact)->Arg(0)->Arg(1);

void BM_JudgeBodyContact(benchmark::State& state) {
  const covopt::BodyContactScene scene = BenchScene(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(covopt::optim::JudgeBodyContact(scene, Chest()));
}
BENCHMARK(BM_JudgeBodyContact)->Arg(0)->Arg(1);

void BM_BodyRegionMaxSafeSpeed(benchmark::State& state) {
  const covopt::BodyContactScene scene = BenchScene(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(covopt::optim::MaxSafeSpeed(scene, Chest()));
}
BENCHMARK(BM_BodyRegionMaxSafeSpeed)->Arg(0)->Arg(1);

void BM_BodyRegionSpeedLimitTable(benchmark::State& state) {
  const std::vector<covopt::materials::BodyLimits> all =
      covopt::materials::BodyRegionTable::BuiltIn().AllLimits(covopt::ContactType::kTransient);
  const covopt::BodyContactScene scene = BenchScene(1);
  for (auto _ : state) benchmark::DoNotOptimize(covopt::optim::BodyRegionSpeedLimitTable(scene, all));
  state.counters["rows"] = static_cast<double>(all.size());
}
BENCHMARK(BM_BodyRegionSpeedLimitTable)->Unit(benchmark::kMicrosecond);

/// BenchScene braking 100 m/s² after 5 ms.
covopt::BodyContactScene BrakingScene(int which) {
  covopt::BodyContactScene scene = BenchScene(which);
  scene.reaction_delay_s = 5e-3;
  scene.braking_m_per_s2 = 100.0;
  return scene;
}

void BM_BrakedJudgeBodyContact(benchmark::State& state) {
  const covopt::BodyContactScene scene = BrakingScene(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(covopt::optim::JudgeBodyContact(scene, Chest()));
}
BENCHMARK(BM_BrakedJudgeBodyContact)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void BM_BrakedMaxSafeSpeed(benchmark::State& state) {
  const covopt::BodyContactScene scene = BrakingScene(static_cast<int>(state.range(0)));
  int runs = 0;
  for (auto _ : state) {
    const covopt::optim::BodyRegionSpeedLimit limit = covopt::optim::MaxSafeSpeed(scene, Chest());
    runs = limit.time_path_runs;
    benchmark::DoNotOptimize(limit);
  }
  state.counters["time_path_runs"] = runs;
}
BENCHMARK(BM_BrakedMaxSafeSpeed)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
