// Benchmarks of the body-region contact (covopt/core/body_contact.hpp): the exact path on a
// prebuilt BodyContactModel (what a speed-limit search or a table reuses), the model's
// construction and FromScene + Solve (issue 24's target: <= 0.2 µs per impact), and the time
// path (ARKODE Dormand-Prince 5(4)) at rtol 1e-6 / 1e-8 / 1e-10. Scenes: the chest (Table A.3,
// transient, 10 kg robot at 1 m/s) under 10 mm of the paper's foam No. 1 on a 20 mm radius,
// bare, and under a very soft foam that bottoms out; and the foam law (docs/model.md §15): VN600
// vinyl-nitrile's measured curve (11 points), 40 mm (within the curve) and 10 mm (used up).
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <covopt/core/body_contact.hpp>

namespace {

std::shared_ptr<const covopt::CompressiveCurve> Vn600() {
  static const std::vector<covopt::StrainStressPoint> points{
      {0.02, 14.3e3}, {0.05, 22.0e3}, {0.10, 30.2e3},  {0.15, 37.4e3},  {0.20, 45.9e3}, {0.25, 57.3e3},
      {0.30, 72.2e3}, {0.35, 91.6e3}, {0.40, 118.0e3}, {0.45, 153.2e3}, {0.49, 189.5e3}};
  static const auto curve =
      std::make_shared<const covopt::CompressiveCurve>(covopt::CompressiveCurve::FromPoints(points));
  return curve;
}

covopt::BodyContactScene BenchScene(long which) {
  covopt::BodyContactScene scene;  // 10 kg robot, chest: 25 kN/m, 40 kg, transient
  scene.speed_m_per_s = 1.0;
  scene.robot_radius_m = 0.02;
  if (which == 0) scene.covering = {.youngs_modulus_Pa = 27.6e6, .poisson_ratio = 0.25, .thickness_m = 10e-3};
  if (which == 2) scene.covering = {.youngs_modulus_Pa = 1e3, .poisson_ratio = 0.3, .thickness_m = 20e-3};  // bottoms out
  if (which >= 3) {  // the foam law
    scene.covering = {.youngs_modulus_Pa = 1e6, .poisson_ratio = 0.3, .thickness_m = which == 3 ? 40e-3 : 10e-3};
    scene.covering.compressive_curve = Vn600();
  }
  return scene;
}

constexpr const char* kSceneNames[] = {"foam No. 1", "bare", "bottoming out", "VN600 40 mm (foam law)",
                                       "VN600 10 mm, used up (foam law)"};

void BM_BodyContactModelFromScene(benchmark::State& state) {
  const covopt::BodyContactScene scene = BenchScene(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(covopt::BodyContactModel::FromScene(scene));
  state.SetLabel(kSceneNames[state.range(0)]);
}
BENCHMARK(BM_BodyContactModelFromScene)->DenseRange(0, 4)->ArgNames({"scene"});

/// The exact path on a prebuilt model: the energy balance's root and the peaks.
void BM_BodyContactExactSolve(benchmark::State& state) {
  const covopt::BodyContactModel model = covopt::BodyContactModel::FromScene(BenchScene(state.range(0)));
  for (auto _ : state) {
    const covopt::BodyContactResult result = covopt::Solve(model);
    benchmark::DoNotOptimize(result.peak_force_N);
  }
  state.SetLabel(kSceneNames[state.range(0)]);
}
BENCHMARK(BM_BodyContactExactSolve)->DenseRange(0, 4)->ArgNames({"scene"});

/// Validation, the model's constants and the exact path from a scene: one impact from scratch.
void BM_BodyContactFromSceneAndSolve(benchmark::State& state) {
  const covopt::BodyContactScene scene = BenchScene(state.range(0));
  for (auto _ : state) {
    const covopt::BodyContactResult result = covopt::Solve(scene);
    benchmark::DoNotOptimize(result.peak_force_N);
  }
  state.SetLabel(kSceneNames[state.range(0)]);
}
BENCHMARK(BM_BodyContactFromSceneAndSolve)->DenseRange(0, 4)->ArgNames({"scene"});

/// The time path on a prebuilt model (per-thread SUNDIALS workspace, reused).
void BM_BodyContactTimePath(benchmark::State& state) {
  const covopt::BodyContactModel model = covopt::BodyContactModel::FromScene(BenchScene(state.range(0)));
  covopt::SolveOptions options;
  options.path = covopt::PathChoice::kTimePath;
  options.time_path.relative_tolerance = std::pow(10.0, -static_cast<double>(state.range(1)));
  for (auto _ : state) {
    const covopt::BodyContactResult result = covopt::Solve(model, options);
    benchmark::DoNotOptimize(result.peak_force_N);
  }
  state.SetLabel(std::string(kSceneNames[state.range(0)]) + ", " +
                 std::string(covopt::ToString(options.time_path.method)));
}
BENCHMARK(BM_BodyContactTimePath)
    ->ArgsProduct({{0, 1, 2, 3, 4}, {6, 8, 10}})
    ->ArgNames({"scene", "rtol_exp"})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
