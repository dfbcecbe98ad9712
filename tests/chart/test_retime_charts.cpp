// The charts of `covopt retime` (chart/retime_charts.hpp): the speed-scale chart draws every
// sample's safe and chosen speed and the uniform slow-down; the cycle-time chart one line per
// covering, the per-link design as points, a sweep point without a safe timing as a gap.
#include <catch2/catch.hpp>

#include <limits>
#include <string>

#include <covopt/core/body_contact.hpp>

#include "chart_test_support.hpp"
#include "covopt/chart/retime_charts.hpp"

using namespace covopt;
using Catch::Matchers::Contains;
using covopt::chart::testing::Count;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string Svg(const chart::GnuplotChart& c) { return c.script(chart::ChartFormat::kSvg, "out.svg"); }

}  // namespace

TEST_CASE("speed-scale chart draws the safe and the chosen speed of every sample", "[chart][retime]") {
  audit::RetimeResult r;
  r.original_time_s = {0.0, 0.5, 1.0};
  r.safe_path_speed = {kInf, 0.25, 3.0};
  r.path_speed = {1.0, 0.25, 1.0};
  r.uniform_speed_scale = 0.25;
  r.cycle_time_s = 2.5;
  r.original_cycle_time_s = 1.0;
  r.uniform_cycle_time_s = 4.0;
  const std::string s = Svg(chart::RetimeSpeedChart(r, "/some/dir/pick.csv"));
  CHECK_THAT(s, Contains("set xlabel 'time of the original program [s]'"));
  CHECK_THAT(s, Contains("set ylabel 'speed scale (path speed) [-]'"));
  CHECK_THAT(s, Contains("pick.csv: cycle time 2.5 s (original 1 s, uniform slow-down 4 s)"));
  CHECK_THAT(s, Contains("0.5 0.25 0.25\n"));   // the sample at the limit
  CHECK_THAT(s, Contains("0 1.6 1\n"));         // unbounded: drawn at the top (1.6 x the fastest 1)
  CHECK_THAT(s, Contains("1 1.6 1\n"));         // above the top: clipped
  CHECK_THAT(s, Contains("uniform slow-down 0.25"));
  CHECK(s.find("/some/dir") == std::string::npos);
  CHECK_THROWS_AS(chart::RetimeSpeedChart(audit::RetimeResult{}, "x"), std::invalid_argument);
}

TEST_CASE("cycle-time chart draws one line per covering and the per-link design as points", "[chart][retime]") {
  report::RetimeSweep sweep;
  sweep.designs = {audit::CycleTimeDesign{.name = "foam A", .covering = {}, .design = std::nullopt},
                   audit::CycleTimeDesign{.name = "per-link design", .covering = {}, .design = audit::AuditDesignOptions{}}};
  sweep.thicknesses_m = {0.0, 0.01};
  sweep.points = {
      {.design = 0, .thickness_m = 0.0, .status = audit::RetimeStatus::kInfeasible, .cycle_time_s = kInf,
       .uniform_cycle_time_s = kInf, .safe_speed_scale = 0.0, .message = "no safe speed"},
      {.design = 0, .thickness_m = 0.01, .status = audit::RetimeStatus::kSafe, .cycle_time_s = 2.0,
       .uniform_cycle_time_s = 3.0, .safe_speed_scale = 0.5, .message = ""},
      {.design = 1, .thickness_m = 0.008, .status = audit::RetimeStatus::kSafe, .cycle_time_s = 1.5,
       .uniform_cycle_time_s = 1.5, .safe_speed_scale = 1.0, .message = ""}};
  const std::string s = Svg(chart::CycleTimeChart(sweep, 1.5));
  CHECK_THAT(s, Contains("set xlabel 'covering thickness [mm]'"));
  CHECK_THAT(s, Contains("set ylabel 'cycle time [s]'"));
  CHECK_THAT(s, Contains("0 NaN NaN\n"));  // no safe timing: a gap
  CHECK_THAT(s, Contains("10 2 3\n"));
  CHECK_THAT(s, Contains("8 1.5 1.5\n"));
  CHECK(Count(s, "'foam A, re-timed'") == 1);
  CHECK(Count(s, "'foam A, uniform slow-down'") == 1);
  CHECK(Count(s, "'per-link design (its thickest link)'") == 1);
  CHECK_THAT(s, Contains("original program 1.5 s"));
  CHECK_THROWS_AS(chart::CycleTimeChart(report::RetimeSweep{}, 1.0), std::invalid_argument);
}
