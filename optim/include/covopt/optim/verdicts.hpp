#pragma once
/// @file verdicts.hpp
/// The head's verdict (covopt::Verdict, core/verdict.hpp) built in one place from what the
/// computations return: the impact's peaks, InjuryAssessment (Assess) for the injury criteria,
/// the covering's travel and the crush check for its design rules, under a DesignRule. Every
/// command that judges the head (simulate, speed-limit, optimize, robot --trajectory, audit,
/// covopt.simulate) gets its SAFE/UNSAFE from Verdict::safe() of a verdict built here. The
/// body regions' verdict is built by JudgeBodyContact (BodyRegionJudgement::verdict).

#include <covopt/core/body_contact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/core/impact_result.hpp>
#include <covopt/core/scene.hpp>
#include <covopt/core/verdict.hpp>
#include <covopt/materials/body_regions.hpp>

#include "covopt/optim/oracle.hpp"
#include "covopt/optim/speed_limit.hpp"

namespace covopt::optim {

/// How the crush criterion applies to a head impact's covering.
struct CrushInput {
  CrushCheck check = CrushCheck::kNoMaterial;
  double compressive_strength_Pa = 0.0;  ///< [Pa], > 0 when check is kChecked
};

/// The covering's travel rule under the Hertz law: the share of its travel (0.8 b_c) used.
inline constexpr std::string_view kFullCompressionRule = "full-compression";
/// The same rule under the foam law (docs/model.md §16): the strain at the peak over the
/// curve's last strain, the layer kept within its measured curve (a used-up layer fails it
/// whatever SF). HeadVerdict names a foam covering's rule so; its counting is the same.
inline constexpr std::string_view kWithinCurveRule = "within-curve";

/// Whose limits the head's criteria are.
inline constexpr std::string_view kParkSource = "Park et al. 2011";

/// The covering's validity at `peaks` of `model` as a verdict counts it (core's
/// CoveringLawValidity): under the paper's criterion (`accept_full_compression`, Park's phase 3
/// accepted) a Hertz covering's full compression is not a validity failure; whatever else takes
/// it out of its law still is (the note then says so). The foam law is unchanged.
CoveringValidity JudgedValidity(const ImpactModel& model, const ImpactPeaks& peaks, bool accept_full_compression);

/// The head's verdict on one impact: the injury criteria of Assess(peaks, limits, area)
/// (laceration, contusion, and fracture: F_max against the struck area's fracture force) and, with a covering (`covered`), its design rules: full compression
/// (counted under the no-full-compression criterion; a fully compressed covering fails it
/// whatever SF) and crush (a known strength: counted unless crushing is allowed; an unknown
/// one: counted, and failed, only where the rule refuses unknown strengths), and, with a
/// `validity` (JudgedValidity), "law-validity" (counted always: out of it is never SAFE). The
/// scope is HeadVerdictScope(rule).
Verdict HeadVerdict(const ImpactPeaks& peaks, bool covered, const InjuryLimits& limits, const DesignRule& rule,
                    const CrushInput& crush = {}, HeadArea area = HeadArea::kFrontal,
                    const CoveringValidity* validity = nullptr);

/// HeadVerdict of a design score (its peaks, its crush check, `compressive_strength_Pa` the
/// material's when the check is kChecked; `area` the struck area; its validity counted as
/// "law-validity"); a failed score is not evaluated.
Verdict HeadVerdict(const DesignScore& score, const InjuryLimits& limits, const DesignRule& rule,
                    double compressive_strength_Pa, HeadArea area = HeadArea::kFrontal);

/// The crush input of a covering check (CrushCheckFor): kChecked with its strength, the
/// material's check otherwise.
CrushInput CrushInputOf(const CoveringCrushCheck& check) noexcept;

/// The head's verdict of an impact of `scene` judged as a limit search judges it (MaxSafeSpeed,
/// CheckTrajectory, the audit): options.rule() (the travel rule counted only with keep_travel),
/// its limits, the covering's strength and the law's validity (JudgedValidity, full compression
/// accepted with allow_full_compression). Its
/// scope is left empty (HeadVerdictScope(options.rule()) has it): the searches build one per
/// impact they judge.
/// `validity`: JudgedValidity of the impact when the caller has it (else it is computed).
Verdict HeadVerdict(const Scene& scene, const ImpactPeaks& peaks, const SpeedLimitOptions& options,
                    const CoveringValidity* validity = nullptr);

// Whose limits the body regions' injury criteria are: each BodyLimits::Citation() (the
// edition of its table, materials/body_regions.hpp).

/// The covering's design rules of one contact, appended to `verdict` (the head's and the body
/// regions' alike): "full-compression", the share of the covering's travel used [-] against 1
/// (counted under the no-full-compression criterion; failed when `fully_compressed`, whatever
/// SF), then "crush", the covering's peak stress [Pa] against its strength (CrushInput).
void AddCoveringRules(Verdict& verdict, double compression_ratio, bool fully_compressed, double stress_Pa,
                      const DesignRule& rule, const CrushInput& crush);

/// A body region's verdict on one contact (JudgeBodyContact fills BodyRegionJudgement::verdict
/// with it): force against F_lim, pressure against p_lim where the pressure is evaluated (ISO/TS
/// 15066 Table A.2), and with a covering (`covered`) AddCoveringRules with the contact's
/// compression and peak pressure, and "law-validity" from the contact's validity (counted always).
/// A failed contact (a time-path run) is not evaluated.
Verdict BodyRegionVerdict(const BodyContactResult& contact, const materials::BodyLimits& limits, bool covered,
                          const DesignRule& rule, const CrushInput& crush);

/// `covopt simulate`'s and covopt.simulate()'s verdict: the head's verdict as a limit search
/// judges it (HeadVerdict(scene, peaks, options)): the law's validity counts always (a Hertz
/// covering's full compression is accepted with `allow_full_compression`), the covering's travel
/// rule only with `keep_travel`; crushing checked where the covering's material has a known
/// strength (`crush`, from CrushCheckFor), unknown strengths reported, not refused, as
/// speed-limit does. The scope is HeadVerdictScope of that rule.
Verdict SimulationVerdict(const Scene& scene, const ImpactPeaks& peaks, const InjuryLimits& limits,
                          double safety_factor, const CoveringCrushCheck& crush, bool allow_full_compression = false,
                          bool keep_travel = false);

}  // namespace covopt::optim
