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
#include <string_view>

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

/// The robot (impactor) as seen along the impact direction.
struct RobotSpec {
  /// Reflected mass in the impact direction [kg], > 0; kFixed for an immovable plate.
  double mass_kg = 10.0;
  /// Relative approach speed at first contact [m/s], in [1e-6, 100].
  double speed_m_per_s = 2.0;
  /// Radius of curvature of the robot surface under the covering [m], > 0; kFlat if flat.
  double radius_m = 0.015;
  /// Young's modulus of the robot structure [Pa] (aluminium by default).
  double youngs_modulus_Pa = 70e9;
  /// Poisson ratio of the robot structure [-], in (-1, 0.5].
  double poisson_ratio = 0.3;
};

/// The soft covering on the robot. thickness_m == 0 means no covering: the robot itself
/// touches the scalp (docs/model.md §2), and modulus and Poisson ratio are ignored.
struct CoveringSpec {
  /// Young's modulus of the covering [Pa] (the paper's polystyrene foam No. 1).
  double youngs_modulus_Pa = 27.6e6;
  /// Poisson ratio of the covering [-], in (-1, 0.5]; 0.25 is the paper's Fig. 9 value
  /// used when a continuous design needs one and none is given (docs/model.md §1).
  double poisson_ratio = 0.25;
  /// Covering thickness [m], >= 0; 0 = no covering.
  double thickness_m = 0.015;
};

/// The head as a rigid mass carrying the scalp.
struct HeadSpec {
  /// Head mass [kg], > 0; kFixed for a head held still (drop tests on a fixed head).
  double mass_kg = 4.5;
  /// Outer radius of the head, i.e. of the scalp surface, R_s [m]; must exceed the scalp
  /// thickness.
  double radius_m = 0.08;
};

/// The scalp: the soft layer over the skull.
struct ScalpSpec {
  double youngs_modulus_Pa = 16.7e6;  ///< [Pa]
  double poisson_ratio = 0.42;        ///< [-], in (-1, 0.5]
  double thickness_m = 0.003;         ///< b_s [m], > 0 and < head radius
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
};

/// One impact scene: everything the model needs.
struct Scene {
  RobotSpec robot;
  CoveringSpec covering;
  HeadSpec head;
  ScalpSpec scalp;
  SkullSpec skull;
  ModelConstants model;
};

/// Injury limits the peaks are judged against (Park et al. Sec. IV-A).
struct InjuryLimits {
  /// Laceration: ultimate tensile stress of skin [Pa].
  double laceration_tensile_stress_Pa = 1.0e6;
  /// Contusion: maximum energy density, 2.52 J/cm² = 25 200 J/m² [J/m²].
  double contusion_energy_density_J_per_m2 = 25200.0;
};

}  // namespace covopt
