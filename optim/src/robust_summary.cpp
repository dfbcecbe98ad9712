// The result summaries of the robust designs (robust_summary.hpp).
#include "covopt/optim/robust_summary.hpp"

#include <string>

#include <covopt/core/number_format.hpp>

#include "covopt/optim/oracle.hpp"
#include "covopt/optim/verdicts.hpp"

namespace covopt::optim {
namespace {

std::string Mm(double metres) { return FormatFixed(metres * 1e3, 2) + " mm"; }

/// A single-row summary: `ratio` against 1 under `safety_factor`, `passed` the design's own word.
ResultSummary OneRow(std::string command, std::string target, std::string criterion, double value, double limit,
                     double safety_factor, bool passed, std::string source, std::string note) {
  ResultSummary s;
  s.command = std::move(command);
  s.safety_factor = safety_factor;
  const double ratio = value / limit;
  s.rows.push_back(SummaryRow{.target = target,
                              .criterion = criterion,
                              .part = CriterionPart::kInjury,
                              .unit = "1",
                              .value = value,
                              .limit = limit,
                              .derated_limit = limit / safety_factor,
                              .ratio = ratio,
                              .margin = 1.0 - safety_factor * ratio,
                              .counted = true,
                              .passed = passed,
                              .binding = false,
                              .law = "",
                              .validity = "",
                              .source = std::move(source),
                              .note = std::move(note)});
  s.targets.push_back(std::move(target));
  s.criteria.push_back(std::move(criterion));
  s.standards.emplace_back(kParkSource);
  return s;
}

}  // namespace

ResultSummary SummarizeRobustDesign(const RobustDesignOptions& options, const RobustThinnestCovering& result,
                                    HeadArea area) {
  const DesignRule rule = options.design.rule();
  const RobustCandidate* rec = result.recommendation ? &result.candidates[*result.recommendation] : nullptr;
  const WorstCase& worst = rec != nullptr ? rec->worst_case : result.bare_robot;
  const CoveringLaw law = rec != nullptr ? rec->outcome.score.peaks.covering_law : CoveringLaw::kHertz;
  ResultSummary s = OneRow("optimize (robust)", HeadTarget(area), std::string(ToString(worst.binding, law)), worst.governing_ratio,
                           1.0, rule.safety_factor, worst.admissible, "the design's criterion over the box",
                           "the worst case over the box of uncertain inputs (found by " + worst.found_by + ")");
  s.scope = HeadVerdictScope(rule);
  s.Finish();
  if (rec != nullptr) {
    const double thickness = rec->outcome.recommended_thickness_m.value_or(rec->outcome.score.design.thickness_m);
    s.governing_case = "the recommended covering, " + rec->outcome.material.name + " at " + Mm(thickness) +
                       ", at its worst case over the box";
    s.covering = SummarizeCovering(thickness, rec->outcome.material.name, law, rec->outcome.score.validity);
  } else {
    s.safe = s.safe && result.verdict == DesignVerdict::kBareRobotSafe;
    s.state = VerdictStateOf(s.evaluated, s.safe, s.margin, s.margin_threshold);
    s.governing_case = "the bare robot at its worst case over the box";
  }
  return s;
}

ResultSummary SummarizeProbabilityDesign(const ProbabilityDesignOptions& options, const ProbabilityDesign& result,
                                         HeadArea area) {
  const ProbabilityCandidate* rec = result.recommendation ? &result.candidates[*result.recommendation] : nullptr;
  const InjuryProbability& p = rec != nullptr ? rec->at_design : result.bare_robot;
  const double bound = p.inadmissible.ci95_high;
  const bool met = rec != nullptr ? rec->meets_target : result.verdict == DesignVerdict::kBareRobotSafe;
  ResultSummary s = OneRow("optimize (probability)", HeadTarget(area), "injury-probability", bound,
                           options.max_probability, 1.0, met, "the target probability",
                           "the upper end of the 95 % interval of P(inadmissible) against the target");
  s.scope = HeadVerdictScope(options.design.rule());
  s.Finish();
  if (rec != nullptr && rec->recommended_thickness_m) {
    s.governing_case = "the recommended covering, " + rec->material.name + " at " + Mm(*rec->recommended_thickness_m);
    s.covering = CoveringSummary{.present = true,
                                 .material = rec->material.name,
                                 .thickness_m = *rec->recommended_thickness_m,
                                 .law = "",
                                 .validity = "",
                                 .validity_ratio = 0.0};
  } else {
    s.governing_case = "the bare robot";
  }
  return s;
}

}  // namespace covopt::optim
