// The compressive-curve chart of `covopt materials show NAME --plot`.
#include "covopt/chart/curve_chart.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "covopt/core/impact_model.hpp"

#include "chart_script.hpp"

namespace covopt::chart {

GnuplotChart CompressiveCurveChart(const materials::Material& material) {
  const CompressiveCurve* curve = material.compressive_curve.get();
  if (curve == nullptr) {
    throw std::invalid_argument("material '" + material.name + "' has no compressive curve to draw");
  }
  // The points, from the implied origin: strain [%], stress [kPa], W [kJ/m³].
  std::string s = "$curve << EOD\n0 0 0\n";
  for (const StrainStressPoint& p : curve->points()) {
    s += fmt::format("{:.9g} {:.9g} {:.9g}\n", 100.0 * p.strain, p.stress_Pa / 1e3,
                     curve->EnergyDensityAt(p.strain) / 1e3);
  }
  s += "EOD\n";
  const double end_pct = 100.0 * curve->last_strain();
  const double top_kPa = curve->last_stress_Pa() / 1e3;
  const double band_top = material.stress_at_25_band_Pa ? material.stress_at_25_band_Pa->high / 1e3 : 0.0;
  s += fmt::format("set title {}\n", internal::GnuplotDoubleQuoted(
                                          material.name + ": compressive curve (" + material.curve_rate + ")"));
  s += "set xlabel 'nominal strain [%]'\nset ylabel 'nominal stress σ [kPa]'\n";
  s += "set y2label 'energy density W = ∫σ dε [kJ/m³]'\nset ytics nomirror\nset y2tics nomirror\n";
  s += fmt::format("set xrange [0:{:.6g}]\nset yrange [0:{:.6g}]\nset y2range [0:*]\n",
                   std::min(100.0, end_pct * 1.15 + 1.0), 1.2 * std::max(top_kPa, band_top));
  s += "set grid\nset key top left\n";
  s += fmt::format("set arrow from {0:.6g}, graph 0 to {0:.6g}, graph 1 nohead dashtype 2 linecolor rgb '#555555'\n",
                   end_pct);
  s += fmt::format("set label 'rigid stop past the last point ({:.4g} %)' at {:.6g}, graph 0.95 right offset -1,0\n",
                   end_pct, end_pct);
  std::string extra;
  if (const auto stress = materials::StressAt25Pa(material)) {
    s += fmt::format("$rated << EOD\n25 {:.9g}\nEOD\n", *stress / 1e3);
    extra += fmt::format(", \\\n     $rated using 1:2 with points pointtype 7 pointsize 1.6 "
                         "linecolor rgb '#c0392b' title 'σ(25 %) = {:.4g} kPa'",
                         *stress / 1e3);
  }
  if (material.stress_at_25_band_Pa) {
    const double low = material.stress_at_25_band_Pa->low / 1e3, high = material.stress_at_25_band_Pa->high / 1e3;
    s += fmt::format("$band << EOD\n25 {0:.9g} {1:.9g} {2:.9g}\nEOD\n", 0.5 * (low + high), low, high);
    extra += fmt::format(", \\\n     $band using 1:2:3:4 with yerrorbars linewidth 2 pointtype 1 linecolor rgb "
                         "'#e67e22' title 'grade band at 25 %: {:.4g} to {:.4g} kPa'",
                         low, high);
  }
  s += fmt::format(
      "plot $curve using 1:2 axes x1y1 with linespoints linewidth 2 pointtype 7 pointsize 0.5 linecolor rgb "
      "'#1f5fa8' title {}, \\\n"
      "     $curve using 1:3 axes x1y2 with lines linewidth 1.5 dashtype 2 linecolor rgb '#2e8b57' "
      "title 'W(ε) (right axis)'{}\n",
      internal::GnuplotDoubleQuoted(material.curve_shape.empty() ? "σ(ε), measured points" : "σ(ε), assumed shape"),
      extra);
  s += "unset output\n";
  return internal::MakeChart(
      "Compressive curve", fmt::format("The compressive curve of {} ({} points; source: {}).", material.name,
                                       curve->points().size(), material.curve_source),
      1000, 650, std::move(s));
}

GnuplotChart FoamWorkingPointChart(const CompressiveCurve& curve, const std::string& covering,
                                   std::span<const WorkingPoint> points) {
  if (points.empty()) throw std::invalid_argument("the working-point chart needs at least one point");
  std::string s = "$curve << EOD\n0 0\n";
  for (const StrainStressPoint& p : curve.points()) s += fmt::format("{:.9g} {:.9g}\n", 100.0 * p.strain, p.stress_Pa / 1e3);
  s += "EOD\n$points << EOD\n";
  double worst = 0.0;
  for (const WorkingPoint& p : points) {
    const double strain = std::clamp(p.strain, 0.0, curve.last_strain());
    worst = std::max(worst, strain);
    s += fmt::format("{:.9g} {:.9g} {}\n", 100.0 * strain, curve.StressAt(strain) / 1e3,
                     internal::GnuplotDoubleQuoted(points.size() <= 3 ? p.label : std::string()));
  }
  s += "EOD\n";
  const double end_pct = 100.0 * curve.last_strain();
  s += fmt::format("set title {}\n", internal::GnuplotDoubleQuoted(covering + ": the working point on its compressive curve"));
  s += "set xlabel 'nominal strain of the covering [%]'\nset ylabel 'nominal stress σ [kPa]'\n";
  s += fmt::format("set xrange [0:{:.6g}]\nset yrange [0:{:.6g}]\nset grid\nset key top left\n",
                   std::min(100.0, end_pct * 1.15 + 1.0), 1.2 * curve.last_stress_Pa() / 1e3);
  s += fmt::format("set arrow from {0:.6g}, graph 0 to {0:.6g}, graph 1 nohead dashtype 2 linecolor rgb '#555555'\n",
                   end_pct);
  s += fmt::format("set label 'rigid stop ({:.4g} %)' at {:.6g}, graph 0.95 right offset -1,0\n", end_pct, end_pct);
  s += fmt::format(
      "plot $curve using 1:2 with linespoints linewidth 2 pointtype 7 pointsize 0.5 linecolor rgb '#1f5fa8' "
      "title 'σ(ε)', \\\n     $points using 1:2 with points pointtype 9 pointsize 2 linecolor rgb '#c0392b' "
      "title {}, \\\n     $points using 1:2:3 with labels left offset 1,0 notitle\n",
      internal::GnuplotDoubleQuoted(points.size() == 1 ? "working point (the peak)" : "working points (each peak)"));
  s += "unset output\n";
  return internal::MakeChart(
      "The covering's working point",
      fmt::format("The nominal stress σ [kPa] of {} over its nominal strain [%] (its compressive curve), the {} "
                  "marked: the covering's strain at the peak and σ there ({:.3g} % at most; the rigid stop at "
                  "{:.3g} %).",
                  covering, points.size() == 1 ? "result's working point" : fmt::format("{} contacts' working points", points.size()),
                  100.0 * worst, end_pct),
      1000, 600, std::move(s));
}

std::optional<GnuplotChart> FoamWorkingPointChartOf(const report::SimulationReport& report) {
  const CoveringSpec& covering = report.scene.covering;
  if (!covering.compressive_curve || covering.thickness_m <= 0.0) return std::nullopt;
  if (!ImpactModel::FromScene(report.scene).is_foam()) return std::nullopt;
  const WorkingPoint point{"", report.result.peaks.covering_strain_at_peak};
  return FoamWorkingPointChart(*covering.compressive_curve, report.covering_material.value_or("the covering"), {&point, 1});
}

std::optional<GnuplotChart> FoamWorkingPointChartOf(const BodyContactScene& scene,
                                                    std::span<const optim::BodyRegionJudgement> judged,
                                                    const std::optional<std::string>& material) {
  if (judged.empty() || !scene.covering.compressive_curve || scene.covering.thickness_m <= 0.0) return std::nullopt;
  if (!BodyContactModel::FromScene(scene).foam()) return std::nullopt;
  std::vector<WorkingPoint> points;
  for (const optim::BodyRegionJudgement& j : judged) {
    points.push_back({fmt::format("{} ({})", j.limits.region->name, j.limits.area->name),
                      j.contact.covering_deflection_m / scene.covering.thickness_m});
  }
  return FoamWorkingPointChart(*scene.covering.compressive_curve, material.value_or("the covering"), points);
}

std::vector<GnuplotChart> SimulationCharts(const report::SimulationReport& report) {
  std::vector<GnuplotChart> charts{HistoryChart(report)};
  if (auto foam = FoamWorkingPointChartOf(report)) charts.push_back(std::move(*foam));
  return charts;
}

}  // namespace covopt::chart
