// A design loop in user code, built against the installed covopt package: sweep the robot
// speed, compute each impact both ways, and fail unless the two paths agree.
#include <cmath>
#include <cstdio>

#include <covopt/core.hpp>

int main() {
  covopt::Scene scene;  // the paper's scene with its 15 mm, 27.6 MPa covering
  covopt::TimeIntegrator integrator;
  for (double speed = 0.5; speed <= 3.0; speed += 0.5) {
    scene.robot.speed_m_per_s = speed;
    const covopt::ImpactModel model = covopt::ImpactModel::FromScene(scene);
    const covopt::ImpactResult exact = covopt::SolveExact(model);
    const covopt::ImpactResult simulated = integrator.Simulate(model);
    const covopt::InjuryAssessment verdict = covopt::Assess(exact.peaks);
    const double mismatch = std::abs(simulated.peaks.peak_force_N / exact.peaks.peak_force_N - 1);
    std::printf("v0 = %.1f m/s: F_max = %.1f N, contusion ratio %.3f (%s), paths differ by %.1e\n",
                speed, exact.peaks.peak_force_N, verdict.contusion.ratio,
                verdict.contusion.safe ? "safe" : "unsafe", mismatch);
    if (!simulated.ok() || mismatch > 1e-6) return 1;
  }
  std::printf("consumer: ok\n");
  return 0;
}
