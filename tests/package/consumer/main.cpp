// A design loop in user code, built against the installed covopt package: sweep the robot
// speed, compute each impact both ways, and fail unless the two paths agree; then take the
// polystyrene coverings from the built-in material catalog (no file needed at run time)
// and fail unless the paper's 27.6 MPa foam is among them; last, one design request
// (covopt::optim::Design) over the catalog, which must recommend a covering that does not
// bottom out; and the reflected mass of a one-joint arm from its URDF (covopt::robot): a
// 2 kg point mass on a 0.5 m lever feels like 2 kg across the lever.
#include <cmath>
#include <cstdio>

#include <covopt/core.hpp>
#include <covopt/materials.hpp>
#include <covopt/optim.hpp>
#include <covopt/robot.hpp>

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

  const auto arm = covopt::robot::KinematicChain::FromUrdfString(
      "<robot name='lever'><link name='base'/><joint name='j' type='continuous'>"
      "<parent link='base'/><child link='lever'/><axis xyz='0 0 1'/></joint><link name='lever'>"
      "<inertial><origin xyz='0.5 0 0'/><mass value='2'/><inertia ixx='0' ixy='0' ixz='0' "
      "iyy='0' iyz='0' izz='0'/></inertial></link></robot>",
      {"", "lever"});
  const auto reflected = covopt::robot::ReflectedMass(arm, Eigen::VectorXd::Zero(1),
                                                      Eigen::Vector3d(0.5, 0, 0), Eigen::Vector3d::UnitY());
  std::printf("%s\n", reflected.message.c_str());
  if (std::abs(*reflected.reflected_mass_kg - 2.0) > 1e-12) return 1;
  std::printf("consumer: ok\n");
  return 0;
}
