// The body-region charts: bare robot against covered, per region or per criterion; the audit's
// link × region map.
#include "covopt/chart/region_charts.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "covopt/chart/curve_chart.hpp"

#include "chart_script.hpp"

namespace covopt::chart {
namespace {

constexpr std::string_view kCoveredColour = "#1f5fa8";
constexpr std::string_view kBareColour = "#9a9a9a";
constexpr std::string_view kLimitColour = "#c0392b";

/// "chest (sternum)": the region and the area as the tables name them.
std::string RegionLabel(const materials::BodyLimits& limits) {
  return fmt::format("{} ({})", limits.region->name, limits.area->name);
}

/// One data block of the bars: "y x-end 'value'" per finite value, y the bar's centre.
std::string BarBlock(const std::string& name, const std::vector<BareCoveredBar>& bars, bool covered, double offset) {
  std::string block = fmt::format("${} << EOD\n", name);
  for (std::size_t i = 0; i < bars.size(); ++i) {
    const std::optional<double>& value = covered ? bars[i].covered : bars[i].bare;
    if (!value || !std::isfinite(*value)) continue;
    const double y = static_cast<double>(bars.size() - 1 - i) + offset;
    block += fmt::format("{} {} \"{:.3g}\"\n", y, *value, *value);
  }
  return block + "EOD\n";
}

}  // namespace

GnuplotChart BareCoveredBarChart(const BareCoveredBars& bars, std::string title, std::string caption) {
  if (bars.bars.empty()) throw std::invalid_argument("a bar chart needs at least one bar");
  double largest = bars.limit.value_or(0.0);
  bool any_covered = false;
  for (const BareCoveredBar& bar : bars.bars) {
    for (const std::optional<double>& v : {bar.bare, bar.covered}) {
      if (v && std::isfinite(*v)) largest = std::max(largest, *v);
    }
    any_covered = any_covered || (bar.covered && std::isfinite(*bar.covered));
  }
  if (!(largest > 0.0)) largest = 1.0;
  const std::size_t n = bars.bars.size();
  std::string s = fmt::format("set title {}\n", internal::GnuplotDoubleQuoted(bars.title));
  s += BarBlock("covered", bars.bars, true, 0.18) + BarBlock("bare", bars.bars, false, -0.18);
  s += fmt::format("set xlabel {}\nset xrange [0:{}]\n", GnuplotQuoted(bars.value_label), 1.18 * largest);
  s += fmt::format("set yrange [-0.6:{}]\nset ytics (", static_cast<double>(n) - 0.4);
  for (std::size_t i = 0; i < n; ++i) {
    s += fmt::format("{}{} {}", i ? ", " : "", GnuplotQuoted(bars.bars[i].label), n - 1 - i);
  }
  s += ") nomirror\nset grid xtics\nset key below horizontal\nset style fill solid 0.85 noborder\n";
  std::string plot = "plot ";
  if (any_covered) {
    plot += fmt::format("$covered using ($2/2):1:(0):2:($1-0.16):($1+0.16) with boxxyerror linecolor rgb '{}' "
                        "title 'covered', $covered using 2:1:3 with labels left offset 0.5,0 notitle, ",
                        kCoveredColour);
  }
  plot += fmt::format("$bare using ($2/2):1:(0):2:($1-0.16):($1+0.16) with boxxyerror linecolor rgb '{}' "
                      "title 'bare robot', $bare using 2:1:3 with labels left offset 0.5,0 notitle",
                      kBareColour);
  if (bars.limit) {
    s += fmt::format("set arrow from {0}, graph 0 to {0}, graph 1 nohead dashtype 2 linewidth 2 linecolor rgb '{1}'\n",
                     *bars.limit, kLimitColour);
    plot += fmt::format(", NaN with lines dashtype 2 linewidth 2 linecolor rgb '{}' title {}", kLimitColour,
                        GnuplotQuoted(bars.limit_label));
  }
  s += plot + "\nunset output\n";
  return internal::MakeChart(std::move(title), std::move(caption), 1000,
                             170 + 30 * static_cast<int>(std::max<std::size_t>(n, 3)), std::move(s));
}

GnuplotChart BodyRegionRatioChart(std::span<const optim::BodyRegionJudgement> covered,
                                  std::span<const std::optional<optim::BodyRegionJudgement>> bare, double safety_factor,
                                  const std::string& note) {
  const std::size_t n = covered.empty() ? bare.size() : covered.size();
  if (n == 0 || (!covered.empty() && bare.size() != covered.size())) {
    throw std::invalid_argument("the body-region chart needs one bare judgement per covered one, and at least one");
  }
  const auto limits_of = [&](std::size_t i) -> const materials::BodyLimits& {
    return covered.empty() ? bare[i]->limits : covered[i].limits;
  };
  const auto covered_at = [&](std::size_t i) -> const optim::BodyRegionJudgement* {
    return covered.empty() ? nullptr : &covered[i];
  };
  BareCoveredBars bars;
  bars.limit = 1.0 / safety_factor;
  bars.limit_label = fmt::format("limit 1/SF = {:.3g}", 1.0 / safety_factor);
  if (n == 1) {
    const materials::BodyLimits& limits = limits_of(0);
    const optim::BodyRegionJudgement* c = covered_at(0);
    const std::optional<optim::BodyRegionJudgement>& b = bare[0];
    bars.title = fmt::format("{}, {} contact: force and pressure ratios", RegionLabel(limits), ToString(limits.contact));
    bars.value_label = "ratio to the ISO/TS 15066 limit [-] (F/F_lim, p/p_lim)";
    bars.bars.push_back({fmt::format("force (limit {:.0f} N)", limits.force_N),
                         b ? std::optional(b->force_ratio) : std::nullopt,
                         c ? std::optional(c->force_ratio) : std::nullopt});
    bars.bars.push_back({fmt::format("pressure (limit {:.0f} N/cm²)", limits.pressure_Pa * 1e-4),
                         b ? b->pressure_ratio : std::nullopt, c ? c->pressure_ratio : std::nullopt});
  } else {
    bars.title = fmt::format("{} regions: the governing ratio, bare robot{}", n, covered.empty() ? "" : " and covered");
    bars.value_label = "governing ratio to the ISO/TS 15066 limits [-] (the larger of F/F_lim and p/p_lim)";
    for (std::size_t i = 0; i < n; ++i) {
      const optim::BodyRegionJudgement* c = covered_at(i);
      bars.bars.push_back({RegionLabel(limits_of(i)), bare[i] ? std::optional(bare[i]->governing_ratio) : std::nullopt,
                           c ? std::optional(c->governing_ratio) : std::nullopt});
    }
  }
  std::string caption = fmt::format(
      "{} [-] of each {} to its ISO/TS 15066 limit{}; safe where safety factor x ratio <= 1 "
      "(dashed line at 1/SF = {:.3g}).",
      n == 1 ? "The force and pressure ratios" : "The governing ratio", n == 1 ? "criterion" : "region",
      covered.empty() ? ", bare robot" : ", covered (blue) and bare robot (grey)", 1.0 / safety_factor);
  if (!note.empty()) caption += " " + note;
  return BareCoveredBarChart(bars, n == 1 ? "Body region: bare robot and covered" : "Body regions: bare robot and covered",
                             std::move(caption));
}

GnuplotChart BodyRegionRatioChart(const BodyContactScene& scene, std::span<const optim::BodyRegionJudgement> judged,
                                  const optim::BodyRegionOptions& options) {
  const double sf = options.rule.safety_factor;
  std::vector<std::optional<optim::BodyRegionJudgement>> bare;
  if (scene.covering.thickness_m <= 0.0) {  // the bare robot is what was judged
    for (const optim::BodyRegionJudgement& j : judged) bare.emplace_back(j);
    return BodyRegionRatioChart({}, bare, sf, "");
  }
  BodyContactScene bare_scene = scene;
  bare_scene.covering.thickness_m = 0.0;
  std::string note;
  if (optim::BareRobotLacksContactArea(bare_scene)) {
    bare.resize(judged.size());
    note = "The bare robot is not drawn: without a contact area its pressure is not evaluated.";
  } else {
    std::size_t refused = 0;
    for (const optim::BodyRegionJudgement& j : judged) {
      try {
        bare.emplace_back(optim::JudgeBodyContact(bare_scene, j.limits, options));
      } catch (const std::invalid_argument&) {
        ++refused;
        bare.emplace_back();
      }
    }
    if (refused > 0) note = fmt::format("The bare robot is not drawn for {} region(s) the model refuses.", refused);
  }
  return BodyRegionRatioChart(judged, bare, sf, note);
}

std::vector<GnuplotChart> BodyRegionSimulationCharts(const BodyContactScene& scene,
                                                     std::span<const optim::BodyRegionJudgement> judged,
                                                     const optim::BodyRegionOptions& options,
                                                     const std::optional<std::string>& material) {
  if (judged.empty()) return {};
  std::vector<GnuplotChart> charts{BodyRegionRatioChart(scene, judged, options)};
  if (auto foam = FoamWorkingPointChartOf(scene, judged, material)) charts.push_back(std::move(*foam));
  return charts;
}

std::vector<GnuplotChart> BodyRegionDesignCharts(const optim::BodyRegionDesignRequest& request,
                                                 const optim::BodyRegionDesignResult& result) {
  if (request.regions.empty() || result.bare_robot.size() != request.regions.size()) return {};  // the head alone
  const std::vector<std::optional<optim::BodyRegionJudgement>> bare(result.bare_robot.begin(), result.bare_robot.end());
  const optim::BodyRegionDesignCandidate* shown =
      result.recommendation ? &result.candidates[*result.recommendation]
                            : (result.candidates.empty() ? nullptr : &result.candidates.front());
  std::span<const optim::BodyRegionJudgement> covered;
  std::string note;
  if (shown != nullptr && shown->regions.size() == bare.size()) {
    covered = shown->regions;
    note = shown->thickness_m
               ? fmt::format("Covered: {} at {:.4g} mm.", shown->material.name, *shown->thickness_m * 1e3)
               : fmt::format("No covering is admissible; covered: the best, {} at the thickest scanned.",
                             shown->material.name);
  }
  BodyContactScene bare_scene = request.scene;
  bare_scene.covering.thickness_m = 0.0;
  if (optim::BareRobotLacksContactArea(bare_scene)) {
    note += " Without a contact area the bare robot's pressure is not evaluated: its bars are the force's.";
  }
  return {BodyRegionRatioChart(covered, bare, request.rule.safety_factor, note)};
}

GnuplotChart BodyRegionSpeedChart(std::span<const report::BodyRegionTableRow> rows) {
  if (rows.empty()) throw std::invalid_argument("the body-region speed chart needs at least one row");
  const bool several_masses = std::any_of(rows.begin(), rows.end(), [&](const report::BodyRegionTableRow& r) {
    return r.robot_mass_kg != rows.front().robot_mass_kg;
  });
  const bool several_materials = std::any_of(rows.begin(), rows.end(), [&](const report::BodyRegionTableRow& r) {
    return r.material != rows.front().material;
  });
  BareCoveredBars bars;
  bool any_covering = false;
  for (const report::BodyRegionTableRow& row : rows) {
    std::string label = row.area.empty() ? row.region : fmt::format("{} ({})", row.region, row.area);
    if (several_masses) {
      label += std::isfinite(row.robot_mass_kg) ? fmt::format(", {:g} kg", row.robot_mass_kg) : ", fixed";
    }
    if (several_materials && !row.material.empty()) label += ", " + row.material;
    bars.bars.push_back({std::move(label), row.bare_max_speed_m_per_s,
                         row.has_covering ? row.covered_max_speed_m_per_s : std::nullopt});
    any_covering = any_covering || row.has_covering;
  }
  bars.title = fmt::format("The largest safe speed per {}", several_masses ? "region and mass" : "region");
  bars.value_label = "largest safe impact speed [m/s]";
  return BareCoveredBarChart(
      bars, "Safe speed per body region",
      fmt::format("The largest safe impact speed [m/s] of each row of the table{}; a row with no safe speed has "
                  "no bar. Each is limited by its region's ISO/TS 15066 force and pressure limits with the "
                  "safety factor.",
                  any_covering ? ", covered (blue) and bare robot (grey)" : ", bare robot"));
}

std::vector<GnuplotChart> BodyRegionTrajectoryCharts(const optim::BodyRegionTrajectoryCheck& check,
                                                     std::span<const materials::BodyLimits> regions,
                                                     double safety_factor) {
  if (check.samples.empty() || regions.empty()) return {};
  const double bound = 1.0 / safety_factor;
  std::string s = fmt::format("set title {}\n", GnuplotQuoted(fmt::format(
                                                     "the largest governing ratio over the {} regions at each sample "
                                                     "(safe: ratio <= 1/SF = {:.3g})",
                                                     regions.size(), bound)));
  s += "$ratio << EOD\n";
  for (const optim::BodyRegionSampleVerdict& v : check.samples) {
    s += fmt::format("{} {}\n", v.time_s, v.moving && std::isfinite(v.worst_ratio) ? fmt::format("{}", v.worst_ratio) : "0");
  }
  s += "EOD\nset xlabel 'time [s]'\nset ylabel 'governing ratio [-]'\nset grid\nset key below horizontal\n";
  s += "set yrange [0:*]\n";
  std::string plot = fmt::format(
      "plot $ratio using 1:2 with lines linewidth 2 linecolor rgb '{}' title 'largest ratio over the regions', "
      "{:g} with lines dashtype 2 linewidth 2 linecolor rgb '{}' title 'limit 1/SF = {:.3g}'",
      kCoveredColour, bound, kLimitColour, bound);
  if (check.worst_sample && *check.worst_sample < check.samples.size()) {
    const optim::BodyRegionSampleVerdict& w = check.samples[*check.worst_sample];
    const std::string where = w.worst_region < regions.size() ? RegionLabel(regions[w.worst_region]) : std::string();
    plot += fmt::format(", '-' using 1:2 with points pointtype 6 pointsize 2 linewidth 2 linecolor rgb '#000000' "
                        "title {}\n{} {}\ne",
                        GnuplotQuoted(fmt::format("sets the scale: t = {:.4g} s, {}", w.time_s, where)), w.time_s,
                        w.worst_ratio);
  }
  s += plot + "\nunset output\n";
  return {internal::MakeChart(
      "Ratio over the motion",
      fmt::format("The largest governing ratio [-] over the {} body regions judged at each sample of the motion, "
                  "over time [s] (0 at rest); safe where safety factor x ratio <= 1 (dashed at 1/SF = {:.3g}).",
                  regions.size(), bound),
      1000, 600, std::move(s))};
}

GnuplotChart AuditRegionMap(const audit::AuditResult& result, double safety_factor) {
  const std::size_t links = result.links.size();
  const std::size_t regions = result.regions.size();
  const double at_limit = 1.0 / safety_factor;
  std::string s = fmt::format("set title {}\n", GnuplotQuoted(fmt::format(
                                                    "governing ratio per link and region, worst over the motion "
                                                    "(safe: ratio <= 1/SF = {:.3g})",
                                                    at_limit)));
  std::string map = "$region_map << EOD\n";
  // The values written in the cells: white on the dark ends of the scale, black between.
  std::string dark = "$region_dark << EOD\n";
  std::string light = "$region_light << EOD\n";
  std::size_t dark_count = 0;
  std::size_t light_count = 0;
  for (std::size_t l = 0; l < links; ++l) {
    for (std::size_t r = 0; r < regions; ++r) {
      const double ratio = result.cell(l, r).governing_ratio;
      // +inf (no speed is safe) is drawn at the top of the scale and written "inf".
      const double shown = std::isfinite(ratio) ? ratio : 2.0 * at_limit;
      map += fmt::format("{} {} {}\n", r, l, shown);
      const bool on_dark = shown >= 1.4 * at_limit || shown <= 0.3 * at_limit;
      (on_dark ? dark : light) +=
          fmt::format("{} {} \"{}\"\n", r, l, std::isfinite(ratio) ? fmt::format("{:.2f}", ratio) : "inf");
      ++(on_dark ? dark_count : light_count);
    }
    map += "\n";
  }
  s += map + "EOD\n" + dark + "EOD\n" + light + "EOD\n";
  s += fmt::format("set cbrange [0:{}]\n", 2.0 * at_limit);
  s += "set palette defined (0 '#1a7f3c', 0.5 '#8fd18b', 0.98 '#f4f1bb', 1.02 '#fdd49e', 1.5 '#f0793d', 2 '#a50f15')\n";
  s += "set cblabel 'governing ratio [-] (limit 1/SF at the middle)'\n";
  s += "set xlabel 'body region'\nset ylabel 'link'\n";
  s += fmt::format("set xrange [-0.5:{}]\nset yrange [-0.5:{}]\n", static_cast<double>(regions) - 0.5,
                   static_cast<double>(links) - 0.5);
  s += "set xtics rotate by 40 right (";
  for (std::size_t r = 0; r < regions; ++r) s += fmt::format("{}{} {}", r ? ", " : "", GnuplotQuoted(result.regions[r]), r);
  s += ")\nset ytics (";
  for (std::size_t l = 0; l < links; ++l) s += fmt::format("{}{} {}", l ? ", " : "", GnuplotQuoted(result.links[l]), l);
  s += ")\nunset key\nset bmargin 12\n";
  // Each cell a filled box (an image one cell wide, one region or one link, has no pixel size),
  // and a block of labels only when it has one: gnuplot 5.4 crashes (signal 11) on labels from a
  // block without a valid point.
  s += "plot $region_map using 1:2:(0.5):(0.5):3 with boxxyerror fillstyle solid 1.0 noborder lc palette notitle";
  if (dark_count > 0) s += ", $region_dark using 1:2:3 with labels font 'sans,10' textcolor rgb '#ffffff' notitle";
  if (light_count > 0) s += ", $region_light using 1:2:3 with labels font 'sans,10' textcolor rgb '#000000' notitle";
  s += "\nunset output\n";
  return internal::MakeChart(
      "Governing ratio per link and region",
      fmt::format("The governing ratio [-] of each link (rows) against each of the {} regions judged (columns), the "
                  "worst over the motion's samples and the link's surface points, written in the cell; green below "
                  "the limit 1/safety factor = {:.3g}, red above (\"inf\": no speed is safe).",
                  regions, at_limit),
      1100, 330 + 34 * static_cast<int>(std::max<std::size_t>(links, 3)), std::move(s));
}

}  // namespace covopt::chart
