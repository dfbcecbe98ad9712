#pragma once
/// @file plot.hpp
/// The force/stress/energy-density chart of `covopt simulate --plot`, drawn by gnuplot.
///
/// The history goes into a gnuplot script as an inline data block; gnuplot runs as a child
/// process (no shell) with its output captured, writes to a temporary file next to the
/// target, which is then renamed over it. PNG uses the pngcairo terminal (gnuplot-nox has
/// it), SVG the svg terminal.

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "output.hpp"

namespace covopt::cli {

enum class PlotFormat { kPng, kSvg };

/// The format for a file name's extension (.png or .svg, any case); empty otherwise.
std::optional<PlotFormat> PlotFormatFor(const std::filesystem::path& path);

/// The first executable file called `name` in the directories of $PATH.
std::optional<std::filesystem::path> FindOnPath(std::string_view name);

/// The message when gnuplot is missing.
inline constexpr std::string_view kGnuplotMissing =
    "gnuplot not found on PATH; install gnuplot-nox or drop --plot";

/// The gnuplot script of `simulate --plot`, two panels against time [ms] from
/// report.result.history, into `output_path`: force [N] (left axis) and tensile stress
/// σ_t = σ_c (1 - 2ν_t)/3 [MPa] (right axis, labelled with the factor back to the
/// compressive stress) with the laceration limit as a line on the tensile axis; below,
/// energy density [J/cm²] with the contusion limit. The limits are report.assessment's;
/// with report.safety_factor > 1 the derated limits (limit / factor) are drawn too.
/// @throws std::invalid_argument for a scene the model rejects.
std::string GnuplotScript(const SimulationReport& report, PlotFormat format,
                          const std::string& output_path);

/// Runs the gnuplot script `make_script(temporary_output)` and renames the temporary
/// output (next to `path`) over `path` once gnuplot has drawn it: any chart, atomically.
/// @throws OutputError when gnuplot is missing or fails (with its messages), or the file
///         cannot be written.
void RunGnuplot(const std::filesystem::path& path,
                const std::function<std::string(const std::string& output_path)>& make_script);

/// The `set terminal` line of a chart: pngcairo or svg (white background), `width` x
/// `height` pixels, sans 11, no enhanced text.
std::string GnuplotTerminal(PlotFormat format, int width, int height);

/// A gnuplot single-quoted string (a quote doubled), for titles, labels and file names.
std::string GnuplotQuoted(std::string_view text);

/// Draws the chart into `path`.
/// @throws OutputError when gnuplot is missing or fails (with its messages), or the file
///         cannot be written.
void PlotHistory(const std::filesystem::path& path, const SimulationReport& report,
                 PlotFormat format);

}  // namespace covopt::cli
