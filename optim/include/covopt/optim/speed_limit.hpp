#pragma once
/// @file speed_limit.hpp
/// The other direction of the design question: for a given robot and covering, the largest
/// impact speed (or reflected robot mass) that stays safe — the speed a power-and-force-
/// limiting controller enforces.
///
/// Definition. The maximum safe speed is the largest v0 such that EVERY speed in (0, v0] is
/// safe: both injury ratios <= 1/safety_factor and, under the default criterion
/// (docs/model.md §6), the covering not fully compressed at the peak (δ_max <= t2; for the
/// bare robot only the ratios count). A controller enforces "speed <= limit", so a safe
/// window above an unsafe speed would not help. The maximum safe mass is defined the same
/// way over the reflected robot mass (0, m_r].
///
/// How. In the conservative model energy is conserved, so the peak penetration δ_max solves
/// U(δ_max) = ½ μ v0² (μ = 1/(1/m_r + 1/m_h), the reduced mass) and grows with v0 and with
/// m_r; the peaks are non-decreasing functions of δ_max (with the literal thresholds, F and
/// σ_c are their running maxima over the contact: ImpactPeaks). So the limit is found on the
/// δ axis: δ_lim, the smallest δ at which a criterion reaches its limit —
///
///     laceration         σ_t,max(δ) = laceration limit / safety_factor
///     contusion          e_A(δ)     = contusion limit / safety_factor
///     full compression   δ = t2     (default criterion, with a covering)
///
/// — by a closed form (σ_c in a phase) or a monotone Newton iteration (e_A) inside the phase
/// where the limit is crossed, to ~1e-15 relative; then
///
///     v_max = sqrt(2 U(δ_lim) / μ)        μ_max = 2 U(δ_lim) / v0²
///     m_r,max = μ_max m_h / (m_h - μ_max)  (free head; μ_max >= m_h: even a fixed robot is
///                                           safe; fixed head: m_r,max = μ_max).
/// The ratios at the limit come from re-running the exact path there (ExactPeaks), so they
/// are the numbers `covopt simulate` prints at that speed or mass: none above 1/s, and the
/// binding one at 1/s within rounding — except where the literal thresholds make σ_c jump past
/// the limit at a phase switch: the limit is then the speed that just reaches the switch, and
/// the laceration ratio there is the one below the jump. About 1-2 µs per answer.
///
/// That the ratios are non-decreasing in v0 and m_r is checked by a dense scan on varied
/// scenes in tests/optim/test_speed_limit.cpp, and every answer is checked against a
/// bisection on the full exact path.
///
/// Scenes beyond the conservative two-mass model (docs/model.md §10.4). The same rule as the
/// design searches chooses the oracle (ChooseOracle, SpeedLimitOptions::oracle): the exact
/// path for a damped contact, the time path for a braking robot or a neck. In none of them
/// are the peaks functions of δ_max alone, nor δ_max of ½ μ v0², so there is no δ axis to
/// solve on (nor when the time path is asked for on a conservative scene). The limit is then
/// bracketed on the oracle itself: speeds (masses) are scanned upward on a geometric grid, 4 points per
/// decade from 1e-6 m/s (1e-6 kg) to the ceiling, the first inadmissible point found, and the
/// step from the last admissible one bisected to 1e-10 relative. Scanning upward keeps the
/// definition (every lower value safe) at the grid's resolution even if a scene were not
/// monotone; that it is monotone in v0 and m_r for braking and neck scenes is checked by a
/// dense scan in the tests. About 70 runs per answer (a few ms on the time path).

#include <optional>
#include <string>
#include <string_view>

#include <covopt/core/scene.hpp>
#include <covopt/materials/material.hpp>

#include "covopt/optim/covering_design.hpp"

namespace covopt::optim {

/// How a limit search ended. Every outcome is an answer.
enum class SpeedLimitStatus {
  /// A criterion binds inside the searched range: the value is the limit.
  kLimited,
  /// Safe up to the top of the searched range (the model's 100 m/s; for a mass, 1e6 kg or a
  /// fixed robot): the value is that ceiling, the true limit (if any) lies above.
  kSafeUpToSearchLimit,
  /// Not even the bottom of the range is safe (the model's 1e-6 m/s; a vanishing mass):
  /// the value is 0.
  kNoSafeValue,
  /// Not an answer: the oracle (the time path) failed on an impact the search needed, so
  /// whether that value is safe is unknown. The value is 0, the ratios are 0, and the message
  /// names the value and the oracle's status and message. A failed run is never read as safe
  /// or unsafe.
  kEvaluationFailed,
};
/// "limited", "safe-up-to-search-limit", "no-safe-value", "evaluation-failed".
std::string_view ToString(SpeedLimitStatus status) noexcept;

/// LimitingCriterion (oracle.hpp): the criterion that binds a limit.

/// Options of MaxSafeSpeed and MaxSafeMass.
struct SpeedLimitOptions {
  /// false (default): a covering fully compressed at the peak is not safe (criterion
  /// "no-full-compression", as DesignOptions). true: the paper's criterion, the ratios only.
  /// With a Hertz covering it also accepts full compression as within the law's validity
  /// (optim::JudgedValidity); otherwise a fully compressed Hertz covering is out of its law
  /// ("law-validity", counted always) and limits the speed at full compression.
  bool allow_full_compression = false;
  /// The covering's travel rule as a limit ("full-compression" under Hertz, "within-curve" under
  /// the foam law, the safety factor as a reserve of travel): true (the library's default, the
  /// rule of the design searches) counts it; false (the commands' default, --keep-travel off)
  /// reports it only: a foam used up below the limit is within its law (the stop is modelled)
  /// and is reported at its own speed (SpeedLimit::covering_used_up_m_per_s).
  bool keep_travel = true;
  DesignCriterion criterion() const noexcept {
    return keep_travel && !allow_full_compression ? DesignCriterion::kNoFullCompression : DesignCriterion::kPaper;
  }
  /// Every ratio that counts (injury, the covering's travel, crush) must be <= 1/safety_factor,
  /// in [1, 100] [-]. Default: 1.
  double safety_factor = 1.0;
  /// The laceration [Pa] and contusion [J/m²] limits, each in (0, inf). Default: 1 MPa and
  /// 2.52 J/cm².
  InjuryLimits limits;
  /// The top of the speed search [m/s], in [1e-6, 100]. Default: 100, the model's ceiling
  /// (docs/model.md §1).
  double max_speed_m_per_s = 100.0;
  /// The top of the mass search for a finite robot [kg], in (0, 1e6]. Default: 1e6, the
  /// model's ceiling. A fixed robot (m_r = inf) is always considered beyond it.
  double max_mass_kg = 1e6;
  /// Which path judges the impacts: auto (default; the exact path's δ-axis solve where the
  /// scene admits it, a bracketed bisection on the time path otherwise), exact, or time-path.
  OracleOptions oracle;
  /// The covering material's compressive strength [Pa], finite and > 0, when it is a material
  /// that crushes: the no-crush criterion SF σ_c,max <= strength then applies (docs/model.md
  /// §12). 0 (default): no crush check (a covering given by its modulus, a material that does
  /// not crush, or one of unknown strength; the caller says which).
  double covering_compressive_strength_Pa = 0.0;
  /// A sacrificial liner: the crush ratio is reported but does not limit. Default: false.
  bool allow_crushing = false;
  /// The admissibility rule of these options: crushing is checked where the strength is known.
  DesignRule rule() const noexcept {
    return DesignRule{safety_factor, criterion(), allow_crushing, !(covering_compressive_strength_Pa > 0.0)};
  }
};

/// The crush check a limit search can make on a scene's covering (docs/model.md §12): the
/// material's compressive strength when it crushes (for SpeedLimitOptions), and what the
/// reader must know when nothing is checked.
struct CoveringCrushCheck {
  /// [Pa]: the catalog material's strength when it crushes; 0 otherwise.
  double compressive_strength_Pa = 0.0;
  /// How the crush criterion applies: kChecked (a strength), kDoesNotCrush, kUnknownStrength
  /// (a catalog material of unknown strength), kNoMaterial (no covering, the default one, or
  /// one given by its modulus).
  CrushCheck check = CrushCheck::kNoMaterial;
  /// One sentence each: a covering assumed because none was given, one given by its modulus
  /// (no material, no strength), or a material of unknown strength.
  std::vector<std::string> notes;
};
/// `material`: the catalog entry the covering was taken from, or nullptr; `covering_given`:
/// the user gave any covering input (thickness, modulus, ν or a material).
CoveringCrushCheck CrushCheckFor(const Scene& scene, const materials::Material* material, bool covering_given);
/// The warning that the default covering is assumed (no covering input given, `scene`'s
/// covering the default): one text for the crush notes and optim::SceneInputWarnings.
std::string DefaultCoveringNote(const Scene& scene);

/// The crush verdict of one impact (docs/model.md §12): σ_c,max [Pa] against a compressive
/// strength [Pa] (> 0), safe when safety_factor × ratio <= 1.
InjuryVerdict CrushVerdict(const ImpactPeaks& peaks, double compressive_strength_Pa, double safety_factor) noexcept;

/// The ratios of the impact at a limit, as the exact path computes them there.
struct LimitRatios {
  double laceration_ratio = 0.0;   ///< σ_t,max / laceration limit [-]
  double contusion_ratio = 0.0;    ///< e_A,max / contusion limit [-]
  /// F_max / the struck area's lowest published fracture force [-] (docs/model.md §7.1)
  double fracture_ratio = 0.0;
  /// The covering's travel used [-] (DesignScore::compression_ratio): > 1 fully compressed; 0
  /// without a covering.
  double compression_ratio = 0.0;
  /// σ_c,max / the covering's compressive strength [-]; 0 without a strength.
  double crush_ratio = 0.0;
  double max_penetration_m = 0.0;  ///< δ_max [m]
};

/// One impact judged by the rules of a limit search.
struct ImpactJudgement {
  LimitRatios ratios;       ///< the exact path's ratios at the scene's own speed and mass
  ImpactPeaks peaks;        ///< the impact's peaks (zero when it failed): HeadVerdict(scene, peaks, options)
  /// The covering's law and its validity at the peaks (JudgedValidity; within bare).
  CoveringValidity validity;
  /// Every ratio that counts <= 1/safety_factor and, under the default criterion, not fully
  /// compressed.
  bool admissible = false;
  /// The time path failed on this impact (the ratios are then +inf and it is not admissible).
  bool failed = false;
};

/// The oracle options.oracle chooses (the exact path, or the time path) on `scene` (its own
/// speed and mass), judged with the criterion, safety factor and limits of `options`: what
/// MaxSafeSpeed and MaxSafeMass call safe.
/// @throws std::invalid_argument for a bad scene or options, or oracle exact on a scene with
///         braking or a neck.
ImpactJudgement JudgeImpact(const Scene& scene, const SpeedLimitOptions& options = {});

/// What MaxSafeSpeed and MaxSafeMass answer besides the limit itself.
struct LimitAnswer {
  SpeedLimitStatus status = SpeedLimitStatus::kLimited;
  LimitingCriterion limited_by = LimitingCriterion::kNone;
  /// The impact at the limit (at the bottom of the range, 1e-6 m/s or kg, for kNoSafeValue;
  /// a fixed robot when that is MaxSafeMass's answer).
  LimitRatios at_limit;
  /// One sentence, e.g. "max safe speed 1.234 m/s, limited by contusion".
  std::string message;
  /// Which path judged the impacts (exact or time path), why, and its evaluations.
  OracleReport oracle;
  /// Found by the bracketed bisection on the oracle (a scene beyond the conservative two-mass
  /// model, or the time path asked for), not by the δ-axis solve.
  bool bracketed = false;
  /// The law that describes the covering ("foam", "hertz"; empty bare) and its validity at the
  /// limit (JudgedValidity of the impact there; within bare).
  std::string covering_law;
  CoveringValidity validity;
};

/// The answer of MaxSafeSpeed.
struct SpeedLimit : LimitAnswer {
  /// The largest safe impact speed [m/s] (kLimited); the search ceiling
  /// (kSafeUpToSearchLimit); 0 (kNoSafeValue).
  double max_safe_speed_m_per_s = 0.0;
  /// The speed [m/s] at which the covering is used up (the foam's curve end, a Hertz covering's
  /// full compression), when it is below the search ceiling; empty bare and where the limit is
  /// bracketed on the oracle (no energy balance). Below the limit the message says "covering
  /// used up at v = ...": not an injury, and without keep_travel not a limit.
  std::optional<double> covering_used_up_m_per_s;
  /// The message with the ratios at the limit.
  std::string BriefReport() const;
};

/// The answer of MaxSafeMass.
struct MassLimit : LimitAnswer {
  /// The largest safe reflected robot mass [kg] (kLimited); kFixed (+inf) when even a fixed
  /// robot is safe, or options.max_mass_kg, for kSafeUpToSearchLimit; 0 (kNoSafeValue).
  double max_safe_mass_kg = 0.0;
  /// The message with the ratios at the limit.
  std::string BriefReport() const;
};

/// The largest impact speed [m/s] at which the scene (robot mass, covering, head, ...) is
/// safe for every lower speed. scene.robot.speed_m_per_s is ignored.
/// @throws std::invalid_argument naming the field, the value and the allowed range for a bad
///         scene or options.
SpeedLimit MaxSafeSpeed(const Scene& scene, const SpeedLimitOptions& options = {});

/// The largest reflected robot mass [kg] that is safe, with every lighter robot, at the
/// scene's speed. scene.robot.mass_kg is ignored.
/// @throws std::invalid_argument as MaxSafeSpeed.
MassLimit MaxSafeMass(const Scene& scene, const SpeedLimitOptions& options = {});

}  // namespace covopt::optim
