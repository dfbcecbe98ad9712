#pragma once
/// @file charts.hpp
/// covopt's charts, drawn by gnuplot, one script per chart: the same script makes the PNG or
/// SVG file of --plot and the inline SVG of a report (html_report.hpp), so each chart has one
/// definition. gnuplot runs as a child process (no shell), once for all the charts asked of it.

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/report/html_report.hpp"

namespace covopt::report {

/// The file format a chart is drawn in.
enum class ChartFormat { kPng, kSvg };

/// The message when gnuplot is missing (names the Debian package).
inline constexpr std::string_view kGnuplotMissing =
    "gnuplot not found on PATH; install gnuplot-nox (Debian) to draw charts and reports";

/// A chart: its title and caption (for a report), and its gnuplot script. The script sets
/// its own terminal (GnuplotTerminal) and `set output` to `output_path`.
struct GnuplotChart {
  std::string title;
  std::string caption;
  std::function<std::string(ChartFormat format, const std::string& output_path)> script;
};

/// Draws `charts` in one gnuplot run and returns each file's bytes, in order.
/// @throws std::runtime_error when gnuplot is missing (kGnuplotMissing) or fails (with its
///         last messages), or draws an empty file.
std::vector<std::string> DrawCharts(std::span<const GnuplotChart> charts, ChartFormat format);

/// The charts as SVG for a report (DrawCharts in SVG, with each chart's title and caption).
std::vector<SvgChart> DrawSvgCharts(std::span<const GnuplotChart> charts);

/// The `set terminal` line: pngcairo or svg (white background), width x height pixels, sans 11.
std::string GnuplotTerminal(ChartFormat format, int width_px, int height_px);

/// A gnuplot single-quoted string (a quote doubled), for titles, labels and file names.
std::string GnuplotQuoted(std::string_view text);

// The charts of each report kind are declared below them by the charts' owner
// (history, design map, speed limit, trajectory, audit heat map).

}  // namespace covopt::report
