#include "covopt/robot/payload.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "chain_impl.hpp"
#include "covopt/robot/kinematic_chain.hpp"

namespace covopt::robot {

Eigen::Matrix3d Payload::InertiaFromSix(double ixx, double iyy, double izz, double ixy, double ixz,
                                        double iyz) {
  Eigen::Matrix3d tensor;
  tensor << ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz;
  return tensor;
}

void CheckPayload(const Payload& payload, const std::string& where) {
  using internal::Refuse;
  if (!(payload.mass_kg >= 0.0 && payload.mass_kg <= kMaxPayloadMassKg)) {
    Refuse(where, "mass", payload.mass_kg, "a mass in [0, 1e4] kg");
  }
  static constexpr std::array<const char*, 3> kAxes{"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    const double value = payload.center_of_mass_m[i];
    if (!(std::abs(value) <= kMaxPayloadOffsetM)) {
      Refuse(where, std::string("centre of mass ") + kAxes[static_cast<std::size_t>(i)], value,
             "a finite length within ±10 m of the tip frame's origin; millimetres need a unit");
    }
  }
  const Eigen::Matrix3d& tensor = payload.inertia_kg_m2;
  static constexpr std::array<std::array<const char*, 3>, 3> kNames{
      {{"ixx", "ixy", "ixz"}, {"iyx", "iyy", "iyz"}, {"izx", "izy", "izz"}}};
  double largest = 0.0;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      const double value = tensor(r, c);
      if (!(std::abs(value) <= kMaxInertiaKgM2)) {
        Refuse(where, std::string("inertia ") + kNames[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)],
               value, "a finite number within ±1e12 kg m²");
      }
      largest = std::max(largest, std::abs(value));
    }
  }
  for (int r = 0; r < 3; ++r) {
    for (int c = r + 1; c < 3; ++c) {
      if (std::abs(tensor(r, c) - tensor(c, r)) > 1e-9 * largest) {
        std::ostringstream allowed;
        allowed << "an inertia tensor is symmetric, but "
                << kNames[static_cast<std::size_t>(c)][static_cast<std::size_t>(r)] << " = " << tensor(c, r)
                << " kg m²";
        Refuse(where, std::string("inertia ") + kNames[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)],
               tensor(r, c), allowed.str());
      }
    }
  }
  internal::CheckPrincipalMoments(tensor, where, "inertia");
  if (payload.mass_kg == 0.0 && (!payload.center_of_mass_m.isZero(0.0) || !tensor.isZero(0.0))) {
    throw std::invalid_argument(where + ": a centre of mass or inertia without a mass is not allowed (give "
                                           "the mass in kg, > 0)");
  }
}

double IsoEffectiveMassKg(double moving_mass_kg, double payload_mass_kg) {
  using internal::Refuse;
  if (!(moving_mass_kg > 0.0 && moving_mass_kg <= kMaxLinkMassKg)) {
    Refuse("ISO/TS 15066 effective mass", "moving mass M", moving_mass_kg,
           "the total mass of the robot's moving parts, in (0, 1e6] kg");
  }
  if (!(payload_mass_kg >= 0.0 && payload_mass_kg <= kMaxPayloadMassKg)) {
    Refuse("ISO/TS 15066 effective mass", "payload mass m_L", payload_mass_kg,
           "the payload with tooling and workpiece, in [0, 1e4] kg");
  }
  return 0.5 * moving_mass_kg + payload_mass_kg;
}

}  // namespace covopt::robot
