#pragma once
/// @file impact_result.hpp
/// What an impact computation returns, whichever path computed it.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/scene.hpp"

namespace covopt {

/// The peak quantities of one impact. F_max and σ_c,max are the largest values over the
/// loading branch 0 <= δ <= δ_max. With the default cumulative thresholds F and σ_c are
/// non-decreasing in δ, so they are the values at δ_max; the literal reading can drop them
/// at a switch, and the maximum may then lie at a switch before δ_max. U and e are
/// non-decreasing in every reading: e_A,max is e(δ_max) (docs/model.md §2, §4).
/// With contact damping d > 0 (docs/model.md §10.1) F = F_el(δ)(1 + d δ') and
/// σ_c = σ_el(δ)(1 + d δ'): F_max and σ_c,max are the maxima over the loading branch and lie
/// before δ_max (where δ' = 0 and the damping term vanishes), inside a phase or at a switch;
/// e_A,max = ∫σ_c dδ over the loading. The compression flags depend on δ_max only.
struct ImpactPeaks {
  double max_penetration_m = 0.0;               ///< δ_max [m]
  double peak_force_N = 0.0;                    ///< F_max = max F over [0, δ_max] [N]
  double max_compressive_stress_Pa = 0.0;       ///< σ_c,max = max σ_c over [0, δ_max] [Pa]
  /// σ_t,max [Pa]: σ_c,max (1 - 2ν_t)/3 under the Hertz law; under the foam law the largest
  /// of (1 − 2ν_t) F/(2π a²) on the layer and Park's value past its stop (docs/model.md §16).
  double max_tensile_stress_Pa = 0.0;
  double max_energy_density_J_per_m2 = 0.0;     ///< e_A,max = e(δ_max) = ∫σ_c dδ [J/m²]
  Phase phase_at_max = Phase::kCoveringOnScalp;  ///< the phase δ_max lies in
  /// The scalp reached full compression (δ_max > t1).
  bool scalp_fully_compressed = false;
  /// The covering reached full compression, the robot touching bone: δ_max lies in the
  /// robot-on-bone segment (δ_max > full_compression_penetration_m).
  /// Without a covering: the scalp did (the bare robot touches bone). Under the foam law
  /// (docs/model.md §16): the layer is used up, δ_max beyond its stop.
  bool fully_compressed = false;
  /// δ where the robot-on-bone segment (phase 3) begins [m]: t2 = 0.8 b_s + 0.8 b_c with
  /// the default cumulative thresholds, max(0.8 b_c, 0.8 b_s) with the literal ones, and
  /// t1 = 0.8 b_s without a covering; the foam law's stop ε_end h (docs/model.md §16).
  /// fully_compressed == (δ_max > this).
  double full_compression_penetration_m = 0.0;
  /// δ where the covering's own travel begins [m]: the start of phase 2 (covering on bone),
  /// t1 = 0.8 b_s; 0 where the literal reading leaves no phase 2, and under the foam law (its
  /// travel is its curve, from contact); equal to full_compression_penetration_m without a
  /// covering (no travel).
  double covering_travel_start_m = 0.0;
  /// The law that described the covering (ImpactModel::covering_law): kFoam or kHertz (also
  /// for the bare robot, whose contact is Park's Hertz chain).
  CoveringLaw covering_law = CoveringLaw::kHertz;
  /// The covering's nominal strain at the peak [-]: under the foam law min(δ_max, stop)/h, at
  /// most the curve's last strain; under the Hertz law the covering's share of δ_max over its
  /// thickness, (min(δ_max, t2) − t1)/b_c, at most the full-compression fraction; 0 bare.
  double covering_strain_at_peak = 0.0;
  /// Foam law: the energy that passed the layer's stop [J], U(δ_max) − U(stop), 0 while the
  /// peak stays within the curve (and for the Hertz law).
  double energy_past_stop_J = 0.0;

  /// The share of the covering's own travel used at the peak [-]:
  /// (δ_max − s) / (t2 − s), s = covering_travel_start_m, t2 = full_compression_penetration_m;
  /// 0 while δ_max <= s and without a covering, 1 at full compression, > 1 beyond it. With the
  /// default thresholds (δ_max − 0.8 b_s) / (0.8 b_c): the scalp's travel does not count
  /// (docs/model.md §6). A safety factor SF reserves travel: SF × this <= 1.
  double covering_compression_ratio() const noexcept {
    const double travel = full_compression_penetration_m - covering_travel_start_m;
    if (!(travel > 0.0) || !(max_penetration_m > covering_travel_start_m)) return 0.0;
    return (max_penetration_m - covering_travel_start_m) / travel;
  }
};

/// The peaks of a contact whose maximum penetration δ_max [m] lies in segment `segment` of
/// `model`: F_max and σ_c,max as the largest of the law at δ_max and at the ends of the
/// segments passed on the way (where the literal law can drop), e_A,max = e(δ_max), the
/// phase and compression flags. Both computation paths build their peaks with it. These are
/// the elastic law's values: with contact damping F and σ_c also depend on δ', and the paths
/// replace F_max, σ_c,max, σ_t,max and e_A,max by the damped ones (ImpactPeaks).
ImpactPeaks PeaksAtMaxPenetration(const ImpactModel& model, std::size_t segment,
                                  double max_penetration_m) noexcept;

/// Whether the covering stayed within its law's validity at the peak, for the head (docs/model.md
/// §16: the foam law within its measured curve, a used-up layer being a rigid stop, modelled,
/// the note saying how much energy passed it; the Hertz law not fully compressed) and for a
/// body region (§15.5: BodyContactResult::validity).
struct CoveringValidity {
  bool within = true;
  std::string note;  ///< for people, with the numbers
  /// How far the covering went along its law's validity limits [-]: the largest value/limit
  /// of the limits that apply, so `within` is ratio <= 1 (up to rounding at the edge). Hertz:
  /// the share of the covering's travel used (1 at full compression) and, for a solid
  /// elastomer, strain/kSolidElastomerMaxStrain and a_c/b_c; a foam on a curved body face:
  /// d/(R_c/2); 0 where the law sets no limit (bare; a foam on the head or on a flat face,
  /// whose used-up layer is a modelled stop).
  double ratio = 0.0;
  /// The same without a Hertz covering's full compression, which the paper's criterion
  /// (allow_full_compression: Park's phase 3 accepted) does not count [-]: the covering is
  /// within its law under that criterion while this is <= 1.
  double ratio_full_compression_allowed = 0.0;
};

/// A solid elastomer under the Hertz law (docs/model.md §12.2): a covering whose Poisson ratio
/// is at least this is nearly incompressible [-]. Bonded to the robot it cannot compress
/// without bulging out sideways, and its shape factor stiffens it (a bonded pad's apparent
/// modulus E (1 + β S²) grows with loaded area over free area), which the half-space law does
/// not describe. Below it (foams, ν ≈ 0-0.3) the layer changes volume and the limit does not
/// apply.
inline constexpr double kSolidElastomerMinPoissonRatio = 0.45;

/// The largest peak nominal strain δ_c/b_c [-] at which the Hertz law is taken to describe a
/// solid elastomer bonded as a layer: Hertz is a small-strain law, and beyond about 20 % a
/// bonded incompressible layer's bulging and shape-factor stiffening dominate its response.
inline constexpr double kSolidElastomerMaxStrain = 0.20;

/// The largest contact radius a_c of a solid elastomer under the Hertz law, as a multiple of
/// its thickness b_c [-]: the half-space needs a contact small against the layer (a << b_c);
/// a contact as wide as the layer is thick feels the rigid core under it, and the
/// incompressible layer is confined there.
inline constexpr double kSolidElastomerMaxContactRadiusPerThickness = 1.0;

/// A Hertz covering at the peak, as its validity needs it.
struct HertzCoveringAtPeak {
  double poisson_ratio = 0.0;        ///< ν_c [-]
  double thickness_m = 0.0;          ///< b_c [m]
  double strain = 0.0;               ///< its own nominal strain δ_c / b_c [-]
  double contact_radius_m = 0.0;     ///< its contact radius a_c [m]
  /// The share of its travel used, 1 at full compression and > 1 beyond (the head's δ beyond
  /// t2, a body region's F_max/F_b) [-]
  double travel_ratio = 0.0;
  bool fully_compressed = false;     ///< past its travel
};

/// Adds a Hertz covering's limits to `validity`, whose note says what the travel did: beyond it
/// (fully compressed) the covering is not within, and a solid elastomer (ν >= 0.45) is within
/// only while its strain is <= kSolidElastomerMaxStrain and a_c <= b_c; the note gets the
/// numbers, e.g. "solid elastomer (ν 0.49) under the Hertz law: peak strain 0.43 > 0.2 (...)".
/// Sets `within`, `ratio` and `ratio_full_compression_allowed`. For the head (with the
/// covering's phase-2 compression and contact radius) and for a body region.
void ApplyHertzCoveringLimits(const HertzCoveringAtPeak& peak, CoveringValidity& validity);

/// The covering's validity at `peaks` of `model`: within, and a note naming the law, e.g.
/// "foam law: within the measured curve (strain 0.31 of its last 0.49 at the peak)" or "foam
/// law: the layer is used up (strain 0.49, the curve's last point): a rigid stop; 0.12 J of
/// the 0.35 J impact energy passed it into the scalp and skull". Bare robot: within, "no covering".
/// Under the Hertz law: not within when fully compressed, and a solid elastomer's limits
/// (ApplyHertzCoveringLimits) on its phase-2 compression (min(δ_max, t2) − t1)/b_c and its
/// phase-2 contact radius √(x/c2), x the phase-local penetration (docs/model.md §12.2).
CoveringValidity CoveringLawValidity(const ImpactModel& model, const ImpactPeaks& peaks);

/// One injury criterion judged against its limit.
struct InjuryVerdict {
  double value = 0.0;  ///< the model's peak (Pa for laceration, J/m² for contusion, N for fracture)
  double limit = 0.0;  ///< the limit, same unit
  double ratio = 0.0;  ///< value / limit [-]; <= 1 is safe
  bool safe = true;    ///< ratio <= 1
};

/// Laceration (tensile stress) and contusion (energy density) verdicts for peaks, and the
/// fracture verdict of the bone under the struck area (docs/model.md §7.1).
struct InjuryAssessment {
  InjuryVerdict laceration;  ///< σ_t,max against the laceration limit [Pa]
  InjuryVerdict contusion;   ///< e_A,max against the contusion limit [J/m²]
  /// F_max against the struck area's lowest published fracture force [N] (FractureForceOf).
  InjuryVerdict fracture;
  HeadArea area = HeadArea::kFrontal;  ///< the struck area the fracture verdict is for
  bool safe() const noexcept { return laceration.safe && contusion.safe && fracture.safe; }
};

/// Judges peaks against limits, and the peak force against the fracture force of `area`.
InjuryAssessment Assess(const ImpactPeaks& peaks, const InjuryLimits& limits = {},
                        HeadArea area = HeadArea::kFrontal) noexcept;

/// Which path produced a result: the exact path, or one SUNDIALS integrator.
enum class ComputationMethod {
  kExact,           ///< energy balance and quadrature (no integration)
  kCvodeAdams,      ///< CVODE, Adams-Moulton (orders 1-12) with fixed-point iteration
  kCvodeBdf,        ///< CVODE, BDF (orders 1-5), Newton with the analytic Jacobian
  kArkodeErk32,     ///< ARKODE explicit RK, Bogacki-Shampine 3(2)
  kArkodeErk54,     ///< ARKODE explicit RK, Dormand-Prince 5(4)
  /// ARKODE explicit RK, ARKODE_VERNER_8_5_6 ("Verner 6(5)"). Measured: the table of
  /// SUNDIALS 6.4.1 converges at order 3, and results are 1e2-1e4 x rtol off and flagged by
  /// the energy self-check (docs/numerics.md). Kept for the numerics study; do not use.
  kArkodeErk65,
  kArkodeErk87,     ///< ARKODE explicit RK, Fehlberg 8(7)
  kArkodeSdirk43,   ///< ARKODE diagonally implicit RK, SDIRK 4(3) (5 stages), Newton
  kArkodeEsdirk54,  ///< ARKODE diagonally implicit RK, ARK5(4)8L[2]SA ESDIRK, Newton
};
/// "exact", "cvode-adams", "cvode-bdf", "arkode-erk32", "arkode-erk54", "arkode-erk65",
/// "arkode-erk87", "arkode-sdirk43", "arkode-esdirk54".
std::string_view ToString(ComputationMethod method) noexcept;
/// The inverse of ToString; empty for an unknown name.
std::optional<ComputationMethod> ParseComputationMethod(std::string_view name) noexcept;
/// Every time-integration method, in the order above.
std::vector<ComputationMethod> TimeIntegrationMethods();

/// Outcome of a computation. Numerical outcomes are values, not exceptions.
enum class SolveStatus {
  kSuccess,          ///< every requested quantity was computed
  kStepLimit,        ///< the integrator hit the step limit before separation
  kSolverFailure,    ///< the integrator returned an error (see message and raw code)
  kEventMissed,      ///< separation/maximum compression was not located consistently
  /// Time path, scenes beyond the conservative two-mass model: the contact had not ended
  /// (δ back to 0) within the extended time path's bound (docs/model.md §10.2): a guard; the
  /// scene that cannot end, a fixed robot driving the head into a fixed torso, is bad input.
  kNoSeparation,
};
std::string_view ToString(SolveStatus status) noexcept;

/// Counters of a time integration (all zero for the exact path).
struct SolverStatistics {
  long steps = 0;                 ///< internal integrator steps
  long rhs_evaluations = 0;       ///< right-hand-side evaluations
  long root_evaluations = 0;      ///< root-function evaluations
  long jacobian_evaluations = 0;  ///< Jacobian evaluations (BDF/Newton only)
  long nonlinear_iterations = 0;  ///< nonlinear solver iterations
  long error_test_failures = 0;   ///< rejected steps (local error test)
  long convergence_failures = 0;  ///< nonlinear solver convergence failures
  long restarts = 0;              ///< re-initialisations at phase switches
};

/// One sample of the force/time history.
struct HistorySample {
  double time_s = 0.0;                          ///< since first contact [s]
  double penetration_m = 0.0;                   ///< δ [m]
  double penetration_rate_m_per_s = 0.0;        ///< δ' [m/s]
  /// The contact force [N]: F(δ), or F_el(δ)(1 + d δ') with contact damping.
  double force_N = 0.0;
  /// The compressive stress [Pa]: σ_c(δ), or σ_el(δ)(1 + d δ') with contact damping.
  double compressive_stress_Pa = 0.0;
  double energy_density_J_per_m2 = 0.0;         ///< e, integrated by the solver [J/m²]
  /// Speeds along the impact axis [m/s] in the frame where the head starts at rest and the
  /// robot at the impact speed (a fixed body keeps its initial speed); δ' is their difference.
  double robot_speed_m_per_s = 0.0;
  double head_speed_m_per_s = 0.0;
  /// The neck's force on the torso, k_n (x_b - x_t) + c_n (ẋ_b - ẋ_t) [N]; 0 without a neck.
  double neck_force_N = 0.0;
  /// Work taken out of the moving bodies so far other than into U and the neck spring [J]:
  /// contact damping, the neck damper, the brake, and the support of a fixed robot (negative:
  /// it pushes). 0 on the conservative path (docs/model.md §10.2).
  double dissipated_work_J = 0.0;
};

/// The tensile stress σ_t [Pa] of a history sample: on Park's chain σ_c (1 − 2ν_t)/3 of the
/// sample's compressive stress (damping included); under the foam law the radial stress at
/// the contact edge of the segment the sample's δ lies in (ImpactModel::TensileStressInSegment).
double TensileStressOf(const ImpactModel& model, const HistorySample& sample) noexcept;

/// What a warning is about. Stable across versions: programs may match on it.
enum class ValidityCode {
  /// A phase's Hertz contact radius sqrt(x/c) is not smaller than a radius it touches
  /// (the paper's footnote 7: eq. (4) needs non-sharp contact).
  kHertzValidity,
  /// The covering is stiffer than the scalp (E_c > E_s) and gives a higher σ_c,max than a
  /// bare robot of the same outer radius R_r + b_c: the layered stress law, which adds
  /// phase-wise Hertz pressures, overstates the stress of a stiff covering.
  kCoveringStifferThanScalp,
  /// δ_max lies in the last 5 % of the covering-on-bone segment (phase 2): not yet fully
  /// compressed, but a little more energy bottoms the covering out.
  kNearFullCompression,
  /// The covering is fully compressed: δ_max lies in the robot-on-bone segment (phase 3).
  kFullyCompressed,
  /// The paper's literal threshold reading (ThresholdReading::kLiteral) is in use.
  kLiteralThresholds,
  /// Time path: the energy residual exceeds max(100 rtol, 1e-9); the integrator did not keep
  /// its tolerance.
  kToleranceNotKept,
  /// Time path: integrated through the force law's C0 kinks without restarting
  /// (TimeIntegrationOptions::restart_at_phase_switches off).
  kNoRestarts,
};
/// "hertz-validity", "covering-stiffer-than-scalp", "near-full-compression",
/// "fully-compressed", "literal-thresholds", "tolerance-not-kept", "no-restarts".
std::string_view ToString(ValidityCode code) noexcept;

/// One warning: a stable code and a message for people, with the numbers.
struct ValidityWarning {
  ValidityCode code = ValidityCode::kHertzValidity;
  std::string message;
};

/// Everything one impact computation reports.
struct ImpactResult {
  ComputationMethod method = ComputationMethod::kExact;
  SolveStatus status = SolveStatus::kSuccess;
  /// Human-readable detail of a failure, including the integrator's own messages.
  std::string message;
  /// The backend's raw return code (CVODE flag), 0 for the exact path.
  int raw_code = 0;

  ImpactPeaks peaks;
  /// Contact duration [s]: from first contact to separation; empty when not computed.
  std::optional<double> contact_duration_s;
  /// Relative speed at separation [m/s]; equals the impact speed in the conservative model,
  /// less with contact damping, braking or a damped neck (docs/model.md §10).
  std::optional<double> rebound_speed_m_per_s;
  /// Coefficient of restitution [-]: rebound speed / impact speed; 1 in the conservative
  /// model. Set with rebound_speed_m_per_s.
  std::optional<double> coefficient_of_restitution;
  /// Time of maximum compression [s]: half the contact duration without damping; the loading
  /// time, shorter than the unloading, with it. Set with contact_duration_s on the exact path.
  std::optional<double> time_of_max_compression_s;
  /// The time path's own accuracy check [-], empty for the exact path: the model conserves
  /// energy, so both of these vanish for an exact solution,
  ///     max( |U(δ_max) / (½ m v0²) - 1|,  |rebound speed / v0 - 1| ).
  /// It costs nothing (U is analytic) and tracks the true error of the peaks within about
  /// a factor of ten (docs/numerics.md). Above max(100 rtol, 1e-9) a warning says the
  /// integrator did not keep its tolerance.
  /// Scenes beyond the conservative two-mass model (and force_extended_dynamics): the energy
  /// balance with the work accounted for, at every maximum of δ and at separation,
  ///     max | ΔK + U(δ) + ½ k_n (x_b - x_t)² + W | / (½ m v0²),
  /// ΔK the change of the moving bodies' kinetic energy, W the integrated work of the
  /// contact damping, the neck damper, the brake and a fixed robot's support
  /// (HistorySample::dissipated_work_J); docs/model.md §10.2.
  std::optional<double> energy_residual;

  SolverStatistics statistics;
  /// Sampled history, when requested (time path only).
  std::vector<HistorySample> history;
  /// The computation's warnings, each a stable code and a message for people: where the
  /// result leaves the model's domain (CheckValidity; docs/model.md §5, §7), then the time
  /// path's own (tolerance not kept, no restarts).
  std::vector<ValidityWarning> warnings;
  /// The covering's law validity at the peaks (CoveringLawValidity); the law is
  /// peaks.covering_law.
  CoveringValidity validity;

  bool ok() const noexcept { return status == SolveStatus::kSuccess; }

  /// Appends a warning.
  void AddWarning(ValidityCode code, std::string message);
  /// The messages of `warnings`, in order.
  std::vector<std::string> WarningMessages() const;
};

/// Where peaks of a model leave the model's domain (docs/model.md §5, §7), in the order of
/// ValidityCode: Hertz validity (per phase reached), a covering stiffer than the scalp with
/// a higher σ_c,max than a bare robot of radius R_r + b_c (both results given), a covering within
/// 5 % of full compression (δ_max >= t2 - 0.05 (t2 - t1), δ_max <= t2), a fully compressed
/// covering, and the literal threshold reading (what it changes against the default reading).
/// The comparisons run the exact path on the comparison scene (~1 µs).
std::vector<ValidityWarning> CheckValidity(const ImpactModel& model, const ImpactPeaks& peaks);

/// The messages of CheckValidity, in its order.
std::vector<std::string> ValidityWarnings(const ImpactModel& model, const ImpactPeaks& peaks);

}  // namespace covopt
