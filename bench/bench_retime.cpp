// Benchmarks of re-timing (audit/retime.hpp) on the shipped Franka FR3 along its pick move
// (robot/models/franka_fr3_pick.csv, 101 samples, 1.5 s), its whole surface at 0.05 m spacing,
// against every transient body region of ISO/TS 15066 and the head (Park et al.), 10 mm of PORON
// 4701-30 320 on every link (fr3_pick.hpp), joints at their URDF speed limits and 10 rad/s².
//   BM_RetimePickFr3                   one Retime: the audit, the time-optimal parameterisation
//                                      and the re-audit; the target is <= 0.5 s on one core.
//   BM_RetimePickBrakingFr3            the same for a robot braking at 200 m/s² 2 ms after
//                                      contact: each sample's braked limit on the time path.
//   BM_CycleTimeAgainstThicknessFr3    the cycle-time sweep over 9 thicknesses, 0 .. 40 mm.
#include <vector>

#include <benchmark/benchmark.h>

#include <covopt/audit/retime.hpp>
#include <covopt/robot/surface.hpp>

#include "fr3_pick.hpp"

namespace {

covopt::audit::AuditSetup Setup() {
  covopt::audit::AuditSetup setup = Fr3AuditSetup(covopt::robot::SurfaceFromUrdfFile(kFr3Urdf, Fr3()));
  setup.contact_area_m2 = 1e-4;  // the bare point of the sweep
  return setup;
}

covopt::audit::RetimeOptions Options() {
  covopt::audit::RetimeOptions options;
  options.joint_acceleration_limits = Eigen::VectorXd::Constant(7, 10.0);
  return options;
}

void BM_RetimePickFr3(benchmark::State& state) {
  const covopt::audit::AuditSetup setup = Setup();
  double cycle_time_s = 0.0, uniform_s = 0.0;
  for (auto _ : state) {
    const covopt::audit::RetimeResult r = covopt::audit::Retime(setup, Pick(), Options());
    cycle_time_s = r.cycle_time_s;
    uniform_s = r.uniform_cycle_time_s;
  }
  state.counters["points"] = static_cast<double>(setup.surface.point_count());
  state.counters["cycle_time_s"] = cycle_time_s;
  state.counters["uniform_s"] = uniform_s;
}
BENCHMARK(BM_RetimePickFr3)->Unit(benchmark::kMillisecond);

void BM_RetimePickBrakingFr3(benchmark::State& state) {
  covopt::audit::AuditSetup setup = Setup();
  setup.reaction_delay_s = 0.002;
  setup.braking_m_per_s2 = 200.0;
  double cycle_time_s = 0.0;
  for (auto _ : state) cycle_time_s = covopt::audit::Retime(setup, Pick(), Options()).cycle_time_s;
  state.counters["cycle_time_s"] = cycle_time_s;
}
BENCHMARK(BM_RetimePickBrakingFr3)->Unit(benchmark::kMillisecond);

void BM_CycleTimeAgainstThicknessFr3(benchmark::State& state) {
  const covopt::audit::AuditSetup setup = Setup();
  const std::vector<covopt::audit::CycleTimeDesign> designs{{"PU foam PORON 4701-30 320", setup.covering, {}}};
  std::vector<double> thicknesses;
  for (int k = 0; k < 9; ++k) thicknesses.push_back(0.005 * k);
  for (auto _ : state) {
    benchmark::DoNotOptimize(covopt::audit::CycleTimeAgainstThickness(setup, Pick(), Options(), designs, thicknesses));
  }
  state.counters["thicknesses"] = static_cast<double>(thicknesses.size());
}
BENCHMARK(BM_CycleTimeAgainstThicknessFr3)->Unit(benchmark::kMillisecond);

}  // namespace
