// A design loop in user code, built against the installed covopt package: sweep the robot
// speed, compute each impact both ways, and fail unless the two paths agree; then take the
// polystyrene coverings from the built-in material catalog (no file needed at run time)
// and fail unless the paper's 27.6 MPa foam is among them; last, one design request
// (covopt::optim::Design) over the catalog, which must recommend a covering that does not
// bottom out.
#include <cmath>
#include <cstdio>

#include <covopt/core.hpp>
#include <covopt/materials.hpp>
#include <covopt/optim.hpp>

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

  const covopt::materials::Catalog& catalog = covopt::materials::Catalog::BuiltIn();
  covopt::materials::MaterialFilter polystyrene;
  polystyrene.name_contains = "polystyrene";
  int found = 0;
  scene.robot.speed_m_per_s = 2.0;
  for (const covopt::materials::Material* material : catalog.Filter(polystyrene)) {
    scene.covering.youngs_modulus_Pa = material->youngs_modulus_Pa;
    scene.covering.poisson_ratio = covopt::materials::PoissonRatioOrDefault(*material);
    const covopt::ImpactResult exact = covopt::SolveExact(covopt::ImpactModel::FromScene(scene));
    std::printf("%s: E = %.1f MPa, F_max = %.1f N\n", material->name.c_str(),
                material->youngs_modulus_Pa / 1e6, exact.peaks.peak_force_N);
    ++found;
  }
  const covopt::materials::Material* paper = catalog.Find("Polystyrene Foam 27.6");
  if (found < 2 || paper == nullptr || paper->youngs_modulus_Pa != 27.6e6) return 1;

  covopt::optim::DesignRequest request;
  request.materials = covopt::optim::SelectCandidates(catalog);
  const covopt::optim::DesignResult design = covopt::optim::Design(request);
  std::printf("%s\n", design.BriefReport().c_str());
  if (!design.recommendation || design.candidates[*design.recommendation].score.peaks.fully_compressed) return 1;
  std::printf("consumer: ok\n");
  return 0;
}
