#include "covopt/core/result_summary.hpp"

#include "covopt/core/number_format.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace covopt {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Appends `item` to `list` unless it is there already (the first mention keeps its place).
void AddOnce(std::vector<std::string>& list, std::string_view item) {
  if (item.empty()) return;
  if (std::find(list.begin(), list.end(), item) == list.end()) list.emplace_back(item);
}

void FinishVerdict(ResultSummary& s) {
  SummaryRow* binding = nullptr;
  bool all_passed = true;
  for (SummaryRow& row : s.rows) {
    row.binding = false;
    if (!row.counted) continue;
    all_passed = all_passed && row.passed;
    if (!std::isnan(row.ratio) && (binding == nullptr || row.ratio > binding->ratio)) binding = &row;
  }
  s.safe = s.evaluated && all_passed;
  if (!s.evaluated) {
    s.governing_ratio = kInf;
    s.margin = -kInf;
  } else if (binding == nullptr) {  // nothing counted: as Verdict, a ratio of 0
    s.governing_ratio = 0.0;
    s.margin = 1.0;
  } else {
    s.governing_ratio = binding->ratio;
    s.margin = binding->margin;
  }
  if (binding != nullptr) {
    binding->binding = true;
    s.governing_target = binding->target;
    s.governing_criterion = binding->criterion;
  }
  s.state = VerdictStateOf(s.evaluated, s.safe, s.margin, s.margin_threshold);
}

void FinishLimits(ResultSummary& s) {
  // A case without a safe value (0, or a value that could not be found) makes the table unsafe.
  const bool every_case_safe = std::all_of(s.limits.begin(), s.limits.end(),
                                           [](const LimitRow& row) { return row.value > 0.0; });
  s.safe = s.evaluated && every_case_safe;
  s.margin = std::numeric_limits<double>::quiet_NaN();  // a table of limits has no one margin
  // The case with the lowest value governs (the first on a tie); its sentence names the value.
  const LimitRow* lowest = nullptr;
  for (const LimitRow& row : s.limits) {
    if (!std::isnan(row.value) && (lowest == nullptr || row.value < lowest->value)) lowest = &row;
  }
  if (lowest != nullptr) {
    s.governing_target = lowest->target;
    s.governing_criterion = lowest->binding_criterion;
    s.governing_case = "the lowest " + lowest->quantity + ": " +
                       (std::isinf(lowest->value) ? std::string("not limited")
                                                  : FormatSignificant(lowest->value, 4) + " " + lowest->unit);
  }
  if (!s.evaluated) {
    s.state = VerdictState::kNotEvaluated;
  } else {
    s.state = s.safe ? VerdictState::kLimits : VerdictState::kUnsafe;
  }
}

}  // namespace

std::string_view ToString(VerdictState state) noexcept {
  switch (state) {
    case VerdictState::kSafe: return "safe";
    case VerdictState::kMarginal: return "marginal";
    case VerdictState::kUnsafe: return "unsafe";
    case VerdictState::kLimits: return "limits";
    case VerdictState::kNotEvaluated: return "not-evaluated";
  }
  return "unknown";
}

std::string_view StateWord(VerdictState state) noexcept {
  switch (state) {
    case VerdictState::kSafe: return "SAFE";
    case VerdictState::kMarginal: return "MARGINAL";
    case VerdictState::kUnsafe: return "UNSAFE";
    case VerdictState::kLimits: return "LIMITS";
    case VerdictState::kNotEvaluated: return "NOT EVALUATED";
  }
  return "UNKNOWN";
}

VerdictState VerdictStateOf(bool evaluated, bool safe, double margin, double threshold) noexcept {
  if (!evaluated) return VerdictState::kNotEvaluated;
  if (!safe) return VerdictState::kUnsafe;
  return margin >= threshold ? VerdictState::kSafe : VerdictState::kMarginal;  // NaN margin: MARGINAL
}

void ResultSummary::AddLimitTable(const LimitTableSummary& table) {
  if (std::find(standards.begin(), standards.end(), table.edition) == standards.end()) standards.push_back(table.edition);
  const bool seen = std::any_of(limit_tables.begin(), limit_tables.end(), [&](const LimitTableSummary& t) {
    return t.sha256 == table.sha256 && t.source == table.source;
  });
  if (!seen) limit_tables.push_back(table);
}

void ResultSummary::AddVerdict(std::string_view target, const Verdict& verdict, std::string_view law,
                               std::string_view validity) {
  safety_factor = verdict.safety_factor;
  evaluated = evaluated && verdict.evaluated;
  AddOnce(targets, target);
  for (const Criterion& c : verdict.criteria) {
    rows.push_back(SummaryRow{.target = std::string(target),
                              .criterion = std::string(c.name),
                              .part = c.part,
                              .unit = std::string(c.unit),
                              .value = c.value,
                              .limit = c.limit,
                              .derated_limit = c.derated_limit,
                              .ratio = c.ratio,
                              .margin = 1.0 - verdict.safety_factor * c.ratio,
                              .counted = c.counted,
                              .passed = c.passed,
                              .binding = false,
                              .law = std::string(law),
                              .validity = std::string(validity),
                              .source = std::string(c.source),
                              .note = std::string(c.note)});
    if (!c.counted) continue;
    AddOnce(criteria, c.name);
    // The standards are the injury limits' sources; a design rule's source is the covering's own
    // (its travel, its strength, its law), not a standard.
    if (c.part == CriterionPart::kInjury) AddOnce(standards, c.source);
  }
  for (const std::string& sentence : verdict.scope) AddOnce(scope, sentence);
}

void ResultSummary::Finish() {
  if (kind == Kind::kVerdict) {
    FinishVerdict(*this);
  } else {
    FinishLimits(*this);
  }
}

}  // namespace covopt
