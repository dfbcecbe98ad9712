#pragma once
/// @file report_option.hpp
/// `--report FILE.html|FILE.pdf`, shared by simulate, optimize, speed-limit, robot --trajectory
/// and audit: the report for the risk-assessment file (covopt/report/html_report.hpp), made
/// from the very JSON object the command prints with --json (provenance included), written
/// only after a run that succeeded (exit 0; an UNSAFE verdict is a result, and is reported).

#include <functional>
#include <optional>
#include <span>
#include <ostream>
#include <string>
#include <vector>

#include "covopt/chart/charts.hpp"
#include "covopt/report/html_report.hpp"
#include "run_context.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// Adds --report FILE.html|FILE.htm|FILE.pdf (group "Output") to `command`. Any other
/// extension is a parse error (exit 2, before any computation) naming the flag and the value.
void AddReportOption(CLI::App& command, std::optional<std::string>& file);

/// Writes the report of `result_json` (a command's --json object with its provenance block)
/// to `file`: HTML through the CLI's file writer (WriteFileAtomically), PDF through
/// WriteReportPdf. The charts are drawn by one gnuplot run (chart::DrawSvgCharts, its scratch
/// files removed on Ctrl-C too).
/// @throws OutputError (exit 1) naming the file when it cannot be written, when gnuplot is
///         missing or fails, or when result_json holds no reportable result (report::HtmlReport
///         refuses a failed run): no file is written then.
void WriteReport(const std::string& file, report::ReportKind kind, const std::string& result_json,
                 std::span<const chart::GnuplotChart> charts);

/// The one way a result object leaves a command: `json_object` (the --json object) gets the
/// run's provenance (WithRunProvenance); the report of `kind` is written to `report_file`
/// when given (`charts` is called only then), and then the object is printed to `out` (one
/// line break after it) when `print_json`. Call it only after the run succeeded.
/// @throws OutputError when the report cannot be written (nothing is printed then).
void PrintAndReport(std::ostream& out, bool print_json, const std::string& json_object,
                    const std::optional<RunContext>& run, const std::optional<std::string>& report_file,
                    report::ReportKind kind, const std::function<std::vector<chart::GnuplotChart>()>& charts);

}  // namespace covopt::cli
