#pragma once
/// @file report_settings.hpp
/// A report's sign-off settings (ReportInfo, report_info.hpp) read from what a front end was
/// given: the scene file's [report] table, the command line's --project, --cell, --assessor,
/// --note, --margin-threshold and --report-appendix, and Python's report_info dict. One reader
/// for the three, so a value is refused the same way everywhere; later settings win (the CLI
/// passes the file's first, then the flags').

#include <span>
#include <string_view>

#include "covopt/report/report_info.hpp"
#include "covopt/scene_file/scene_file.hpp"

namespace covopt::report {

using scene_file::ReportSetting;

/// A margin threshold written as a share: "10%" (a percentage, blanks allowed before the sign)
/// or a bare number in [0, 1) ("0.1").
/// @return the share [-], in [0, 1).
/// @throws std::invalid_argument "<name>: ..." (the problem alone when `name` is empty) naming the value and the range [0, 1) (0 % to
///         100 %); a bare number of 1 or more is refused as a likely percentage ("write 10%").
double ParseMarginThreshold(std::string_view text, std::string_view name);

/// Applies `settings` to `info` in order, each read by its key (ReportKeys(): project, cell,
/// assessor, note as texts; margin_threshold a number or a text for ParseMarginThreshold;
/// appendix "none", "summary" or "full") and checked as CheckReportInfo checks it. `info` is
/// changed only when every setting is good.
/// @throws std::invalid_argument "<setting.name>: ..." naming the value and what is allowed,
///         for an unknown key, a value of the wrong type or a value out of range (with an empty
///         name, the problem alone: for a caller that names the value itself).
void ApplyReportSettings(std::span<const ReportSetting> settings, ReportInfo& info);

}  // namespace covopt::report
