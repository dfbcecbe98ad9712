// The chart of `covopt robot --trajectory` (--plot and the report).
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "covopt/chart/charts.hpp"
#include "covopt/report/scene_headline.hpp"

#include "chart_script.hpp"

namespace covopt::chart {

using report::SceneHeadline;

GnuplotChart TrajectoryChart(const TrajectoryChartInput& input) {
  const optim::TrajectoryCheck& check = input.check;
  const double scale = check.safe_speed_scale;
  const bool scaled = std::isfinite(scale) && scale > 0.0;
  double peak = 0.0;
  for (const optim::SampleVerdict& v : check.samples) {
    peak = std::max(peak, v.speed_m_per_s * (scaled ? std::max(1.0, scale) : 1.0));
  }
  const double top = peak > 0.0 ? 1.5 * peak : 1.0;
  std::string s = "$data << EOD\n";
  for (const optim::SampleVerdict& v : check.samples) {
    // At rest there is no motion, hence no limit along it (the check's is the heaviest direction's).
    const bool none = !v.moving || v.speed_limit.status == optim::SpeedLimitStatus::kNoSafeValue;
    s += fmt::format("{} {} {} {}\n", v.time_s, v.speed_m_per_s,
                     none ? std::string("NaN") : fmt::format("{}", v.speed_limit.max_safe_speed_m_per_s),
                     scaled ? fmt::format("{}", v.speed_m_per_s * scale) : std::string("NaN"));
  }
  s += "EOD\n";
  const std::array<std::string_view, 2> omitted{"robot.mass", "robot.speed"};
  const std::string verdict =
      check.worst_sample ? fmt::format("{}, safe speed scale {:.4g}", optim::ToString(check.status), scale)
                         : std::string(optim::ToString(check.status));
  s += fmt::format(
      "set title {} . \"\\n\" . {}\n",
      GnuplotQuoted(fmt::format("covopt robot --trajectory {} (tip {}): {}",
                                std::filesystem::path(input.trajectory_name).filename().string(), input.tip_link,
                                verdict)),
      GnuplotQuoted(fmt::format("{}; criterion {}{}", SceneHeadline(input.scene, omitted),
                                optim::ToString(input.limit.criterion()),
                                input.limit.safety_factor != 1.0
                                    ? fmt::format(", safety factor {:g}", input.limit.safety_factor)
                                    : std::string())));
  s += "set grid linecolor rgb '#dddddd'\nset key below\nset autoscale xfix\n";
  s += fmt::format("set yrange [0:{}]\n", top);
  s += "set xlabel 'time [s]'\nset ylabel 'speed of the contact point [m/s]'\n";
  s += "plot $data using 1:2 with lines linewidth 2 linecolor rgb '#1f5fa8' title 'speed', "
       "$data using 1:3 with lines linewidth 2 linecolor rgb '#c0392b' title 'max safe speed at the "
       "reflected mass along the motion'";
  if (scaled) {
    s += fmt::format(", $data using 1:4 with lines linewidth 2 dashtype 2 linecolor rgb '#1f5fa8' title {}",
                     GnuplotQuoted(fmt::format("speed x {:.4g} (the safe speed scale)", scale)));
  }
  if (check.worst_sample) {
    const optim::SampleVerdict& w = check.samples[*check.worst_sample];
    s += fmt::format(", '-' using 1:2 with points pointtype 7 pointsize 1.3 linecolor rgb '#000000' title {}",
                     GnuplotQuoted(fmt::format("worst sample ({}, t = {:.4g} s)", *check.worst_sample, w.time_s)));
    s += fmt::format("\n{} {}\ne", w.time_s, w.speed_limit.max_safe_speed_m_per_s);
  }
  s += "\nunset output\n";
  return internal::MakeChart(
      "Speed along the trajectory and its limit",
      fmt::format("The contact point's speed [m/s] over time [s] against the largest safe impact speed at the "
                  "reflected mass along its motion (criterion {}, Park et al. 2011's skin limits{}){}.",
                  optim::ToString(input.limit.criterion()),
                  input.limit.safety_factor != 1.0
                      ? fmt::format(" divided by the safety factor {:g}", input.limit.safety_factor)
                      : std::string(),
                  scaled ? fmt::format("; dashed: the speed scaled by the safe speed scale {:.4g}, which touches the "
                                       "limit at the worst sample",
                                       scale)
                         : std::string()),
      1000, 600, std::move(s));
}

}  // namespace covopt::chart
