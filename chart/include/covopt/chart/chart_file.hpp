#pragma once
/// @file chart_file.hpp
/// A chart (charts.hpp, drawn by gnuplot) written to its file by the one file writer
/// (OutputFile, atomically), with gnuplot's scratch files registered for removal should Ctrl-C
/// end the process (RegisterTemporaryFile): the CLI's --plot. PNG uses the pngcairo terminal
/// (gnuplot-nox has it), SVG the svg terminal.

#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "covopt/chart/charts.hpp"
#include "covopt/report/simulation_json.hpp"

namespace covopt::chart {

/// The format for a file name's extension (.png or .svg, any case); empty otherwise.
std::optional<ChartFormat> ChartFormatFor(const std::filesystem::path& path);

/// The observer that registers gnuplot's scratch files and directory with the signal
/// handlers of the file writer (RegisterTemporaryFile), so an interrupted chart leaves nothing behind.
ScratchObserver SignalSafeScratch();

/// Draws `chart` in the format of `path`'s extension (PNG unless .svg) and writes it to
/// `path` by OutputFile's rules (checked before gnuplot runs; replaced atomically).
/// @throws OutputError when gnuplot is missing or fails (with its messages), or the file
///         cannot be written.
void RunGnuplot(const std::filesystem::path& path, const GnuplotChart& chart);

/// RunGnuplot for a script made here: `make_script(output_path)` sets its own terminal and
/// `set output` to output_path.
void RunGnuplot(const std::filesystem::path& path,
                const std::function<std::string(const std::string& output_path)>& make_script);

/// The chart of `simulate --plot` (HistoryChart) into `path`.
/// @throws OutputError when the report has no history, gnuplot is missing or fails, or the
///         file cannot be written.
void PlotHistory(const std::filesystem::path& path, const report::SimulationReport& report);

}  // namespace covopt::chart
