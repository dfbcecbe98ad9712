// What `covopt optimize` spends outside the exact path: Ipopt's own cost on a problem whose
// evaluations are free (application and options set-up, MUMPS, its iterations), cold and
// warm-started, with the Lagrangian's Hessian and with L-BFGS. Compare with
// BM_FindThinnestSafeCovering (bench_impact.cpp), with and without the Ipopt polish.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include <covopt/optim/backends.hpp>

namespace {

using covopt::optim::Problem;

/// The shape of the covering polish at no cost: min x_1 s.t. 0.09 + 0.01 (x_0 - 7.2)² - x_1 <= 0 (a parabola: optimum (7.2, 0.09)),
/// and x_0 - 7.4 <= 0, on the box [6.95, 7.45] x [0.05, 0.5]; exact Hessian of the Lagrangian.
class FreeParabola : public Problem {
 public:
  std::size_t dimension() const override { return 2; }
  std::size_t inequality_count() const override { return 2; }
  std::vector<double> lower_bounds() const override { return {6.95, 0.05}; }
  std::vector<double> upper_bounds() const override { return {7.45, 0.5}; }
  bool Objective(std::span<const double> x, double& value, std::span<double> g) const override {
    value = x[1];
    if (!g.empty()) {
      g[0] = 0.0;
      g[1] = 1.0;
    }
    return true;
  }
  bool Constraints(std::span<const double> x, std::span<double> c, std::span<double> j) const override {
    c[0] = 0.09 + 0.01 * (x[0] - 7.2) * (x[0] - 7.2) - x[1];
    c[1] = x[0] - 7.4;
    if (!j.empty()) {
      j[0] = 0.02 * (x[0] - 7.2);
      j[1] = -1.0;
      j[2] = 1.0;
      j[3] = 0.0;
    }
    return true;
  }
  bool provides_lagrangian_hessian() const override { return true; }
  bool LagrangianHessian(std::span<const double>, double, std::span<const double> lambda,
                         std::span<double> h) const override {
    h[0] = 0.02 * lambda[0];
    h[1] = 0.0;
    h[2] = 0.0;
    return true;
  }
};

/// Ipopt on FreeParabola. start 0: from (7.0, 0.2), cold, Hessian; 1: the same with L-BFGS;
/// 2: warm-started from the optimum (the polish's case: Ipopt only confirms).
void BM_IpoptStartup(benchmark::State& state) {
  const FreeParabola problem;
  covopt::optim::IpoptOptions options;
  std::vector<double> start = {7.0, 0.2};
  if (state.range(0) == 1) options.limited_memory_hessian = true;
  if (state.range(0) == 2) {
    options.warm_start = true;
    start = {7.2, 0.09};
  }
  long iterations_proxy = 0;
  for (auto _ : state) {
    const auto result = covopt::optim::SolveWithIpopt(problem, start, options);
    iterations_proxy = result.report.gradient_evaluations;
    benchmark::DoNotOptimize(result.x.data());
  }
  state.counters["gradient_evaluations"] = static_cast<double>(iterations_proxy);
}
BENCHMARK(BM_IpoptStartup)->Arg(0)->Arg(1)->Arg(2)->ArgNames({"start"})->Unit(benchmark::kMicrosecond);

}  // namespace
