#pragma once
/// @file payload.hpp
/// A tool or payload rigidly mounted on the chain's tip link (the flange): a gripper with the
/// part it holds. It moves with the tip, so it counts in the reflected mass: the chain adds it,
/// as a rigid body, to the tip segment's inertia (ChainSpec::payload).
///
///     covopt::robot::Payload tool;
///     tool.mass_kg = 1.2;                                     // gripper and part
///     tool.center_of_mass_m = {0.0, 0.0, 0.08};               // tip frame [m]
///     tool.inertia_kg_m2 = Eigen::Vector3d(2e-3, 2e-3, 1e-3).asDiagonal();  // about the CoM
///     spec.payload = tool;
///
/// And, for a user without a robot model, ISO/TS 15066:2016's own estimate of the robot's
/// effective mass, m_R = M/2 + m_L (IsoEffectiveMassKg).

#include <string>

#include <Eigen/Core>

namespace covopt::robot {

/// The heaviest payload accepted [kg]: 10 t, above the heaviest industrial robot's rated
/// payload (2.3 t); more is a typo or grams.
inline constexpr double kMaxPayloadMassKg = 1e4;
/// The farthest a payload's centre of mass may lie from the tip frame's origin, per
/// coordinate [m]; more is almost surely millimetres.
inline constexpr double kMaxPayloadOffsetM = 10.0;

/// A rigid body on the tip link. All zero (the default): no payload, and the chain is exactly
/// the URDF's.
struct Payload {
  /// The mass of tool and part [kg], in [0, kMaxPayloadMassKg].
  double mass_kg = 0.0;
  /// The centre of mass in the tip link's frame [m], each coordinate within
  /// ±kMaxPayloadOffsetM.
  Eigen::Vector3d center_of_mass_m = Eigen::Vector3d::Zero();
  /// The inertia tensor about the centre of mass, in the tip link's axes [kg m²]: symmetric,
  /// positive semi-definite, its principal moments obeying the triangle inequality. Zero: a
  /// point mass. Off-diagonal entries are the tensor's own (URDF's ixy = -∫xy dm), as KDL's.
  Eigen::Matrix3d inertia_kg_m2 = Eigen::Matrix3d::Zero();

  /// No mass, no inertia: nothing is added to the chain.
  bool empty() const noexcept { return mass_kg == 0.0 && inertia_kg_m2.isZero(0.0); }
  /// The tensor from its six values [kg m²], in the order of URDF's <inertia> and KDL:
  /// ixx, iyy, izz, ixy, ixz, iyz.
  static Eigen::Matrix3d InertiaFromSix(double ixx, double iyy, double izz, double ixy, double ixz,
                                        double iyz);
};

/// Checks a payload; `where` starts the message ("payload").
/// @throws std::invalid_argument in one line naming the field, the value and why: a mass that
///         is negative, not finite or above kMaxPayloadMassKg; a centre of mass or inertia
///         given without a mass; a centre-of-mass coordinate not finite or beyond
///         kMaxPayloadOffsetM; an inertia entry not finite or beyond ±1e12 kg m²; a tensor
///         that is not symmetric (to 1e-9 of its largest entry), has a negative principal
///         moment, or whose largest principal moment exceeds the sum of the other two (both to
///         1e-6 of the largest moment, as for a URDF's <inertia>).
void CheckPayload(const Payload& payload, const std::string& where = "payload");

/// ISO/TS 15066:2016, Annex A, A.3.2 (eq. A.4): the effective mass of the robot for the
/// transient-contact energy, m_R = M/2 + m_L [kg], where M is the total mass of the robot's
/// moving parts [kg] and m_L the effective payload, tooling and workpiece included [kg]. The
/// standard's estimate for a user without a robot model; the reflected mass from a URDF
/// (ReflectedMass) is the better one where a model exists.
/// @throws std::invalid_argument naming "moving mass M" or "payload mass m_L" and the value
///         unless M is finite, > 0 and at most 1e6 kg (kMaxLinkMassKg) and m_L is finite in
///         [0, kMaxPayloadMassKg].
double IsoEffectiveMassKg(double moving_mass_kg, double payload_mass_kg);

}  // namespace covopt::robot
