// covopt benchmarks (Google Benchmark): the exact path and the CVODE time path on the
// paper's scenes. Run: ./build/bench/covopt_bench   (not part of CTest; numbers in README).
#include <benchmark/benchmark.h>

#include <cmath>

#include <covopt/core.hpp>

namespace {

covopt::Scene PaperSceneWithCovering() {
  covopt::Scene scene;  // 10 kg, 2 m/s, R_r 15 mm, free 4.5 kg head
  scene.covering = {27.6e6, 0.22, 0.015};
  return scene;
}

covopt::Scene PaperSceneBare() {
  covopt::Scene scene;
  scene.covering.thickness_m = 0.0;
  return scene;
}

const covopt::ImpactModel& Model(int which) {
  static const covopt::ImpactModel covered = covopt::ImpactModel::FromScene(PaperSceneWithCovering());
  static const covopt::ImpactModel bare = covopt::ImpactModel::FromScene(PaperSceneBare());
  return which == 0 ? covered : bare;
}

void BM_ModelFromScene(benchmark::State& state) {
  const covopt::Scene scene = PaperSceneWithCovering();
  for (auto _ : state) benchmark::DoNotOptimize(covopt::ImpactModel::FromScene(scene));
}
BENCHMARK(BM_ModelFromScene);

void BM_ExactPeaks(benchmark::State& state) {
  const auto& model = Model(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(covopt::ExactPeaks(model));
}
BENCHMARK(BM_ExactPeaks)->Arg(0)->Arg(1)->ArgNames({"bare"});

void BM_ExactPeaksAndDuration(benchmark::State& state) {
  const auto& model = Model(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const covopt::ImpactPeaks peaks = covopt::ExactPeaks(model);
    benchmark::DoNotOptimize(covopt::ExactContactDuration(model, peaks));
  }
}
BENCHMARK(BM_ExactPeaksAndDuration)->Arg(0)->Arg(1)->ArgNames({"bare"});

void BM_Cvode(benchmark::State& state) {
  const auto& model = Model(static_cast<int>(state.range(0)));
  covopt::TimeIntegrationOptions options;
  options.method = state.range(1) == 0 ? covopt::CvodeMethod::kAdams : covopt::CvodeMethod::kBdf;
  options.relative_tolerance = std::pow(10.0, -static_cast<double>(state.range(2)));
  covopt::TimeIntegrator integrator;
  long steps = 0;
  for (auto _ : state) {
    const covopt::ImpactResult result = integrator.Simulate(model, options);
    steps = result.statistics.steps;
    benchmark::DoNotOptimize(result.peaks.max_penetration_m);
  }
  state.counters["steps"] = static_cast<double>(steps);
}
BENCHMARK(BM_Cvode)
    ->ArgsProduct({{0, 1}, {0, 1}, {6, 8, 10}})
    ->ArgNames({"bare", "bdf", "rtol_exp"})
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
