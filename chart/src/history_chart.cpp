// The force/stress/energy-density chart of `covopt simulate` (--plot and the report).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/solve.hpp"
#include "covopt/chart/charts.hpp"
#include "covopt/report/scene_headline.hpp"

#include "chart_script.hpp"

namespace covopt::chart {

using report::SceneHeadline;
using report::SceneDetailsBeyondHeadline;
using report::SimulationReport;

namespace {

// The parts of the chart, defined after it.
std::string HistoryTitle(const SimulationReport& report, double laceration_ratio, double contusion_ratio);
std::string HistoryData(const ImpactModel& model, const ImpactResult& r);
std::string MultiplotLayout(const std::string& title, const ImpactResult& r);

/// The chart of a result with its history; `note` ends the caption.
GnuplotChart ChartOfHistory(const SimulationReport& report, const std::string& note) {
  const ImpactResult& r = report.result;
  const ImpactModel model = ImpactModel::FromScene(report.scene);
  // σ_t = σ_c (1 - 2ν_t)/3: the chart shows the stress the laceration limit judges; the
  // axis label gives the factor back to the compressive stress.
  const double tensile_per_compressive = model.TensileFromCompressive(1.0);
  static const Criterion kUnjudged{};  // a report not judged: limits 0, no limit lines drawn
  const Criterion* found_lac = report.verdict.Find("laceration");
  const Criterion* found_con = report.verdict.Find("contusion");
  const Criterion& lac = found_lac ? *found_lac : kUnjudged;
  const Criterion& con = found_con ? *found_con : kUnjudged;
  const std::string blue = "#1f5fa8";
  const std::string red = "#c0392b";
  const std::string green = "#2e8b57";
  std::string s = HistoryData(model, r);
  s += MultiplotLayout(HistoryTitle(report, lac.ratio, con.ratio), r);
  // Every axis reaches about a third past its highest curve or line, so the key sits above
  // them. The force axis has more room than the stress axis so that its peak does not sit on
  // the laceration limit's line.
  constexpr double kHeadroom = 1.3;
  constexpr double kForceHeadroom = 1.5;

  // Top panel.
  s += "set size 1, 0.55\nset origin 0, 0.38\nset tmargin 1\nset bmargin 1\n";
  s += "set format x ''\nunset xlabel\n";
  s += fmt::format("set ylabel 'force [N]' textcolor rgb '{}'\n", blue);
  // Under the foam law σ_t is the radial stress at the contact's edge, no fixed multiple of σ_c.
  s += model.is_foam()
           ? fmt::format("set y2label 'tensile stress σ_t [MPa]' textcolor rgb '{}'\n", red)
           : fmt::format("set y2label 'tensile stress σ_t [MPa]  (compressive σ_c = {:.4g} σ_t)' textcolor rgb '{}'\n",
                         1.0 / tensile_per_compressive, red);
  s += fmt::format("set ytics nomirror textcolor rgb '{}'\n", blue);
  s += fmt::format("set y2tics nomirror textcolor rgb '{}'\n", red);
  s += fmt::format("set yrange [0:{}]\nset y2range [0:{}]\nset border 11\n",
                   kForceHeadroom * r.peaks.peak_force_N,
                   kHeadroom * std::max(r.peaks.max_tensile_stress_Pa, lac.limit) / 1e6);
  // With a safety factor, the derated limit (the one the verdict uses) beside the limit.
  const double sf = report.verdict.safety_factor;
  const auto derated = [&](double limit, std::string_view unit, std::string_view colour,
                           std::string_view axes) {
    if (sf == 1.0) return std::string();
    return fmt::format(
        ", \\\n     {} {} with lines linewidth 1.5 dashtype 3 linecolor rgb '{}' "
        "title 'derated limit {:.4g} {} (limit / safety factor {:g})'",
        limit / sf, axes, colour, limit / sf, unit, sf);
  };
  s += fmt::format(
      "plot $history using 1:2 axes x1y1 with lines linewidth 2 linecolor rgb '{0}' "
      "title 'force [N] (left axis)', \\\n"
      "     $history using 1:3 axes x1y2 with lines linewidth 2 dashtype 2 linecolor rgb '{1}' "
      "title 'tensile stress [MPa] (right axis)', \\\n"
      "     {2} axes x1y2 with lines linewidth 1.5 dashtype 4 linecolor rgb '{1}' "
      "title 'laceration limit {3:g} MPa (tensile)'{4}\n",
      blue, red, lac.limit / 1e6, lac.limit / 1e6, derated(lac.limit / 1e6, "MPa", red, "axes x1y2"));

  // Bottom panel.
  s += "set size 1, 0.38\nset origin 0, 0\nset tmargin 0.5\nset bmargin 3.5\n";
  s += "set format x '% h'\nset xlabel 'time [ms]'\n";
  s += fmt::format("set ylabel 'energy density [J/cm²]' textcolor rgb '{}'\n", green);
  s += fmt::format("set ytics mirror textcolor rgb '{}'\n", green);
  s += fmt::format("unset y2label\nunset y2tics\nset border 15\nset yrange [0:{}]\n",
                   kHeadroom * std::max(r.peaks.max_energy_density_J_per_m2, con.limit) / 1e4);
  s += fmt::format(
      "plot $history using 1:4 with lines linewidth 2 linecolor rgb '{0}' "
      "title 'energy density [J/cm²]', \\\n"
      "     {1} with lines linewidth 1.5 dashtype 4 linecolor rgb '#000000' "
      "title 'contusion limit {2:g} J/cm²'{3}\n",
      green, con.limit / 1e4, con.limit / 1e4, derated(con.limit / 1e4, "J/cm²", "#000000", ""));
  s += "unset multiplot\nunset output\n";
  return internal::MakeChart(
      "Force, stress and energy density over time",
      fmt::format("The impact of {} over time: the contact force [N] and the scalp's tensile stress [MPa] against the "
                  "laceration limit {:g} MPa (Park et al. 2011), and the energy density [J/cm²] against the contusion "
                  "limit {:g} J/cm²{}.",
                  SceneHeadline(report.scene), lac.limit / 1e6, con.limit / 1e4,
                  sf == 1.0 ? std::string() : fmt::format("; dotted: the limits divided by the safety factor {:g}", sf)) +
          note,
      1100, 900, std::move(s));
}

/// The chart's title: the scene, the peaks with their ratios, the method and the samples.
std::string HistoryTitle(const SimulationReport& report, double laceration_ratio, double contusion_ratio) {
  const ImpactResult& r = report.result;
  std::string title = fmt::format("covopt simulate: {}", SceneHeadline(report.scene));
  if (const auto details = SceneDetailsBeyondHeadline(report.scene); !details.empty()) {
    title += fmt::format("; {}", fmt::join(details, ", "));
  }
  title += fmt::format(
      "\npeak force {:.4g} N; max tensile stress {:.4g} MPa (laceration ratio {:.3g}); max "
      "energy density {:.4g} J/cm² (contusion ratio {:.3g})\n{}, {} history samples",
      r.peaks.peak_force_N, r.peaks.max_tensile_stress_Pa / 1e6, laceration_ratio,
      r.peaks.max_energy_density_J_per_m2 / 1e4, contusion_ratio, ToString(r.method),
      r.history.size());
  return title;
}

/// The history as a data block $history: time [ms], force [N], tensile stress [MPa], energy
/// density [J/cm²]; a sample with a non-finite value is left out.
std::string HistoryData(const ImpactModel& model, const ImpactResult& r) {
  std::string s = "$history << EOD\n";
  for (const HistorySample& h : r.history) {
    const double t_ms = h.time_s * 1e3;
    const double tensile_MPa = TensileStressOf(model, h) / 1e6;
    const double energy_density_J_per_cm2 = h.energy_density_J_per_m2 / 1e4;
    if (!std::isfinite(t_ms) || !std::isfinite(h.force_N) || !std::isfinite(tensile_MPa) ||
        !std::isfinite(energy_density_J_per_cm2)) {
      continue;
    }
    s += fmt::format("{} {} {} {}\n", t_ms, h.force_N, tensile_MPa, energy_density_J_per_cm2);
  }
  s += "EOD\n";
  return s;
}

/// Two panels sharing the time axis: force and tensile stress with the laceration limit,
/// then energy density with the contusion limit. Fixed margins keep the time axes aligned
/// and leave room for the two title lines; the key in two rows across the top of each panel;
/// the moment of maximum compression marked.
std::string MultiplotLayout(const std::string& title, const ImpactResult& r) {
  std::string s = fmt::format("set multiplot title {}\n", internal::GnuplotDoubleQuoted(title));
  s += "set lmargin 12\nset rmargin 14\n";
  s += "set xrange [0:*]\nset autoscale xfix\nset xtics nomirror\n";
  s += "set grid xtics ytics linecolor rgb '#dddddd'\n";
  s += "set key inside top center horizontal maxcols 2 width 1 opaque box linecolor rgb "
       "'#cccccc'\n";
  if (r.time_of_max_compression_s && std::isfinite(*r.time_of_max_compression_s)) {
    const double t_ms = *r.time_of_max_compression_s * 1e3;
    s += fmt::format(
        "set arrow 1 from {0}, graph 0 to {0}, graph 1 nohead dashtype 3 linecolor rgb '#777777'\n"
        "set label 1 'max compression' at {0}, graph 0.04 offset 0.5, 0 textcolor rgb '#555555'\n",
        t_ms);
  }
  return s;
}

}  // namespace

GnuplotChart HistoryChart(const SimulationReport& report) {
  if (!report.result.history.empty()) return ChartOfHistory(report, "");
  // The exact path has no history: the same scene on the time path draws it, and the caption
  // says how far its peak force lies from the reported one.
  SolveOptions options;
  options.path = PathChoice::kTimePath;
  options.record_history = true;
  SimulationReport charted = report;
  charted.result = Solve(report.scene, options);
  if (!charted.result.ok() || charted.result.history.empty()) {
    throw std::runtime_error(fmt::format("the force chart's time-path run failed ({}: {})",
                                         ToString(charted.result.method), charted.result.message));
  }
  const double reported_force_N = report.result.peaks.peak_force_N;
  const double relative = std::abs(charted.result.peaks.peak_force_N - reported_force_N) / reported_force_N;
  return ChartOfHistory(
      charted, fmt::format(" The result came from the {} path, which has no time history: the curves are the same "
                           "scene on the time path ({}), whose peak force differs from the reported one by {:.1e} "
                           "(relative).",
                           ToString(report.result.method), ToString(charted.result.method), relative));
}

}  // namespace covopt::chart
