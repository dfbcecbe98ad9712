#pragma once
/// @file report_info.hpp
/// What a report says besides the result: who it is for and who signs it (project, cell,
/// assessor, note), the margin below which SAFE reads MARGINAL, and how much of the result the
/// appendix holds. Set by the CLI (--project, --cell, --assessor, --note, --margin-threshold,
/// --report-appendix, or a [report] table of the scene file; a flag wins over the file), by
/// Python (to_html(path, report_info={...}), to_pdf), printed on the report's first page with
/// the date, version and input digests of the result's provenance, above empty signature lines
/// for the assessor and the approver.

#include <string>
#include <string_view>

#include "covopt/core/result_summary.hpp"

namespace covopt::report {

/// How much of the result a report's appendix holds.
enum class ReportAppendix {
  kNone,     ///< no appendix (the HTML still carries the whole JSON, collapsed)
  kSummary,  ///< every summary row and every input (the default)
  kFull,     ///< every value of the result's JSON, as nested tables
};
/// "none", "summary", "full".
std::string_view ToString(ReportAppendix appendix) noexcept;
/// The appendix called `name` ("none", "summary", "full").
/// @throws std::invalid_argument naming the value and the allowed ones.
ReportAppendix ParseReportAppendix(std::string_view name);

/// The sign-off fields and the report's settings. Texts are printed as given (escaped); each
/// at most 2000 characters, without control characters other than line breaks in `note`.
struct ReportInfo {
  std::string project;
  std::string cell;
  std::string assessor;
  std::string note;
  /// A SAFE verdict with a margin below this [-] reads MARGINAL; in [0, 1), default 10 %.
  double margin_threshold = kDefaultMarginThreshold;
  ReportAppendix appendix = ReportAppendix::kSummary;
};

/// Checks `info` (lengths, characters, the threshold's range).
/// @throws std::invalid_argument naming the field, the value and the allowed range.
void CheckReportInfo(const ReportInfo& info);

}  // namespace covopt::report
