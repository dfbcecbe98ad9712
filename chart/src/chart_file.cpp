#include "covopt/chart/chart_file.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include <fmt/format.h>

#include "covopt/report/output_file.hpp"

namespace covopt::chart {

using report::FindOnPath;
using report::OutputError;
using report::OutputFile;
using report::RegisterTemporaryFile;
using report::UnregisterTemporaryFile;
using report::SimulationReport;

std::optional<ChartFormat> ChartFormatFor(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".png") return ChartFormat::kPng;
  if (extension == ".svg") return ChartFormat::kSvg;
  return std::nullopt;
}

ScratchObserver SignalSafeScratch() {
  return {[](const std::string& path) { return RegisterTemporaryFile(path); },
          [](int slot) { UnregisterTemporaryFile(slot); }};
}

void RunGnuplot(const std::filesystem::path& path, const GnuplotChart& chart) {
  if (!FindOnPath("gnuplot")) throw OutputError(std::string(kGnuplotMissing));
  // The target is checked (and its temporary made) before gnuplot runs, by the one file
  // writer's rules; gnuplot draws into its scratch directory, whose file is then copied in.
  OutputFile file(path);
  GnuplotChart named = chart;
  named.title = path.string();  // gnuplot's errors name the file
  std::vector<std::string> drawn;
  try {
    drawn = DrawCharts({&named, 1}, ChartFormatFor(path).value_or(ChartFormat::kPng), SignalSafeScratch());
  } catch (const std::runtime_error& e) {
    throw OutputError(e.what());
  }
  file.Write(drawn.front());
  file.Commit();
}

void RunGnuplot(const std::filesystem::path& path,
                const std::function<std::string(const std::string& output_path)>& make_script) {
  GnuplotChart chart;
  chart.script = [&make_script](ChartFormat, const std::string& output_path) { return make_script(output_path); };
  RunGnuplot(path, chart);
}

void PlotHistory(const std::filesystem::path& path, const SimulationReport& report) {
  if (report.result.history.empty()) {
    throw OutputError(fmt::format("cannot plot '{}': the result has no history", path.string()));
  }
  RunGnuplot(path, HistoryChart(report));
}

}  // namespace covopt::chart
