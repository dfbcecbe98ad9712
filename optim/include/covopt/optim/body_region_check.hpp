#pragma once
/// @file body_region_check.hpp
/// ISO/TS 15066 body regions with the covering (docs/model.md §13): the verdict of one contact,
/// the largest safe speed per region, the all-regions table an integrator wants, and the
/// covering that lets the robot reach a speed for every region named.
///
/// The verdict of a contact with one area of one region (limits from
/// covopt/materials/body_regions.hpp), under a DesignRule with safety factor SF:
///
///     force         SF × F_max / F_lim <= 1
///     pressure      SF × p_max / p_lim <= 1     (not evaluated for a bare robot without an area)
///     compression   SF × δ_c / (0.8 b_c) <= 1   (with a covering, under the default criterion;
///                                                fully compressed is never admissible then)
///     crush         SF × p_max / strength <= 1  (a catalog material of known strength, unless
///                                                crushing is allowed: the covering's peak
///                                                pressure is its compressive stress)
///
/// The speed limit: each ratio grows with the speed, and each limit is a force on the energy
/// balance (F_lim/SF; the force at which p_max reaches p_lim/SF or strength/SF; the force at
/// δ_c = 0.8 b_c/SF), so v_max = min over the counted limits of SpeedAtPeakForce(F*), in
/// closed form. Bare robot: F_lim / sqrt(mu k_H) (Annex A).
///
/// A braking robot (BodyContactScene::robot_brakes, docs/model.md §13.10) has no energy
/// balance: its contacts are judged on the time path, and its speed limit is bracketed there
/// (speed_limit.hpp's scan and narrowing), starting just below the unbraked closed-form limit,
/// which bounds it from below (braking only lowers the peaks), and narrowed by regula falsi on
/// the governing ratio: 7 to 14 time-path runs to the peak (SolveBodyContactPeaks), 0.2-0.4 ms
/// (bench/bench_body_region_check.cpp),
/// so the audit can call it per point-sample where the unbraked bound could govern.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <covopt/core/body_contact.hpp>
#include <covopt/core/scene.hpp>
#include <covopt/core/verdict.hpp>
#include <covopt/materials/body_regions.hpp>

#include "covopt/optim/covering_design.hpp"
#include "covopt/optim/oracle.hpp"
#include "covopt/optim/speed_limit.hpp"

namespace covopt::optim {

/// Which limit of a body-region verdict binds.
enum class BodyLimitKind {
  kNone,             ///< nothing binds within the searched range
  kForce,            ///< F_max against F_lim / SF
  kPressure,         ///< p_max against p_lim / SF
  kFullCompression,  ///< the covering's travel against 1 / SF
  kCrush,            ///< p_max against the covering's compressive strength / SF
  kLawValidity,      ///< the covering's law leaves its validity (core/verdict.hpp's "law-validity")
};
/// "none", "force", "pressure", "full-compression", "crush", "law-validity".
std::string_view ToString(BodyLimitKind kind) noexcept;

/// How a body-region contact is judged.
struct BodyRegionOptions {
  /// Safety factor, criterion (no-full-compression by default), crushing and unknown strengths.
  DesignRule rule;
  /// The covering's material, when it is a catalog one: its crush behaviour and strength
  /// (only these are read; the covering's modulus, Poisson ratio and thickness are the
  /// scene's). Empty: a covering given by its modulus (no crush check: CrushCheck::kNoMaterial).
  /// Not read for the bare robot.
  std::optional<CandidateMaterial> material;
  /// The design rule "within the covering's travel" (docs/model.md §15.6) as a limit: the
  /// covering's compression stays within its travel with the safety factor as a reserve,
  /// SF × δ_c / travel <= 1 — travel 0.8 b_c for a Hertz layer (today's full-compression limit,
  /// exactly), the curve's last strain ε_end h for a foam (d <= ε_end h / SF). It is the
  /// verdict's "full-compression" criterion (a design rule), counted when set. Default false:
  /// the verdicts and speed limits judge injury, the criterion is reported uncounted, and a
  /// covering used up below the limit is reported as its own speed
  /// (BodyRegionSpeedLimit::covering_used_up_m_per_s). The rule's criterion (DesignRule) is not
  /// read for the body regions: this decides.
  bool keep_travel = false;
};

/// The options of a body-region verdict as both shells take them: the safety factor; the
/// paper's criterion when `allow_full_compression`; the covering's travel rule as a limit only
/// with `keep_travel` (--keep-travel, keep_travel=True; not with allow_full_compression: the
/// travel rule is then reported, and a covering used up is reported at its speed); crushing allowed
/// when `allow_crushing`; a covering of unknown strength judged without the crush check when
/// `unknown_strength_allowed`; and the covering's catalog `material` (its crush behaviour and
/// strength), if any.
BodyRegionOptions BodyRegionOptionsOf(double safety_factor, bool allow_full_compression, bool allow_crushing,
                                      bool unknown_strength_allowed, const materials::Material* material,
                                      bool keep_travel = false);

/// The rule a body-region verdict applies under `options`: options.rule with its travel
/// criterion set by keep_travel (no full compression when set, else the paper's: the travel
/// reported); what BodyRegionCriterion and the scopes describe for the judging commands.
DesignRule JudgedRule(const BodyRegionOptions& options) noexcept;

/// The bare robot's own verdict needs its pressure: Table A.2 limits the pressure as well as the
/// force, and a bare robot's pressure is its force over its contact area. True for a scene with
/// no covering and no contact area, whose verdict would be the force's alone (the CLI, Python and
/// SweepBodyRegion refuse to judge it; with a covering the pressure is the Hertz pressure).
bool BareRobotLacksContactArea(const BodyContactScene& scene) noexcept;

/// `scene` with the region's k_H, m_H and contact type from `limits`.
BodyContactScene WithRegion(BodyContactScene scene, const materials::BodyLimits& limits);

/// One contact judged against one region's limits. For a braking robot the contact is the
/// time path's; if that run failed (contact.ok() false) the judgement is not an answer:
/// governing kNone; force_ratio, governing_ratio (and pressure_ratio where the pressure is
/// evaluated) +inf; margin -inf; not admissible; and the scope says why.
struct BodyRegionJudgement {
  materials::BodyLimits limits;
  BodyContactResult contact;   ///< the exact path's peaks (the time path's for a braking robot)
  double force_ratio = 0.0;    ///< F_max / F_lim [-]
  /// p_max / p_lim [-]; empty when the pressure is not evaluated (bare robot, no area).
  std::optional<double> pressure_ratio;
  double compression_ratio = 0.0;  ///< δ_c / (0.8 b_c) [-]; 0 bare
  CrushCheck crush_check = CrushCheck::kNoMaterial;
  double crush_ratio = 0.0;        ///< p_max / strength [-] when crush_check is kChecked
  BodyLimitKind governing = BodyLimitKind::kForce;  ///< the largest counted ratio
  double governing_ratio = 0.0;    ///< unscaled [-]
  /// SF × every counted ratio <= 1 (and not fully compressed under the default criterion;
  /// a material of unknown strength only where the rule allows it).
  bool admissible = false;
  /// 1 − SF × governing_ratio.
  double margin = 0.0;
  /// Whose criteria, e.g. "ISO/TS 15066:2016 transient, chest (sternum): 280 N, 240 N/cm²".
  std::string scope;
  /// The verdict (BodyRegionVerdict, verdicts.hpp): force, pressure, the covering's design rules;
  /// admissible == verdict.safe(), margin == verdict.margin(). Its scope is `scope`.
  Verdict verdict;
};

/// Judges `scene` (its robot, speed and covering; the region's fields are taken from
/// `limits`) against `limits` under `options`.
/// @throws std::invalid_argument naming the field for a bad scene or options.
BodyRegionJudgement JudgeBodyContact(const BodyContactScene& scene,
                                     const materials::BodyLimits& limits,
                                     const BodyRegionOptions& options = {});
/// JudgeBodyContact with the time path's integrator, tolerances and step limit for a braking
/// robot (the only path that answers it; not read otherwise). The overloads without it use
/// TimeIntegrationOptions{} (ERK 5(4), rtol 1e-8).
/// @throws std::invalid_argument as JudgeBodyContact, or naming a time_path option.
BodyRegionJudgement JudgeBodyContact(const BodyContactScene& scene, const materials::BodyLimits& limits,
                                     const BodyRegionOptions& options, const TimeIntegrationOptions& time_path);

/// The largest speed safe against one region (every lower speed is safe too).
struct BodyRegionSpeedLimit {
  /// kLimited, kSafeUpToSearchLimit (above the model's 100 m/s; the value is 100), or
  /// kNoSafeValue (a material that crushes or bottoms out at any speed cannot; 0). For a
  /// braking robot also kEvaluationFailed: a time-path run the search needed failed, so there
  /// is no answer (the value is 0 and the message names the speed and the failure).
  SpeedLimitStatus status = SpeedLimitStatus::kLimited;
  double max_safe_speed_m_per_s = 0.0;  ///< [m/s]
  BodyLimitKind limited_by = BodyLimitKind::kNone;
  /// The contact at the limit speed, judged (the binding ratio is 1/SF there within rounding).
  BodyRegionJudgement at_limit;
  /// One sentence: "chest (sternum), transient: 0.626 m/s, limited by force (ISO/TS 15066 ...)".
  std::string message;
  /// The time-path runs a braking robot's limit took; 0 in closed form.
  int time_path_runs = 0;
  /// The speed [m/s] at which the covering is used up (its travel reached: past it a rigid
  /// stop), when it is below the model's 100 m/s; empty bare and for a braking robot (no closed
  /// form). Below max_safe_speed_m_per_s the message says "covering used up at v = ...": not an
  /// injury, and without keep_travel not a limit.
  std::optional<double> covering_used_up_m_per_s;
};

/// The largest safe speed of `scene`'s robot and covering against `limits` (scene's speed is
/// ignored), in closed form on the energy balance (a foam covering: each limit is an energy,
/// docs/model.md §15.6); bracketed on the time path for a braking
/// robot (see the file comment: about 10 runs).
/// @throws std::invalid_argument as JudgeBodyContact.
BodyRegionSpeedLimit MaxSafeSpeed(const BodyContactScene& scene,
                                  const materials::BodyLimits& limits,
                                  const BodyRegionOptions& options = {});
/// MaxSafeSpeed with the time path's options for a braking robot (JudgeBodyContact's overload).
BodyRegionSpeedLimit MaxSafeSpeed(const BodyContactScene& scene, const materials::BodyLimits& limits,
                                  const BodyRegionOptions& options, const TimeIntegrationOptions& time_path);

/// One row of the all-regions table: one area of one region, bare and with the covering.
struct BodyRegionSpeedLimitRow {
  materials::BodyLimits limits;
  BodyRegionSpeedLimit bare;
  /// With the scene's covering; empty when the scene has none.
  std::optional<BodyRegionSpeedLimit> covered;
  /// covered / bare speed [-] (empty without a covering or a bare limit of 0).
  std::optional<double> gain() const noexcept;
};

/// The table for every entry of `regions` (e.g. BodyRegionTable::AllLimits(contact)), in order.
/// About 1-2 µs per row, most of it the rows' text (bench/bench_body_region_check.cpp).
/// @throws std::invalid_argument as JudgeBodyContact.
std::vector<BodyRegionSpeedLimitRow> BodyRegionSpeedLimitTable(
    const BodyContactScene& scene, std::span<const materials::BodyLimits> regions,
    const BodyRegionOptions& options = {});
/// The table with the time path's options for a braking robot (JudgeBodyContact's overload).
std::vector<BodyRegionSpeedLimitRow> BodyRegionSpeedLimitTable(const BodyContactScene& scene,
                                                               std::span<const materials::BodyLimits> regions,
                                                               const BodyRegionOptions& options,
                                                               const TimeIntegrationOptions& time_path);

/// Whose criteria judge the head among the body regions: "skin injury, Park et al. 2011".
std::string_view HeadCriteriaName() noexcept;

/// The criteria a body-region verdict applies under `rule`, in words (the "criterion" of
/// `covopt speed-limit/optimize/robot --body-region --json` and covopt's Python results):
/// "each region's force and pressure (ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M)[, the
/// head's laceration and contusion (Park et al. 2011)][, the covering not fully compressed][, the
/// covering not crushed where its strength is known]; safety factor SF on each". `citation`: the
/// edition of the limit table judged on (materials::ContactTargets::Citation()); empty: the
/// built-in table's.
std::string BodyRegionCriterion(const DesignRule& rule, bool head, std::string_view citation = {});

/// `covopt optimize --body-region ... --speed V`: the covering (catalog material and
/// thickness) that lets the robot reach the speed for every region named.
struct BodyRegionDesignRequest {
  /// The robot (mass, radius, contact area) and the target speed; its covering is designed.
  BodyContactScene scene;
  /// The regions (areas, contact types) to protect; may be empty when the head is judged.
  std::vector<materials::BodyLimits> regions;
  /// Set: the head too, judged by Park et al.'s skin model (its robot mass, radius and speed
  /// are taken from `scene`; its covering from each candidate).
  std::optional<Scene> head;
  /// The candidates, in catalog order (SelectCandidates).
  std::vector<CandidateMaterial> materials;
  /// Safety factor, criterion, crushing, unknown strengths.
  DesignRule rule;
  /// The law the materials are designed with (DesignOptions::covering_law): auto (default) the
  /// foam law for a material with a measured curve, foam, or hertz.
  CoveringLaw covering_law = CoveringLaw::kAuto;
  /// Thickness range [m] scanned per material, and the resolution of the bisection.
  double min_thickness_m = 0.1e-3;
  double max_thickness_m = 0.05;
  int thickness_scan_points = 250;
  double thickness_resolution_m = 1e-6;
  /// The recommended thickness is rounded up to a multiple of this [m] (0: not rounded) and
  /// checked again.
  double thickness_step_m = 0.5e-3;
};

/// One candidate material's outcome.
struct BodyRegionDesignCandidate {
  CandidateMaterial material;
  /// The thinnest admissible thickness [m] (rounded up to the step), if any in range.
  std::optional<double> thickness_m;
  /// At that thickness (or at the thickest scanned, when none is admissible): one judgement
  /// per region, in the request's order.
  std::vector<BodyRegionJudgement> regions;
  /// The head's score at that thickness, when the head is judged.
  std::optional<DesignScore> head;
  /// The governing ratio over every region (and the head), unscaled, and where it is.
  double governing_ratio = 0.0;
  std::string governing_where;  ///< e.g. "hands-fingers (palm-dominant): pressure"
  bool admissible() const noexcept { return thickness_m.has_value(); }
};

/// The answer of DesignForBodyRegions.
struct BodyRegionDesignResult {
  /// One sentence: "Recommended: ... at 6.5 mm (every region safe at 1.2 m/s)", or why not.
  std::string message;
  /// Every region's verdict for the bare robot at the speed (and the head's, if judged).
  std::vector<BodyRegionJudgement> bare_robot;
  std::optional<DesignScore> bare_head;
  /// Every region (and the head) safe for the bare robot, with its pressure checked: false
  /// when the scene gives no contact area (a verdict on the force alone is not "safe").
  bool bare_robot_safe = false;
  /// Admissible first (thinnest, then by margin), then the others by governing ratio.
  std::vector<BodyRegionDesignCandidate> candidates;
  std::optional<std::size_t> recommendation;
  /// What every verdict covers: one line per standard or model applied.
  std::vector<std::string> scope;
  std::vector<std::string> warnings;
};

/// Designs the covering for every region named in `request`: per material, the thinnest
/// admissible thickness by a scan of thickness_scan_points over [min, max] then bisection
/// (the admissible set need not be an interval), rounded up to the step and checked again,
/// as the catalog snap of FindThinnestSafeCovering. The head is scored as that snap scores a
/// material: ExactPathOracle::ScoreMaterial, CheckCrush, DesignScore::admissible(rule).
/// @throws std::invalid_argument naming the field for bad input (no regions and no head, a
///         flat robot, an out-of-range thickness range or speed, a material's modulus, Poisson
///         ratio or strength, a head scene the exact path cannot answer).
BodyRegionDesignResult DesignForBodyRegions(const BodyRegionDesignRequest& request);

}  // namespace covopt::optim
