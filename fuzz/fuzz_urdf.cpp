// libFuzzer target: the URDF reader (robot::KinematicChain::FromUrdfString, base = the root,
// tip = the link named "tip"), then a reflected mass at a fixed configuration inside the joint
// limits if the chain builds. Bad input must end in std::invalid_argument; an accepted chain
// must give reflected masses that are positive or +infinity ("fixed"), never NaN, with finite
// unit directions and a finite contact point. Anything else (a crash, a hang, a sanitizer
// report, another exception, a NaN) is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "covopt/robot.hpp"

namespace {

bool Mass(double kg) { return !std::isnan(kg) && kg > 0.0; }  // +infinity: fixed

bool Unit(const Eigen::Vector3d& v) { return v.allFinite() && std::abs(v.norm() - 1.0) < 1e-6; }

/// A configuration inside each joint's limits: 40 % of the way from lower to upper, else 0.3.
Eigen::VectorXd Configuration(const covopt::robot::KinematicChain& chain) {
  Eigen::VectorXd q(static_cast<Eigen::Index>(chain.joint_count()));
  Eigen::Index i = 0;
  for (const covopt::robot::ChainJoint& joint : chain.joints()) {
    if (joint.type == covopt::robot::JointType::kFixed) continue;
    const auto& limits = joint.limits;
    q[i++] = limits.has_position ? limits.lower + 0.4 * (limits.upper - limits.lower) : 0.3;
  }
  return q;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const auto chain = covopt::robot::KinematicChain::FromUrdfString(text, {"", "tip"}, "fuzz.urdf");
    if (chain.joint_count() == 0 || !std::isfinite(chain.moving_mass_kg())) std::abort();
    const auto result = covopt::robot::ReflectedMass(chain, Configuration(chain), Eigen::Vector3d(0.01, 0.02, 0),
                                                     Eigen::Vector3d(1.0, 0.5, -0.2));
    if (!Mass(*result.reflected_mass_kg) || !Mass(result.min_reflected_mass_kg) ||
        !Mass(result.max_reflected_mass_kg) || !Unit(*result.direction) || !Unit(result.min_direction) ||
        !Unit(result.max_direction) || !result.contact_point_m.allFinite()) {
      std::abort();  // an accepted robot gave a NaN or a non-unit direction
    }
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
