// The design request of `covopt optimize` as one call: candidates from a catalog, problem (a)
// or (b), the headline, and the warnings the answer carries.
#include "covopt/optim/design.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <covopt/core/impact_model.hpp>
#include <covopt/core/impact_result.hpp>
#include <covopt/core/number_format.hpp>
#include <covopt/materials/material.hpp>

#include "covopt/optim/design_answer.hpp"

namespace covopt::optim {
namespace {

std::string Mm(double metres) { return FormatFixed(metres * 1e3, 2) + " mm"; }
std::string MPa(double pascals) { return FormatSignificant(pascals * 1e-6, 3) + " MPa"; }
std::string Ratio(double ratio) { return FormatFixed(ratio, 3); }

/// Why the catalog has no admissible material, when crushing or an unknown strength is part of
/// it: " N materials would crush; M have an unknown strength (--allow-unknown-strength)."
std::string WhyNoMaterial(const DesignResult& r) {
  if (r.rule.crushing_allowed) return "";
  int crush = 0, unknown = 0;
  for (const CandidateOutcome& c : r.candidates) {
    if (c.score.crush_check == CrushCheck::kUnknownStrength && !r.rule.unknown_strength_allowed) ++unknown;
    if (c.score.governing(r.rule).criterion == LimitingCriterion::kCrush) ++crush;
  }
  std::string why;
  if (crush > 0) {
    why.append(" ").append(std::to_string(crush));
    why += crush == 1 ? " material would crush where it is thick enough."
                      : " materials would crush where they are thick enough.";
  }
  if (unknown > 0) {
    why.append(" ").append(std::to_string(unknown));
    why += std::string(" of unknown strength ") + (unknown == 1 ? "is" : "are") +
           " not considered (--allow-unknown-strength admits them, unverified).";
  }
  return why;
}

/// The sentence that answers the request.
std::string Headline(const DesignResult& r, double max_thickness) {
  const DesignScore& best = r.continuous.score;
  switch (r.verdict) {
    case DesignVerdict::kBareRobotSafe:
      return "The bare robot is already safe in this scene: no covering is needed.";
    case DesignVerdict::kCoveringFound: {
      const CandidateOutcome& c = r.candidates[*r.recommendation];
      return "Recommended: " + c.material.name + " at " + Mm(*c.recommended_thickness_m) + ".";
    }
    case DesignVerdict::kNoSafeMaterial:
      return (r.thickness_m ? "No catalog material is admissible at " + Mm(*r.thickness_m) + "; a covering of " +
                                  MPa(best.design.youngs_modulus_Pa) + " would be"
                            : "No catalog material is admissible within " + Mm(max_thickness) +
                                  "; the continuous optimum (a Hertz ideal: " + MPa(best.design.youngs_modulus_Pa) +
                                  ", " + Mm(best.design.thickness_m) + ") would be") +
             (r.rule.crushing_allowed ? "" : ", in a material whose compressive strength is at least " +
                                                 MPa(best.required_strength_Pa(r.rule.safety_factor))) +
             "." + WhyNoMaterial(r);
    case DesignVerdict::kNothingSafe:
      break;
  }
  const std::string least =
      r.candidates.empty()
          ? std::string()
          : " The least unsafe material is " + r.candidates.front().material.name + " (worst ratio " +
                Ratio(r.candidates.front().score.worst_ratio()) +
                (r.candidates.front().score.peaks.fully_compressed ? ", fully compressed" : "") + ").";
  if (r.thickness_m && r.continuous.every_modulus_fully_compressed) {
    return "Nothing is admissible at " + Mm(*r.thickness_m) +
           ": every modulus up to the search's maximum is fully compressed at the peak (the robot reaches "
           "the bone through the covering)." +
           least;
  }
  return r.thickness_m ? "Nothing is admissible at " + Mm(*r.thickness_m) + ": even the best modulus (" +
                             MPa(best.design.youngs_modulus_Pa) + ") leaves a worst ratio of " +
                             Ratio(best.worst_ratio()) + "." + least
                       : "Nothing is admissible within " + Mm(max_thickness) +
                             ": no modulus in the search range meets the criterion at any thickness." + least;
}

/// The warnings of an answer (besides the input's own, which the caller knows).
std::vector<std::string> Warnings(const DesignRequest& request, const DesignResult& r) {
  std::vector<std::string> warnings;
  const SolverReport& global = r.continuous.global;
  if (!global.backend.empty() && !EndedNormally(global.termination)) {
    // Not an error: stage 1 only brackets; the nested search answers on its own.
    warnings.push_back("the global stage failed: " + std::string(ToString(global.termination)) + " (" +
                       global.backend + " code " + std::to_string(global.raw_code) + " " + global.raw_name +
                       "); its point was not used, the bracketed search answered alone");
  }
  const SolverReport& local = r.continuous.local;
  if (!local.backend.empty() && local.termination != Termination::kConverged &&
      local.termination != Termination::kAcceptable) {
    warnings.push_back("the local polish failed: " + std::string(ToString(local.termination)) + " (" +
                       local.backend + " code " + std::to_string(local.raw_code) + " " + local.raw_name +
                       "); the bracketed search's point is reported");
  }
  if (r.recommendation) {
    const CandidateOutcome& c = r.candidates[*r.recommendation];
    // docs/model.md §5: a design that works only with the covering bottomed out (paper's criterion).
    if (c.score.peaks.fully_compressed) {
      warnings.push_back(
          "the recommended covering is fully compressed at the peak (the robot reaches the bone through it): "
          "its margin rests on the stiff robot-bone phase of the model; without --allow-full-compression it "
          "would not be admissible");
    }
    if (c.score.crush_check == CrushCheck::kUnknownStrength) {
      warnings.push_back("the recommended material's compressive strength is unknown: the design is unverified for "
                         "crushing; check that " + c.material.name + " stays elastic up to " +
                         MPa(c.score.required_strength_Pa(request.options.safety_factor)) +
                         " (its peak compressive stress times the safety factor)");
    } else if (c.score.crush_check == CrushCheck::kChecked && request.options.allow_crushing &&
               request.options.safety_factor * c.score.crush_ratio > 1.0) {
      warnings.push_back("the recommended covering crushes: its peak compressive stress is " +
                         FormatSignificant(request.options.safety_factor * c.score.crush_ratio, 3) +
                         " times its compressive strength (with the safety factor); a sacrificial liner protects "
                         "once and must be replaced after every impact (--allow-crushing)");
    }
    // Where the recommended design leaves the model's domain (core's validity checks).
    Scene covered = request.scene;
    covered.covering = CoveringOf(c.material, *c.recommended_thickness_m, request.options.covering_law);
    for (const std::string& w : ValidityWarnings(ImpactModel::FromScene(covered), c.score.peaks)) {
      if (w.find("fully compressed") == std::string::npos) warnings.push_back("recommended covering: " + w);
    }
  }
  if (r.oracle.failed_evaluations > 0) {
    warnings.push_back(std::to_string(r.oracle.failed_evaluations) + " of " + std::to_string(r.oracle.evaluations) +
                       " " + r.oracle.Name() + " evaluations failed and counted as inadmissible (first: " +
                       r.oracle.first_failure + ")");
  }
  if (r.covering_needed() && r.continuous.score.peaks.fully_compressed) {
    warnings.push_back(
        "the continuous optimum is fully compressed at the peak (the robot reaches the bone through the covering)");
  }
  return warnings;
}

}  // namespace

std::string_view ToString(DesignProblem problem) noexcept {
  switch (problem) {
    case DesignProblem::kThinnestSafeCovering: return "thinnest-safe-covering";
    case DesignProblem::kLeastInjuryAtThickness: return "least-injury-at-thickness";
  }
  return "unknown";
}

std::string_view ToString(DesignStatus status) noexcept {
  switch (status) {
    case DesignStatus::kSuccess: return "success";
    case DesignStatus::kOracleFailed: return "oracle-failed";
  }
  return "unknown";
}

std::string DesignResult::BriefReport() const {
  std::string report = std::string(ToString(verdict)) + " (" + std::string(ToString(criterion)) + "): " + message;
  if (covering_needed()) {
    report += std::string(" Continuous ") + (thickness_m ? "best" : "optimum") + " (Hertz ideal): " +
              MPa(continuous.score.design.youngs_modulus_Pa) + " at " + Mm(continuous.score.design.thickness_m) +
              ", worst ratio " + Ratio(continuous.score.worst_ratio()) + ".";
  }
  return report + " " + std::to_string(evaluations) + " " + oracle.Name() + " evaluations, " +
         FormatFixed(seconds * 1e3, 1) + " ms.";
}

std::vector<CandidateMaterial> SelectCandidates(const materials::Catalog& catalog, std::span<const std::string> names,
                                                std::span<const std::string> families) {
  std::vector<const materials::Material*> chosen;
  if (!names.empty()) {
    for (const std::string& name : names) {
      const materials::Material* m = catalog.Find(name);
      if (!m) throw std::invalid_argument(catalog.MissingMaterialMessage(name));
      chosen.push_back(m);
    }
  } else {
    for (const materials::Material& m : catalog.materials()) chosen.push_back(&m);
  }
  if (!families.empty()) {
    // The catalog's own filter matches families ignoring case; a family it matches nothing
    // of is unknown.
    auto of_families = [&catalog](std::vector<std::string> wanted) {
      materials::MaterialFilter filter;
      filter.families = std::move(wanted);
      return catalog.Filter(filter);
    };
    for (const std::string& family : families) {
      if (of_families({family}).empty()) {
        std::string list;
        for (const std::string& k : catalog.families()) list += (list.empty() ? "" : ", ") + k;
        throw std::invalid_argument("no family '" + family + "' in the catalog (families: " + list + ")");
      }
    }
    const std::vector<const materials::Material*> kept = of_families({families.begin(), families.end()});
    std::erase_if(chosen, [&](const materials::Material* m) {
      return std::find(kept.begin(), kept.end(), m) == kept.end();
    });
  }
  std::vector<CandidateMaterial> candidates;
  for (const materials::Material* m : chosen) candidates.push_back(CandidateOf(*m));
  return candidates;
}

CandidateMaterial CandidateOf(const materials::Material& m) {
  return {.name = m.name,
          .youngs_modulus_Pa = m.youngs_modulus_Pa,
          .poisson_ratio = materials::PoissonRatioOrDefault(m),
          .poisson_assumed = !m.poisson_ratio.has_value(),
          .family = m.family,
          .crush_behaviour = m.crush_behaviour,
          .compressive_strength_Pa = m.compressive_strength_Pa.value_or(0.0),
          .compressive_curve = m.compressive_curve,
          .recovers = m.recovers,
          .rate_factor = m.rate_factor,
          .stress_at_25_band_Pa = m.stress_at_25_band_Pa};
}

void KeepCandidatesForLaw(std::vector<CandidateMaterial>& candidates, CoveringLaw law) {
  if (law != CoveringLaw::kFoam) return;
  std::erase_if(candidates, [](const CandidateMaterial& c) { return !c.compressive_curve; });
}

std::vector<std::string> KeepCandidatesTheSceneModels(std::vector<CandidateMaterial>& candidates, CoveringLaw law,
                                                      const Scene& scene) {
  const auto curved = std::find_if(candidates.begin(), candidates.end(),
                                   [](const CandidateMaterial& c) { return c.compressive_curve != nullptr; });
  if (law != CoveringLaw::kAuto || curved == candidates.end()) return {};
  Scene foam = scene;
  foam.covering = CoveringOf(*curved, std::max(scene.covering.thickness_m, 1e-3), CoveringLaw::kFoam);
  try {
    (void)ImpactModel::FromScene(foam);
    return {};
  } catch (const std::invalid_argument& e) {
    const auto dropped = std::erase_if(candidates, [](const CandidateMaterial& c) { return c.compressive_curve; });
    return {std::to_string(dropped) + " material" + (dropped == 1 ? "" : "s") +
            " with a measured compressive curve left out: the foam law cannot judge this scene (" + e.what() +
            "); --covering-law hertz reads them with the Hertz law"};
  }
}

DesignResult Design(const DesignRequest& request) {
  DesignResult r;
  r.criterion = request.options.criterion();
  r.rule = request.options.rule();
  r.scope = HeadVerdictScope(r.rule);
  r.thickness_m = request.thickness_m;
  // Both problems answer with the same fields.
  auto take = [&r](auto&& answer) {
    r.verdict = answer.verdict;
    r.bare_robot = answer.bare_robot;
    r.continuous = std::move(answer.continuous);
    r.candidates = std::move(answer.candidates);
    r.recommendation = answer.recommendation;
    r.evaluations = answer.evaluations;
    r.seconds = answer.seconds;
    r.oracle = answer.oracle;
  };
  if (request.thickness_m) {
    r.problem = DesignProblem::kLeastInjuryAtThickness;
    take(MinimizeInjuryAtThickness(request.scene, *request.thickness_m, request.materials, request.options));
  } else {
    take(FindThinnestSafeCovering(request.scene, request.materials, request.options));
  }
  // A failed evaluation is never an answer: the bare robot's verdict, or a continuous
  // optimum that is itself a failed evaluation, leaves nothing usable.
  if (r.bare_robot.failed || (r.covering_needed() && r.continuous.score.failed)) {
    r.status = DesignStatus::kOracleFailed;
    r.message = "The " + r.oracle.Name() + " failed where the answer needs it (" +
                std::to_string(r.oracle.failed_evaluations) + " of " + std::to_string(r.oracle.evaluations) +
                " evaluations failed; first: " + r.oracle.first_failure + ").";
    r.warnings = {};
    return r;
  }
  AnswerOverRange(request, r);  // the default answer: admissible over the stated uncertainty (design_answer.hpp)
  r.message = Headline(r, request.options.space.max_thickness_m);
  if (r.nearest_changes) r.message += " No catalog material works for this scene; " + r.nearest_changes->Describe() + ".";
  r.warnings = Warnings(request, r);
  return r;
}

}  // namespace covopt::optim
