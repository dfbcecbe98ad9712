#pragma once
/// @file report_option.hpp
/// `--report FILE.html|FILE.pdf`, shared by simulate, optimize, speed-limit, robot --trajectory
/// and audit: the report for the risk-assessment file (covopt/report/html_report.hpp), made
/// from the very JSON object the command prints with --json (provenance included), written
/// only after a run that succeeded (exit 0; an UNSAFE verdict is a result, and is reported).
/// Beside it the sign-off flags (--project, --cell, --assessor, --note, --margin-threshold,
/// --report-appendix), which need --report and win over the scene file's [report] table.

#include <functional>
#include <optional>
#include <span>
#include <ostream>
#include <string>
#include <vector>

#include "covopt/report/charts.hpp"
#include "covopt/report/html_report.hpp"
#include "covopt/scene_file/scene_file.hpp"
#include "run_context.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The report's flags as typed.
struct ReportFlags {
  /// --report FILE.html|FILE.pdf: the report, written after a run that succeeded.
  std::optional<std::string> file;
  /// --project, --cell, --assessor, --note TEXT; --margin-threshold SHARE ("10%" or 0.1);
  /// --report-appendix none|summary|full (report::ReportInfo).
  std::optional<std::string> project;
  std::optional<std::string> cell;
  std::optional<std::string> assessor;
  std::optional<std::string> note;
  std::optional<std::string> margin_threshold;
  std::optional<std::string> appendix;

  /// The sign-off flags given, as settings named by their flags ("--project").
  std::vector<scene_file::ReportSetting> Settings() const;
};

/// What a command's inputs add to its report: the scene file's [report] table (already
/// checked), applied before the flags.
struct ResultInputs {
  std::vector<scene_file::ReportSetting> file_report;
};

/// Adds --report FILE.html|FILE.htm|FILE.pdf (group "Output") and the sign-off flags (group
/// "Report", each needing --report) to `command`. Any other extension, and a sign-off value
/// the report refuses (report::ApplyReportSettings), is a parse error (exit 2, before any
/// computation) naming the flag and the value.
void AddReportOption(CLI::App& command, ReportFlags& flags);

/// The report's settings: report::ReportInfo's defaults, then the scene file's [report]
/// table, then the flags.
/// @throws InputError for a value the report refuses (checked at parse time already).
report::ReportInfo ReportInfoOf(const ReportFlags& flags, const ResultInputs& inputs);

/// Writes the report of `result_json` (a command's --json object with its provenance block)
/// to `file`: HTML through the CLI's file writer (WriteFileAtomically), PDF through
/// WriteReportPdf. The charts are drawn by one gnuplot run (report::DrawSvgCharts, its scratch
/// files removed on Ctrl-C too).
/// @throws OutputError (exit 1) naming the file when it cannot be written, when gnuplot is
///         missing or fails, or when result_json holds no reportable result (report::HtmlReport
///         refuses a failed run): no file is written then.
void WriteReport(const std::string& file, report::ReportKind kind, const std::string& result_json,
                 std::span<const report::GnuplotChart> charts, const report::ReportInfo& info = {});

/// The one way a result object leaves a command: `json_object` (the --json object) gets the
/// run's provenance (WithRunProvenance); the report of `kind` is written to `report.file` when
/// given (`charts` is called only then; its settings ReportInfoOf(report, inputs)), and then the object is printed to `out` (one
/// line break after it) when `print_json`. Call it only after the run succeeded.
/// @throws OutputError when the report cannot be written (nothing is printed then).
void PrintAndReport(std::ostream& out, bool print_json, const std::string& json_object,
                    const std::optional<RunContext>& run, const ReportFlags& report, const ResultInputs& inputs,
                    report::ReportKind kind, const std::function<std::vector<report::GnuplotChart>()>& charts);

}  // namespace covopt::cli
