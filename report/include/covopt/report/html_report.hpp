#pragma once
/// @file html_report.hpp
/// The report for the risk-assessment file: one self-contained HTML document (inline CSS and
/// inline SVG charts, no script, nothing fetched at view time) made from a command's result.
///
/// The report is rendered from the very JSON object the command prints with --json (provenance
/// block included), so the report and the JSON cannot disagree, and the CLI's --report and
/// Python's result.to_html() are one function. It contains: the verdict (SAFE or UNSAFE, equally
/// prominent) with the governing criterion and ratio; every input with its unit; the criteria and
/// limits with their sources (Park et al. 2011, ISO/TS 15066:2016 Table A.2 with the row, the
/// material's datasheet); every verdict with ratio and margin; the assumptions and validity
/// limits of the model (docs/model.md); the warnings; the charts; the provenance.

#include <string>
#include <string_view>
#include <vector>

namespace covopt::report {

/// The command a report is for.
enum class ReportKind { kSimulate, kOptimize, kSpeedLimit, kTrajectory, kAudit };

/// "simulate", "optimize", "speed-limit", "robot --trajectory", "audit".
std::string_view ToString(ReportKind kind) noexcept;

/// A chart of a report: a standalone SVG document (gnuplot's, its XML prolog allowed) with a
/// title and a caption saying what it shows.
struct SvgChart {
  std::string title;
  std::string caption;
  std::string svg;
};

/// What a report is made of.
struct ReportContent {
  ReportKind kind = ReportKind::kSimulate;
  /// The JSON object the command prints with --json (the Python result's to_dict()), with its
  /// "provenance" block (provenance.hpp).
  std::string result_json;
  /// The charts, in the order they appear.
  std::vector<SvgChart> charts;
};

/// The report as one HTML document (UTF-8).
/// @throws std::invalid_argument when result_json is not a JSON object, has no "provenance"
///         block, or holds no verdict of that kind (a failed run is never reported).
std::string HtmlReport(const ReportContent& content);

}  // namespace covopt::report
