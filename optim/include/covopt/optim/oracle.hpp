#pragma once
/// @file oracle.hpp
/// The objective/constraint oracle of the covering design searches: one interface
/// (DesignOracle), two implementations.
///
///  - ExactPathOracle: the exact energy-balance path (docs/model.md §3.1), ~0.2 µs per design,
///    analytic gradients (ExactPeakSensitivities). It needs the energy integral: the
///    conservative two-mass impact, and the damped two-mass contact (a few µs per design,
///    gradients by a central difference of its values).
///  - TimePathOracle: the SUNDIALS time path (SimulateImpact) with any integrator and
///    tolerance, tens of µs per design; gradients from CVODES forward sensitivities
///    (TimePathPeakSensitivities) for the two-mass contact, by a controlled central difference
///    for a braking robot or a neck (docs/model.md §10.4).
///
/// ChooseOracle is the one rule every caller (design searches, speed limits) uses: `auto`
/// takes the exact path where the scene admits it and the time path otherwise. A time-path
/// evaluation that fails (status not success) is a failed evaluation: counted, reported, its
/// score inadmissible with infinite ratios (DesignScore::failed), never an answer.
///
///     const auto oracle = covopt::optim::MakeOracle(scene, 0.25, {}, {});  // auto
///     const covopt::optim::DesignScore score = oracle->Score({16e6, 0.015});

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <covopt/core/impact_result.hpp>
#include <covopt/core/scene.hpp>
#include <covopt/core/solve.hpp>
#include <covopt/core/time_integration.hpp>

namespace covopt::optim {

/// A covering: modulus [Pa] and thickness [m].
struct CoveringDesign {
  double youngs_modulus_Pa = 0.0;
  double thickness_m = 0.0;
};

/// Which designs count as acceptable (docs/model.md §6).
enum class DesignCriterion {
  kNoFullCompression,  ///< safe and the covering not fully compressed at the peak (default)
  kPaper,              ///< safe (both injury ratios) only, as the paper designs
};
/// "no-full-compression" or "paper".
std::string_view ToString(DesignCriterion criterion) noexcept;

/// One criterion of the design rule, or none (docs/model.md §6, §12).
enum class LimitingCriterion {
  kNone,             ///< nothing binds (within a searched range)
  kLaceration,       ///< σ_t,max against the laceration limit / safety factor
  kContusion,        ///< e_A,max against the contusion limit / safety factor
  kFullCompression,  ///< the covering's travel used against 1 / safety factor (default criterion)
  kCrush,            ///< σ_c,max against the material's compressive strength / safety factor
  /// F_max against the struck area's lowest published fracture force / safety factor
  /// (docs/model.md §7.1)
  kFracture,
  /// The covering's law leaves its validity (CoveringValidity::within false; core/verdict.hpp's
  /// "law-validity"): e.g. a Hertz covering fully compressed without the paper's criterion.
  kLawValidity,
};
/// "none", "laceration", "contusion", "full-compression", "crush", "fracture", "law-validity".
std::string_view ToString(LimitingCriterion criterion) noexcept;
/// The criterion's name for a covering under `law`: ToString, except the travel rule of a foam
/// layer, "within-curve" (the strain at the peak within its measured curve, SF as a strain
/// reserve) where the Hertz law's is "full-compression".
std::string_view ToString(LimitingCriterion criterion, CoveringLaw law) noexcept;

/// How the crush criterion applies to a design (docs/model.md §12).
enum class CrushCheck {
  kNoMaterial,       ///< a continuous design or the bare robot: no material to check
  kChecked,          ///< the material's compressive strength is known: crush_ratio is set
  kDoesNotCrush,     ///< an elastomer, gel or flexible foam: full compression is its limit
  kUnknownStrength,  ///< the material's strength is unknown: the design is unverified for crushing
};
/// "no-material", "checked", "does-not-crush", "unknown-strength".
std::string_view ToString(CrushCheck check) noexcept;

/// What makes a design admissible (docs/model.md §6, §7.1, §12): the safety factor SF times every
/// ratio that counts is <= 1. The injury ratios (laceration, contusion, fracture) always count; the covering's travel ratio
/// (DesignScore::compression_ratio) under the no-full-compression criterion, with a
/// covering; the crush ratio for a material of known strength unless crushing is allowed.
/// A material of unknown strength is inadmissible unless crushing or unknown strengths are
/// allowed.
struct DesignRule {
  /// SF in [1, 100] [-]. It derates the injury limits and the strength, and reserves the
  /// covering's travel: SF × (δ_max − t1) / (0.8 b_c) <= 1.
  double safety_factor = 1.0;
  /// kNoFullCompression (default): the covering's travel counts. kPaper: it does not.
  DesignCriterion criterion = DesignCriterion::kNoFullCompression;
  /// A sacrificial liner: the crush ratio is reported but does not count. Default: false.
  bool crushing_allowed = false;
  /// Materials of unknown strength may be admissible (each is warned about). Default: false.
  bool unknown_strength_allowed = false;
  bool compression_counts() const noexcept { return criterion == DesignCriterion::kNoFullCompression; }
  /// A material of unknown strength is never admissible under this rule.
  bool refuses_unknown_strength() const noexcept { return !crushing_allowed && !unknown_strength_allowed; }
  /// The criteria applied, in words, e.g. "laceration and contusion (Park et al. 2011), no full
  /// compression, no crushing; safety factor 1".
  std::string Describe() const;
  /// The criteria applied, by name ("laceration", "contusion", "fracture", "full-compression",
  /// "crush").
  std::vector<std::string> Parts() const;
};

/// What a verdict on the head covers, for every output that judges a head impact: the
/// criteria of `rule` in words, then what ISO/TS 15066:2016 says of the head (Annex A, A.3.2:
/// transient contact with the skull, forehead and face is not permitted; quasi-static limits
/// of Table A.2: skull and forehead 130 N and 130 N/cm², face 65 N and 110 N/cm²).
std::vector<std::string> HeadVerdictScope(const DesignRule& rule);

/// The largest ratio that counts under a rule, and its criterion.
struct GoverningRatio {
  LimitingCriterion criterion = LimitingCriterion::kLaceration;
  double ratio = 0.0;  ///< unscaled (the rule's SF multiplies it) [-]
};

/// The head of a validity note where the paper's criterion accepts a fully compressed Hertz
/// covering (JudgedValidity, DesignScore::judged_validity); the covering's own note follows.
inline constexpr std::string_view kFullCompressionAcceptedNote =
    "Hertz law: the covering is fully compressed (phase 3, the robot on the bone through it), accepted under the "
    "paper's criterion (allow full compression); ";

/// The injury ratios of one design.
struct DesignScore {
  CoveringDesign design;  ///< thickness 0: the bare robot
  double poisson_ratio = 0.25;
  ImpactPeaks peaks;
  double laceration_ratio = 0.0;  ///< σ_t,max / laceration limit
  double contusion_ratio = 0.0;   ///< e_A,max / contusion limit
  /// F_max / the lowest published fracture force of the struck area (Scene's head.area,
  /// docs/model.md §7.1)
  double fracture_ratio = 0.0;
  /// The share of the covering's own travel used at the peak [-]
  /// (ImpactPeaks::covering_compression_ratio: (δ_max − t1) / (0.8 b_c)): > 1 means bottomed
  /// out. 0 for the bare robot and while δ_max stays within the scalp's travel.
  double compression_ratio = 0.0;
  /// Whether the covering's law describes this impact (core's CoveringLawValidity, with a Hertz
  /// covering's full compression accepted under the paper's criterion: optim::JudgedValidity);
  /// HeadVerdict(const DesignScore&, ...) counts it as "law-validity". Within for the bare robot.
  CoveringValidity validity;
  /// Whether and how the crush criterion applies (kNoMaterial unless scored for a material).
  CrushCheck crush_check = CrushCheck::kNoMaterial;
  /// σ_c,max / the material's compressive strength [-] when crush_check is kChecked; else 0.
  double crush_ratio = 0.0;
  /// The oracle could not evaluate this design (a time-path integration failed): the
  /// ratios are +inf and peaks.fully_compressed is set, so it is never safe, admissible or
  /// best under either criterion; the oracle counts it.
  bool failed = false;
  bool bare() const noexcept { return design.thickness_m == 0.0; }
  /// The largest injury ratio: laceration, contusion or fracture.
  double worst_ratio() const noexcept {
    const double skin = laceration_ratio > contusion_ratio ? laceration_ratio : contusion_ratio;
    return skin > fracture_ratio ? skin : fracture_ratio;
  }
  /// Every injury ratio <= 1/safety_factor (the skin criteria and the bone's fracture).
  bool safe(double safety_factor) const noexcept { return worst_ratio() * safety_factor <= 1.0; }
  /// The covering is fully compressed, or uses more than 1/safety_factor of its travel
  /// (never for the bare robot).
  bool compression_exceeded(double safety_factor) const noexcept {
    return !bare() && (peaks.fully_compressed || safety_factor * compression_ratio > 1.0);
  }
  /// The compressive strength a material needs for this design not to crush under a safety
  /// factor [Pa]: SF × σ_c,max (docs/model.md §12).
  double required_strength_Pa(double safety_factor) const noexcept {
    return safety_factor * peaks.max_compressive_stress_Pa;
  }
  /// Whether the paper's criterion accepts this covering's full compression under `rule`: a
  /// Hertz covering (its travel is then no validity limit, its other limits still are).
  bool full_compression_accepted(const DesignRule& rule) const noexcept {
    return rule.criterion == DesignCriterion::kPaper && peaks.covering_law == CoveringLaw::kHertz;
  }
  /// How far along its law's validity limits the covering went under `rule` [-] (0 bare):
  /// CoveringValidity::ratio, or ratio_full_compression_allowed where the paper's criterion
  /// accepts full compression (as optim::JudgedValidity).
  double validity_ratio(const DesignRule& rule) const noexcept {
    if (bare()) return 0.0;
    return full_compression_accepted(rule) ? validity.ratio_full_compression_allowed : validity.ratio;
  }
  /// The covering is out of its law's validity under `rule`: not within, unless the paper's
  /// criterion accepts a Hertz covering's full compression and its other limits hold.
  bool validity_fails(const DesignRule& rule) const noexcept {
    if (bare()) return false;
    return full_compression_accepted(rule) ? validity.ratio_full_compression_allowed > 1.0 : !validity.within;
  }
  /// The validity as judged under `rule` (within, ratio and note; as optim::JudgedValidity).
  CoveringValidity judged_validity(const DesignRule& rule) const;
  /// The largest ratio that counts under `rule`, and which criterion it is; the law's validity
  /// counts as validity_ratio(rule) / SF (not derated: SF × its ratio is the validity ratio).
  GoverningRatio governing(const DesignRule& rule) const noexcept;
  /// 1 − SF × the governing ratio: >= 0 when every counted criterion holds, the fraction of
  /// the (derated) limit left over on the one that binds.
  double margin(const DesignRule& rule) const noexcept {
    return 1.0 - rule.safety_factor * governing(rule).ratio;
  }
  /// Every criterion of `rule` holds (the bare robot: the injury ratios).
  bool admissible(const DesignRule& rule) const noexcept;
  /// admissible(DesignRule{safety_factor, criterion}): for designs without a material.
  bool admissible(double safety_factor, DesignCriterion criterion) const noexcept {
    return admissible(DesignRule{safety_factor, criterion});
  }
};

/// d(ratio)/d(log10 E_c) and d(ratio)/d(b_c) [1/m].
struct RatioGradient {
  double laceration[2] = {0.0, 0.0};
  double contusion[2] = {0.0, 0.0};
  double compression[2] = {0.0, 0.0};  ///< of DesignScore::compression_ratio
  double fracture[2] = {0.0, 0.0};     ///< of DesignScore::fracture_ratio
};

/// What a caller asks for: core's path choice (kAuto: the exact path where the scene admits
/// it, else the time path; kExact: refused for a scene it cannot answer; kTimePath: whatever
/// the scene). covopt::ToString names it "auto", "exact", "time-path".
using OracleChoice = PathChoice;
/// The inverse of ToString; empty for an unknown name.
std::optional<OracleChoice> ParseOracleChoice(std::string_view name) noexcept;

/// Which oracle runs.
enum class OracleKind {
  kExact,     ///< ExactPathOracle
  kTimePath,  ///< TimePathOracle
};
/// "exact", "time-path".
std::string_view ToString(OracleKind kind) noexcept;

/// Where an oracle's gradients come from.
enum class GradientSource {
  kAnalytic,               ///< ExactPeakSensitivities (exact path, conservative scene)
  kForwardSensitivities,   ///< CVODES forward sensitivities (time path, two-mass contact)
  kCentralDifference,      ///< a central difference of the oracle's own values
};
/// "analytic", "cvodes-forward-sensitivities", "central-difference".
std::string_view ToString(GradientSource source) noexcept;

/// The oracle's options.
struct OracleOptions {
  /// auto (default), exact or time-path.
  OracleChoice choice = OracleChoice::kAuto;
  /// The time path's integrator and tolerances when it runs (any method but kExact; rtol in
  /// [1e-14, 1e-2]). Default: TimeIntegrationOptions{} (ARKODE ERK 5(4), rtol 1e-8).
  /// record_history is ignored.
  TimeIntegrationOptions time_path;
};

/// The oracle a choice leads to on a scene, and why.
struct OracleSelection {
  OracleKind kind = OracleKind::kExact;
  /// One sentence, e.g. "auto: the conservative two-mass impact has an energy integral, the
  /// exact path answers every peak".
  std::string reason;
  GradientSource gradient = GradientSource::kAnalytic;
};

/// The rule every search uses (docs/model.md §10.4).
/// @throws std::invalid_argument for kExact on a scene the exact path cannot answer
///         ("oracle exact: the exact path needs an energy integral; ...").
OracleSelection ChooseOracle(const Scene& scene, OracleChoice choice);

/// Which oracle ran, how, what it cost and what failed.
struct OracleReport {
  OracleKind kind = OracleKind::kExact;
  std::string reason;  ///< OracleSelection::reason
  /// The time path's integrator and rtol; kExact and 0 for the exact path.
  ComputationMethod method = ComputationMethod::kExact;
  double relative_tolerance = 0.0;
  GradientSource gradient = GradientSource::kAnalytic;
  long evaluations = 0;           ///< designs scored (each one impact computation)
  long gradient_evaluations = 0;  ///< designs scored with a gradient (included in evaluations)
  long failed_evaluations = 0;    ///< evaluations whose integration failed
  std::string first_failure;      ///< the first failed evaluation's message; empty if none
  /// Central differences only: the largest relative disagreement between the gradients from
  /// steps h and 2h over all gradient evaluations [-] (the difference's own error check;
  /// one-sided differences beside a phase switch are not in it).
  double gradient_step_disagreement = 0.0;
  /// "exact path" or "time path (arkode-erk54, rtol 1e-08)".
  std::string Name() const;
};

/// The objective/constraint oracle over covering designs. `scene`'s covering is replaced by
/// each design. Thread-safe: the catalog snap scores materials on several threads.
class DesignOracle {
 public:
  virtual ~DesignOracle() = default;
  DesignOracle(const DesignOracle&) = delete;
  DesignOracle& operator=(const DesignOracle&) = delete;

  /// Ratios of a design (thickness > 0) with the oracle's ν_c.
  virtual DesignScore Score(const CoveringDesign& design) const = 0;
  /// Ratios and their gradient (GradientSource of the report).
  virtual DesignScore Score(const CoveringDesign& design, RatioGradient& gradient) const = 0;
  /// Ratios of a design with another Poisson ratio (a Hertz material without a curve):
  /// ScoreCovering of {E, ν, b}.
  DesignScore ScoreMaterial(const CoveringDesign& design, double poisson_ratio) const;
  /// Ratios of a whole covering (a catalog material: CoveringOf(material, b, law)), its curve
  /// and law included: the foam law scores a material with a measured curve. Its validity is
  /// set. Thickness > 0.
  virtual DesignScore ScoreCovering(const CoveringSpec& covering) const = 0;
  /// The same scene without covering.
  virtual DesignScore ScoreBare() const = 0;
  /// A relative step for difference quotients of this oracle's gradients (the Ipopt polish's
  /// Hessian) [-]: 1e-5 for the exact path, larger for the time path's noisier values.
  virtual double DifferenceStep() const noexcept = 0;

  const Scene& scene() const noexcept { return scene_; }
  /// Evaluations so far (thread-safe counter).
  long evaluations() const noexcept { return evaluations_.load(); }
  long failed_evaluations() const noexcept { return failed_evaluations_.load(); }
  /// The selection, counters and first failure so far.
  OracleReport Report() const;

 protected:
  DesignOracle(const Scene& scene, double covering_poisson_ratio, const InjuryLimits& limits,
               OracleSelection selection, const TimeIntegrationOptions* time_path);
  /// Fills the ratios of a score from its peaks.
  void Judge(DesignScore& score) const;
  /// Counts a failed evaluation and marks the score failed (ratios +inf).
  void Fail(DesignScore& score, const std::string& message) const;
  /// Records a central difference's step disagreement.
  void NoteDisagreement(double relative) const;
  /// The scene with `design` and ν as its covering.
  Scene WithCovering(const CoveringDesign& design, double poisson_ratio) const;
  /// d(compression ratio)/d(b_c) from dδ_max/db_c: t2 moves with b_c (docs/model.md §3.4).
  double CompressionThicknessDerivative(const DesignScore& score, double max_penetration_per_m) const;

  Scene scene_;
  InjuryLimits limits_;
  OracleSelection selection_;
  ComputationMethod method_ = ComputationMethod::kExact;
  double relative_tolerance_ = 0.0;
  mutable std::atomic<long> evaluations_{0};
  mutable std::atomic<long> gradient_evaluations_{0};
  mutable std::atomic<long> failed_evaluations_{0};
  mutable std::mutex failure_mutex_;
  mutable std::string first_failure_;
  mutable double gradient_step_disagreement_ = 0.0;
};

/// The exact path as the oracle.
class ExactPathOracle final : public DesignOracle {
 public:
  /// @throws std::invalid_argument if the rest of the scene is invalid, or the exact path
  ///         cannot answer it (a braking robot, a neck).
  ExactPathOracle(const Scene& scene, double covering_poisson_ratio, const InjuryLimits& limits = {},
                  std::string reason = "exact: as asked");
  DesignScore Score(const CoveringDesign& design) const override;
  DesignScore Score(const CoveringDesign& design, RatioGradient& gradient) const override;
  DesignScore ScoreCovering(const CoveringSpec& covering) const override;
  DesignScore ScoreBare() const override;
  double DifferenceStep() const noexcept override { return 1e-5; }
};

/// The exact path's oracle by its earlier name.
using CoveringOracle = ExactPathOracle;

/// The time path as the oracle.
class TimePathOracle final : public DesignOracle {
 public:
  /// @throws std::invalid_argument if the scene is invalid or an option is out of range
  ///         (naming oracle.time_path.<field>).
  TimePathOracle(const Scene& scene, double covering_poisson_ratio, const InjuryLimits& limits = {},
                 const TimeIntegrationOptions& time_path = {}, std::string reason = "time-path: chosen");
  DesignScore Score(const CoveringDesign& design) const override;
  DesignScore Score(const CoveringDesign& design, RatioGradient& gradient) const override;
  DesignScore ScoreCovering(const CoveringSpec& covering) const override;
  DesignScore ScoreBare() const override;
  double DifferenceStep() const noexcept override;

 private:
  DesignScore Simulate(const CoveringSpec& covering) const;
  TimeIntegrationOptions time_path_;
};

/// The oracle `options` choose for `scene` (ChooseOracle), built.
/// @throws std::invalid_argument as ChooseOracle and the oracles' constructors.
std::unique_ptr<DesignOracle> MakeOracle(const Scene& scene, double covering_poisson_ratio,
                                         const InjuryLimits& limits, const OracleOptions& options);

}  // namespace covopt::optim
