// The default answer: the design's admissible candidates checked over their stated
// uncertainty (material_range.hpp), raised to the thinnest thickness that holds over it or
// refused, re-ranked, and the nearest changes when none is left.
#include "covopt/optim/design_answer.hpp"

#include <algorithm>
#include <numeric>

#include <covopt/core/number_format.hpp>

namespace covopt::optim {
namespace {

std::string Mm(double metres) { return FormatFixed(metres * 1e3, 2) + " mm"; }

/// The score of `c` at `thickness_m` with its curve scaled by `scale` (the range's worst end),
/// as the design's rows show a score.
DesignScore ScoreAt(const Scene& scene, const RangedMaterial& m, const CandidateMaterial& c, double thickness_m,
                    double scale, const InjuryLimits& limits, const DesignRule& rule) {
  DesignScore s;
  s.design = {c.youngs_modulus_Pa, thickness_m};
  s.poisson_ratio = c.poisson_ratio;
  RangeImpact impact = RangeImpactAt(scene, m, thickness_m, scale, !rule.compression_counts());
  s.peaks = impact.peaks;
  s.validity = std::move(impact.validity);
  const InjuryAssessment injury = Assess(s.peaks, limits, scene.head.area);  // as the oracle judges a score
  s.laceration_ratio = injury.laceration.ratio;
  s.contusion_ratio = injury.contusion.ratio;
  s.fracture_ratio = injury.fracture.ratio;
  s.compression_ratio = s.peaks.covering_compression_ratio();
  CheckCrush(c, s);
  return s;
}

/// "at curve scale 0.558: within-curve 1.23 (margin -23.0 %)".
std::string WorstText(const MaterialRangeCheck& check) {
  const Verdict& v = check.worst();
  return "worst at curve scale " + FormatSignificant(check.worst_scale(), 3) + ": " +
         std::string(v.governing_name()) + ", margin " + FormatPercent(v.margin());
}

/// One curve candidate judged over its range: at the thinnest thickness that
/// holds at both ends of it (problem a; its designed thickness need not be that one) or at the
/// given thickness (problem b), with its row's score at the range's worst end there; refused
/// when none holds. Its note says what changed.
void CheckCandidate(const DesignRequest& request, const DesignResult& r, CandidateOutcome& c, std::string& note) {
  const DesignOptions& o = request.options;
  const RangedMaterial m = RangedMaterialOf(c.material, request.options.covering_law);
  if (!m.foam()) return;
  // The thickness it was designed at [m], 0 when it was not admissible as designed.
  const double designed = c.safe ? r.thickness_m.value_or(c.recommended_thickness_m.value_or(0.0)) : 0.0;
  std::optional<double> holds;
  if (r.thickness_m) {
    if (CheckOverRange(request.scene, m, *r.thickness_m, o).admissible()) holds = r.thickness_m;
  } else {
    holds = ThinnestOverRange(request.scene, m, o, o.space.max_thickness_m);
  }
  const double judged_at = holds.value_or(r.thickness_m ? *r.thickness_m : o.space.max_thickness_m);
  const MaterialRangeCheck check = CheckOverRange(request.scene, m, judged_at, o);
  c.score = ScoreAt(request.scene, m, c.material, judged_at, check.worst_scale(), o.limits, r.rule);
  c.margin = c.score.margin(r.rule);
  if (holds) {
    const bool changed = designed != *holds;
    if (changed) {
      note = (designed > 0.0 ? Mm(designed) + " as designed, " : std::string("admissible: ")) + Mm(*holds) + " over " +
             m.range.Describe() + " (" + WorstText(check) + ")";
    }
    c.safe = true;
    if (!r.thickness_m) {
      if (changed) c.stock_thickness_beyond_max_m.reset();
      c.min_safe_thickness_m = c.recommended_thickness_m = holds;
    }
    return;
  }
  c.safe = false;
  c.stock_thickness_beyond_max_m.reset();
  if (!r.thickness_m) c.min_safe_thickness_m = c.recommended_thickness_m = std::nullopt;
  note = "not admissible over " + m.range.Describe() + (r.thickness_m ? " at " : " within ") + Mm(judged_at) +
         " (" + WorstText(check) + ")";
}

/// Admissible candidates first (problem a: thinnest, then margin; b: margin), the others after
/// in their order; the notes follow their candidates.
void Rerank(DesignResult& r) {
  std::vector<std::size_t> order(r.candidates.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto before = [&r](std::size_t a, std::size_t b) {
    const CandidateOutcome &x = r.candidates[a], &y = r.candidates[b];
    if (x.safe != y.safe) return x.safe;
    if (!x.safe) return false;
    if (!r.thickness_m && *x.recommended_thickness_m != *y.recommended_thickness_m) {
      return *x.recommended_thickness_m < *y.recommended_thickness_m;
    }
    return x.margin > y.margin;
  };
  std::stable_sort(order.begin(), order.end(), before);
  std::vector<CandidateOutcome> candidates;
  std::vector<std::string> notes;
  for (std::size_t i : order) {
    candidates.push_back(std::move(r.candidates[i]));
    notes.push_back(std::move(r.range_notes[i]));
  }
  r.candidates = std::move(candidates);
  r.range_notes = std::move(notes);
}

}  // namespace

void AnswerOverRange(const DesignRequest& request, DesignResult& r) {
  if (!r.ok() || !r.covering_needed() || r.candidates.empty()) return;
  const CoveringLaw law = request.options.covering_law;  // the design's law (CoveringOf), as the shells set it
  if (ChooseOracle(request.scene, OracleChoice::kAuto).kind != OracleKind::kExact) {
    const bool curves = std::any_of(r.candidates.begin(), r.candidates.end(), [&](const CandidateOutcome& c) {
      return RangedMaterialOf(c.material, law).foam();
    });
    if (curves) {
      r.warnings.push_back("the candidates were not checked over their stated uncertainty: the check needs the "
                           "exact path (a scene without braking or a neck)");
    }
    return;
  }
  r.range_notes.assign(r.candidates.size(), std::string());
  for (std::size_t i = 0; i < r.candidates.size(); ++i) CheckCandidate(request, r, r.candidates[i], r.range_notes[i]);
  Rerank(r);
  r.recommendation.reset();
  if (!r.candidates.empty() && r.candidates.front().safe) r.recommendation = 0;
  if (r.recommendation) {
    const CandidateOutcome& best = r.candidates.front();
    r.verdict = DesignVerdict::kCoveringFound;
    r.material_range = CheckOverRange(request.scene, RangedMaterialOf(best.material, law),
                                      *best.recommended_thickness_m, request.options);
    return;
  }
  if (r.verdict == DesignVerdict::kCoveringFound) r.verdict = DesignVerdict::kNoSafeMaterial;  // none holds over its range
  std::vector<RangedMaterial> materials;
  for (const CandidateOutcome& c : r.candidates) materials.push_back(RangedMaterialOf(c.material, law));
  r.nearest_changes = FindNearestChanges(request.scene, materials, request.options, r.thickness_m);
}

}  // namespace covopt::optim
