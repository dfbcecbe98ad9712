// Benchmarks of TimeOptimalParameterization (optim/time_optimal_path.hpp): a 7-joint path of
// the pick move's length (1.5 s of program, s = the program's time) with the FR3's joint limits
// (2.62-5.26 rad/s, 10 rad/s²), the programmed speed as the path-speed cap and a dip to 0.45 of
// it around s = 0.825 s (a local safety limit), at 101, 1001 and 10001 samples. The cost is
// linear in the samples: per segment 30 constraints, u eliminated between 15 upper and 15 lower
// bounds.
#include <cmath>
#include <vector>

#include <benchmark/benchmark.h>

#include <covopt/optim/time_optimal_path.hpp>

namespace {

namespace co = covopt::optim;

struct Problem {
  co::PathSamples path;
  co::PathLimits limits;
};

Problem SevenJointPath(int samples) {
  Problem problem;
  const double duration_s = 1.5;
  problem.limits.max_joint_speed.resize(7);
  problem.limits.max_joint_speed << 2.62, 2.62, 2.62, 2.62, 5.26, 4.18, 5.26;
  problem.limits.max_joint_acceleration = Eigen::VectorXd::Constant(7, 10.0);
  for (int i = 0; i < samples; ++i) {
    const double s = duration_s * i / (samples - 1);
    Eigen::VectorXd slope(7);
    for (int j = 0; j < 7; ++j) {
      const double rate = 1.0 + 0.6 * j;  // rad per unit of s, varying per joint
      slope[j] = 0.9 * rate * std::cos(rate * s + 0.4 * j);
    }
    problem.path.s.push_back(s);
    problem.path.dq_ds.push_back(slope);
    problem.limits.max_path_speed.push_back(std::abs(s - 0.825) < 0.05 ? 0.45 : 1.0);
  }
  return problem;
}

void BM_TimeOptimalParameterization(benchmark::State& state) {
  const Problem problem = SevenJointPath(static_cast<int>(state.range(0)));
  const co::TimeOptimalProfile profile = co::TimeOptimalParameterization(problem.path, problem.limits);
  if (!profile.ok()) state.SkipWithError(profile.message.c_str());
  state.counters["duration_s"] = profile.duration_s();
  for (auto _ : state) {
    benchmark::DoNotOptimize(co::TimeOptimalParameterization(problem.path, problem.limits));
  }
  state.counters["samples"] = static_cast<double>(state.range(0));
  state.counters["per_sample"] =
      benchmark::Counter(static_cast<double>(state.range(0)), benchmark::Counter::kIsIterationInvariantRate |
                                                                    benchmark::Counter::kInvert);
}
BENCHMARK(BM_TimeOptimalParameterization)->Arg(101)->Arg(1001)->Arg(10001)->Unit(benchmark::kMicrosecond);

}  // namespace
