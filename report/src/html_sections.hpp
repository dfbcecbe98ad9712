#pragma once
/// @file html_sections.hpp
/// The HTML report's sections (private to covopt_report): its style sheet, tables, inputs,
/// verdicts, materials, the models' assumptions, the appendix and the provenance.

#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "html_assessment.hpp"
#include "html_text.hpp"

namespace covopt::report::internal::html {

/// The report's style sheet (A4 print and screen).
extern const std::string_view kCss;

/// Opens a table with its columns (name, width in %) and its body.
void OpenTable(std::string& out, std::initializer_list<std::pair<std::string_view, int>> columns,
               std::string_view cls = "");
void Cell(std::string& out, std::string_view text, std::string_view cls = "");

/// The inputs: every leaf under the result's `keys`, SI as in the JSON and read in display units.
void WriteInputs(std::string& out, const Json& j, const std::vector<std::string>& keys);
/// The verdict rows of `a`.
void WriteVerdicts(std::string& out, const Assessment& a);
/// The datasheet of each catalog material the result uses.
void WriteMaterials(std::string& out, const Json& j);
/// The assumptions and validity limits (docs/model.md) of the models `a` rests on.
void WriteModels(std::string& out, const Assessment& a);

/// Every value of `v` as tables (html_appendix.cpp).
void WriteAppendix(std::string& out, const Json& v, const std::string& path);
/// The provenance object: its fields and the input files' SHA-256 (html_appendix.cpp).
void WriteProvenance(std::string& out, const Json& p);

/// A string, the strings of an array, or an object's description, as a list.
std::vector<std::string> TextList(const Json* v);

}  // namespace covopt::report::internal::html
