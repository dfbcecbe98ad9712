// libFuzzer target: the trajectory reader (robot::ReadJointTrajectory) for a fixed planar
// two-link arm (the one of tests/robot/data/planar_2link.urdf), then robot::ContactMotion on
// what it accepts. Bad input must end in std::invalid_argument; an accepted trajectory must
// have 1 + 2n finite numbers per sample in non-decreasing time, and give finite speeds and
// contact points, unit directions while moving, and reflected masses that are positive or
// +infinity, never NaN. Anything else is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>

#include "covopt/robot.hpp"
#include "planar_arm.hpp"

namespace {

using covopt::fuzz::Arm;

void CheckTrajectory(const covopt::robot::JointTrajectory& t) {
  if (t.size() == 0 || t.positions.size() != t.size() || t.velocities.size() != t.size()) std::abort();
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t.time_s[i]) || (i > 0 && t.time_s[i] < t.time_s[i - 1])) std::abort();
    if (t.positions[i].size() != 2 || t.velocities[i].size() != 2 || !t.positions[i].allFinite() ||
        !t.velocities[i].allFinite()) {
      std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const auto trajectory = covopt::robot::ReadJointTrajectory(in, 2, "fuzz.csv");
    CheckTrajectory(trajectory);
    const auto motion = covopt::robot::ContactMotion(Arm(), trajectory, Eigen::Vector3d(0.05, 0, 0));
    for (const auto& s : motion.samples) {
      if (!std::isfinite(s.speed_m_per_s) || !s.contact_point_m.allFinite() || std::isnan(s.reflected_mass_kg) ||
          !(s.reflected_mass_kg > 0.0) || (s.moving && std::abs(s.direction.norm() - 1.0) > 1e-6)) {
        std::abort();  // an accepted trajectory gave a NaN or a wrong direction
      }
    }
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
