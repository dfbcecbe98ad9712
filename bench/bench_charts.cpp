// Benchmarks of the report's charts (report/charts.hpp): one DrawSvgCharts call per chart kind,
// gnuplot's run included, and what each chart computes when made (the design map's grid, the
// speed-limit curves); and all five in one gnuplot run. Issue 26's target: a report adds at
// most 50 ms to a command. Skipped (with a message) where gnuplot is not on PATH.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>
#include <vector>

#include <covopt/core.hpp>
#include <covopt/materials.hpp>
#include <covopt/optim.hpp>
#include <covopt/audit/audit.hpp>

#include "covopt/chart/charts.hpp"

namespace {

using namespace covopt;

report::SimulationReport History() {
  TimeIntegrationOptions options;
  options.record_history = true;
  report::SimulationReport r;
  r.result = SimulateImpact(ImpactModel::FromScene(r.scene), options);
  r.verdict = optim::HeadVerdict(r.result.peaks, true, InjuryLimits{}, optim::DesignRule{});
  return r;
}

chart::TrajectoryChartInput Trajectory() {
  std::vector<optim::MotionSample> samples;
  for (int k = 0; k <= 200; ++k) {  // a 2 s move, 100 Hz, a sine speed profile, 8..12 kg
    const double t = 0.01 * k;
    samples.push_back({t, 1.5 * std::sin(M_PI * t / 2.0), 10.0 + 2.0 * std::cos(M_PI * t)});
  }
  chart::TrajectoryChartInput input;
  input.check = optim::CheckTrajectory(input.scene, samples);
  input.trajectory_name = "bench.csv";
  input.tip_link = "fr3_link8";
  return input;
}

audit::AuditResult Audit() {  // 7 links, 500 samples: the chart's data only
  audit::AuditResult r;
  r.status = optim::TrajectoryCheckStatus::kSafe;
  r.regions = {"chest (sternum)", "head (Park et al. 2011)"};
  for (int l = 0; l < 7; ++l) r.links.push_back("fr3_link" + std::to_string(l + 1));
  for (int i = 0; i < 500; ++i) {
    r.time_s.push_back(0.01 * i);
    for (int l = 0; l < 7; ++l) r.ratio_over_time.push_back(0.1 * l * (1.0 + std::sin(0.02 * i)));
  }
  r.sample_count = 500;
  return r;
}

bool HaveGnuplot(benchmark::State& state) {
  if (report::FindOnPath("gnuplot")) return true;
  state.SkipWithError("gnuplot is not on PATH");
  return false;
}

void Draw(benchmark::State& state, const chart::GnuplotChart& chart) {
  for (auto _ : state) benchmark::DoNotOptimize(chart::DrawSvgCharts({&chart, 1}));
}

void BM_HistoryChart(benchmark::State& state) {
  if (!HaveGnuplot(state)) return;
  const report::SimulationReport r = History();
  for (auto _ : state) {
    const chart::GnuplotChart chart = chart::HistoryChart(r);
    benchmark::DoNotOptimize(chart::DrawSvgCharts({&chart, 1}));
  }
}
BENCHMARK(BM_HistoryChart)->Unit(benchmark::kMillisecond);

/// The design map with its 41 x 31 grid computed (the optimiser's answer is not).
void BM_DesignMapChart(benchmark::State& state) {
  if (!HaveGnuplot(state)) return;
  optim::DesignRequest request;
  request.materials = optim::SelectCandidates(materials::Catalog::BuiltIn());
  const optim::DesignResult result = optim::Design(request);
  for (auto _ : state) {
    const chart::GnuplotChart chart = chart::DesignMapChart(optim::ComputeDesignMap(request, result));
    benchmark::DoNotOptimize(chart::DrawSvgCharts({&chart, 1}));
  }
}
BENCHMARK(BM_DesignMapChart)->Unit(benchmark::kMillisecond);

void BM_DesignMapGridOnly(benchmark::State& state) {
  optim::DesignRequest request;
  request.materials = optim::SelectCandidates(materials::Catalog::BuiltIn());
  const optim::DesignResult result = optim::Design(request);
  for (auto _ : state) benchmark::DoNotOptimize(optim::ComputeDesignMap(request, result));
}
BENCHMARK(BM_DesignMapGridOnly)->Unit(benchmark::kMillisecond);

/// The speed-limit chart with its curves computed (two coverings and the bare robot, 121
/// masses each).
void BM_SpeedLimitChart(benchmark::State& state) {
  if (!HaveGnuplot(state)) return;
  chart::SpeedLimitChartInput input;
  input.coverings = {{Scene{}, std::nullopt}, {Scene{}, std::string("soft")}};
  input.coverings[1].scene.covering = {2e6, 0.25, 0.01};
  for (auto _ : state) {
    const chart::GnuplotChart chart = chart::SpeedLimitChart(input);
    benchmark::DoNotOptimize(chart::DrawSvgCharts({&chart, 1}));
  }
}
BENCHMARK(BM_SpeedLimitChart)->Unit(benchmark::kMillisecond);

void BM_TrajectoryChart(benchmark::State& state) {
  if (!HaveGnuplot(state)) return;
  Draw(state, chart::TrajectoryChart(Trajectory()));
}
BENCHMARK(BM_TrajectoryChart)->Unit(benchmark::kMillisecond);

void BM_AuditHeatMap(benchmark::State& state) {
  if (!HaveGnuplot(state)) return;
  Draw(state, chart::AuditHeatMap(Audit(), 1.0, "bench.csv"));
}
BENCHMARK(BM_AuditHeatMap)->Unit(benchmark::kMillisecond);

/// All five charts in one gnuplot run (charts made beforehand).
void BM_AllChartsOneRun(benchmark::State& state) {
  if (!HaveGnuplot(state)) return;
  optim::DesignRequest request;
  request.materials = optim::SelectCandidates(materials::Catalog::BuiltIn());
  const optim::DesignResult result = optim::Design(request);
  chart::SpeedLimitChartInput speed;
  speed.coverings = {{Scene{}, std::nullopt}};
  const std::vector<chart::GnuplotChart> charts = {
      chart::HistoryChart(History()), chart::DesignMapChart(optim::ComputeDesignMap(request, result)),
      chart::SpeedLimitChart(speed), chart::TrajectoryChart(Trajectory()),
      chart::AuditHeatMap(Audit(), 1.0, "bench.csv")};
  for (auto _ : state) benchmark::DoNotOptimize(chart::DrawSvgCharts(charts));
}
BENCHMARK(BM_AllChartsOneRun)->Unit(benchmark::kMillisecond);

}  // namespace
