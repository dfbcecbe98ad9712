// The audit in user code, built against the installed covopt package with
// find_package(covopt COMPONENTS audit) only: a one-joint lever with a collision sphere swings
// through two samples; AssembleAudit takes its URDF text, the samples and the chest (transient)
// with a bare robot's contact area; Audit judges it. The reflected mass of the sphere's centre
// is the lever's 2 kg (a point mass at 0.5 m, the sphere around it), and the verdict is an answer.
#include <cmath>
#include <cstdio>
#include <string>

#include <covopt/audit/assemble.hpp>
#include <covopt/audit/audit.hpp>
#include <covopt/materials/body_regions.hpp>

int main() {
  const std::string urdf =
      "<robot name='lever'><link name='base'/><joint name='j' type='continuous'>"
      "<parent link='base'/><child link='lever'/><axis xyz='0 0 1'/></joint><link name='lever'>"
      "<inertial><origin xyz='0.5 0 0'/><mass value='2'/><inertia ixx='0' ixy='0' ixz='0' "
      "iyy='0' iyz='0' izz='0'/></inertial>"
      "<collision><origin xyz='0.5 0 0'/><geometry><sphere radius='0.05'/></geometry></collision></link></robot>";
  covopt::audit::AuditInputs in(covopt::robot::KinematicChain::FromUrdfString(urdf, {"", "lever"}), "");
  in.urdf_text = urdf;
  covopt::robot::JointTrajectory samples;
  samples.time_s = {0.0, 0.1};
  samples.positions = {Eigen::VectorXd::Constant(1, 0.0), Eigen::VectorXd::Constant(1, 0.1)};
  samples.velocities = {Eigen::VectorXd::Constant(1, 1.0), Eigen::VectorXd::Constant(1, 1.0)};
  in.trajectory = samples;
  in.scene.covering.thickness_m = 0.0;  // bare: judged on its contact area
  in.contact_area_m2 = 1e-4;
  in.regions = {covopt::materials::BodyRegionTable::BuiltIn().Limits("chest", "", covopt::ContactType::kTransient)};
  const covopt::audit::AssembledAudit audit = covopt::audit::AssembleAudit(in);
  const covopt::audit::AuditResult result = covopt::audit::Audit(audit.setup, audit.trajectory, audit.options);
  std::printf("%s\n", result.message.c_str());
  if (!result.limiting_cell) return 1;
  const covopt::audit::AuditCell& cell = result.cells[*result.limiting_cell];
  // Every point of the sphere reflects the lever's mass scaled by (0.5 m / its distance)².
  if (!(cell.reflected_mass_kg > 2.0 * std::pow(0.5 / 0.55, 2) * 0.999 &&
        cell.reflected_mass_kg < 2.0 * std::pow(0.5 / 0.45, 2) * 1.001)) {
    return 1;
  }
  if (!(result.safe_speed_scale > 0.0 && std::isfinite(result.safe_speed_scale))) return 1;
  std::printf("audit consumer: ok\n");
  return 0;
}
