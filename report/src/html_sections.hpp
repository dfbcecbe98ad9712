#pragma once
/// @file html_sections.hpp
/// The HTML report's sections (private to covopt_report): its style sheet, tables, the first
/// page, the verdict rows, the inputs, the material, the models' assumptions, the appendix and
/// the provenance. Each lays out what it is given: the verdict is the result's summary's.

#include <initializer_list>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <covopt/core/result_summary.hpp>

#include "covopt/report/html_report.hpp"
#include "html_text.hpp"

namespace covopt::report::internal::html {

/// The report's style sheet (A4 print and screen).
extern const std::string_view kCss;

/// Opens a table with its columns (name, width in %) and its body.
void OpenTable(std::string& out, std::initializer_list<std::pair<std::string_view, int>> columns,
               std::string_view cls = "");
void Cell(std::string& out, std::string_view text, std::string_view cls = "");

/// What the first page shows (html_page_one.cpp).
struct PageOne {
  const ResultSummary* summary = nullptr;
  const ReportInfo* info = nullptr;
  const Json* provenance = nullptr;
  VerdictState state = VerdictState::kUnsafe;  ///< with the report's margin threshold
  bool safe = false;                           ///< the summary's verdict
  double threshold = kDefaultMarginThreshold;  ///< [-]
  std::string margin_text;      ///< the summary's margin as its JSON text ("null" for none)
  std::string ratio_text;       ///< the summary's governing ratio as its JSON text
  std::string threshold_text;   ///< the threshold's shortest JSON text ("0.1")
};
/// The first page: header, verdict, governing case, what was judged, covering, robot, sign-off.
void WritePageOne(std::string& out, const PageOne& page);

/// The verdict rows (or the limit rows) of `summary`; at most `max_rows` rows (the binding,
/// the failed and the largest ratios), saying how many are left to the appendix.
void WriteRows(std::string& out, const ResultSummary& summary, std::size_t max_rows);

/// The inputs of a `kind` result as tables by group (html_inputs.cpp): robot, covering, human,
/// criteria, solver, other; each leaf's quantity, value in the CLI's unit, unit and source (the
/// JSON's "input_sources").
void WriteInputs(std::string& out, const Json& j, ReportKind kind);
/// The datasheet of the covering's catalog material.
void WriteMaterial(std::string& out, const ResultSummary& summary);
/// The assumptions and validity limits (docs/model.md) of the models the summary rests on.
void WriteModels(std::string& out, const ResultSummary& summary, const Json& j);

/// The appendix section `appendix` asks for: nothing; the result's scalar values and, when the
/// body showed fewer than all (`body_rows`), every summary row; every value of the result `j`
/// (html_appendix.cpp).
void WriteAppendixSection(std::string& out, ReportAppendix appendix, const ResultSummary& summary, const Json& j,
                          std::size_t body_rows);
/// Every value of `v` as tables (html_appendix.cpp).
void WriteAppendix(std::string& out, const Json& v, const std::string& path);
/// The provenance object: its fields and the input files' SHA-256 (html_appendix.cpp).
void WriteProvenance(std::string& out, const Json& p);

/// A string, or the strings of an array, as a list.
std::vector<std::string> TextList(const Json* v);

}  // namespace covopt::report::internal::html
