// The result summaries of optim's results (summaries.hpp): optimize, speed-limit and
// robot --trajectory.
#include "covopt/optim/summaries.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <covopt/core/number_format.hpp>

#include "covopt/optim/oracle.hpp"
#include "covopt/optim/verdicts.hpp"

namespace covopt::optim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string Number(double value) { return FormatSignificant(value, 4); }
std::string Mm(double metres) { return FormatFixed(metres * 1e3, 2) + " mm"; }
std::string Mass(double kg) { return std::isinf(kg) ? std::string("fixed") : Number(kg) + " kg"; }

/// Appends the sentences of `more` not yet in `scope`.
void AddScope(std::vector<std::string>& scope, const std::vector<std::string>& more) {
  for (const std::string& sentence : more) {
    if (std::find(scope.begin(), scope.end(), sentence) == scope.end()) scope.push_back(sentence);
  }
}

RobotSummary SceneRobot(double mass_kg, double speed_m_per_s) {
  return RobotSummary{.model_file = "",
                      .motion = "",
                      .joints = {},
                      .reflected_mass_kg = mass_kg,
                      .payload_kg = 0.0,
                      .speed_m_per_s = speed_m_per_s};
}

/// What a limit search judges, as lists (targets, criteria, standards, scope): the head's
/// verdict of `options` on a still impact, row by row, kept only for its names.
void AddJudged(ResultSummary& s, const Scene& scene, const SpeedLimitOptions& options) {
  ResultSummary judged;
  judged.AddVerdict(HeadTarget(scene.head.area), HeadVerdict(scene, ImpactPeaks{}, options), "", "");
  s.targets = judged.targets;
  s.criteria = judged.criteria;
  s.standards = judged.standards;
  AddScope(s.scope, HeadVerdictScope(options.rule()));
}

/// The limit of one row, as the table's quantity reads it.
LimitRow RowLimit(SpeedLimitQuantity quantity, const Scene& scene, const SpeedLimitRow& row,
                  const SpeedLimitOptions& options) {
  const bool speed = quantity == SpeedLimitQuantity::kSpeed;
  const LimitAnswer& answer = speed ? static_cast<const LimitAnswer&>(row.speed_limit) : row.mass_limit;
  std::string target = HeadTarget(scene.head.area);
  if (row.material) target += ", " + *row.material;
  target += speed ? ", robot mass " + Mass(row.robot_mass_kg) : ", speed " + Number(row.speed_m_per_s) + " m/s";
  const bool covered = !answer.covering_law.empty();
  LimitRow r{.target = target,
             .quantity = speed ? "max safe speed" : "max safe mass",
             .unit = speed ? "m/s" : "kg",
             .value = speed ? row.speed_limit.max_safe_speed_m_per_s : row.mass_limit.max_safe_mass_kg,
             .binding_criterion = std::string(ToString(answer.limited_by)),
             .law = covered ? answer.covering_law : std::string("bare"),
             .validity = ValidityWords(covered, answer.validity),
             .note = ""};
  switch (answer.status) {
    case SpeedLimitStatus::kLimited: break;
    case SpeedLimitStatus::kSafeUpToSearchLimit:
      r.note = "not limited below the search limit " +
               (speed ? Number(options.max_speed_m_per_s) + " m/s" : Mass(options.max_mass_kg));
      r.value = kInf;
      r.binding_criterion = "";
      break;
    case SpeedLimitStatus::kNoSafeValue: r.note = "no safe value"; r.value = 0.0; break;
    case SpeedLimitStatus::kEvaluationFailed: r.note = "not evaluated: " + answer.message; r.value = kNaN; break;
  }
  return r;
}

/// The law and validity words of a body contact.
std::string ContactLaw(const BodyContactResult& c) { return LawWord(c.covering_law.has_value(), c.covering_law.value_or(CoveringLaw::kHertz)); }
std::string ContactValidity(const BodyContactResult& c) { return ValidityWords(c.covering_law.has_value(), c.validity); }

void AddOnce(std::vector<std::string>& list, const std::vector<std::string>& more) { AddScope(list, more); }

}  // namespace

std::string RegionTarget(const materials::BodyLimits& limits) {
  return limits.region->name + " (" + limits.area->name + ")";
}

std::optional<LimitTableSummary> LimitTableOf(const materials::BodyLimits& limits) {
  if (limits.region == nullptr || !limits.region->table) return std::nullopt;
  const materials::LimitTableInfo& table = *limits.region->table;
  return LimitTableSummary{.title = table.title, .edition = table.edition, .source = table.source, .sha256 = table.sha256};
}

void AddLimitTable(ResultSummary& summary, const materials::BodyLimits& limits) {
  if (const auto table = LimitTableOf(limits)) summary.AddLimitTable(*table);
}

void AppendSummary(ResultSummary& summary, const ResultSummary& more) {
  for (const LimitTableSummary& t : more.limit_tables) summary.AddLimitTable(t);
  summary.rows.insert(summary.rows.end(), more.rows.begin(), more.rows.end());
  AddOnce(summary.targets, more.targets);
  AddOnce(summary.criteria, more.criteria);
  AddOnce(summary.standards, more.standards);
  AddOnce(summary.scope, more.scope);
  summary.evaluated = summary.evaluated && more.evaluated;
}

ResultSummary SummarizeBodyContact(const BodyContactScene& scene, std::string_view material,
                                   std::span<const BodyRegionJudgement> regions, const ResultSummary* head) {
  ResultSummary s;
  s.command = "simulate --body-region";
  const BodyContactResult* governing = nullptr;
  for (const BodyRegionJudgement& j : regions) {
    s.AddVerdict(RegionTarget(j.limits), j.verdict, ContactLaw(j.contact), ContactValidity(j.contact));
    AddLimitTable(s, j.limits);
    if (!j.scope.empty()) AddScope(s.scope, {j.scope});
  }
  if (head != nullptr) AppendSummary(s, *head);
  s.Finish();
  for (std::size_t i = 0; i < regions.size(); ++i) {
    if (RegionTarget(regions[i].limits) == s.governing_target) governing = &regions[i].contact;
  }
  s.governing_case = "one contact of the robot at " + Number(scene.speed_m_per_s) + " m/s, " +
                     std::string(ToString(scene.contact)) + ", with the " + s.governing_target;
  if (governing != nullptr && governing->covering_law) {
    s.covering = SummarizeCovering(scene.covering.thickness_m, material, *governing->covering_law, governing->validity);
  } else if (head != nullptr && head->covering.present) {
    s.covering = head->covering;
  } else {
    s.covering = SummarizeCovering(scene.covering.thickness_m, material, CoveringLaw::kHertz, CoveringValidity{});
  }
  s.robot = SceneRobot(scene.robot_mass_kg, scene.speed_m_per_s);
  return s;
}

ResultSummary SummarizeBodyRegionDesign(const BodyRegionDesignRequest& request, const BodyRegionDesignResult& result) {
  const BodyRegionDesignCandidate* rec = result.recommendation ? &result.candidates[*result.recommendation] : nullptr;
  const std::vector<BodyRegionJudgement>& regions = rec != nullptr ? rec->regions : result.bare_robot;
  const std::optional<DesignScore>& head = rec != nullptr ? rec->head : result.bare_head;
  ResultSummary s;
  s.command = "optimize --body-region";
  for (const BodyRegionJudgement& j : regions) {
    s.AddVerdict(RegionTarget(j.limits), j.verdict, ContactLaw(j.contact), ContactValidity(j.contact));
    AddLimitTable(s, j.limits);
  }
  if (head) {
    const bool crushes = rec != nullptr && rec->material.crush_behaviour == materials::CrushBehaviour::kCrushes;
    const HeadArea area = request.head ? request.head->head.area : HeadArea::kFrontal;
    const Verdict v = HeadVerdict(*head, InjuryLimits{}, request.rule, crushes ? rec->material.compressive_strength_Pa : 0.0,
                                  area);
    const bool covered = !head->bare();
    s.AddVerdict(HeadTarget(area), v, LawWord(covered, head->peaks.covering_law),
                 ValidityWords(covered, head->judged_validity(request.rule)));
  }
  AddScope(s.scope, result.scope);
  s.Finish();
  const std::string at = "one contact at " + Number(request.scene.speed_m_per_s) + " m/s with the " + s.governing_target;
  if (rec != nullptr) {
    s.governing_case = "the recommended covering, " + rec->material.name + " at " + Mm(*rec->thickness_m) + ": " + at;
    const BodyRegionJudgement* first = regions.empty() ? nullptr : &regions.front();
    const CoveringLaw law = first != nullptr && first->contact.covering_law ? *first->contact.covering_law
                            : head                                         ? head->peaks.covering_law
                                                                           : CoveringLaw::kHertz;
    s.covering = SummarizeCovering(*rec->thickness_m, rec->material.name, law,
                                   first != nullptr ? first->contact.validity : CoveringValidity{});
  } else {
    s.safe = s.safe && result.bare_robot_safe;
    s.state = VerdictStateOf(s.evaluated, s.safe, s.margin, s.margin_threshold);
    s.governing_case = std::string(result.bare_robot_safe ? "no covering needed; the bare robot: "
                                                          : "no covering found; the bare robot: ") + at;
  }
  s.robot = SceneRobot(request.scene.robot_mass_kg, request.scene.speed_m_per_s);
  return s;
}

ResultSummary SummarizeBodyRegionTrajectory(const BodyRegionTrajectoryCheck& check,
                                            std::span<const materials::BodyLimits> regions,
                                            const BodyContactScene& scene, double safety_factor) {
  ResultSummary s;
  s.command = "robot --trajectory --body-region";
  s.safety_factor = safety_factor;
  for (const materials::BodyLimits& limits : regions) {
    s.targets.push_back(RegionTarget(limits));
    AddLimitTable(s, limits);
  }
  const BodyRegionSampleVerdict* worst = check.worst_sample ? &check.samples[*check.worst_sample] : nullptr;
  const bool covered = scene.covering.thickness_m > 0.0;
  if (worst != nullptr && worst->worst_region < regions.size()) {
    const std::string criterion(ToString(worst->binding));
    const bool rule = criterion == "full-compression" || criterion == "crush" || criterion == kLawValidityRule;
    s.rows.push_back(SummaryRow{.target = RegionTarget(regions[worst->worst_region]),
                                .criterion = criterion,
                                .part = rule ? CriterionPart::kDesignRule : CriterionPart::kInjury,
                                .unit = "1",
                                .value = worst->worst_ratio,
                                .limit = 1.0,
                                .derated_limit = 1.0 / safety_factor,
                                .ratio = worst->worst_ratio,
                                .margin = 1.0 - safety_factor * worst->worst_ratio,
                                .counted = true,
                                .passed = worst->safe,
                                .binding = false,
                                .law = LawWord(covered, scene.covering.law),
                                .validity = "",
                                .source = regions[worst->worst_region].Citation(),
                                .note = "the largest ratio over the regions at the worst sample"});
    s.criteria.push_back(criterion);
    s.governing_case = "sample " + std::to_string(*check.worst_sample) + " at t = " + Number(worst->time_s) + " s: " +
                       Number(worst->speed_m_per_s) + " m/s, reflected mass " + Mass(worst->reflected_mass_kg) +
                       "; the program's safe speed scale " + Number(check.safe_speed_scale);
  }
  s.Finish();
  if (worst == nullptr) s.governing_case = check.message;
  s.robot = SceneRobot(worst != nullptr ? worst->reflected_mass_kg : kNaN, worst != nullptr ? worst->speed_m_per_s : kNaN);
  s.robot.motion = std::to_string(check.samples.size()) + " samples";
  s.covering = SummarizeCovering(scene.covering.thickness_m, "", scene.covering.law, CoveringValidity{});
  return s;
}

ResultSummary SummarizeDesign(const DesignRequest& request, const DesignResult& result) {
  const DesignRule& rule = result.rule;
  const HeadArea area = request.scene.head.area;
  const CandidateOutcome* rec = result.recommendation ? &result.candidates[*result.recommendation] : nullptr;
  const DesignScore& score = rec != nullptr ? rec->score : result.bare_robot;
  const bool crushes = rec != nullptr && rec->material.crush_behaviour == materials::CrushBehaviour::kCrushes;
  const Verdict verdict =
      HeadVerdict(score, request.options.limits, rule, crushes ? rec->material.compressive_strength_Pa : 0.0, area);
  const CoveringValidity validity = score.judged_validity(rule);
  const bool covered = !score.bare();
  ResultSummary s;
  s.command = "optimize";
  s.evaluated = result.ok();
  s.AddVerdict(HeadTarget(area), verdict, LawWord(covered, score.peaks.covering_law), ValidityWords(covered, validity));
  AddScope(s.scope, result.scope);
  s.Finish();
  const std::string at = "one impact at " + Number(request.scene.robot.speed_m_per_s) + " m/s";
  if (rec != nullptr) {
    s.governing_case = "the recommended covering, " + rec->material.name + " at " + Mm(score.design.thickness_m) +
                       ": " + at;
    s.covering = SummarizeCovering(score.design.thickness_m, rec->material.name, score.peaks.covering_law, validity);
  } else {
    // No recommendation: the bare robot's rows, safe only when it needs no covering.
    s.safe = s.safe && !result.covering_needed();
    s.state = VerdictStateOf(s.evaluated, s.safe, s.margin, s.margin_threshold);
    s.governing_case = std::string(result.covering_needed() ? "no covering found; the bare robot: "
                                                            : "no covering needed; the bare robot: ") + at;
  }
  s.robot = SceneRobot(request.scene.robot.mass_kg, request.scene.robot.speed_m_per_s);
  return s;
}

ResultSummary SummarizeSpeedLimits(SpeedLimitQuantity quantity, const Scene& scene, const SpeedLimitOptions& options,
                                   std::span<const SpeedLimitRow> rows) {
  ResultSummary s;
  s.kind = ResultSummary::Kind::kLimits;
  s.command = "speed-limit";
  s.safety_factor = options.safety_factor;
  AddJudged(s, scene, options);
  for (const SpeedLimitRow& row : rows) {
    s.limits.push_back(RowLimit(quantity, scene, row, options));
    if (std::isnan(s.limits.back().value)) s.evaluated = false;
  }
  s.Finish();
  const bool speed = quantity == SpeedLimitQuantity::kSpeed;
  const double mass = speed ? (rows.size() == 1 ? rows.front().robot_mass_kg : kNaN) : scene.robot.mass_kg;
  const double at_speed = speed ? kNaN : (rows.size() == 1 ? rows.front().speed_m_per_s : kNaN);
  s.robot = SceneRobot(mass, at_speed);
  if (!rows.empty()) {
    const LimitAnswer& first = speed ? static_cast<const LimitAnswer&>(rows.front().speed_limit) : rows.front().mass_limit;
    const bool several = std::any_of(rows.begin(), rows.end(), [&](const SpeedLimitRow& r) {
      return r.material.value_or("") != rows.front().material.value_or("");
    });
    s.covering = SummarizeCovering(scene.covering.thickness_m,
                                   several ? "several (one per row)" : rows.front().material.value_or(""),
                                   first.covering_law == "foam" ? CoveringLaw::kFoam : CoveringLaw::kHertz,
                                   first.validity);
  }
  return s;
}

ResultSummary SummarizeTrajectory(const TrajectoryCheck& check, const Scene& scene, std::string_view material) {
  ResultSummary s;
  s.command = "robot --trajectory";
  const bool covered = scene.covering.thickness_m > 0.0;
  const CoveringLaw law = check.covering_law == "foam" ? CoveringLaw::kFoam : CoveringLaw::kHertz;
  s.evaluated = check.status != TrajectoryCheckStatus::kEvaluationFailed;
  const SampleVerdict* worst =
      check.worst_sample && s.evaluated ? &check.samples[*check.worst_sample] : nullptr;
  if (worst != nullptr) {
    s.AddVerdict(HeadTarget(scene.head.area), worst->verdict, LawWord(covered, law),
                 ValidityWords(covered, worst->validity));
  }
  s.Finish();
  if (worst != nullptr) {
    s.governing_case = "sample " + std::to_string(*check.worst_sample) + " at t = " + Number(worst->time_s) + " s: " +
                       Number(worst->speed_m_per_s) + " m/s, reflected mass " + Mass(worst->reflected_mass_kg) +
                       "; the program's safe speed scale " + Number(check.safe_speed_scale);
  } else {
    s.governing_case = check.message;
  }
  s.covering = SummarizeCovering(scene.covering.thickness_m, material, law, check.validity);
  s.robot = SceneRobot(worst != nullptr ? worst->reflected_mass_kg : kNaN,
                       worst != nullptr ? worst->speed_m_per_s : kNaN);
  s.robot.motion = std::to_string(check.samples.size()) + " samples";
  return s;
}

}  // namespace covopt::optim
