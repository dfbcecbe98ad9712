#pragma once
// The benchmark loop of a time-path run, shared by bench_impact.cpp (the δ-only path) and
// bench_extended.cpp (the extended path): one TimeIntegrator reused across iterations, the
// step count as a counter and the method as the label.
#include <benchmark/benchmark.h>

#include <string>

#include <covopt/core.hpp>

inline void RunTimePathLoop(benchmark::State& state, const covopt::ImpactModel& model,
                            const covopt::TimeIntegrationOptions& options) {
  covopt::TimeIntegrator integrator;
  long steps = 0;
  for (auto _ : state) {
    const covopt::ImpactResult result = integrator.Simulate(model, options);
    steps = result.statistics.steps;
    benchmark::DoNotOptimize(result.peaks.max_penetration_m);
  }
  state.counters["steps"] = static_cast<double>(steps);
  state.SetLabel(std::string(covopt::ToString(options.method)));
}
