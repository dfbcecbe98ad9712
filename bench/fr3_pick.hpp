#pragma once
// The shipped Franka FR3 model and its pick move (robot/models/), shared by
// bench_link_kinematics.cpp, bench_audit.cpp and bench_html_report.cpp: loaded once per process.
#include <string>
#include <utility>
#include <vector>

#include <covopt/materials/body_regions.hpp>
#include <covopt/materials/catalog.hpp>
#include <covopt/audit/audit.hpp>
#include <covopt/optim/design.hpp>

#include <covopt/robot/kinematic_chain.hpp>
#include <covopt/robot/surface.hpp>
#include <covopt/robot/trajectory.hpp>

inline const std::string kFr3Urdf = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3.urdf";

/// The FR3 from its base to the flange (fr3_link8).
inline const covopt::robot::KinematicChain& Fr3() {
  static const covopt::robot::KinematicChain chain =
      covopt::robot::KinematicChain::FromUrdfFile(kFr3Urdf, {"", "fr3_link8"});
  return chain;
}

/// robot/models/franka_fr3_pick.csv: 101 samples, 1.5 s.
inline const covopt::robot::JointTrajectory& Pick() {
  static const covopt::robot::JointTrajectory trajectory =
      covopt::robot::ReadJointTrajectory(std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3_pick.csv", 7);
  return trajectory;
}

/// An audit of the FR3 on `surface` against every transient body region of ISO/TS 15066 and
/// the head (Park et al.), every link wearing 10 mm of PORON 4701-30 320.
inline covopt::audit::AuditSetup Fr3AuditSetup(covopt::robot::RobotSurface surface) {
  covopt::audit::AuditSetup setup{Fr3(), std::move(surface)};
  const std::vector<std::string> names{"PU foam PORON 4701-30 320"};
  const covopt::optim::CandidateMaterial foam =
      covopt::optim::SelectCandidates(covopt::materials::Catalog::BuiltIn(), names).front();
  setup.covering = {covopt::CoveringSpec{foam.youngs_modulus_Pa, foam.poisson_ratio, 0.01}, foam};
  setup.regions = covopt::materials::BodyRegionTable::BuiltIn().AllLimits(covopt::ContactType::kTransient);
  setup.head = covopt::Scene{};
  return setup;
}
