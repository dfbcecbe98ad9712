// The force law of docs/model.md §2: validation of a Scene and construction of the segments.
#include "covopt/core/impact_model.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "covopt/core/physical_floors.hpp"
#include "numeric_format.hpp"
#include "range_check.hpp"
#include "robot_reaction.hpp"

namespace covopt {
namespace {

using internal::FormatNumber;

constexpr double kMinSpeed_m_per_s = 1e-6;  // see CheckScene
constexpr double kHertzPressureFactor = 3.0 / (2.0 * std::numbers::pi);  // k = 3/(2π)

using internal::CheckInRange;
using internal::CheckZeroOrInRange;

[[noreturn]] void Reject(const std::string& field, const std::string& requirement, double value) {
  internal::RejectValue(field, requirement, value);
}

[[noreturn, gnu::cold, gnu::noinline]] void RejectPoisson(const char* field, double value) {
  Reject(field, "in (-1, 0.5]", value);
}

inline void CheckPoisson(const char* field, double value) {
  if (!(value > -1.0 && value <= 0.5)) RejectPoisson(field, value);
}

/// finite and in [0, max] [unit].
void CheckNonNegative(const char* field, double value, double max, const char* unit,
                      const char* zero_means) {
  if (value >= 0.0 && value <= max) return;
  Reject(field, "in [0, " + FormatNumber(max) + "] " + unit + " (0 = " + zero_means + ")", value);
}

/// An elastic modulus [Pa]: from the floor kMinModulus_Pa to 1e13 Pa.
inline void CheckModulus(const char* field, double value) {
  CheckInRange(field, value, kMinModulus_Pa, 1e13, "Pa");
}

/// The inputs of the scenes beyond the conservative two-mass model (docs/model.md §10): out
/// of line, since the paper's scene (all zero) skips it.
[[gnu::noinline]] void CheckExtendedScene(const Scene& s) {
  CheckNonNegative("model.damping", s.model.damping_s_per_m, 1e3, "s/m", "no damping");
  internal::CheckRobotReaction(s.robot.reaction_delay_s, s.robot.braking_m_per_s2, s.robot.mass_kg);
  const HeadSpec& h = s.head;
  CheckNonNegative("head.neck_stiffness", h.neck_stiffness_N_per_m, 1e9, "N/m", "no neck spring");
  CheckNonNegative("head.neck_damping", h.neck_damping_N_s_per_m, 1e7, "N*s/m", "no neck damper");
  const bool neck = h.neck_stiffness_N_per_m > 0.0 || h.neck_damping_N_s_per_m > 0.0;
  if (h.torso_mass_kg == 0.0) {
    if (neck) {
      throw std::invalid_argument(
          "head.torso_mass is needed for a neck: head.neck_stiffness and head.neck_damping "
          "connect the head to a torso (give head.torso_mass in [0.001, 1e+06] kg or fixed)");
    }
    return;
  }
  CheckInRange("head.torso_mass", h.torso_mass_kg, kMinMass_kg, 1e6, "kg", "fixed (infinite), or 0 for no neck");
  if (!neck) {
    throw std::invalid_argument(
        "head.torso_mass is given but the neck has neither stiffness nor damping (give "
        "head.neck_stiffness or head.neck_damping > 0, or no torso) (got head.torso_mass " +
        FormatNumber(h.torso_mass_kg) + " kg)");
  }
  if (std::isinf(h.mass_kg)) {
    throw std::invalid_argument(
        "head.torso_mass needs a head that moves: head.mass is fixed, so the neck would carry "
        "nothing (give a finite head.mass, or no torso)");
  }
  // The time floor holds for the neck too: its damper relaxes the head against the torso in
  // μ_n / c_n (μ_n the two bodies' reduced mass). Below 1 µs it is a rigid link, and the time
  // path's explicit integrators run out of steps (1 g torso, 1e7 N*s/m: τ = 1e-10 s).
  const double neck_mass_kg = 1.0 / (1.0 / h.mass_kg + (std::isinf(h.torso_mass_kg) ? 0.0 : 1.0 / h.torso_mass_kg));
  const double max_neck_damping = neck_mass_kg / kMinTime_s;
  if (h.neck_damping_N_s_per_m > max_neck_damping) {
    Reject("head.neck_damping",
           "in [0, " + FormatSignificant(max_neck_damping) + "] N*s/m for head.mass " + FormatNumber(h.mass_kg) +
               " kg and head.torso_mass " + FormatNumber(h.torso_mass_kg) +
               " kg: a stiffer damper stops the head against the torso within 1 us, below the model's time floor",
           h.neck_damping_N_s_per_m);
  }
  if (std::isinf(h.torso_mass_kg) && std::isinf(s.robot.mass_kg)) {
    throw std::invalid_argument(
        "robot.mass and head.torso_mass are both fixed: the robot would drive the head into the "
        "torso for ever and the contact could never end (give a finite mass in [0.001, 1e+06] kg to "
        "one of them)");
  }
}

}  // namespace

void internal::CheckRobotReaction(double reaction_delay_s, double braking_m_per_s2, double robot_mass_kg) {
  CheckZeroOrInRange("robot.reaction_delay", reaction_delay_s, kMinTime_s, 10.0, "s", "brake at contact");
  CheckNonNegative("robot.braking", braking_m_per_s2, 1e4, "m/s2", "no braking");
  if (braking_m_per_s2 > 0.0 && std::isinf(robot_mass_kg)) {
    throw std::invalid_argument(
        "robot.braking needs a robot that moves: robot.mass is fixed (give a finite robot.mass, "
        "or braking 0)");
  }
}

namespace {

/// The covering's law (docs/model.md §16): a known value; kFoam needs a curve where there is a
/// covering (a bare scene, e.g. optimize's covering to be designed, has none to read); the foam law
/// has no damped, braking, neck or literal-threshold variant (those are Park's chain's).
void CheckCoveringLaw(const Scene& s) {
  const CoveringLaw law = s.covering.law;
  if (law != CoveringLaw::kAuto && law != CoveringLaw::kFoam && law != CoveringLaw::kHertz) {
    throw std::invalid_argument("covering.law must be auto, foam or hertz (got " +
                                std::to_string(static_cast<int>(law)) + ")");
  }
  if (law == CoveringLaw::kFoam && !s.covering.compressive_curve && s.covering.thickness_m > 0.0) {
    throw std::invalid_argument(
        "covering.law is foam but the covering has no compressive_curve: the foam law needs the "
        "material's measured curve (give one, or covering.law auto or hertz)");
  }
  if (!(s.covering.thickness_m > 0.0) || law == CoveringLaw::kHertz || !s.covering.compressive_curve) return;
  auto refuse = [](const std::string& field, const std::string& value) {
    throw std::invalid_argument(field + " (" + value +
                                ") is not modelled with the foam law of a covering with a measured curve "
                                "(docs/model.md §16): give covering.law hertz, or leave " + field + " at its default");
  };
  if (s.model.damping_s_per_m != 0.0) refuse("model.damping", FormatNumber(s.model.damping_s_per_m) + " s/m");
  if (s.robot.braking_m_per_s2 != 0.0) refuse("robot.braking", FormatNumber(s.robot.braking_m_per_s2) + " m/s2");
  if (s.head.torso_mass_kg != 0.0) refuse("head.torso_mass", FormatNumber(s.head.torso_mass_kg) + " kg");
  if (s.model.thresholds != ThresholdReading::kCumulative) refuse("model.thresholds", "literal");
}

void CheckScene(const Scene& s) {
  CheckInRange("robot.mass", s.robot.mass_kg, kMinMass_kg, 1e6, "kg", "fixed (infinite)");
  // Below ~1e-150 m/s the energy ½mv² underflows and the contact duration is NaN; 1 µm/s
  // is far below any impact and keeps every quantity of the exact path finite.
  if (!(s.robot.speed_m_per_s >= kMinSpeed_m_per_s && s.robot.speed_m_per_s <= 100.0)) {
    Reject("robot.speed", "in [" + FormatNumber(kMinSpeed_m_per_s) + ", 100] m/s", s.robot.speed_m_per_s);
  }
  CheckInRange("robot.radius", s.robot.radius_m, kMinRadius_m, 100.0, "m", "flat (infinite)");
  CheckModulus("robot.modulus", s.robot.youngs_modulus_Pa);
  CheckPoisson("robot.poisson", s.robot.poisson_ratio);

  const double b_c = s.covering.thickness_m;
  CheckZeroOrInRange("covering.thickness", b_c, kMinLayerThickness_m, 1.0, "m", "no covering");
  if (b_c > 0.0) {
    CheckModulus("covering.modulus", s.covering.youngs_modulus_Pa);
    CheckPoisson("covering.poisson", s.covering.poisson_ratio);
  }
  CheckCoveringLaw(s);

  CheckInRange("head.mass", s.head.mass_kg, kMinMass_kg, 1e6, "kg", "fixed (infinite)");
  CheckInRange("head.radius", s.head.radius_m, kMinRadius_m, 10.0, "m");
  CheckModulus("scalp.modulus", s.scalp.youngs_modulus_Pa);
  CheckPoisson("scalp.poisson", s.scalp.poisson_ratio);
  CheckInRange("scalp.thickness", s.scalp.thickness_m, kMinLayerThickness_m, 1.0, "m");
  // The skull's radius, head.radius - scalp.thickness, is a radius too: at least the floor.
  if (!(s.head.radius_m - s.scalp.thickness_m >= kMinRadius_m)) {
    Reject("head.radius",
           "at least scalp.thickness + " + FormatSignificant(kMinRadius_m) + " m (the skull's least radius) = " +
               FormatSignificant(s.scalp.thickness_m + kMinRadius_m) + " m",
           s.head.radius_m);
  }
  CheckModulus("skull.modulus", s.skull.youngs_modulus_Pa);
  CheckPoisson("skull.poisson", s.skull.poisson_ratio);

  if (std::isinf(s.robot.mass_kg) && std::isinf(s.head.mass_kg)) {
    throw std::invalid_argument(
        "robot.mass and head.mass are both fixed: at least one body must be free to move "
        "(give a finite mass in [0.001, 1e+06] kg to one of them)");
  }

  const ModelConstants& m = s.model;
  auto check_exponent = [](const char* field, double n) {
    if (!(n >= 1.0 && n <= 5.0)) Reject(field, "in [1, 5]", n);
  };
  check_exponent("model.exponent_covering_scalp", m.exponent_covering_scalp);
  check_exponent("model.exponent_covering_bone", m.exponent_covering_bone);
  check_exponent("model.exponent_robot_bone", m.exponent_robot_bone);
  CheckPoisson("model.tensile_poisson", m.tensile_poisson_ratio);
  const double f = m.full_compression_fraction;
  if (!(f > 0.0 && f <= 1.0)) Reject("model.full_compression_fraction", "in (0, 1]", f);
  if (m.thresholds != ThresholdReading::kCumulative && m.thresholds != ThresholdReading::kLiteral) {
    throw std::invalid_argument("model.thresholds must be cumulative or literal");
  }
  if (m.damping_s_per_m != 0.0 || s.robot.reaction_delay_s != 0.0 ||
      s.robot.braking_m_per_s2 != 0.0 || s.head.torso_mass_kg != 0.0 ||
      s.head.neck_stiffness_N_per_m != 0.0 || s.head.neck_damping_N_s_per_m != 0.0) {
    CheckExtendedScene(s);
  }
}

/// Generalised Hertz stiffness K = 4/3 ((1-ν1²)/E1 + (1-ν2²)/E2)⁻¹ c^(-1/2)  (eq. 3).
double HertzStiffness(double e1, double nu1, double e2, double nu2, double curvature) {
  const double compliance = (1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2;
  return 4.0 / 3.0 / compliance / std::sqrt(curvature);
}

/// 1/R with 1/∞ = 0.
double Inverse(double radius) { return std::isinf(radius) ? 0.0 : 1.0 / radius; }

/// A power-law segment of §2 from `start` to +inf, its offsets zero (the caller sets them).
ForceLawSegment HertzSegment(Phase phase, double start, double origin, double stiffness, double exponent,
                             double curvature, double radius_a, double radius_b) {
  ForceLawSegment seg;
  seg.phase = phase;
  seg.start_m = start;
  seg.end_m = std::numeric_limits<double>::infinity();
  seg.origin_m = origin;
  seg.stiffness = stiffness;
  seg.exponent = exponent;
  seg.curvature_per_m = curvature;
  seg.radius_a_m = radius_a;
  seg.radius_b_m = radius_b;
  return seg;
}

}  // namespace

int PhaseNumber(Phase phase) noexcept {
  switch (phase) {
    case Phase::kCoveringOnScalp:
    case Phase::kRobotOnScalp: return 1;
    case Phase::kCoveringOnBone: return 2;
    case Phase::kRobotOnBone: return 3;
  }
  return 0;
}

std::string_view ToString(Phase phase) noexcept {
  switch (phase) {
    case Phase::kCoveringOnScalp: return "covering on scalp";
    case Phase::kRobotOnScalp: return "robot on scalp";
    case Phase::kCoveringOnBone: return "covering on bone";
    case Phase::kRobotOnBone: return "robot on bone";
  }
  return "unknown";
}

void ImpactModel::BuildFoamLaw(double t1, double c1, double c3, double r_cover, double r_bone) {
  // The layer takes the whole compression up to its curve's end (the scalp beside it is rigid
  // under its spread pressure), then is a rigid stop (docs/model.md §16).
  const Scene& s = scene_;
  covering_law_ = CoveringLaw::kFoam;
  const CompressiveCurve& curve = *s.covering.compressive_curve;
  const double h = s.covering.thickness_m;
  const double r_robot = s.robot.radius_m, r_scalp = s.head.radius_m;
  ForceLawSegment& foam = segments_[0];
  foam.phase = Phase::kCoveringOnScalp;
  foam.end_m = curve.last_strain() * h;
  foam.exponent = 2.0;  // F grows as δ² from contact; unused by the foam law's formulas
  foam.curvature_per_m = c1;  // 1/R, R = 1/(1/R_c + 1/R_s) the relative radius
  foam.radius_a_m = r_cover;
  foam.radius_b_m = r_scalp;
  foam.curve = &curve;
  foam.foam_thickness_m = h;
  foam.foam_area_m2 = 2.0 * std::numbers::pi / c1 * h;
  segment_count_ = 1;

  // Past the stop δ_s the robot presses the head as the bare robot does (robot on scalp, K1 up
  // to t1, then robot on bone, K3), its chain continued from the penetration x_s at which it
  // carries the layer's force F(δ_s): F(δ) = F_bare(x_s + δ − δ_s), U(δ) = U(δ_s) +
  // U_bare(x_s + δ − δ_s) − U_bare(x_s), σ_c and e likewise. The segments' origins lie x_s
  // before the stop (as the literal reading's do), so the force is continuous there.
  const double stop = foam.end_m;
  const ContactState at_stop = StateInSegment(0, stop);
  const double c1_bare = Inverse(r_robot) + 1.0 / r_scalp;
  const double k1 = HertzStiffness(s.robot.youngs_modulus_Pa, s.robot.poisson_ratio, s.scalp.youngs_modulus_Pa,
                                   s.scalp.poisson_ratio, c1_bare);
  const double k3 = HertzStiffness(s.robot.youngs_modulus_Pa, s.robot.poisson_ratio, s.skull.youngs_modulus_Pa,
                                   s.skull.poisson_ratio, c3);
  const double n1 = s.model.exponent_covering_scalp, n3 = s.model.exponent_robot_bone;
  const double force_t1 = k1 * std::pow(t1, n1);  // the bare robot's F at full scalp compression
  const double stress_t1 = kHertzPressureFactor * k1 * c1_bare * std::pow(t1, n1 - 1.0);
  ForceLawSegment& next = segments_[1];
  if (at_stop.force_N < force_t1) {
    // Robot on scalp from x_s = (F/K1)^(1/n1), then robot on bone at x_s + δ − δ_s = t1.
    const double origin = stop - std::pow(at_stop.force_N / k1, 1.0 / n1);
    next = HertzSegment(Phase::kRobotOnScalp, stop, origin, k1, n1, c1_bare, r_robot, r_scalp);
    next.end_m = origin + t1;
  } else {
    // The layer carried more than the bare scalp takes: robot on bone at once, from
    // x_s = t1 + ((F − F1)/K3)^(1/n3) of the bare chain.
    const double origin = stop - std::pow((at_stop.force_N - force_t1) / k3, 1.0 / n3);
    next = HertzSegment(Phase::kRobotOnBone, stop, origin, k3, n3, c3, r_robot, r_bone);
    next.force_offset_N = force_t1;
    next.stress_offset_Pa = stress_t1;
  }
  next.energy_at_start_J = at_stop.potential_energy_J;
  next.energy_density_at_start_J_per_m2 = at_stop.energy_density_J_per_m2;
  segment_count_ = 2;
  if (next.phase == Phase::kRobotOnBone) return;
  ForceLawSegment& bone = segments_[2];
  bone = HertzSegment(Phase::kRobotOnBone, next.end_m, next.end_m, k3, n3, c3, r_robot, r_bone);
  const ContactState at_bone = StateInSegment(1, bone.start_m);
  bone.force_offset_N = at_bone.force_N;
  bone.stress_offset_Pa = at_bone.compressive_stress_Pa;
  bone.energy_at_start_J = at_bone.potential_energy_J;
  bone.energy_density_at_start_J_per_m2 = at_bone.energy_density_J_per_m2;
  segment_count_ = 3;
}

ImpactModel ImpactModel::FromScene(const Scene& scene) {
  CheckScene(scene);
  ImpactModel model;
  model.scene_ = scene;
  const Scene& s = model.scene_;
  const ModelConstants& constants = s.model;

  model.effective_mass_kg_ = 1.0 / (Inverse(s.robot.mass_kg) + Inverse(s.head.mass_kg));
  model.impact_energy_J_ =
      0.5 * model.effective_mass_kg_ * s.robot.speed_m_per_s * s.robot.speed_m_per_s;
  model.tensile_factor_ = (1.0 - 2.0 * constants.tensile_poisson_ratio) / 3.0;

  const bool covered = s.covering.thickness_m > 0.0;
  const double r_robot = s.robot.radius_m;
  const double r_cover = std::isinf(r_robot) ? r_robot : r_robot + s.covering.thickness_m;
  const double r_scalp = s.head.radius_m;
  const double r_bone = s.head.radius_m - s.scalp.thickness_m;
  // The body touching the scalp: the covering, or the bare robot (docs/model.md §2).
  const double e_outer = covered ? s.covering.youngs_modulus_Pa : s.robot.youngs_modulus_Pa;
  const double nu_outer = covered ? s.covering.poisson_ratio : s.robot.poisson_ratio;
  const double r_outer = covered ? r_cover : r_robot;

  const double c1 = Inverse(r_outer) + 1.0 / r_scalp;
  const double c2 = Inverse(r_cover) + 1.0 / r_bone;
  const double c3 = Inverse(r_robot) + 1.0 / r_bone;

  const double t1 = constants.full_compression_fraction * s.scalp.thickness_m;
  const double covering_travel = constants.full_compression_fraction * s.covering.thickness_m;

  std::size_t count = 0;
  auto add = [&](Phase phase, double start, double origin, double stiffness, double exponent,
                 double curvature, double radius_a, double radius_b) {
    ForceLawSegment seg = HertzSegment(phase, start, origin, stiffness, exponent, curvature, radius_a, radius_b);
    if (count > 0) {
      model.segments_[count - 1].end_m = start;
      // Offsets: the previous law at this segment's origin (F, σ) and start (U, e).
      // Cumulative: origin == start, so all four are continuous.
      const ContactState at_origin = model.StateInSegment(count - 1, origin);
      const ContactState at_start =
          start == origin ? at_origin : model.StateInSegment(count - 1, start);
      seg.force_offset_N = at_origin.force_N;
      seg.stress_offset_Pa = at_origin.compressive_stress_Pa;
      seg.energy_at_start_J = at_start.potential_energy_J;
      seg.energy_density_at_start_J_per_m2 = at_start.energy_density_J_per_m2;
    }
    model.segments_[count++] = seg;
    model.segment_count_ = count;
  };

  if (covered && s.covering.compressive_curve && s.covering.law != CoveringLaw::kHertz) {
    model.BuildFoamLaw(t1, c1, c3, r_cover, r_bone);
    return model;
  }

  add(covered ? Phase::kCoveringOnScalp : Phase::kRobotOnScalp, 0.0, 0.0,
      HertzStiffness(e_outer, nu_outer, s.scalp.youngs_modulus_Pa, s.scalp.poisson_ratio, c1),
      constants.exponent_covering_scalp, c1, r_outer, r_scalp);

  const double k3 = HertzStiffness(s.robot.youngs_modulus_Pa, s.robot.poisson_ratio,
                                   s.skull.youngs_modulus_Pa, s.skull.poisson_ratio, c3);
  if (!covered) {
    // Cumulative: phase 3 continues phase 1 at t1. Literal: eq. (2)'s if-chain with
    // b_cm = 0.8 b_c = 0 takes phase 3's law from δ > b_sm measured from 0, F = K_rb δ^n_rb
    // (offset F(0) = 0): the force and stress drop at t1 in the paper's scene.
    const double origin = constants.thresholds == ThresholdReading::kCumulative ? t1 : 0.0;
    add(Phase::kRobotOnBone, t1, origin, k3, constants.exponent_robot_bone, c3, r_robot, r_bone);
    return model;
  }

  const double k2 = HertzStiffness(s.covering.youngs_modulus_Pa, s.covering.poisson_ratio,
                                   s.skull.youngs_modulus_Pa, s.skull.poisson_ratio, c2);
  const double t2 = constants.thresholds == ThresholdReading::kCumulative ? t1 + covering_travel
                                                                          : covering_travel;
  if (t2 > t1) {
    add(Phase::kCoveringOnBone, t1, t1, k2, constants.exponent_covering_bone, c2, r_cover, r_bone);
    add(Phase::kRobotOnBone, t2, t2, k3, constants.exponent_robot_bone, c3, r_robot, r_bone);
  } else {
    // Literal reading with 0.8 b_c <= 0.8 b_s: eq. (2)'s if-chain gives phase 1 up to b_sm,
    // then phase 3 measured from b_cm with the offset F(b_cm) of phase 1.
    add(Phase::kRobotOnBone, t1, t2, k3, constants.exponent_robot_bone, c3, r_robot, r_bone);
  }
  return model;
}

std::size_t ImpactModel::SegmentIndexAt(double penetration_m) const noexcept {
  std::size_t i = 0;
  while (i + 1 < segment_count_ && penetration_m > segments_[i].end_m) ++i;
  return i;
}

namespace {

/// The foam law of segment `seg` at δ (docs/model.md §16), δ clamped to [0, the stop].
ContactState FoamState(const ForceLawSegment& seg, double penetration_m) noexcept {
  const CompressiveCurve& curve = *seg.curve;
  const double h = seg.foam_thickness_m;
  const double strain = std::clamp(penetration_m, 0.0, seg.end_m) / h;
  const double w = curve.EnergyDensityAt(strain);
  const double stress = curve.StressAt(strain);
  ContactState state;
  state.phase = seg.phase;
  state.force_N = seg.foam_area_m2 * w;
  state.potential_energy_J = seg.foam_area_m2 * h * curve.SecondIntegralAt(strain);
  state.compressive_stress_Pa = stress;
  state.energy_density_J_per_m2 = h * w;
  state.stiffness_N_per_m = seg.foam_area_m2 * stress / h;
  return state;
}

}  // namespace

double ImpactModel::TensileStressInSegment(std::size_t i, double penetration_m) const noexcept {
  const ForceLawSegment& seg = segments_[i];
  if (!seg.curve) return TensileFromCompressive(StateInSegment(i, penetration_m).compressive_stress_Pa);
  {
    // (1 − 2ν_t) F/(2π a²) with F = 2π R h W(ε), a² = 2 R δ: (1 − 2ν_t) W(ε)/(2ε) → 0 at contact.
    const double strain = std::clamp(penetration_m, 0.0, seg.end_m) / seg.foam_thickness_m;
    if (!(strain > 0.0)) return 0.0;
    return 1.5 * tensile_factor_ * seg.curve->EnergyDensityAt(strain) / strain;
  }
}

ContactState ImpactModel::StateInSegment(std::size_t i, double penetration_m) const noexcept {
  const ForceLawSegment& seg = segments_[i];
  if (seg.curve) [[unlikely]] return FoamState(seg, penetration_m);
  const double n = seg.exponent;
  const double x = std::max(penetration_m - seg.origin_m, 0.0);
  const double x0 = seg.start_m - seg.origin_m;  // > 0 only in the literal ill-ordered case
  const double d = penetration_m - seg.start_m;
  const double x_pow_nm1 = std::pow(x, n - 1.0);
  const double x_pow_n = x_pow_nm1 * x;
  const double kc = kHertzPressureFactor * seg.stiffness * seg.curvature_per_m;
  ContactState state;
  state.phase = seg.phase;
  state.force_N = seg.force_offset_N + seg.stiffness * x_pow_n;
  state.stiffness_N_per_m = n * seg.stiffness * x_pow_nm1;
  state.compressive_stress_Pa = seg.stress_offset_Pa + kc * x_pow_nm1;
  double u_local = seg.stiffness * x_pow_n * x / (n + 1.0);
  double e_local = kc * x_pow_n / n;
  if (x0 > 0.0) {
    // x^p - x0^p as x0^p expm1(p log1p(d/x0)): the difference of the two powers, each of
    // order K x0^p/p, which can far exceed U, cancelled just past the start (U and e were
    // off by up to 1e-5 there). x clamped at 0 is d/x0 = -1.
    const double log_growth = std::log1p(std::max(d / x0, -1.0));
    const double x0_pow_n = std::pow(x0, n);
    u_local = seg.stiffness * x0_pow_n * x0 * std::expm1((n + 1.0) * log_growth) / (n + 1.0);
    e_local = kc * x0_pow_n * std::expm1(n * log_growth) / n;
  }
  state.potential_energy_J = seg.energy_at_start_J + seg.force_offset_N * d + u_local;
  state.energy_density_J_per_m2 =
      seg.energy_density_at_start_J_per_m2 + seg.stress_offset_Pa * d + e_local;
  return state;
}

ContactState ImpactModel::StateAt(double penetration_m) const noexcept {
  if (!(penetration_m > 0.0)) {
    ContactState none;
    none.phase = segments_[0].phase;
    return none;
  }
  return StateInSegment(SegmentIndexAt(penetration_m), penetration_m);
}

double ImpactModel::EnergyDifferenceInSegment(std::size_t i, double upper_penetration_m,
                                              double gap_m) const noexcept {
  return EnergyGapBelow(*this, i, upper_penetration_m)(gap_m);
}

ImpactModel::EnergyGapBelow::EnergyGapBelow(const ImpactModel& model, std::size_t i,
                                            double upper_penetration_m) noexcept {
  const ForceLawSegment& seg = model.segments_[i];
  if (seg.curve) {
    // U(δ_b) − U(δ_b − g) = A h [W γ − σ γ²/2 + σ' γ³/6], γ = g/h, within δ_b's curve piece.
    foam_ = &seg;
    upper_local_m_ = upper_penetration_m;
    const CompressiveCurve& curve = *seg.curve;
    const double h = seg.foam_thickness_m;
    const double strain = std::clamp(upper_penetration_m / h, 0.0, curve.last_strain());
    const auto points = curve.points();
    const auto above = std::lower_bound(points.begin(), points.end(), strain,
                                        [](const StrainStressPoint& p, double e) { return p.strain < e; });
    const double piece_start = above == points.begin() ? 0.0 : std::prev(above)->strain;
    piece_gap_m_ = (strain - piece_start) * h;
    foam_w_ = seg.foam_area_m2 * h * curve.EnergyDensityAt(strain);
    foam_stress_ = seg.foam_area_m2 * curve.StressAt(strain);
    foam_slope_ = seg.foam_area_m2 * curve.SlopeAt(strain) / h;
    return;
  }
  force_offset_N_ = seg.force_offset_N;
  stiffness_ = seg.stiffness;
  power_ = seg.exponent + 1.0;
  upper_local_m_ = upper_penetration_m - seg.origin_m;
  upper_local_pow_ = upper_local_m_ > 0.0 ? std::pow(upper_local_m_, power_) : 0.0;
  inverse_upper_local_per_m_ = upper_local_m_ > 0.0 ? 1.0 / upper_local_m_ : 0.0;
  stiffness_over_power_ = stiffness_ / power_;
}

double ImpactModel::EnergyGapBelow::operator()(double gap_m) const noexcept {
  const double x_b = upper_local_m_;
  if (!(x_b > 0.0) || !(gap_m > 0.0)) return 0.0;
  if (foam_) [[unlikely]] {
    if (gap_m <= piece_gap_m_) {  // the cubic of δ_b's piece: W g/h − σ g²/(2h) + σ' g³/(6h) (scaled)
      return gap_m / foam_->foam_thickness_m *
             (foam_w_ - gap_m * (foam_stress_ / 2.0 - gap_m * foam_slope_ / 6.0));
    }
    const double h = foam_->foam_thickness_m;
    return foam_->foam_area_m2 * h * foam_->curve->SecondIntegralDrop(x_b / h, gap_m / h);
  }
  // x_b^p - x_a^p = -x_b^p expm1(p log1p(-d/x_b)), exact in relative terms for small d.
  const double ratio = gap_m * inverse_upper_local_per_m_;
  const double power_difference =
      ratio >= 1.0 ? upper_local_pow_ : -upper_local_pow_ * std::expm1(power_ * std::log1p(-ratio));
  return force_offset_N_ * gap_m + stiffness_over_power_ * power_difference;
}

}  // namespace covopt
