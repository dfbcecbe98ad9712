// The report's first page (html_sections.hpp): the header, the verdict in three states with its
// margin, the governing case, what was judged, the covering, the robot and the sign-off block.
// Everything comes from the result's summary (covopt/core/result_summary.hpp) and the report's
// fields (report_info.hpp); nothing is judged here.
#include <cmath>
#include <string>
#include <vector>

#include "html_sections.hpp"

namespace covopt::report::internal::html {

namespace {

/// A share as a percentage without trailing zeros: "10 %" for 0.1, "12.5 %" for 0.125.
std::string ShortPercent(double fraction) { return Significant(100.0 * fraction, 3) + " %"; }

std::string JoinList(const std::vector<std::string>& items, std::string_view empty = "—") {
  if (items.empty()) return std::string(empty);
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

/// At most `shown` items, then how many more: page 1 stays one page.
std::string ShortList(const std::vector<std::string>& items, std::size_t shown) {
  if (items.size() <= shown) return JoinList(items);
  const std::vector<std::string> head(items.begin(), items.begin() + static_cast<std::ptrdiff_t>(shown));
  return JoinList(head) + " and " + std::to_string(items.size() - shown) + " more (all in the result's JSON)";
}

/// "head (frontal) contusion".
std::string RowName(const SummaryRow& row) { return row.target + " " + row.criterion; }

/// The sentence under the state word: the state in words, never in colour alone.
std::string StateSentence(const PageOne& p) {
  const ResultSummary& s = *p.summary;
  const std::string asked = ShortPercent(p.threshold);
  switch (p.state) {
    case VerdictState::kSafe:
      return "SAFE with a margin of " + FormatPercent(s.margin) + " (at least " + asked + " asked).";
    case VerdictState::kMarginal:
      return "MARGINAL: safe, but the margin " + FormatPercent(s.margin) + " is below the " + asked + " asked.";
    case VerdictState::kLimits:
      return "LIMITS: a table of the largest safe values, one per case (" + std::to_string(s.limits.size()) +
             "); the robot is safe at or below each row's value.";
    case VerdictState::kNotEvaluated: return "NOT EVALUATED: the result could not be computed.";
    case VerdictState::kUnsafe: break;
  }
  std::vector<std::string> failed;
  if (s.kind == ResultSummary::Kind::kLimits) {
    for (const LimitRow& row : s.limits) {
      if (!(row.value > 0.0)) failed.push_back(row.target);
    }
    return "UNSAFE: no safe value for " + JoinList(failed) + ".";
  }
  for (const SummaryRow& row : s.rows) {
    if (row.counted && !row.passed && failed.size() < 4) {
      failed.push_back(RowName(row) + (std::isfinite(row.margin) ? " (margin " + FormatPercent(row.margin) + ")" : ""));
    }
  }
  return "UNSAFE: " + (failed.empty() ? std::string("a counted criterion fails") : "fails " + JoinList(failed)) + ".";
}

/// One term and its description.
void Term(std::string& out, std::string_view term, std::string_view text) {
  out += "<dt>";
  Escape(out, term);
  out += "</dt><dd>";
  Escape(out, text.empty() ? "—" : text);
  out += "</dd>\n";
}

std::string Mass(double kg) { return std::isfinite(kg) ? Significant(kg) + " kg" : "not one value (see the rows)"; }

void WriteVerdict(std::string& out, const PageOne& p) {
  const ResultSummary& s = *p.summary;
  const std::string state(ToString(p.state));
  out += "<section id=\"verdict\" class=\"verdict " + state + "\" data-state=\"" + state + "\" data-safe=\"";
  out += p.safe ? "true" : "false";
  out += "\">\n<div class=\"word\">";
  Escape(out, StateWord(p.state));
  out += "</div>\n<div class=\"sentence\">";
  Escape(out, StateSentence(p));
  out += "</div>\n<div class=\"governing\">Margin <span id=\"margin\" data-value=\"";
  Escape(out, p.margin_text);
  out += "\">";
  Escape(out, s.kind == ResultSummary::Kind::kLimits ? "none (a table of limits)" : FormatPercent(s.margin));
  out += "</span>, threshold <span id=\"margin-threshold\" data-value=\"";
  Escape(out, p.threshold_text);
  out += "\">";
  Escape(out, ShortPercent(p.threshold));
  out += "</span>; governing ratio <span id=\"governing-ratio\" data-value=\"";
  Escape(out, p.ratio_text);
  out += "\">";
  Escape(out, p.ratio_text == "null" ? "none (see the table of limits)" : Significant(s.governing_ratio));
  out += "</span>; safety factor ";
  Escape(out, Significant(s.safety_factor));
  out += "</div>\n</section>\n";
}

void WriteFacts(std::string& out, const PageOne& p) {
  const ResultSummary& s = *p.summary;
  out += "<div class=\"facts\">\n<section id=\"governing-case\"><h3>Governing case</h3><dl>\n";
  Term(out, "target", s.governing_target);
  Term(out, "criterion", s.governing_criterion);
  Term(out, "ratio", p.ratio_text == "null" ? "" : Significant(s.governing_ratio) + " (value / limit)");
  Term(out, "where", s.governing_case);
  out += "</dl></section>\n<section id=\"judged\"><h3>What was judged</h3><dl>\n";
  Term(out, "targets", ShortList(s.targets, 6));
  Term(out, "criteria", JoinList(s.criteria));
  Term(out, "standards", JoinList(s.standards));
  for (const LimitTableSummary& t : s.limit_tables) {
    Term(out, "limit table", t.title + " (" + t.source + ", SHA-256 " + t.sha256 + ")");
  }
  Term(out, "safety factor", Significant(s.safety_factor) + " (each limit derated to limit / SF)");
  out += "</dl></section>\n<section id=\"covering\"><h3>Covering</h3><dl>\n";
  const CoveringSummary& c = s.covering;
  if (c.present) {
    Term(out, "material", c.material.empty() ? "given by its modulus (no catalog material)" : c.material);
    Term(out, "thickness", Significant(c.thickness_m * 1e3) + " mm");
    Term(out, "law", c.law);
    Term(out, "validity", std::isfinite(c.validity_ratio)
                              ? c.validity + " (validity ratio " + Significant(c.validity_ratio) + ", 1 at the law's edge)"
                              : c.validity);
  } else {
    Term(out, "material", "none: the bare robot");
  }
  out += "</dl></section>\n<section id=\"robot\"><h3>Robot</h3><dl>\n";
  const RobotSummary& r = s.robot;
  Term(out, "model file", r.model_file.empty() ? "none: a reflected mass given directly" : r.model_file);
  Term(out, r.joints.empty() ? "motion" : "joints", r.joints.empty() ? r.motion : JoinList(r.joints));
  if (!r.joints.empty()) Term(out, "motion", r.motion);
  Term(out, "reflected mass", Mass(r.reflected_mass_kg));
  Term(out, "payload", Mass(r.payload_kg));
  Term(out, "speed", std::isfinite(r.speed_m_per_s) ? Significant(r.speed_m_per_s) + " m/s" : "not one value (see the rows)");
  out += "</dl></section>\n</div>\n";
}

void Field(std::string& out, std::string_view field, std::string_view term, std::string_view text) {
  out += "<dt>";
  Escape(out, term);
  out += "</dt><dd data-field=\"";
  out += field;
  out += "\"";
  if (text.empty()) out += " class=\"blank\"";
  out += ">";
  Escape(out, text);
  out += "</dd>\n";
}

void WriteSignOff(std::string& out, const PageOne& p) {
  const ReportInfo& info = *p.info;
  const Json& prov = *p.provenance;
  out += "<section id=\"sign-off\"><h3>Sign-off</h3><dl>\n";
  Field(out, "project", "project", info.project);
  Field(out, "cell", "cell", info.cell);
  Field(out, "assessor", "assessor", info.assessor);
  Field(out, "note", "note", info.note);
  Field(out, "date", "report date", StringAt(prov, "date_utc"));
  Field(out, "version", "software",
        StringAt(prov, "software", "covopt") + " " + StringAt(prov, "version") + ", commit " + StringAt(prov, "commit"));
  std::string digests;
  if (const Json* inputs = Find(prov, "inputs"); inputs && inputs->is_array()) {
    for (const Json& f : *inputs) {
      digests += (digests.empty() ? "" : "; ") + StringAt(f, "role") + " " + StringAt(f, "path") + " SHA-256 " +
                 StringAt(f, "sha256");
    }
  }
  Field(out, "digests", "input digests",
        digests.empty() ? "none: every input was given on the command line or is built in" : digests);
  out += "</dl>\n";
  for (const auto& [role, title] : {std::pair{"assessor", "Assessor"}, std::pair{"approver", "Approver"}}) {
    out += "<div class=\"signature-line\" data-role=\"";
    out += role;
    out += "\"><span class=\"role\">";
    out += title;
    out += "</span><span class=\"line\">name</span><span class=\"line\">signature</span><span class=\"line\">date</span></div>\n";
  }
  out += "</section>\n";
}

}  // namespace

void WritePageOne(std::string& out, const PageOne& p) {
  out += "<section id=\"page-one\">\n<header>\n<h1>";
  Escape(out, "Collision safety report: covopt " + p.summary->command);
  out += "</h1>\n<p class=\"meta\">";
  const std::string project = p.info->project.empty() ? "no project given" : "project " + p.info->project;
  const std::string cell = p.info->cell.empty() ? "no cell given" : "cell " + p.info->cell;
  Escape(out, project + " · " + cell);
  out += "</p>\n</header>\n";
  WriteVerdict(out, p);
  WriteFacts(out, p);
  WriteSignOff(out, p);
  out += "</section>\n";
}

}  // namespace covopt::report::internal::html
