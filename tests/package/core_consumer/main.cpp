// A user of covopt::core alone: the paper's scene on the exact path and the time path
// (SUNDIALS), which must agree.
#include <cmath>
#include <cstdio>

#include <covopt/core.hpp>

int main() {
  const covopt::Scene scene;  // the paper's scene with its 15 mm, 27.6 MPa covering
  const covopt::ImpactModel model = covopt::ImpactModel::FromScene(scene);
  const covopt::ImpactResult exact = covopt::SolveExact(model);
  const covopt::ImpactResult simulated = covopt::TimeIntegrator().Simulate(model);
  const double mismatch = std::abs(simulated.peaks.peak_force_N / exact.peaks.peak_force_N - 1);
  std::printf("F_max = %.1f N, paths differ by %.1e\n", exact.peaks.peak_force_N, mismatch);
  if (!simulated.ok() || mismatch > 1e-6) return 1;
  std::printf("core consumer: ok\n");
  return 0;
}
