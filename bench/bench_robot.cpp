// Benchmarks of the robot model and the trajectory check on the shipped Franka FR3
// (robot/models/franka_fr3.urdf) at its "ready" configuration (robot/models/README.md):
// robot::ReflectedMass along a direction and the extremes alone, robot::ContactMotion per
// sample, and optim::CheckTrajectory per sample of the shipped pick trajectory
// (robot/models/franka_fr3_pick.csv; items = samples, so "items_per_second" is samples/s).
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include <covopt/core/scene.hpp>
#include <covopt/optim/trajectory_check.hpp>
#include <covopt/robot/kinematic_chain.hpp>
#include <covopt/robot/reflected_mass.hpp>
#include <covopt/robot/trajectory.hpp>

namespace {

const std::string kModels = COVOPT_ROBOT_MODELS_DIR;

const covopt::robot::KinematicChain& Fr3() {
  static const covopt::robot::KinematicChain chain =
      covopt::robot::KinematicChain::FromUrdfFile(kModels + "/franka_fr3.urdf", {"", "fr3_link8"});
  return chain;
}

Eigen::VectorXd Ready() {
  constexpr double pi = std::numbers::pi;
  Eigen::VectorXd q(7);
  q << 0.0, -pi / 4, 0.0, -3 * pi / 4, 0.0, pi / 2, pi / 4;
  return q;
}

const covopt::robot::JointTrajectory& Pick() {
  static const covopt::robot::JointTrajectory trajectory =
      covopt::robot::ReadJointTrajectory(kModels + "/franka_fr3_pick.csv", 7);
  return trajectory;
}

/// Along (1, 0, 0) (arg 1) or the extremes alone (arg 0).
void BM_ReflectedMassFr3(benchmark::State& state) {
  const covopt::robot::KinematicChain& chain = Fr3();
  const Eigen::VectorXd q = Ready();
  std::optional<Eigen::Vector3d> direction;
  if (state.range(0) == 1) direction = Eigen::Vector3d(1.0, 0.0, 0.0);
  for (auto _ : state) {
    benchmark::DoNotOptimize(covopt::robot::ReflectedMass(chain, q, Eigen::Vector3d::Zero(), direction));
  }
}
BENCHMARK(BM_ReflectedMassFr3)->Arg(0)->Arg(1);

void BM_ContactMotionFr3Pick(benchmark::State& state) {
  const covopt::robot::JointTrajectory& trajectory = Pick();
  for (auto _ : state) {
    benchmark::DoNotOptimize(covopt::robot::ContactMotion(Fr3(), trajectory, Eigen::Vector3d::Zero()));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<benchmark::IterationCount>(trajectory.size()));
}
BENCHMARK(BM_ContactMotionFr3Pick);

void BM_CheckTrajectoryFr3Pick(benchmark::State& state) {
  const covopt::robot::ContactMotionResult motion =
      covopt::robot::ContactMotion(Fr3(), Pick(), Eigen::Vector3d::Zero());
  const std::vector<covopt::optim::MotionSample> samples = covopt::optim::MotionSamples(motion.samples);
  const covopt::Scene scene;  // the paper's covering and head
  for (auto _ : state) benchmark::DoNotOptimize(covopt::optim::CheckTrajectory(scene, samples));
  state.SetItemsProcessed(state.iterations() * static_cast<benchmark::IterationCount>(samples.size()));
}
BENCHMARK(BM_CheckTrajectoryFr3Pick);

}  // namespace
