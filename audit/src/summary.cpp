// The result summary of an audit (summary.hpp).
#include "covopt/audit/summary.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

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
    if (worst == nullptr) continue;  // the link never moves
    s.rows.push_back(CellRow(setup, result, *worst));
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

}  // namespace covopt::audit
