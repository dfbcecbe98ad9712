/// @file report_bindings.cpp
/// The provenance block and input sources of every Python result and the report of
/// result.to_html() and result.to_pdf(): all from covopt::report (provenance.hpp,
/// input_sources.hpp, html_report.hpp, report_settings.hpp, pdf_print.hpp), the CLI's own.
/// covopt/_provenance.py makes the command ("covopt.optimize(materials=['PORON XRD 15 pcf'])")
/// and names the input files and keywords; this only calls the library.

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "covopt/chart/charts.hpp"
#include "covopt/report/html_report.hpp"
#include "covopt/report/input_sources.hpp"
#include "covopt/report/pdf_print.hpp"
#include "covopt/report/provenance.hpp"
#include "covopt/report/summary_json.hpp"
#include "covopt/report/report_settings.hpp"
#include "covopt/scene_file/fields.hpp"
#include "covopt/scene_file/spelling.hpp"
#include "covopt/scene_file/scene_inputs.hpp"
#include "report_charts.hpp"
#include "scene_keywords.hpp"

namespace py = pybind11;

namespace covopt::python {
namespace {

/// report::MakeProvenance as a dict: `inputs` are (role, path) pairs.
py::object Provenance(std::string command, const std::vector<std::pair<std::string, std::string>>& inputs) {
  std::vector<report::InputFile> files;
  for (const auto& [role, path] : inputs) files.push_back({role, path});
  return JsonToPython(report::ProvenanceJson(report::MakeProvenance(std::move(command), files), -1));
}

/// report::InputSourcesJson as a dict: the scene keywords the call was given (robot_mass, ...;
/// material sets the covering's modulus and Poisson ratio from the catalog).
py::object InputSources(const std::string& result_json, const std::vector<std::string>& keywords) {
  report::InputOrigins origins;
  const auto spellings = scene_file::SceneInputSpellings(scene_file::ValueStyle::kKeyword);
  for (const std::string& keyword : keywords) {
    for (const scene_file::FieldSpelling& spelling : spellings) {
      if (spelling.name == keyword) origins.given[std::string(spelling.field)] = "keyword " + keyword;
    }
    if (keyword == "material") origins.from_catalog = {"covering.modulus", "covering.poisson"};
  }
  return JsonToPython(report::InputSourcesJson(result_json, origins, -1));
}

/// report_info (a dict, or None) as the report's settings, each named "report_info['key']".
/// @throws std::invalid_argument naming every unknown key, or a value the report refuses.
report::ReportInfo ReportInfoOf(const py::object& report_info) {
  report::ReportInfo info;
  if (report_info.is_none()) return info;
  if (!py::isinstance<py::dict>(report_info)) {
    throw std::invalid_argument("report_info must be a dict with keys project, cell, assessor, note, "
                                "margin_threshold, appendix (got " + py::repr(report_info).cast<std::string>() + ")");
  }
  const auto keys = scene_file::ReportKeys();
  std::vector<scene_file::ReportSetting> settings;
  std::string unknown;
  for (const auto& [key, value] : report_info.cast<py::dict>()) {
    const std::string name = py::str(key).cast<std::string>();
    const std::string shown = "report_info[" + py::repr(key).cast<std::string>() + "]";
    if (!py::isinstance<py::str>(key) || std::find(keys.begin(), keys.end(), name) == keys.end()) {
      unknown += (unknown.empty() ? "" : ", ") + py::repr(key).cast<std::string>();
    } else if (py::isinstance<py::str>(value)) {
      settings.push_back({name, value.cast<std::string>(), shown});
    } else if ((py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value)) && !py::isinstance<py::bool_>(value)) {
      settings.push_back({name, value.cast<double>(), shown});
    } else if (!value.is_none()) {
      throw std::invalid_argument(shown + ": expected a str" + (name == "margin_threshold" ? " or a number" : "") +
                                  " (got " + py::repr(value).cast<std::string>() + ")");
    }
  }
  if (!unknown.empty()) {
    throw std::invalid_argument("report_info: unknown key(s) " + unknown +
                                "; the keys are project, cell, assessor, note, margin_threshold, appendix");
  }
  report::ApplyReportSettings(settings, info);
  return info;
}

/// The kind called `kind` (report::ToString(ReportKind)).
report::ReportKind KindOf(const std::string& kind) {
  constexpr std::array kKinds{report::ReportKind::kSimulate, report::ReportKind::kOptimize,
                              report::ReportKind::kSpeedLimit, report::ReportKind::kTrajectory,
                              report::ReportKind::kAudit, report::ReportKind::kRetime,
                              report::ReportKind::kMeasure};
  for (const report::ReportKind k : kKinds) {
    if (report::ToString(k) == kind) return k;
  }
  throw std::invalid_argument("html_report: no report of kind '" + kind + "'");
}

/// report::HtmlReport of a result's JSON text; `kind` is report::ToString(ReportKind).
/// `charts` (a ReportCharts, or None) are drawn by one gnuplot run; `report_info` a dict of the
/// sign-off settings, or None.
std::string HtmlReport(const std::string& kind, const std::string& result_json, const py::object& charts,
                       const py::object& report_info) {
  const report::ReportKind k = KindOf(kind);
  report::ReportInfo info = ReportInfoOf(report_info);
  const ReportCharts* maker = charts.is_none() ? nullptr : &charts.cast<const ReportCharts&>();
  py::gil_scoped_release release;
  std::vector<report::SvgChart> drawn;
  if (maker != nullptr && maker->make) {
    const std::vector<chart::GnuplotChart> gnuplot = maker->make();
    drawn = chart::DrawSvgCharts(gnuplot);
  }
  return report::HtmlReport({k, result_json, std::move(drawn), std::move(info)});
}

/// HtmlReport printed to the PDF file `path` by the library (report::WriteReportPdf: a headless
/// Chromium, $COVOPT_CHROMIUM_TIMEOUT as the CLI reads it).
void PdfReport(const std::string& kind, const std::string& result_json, const py::object& charts,
               const py::object& report_info, const std::string& path) {
  const std::string html = HtmlReport(kind, result_json, charts, report_info);
  const auto timeout = report::ChromiumTimeout();
  py::gil_scoped_release release;
  report::WriteReportPdf(path, html, timeout);
}

}  // namespace

void BindReport(py::module_& m) {
  m.def("provenance", &Provenance, py::arg("command"), py::arg("inputs"));
  py::class_<ReportCharts>(m, "_ReportCharts", "The charts of a result's report, drawn when to_html asks.");
  m.def("html_report", &HtmlReport, py::arg("kind"), py::arg("result_json"), py::arg("charts") = py::none(),
        py::arg("report_info") = py::none());
  m.def("pdf_report", &PdfReport, py::arg("kind"), py::arg("result_json"), py::arg("charts"), py::arg("report_info"),
        py::arg("path"));
  m.def("input_sources", &InputSources, py::arg("result_json"), py::arg("keywords"));
  // The result summary of a result's JSON text, as the CLI prints it (report::SummaryText), and
  // its first line (Python's repr); ValueError when the result has no "summary".
  m.def("summary_text", [](const std::string& result_json) {
    return report::SummaryText(report::SummaryFromJson(result_json));
  }, py::arg("result_json"));
  m.def("summary_headline", [](const std::string& result_json) {
    return report::SummaryHeadline(report::SummaryFromJson(result_json));
  }, py::arg("result_json"));
}

}  // namespace covopt::python
