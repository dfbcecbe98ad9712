// The Safety-Map chart of `covopt speed-limit` (--plot and the report).
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "covopt/chart/charts.hpp"
#include "covopt/report/scene_headline.hpp"

#include "chart_script.hpp"

namespace covopt::chart {

using report::SceneHeadline;

GnuplotChart SpeedLimitChart(const SpeedLimitChartInput& input) {
  if (input.coverings.empty()) throw std::invalid_argument("the speed-limit chart needs at least one covering");
  std::vector<double> masses;
  for (const double m : input.masses_kg) {
    if (std::isfinite(m)) masses.push_back(m);
  }
  // 121 log-spaced masses over the rows' finite masses, or 0.5 .. 200 kg.
  const auto [low, high] = std::minmax_element(masses.begin(), masses.end());
  const bool spread = masses.size() >= 2 && *low < *high;
  const double from = spread ? *low : 0.5, to = spread ? *high : 200.0;
  masses.clear();
  for (int i = 0; i <= 120; ++i) masses.push_back(from * std::pow(to / from, i / 120.0));
  struct Curve {
    std::string title;
    Scene scene;
  };
  std::vector<Curve> curves;
  bool bare_listed = false;
  for (const SpeedLimitChartInput::Covering& covering : input.coverings) {
    const Scene& s = covering.scene;
    if (!(s.covering.thickness_m > 0.0)) {
      bare_listed = true;
      curves.push_back({"bare robot", s});
      continue;
    }
    curves.push_back({fmt::format("{} {:g} mm",
                                  covering.material ? *covering.material
                                                    : fmt::format("{:.3g} MPa", s.covering.youngs_modulus_Pa * 1e-6),
                                  s.covering.thickness_m * 1e3),
                      s});
  }
  if (!bare_listed) {
    Scene bare = input.coverings.front().scene;
    bare.covering.thickness_m = 0.0;
    curves.push_back({"bare robot", bare});
  }
  std::string s = "$data << EOD\n";
  for (const Curve& curve : curves) {
    for (const double m : masses) {
      Scene scene = curve.scene;
      scene.robot.mass_kg = m;
      const optim::SpeedLimit limit = optim::MaxSafeSpeed(scene, input.options);
      if (limit.status == optim::SpeedLimitStatus::kNoSafeValue ||
          limit.status == optim::SpeedLimitStatus::kEvaluationFailed) {
        s += fmt::format("{} NaN\n", m);
      } else {
        s += fmt::format("{} {}\n", m, limit.max_safe_speed_m_per_s);
      }
    }
    s += "\n\n";
  }
  s += "EOD\n";
  const std::array<std::string_view, 8> colours{"#1f5fa8", "#c0392b", "#2e8b57", "#8e44ad",
                                                "#d68910", "#17a2b8", "#555555", "#e84393"};
  Scene headline_scene = input.coverings.front().scene;
  const std::array<std::string_view, 4> omitted{"robot.mass", "robot.speed", "covering.thickness", "covering.modulus"};
  const double sf = input.options.safety_factor;
  s += fmt::format(
      "set title \"covopt speed-limit: the largest safe impact speed over the reflected robot mass\\n{}; "
      "limits {:g} MPa, {:g} J/cm²{}; criterion {}\"\n",
      SceneHeadline(headline_scene, omitted), input.options.limits.laceration_tensile_stress_Pa * 1e-6,
      input.options.limits.contusion_energy_density_J_per_m2 * 1e-4,
      sf != 1.0 ? fmt::format(", safety factor {:g}", sf) : std::string(), optim::ToString(input.options.criterion()));
  s += "set logscale xy\nset grid xtics ytics mxtics mytics linecolor rgb '#dddddd'\n";
  s += "set xlabel 'reflected robot mass [kg]'\nset ylabel 'max safe impact speed [m/s]'\n";
  s += "set key outside right top\nset autoscale xfix\n";
  s += "plot ";
  for (std::size_t i = 0; i < curves.size(); ++i) {
    const bool bare = curves[i].title == "bare robot";
    s += fmt::format("$data index {} using 1:2 with lines linewidth 2 {}linecolor rgb '{}' title {}{}", i,
                     bare ? "dashtype 2 " : "", bare ? std::string_view("#000000") : colours[i % colours.size()],
                     GnuplotQuoted(curves[i].title), i + 1 < curves.size() ? ", " : "\n");
  }
  s += "unset output\n";
  return internal::MakeChart(
      "Speed limit over the reflected mass",
      fmt::format("The largest safe impact speed [m/s] over the reflected robot mass [kg] (log axes), one curve per "
                  "covering and one for the bare robot (dashed): below a curve every impact is safe by the criterion "
                  "{} with the skin limits {:g} MPa and {:g} J/cm² (Park et al. 2011){}.",
                  optim::ToString(input.options.criterion()), input.options.limits.laceration_tensile_stress_Pa * 1e-6,
                  input.options.limits.contusion_energy_density_J_per_m2 * 1e-4,
                  sf != 1.0 ? fmt::format(" divided by the safety factor {:g}", sf) : std::string()),
      1000, 700, std::move(s));
}

}  // namespace covopt::chart
