// The report for the risk-assessment file (html_report.hpp): one self-contained HTML5 document
// rendered from a command's --json object and its charts' SVG. What it says is read by
// html_assessment.cpp; its sections are written by html_sections.cpp and html_appendix.cpp.
#include "covopt/report/html_report.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "html_assessment.hpp"
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
  }
  return "unknown";
}

namespace {

using namespace internal::html;

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

/// What the result says, by the kind of command that printed it.
Assessment Assess(ReportKind kind, const Json& j) {
  Assessment a;
  try {
    switch (kind) {
      case ReportKind::kSimulate: AssessSimulate(a, j); break;
      case ReportKind::kOptimize: AssessOptimize(a, j); break;
      case ReportKind::kSpeedLimit: AssessSpeedLimit(a, j); break;
      case ReportKind::kTrajectory: AssessTrajectory(a, j); break;
      case ReportKind::kAudit: AssessAudit(a, j); break;
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument("report: result_json is not a " + std::string(ToString(kind)) +
                                " result (" + e.what() + ")");
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("report: no report for a " + std::string(ToString(kind)) +
                                " run without a verdict: " + e.what());
  }
  return a;
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

/// The document's head and the report's header: what ran, when, and the command line.
void WriteHeader(std::string& out, const std::string& kind, const std::string& word, const Json& provenance) {
  out += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'; img-src data:\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>";
  Escape(out, "covopt " + kind + " report: " + word);
  out += "</title>\n<style>";
  out += kCss;
  out += "</style>\n</head>\n<body>\n<header>\n<h1>";
  Escape(out, "Collision safety report: covopt " + kind);
  out += "</h1>\n<p class=\"meta\">";
  Escape(out, StringAt(provenance, "software", "covopt") + " " + StringAt(provenance, "version") + ", commit " +
                  StringAt(provenance, "commit") + ", " + StringAt(provenance, "date_utc"));
  out += "<br><code>";
  Escape(out, StringAt(provenance, "command"));
  out += "</code></p>\n</header>\n";
}

/// The verdict: SAFE and UNSAFE in the same element, size and place; only the colours differ.
void WriteVerdictBox(std::string& out, const Assessment& a, const std::string& word) {
  out += "<section id=\"verdict\" class=\"verdict ";
  out += a.safe ? "safe" : "unsafe";
  out += "\" data-safe=\"";
  out += a.safe ? "true" : "false";
  out += "\">\n<div class=\"word\">" + word + "</div>\n<div class=\"headline\">";
  Escape(out, a.headline);
  out += "</div>\n<div class=\"governing\">Governing: ";
  Escape(out, a.governing.criterion.empty() ? "—" : a.governing.criterion);
  out += ", ratio <span id=\"governing-ratio\" data-value=\"";
  Escape(out, ScalarText(a.governing.ratio));
  out += "\">";
  Escape(out, a.governing.ratio.is_number() ? Significant(a.governing.ratio.get<double>()) : "none (see below)");
  out += "</span>";
  if (a.governing.ratio.is_number()) {
    out += ", margin ";
    Escape(out, Percent(1.0 - a.safety_factor * a.governing.ratio.get<double>()));
  }
  out += " (safety factor ";
  Escape(out, Significant(a.safety_factor));
  out += ")</div>\n</section>\n";
  out += "<p><b>Margin</b>, here and below, is 1 − SF × ratio, the share of the derated limit (limit / SF) left over; "
         "a ratio is value / limit. Negative margins exceed the limit.";
  if (!a.safe_means.empty()) {
    out += " ";
    Escape(out, a.safe_means);
  }
  out += "</p>\n";
}

/// What the verdict covers: the result's scope, and each criterion it names that the scope does not say.
void WriteScope(std::string& out, const Json& j) {
  std::vector<std::string> scope = TextList(Find(j, "scope"));
  for (const std::string& s : TextList(Find(j, "criterion"))) {
    const bool said = std::any_of(scope.begin(), scope.end(), [&](const std::string& t) { return t.find(s) != std::string::npos; });
    if (!said) scope.push_back("Criterion: " + s);
  }
  if (scope.empty()) scope.push_back("The criteria listed under Criteria and limits.");
  for (const std::string& s : scope) {
    out += "<li>";
    Escape(out, s);
    out += "</li>\n";
  }
  out += "</ul>\n";
}

/// The criteria and their limits, each once, with the safety factor.
void WriteCriteria(std::string& out, const Assessment& a) {
  OpenTable(out, {{"criterion", 30}, {"limit", 20}, {"source", 50}});
  std::set<std::string> seen;
  for (const Criterion& c : a.criteria) {
    if (!seen.insert(c.name + c.limit).second) continue;
    out += "<tr>";
    Cell(out, c.name);
    Cell(out, c.limit);
    Cell(out, c.source);
    out += "</tr>\n";
  }
  out += "</tbody></table>\n<p>Safety factor SF = ";
  Escape(out, Significant(a.safety_factor));
  out += ": each ratio must stay at or below 1/SF (the derated limit is limit / SF).</p>\n";
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
  const Json j = ParseResult(content.result_json);
  const Json& provenance = j.at("provenance");
  const Assessment a = Assess(content.kind, j);
  const std::vector<std::string> svgs = InlineCharts(content.charts);

  const std::string word = a.safe ? "SAFE" : "UNSAFE";
  std::string out;
  out.reserve(content.result_json.size() * 3 + 32768);
  WriteHeader(out, std::string(ToString(content.kind)), word, provenance);
  WriteVerdictBox(out, a, word);
  out += "<h2>What the verdict covers</h2>\n<ul>\n";
  WriteScope(out, j);
  out += "<h2>Inputs</h2>\n";
  WriteInputs(out, j, a.input_keys);
  out += "<h2>Criteria and limits</h2>\n";
  WriteCriteria(out, a);
  out += "<h2>Verdicts</h2>\n";
  WriteVerdicts(out, a);
  out += "<h2>Materials</h2>\n";
  WriteMaterials(out, j);
  out += "<h2>Assumptions and validity limits</h2>\n<p>From docs/model.md, for the models this result rests on.</p>\n";
  WriteModels(out, a);
  out += "<h2>Warnings</h2>\n";
  WriteWarnings(out, j);
  out += "<h2>Charts</h2>\n";
  WriteCharts(out, content.charts, svgs);
  out += "<h2>Provenance</h2>\n";
  WriteProvenance(out, provenance);
  out += "<section class=\"appendix-section\">\n<h2>Appendix: every value of the result</h2>\n"
         "<p>The JSON object the command printed with --json, in full (SI units, as in its keys).</p>\n";
  WriteAppendix(out, j, "");
  out += "\n</section>\n</body>\n</html>\n";
  return out;
}

}  // namespace covopt::report
