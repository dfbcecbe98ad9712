#pragma once
/// @file charts.hpp
/// covopt's charts, drawn by gnuplot, one script per chart: the same script makes the PNG or
/// SVG file of --plot and the inline SVG of a report (html_report.hpp), so each chart has one
/// definition. gnuplot runs as a child process (no shell), once for all the charts asked of it.

#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/scene.hpp"
#include "covopt/audit/audit.hpp"
#include "covopt/optim/design_map.hpp"
#include "covopt/optim/speed_limit.hpp"
#include "covopt/optim/trajectory_check.hpp"
#include "covopt/report/find_on_path.hpp"
#include "covopt/report/html_report.hpp"
#include "covopt/report/simulation_json.hpp"

namespace covopt::chart {

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

/// Who is told of the scratch files DrawCharts makes, e.g. to remove them should a signal end
/// the process (the library installs no signal handler; the CLI registers them with its own).
/// `made(path)` is called right after each scratch path is created (DrawCharts' private
/// directory first, then every file in it) and returns a token; `removed(token)` once that
/// path is gone. Either may be empty.
struct ScratchObserver {
  std::function<int(const std::string& path)> made;
  std::function<void(int token)> removed;
};

/// Draws `charts` in one gnuplot run and returns each file's bytes, in order. gnuplot runs
/// as a child process (no shell, stdin /dev/null, its messages captured) on one script made
/// of every chart's script (the charts separated by `reset session`); the script, the log and
/// the drawn files live in a private temporary directory (mode 0700) that is removed on every
/// path out. No charts: no gnuplot, an empty result.
/// @throws std::runtime_error when gnuplot is missing (kGnuplotMissing) or fails (with its
///         last messages), or draws an empty file (naming the chart's title); as a chart's
///         script throws (std::invalid_argument for a scene the model rejects).
std::vector<std::string> DrawCharts(std::span<const GnuplotChart> charts, ChartFormat format,
                                    const ScratchObserver& observer = {});

/// The charts as SVG for a report (DrawCharts in SVG, with each chart's title and caption).
/// @throws as DrawCharts.
std::vector<report::SvgChart> DrawSvgCharts(std::span<const GnuplotChart> charts,
                                    const ScratchObserver& observer = {});

/// The `set terminal` line: pngcairo or svg (white background), width x height pixels, sans 11.
std::string GnuplotTerminal(ChartFormat format, int width_px, int height_px);

/// A gnuplot single-quoted string (a quote doubled), for titles, labels and file names.
std::string GnuplotQuoted(std::string_view text);

// ---------------------------------------------------------------------------------------
// The charts of the reports and of --plot. Each function computes what its chart shows
// when called (the speed-limit chart's curves, for example); the GnuplotChart it returns
// holds only text and can be drawn in any format, any number of times.

/// `simulate`: force [N] and tensile stress σ_t = σ_c (1 - 2ν_t)/3 [MPa] over time [ms] (two
/// axes, the laceration limit on the stress axis), below them the energy density [J/cm²]
/// with the contusion limit; the limits are report.verdict's criteria, and with its
/// safety factor > 1 the derated limits (limit / factor) are drawn too. 1100 x 900.
/// A result without a history (the exact path's) is drawn from the same scene on the time path
/// (Solve with record_history), and the caption says so with the relative difference of its
/// peak force from the reported one.
/// @throws std::invalid_argument for a scene the model rejects; std::runtime_error when that
///         time-path run fails.
GnuplotChart HistoryChart(const report::SimulationReport& report);

/// The charts of a head simulation's report (`simulate`, with ranges too): HistoryChart, then
/// the working point on the covering's compressive curve when the foam law judged it
/// (FoamWorkingPointChartOf, curve_chart.hpp).
/// @throws as HistoryChart.
std::vector<GnuplotChart> SimulationCharts(const report::SimulationReport& report);

/// What the speed-limit chart draws: the largest safe impact speed over the reflected mass,
/// one curve per covering and one for the bare robot.
struct SpeedLimitChartInput {
  /// One curve per covering: its scene (the robot mass is varied) and its catalog material
  /// (the curve's label; without one, the covering's modulus). A covering of thickness 0 is
  /// the bare robot's curve; without one, the bare robot's curve is the first covering's
  /// scene without covering.
  struct Covering {
    Scene scene;
    std::optional<std::string> material;
  };
  std::vector<Covering> coverings;
  /// The masses of the table's rows [kg] (+inf, a fixed robot, is skipped): the curves span
  /// their finite range at 121 log-spaced masses, or 0.5 .. 200 kg when they span none.
  std::vector<double> masses_kg;
  /// The limits, safety factor and criterion of every curve (optim::MaxSafeSpeed).
  optim::SpeedLimitOptions options;
};

/// `speed-limit`: max safe impact speed [m/s] over the reflected robot mass [kg], log axes
/// (the Safety-Map chart). 1000 x 700.
/// @throws std::invalid_argument as optim::MaxSafeSpeed, or without coverings.
GnuplotChart SpeedLimitChart(const SpeedLimitChartInput& input);

/// What the trajectory chart draws.
struct TrajectoryChartInput {
  optim::TrajectoryCheck check;  ///< optim::CheckTrajectory's answer
  Scene scene;                   ///< the covering and head checked (robot mass and speed unused)
  optim::SpeedLimitOptions limit;  ///< the limits, safety factor and criterion
  std::string trajectory_name;   ///< the trajectory file's name, for the title
  std::string tip_link;          ///< the link the contact point is on
};

/// `robot --trajectory`: the contact point's speed and its max safe speed [m/s] over time
/// [s], the profile scaled by the safe speed scale (dashed), which touches the limit at the
/// worst sample, marked. 1000 x 600.
GnuplotChart TrajectoryChart(const TrajectoryChartInput& input);

/// `audit`: a heat map of the largest ratio per sample and link (result.ratio_over_time,
/// which must be kept), time across, links up, green below the limit 1/safety_factor and
/// red above, the limiting cell marked; the title names `trajectory_name`, the verdict and
/// the limiting link and region. 1100 wide.
GnuplotChart AuditHeatMap(const audit::AuditResult& result, double safety_factor,
                          const std::string& trajectory_name);

/// `optimize`: the design map (optim::DesignMap): the governing ratio over covering thickness
/// [mm] x Young's modulus [MPa] (log axis) as a colour map, green below the limit
/// 1/safety factor and red above, one contour per criterion at its limit (labelled), the
/// chosen design marked and labelled, the catalog candidates marked. 1100 x 800.
GnuplotChart DesignMapChart(const optim::DesignMap& map);

}  // namespace covopt::chart
