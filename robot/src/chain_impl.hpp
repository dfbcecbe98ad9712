#pragma once
/// @file chain_impl.hpp
/// KinematicChain's insides (private to covopt_robot): the KDL chain and what the public
/// accessors return.

#include <string>
#include <vector>

#include <Eigen/Core>
#include <kdl/chain.hpp>
#include <kdl/jntarray.hpp>

#include "covopt/robot/kinematic_chain.hpp"

namespace covopt::robot {

struct KinematicChain::Impl {
  std::string robot_name;
  std::string source_name;
  std::string base_link;
  std::string tip_link;
  std::vector<ChainJoint> joints;
  std::vector<std::string> joint_names;
  double moving_mass_kg = 0.0;
  std::vector<std::string> lumped_joint_names;
  std::vector<std::string> warnings;
  KDL::Chain chain;
};

namespace internal {

/// Checks q against the chain (length, finite values) and copies it into a KDL::JntArray.
/// @throws std::invalid_argument "joints: ..." naming the joint and value.
KDL::JntArray ToJntArray(const KinematicChain& chain, const Eigen::VectorXd& q,
                         const char* what = "joints");

/// Checks that every component of `v` is finite.
/// @throws std::invalid_argument "<what>: component <i> must be finite (got nan)".
void CheckFinite(const Eigen::Vector3d& v, const char* what);

}  // namespace internal
}  // namespace covopt::robot
