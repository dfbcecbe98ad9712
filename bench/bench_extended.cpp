// covopt benchmarks: the extended time path (docs/model.md §10.2, §10.3) on the paper's
// covered scene: a robot braking at 100 m/s² after 2 ms, a head on a neck (30 kg torso,
// 20 kN/m, 200 N·s/m: test inputs, not physiology) and the conservative scene forced onto the
// extended path, whose δ-only counterpart is BM_TimePath (bench_impact.cpp).
#include <benchmark/benchmark.h>

#include <string>

#include <covopt/core.hpp>

#include "time_path_loop.hpp"

namespace {

const covopt::ImpactModel& ExtendedModel(int which) {
  auto make = [](int scene_index) {
    covopt::Scene scene;  // 10 kg, 2 m/s, R_r 15 mm, free 4.5 kg head
    scene.covering = {27.6e6, 0.22, 0.015};
    if (scene_index == 0) {
      scene.robot.braking_m_per_s2 = 100.0;
      scene.robot.reaction_delay_s = 0.002;
    } else if (scene_index == 1) {
      scene.head.torso_mass_kg = 30.0;
      scene.head.neck_stiffness_N_per_m = 2e4;
      scene.head.neck_damping_N_s_per_m = 200.0;
    }
    return covopt::ImpactModel::FromScene(scene);
  };
  static const covopt::ImpactModel braking = make(0);
  static const covopt::ImpactModel neck = make(1);
  static const covopt::ImpactModel conservative = make(2);
  return which == 0 ? braking : which == 1 ? neck : conservative;
}

/// scene: 0 braking, 1 neck, 2 conservative (forced onto the extended path); method: 0 ARKODE
/// Dormand-Prince 5(4) (the default), 1 CVODE Adams; at the default rtol 1e-8.
void BM_ExtendedTimePath(benchmark::State& state) {
  static const covopt::ComputationMethod kMethods[] = {covopt::ComputationMethod::kArkodeErk54,
                                                       covopt::ComputationMethod::kCvodeAdams};
  const auto& model = ExtendedModel(static_cast<int>(state.range(0)));
  covopt::TimeIntegrationOptions options;
  options.method = kMethods[state.range(1)];
  options.force_extended_dynamics = true;
  RunTimePathLoop(state, model, options);
}
BENCHMARK(BM_ExtendedTimePath)
    ->ArgsProduct({{0, 1, 2}, {0, 1}})
    ->ArgNames({"scene", "method"})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
