// The result summary of an audit (summary.hpp).
#include "covopt/audit/summary.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <covopt/core/impact_result.hpp>
#include <covopt/core/number_format.hpp>
#include <covopt/optim/summaries.hpp>
#include <covopt/optim/verdicts.hpp>

namespace covopt::audit {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string Number(double value) { return FormatSignificant(value, 4); }

const AuditCovering& CoveringOfLink(const AuditSetup& setup, const std::string& link) {
  const auto own = setup.link_coverings.find(link);
  return own != setup.link_coverings.end() ? own->second : setup.covering;
}

/// The law a covering is judged with: the foam law for a material with a measured curve (unless
/// Hertz is asked for), else Hertz.
CoveringLaw LawOf(const AuditCovering& c) {
  const bool curve = c.material && c.material->compressive_curve != nullptr;
  return curve && c.covering.law != CoveringLaw::kHertz ? CoveringLaw::kFoam : CoveringLaw::kHertz;
}

bool IsDesignRule(std::string_view criterion) {
  return criterion == "full-compression" || criterion == "within-curve" || criterion == "crush" ||
         criterion == kLawValidityRule;
}

SummaryRow CellRow(const AuditSetup& setup, const AuditResult& result, const AuditCell& cell) {
  const double sf = setup.rule.safety_factor;
  const std::string& link = result.links.at(cell.link);
  const AuditCovering& covering = CoveringOfLink(setup, link);
  const bool covered = covering.covering.thickness_m > 0.0;
  const std::string criterion(cell.binding_name());
  const bool head = cell.head_criterion != optim::LimitingCriterion::kNone;
  return SummaryRow{.target = link + " × " + result.regions.at(cell.region),
                    .criterion = criterion,
                    .part = IsDesignRule(criterion) ? CriterionPart::kDesignRule : CriterionPart::kInjury,
                    .unit = "m/s",
                    .value = cell.speed_m_per_s,
                    .limit = sf * cell.max_safe_speed_m_per_s,
                    .derated_limit = cell.max_safe_speed_m_per_s,
                    .ratio = cell.governing_ratio,
                    .margin = 1.0 - sf * cell.governing_ratio,
                    .counted = true,
                    .passed = sf * cell.governing_ratio <= 1.0,
                    .binding = false,
                    .law = LawWord(covered, LawOf(covering)),
                    .validity = covered ? "see the warnings" : "",
                    .source = head ? std::string(optim::kParkSource) : setup.regions.at(cell.region).Citation(),
                    .note = "the speed against the largest safe speed there (" +
                            Number(cell.max_safe_speed_m_per_s) + " m/s)"};
}

/// A link none of whose cells the exposure zones judge: reported, not counted, not passed.
SummaryRow NotJudgedRow(const AuditResult& result, std::size_t link, const std::string& why) {
  return SummaryRow{.target = result.links.at(link) + " × every region",
                    .criterion = std::string(kNotJudgedCriterion),
                    .part = CriterionPart::kInjury,
                    .unit = "m/s",
                    .value = kNaN,
                    .limit = kNaN,
                    .derated_limit = kNaN,
                    .ratio = kNaN,
                    .margin = kNaN,
                    .counted = false,
                    .passed = false,
                    .binding = false,
                    .law = "",
                    .validity = "",
                    .source = "exposure zones",
                    .note = "not judged: " + why};
}

}  // namespace

ResultSummary SummarizeAudit(const AuditSetup& setup, const AuditResult& result) {
  ResultSummary s;
  s.command = "audit";
  s.safety_factor = setup.rule.safety_factor;
  const std::size_t regions = result.regions.size();
  for (std::size_t link = 0; link < result.links.size() && regions > 0; ++link) {
    const AuditCell* worst = nullptr;
    for (std::size_t r = 0; r < regions; ++r) {
      const AuditCell& cell = result.cell(link, r);
      if (cell.sample && (worst == nullptr || cell.governing_ratio > worst->governing_ratio)) worst = &cell;
    }
    if (worst != nullptr) {
      s.rows.push_back(CellRow(setup, result, *worst));
      continue;
    }
    // No judged cell: the link never moves, or the exposure zones judge none of its cells.
    const AuditCell& first = result.cell(link, 0);
    if (first.not_judged.empty()) continue;
    s.rows.push_back(NotJudgedRow(result, link, first.not_judged));
  }
  for (const std::string& region : result.regions) s.targets.push_back(region);
  for (const SummaryRow& row : s.rows) {
    if (std::find(s.criteria.begin(), s.criteria.end(), row.criterion) == s.criteria.end()) {
      s.criteria.push_back(row.criterion);
    }
  }
  for (const materials::BodyLimits& limits : setup.regions) optim::AddLimitTable(s, limits);
  if (setup.head) s.standards.emplace_back(optim::kParkSource);
  s.scope = result.scope;
  s.Finish();

  const AuditCell* limiting =
      result.limiting_cell && *result.limiting_cell < result.cells.size() ? &result.cells[*result.limiting_cell] : nullptr;
  const std::filesystem::path file(setup.chain.source_name());
  s.robot = RobotSummary{.model_file = file.filename().string(),
                         .motion = std::to_string(result.sample_count) + " samples",
                         .joints = setup.chain.joint_names(),
                         .reflected_mass_kg = limiting != nullptr ? limiting->reflected_mass_kg : kNaN,
                         .payload_kg = setup.chain.payload().empty() ? 0.0 : setup.chain.payload().mass_kg,
                         .speed_m_per_s = limiting != nullptr ? limiting->speed_m_per_s : kNaN};
  if (limiting == nullptr || !limiting->sample) {
    s.governing_case = result.message;
    return s;
  }
  const std::string& link = result.links.at(limiting->link);
  s.governing_case = "link " + link + " against the " + result.regions.at(limiting->region) + ", sample " +
                     std::to_string(*limiting->sample) + " at t = " + Number(limiting->time_s) + " s, point " +
                     std::to_string(limiting->point) + "; the program's safe speed scale " +
                     Number(result.safe_speed_scale);
  const AuditCovering& covering = CoveringOfLink(setup, link);
  CoveringValidity unjudged;
  s.covering = SummarizeCovering(covering.covering.thickness_m, covering.material ? covering.material->name : "",
                                 LawOf(covering), unjudged);
  s.covering.validity = s.covering.present ? "see the warnings" : "";
  s.covering.validity_ratio = kNaN;
  return s;
}

namespace {

/// "cycle time 1.734 s (original 1.5 s; uniform slow-down 3.316 s, scale 0.4523)".
std::string CycleTimes(const RetimeResult& r) {
  return "cycle time " + Number(r.cycle_time_s) + " s (original " + Number(r.original_cycle_time_s) +
         " s; uniform slow-down " + Number(r.uniform_cycle_time_s) + " s, scale " + Number(r.uniform_speed_scale) + ")";
}

}  // namespace

ResultSummary SummarizeRetime(const AuditSetup& setup, const RetimeResult& result, double tolerance) {
  const bool answer = result.status == RetimeStatus::kSafe || result.status == RetimeStatus::kAtRest;
  // At rest nothing was re-timed: the original program's audit is the answer.
  ResultSummary s = SummarizeAudit(setup, result.status == RetimeStatus::kSafe ? result.after : result.before);
  s.command = "retime";
  if (answer) {
    // The re-audit accepts a sample within its tolerance: a time-optimal program sits on its limit.
    for (SummaryRow& row : s.rows) {
      if (!row.passed && setup.rule.safety_factor * row.ratio <= 1.0 + tolerance) {
        row.passed = true;
        row.note += "; within the re-audit's tolerance " + Number(tolerance);
      }
      row.binding = false;
    }
    const std::string governing = s.governing_case;
    s.Finish();
    s.governing_case = "re-timed program, " + CycleTimes(result) + (governing.empty() ? "" : ": " + governing);
    s.robot.motion = std::to_string(result.trajectory.time_s.size()) + " samples re-timed, " + CycleTimes(result);
  } else {
    s.safe = false;
    s.evaluated = result.status != RetimeStatus::kEvaluationFailed;
    s.state = s.evaluated ? VerdictState::kUnsafe : VerdictState::kNotEvaluated;
    s.governing_case = "no safe timing (" + std::string(ToString(result.status)) + "): " + result.message;
  }
  s.scope = result.scope;  // the audit's, and what the re-timing kept and bounded
  return s;
}

std::vector<RetimeSlowdown> RetimeSlowdowns(const RetimeResult& result) {
  std::vector<RetimeSlowdown> slowdowns;
  const std::size_t n = result.path_speed.size();
  if (n == 0 || result.original_time_s.size() != n) return slowdowns;
  constexpr double kSlow = 1.0 - 1e-9;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(result.path_speed[i] < kSlow)) continue;
    if (slowdowns.empty() || slowdowns.back().last_sample + 1 != i) {
      slowdowns.push_back(RetimeSlowdown{.first_sample = i, .last_sample = i, .start_time_s = result.original_time_s[i],
                                         .end_time_s = result.original_time_s[i], .min_path_speed = result.path_speed[i],
                                         .slowest_sample = i, .bound = "", .link = "", .region = ""});
    }
    RetimeSlowdown& d = slowdowns.back();
    d.last_sample = i;
    d.end_time_s = result.original_time_s[i];
    if (result.path_speed[i] <= d.min_path_speed) {
      d.min_path_speed = result.path_speed[i];
      d.slowest_sample = i;
    }
  }
  for (RetimeSlowdown& d : slowdowns) {
    const std::size_t i = d.slowest_sample;
    const optim::PathSpeedBound bound = i < result.bound.size() ? result.bound[i] : optim::PathSpeedBound::kPathSpeed;
    d.bound = optim::ToString(bound);
    const bool safety = bound == optim::PathSpeedBound::kPathSpeed && i < result.safe_path_speed.size() &&
                        result.safe_path_speed[i] <= result.path_speed[i] * (1.0 + 1e-6);
    if (!safety) continue;
    if (i < result.limiting_link.size() && result.limiting_link[i] < result.before.links.size()) {
      d.link = result.before.links[result.limiting_link[i]];
    }
    if (i < result.limiting_region.size() && result.limiting_region[i] < result.before.regions.size()) {
      d.region = result.before.regions[result.limiting_region[i]];
    }
  }
  return slowdowns;
}

}  // namespace covopt::audit
