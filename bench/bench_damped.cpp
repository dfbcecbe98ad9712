// covopt benchmarks: the exact path with Hunt-Crossley contact damping (docs/model.md §10.1)
// on the paper's scenes at d = 0.2 s/m. The conservative scenes are in bench_impact.cpp
// (BM_ExactPeaks, BM_ExactPeaksAndDuration): the same calls, so the two read side by side.
#include <benchmark/benchmark.h>

#include <covopt/core.hpp>

namespace {

constexpr double kDampingSPerM = 0.2;

/// The paper's Sec. IV scene (10 kg, 2 m/s, R_r 15 mm, free 4.5 kg head), with its 15 mm,
/// 27.6 MPa covering (bare = 0) or without one (bare = 1), damped at 0.2 s/m.
const covopt::ImpactModel& DampedModel(int bare) {
  auto make = [](double thickness_m) {
    covopt::Scene scene;
    scene.covering = {27.6e6, 0.22, thickness_m};
    scene.model.damping_s_per_m = kDampingSPerM;
    return covopt::ImpactModel::FromScene(scene);
  };
  static const covopt::ImpactModel covered = make(0.015);
  static const covopt::ImpactModel bare_robot = make(0.0);
  return bare != 0 ? bare_robot : covered;
}

/// δ_max, the largest F and σ_c over the loading branch and e_A (a quadrature).
void BM_DampedExactPeaks(benchmark::State& state) {
  const auto& model = DampedModel(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(covopt::ExactPeaks(model));
}
BENCHMARK(BM_DampedExactPeaks)->Arg(0)->Arg(1)->ArgNames({"bare"});

/// The peaks and the contact duration (loading and unloading times, which differ).
void BM_DampedExactPeaksAndDuration(benchmark::State& state) {
  const auto& model = DampedModel(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const covopt::ImpactPeaks peaks = covopt::ExactPeaks(model);
    benchmark::DoNotOptimize(covopt::ExactContactDuration(model, peaks));
  }
}
BENCHMARK(BM_DampedExactPeaksAndDuration)->Arg(0)->Arg(1)->ArgNames({"bare"});

}  // namespace
