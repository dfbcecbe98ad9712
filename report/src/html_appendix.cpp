// The HTML report's appendix (none; the summary; every value of the result) and provenance
// (html_sections.hpp).
#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "covopt/report/report_info.hpp"
#include "html_sections.hpp"

namespace covopt::report::internal::html {

namespace {

bool IsScalarArray(const Json& v) {
  return v.is_array() && std::all_of(v.begin(), v.end(), [](const Json& e) { return e.is_primitive(); });
}

/// A value that reads on one line: a scalar, an empty or scalar array, or a small object of
/// such (at most 4 scalars).
bool IsInline(const Json& v) {
  if (v.is_primitive() || v.empty() || IsScalarArray(v)) return true;
  return v.is_object() && v.size() <= 4 &&
         std::all_of(v.begin(), v.end(), [](const Json& e) { return e.is_primitive() || (e.is_array() && e.empty()); });
}

void InlineText(std::string& out, const Json& v) {
  if (v.is_string()) {
    Escape(out, v.get<std::string>());
  } else if (v.is_primitive()) {
    out += v.dump();
  } else if (v.empty()) {
    out += v.is_array() ? "[]" : "{}";
  } else if (v.is_array()) {
    out += "[";
    bool first = true;
    for (const Json& e : v) {
      if (!first) out += ", ";
      first = false;
      if (e.is_string()) {  // quoted: "\"" + text + "\"" escaped (GCC 12 warns on that concatenation here)
        out += "&quot;";
        Escape(out, e.get<std::string>());
        out += "&quot;";
      } else {
        Escape(out, e.dump());
      }
    }
    out += "]";
  } else {
    bool first = true;
    for (const auto& [key, e] : v.items()) {
      if (!first) out += "; ";
      first = false;
      out += "<span class=\"key\">";
      Escape(out, key);
      out += "</span> ";
      InlineText(out, e);
    }
  }
}

/// Both are objects with the same keys in the same order.
bool SameKeys(const Json& a, const Json& b) {
  if (!a.is_object() || !b.is_object() || a.size() != b.size()) return false;
  auto i = a.begin();
  for (auto k = b.begin(); k != b.end(); ++k, ++i) {
    if (i.key() != k.key()) return false;
  }
  return true;
}

}  // namespace

/// Every value of `v` (an object or array) as full-width tables, one per nested object or
/// array, headed by its dotted path: scalars (and small objects of scalars) on one line, two
/// key/value pairs a row; an array of like objects of at most 14 inline values as one table
/// with a column per key. Nested values get their own table after their parent's.
void WriteAppendix(std::string& out, const Json& v, const std::string& path) {
  out += "<h4 class=\"key\">";
  Escape(out, path.empty() ? "(the result)" : path);
  out += "</h4>\n";
  const bool columns = v.is_array() && v.front().is_object() && v.front().size() <= 14 &&
                       std::all_of(v.begin(), v.end(), [&](const Json& e) {
                         return SameKeys(e, v.front()) &&
                                std::all_of(e.begin(), e.end(), [](const Json& x) { return IsInline(x); });
                       });
  if (columns) {
    out += "<table class=\"appendix\"><thead><tr><th>#</th>";
    for (const auto& [key, unused] : v.front().items()) {
      out += "<th>";
      Escape(out, key);
      out += "</th>";
    }
    out += "</tr></thead><tbody>\n";
    std::size_t index = 0;
    for (const Json& e : v) {
      out += "<tr><td>" + std::to_string(index++) + "</td>";
      for (const auto& [key, child] : e.items()) {
        out += "<td>";
        InlineText(out, child);
        out += "</td>";
      }
      out += "</tr>\n";
    }
    out += "</tbody></table>\n";
    return;
  }
  std::vector<std::pair<std::string, const Json*>> entries;
  if (v.is_object()) {
    for (const auto& [key, child] : v.items()) entries.emplace_back(key, &child);
  } else {
    for (std::size_t i = 0; i < v.size(); ++i) entries.emplace_back(std::to_string(i), &v[i]);
  }
  out += "<table class=\"appendix\"><colgroup><col style=\"width:20%\"><col style=\"width:30%\">"
         "<col style=\"width:20%\"><col style=\"width:30%\"></colgroup><tbody>\n";
  for (std::size_t i = 0; i < entries.size(); i += 2) {
    out += "<tr>";
    for (std::size_t k = i; k < i + 2; ++k) {
      if (k >= entries.size()) {
        out += "<td></td><td></td>";
        continue;
      }
      const auto& [key, child] = entries[k];
      out += "<td class=\"key\">";
      Escape(out, key);
      out += "</td><td>";
      if (IsInline(*child)) {
        InlineText(out, *child);
      } else {
        out += "see ";
        Escape(out, path.empty() ? key : path + "." + key);
      }
      out += "</td>";
    }
    out += "</tr>\n";
  }
  out += "</tbody></table>\n";
  for (const auto& [key, child] : entries) {
    if (!IsInline(*child)) WriteAppendix(out, *child, path.empty() ? key : path + "." + key);
  }
}

void WriteAppendixSection(std::string& out, ReportAppendix appendix, const ResultSummary& summary, const Json& j,
                          std::size_t body_rows) {
  out += "<section id=\"appendix\" data-appendix=\"";
  out += ToString(appendix);
  out += "\">\n";
  if (appendix == ReportAppendix::kFull) {
    out += "<h2>Appendix: every value of the result</h2>\n"
           "<p>The JSON object the command printed with --json, in full (SI units, as in its keys).</p>\n";
    WriteAppendix(out, j, "");
  } else if (appendix == ReportAppendix::kSummary) {
    out += "<h2>Appendix: the summary</h2>\n<p>The result's values that are neither inputs nor rows";
    out += summary.rows.size() > body_rows ? ", and every verdict row" : "";
    out += ". Every other value is in the result's JSON (<code>--json</code>; in the HTML report, under its last "
           "heading).</p>\n";
    if (summary.rows.size() > body_rows) WriteRows(out, summary, summary.rows.size());
    Json values = Json::object();
    for (const auto& [key, value] : j.items()) {
      if (value.is_primitive() && key != "safety_factor") values[key] = value;
    }
    if (!values.empty()) WriteAppendix(out, values, "the result's scalar values");
  }
  out += "</section>\n";
}

void WriteProvenance(std::string& out, const Json& p) {
  OpenTable(out, {{"field", 22}, {"value", 78}});
  for (const auto& [key, value] : p.items()) {
    if (key == "inputs") continue;
    out += "<tr>";
    Cell(out, key, "key");
    out += "<td><code>";
    Escape(out, ScalarText(value));
    out += "</code></td></tr>\n";
  }
  out += "</tbody></table>\n<h3>Input files</h3>\n";
  const Json* inputs = Find(p, "inputs");
  if (!inputs || !inputs->is_array() || inputs->empty()) {
    out += "<p>None: every input was given on the command line (above) or is built in.</p>\n";
    return;
  }
  OpenTable(out, {{"role", 12}, {"path", 30}, {"SHA-256", 46}, {"bytes", 12}});
  for (const Json& f : *inputs) {
    out += "<tr>";
    Cell(out, StringAt(f, "role"));
    out += "<td><code>";
    Escape(out, StringAt(f, "path"));
    out += "</code></td><td><code>";
    Escape(out, StringAt(f, "sha256"));
    out += "</code></td>";
    Cell(out, ScalarText(f.value("size_bytes", Json(nullptr))), "num");
    out += "</tr>\n";
  }
  out += "</tbody></table>\n";
}

}  // namespace covopt::report::internal::html
