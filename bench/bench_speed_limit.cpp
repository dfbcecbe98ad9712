// Benchmarks of MaxSafeSpeed and MaxSafeMass (optim/speed_limit.hpp): one answer each, on the
// paper's scene with its 15 mm covering (limited by contusion), the bare robot (laceration)
// and a soft covering limited by full compression. Target: <= 5 µs per answer.
#include <benchmark/benchmark.h>

#include <covopt/core/scene.hpp>
#include <covopt/optim/speed_limit.hpp>

namespace {

covopt::Scene BenchScene(int which) {
  covopt::Scene scene;  // 10 kg, R 15 mm, 15 mm of 27.6 MPa, free 4.5 kg head
  if (which == 1) scene.covering.thickness_m = 0.0;
  if (which == 2) scene.covering = {2e6, 0.25, 0.01};
  return scene;
}

void BM_MaxSafeSpeed(benchmark::State& state) {
  const covopt::Scene scene = BenchScene(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(covopt::optim::MaxSafeSpeed(scene));
}
BENCHMARK(BM_MaxSafeSpeed)->Arg(0)->Arg(1)->Arg(2);

void BM_MaxSafeMass(benchmark::State& state) {
  const covopt::Scene scene = BenchScene(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(covopt::optim::MaxSafeMass(scene));
}
BENCHMARK(BM_MaxSafeMass)->Arg(0)->Arg(1)->Arg(2);

}  // namespace
