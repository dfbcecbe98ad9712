/// @file report_bindings.cpp
/// The provenance block of every Python result and the HTML report of result.to_html(): both
/// from covopt::report (provenance.hpp, html_report.hpp), the CLI's own. covopt/_provenance.py
/// makes the command ("covopt.optimize(materials=['PORON XRD 15 pcf'])") and names the input
/// files; this only calls the library.

#include <array>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "covopt/report/charts.hpp"
#include "covopt/report/html_report.hpp"
#include "covopt/report/provenance.hpp"
#include "covopt/report/summary_json.hpp"
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

/// report::HtmlReport of a result's JSON text; `kind` is report::ToString(ReportKind).
/// `charts` (a ReportCharts, or None) are drawn by one gnuplot run.
std::string HtmlReport(const std::string& kind, const std::string& result_json, const py::object& charts) {
  constexpr std::array kKinds{report::ReportKind::kSimulate, report::ReportKind::kOptimize,
                              report::ReportKind::kSpeedLimit, report::ReportKind::kTrajectory,
                              report::ReportKind::kAudit};
  for (const report::ReportKind k : kKinds) {
    if (report::ToString(k) == kind) {
      const ReportCharts* maker = charts.is_none() ? nullptr : &charts.cast<const ReportCharts&>();
      py::gil_scoped_release release;
      std::vector<report::SvgChart> drawn;
      if (maker != nullptr && maker->make) {
        const std::vector<report::GnuplotChart> gnuplot = maker->make();
        drawn = report::DrawSvgCharts(gnuplot);
      }
      return report::HtmlReport({k, result_json, std::move(drawn), {}});
    }
  }
  throw std::invalid_argument("html_report: no report of kind '" + kind + "'");
}

}  // namespace

void BindReport(py::module_& m) {
  m.def("provenance", &Provenance, py::arg("command"), py::arg("inputs"));
  py::class_<ReportCharts>(m, "_ReportCharts", "The charts of a result's report, drawn when to_html asks.");
  m.def("html_report", &HtmlReport, py::arg("kind"), py::arg("result_json"), py::arg("charts") = py::none());
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
