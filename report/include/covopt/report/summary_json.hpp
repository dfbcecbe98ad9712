#pragma once
/// @file summary_json.hpp
/// The result summary (covopt/core/result_summary.hpp) as JSON and as text: the "summary"
/// object of every result's --json, the block the CLI's text prints, Python's repr, and what
/// the HTML report reads back (SummaryFromJson) to lay out its first page.
///
/// The JSON object (keys in this order; a number that is not finite is null):
///   {"kind": "verdict"|"limits", "command", "evaluated", "safe", "state": "safe"|"marginal"|
///    "unsafe"|"limits"|"not-evaluated", "safety_factor", "margin", "margin_threshold",
///    "governing": {"target", "criterion", "ratio", "case"}, "targets": [...], "criteria": [...],
///    "standards": [...], "limit_tables": [{title, edition, source, sha256}], "scope": [...],
///    "covering": null | {"material", "thickness_m", "law", "validity", "validity_ratio"},
///    "robot": {"model_file", "motion", "joints": [...], "reflected_mass_kg", "payload_kg",
///              "speed_m_per_s"},
///    "rows": [{"target", "criterion", "part": "injury"|"design-rule", "unit", "value", "limit",
///              "derated_limit", "ratio", "margin", "counted", "passed", "binding", "law",
///              "validity", "source", "note"}],
///    "limits": [{"target", "quantity", "unit", "value", "binding_criterion", "law", "validity",
///                "note"}]}
///
/// A null reads back as the one non-finite value that key can hold: "margin" as −inf (a verdict
/// not evaluated; NaN for a table of limits), "governing"."ratio" as +inf, a row's "ratio" as
/// +inf (NaN when its "limit" is null: unknown), a row's "margin" as −inf (NaN when its ratio is
/// NaN), a limit row's "value" as +inf (not limited below the search limit), and every other
/// number as NaN (unknown, or not one value).

#include <string>

#include "covopt/core/result_summary.hpp"

namespace covopt::report {

/// The summary as the JSON object above (compact text).
std::string SummaryJson(const ResultSummary& summary);

/// The summary read back from the "summary" object of a result's JSON text (`result_json`, the
/// whole --json object) or from the object itself.
/// @throws std::invalid_argument when there is no "summary" object or it lacks a key above.
ResultSummary SummaryFromJson(const std::string& result_json);

/// The summary as the CLI's text prints it: the state word with the margin and the threshold,
/// the governing case, the covering, then one line per row (target, criterion, value, limit,
/// derated limit, ratio, margin, binding mark) in the units the CLI uses (MPa, J/cm², N, mm).
/// Ends with a line break. `indent` spaces start every line; without `rows` the row and limit
/// lines are left out (for a text that prints each criterion in its own detail after it).
std::string SummaryText(const ResultSummary& summary, int indent = 0, bool rows = true);

/// The first line of SummaryText, without its line break: the state word with the margin and
/// the threshold and the governing row, e.g. "MARGINAL, margin 0.2 % < 10.0 %: head (frontal)
/// contusion ratio 0.998" (Python's repr of a result; the speed-limit table's verdict line).
std::string SummaryHeadline(const ResultSummary& summary);

}  // namespace covopt::report
