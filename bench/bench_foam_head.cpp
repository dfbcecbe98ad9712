// The foam law on the head (docs/model.md §16) against today's Hertz covering, exact path: the
// issue's goal is a foam impact within 2x the cost of a Hertz one. Scenes: the paper's (10 kg,
// R_r 15 mm, free 4.5 kg head) wearing NIST's VN600 curve (11 points), 20 mm at 0.3 m/s (within
// the curve) and 5 mm at 2 m/s (used up: the rigid stop and the bare robot's chain past it), and
// the paper's 15 mm, 27.6 MPa Hertz covering at 2 m/s.
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include <covopt/core.hpp>
#include <covopt/optim/speed_limit.hpp>

namespace {

covopt::Scene FoamHeadScene(int which) {
  covopt::Scene scene;  // 10 kg, 2 m/s, R_r 15 mm, free 4.5 kg head, 15 mm 27.6 MPa (Hertz)
  if (which == 0) return scene;
  static const auto vn600 = std::make_shared<const covopt::CompressiveCurve>(covopt::CompressiveCurve::FromPoints(
      std::vector<covopt::StrainStressPoint>{{0.02, 14.3e3},
                                             {0.05, 22.0e3},
                                             {0.10, 30.2e3},
                                             {0.15, 37.4e3},
                                             {0.20, 45.9e3},
                                             {0.25, 57.3e3},
                                             {0.30, 72.2e3},
                                             {0.35, 91.6e3},
                                             {0.40, 118.0e3},
                                             {0.45, 153.2e3},
                                             {0.49, 189.5e3}}));
  scene.covering = covopt::CoveringSpec{.youngs_modulus_Pa = 1e6,
                                        .poisson_ratio = 0.0,
                                        .thickness_m = which == 1 ? 0.02 : 0.005,
                                        .compressive_curve = vn600};
  scene.robot.speed_m_per_s = which == 1 ? 0.3 : 2.0;
  return scene;
}

constexpr const char* kLabels[] = {"hertz", "foam-within", "foam-used-up"};

void BM_FoamHeadExactPeaks(benchmark::State& state) {
  const covopt::ImpactModel model = covopt::ImpactModel::FromScene(FoamHeadScene(static_cast<int>(state.range(0))));
  for (auto _ : state) benchmark::DoNotOptimize(covopt::ExactPeaks(model));
  state.SetLabel(kLabels[state.range(0)]);
}
BENCHMARK(BM_FoamHeadExactPeaks)->DenseRange(0, 2)->ArgNames({"scene"});

/// Validation, the force law and the peaks: what every evaluation of a design costs.
void BM_FoamHeadModelAndPeaks(benchmark::State& state) {
  const covopt::Scene scene = FoamHeadScene(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(covopt::ExactPeaks(covopt::ImpactModel::FromScene(scene)));
  state.SetLabel(kLabels[state.range(0)]);
}
BENCHMARK(BM_FoamHeadModelAndPeaks)->DenseRange(0, 2)->ArgNames({"scene"});

/// SolveExact: peaks, the duration quadrature (split at the curve's points under the foam law)
/// and the validity checks.
void BM_FoamHeadSolveExact(benchmark::State& state) {
  const covopt::ImpactModel model = covopt::ImpactModel::FromScene(FoamHeadScene(static_cast<int>(state.range(0))));
  for (auto _ : state) benchmark::DoNotOptimize(covopt::SolveExact(model));
  state.SetLabel(kLabels[state.range(0)]);
}
BENCHMARK(BM_FoamHeadSolveExact)->DenseRange(0, 2)->ArgNames({"scene"})->Unit(benchmark::kMicrosecond);

/// The head's speed limit (default criterion) on the penetration axis.
void BM_FoamHeadSpeedLimit(benchmark::State& state) {
  const covopt::Scene scene = FoamHeadScene(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(covopt::optim::MaxSafeSpeed(scene));
  state.SetLabel(kLabels[state.range(0)]);
}
BENCHMARK(BM_FoamHeadSpeedLimit)->DenseRange(0, 2)->ArgNames({"scene"})->Unit(benchmark::kMicrosecond);

}  // namespace

namespace {

/// The duration quadrature alone (peaks given).
void BM_FoamHeadDuration(benchmark::State& state) {
  const covopt::ImpactModel model = covopt::ImpactModel::FromScene(FoamHeadScene(static_cast<int>(state.range(0))));
  const covopt::ImpactPeaks peaks = covopt::ExactPeaks(model);
  for (auto _ : state) benchmark::DoNotOptimize(covopt::ExactContactDuration(model, peaks));
  state.SetLabel(kLabels[state.range(0)]);
}
BENCHMARK(BM_FoamHeadDuration)->DenseRange(0, 2)->ArgNames({"scene"});

}  // namespace
