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
/// limits of the model (docs/model.md); the warnings; the charts; the provenance; an appendix
/// with every value of the JSON as nested tables (keys the report does not know land there too).
///
/// The document: HTML5, UTF-8, inline CSS for screen and print (A4, table rows and figures not
/// split across pages), a Content-Security-Policy that forbids every fetch and every script, no
/// script, no link, no font or image from outside. Every text of the JSON is HTML-escaped. A
/// chart's SVG loses its XML prolog and DOCTYPE, and each chart's element ids (and the
/// `href="#..."`/`url(#...)` references to them) get the prefix "chart<N>-" (N = 1, 2, ... in
/// order), so ids stay unique across charts; an SVG that refers to anything outside itself is
/// refused.
///
/// Margin, everywhere in the report: 1 − SF × ratio (ratio = value / limit, SF the safety
/// factor), the share of the derated limit left over; negative beyond the limit.
///
/// Machine-checkable markup (for tests and tools):
/// - `<section id="verdict" data-safe="true|false">`, its visible word "SAFE" or "UNSAFE" in a
///   `<div class="word">`; both verdicts use the same element, size, weight and place, only the
///   colours differ (classes "verdict safe" / "verdict unsafe").
/// - `<span id="governing-ratio" data-value="...">`: the governing ratio, data-value the JSON's
///   number text exactly as --json printed it ("null" where the kind has none: a speed-limit
///   table of body regions or over ranges, whose rows carry limits, not ratios). Per kind it is
///   the largest ratio of: simulate, the verdicts (laceration, contusion, crush; with ranges also
///   worst_case.governing_ratio; with --body-region every region's force, pressure, compression
///   and crush ratio and the head's); optimize, recommendation.governing_ratio (with
///   --max-injury-probability, P(inadmissible) / max_probability; no recommendation: the bare
///   robot's largest ratio); speed-limit, the rows' ratios at the limit (1 at the binding
///   criterion by construction); robot --trajectory, every sample's ratios (laceration_ratio,
///   contusion_ratio, compression_ratio; worst_ratio with --body-region); audit, every cell's
///   governing_ratio.
/// - Every input value (the leaves of the JSON's scene and other input objects of the kind:
///   safety_factor, limits, design_space, search_limit, uncertain_inputs, robot, coverings, ...)
///   in an element with `data-key="<dotted JSON path>"` (array elements by index:
///   "uncertain_inputs.0.low", "scene.robot.mass_kg") and `data-value="<the JSON value's text
///   exactly>"` (a number as --json printed it, a string's characters, true/false/null).
/// - Each chart in `<figure class="chart" id="chart-<N>">` holding one inline `<svg>`.
///
/// What SAFE means per kind: simulate, the JSON's "safe" (with ranges, and the worst case over
/// them admissible); optimize, a recommendation that is admissible (none found: UNSAFE; none
/// needed because the bare robot is safe: SAFE); speed-limit, every row has a safe limit above
/// zero (the robot is safe at or below its row's limit; a row with no safe value: UNSAFE);
/// robot --trajectory and audit, status "safe" (or "at-rest").

#include <string>
#include <string_view>
#include <vector>

#include "covopt/report/report_info.hpp"

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
  /// The sign-off fields, the margin threshold and the appendix (report_info.hpp).
  ReportInfo info;
};

/// The report as one HTML document (UTF-8).
/// @throws std::invalid_argument when result_json is not a JSON object, has no "provenance"
///         block, or holds no verdict of that kind (a failed run is never reported: a trajectory
///         or audit status other than safe/unsafe/at-rest, a speed-limit row whose evaluation
///         failed), or a chart's SVG is not an inline-able SVG document.
std::string HtmlReport(const ReportContent& content);

}  // namespace covopt::report
