#pragma once
/// @file html_report.hpp
/// The report for the risk-assessment file: one self-contained HTML document (inline CSS and
/// inline SVG charts, no script, nothing fetched at view time) made from a command's result.
///
/// The report is rendered from the very JSON object the command prints with --json (provenance
/// block included), so the report and the JSON cannot disagree, and the CLI's --report and
/// Python's result.to_html() are one function. What it says is the result's "summary" object
/// (summary_json.hpp), made by the library from the result: the report lays it out and judges
/// nothing; it reads no prose.
///
/// The document, in order:
/// - page 1 (`<section id="page-one">`, a page break after it in print): the header (title,
///   project, cell); the verdict in one of four states with its word and a sentence, so the state
///   is in words and not colour alone: SAFE (green; margin >= the report's margin threshold),
///   MARGINAL (amber; safe, margin below it), UNSAFE (red), LIMITS (blue; a table of limits); the
///   margin, the threshold and the governing ratio; the governing case; what was judged (targets,
///   criteria, standards with editions, safety factor); the covering; the robot; the sign-off
///   block (ReportInfo's project, cell, assessor, note; the provenance's date, version, commit
///   and input digests; empty signature lines for the assessor and the approver);
/// - the verdict rows (or the limit rows) with units, ratios and margins (at most 24; the
///   governing, the failed and the largest ratios first; all in the summary appendix);
/// - the charts; the inputs as tables by group; the warnings; the covering material's datasheet;
///   the assumptions and validity limits of the models (docs/model.md) the summary's criteria,
///   law and command rest on; the provenance;
/// - the appendix ReportInfo::appendix asks for: none; summary (every row and the result's
///   scalar values); full (every value of the JSON as nested tables);
/// - the whole JSON in a collapsed `<details id="result-json">`, not printed.
///
/// The document: HTML5, UTF-8, inline CSS for screen and print (A4, table rows and figures not
/// split across pages), a Content-Security-Policy that forbids every fetch and every script, no
/// script, no link, no font or image from outside. Every text of the JSON and of ReportInfo is
/// HTML-escaped. A chart's SVG loses its XML prolog and DOCTYPE, and each chart's element ids
/// (and the `href="#..."`/`url(#...)` references to them) get the prefix "chart<N>-" (N = 1, 2,
/// ... in order), so ids stay unique across charts; an SVG that refers to anything outside
/// itself is refused.
///
/// Margin, everywhere in the report: 1 − SF × ratio (ratio = value / limit, SF the safety
/// factor), the share of the derated limit left over; negative beyond the limit.
///
/// Machine-checkable markup (for tests and tools):
/// - `<section id="verdict" class="verdict S" data-state="S" data-safe="true|false">`, S one of
///   safe, marginal, unsafe, limits; its visible word in a `<div class="word">` and the sentence
///   in a `<div class="sentence">`; every state uses the same element, size, weight and place,
///   only the colours differ. data-safe is the summary's verdict (true for SAFE and MARGINAL).
/// - `<span id="margin" data-value="...">`, `<span id="margin-threshold" data-value="...">` and
///   `<span id="governing-ratio" data-value="...">`: the summary's margin and governing ratio as
///   the JSON's number text exactly ("null" where there is none: a table of limits), the
///   threshold's shortest text ("0.1").
/// - `<section id="governing-case">`, `id="judged"`, `id="covering"`, `id="robot"`,
///   `id="sign-off"` (with `<dd data-field="project|cell|assessor|note|date|version|digests">`,
///   class "blank" when empty, and `<div class="signature-line" data-role="assessor|approver">`).
/// - `<table class="inputs" data-group="robot|covering|human|criteria|solver|other">` with the
///   columns quantity, value, unit, source: each input leaf of the result (the leaves of its
///   scene and other input objects: safety_factor, limits, design_space, search_limit,
///   uncertain_inputs, robot, coverings, ...) with its value cell
///   `data-key="<dotted JSON path>"` (array elements by index: "uncertain_inputs.0.low") and
///   `data-value="<the JSON value's text exactly>"`, its value in the unit the command line uses
///   (mm, MPa, J/cm², N/cm², cm²), its unit cell `class="unit"` ("-" for a pure number, "text"
///   for a word), its source cell `class="source"` (the JSON's "input_sources" entry of that
///   path: "flag --robot-mass", "scene file s.toml", "catalog", "default"; "—" where it has none).
/// - Each chart in `<figure class="chart" id="chart-<N>">` holding one inline `<svg>`.
/// - `<section id="appendix" data-appendix="none|summary|full">`; `<details id="result-json">`.

#include <string>
#include <string_view>
#include <vector>

#include "covopt/report/report_info.hpp"

namespace covopt::report {

/// The command a report is for.
enum class ReportKind { kSimulate, kOptimize, kSpeedLimit, kTrajectory, kAudit, kRetime, kMeasure };

/// "simulate", "optimize", "speed-limit", "robot --trajectory", "audit", "retime", "measure".
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
///         block or no "summary", is another command's result, was not evaluated (a failed run
///         is never reported), when content.info fails CheckReportInfo, or when a chart's SVG is
///         not an inline-able SVG document.
std::string HtmlReport(const ReportContent& content);

}  // namespace covopt::report
