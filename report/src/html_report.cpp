// The report for the risk-assessment file (html_report.hpp): one self-contained HTML5 document
// rendered from a command's --json object and its charts' SVG. What it says is the result's
// summary (summary_json.hpp); its sections are laid out by html_page_one.cpp,
// html_sections.cpp, html_inputs.cpp and html_appendix.cpp.
#include "covopt/report/html_report.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "covopt/report/summary_json.hpp"

#include "html_sections.hpp"
#include "html_svg.hpp"
#include "html_text.hpp"

namespace covopt::report {

std::string_view ToString(ReportKind kind) noexcept {
  switch (kind) {
    case ReportKind::kSimulate: return "simulate";
    case ReportKind::kOptimize: return "optimize";
    case ReportKind::kSpeedLimit: return "speed-limit";
    case ReportKind::kTrajectory: return "robot --trajectory";
    case ReportKind::kAudit: return "audit";
    case ReportKind::kRetime: return "retime";
    case ReportKind::kMeasure: return "measure";
  }
  return "unknown";
}

namespace {

using namespace internal::html;

/// The verdict rows the body shows; the appendix holds the rest.
constexpr std::size_t kMainRows = 24;

/// The command's --json object, with its provenance.
Json ParseResult(const std::string& result_json) {
  Json j;
  try {
    j = Json::parse(result_json);
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(std::string("report: result_json is not JSON (") + e.what() + ")");
  }
  if (!j.is_object()) {
    throw std::invalid_argument("report: result_json must be the JSON object a command prints with --json (got a " +
                                std::string(j.type_name()) + ")");
  }
  const Json* provenance = Find(j, "provenance");
  if (!provenance || !provenance->is_object()) {
    throw std::invalid_argument(
        "report: result_json has no \"provenance\" object (add it with report::WithProvenance)");
  }
  return j;
}

/// The result's summary (summary_json.hpp), refused when it has none or holds no verdict.
ResultSummary ReadSummary(ReportKind kind, const std::string& result_json) {
  ResultSummary s;
  try {
    s = SummaryFromJson(result_json);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("report: the " + std::string(ToString(kind)) +
                                " result has no summary to report (" + e.what() + ")");
  }
  if (!s.command.empty() && s.command.rfind(ToString(kind), 0) != 0) {
    throw std::invalid_argument("report: the result is of covopt " + s.command + ", not of covopt " +
                                std::string(ToString(kind)));
  }
  if (!s.evaluated || s.state == VerdictState::kNotEvaluated) {
    throw std::invalid_argument("report: no report for a " + std::string(ToString(kind)) +
                                " run without a verdict: the result could not be computed");
  }
  return s;
}

/// The JSON text of the summary's `key` (of `sub` when given), "null" when absent.
std::string SummaryNumberText(const Json& j, std::string_view sub, std::string_view key) {
  const Json* holder = Find(j, "summary");
  if (holder && !sub.empty()) holder = Find(*holder, sub);
  const Json* v = holder ? Find(*holder, key) : nullptr;
  return v && v->is_number() ? v->dump() : "null";
}

/// The first page's facts: the state with the report's threshold, the numbers' JSON texts.
PageOne MakePageOne(const ResultSummary& s, const ReportContent& content, const Json& j) {
  PageOne p;
  p.summary = &s;
  p.info = &content.info;
  p.provenance = &j.at("provenance");
  p.threshold = content.info.margin_threshold;
  p.safe = s.safe;
  if (s.kind == ResultSummary::Kind::kLimits) {
    p.state = s.safe ? VerdictState::kLimits : VerdictState::kUnsafe;
  } else {
    p.state = VerdictStateOf(s.evaluated, s.safe, s.margin, p.threshold);
  }
  p.margin_text = s.kind == ResultSummary::Kind::kLimits ? "null" : SummaryNumberText(j, "", "margin");
  p.ratio_text = SummaryNumberText(j, "governing", "ratio");
  p.threshold_text = Json(p.threshold).dump();
  return p;
}

/// Each chart's SVG made fit to inline, its ids prefixed with its number.
std::vector<std::string> InlineCharts(const std::vector<SvgChart>& charts) {
  std::vector<std::string> svgs;
  svgs.reserve(charts.size());
  for (std::size_t i = 0; i < charts.size(); ++i) {
    std::string prefix = "chart";  // ids of chart 1 become "chart1-gnuplot_canvas", ...
    prefix += std::to_string(i + 1);
    prefix += '-';
    svgs.push_back(covopt::internal::InlineSvg(charts[i].svg, prefix, i + 1));
  }
  return svgs;
}

/// The document's head: title, security policy and style sheet.
void WriteHead(std::string& out, const std::string& kind, std::string_view word) {
  out += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'; img-src data:\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>";
  Escape(out, "covopt " + kind + " report: " + std::string(word));
  out += "</title>\n<style>";
  out += kCss;
  out += "</style>\n</head>\n<body>\n";
}

/// What the verdict covers, in the summary's words.
void WriteScope(std::string& out, const ResultSummary& s) {
  if (s.kind == ResultSummary::Kind::kLimits) {
    out += "<p>The robot is safe at or below each row's value; the binding criterion is the one that reaches its "
           "derated limit there.</p>\n";
  } else {
    out += "<p><b>Margin</b>, here and below, is 1 − SF × ratio, the share of the derated limit (limit / SF) left "
         "over; a ratio is value / limit. Negative margins exceed the limit.</p>\n";
  }
  if (s.scope.empty()) return;
  out += "<ul class=\"compact\">\n";
  for (const std::string& sentence : s.scope) {
    out += "<li>";
    Escape(out, sentence);
    out += "</li>\n";
  }
  out += "</ul>\n";
}

void WriteWarnings(std::string& out, const Json& j) {
  const std::vector<std::string> warnings = TextList(Find(j, "warnings"));
  if (warnings.empty()) {
    out += "<p>None.</p>\n";
  } else {
    out += "<ul class=\"warnings\">\n";
    for (const std::string& w : warnings) {
      out += "<li>";
      Escape(out, w);
      out += "</li>\n";
    }
    out += "</ul>\n";
  }
}

void WriteCharts(std::string& out, const std::vector<SvgChart>& charts, const std::vector<std::string>& svgs) {
  if (charts.empty()) out += "<p>No charts.</p>\n";
  for (std::size_t i = 0; i < charts.size(); ++i) {
    out += "<figure class=\"chart\" id=\"chart-" + std::to_string(i + 1) + "\">\n";
    out += svgs[i];
    out += "\n<figcaption><b>Figure " + std::to_string(i + 1) + ". ";
    Escape(out, charts[i].title);
    out += "</b> ";
    Escape(out, charts[i].caption);
    out += "</figcaption>\n</figure>\n";
  }
}

}  // namespace

std::string HtmlReport(const ReportContent& content) {
  CheckReportInfo(content.info);
  const Json j = ParseResult(content.result_json);
  const ResultSummary summary = ReadSummary(content.kind, content.result_json);
  const PageOne page = MakePageOne(summary, content, j);
  const std::vector<std::string> svgs = InlineCharts(content.charts);

  std::string out;
  out.reserve(content.result_json.size() * 3 + 32768);
  WriteHead(out, std::string(ToString(content.kind)), StateWord(page.state));
  WritePageOne(out, page);
  out += summary.kind == ResultSummary::Kind::kLimits ? "<h2>Limits, one row per case</h2>\n" : "<h2>Verdict rows</h2>\n";
  WriteScope(out, summary);
  WriteRows(out, summary, kMainRows);
  out += "<h2>Charts</h2>\n";
  WriteCharts(out, content.charts, svgs);
  out += "<h2>Inputs</h2>\n";
  WriteInputs(out, j, content.kind);
  out += "<h2>Warnings</h2>\n";
  WriteWarnings(out, j);
  out += "<h2>Material</h2>\n";
  WriteMaterial(out, summary);
  out += "<h2>Assumptions and validity limits</h2>\n<p>From docs/model.md, for the models this result rests on.</p>\n";
  WriteModels(out, summary, j);
  out += "<h2>Provenance</h2>\n";
  WriteProvenance(out, j.at("provenance"));
  WriteAppendixSection(out, content.info.appendix, summary, j, kMainRows);
  out += "<details id=\"result-json\"><summary>The result's JSON (--json), in full</summary>\n<pre><code>";
  Escape(out, j.dump(1));
  out += "</code></pre>\n</details>\n</body>\n</html>\n";
  return out;
}

}  // namespace covopt::report
