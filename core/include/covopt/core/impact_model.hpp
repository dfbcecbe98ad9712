#pragma once
/// @file impact_model.hpp
/// The multi-layer Hertz contact law of Park et al. (2011) as docs/model.md §2 reads it, and
/// the foam law of a covering with a measured curve (docs/model.md §16).
///
/// An ImpactModel is an immutable, validated value built from a Scene. It holds the law
/// as up to three segments in the penetration δ [m]:
///
///     phase 1  covering (or bare robot) on scalp   0  <= δ <= t1
///     phase 2  covering on bone                    t1 <  δ <= t2   (only with a covering)
///     phase 3  robot on bone                       t2 <  δ
///
/// Inside a segment, with the phase-local penetration x = δ - origin,
///
///     F(δ) = F_off + K x^n                    force [N]
///     σ(δ) = σ_off + k K c x^(n-1)            compressive stress [Pa], k = 3/(2π)
///
/// and U = ∫F dδ [J], e = ∫σ dδ [J/m²] accumulate from 0. With the default cumulative
/// thresholds origin == start and the offsets are the values reached at the segment start,
/// so F, U, σ, e are continuous and non-decreasing. The literal reading
/// (ThresholdReading::kLiteral) can put phase 3's origin before its start (when
/// 0.8 b_c <= 0.8 b_s, and always without a covering, where the origin is 0); F and σ then
/// jump at the switch, up or down, as the paper's eq. (2) and (4) do, while U and e stay
/// continuous and non-decreasing (docs/model.md §4).
/// The model needs no more phases than the scene has: no covering gives two segments.

#include <array>
#include <cstddef>
#include <string_view>

#include "covopt/core/scene.hpp"

namespace covopt {

/// Which bodies are in contact in a segment of the force law.
enum class Phase {
  kCoveringOnScalp = 1,  ///< phase 1 with a covering
  kRobotOnScalp = 11,    ///< phase 1 without a covering (the bare robot touches the scalp)
  kCoveringOnBone = 2,   ///< phase 2: scalp fully compressed, covering on bone
  kRobotOnBone = 3,      ///< phase 3: everything soft fully compressed, robot on bone
};

/// The paper's phase number: 1, 2 or 3.
int PhaseNumber(Phase phase) noexcept;
/// A short human-readable name, e.g. "covering on scalp".
std::string_view ToString(Phase phase) noexcept;

/// One piece of the piecewise force law (see the file comment for the formulas).
struct ForceLawSegment {
  Phase phase = Phase::kCoveringOnScalp;
  double start_m = 0.0;   ///< δ at which the segment begins [m]
  double end_m = 0.0;     ///< δ at which it ends [m] (+inf for the last segment)
  double origin_m = 0.0;  ///< δ where the phase-local penetration x is zero [m]
  double stiffness = 0.0;           ///< K [N/m^n]
  double exponent = 1.5;            ///< n [-]
  double curvature_per_m = 0.0;     ///< curvature sum c [1/m]
  double force_offset_N = 0.0;      ///< F_off [N]
  double stress_offset_Pa = 0.0;    ///< σ_off [Pa]
  double energy_at_start_J = 0.0;   ///< U(start) [J]
  double energy_density_at_start_J_per_m2 = 0.0;  ///< e(start) [J/m²]
  /// Radii of curvature of the two bodies in contact [m] (+inf when flat), for the Hertz
  /// validity check (contact radius sqrt(x/c) must stay below both).
  double radius_a_m = 0.0;
  double radius_b_m = 0.0;
  /// The foam law (docs/model.md §16): the covering's measured curve σ(ε) (owned by the
  /// model's scene), null for a Hertz segment. A foam segment's law is
  ///     F = A W(δ/h),  U = A h V(δ/h),  σ_c = σ(δ/h),  e = h W(δ/h),  A = 2π R h,
  /// R = 1/(1/R_c + 1/R_s) the relative radius, h the layer's thickness; stiffness and
  /// exponent are then unused.
  const CompressiveCurve* curve = nullptr;
  double foam_thickness_m = 0.0;  ///< h [m]
  double foam_area_m2 = 0.0;      ///< A = 2π R h [m²]
};

/// The force law and its integrals at one penetration.
struct ContactState {
  double force_N = 0.0;
  double potential_energy_J = 0.0;                 ///< U = ∫F dδ
  double compressive_stress_Pa = 0.0;              ///< σ_c
  double energy_density_J_per_m2 = 0.0;            ///< e = ∫σ_c dδ
  double stiffness_N_per_m = 0.0;                  ///< dF/dδ (one-sided at a switch)
  Phase phase = Phase::kCoveringOnScalp;
};

/// The validated model of one scene. Cheap to copy; all members are const after creation.
class ImpactModel {
 public:
  /// Validates every field of `scene` and builds the force law.
  /// @throws std::invalid_argument naming the field, the value and the allowed range,
  ///         e.g. "covering.thickness must be 0 (no covering) or in [0.0001, 1] m (got -0.001)";
  ///         every length, mass, time and modulus at least its floor (physical_floors.hpp).
  static ImpactModel FromScene(const Scene& scene);

  /// The scene as given (after validation).
  const Scene& scene() const noexcept { return scene_; }
  /// Effective mass m = 1/(1/m_r + 1/m_b) [kg] (a fixed body contributes 1/∞ = 0).
  double effective_mass_kg() const noexcept { return effective_mass_kg_; }
  /// Kinetic energy of the relative motion, ½ m v0² [J]; U(δ_max) equals it.
  double impact_energy_J() const noexcept { return impact_energy_J_; }
  /// Impact speed v0 [m/s].
  double impact_speed_m_per_s() const noexcept { return scene_.robot.speed_m_per_s; }
  /// True when the scene has a covering (thickness > 0).
  bool has_covering() const noexcept { return scene_.covering.thickness_m > 0.0; }
  /// The law that describes the covering, resolved from CoveringSpec::law: kFoam (a covering
  /// with a measured curve under kAuto or kFoam: docs/model.md §16) or kHertz (Park's chain;
  /// also the bare robot's).
  CoveringLaw covering_law() const noexcept { return covering_law_; }
  /// True for a covering under the foam law: segment 0 is the foam layer (covering on scalp),
  /// then the robot on the scalp through the used-up layer, then the robot on bone.
  bool is_foam() const noexcept { return covering_law_ == CoveringLaw::kFoam; }
  /// The foam law's stop [m]: δ where the layer reaches its curve's last strain, ε_end h
  /// (the end of segment 0); 0 for the Hertz law.
  double foam_stop_penetration_m() const noexcept { return is_foam() ? segments_[0].end_m : 0.0; }

  /// Number of segments of the law (2 without a covering or with an ill-ordered literal
  /// law, 3 otherwise). The last segment is always phase 3, robot on bone.
  std::size_t segment_count() const noexcept { return segment_count_; }
  const ForceLawSegment& segment(std::size_t i) const noexcept { return segments_[i]; }
  /// Index of the segment containing δ [m] (δ on a switch belongs to the lower segment;
  /// δ < 0 maps to segment 0).
  std::size_t SegmentIndexAt(double penetration_m) const noexcept;

  /// F, U, σ_c, e and dF/dδ at penetration δ [m]. δ <= 0 gives all zeros (no contact).
  ContactState StateAt(double penetration_m) const noexcept;
  /// The same, evaluated with segment i's formula (continued past its ends; the
  /// phase-local penetration is clamped at 0, so no pow of a negative base).
  ContactState StateInSegment(std::size_t i, double penetration_m) const noexcept;

  /// U(δ_b) - U(δ_a) [J] for 0 <= δ_a <= δ_b inside segment i, computed from the gap
  /// d = δ_b - δ_a [m] without cancellation (expm1/log1p), so it stays accurate when
  /// d << δ_b.
  double EnergyDifferenceInSegment(std::size_t i, double upper_penetration_m,
                                   double gap_m) const noexcept;

  /// EnergyDifferenceInSegment for many gaps below one δ_b in one segment (the duration
  /// quadrature asks for 20 per segment): x_b^(n+1), 1/x_b and K/(n+1) are computed once
  /// (EnergyDifferenceInSegment is one such call, so the two agree to the bit).
  class EnergyGapBelow {
   public:
    EnergyGapBelow(const ImpactModel& model, std::size_t i, double upper_penetration_m) noexcept;
    /// U(δ_b) - U(δ_b - gap) [J].
    double operator()(double gap_m) const noexcept;

   private:
    double force_offset_N_ = 0.0, stiffness_ = 0.0, power_ = 0.0;
    double upper_local_m_ = 0.0;      ///< x_b, δ_b in the segment's local coordinate [m]
    double upper_local_pow_ = 0.0;    ///< x_b^power
    double inverse_upper_local_per_m_ = 0.0;  ///< 1/x_b [1/m] (0 when x_b <= 0: unused)
    double stiffness_over_power_ = 0.0;       ///< K/power
    const ForceLawSegment* foam_ = nullptr;   ///< a foam segment: U's drop from its curve
    /// A foam segment: W, σ and dσ/dε at δ_b/h on its curve piece (whose start is
    /// piece_gap_ below δ_b [m]), scaled by A h and h (U's drop is a cubic in the gap there).
    double foam_w_ = 0.0, foam_stress_ = 0.0, foam_slope_ = 0.0, piece_gap_m_ = 0.0;
  };

  /// Tensile stress from compressive stress, σ_t = σ_c (1 - 2ν_t)/3 [Pa] (eq. 5): Park's
  /// chain, where σ_c is a Hertz peak pressure. The foam law's σ_t is TensileStressInSegment's.
  double TensileFromCompressive(double compressive_stress_Pa) const noexcept {
    return compressive_stress_Pa * tensile_factor_;
  }
  /// σ_t [Pa] at δ [m] with segment i's formula: on a foam segment the radial stress at the
  /// contact edge, (1 − 2ν_t) F/(2π a²) = (1 − 2ν_t) W(ε)/(2ε) (docs/model.md §16); on a Hertz
  /// segment Park's σ_c (1 − 2ν_t)/3.
  double TensileStressInSegment(std::size_t i, double penetration_m) const noexcept;

 private:
  ImpactModel() = default;
  /// The foam law's segments (docs/model.md §16), from the Hertz chain's thresholds and radii.
  void BuildFoamLaw(double t1, double c1, double c3, double r_cover, double r_bone);

  Scene scene_{};
  double effective_mass_kg_ = 0.0;
  double impact_energy_J_ = 0.0;
  double tensile_factor_ = 0.0;
  CoveringLaw covering_law_ = CoveringLaw::kHertz;
  std::array<ForceLawSegment, 3> segments_{};
  std::size_t segment_count_ = 0;
};

}  // namespace covopt
