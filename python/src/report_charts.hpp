#pragma once
/// @file report_charts.hpp
/// The charts of a Python result's report (result.to_html): the bindings that make a reportable
/// result put a ReportCharts under the dict's private key "_report_charts"; covopt/_results.py
/// takes it off the dict (it never reaches to_dict()) and hands it to html_report. It holds the
/// typed result and draws nothing until to_html asks (covopt/chart/charts.hpp, as the CLI's --report).

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>

#include "covopt/chart/charts.hpp"

namespace covopt::python {

/// The report's charts, made on demand from what the binding captured.
struct ReportCharts {
  std::function<std::vector<chart::GnuplotChart>()> make;
};

/// A trajectory argument's name for a chart title: a path's file name, "<arrays>" for data.
inline std::string TrajectoryName(const pybind11::object& trajectory) {
  if (pybind11::isinstance<pybind11::str>(trajectory) || pybind11::hasattr(trajectory, "__fspath__")) {
    return std::filesystem::path(pybind11::str(trajectory).cast<std::string>()).filename().string();
  }
  return "<arrays>";
}

/// `dict` with `make` under "_report_charts".
inline pybind11::dict WithReportCharts(pybind11::dict dict, std::function<std::vector<chart::GnuplotChart>()> make) {
  dict["_report_charts"] = pybind11::cast(ReportCharts{std::move(make)});
  return dict;
}

}  // namespace covopt::python
