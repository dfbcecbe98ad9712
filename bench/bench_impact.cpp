// covopt benchmarks (Google Benchmark): the exact path and the time path (ARKODE and CVODE)
// on the paper's scenes. Run: ./build/bench/covopt_bench   (not part of CTest; numbers in README).
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include <covopt/core.hpp>
#include <covopt/optim/covering_design.hpp>

#include "time_path_loop.hpp"

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

/// Model construction (validation and the force law) and the exact peaks from a scene: what
/// every evaluation of a design costs (issue 15's target: <= 200 ns).
void BM_ModelAndPeaks(benchmark::State& state) {
  const covopt::Scene scene = state.range(0) != 0 ? PaperSceneBare() : PaperSceneWithCovering();
  for (auto _ : state) {
    benchmark::DoNotOptimize(covopt::ExactPeaks(covopt::ImpactModel::FromScene(scene)));
  }
}
BENCHMARK(BM_ModelAndPeaks)->Arg(0)->Arg(1)->ArgNames({"bare"});

void BM_ExactPeaksAndDuration(benchmark::State& state) {
  const auto& model = Model(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const covopt::ImpactPeaks peaks = covopt::ExactPeaks(model);
    benchmark::DoNotOptimize(covopt::ExactContactDuration(model, peaks));
  }
}
BENCHMARK(BM_ExactPeaksAndDuration)->Arg(0)->Arg(1)->ArgNames({"bare"});

/// The time path with the default integrator (ARKODE Dormand-Prince 5(4)) and the two CVODE
/// families, at rtol 1e-6 / 1e-8 / 1e-10 (the label names the method).
void BM_TimePath(benchmark::State& state) {
  static const covopt::ComputationMethod kMethods[] = {covopt::ComputationMethod::kArkodeErk54,
                                                       covopt::ComputationMethod::kCvodeAdams,
                                                       covopt::ComputationMethod::kCvodeBdf};
  const auto& model = Model(static_cast<int>(state.range(0)));
  covopt::TimeIntegrationOptions options;
  options.method = kMethods[state.range(1)];
  options.relative_tolerance = std::pow(10.0, -static_cast<double>(state.range(2)));
  RunTimePathLoop(state, model, options);
}
BENCHMARK(BM_TimePath)
    ->ArgsProduct({{0, 1}, {0, 1, 2}, {6, 8, 10}})
    ->ArgNames({"bare", "method", "rtol_exp"})
    ->Unit(benchmark::kMicrosecond);

void BM_OracleWithGradient(benchmark::State& state) {
  const covopt::optim::CoveringOracle oracle(covopt::Scene{}, 0.25);
  covopt::optim::RatioGradient gradient;
  for (auto _ : state) {
    benchmark::DoNotOptimize(oracle.Score({13e6, 0.0142}, gradient).contusion_ratio);
  }
}
BENCHMARK(BM_OracleWithGradient);

void BM_OracleWithoutGradient(benchmark::State& state) {
  const covopt::optim::CoveringOracle oracle(covopt::Scene{}, 0.25);
  for (auto _ : state) benchmark::DoNotOptimize(oracle.Score({13e6, 0.0142}).contusion_ratio);
}
BENCHMARK(BM_OracleWithoutGradient);

/// The paper's Table IV materials: the search `covopt optimize` runs, without the CLI.
void BM_FindThinnestSafeCovering(benchmark::State& state) {
  const std::vector<covopt::optim::CandidateMaterial> materials = {
      {"polystyrene 27.6", 27.6e6, 0.22}, {"polystyrene 48.3", 48.3e6, 0.25},
      {"polyurethane 62.1", 62.1e6, 0.20}, {"polyurethane 137.9", 137.9e6, 0.29}};
  covopt::optim::DesignOptions options;
  options.local_polish = state.range(0) != 0;
  long evaluations = 0;
  for (auto _ : state) {
    const auto result = covopt::optim::FindThinnestSafeCovering(covopt::Scene{}, materials, options);
    evaluations = result.evaluations;
    benchmark::DoNotOptimize(result.continuous.score.design.thickness_m);
  }
  state.counters["evaluations"] = static_cast<double>(evaluations);
}
BENCHMARK(BM_FindThinnestSafeCovering)->Arg(1)->Arg(0)->ArgNames({"ipopt"})->Unit(benchmark::kMillisecond);

/// 200 x 200 map over (E_c, b_c) with the exact path.
void BM_DesignMap200x200(benchmark::State& state) {
  covopt::Scene scene;
  for (auto _ : state) {
    double sum = 0.0;
    for (int i = 0; i < 200; ++i) {
      scene.covering.youngs_modulus_Pa = std::pow(10.0, 5.0 + 4.0 * i / 199.0);
      for (int j = 0; j < 200; ++j) {
        scene.covering.thickness_m = 0.05 * (j + 1) / 200.0;
        sum += covopt::ExactPeaks(covopt::ImpactModel::FromScene(scene)).max_energy_density_J_per_m2;
      }
    }
    benchmark::DoNotOptimize(sum);
  }
}
BENCHMARK(BM_DesignMap200x200)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
