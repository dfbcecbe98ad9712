// The compressive-curve chart of `covopt materials show NAME --plot`.
#include "covopt/chart/curve_chart.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

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

}  // namespace covopt::chart
