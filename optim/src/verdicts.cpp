#include "covopt/optim/verdicts.hpp"

#include <limits>

namespace covopt::optim {
namespace {

/// The head's injury criteria: name, unit and where Assess puts them. Adding a criterion to
/// InjuryAssessment adds one line here.
struct HeadInjury {
  std::string_view name;
  std::string_view unit;
  InjuryVerdict InjuryAssessment::*verdict;
};
constexpr HeadInjury kHeadInjuries[] = {
    {"laceration", "Pa", &InjuryAssessment::laceration},
    {"contusion", "J/m2", &InjuryAssessment::contusion},
    {"fracture", "N", &InjuryAssessment::fracture},
};

/// Whose limit a head criterion is: Park et al.'s for the skin, the struck area's published
/// fracture force (its citation) for the bone, or the caller's given force.
std::string_view HeadSource(const HeadInjury& injury, const InjuryVerdict& verdict, HeadArea area) {
  if (injury.verdict != &InjuryAssessment::fracture) return kParkSource;
  const FractureForce& row = FractureForceOf(area);
  return verdict.limit == row.force_N ? row.source : std::string_view("given (limits.fracture_force_N)");
}

}  // namespace

void AddCoveringRules(Verdict& v, double compression_ratio, bool fully_compressed, double stress_Pa,
                      const DesignRule& rule, const CrushInput& crush) {
  v.Add(kFullCompressionRule, CriterionPart::kDesignRule, "1", compression_ratio, 1.0, "the covering's travel",
        rule.compression_counts(), fully_compressed);
  switch (crush.check) {
    case CrushCheck::kChecked:
      v.Add("crush", CriterionPart::kDesignRule, "Pa", stress_Pa, crush.compressive_strength_Pa,
            "the material's compressive strength", !rule.crushing_allowed);
      return;
    case CrushCheck::kUnknownStrength: {
      Criterion& c = v.Add("crush", CriterionPart::kDesignRule, "Pa", stress_Pa,
                           std::numeric_limits<double>::quiet_NaN(), "the material's compressive strength",
                           rule.refuses_unknown_strength(), true);
      c.note = rule.refuses_unknown_strength() ? "strength unknown: refused" : "strength unknown: not checked";
      return;
    }
    case CrushCheck::kDoesNotCrush:
    case CrushCheck::kNoMaterial: return;
  }
}

namespace {

/// HeadVerdict without its scope (the limit searches judge ~70 impacts per answer).
Verdict HeadCriteria(const ImpactPeaks& peaks, bool covered, const InjuryLimits& limits, const DesignRule& rule,
                     const CrushInput& crush, HeadArea area, const CoveringValidity* validity) {
  Verdict v;
  v.safety_factor = rule.safety_factor;
  const InjuryAssessment assessment = Assess(peaks, limits, area);
  for (const HeadInjury& injury : kHeadInjuries) {
    const InjuryVerdict& iv = assessment.*injury.verdict;
    v.Add(injury.name, CriterionPart::kInjury, injury.unit, iv.value, iv.limit, HeadSource(injury, iv, area));
  }
  if (covered) {
    AddCoveringRules(v, peaks.covering_compression_ratio(), peaks.fully_compressed, peaks.max_compressive_stress_Pa,
                     rule, crush);
    if (peaks.covering_law == CoveringLaw::kFoam) {
      // The foam law's travel is its measured curve (docs/model.md §16): the design rule keeps
      // the peak strain within it, the safety factor as a reserve of strain.
      for (Criterion& c : v.criteria) {
        if (c.name != kFullCompressionRule) continue;
        c.name = kWithinCurveRule;
        c.source = "the foam's measured curve (strain at the peak over the curve's last strain)";
      }
    }
    if (validity) AddLawValidity(v, validity->within, validity->ratio);
  }
  return v;
}

}  // namespace

CoveringValidity JudgedValidity(const ImpactModel& model, const ImpactPeaks& peaks, bool accept_full_compression) {
  CoveringValidity validity = CoveringLawValidity(model, peaks);
  if (!accept_full_compression || model.is_foam()) return validity;
  // Under the paper's criterion the Hertz covering's travel is no validity limit: how far along
  // is its other limits' ratio (a solid elastomer's), as DesignScore::validity_ratio.
  validity.ratio = validity.ratio_full_compression_allowed;
  if (validity.within || !peaks.fully_compressed) return validity;
  // The paper's criterion accepts phase 3 (the robot on the bone through the covering): judged
  // as if the covering had stopped at its full compression, whatever else holds still counts.
  ImpactPeaks at_full = peaks;
  at_full.fully_compressed = false;
  CoveringValidity accepted = CoveringLawValidity(model, at_full);
  accepted.ratio = accepted.ratio_full_compression_allowed;
  if (!accepted.within) return accepted;
  accepted.note = std::string(kFullCompressionAcceptedNote) + accepted.note;
  return accepted;
}

Verdict HeadVerdict(const ImpactPeaks& peaks, bool covered, const InjuryLimits& limits, const DesignRule& rule,
                    const CrushInput& crush, HeadArea area, const CoveringValidity* validity) {
  Verdict v = HeadCriteria(peaks, covered, limits, rule, crush, area, validity);
  v.scope = HeadVerdictScope(rule);
  return v;
}

Verdict HeadVerdict(const DesignScore& score, const InjuryLimits& limits, const DesignRule& rule,
                    double compressive_strength_Pa, HeadArea area) {
  const CoveringValidity validity = score.judged_validity(rule);
  Verdict v = HeadVerdict(score.peaks, !score.bare(), limits, rule, {score.crush_check, compressive_strength_Pa}, area,
                          &validity);
  v.evaluated = !score.failed;
  return v;
}

Verdict BodyRegionVerdict(const BodyContactResult& contact, const materials::BodyLimits& limits, bool covered,
                          const DesignRule& rule, const CrushInput& crush) {
  Verdict v;
  v.safety_factor = rule.safety_factor;
  if (!contact.ok()) {
    v.evaluated = false;
    return v;
  }
  // The criteria keep a view of their source: the table's edition, which lives as long as the table.
  const std::string_view source = limits.region != nullptr && limits.region->table
                                      ? std::string_view(limits.region->table->edition)
                                      : std::string_view(materials::BuiltInEdition());
  v.Add("force", CriterionPart::kInjury, "N", contact.peak_force_N, limits.force_N, source);
  if (contact.peak_pressure_Pa) {
    v.Add("pressure", CriterionPart::kInjury, "Pa", *contact.peak_pressure_Pa, limits.pressure_Pa, source);
  }
  if (covered) {
    AddCoveringRules(v, contact.compression_ratio, contact.fully_compressed, contact.covering_stress_Pa, rule, crush);
    AddLawValidity(v, contact.validity.within, contact.validity.ratio);
  }
  return v;
}

CrushInput CrushInputOf(const CoveringCrushCheck& check) noexcept {
  if (check.compressive_strength_Pa > 0.0) return {CrushCheck::kChecked, check.compressive_strength_Pa};
  return {check.check, 0.0};
}

Verdict HeadVerdict(const Scene& scene, const ImpactPeaks& peaks, const SpeedLimitOptions& options,
                    const CoveringValidity* given) {
  const double strength = options.covering_compressive_strength_Pa;
  const CrushInput crush = strength > 0.0 ? CrushInput{CrushCheck::kChecked, strength} : CrushInput{};
  const bool covered = scene.covering.thickness_m > 0.0;
  CoveringValidity validity;
  if (given) {
    validity = *given;
  } else if (covered) {
    validity = JudgedValidity(ImpactModel::FromScene(scene), peaks, options.allow_full_compression);
  }
  return HeadCriteria(peaks, covered, options.limits, options.rule(), crush, scene.head.area, &validity);
}

Verdict SimulationVerdict(const Scene& scene, const ImpactPeaks& peaks, const InjuryLimits& limits,
                          double safety_factor, const CoveringCrushCheck& crush, bool allow_full_compression,
                          bool keep_travel) {
  SpeedLimitOptions options;
  options.safety_factor = safety_factor;
  options.limits = limits;
  options.allow_full_compression = allow_full_compression;
  options.keep_travel = keep_travel;
  DesignRule rule = options.rule();
  rule.unknown_strength_allowed = true;  // reported, not refused
  const bool covered = scene.covering.thickness_m > 0.0;
  CoveringValidity validity;
  if (covered) validity = JudgedValidity(ImpactModel::FromScene(scene), peaks, allow_full_compression);
  Verdict v = HeadCriteria(peaks, covered, limits, rule, CrushInputOf(crush), scene.head.area, &validity);
  v.scope = HeadVerdictScope(rule);
  return v;
}

}  // namespace covopt::optim
