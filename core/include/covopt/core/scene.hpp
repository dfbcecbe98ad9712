#pragma once
/// @file scene.hpp
/// The inputs of one robot-head impact: plain aggregates in SI units.
///
/// A Scene is what a user writes (or a scene file / the CLI fills in). It is not checked
/// here; ImpactModel::FromScene validates it and throws std::invalid_argument naming the
/// offending field. Defaults are the values of Park et al. (ICRA 2011) and of
/// docs/model.md §1: the paper's Sec. IV scene (10 kg robot at 2 m/s, R_r = 15 mm)
/// against a free 4.5 kg head, wearing the paper's recommended 15 mm, 27.6 MPa covering.

#include <limits>
#include <memory>
#include <string_view>

#include "covopt/core/compressive_curve.hpp"
#include "covopt/core/head_area.hpp"

namespace covopt {

/// Use as a mass [kg] for a body that does not move (a fixed robot/plate, a fixed head).
inline constexpr double kFixed = std::numeric_limits<double>::infinity();
/// Use as a radius [m] for a flat robot surface.
inline constexpr double kFlat = std::numeric_limits<double>::infinity();

/// How the phase thresholds of the piecewise force law are placed (docs/model.md §2, §4).
enum class ThresholdReading {
  /// Default. Phase 2 (covering on bone) starts at t1 = 0.8 b_s, phase 3 (robot on bone)
  /// at t2 = t1 + 0.8 b_c: the scalp and the covering compress one after the other.
  kCumulative,
  /// The paper's literal text: phase 3 starts at t2 = 0.8 b_c. Rejected by docs/model.md §4
  /// (it contradicts the paper's own Sec. IV numbers) and kept for comparison. When
  /// 0.8 b_c < 0.8 b_s the if-chain of eq. (2) is ill-ordered: phase 2 vanishes and the
  /// force jumps at t1, exactly as the literal equation says. Without a covering
  /// (0.8 b_c = 0) phase 3's law is measured from δ = 0 from t1 on: F = K_rb δ^n_rb, a drop
  /// in the paper's scene. The reported F_max and σ_c,max are then the largest over the
  /// contact, not the values at δ_max.
  kLiteral,
};

/// "cumulative" or "literal".
std::string_view ToString(ThresholdReading reading) noexcept;

/// The robot (impactor) as seen along the impact direction. Here and below every Young's
/// modulus is in [1e3, 1e13] Pa (the floor kMinModulus_Pa): the floors of
/// covopt/core/physical_floors.hpp bound every length, mass, time and modulus from below.
struct RobotSpec {
  /// Reflected mass in the impact direction [kg], in [1e-3, 1e6] (the floor kMinMass_kg,
  /// physical_floors.hpp); kFixed for an immovable plate.
  double mass_kg = 10.0;
  /// Relative approach speed at first contact [m/s], in [1e-6, 100].
  double speed_m_per_s = 2.0;
  /// Radius of curvature of the robot surface under the covering [m], in [1e-4, 100] (the
  /// floor kMinRadius_m); kFlat if flat.
  double radius_m = 0.015;
  /// Young's modulus of the robot structure [Pa] (aluminium by default).
  double youngs_modulus_Pa = 70e9;
  /// Poisson ratio of the robot structure [-], in (-1, 0.5].
  double poisson_ratio = 0.3;
  /// The robot's reaction (docs/model.md §10.2): from this long after first contact [s],
  /// 0 or in [1e-6, 10] (the floor kMinTime_s), the robot brakes with `braking_m_per_s2` while it still moves forward.
  double reaction_delay_s = 0.0;
  /// Braking deceleration [m/s²], in [0, 1e4]: a force m_r a against the robot's motion once
  /// the reaction delay has passed, until the robot stops. 0 (default): the robot does not
  /// brake. Needs a robot that moves (finite mass).
  double braking_m_per_s2 = 0.0;
};

/// The soft covering on the robot. thickness_m == 0 means no covering: the robot itself
/// touches the scalp (docs/model.md §2), and modulus and Poisson ratio are ignored.
struct CoveringSpec {
  /// Young's modulus of the covering [Pa] (the paper's polystyrene foam No. 1).
  double youngs_modulus_Pa = 27.6e6;
  /// Poisson ratio of the covering [-], in (-1, 0.5]; 0.25 is the paper's Fig. 9 value
  /// used when a continuous design needs one and none is given (docs/model.md §1).
  double poisson_ratio = 0.25;
  /// Covering thickness [m], 0 (no covering) or in [1e-4, 1] (the floor kMinLayerThickness_m).
  double thickness_m = 0.015;
  /// The material's measured compressive curve (covopt/core/compressive_curve.hpp), shared and
  /// immutable; null: none, and only the Hertz law describes the covering.
  std::shared_ptr<const CompressiveCurve> compressive_curve;
  /// Which law describes the covering: kAuto (the default) takes the foam law where a curve is
  /// given and Hertz otherwise; kFoam needs a curve.
  CoveringLaw law = CoveringLaw::kAuto;
};

/// The head as a rigid mass carrying the scalp.
struct HeadSpec {
  /// Head mass [kg], in [1e-3, 1e6]; kFixed for a head held still (drop tests on a fixed head).
  double mass_kg = 4.5;
  /// Outer radius of the head, i.e. of the scalp surface, R_s [m]; must exceed the scalp
  /// thickness.
  double radius_m = 0.08;
  /// A compliant neck (docs/model.md §10.3): the head hangs on a torso of this mass [kg] by
  /// a spring and a damper along the impact axis. 0 (default): no neck, the head is a free
  /// (or fixed) body; otherwise in [1e-3, 1e6], or kFixed for a torso held still. Needs a free head and
  /// a neck stiffness or damping.
  double torso_mass_kg = 0.0;
  /// The neck's stiffness k_n [N/m], in [0, 1e9]; needs a torso.
  double neck_stiffness_N_per_m = 0.0;
  /// The neck's damping c_n [N·s/m], in [0, 1e7]; needs a torso; at most μ_n / 1 µs (μ_n the
  /// reduced mass of head and torso), the time floor of the damper's relaxation.
  double neck_damping_N_s_per_m = 0.0;
  /// Where the robot strikes (docs/model.md §7.1): the bone whose lowest published fracture
  /// force the peak force is judged against (Assess). Default: the forehead, Park et al.'s
  /// site. It does not change the impact's mechanics.
  HeadArea area = HeadArea::kFrontal;
  /// The head hangs on a neck (a torso mass is given).
  bool has_neck() const noexcept { return torso_mass_kg != 0.0; }
};

/// The scalp: the soft layer over the skull.
struct ScalpSpec {
  double youngs_modulus_Pa = 16.7e6;  ///< [Pa]
  double poisson_ratio = 0.42;        ///< [-], in (-1, 0.5]
  double thickness_m = 0.003;         ///< b_s [m], in [1e-4, 1], at least 1e-4 below the head radius
};

/// The skull bone under the scalp.
struct SkullSpec {
  double youngs_modulus_Pa = 6.5e9;  ///< [Pa]
  double poisson_ratio = 0.22;       ///< [-], in (-1, 0.5]
};

/// Constants of the force law and of the stress formulas. The defaults are the paper's;
/// change them only to study the model itself.
struct ModelConstants {
  double exponent_covering_scalp = 1.65;  ///< n_cs (phase 1) [-], in [1, 5]
  double exponent_covering_bone = 1.8;    ///< n_cb (phase 2) [-], in [1, 5]
  double exponent_robot_bone = 2.65;      ///< n_rb (phase 3) [-], in [1, 5]
  /// Poisson ratio of the scalp in the tensile-stress formula σ_t = σ_c (1 - 2ν_t)/3 [-].
  double tensile_poisson_ratio = 0.42;
  /// A soft layer is fully compressed at this fraction of its thickness [-], in (0, 1].
  double full_compression_fraction = 0.8;
  ThresholdReading thresholds = ThresholdReading::kCumulative;
  /// Hunt-Crossley contact damping d [s/m], in [0, 1e3] (docs/model.md §10.1): the contact
  /// force is F_el(δ) (1 + d δ') and the stress σ_el(δ) (1 + d δ'). 0 (default): the
  /// paper's conservative contact.
  double damping_s_per_m = 0.0;
};

/// One impact scene: everything the model needs.
struct Scene {
  RobotSpec robot;
  CoveringSpec covering;
  HeadSpec head;
  ScalpSpec scalp;
  SkullSpec skull;
  ModelConstants model;
  /// The contact dissipates energy (damping > 0).
  bool is_damped() const noexcept { return model.damping_s_per_m > 0.0; }
  /// The robot brakes after its reaction delay (braking > 0).
  bool robot_brakes() const noexcept { return robot.braking_m_per_s2 > 0.0; }
  /// The scene has the energy integral of a two-body contact (conservative, or with contact
  /// damping, docs/model.md §10.1): no braking and no neck. The one rule of where the exact path
  /// answers every peak (SolveExact, Solve's automatic choice, the sweep, optim's oracles); a
  /// braking robot or a neck has only the time path (docs/model.md §10.2, §10.3).
  bool has_energy_integral() const noexcept { return !robot_brakes() && !head.has_neck(); }
  /// The scene is the paper's conservative two-mass impact: no damping, no braking, no neck.
  /// Only such a scene has the energy integral the exact path needs for every quantity
  /// (a damped scene keeps an exact path of its own; braking and a neck need the time path).
  bool is_conservative_two_mass() const noexcept {
    return !is_damped() && has_energy_integral();
  }
};

/// Injury limits the peaks are judged against (Park et al. Sec. IV-A).
struct InjuryLimits {
  /// Laceration: ultimate tensile stress of skin [Pa].
  double laceration_tensile_stress_Pa = 1.0e6;
  /// Contusion: maximum energy density, 2.52 J/cm² = 25 200 J/m² [J/m²].
  double contusion_energy_density_J_per_m2 = 25200.0;
  /// Fracture: the peak force the struck bone takes [N], replacing the struck area's lowest
  /// published fracture force (FractureForceOf, docs/model.md §7.1) when > 0; 0 (default): the
  /// published value. 0 or in [1, 1e13] N.
  double fracture_force_N = 0.0;
};

/// The fracture force [N] the peak force is judged against: limits.fracture_force_N when
/// given (> 0), else the lowest published fracture force of `area`.
double FractureLimit(const InjuryLimits& limits, HeadArea area) noexcept;

/// Checks injury limits against their floors (physical_floors.hpp): laceration in
/// [1e3, 1e13] Pa, contusion in [1, 1e13] J/m², the fracture force 0 or in [1, 1e13] N, so
/// that every ratio to them is finite.
/// @throws std::invalid_argument naming the field, the value and the range, e.g.
///         "limits.laceration_tensile_stress_Pa must be in [1000, 1e+13] Pa (got 5e-324)".
void CheckInjuryLimits(const InjuryLimits& limits);

}  // namespace covopt
