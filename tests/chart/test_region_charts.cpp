// The body-region charts (chart/region_charts.hpp): each
// script names its axes with their units and draws every bar, line or cell it is given.
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <covopt/core.hpp>
#include <covopt/materials.hpp>
#include <covopt/optim.hpp>

#include "chart_test_support.hpp"
#include "covopt/chart/charts.hpp"
#include "covopt/chart/region_charts.hpp"

using namespace covopt;
using Catch::Matchers::Contains;
using covopt::chart::testing::Count;
using covopt::chart::testing::CoveredScene;

namespace {

std::string Svg(const chart::GnuplotChart& c) { return c.script(chart::ChartFormat::kSvg, "out.svg"); }

}  // namespace

TEST_CASE("bar chart draws every bar with its value and the limit line", "[chart][regions]") {
  chart::BareCoveredBars bars;
  bars.title = "t";
  bars.value_label = "governing ratio [-]";
  bars.bars = {{"alpha", 0.25, 0.125}, {"beta", 2.5, std::nullopt}, {"gamma", std::nullopt, 0.75}};
  bars.limit = 0.5;
  bars.limit_label = "limit 1/SF = 0.5";
  const std::string s = Svg(chart::BareCoveredBarChart(bars, "Title", "Caption [-]"));
  CHECK_THAT(s, Contains("set xlabel 'governing ratio [-]'"));
  for (const char* label : {"'alpha' 2", "'beta' 1", "'gamma' 0"}) CHECK_THAT(s, Contains(label));
  CHECK_THAT(s, Contains("\"0.125\""));  // alpha covered
  CHECK_THAT(s, Contains("\"2.5\""));    // beta bare
  CHECK_THAT(s, Contains("\"0.75\""));   // gamma covered
  CHECK_THAT(s, Contains("title 'limit 1/SF = 0.5'"));
  CHECK_THROWS_AS(chart::BareCoveredBarChart({}, "x", "y"), std::invalid_argument);
}

TEST_CASE("all-regions ratio chart has a bar for every region, bare and covered", "[chart][regions]") {
  const std::vector<materials::BodyLimits> all =
      materials::BodyRegionTable::BuiltIn().AllLimits(ContactType::kTransient);
  REQUIRE(all.size() > 10);
  const BodyContactScene scene = CoveredScene();
  optim::BodyRegionOptions options;
  options.rule.safety_factor = 2.0;
  std::vector<optim::BodyRegionJudgement> judged;
  for (const materials::BodyLimits& limits : all) judged.push_back(optim::JudgeBodyContact(scene, limits, options));
  const chart::GnuplotChart c = chart::BodyRegionRatioChart(scene, judged, options);
  const std::string s = Svg(c);
  for (const materials::BodyLimits& limits : all) {
    CHECK_THAT(s, Contains("'" + limits.region->name + " (" + limits.area->name + ")'"));
  }
  CHECK_THAT(s, Contains("set xlabel 'governing ratio to the ISO/TS 15066 limits [-]"));
  CHECK_THAT(s, Contains("title 'covered'"));
  CHECK_THAT(s, Contains("title 'bare robot'"));
  CHECK_THAT(s, Contains("limit 1/SF = 0.5"));
  // One data line per region in each block: the covered one and the bare one.
  const std::string covered = s.substr(s.find("$covered << EOD"), s.find("EOD\n$bare") - s.find("$covered << EOD"));
  CHECK(Count(covered, "\n") == all.size() + 1);
  CHECK_THAT(c.caption, Contains("[-]"));
}

TEST_CASE("one-region ratio chart draws force and pressure, bare and covered", "[chart][regions]") {
  const materials::BodyLimits chest = materials::BodyRegionTable::BuiltIn().Limits("chest", "", ContactType::kTransient);
  const BodyContactScene scene = CoveredScene();
  const optim::BodyRegionJudgement j = optim::JudgeBodyContact(scene, chest, {});
  const std::string s = Svg(chart::BodyRegionRatioChart(scene, {&j, 1}, {}));
  CHECK_THAT(s, Contains("'force (limit 280 N)'"));
  CHECK_THAT(s, Contains("'pressure (limit 240 N/cm²)'"));
  CHECK_THAT(s, Contains("F/F_lim, p/p_lim"));
  // The bare robot is judged again without its covering: its force is larger.
  BodyContactScene bare = scene;
  bare.covering.thickness_m = 0.0;
  const optim::BodyRegionJudgement b = optim::JudgeBodyContact(bare, chest, {});
  CHECK(b.force_ratio > j.force_ratio);
  CHECK_THAT(s, Contains(fmt::format("\"{:.3g}\"", b.force_ratio)));
  CHECK_THAT(s, Contains(fmt::format("\"{:.3g}\"", j.force_ratio)));
}

TEST_CASE("body-region speed chart has a bar per row, masses named when several", "[chart][regions]") {
  std::vector<report::BodyRegionTableRow> rows(3);
  rows[0] = {.robot_mass_kg = 5.0, .region = "chest", .area = "sternum", .bare_max_speed_m_per_s = 0.2,
             .has_covering = true, .covered_max_speed_m_per_s = 0.6};
  rows[1] = {.robot_mass_kg = 20.0, .region = "chest", .area = "sternum", .bare_max_speed_m_per_s = 0.1,
             .has_covering = true, .covered_max_speed_m_per_s = 0.3};
  rows[2] = {.robot_mass_kg = 20.0, .region = "head", .bare_max_speed_m_per_s = std::nullopt,
             .has_covering = true, .covered_max_speed_m_per_s = 0.25};
  const std::string s = Svg(chart::BodyRegionSpeedChart(rows));
  CHECK_THAT(s, Contains("set xlabel 'largest safe impact speed [m/s]'"));
  CHECK_THAT(s, Contains("'chest (sternum), 5 kg' 2"));
  CHECK_THAT(s, Contains("'chest (sternum), 20 kg' 1"));
  CHECK_THAT(s, Contains("'head, 20 kg' 0"));
  CHECK_THAT(s, Contains("\"0.6\""));
  CHECK_THAT(s, Contains("\"0.25\""));
}

TEST_CASE("audit region map writes every link x region ratio in its cell", "[chart][regions][audit]") {
  audit::AuditResult result;
  result.links = {"link1", "link2"};
  result.regions = {"chest (sternum)", "hand (palm)", "head (Park et al. 2011)"};
  for (std::size_t l = 0; l < 2; ++l) {
    for (std::size_t r = 0; r < 3; ++r) {
      audit::AuditCell cell;
      cell.link = l;
      cell.region = r;
      cell.governing_ratio = 0.1 * static_cast<double>(1 + l * 3 + r);
      result.cells.push_back(cell);
    }
  }
  result.cells.back().governing_ratio = std::numeric_limits<double>::infinity();
  const chart::GnuplotChart c = chart::AuditRegionMap(result, 2.0);
  const std::string s = Svg(c);
  for (const char* name : {"'link1' 0", "'link2' 1", "'chest (sternum)' 0", "'hand (palm)' 1",
                           "'head (Park et al. 2011)' 2"}) {
    CHECK_THAT(s, Contains(name));
  }
  for (const char* cell : {"0 0 \"0.10\"", "2 0 \"0.30\"", "1 1 \"0.50\"", "2 1 \"inf\""}) CHECK_THAT(s, Contains(cell));
  CHECK_THAT(s, Contains("set cbrange [0:1]"));  // the limit 1/SF = 0.5 in the middle
  CHECK_THAT(s, Contains("governing ratio [-]"));
}

TEST_CASE("audit region map of one region, every value on the dark end: drawn by gnuplot, no empty label block",
          "[chart][regions][audit]") {
  // gnuplot 5.4 crashed (signal 11) on a block of labels without a valid point: an audit of the
  // chest alone whose ratios all sit on the dark ends of the scale left the light block empty.
  audit::AuditResult result;
  result.links = {"link0", "link1", "link2"};
  result.regions = {"chest (sternum)"};
  for (std::size_t l = 0; l < 3; ++l) {
    audit::AuditCell cell;
    cell.link = l;
    cell.region = 0;
    cell.governing_ratio = l == 0 ? 0.0 : 5.0 * static_cast<double>(l);  // 0, 5, 10: all dark
    result.cells.push_back(cell);
  }
  const chart::GnuplotChart c = chart::AuditRegionMap(result, 1.0);
  const std::string s = Svg(c);
  CHECK_THAT(s, Contains("$region_dark using"));
  CHECK_THAT(s, !Contains("$region_light using"));
  CHECK_THAT(s, !Contains("NaN"));
  const std::vector<report::SvgChart> drawn = chart::DrawSvgCharts({&c, 1});
  REQUIRE(drawn.size() == 1);
  CHECK_THAT(drawn.front().svg, Contains("<svg"));
  CHECK_THAT(drawn.front().svg, Contains("10.00"));
}

TEST_CASE("trajectory region chart draws the worst ratio at every sample and marks the worst", "[chart][regions]") {
  const materials::BodyLimits chest = materials::BodyRegionTable::BuiltIn().Limits("chest", "", ContactType::kTransient);
  optim::BodyRegionTrajectoryCheck check;
  for (int i = 0; i < 5; ++i) {
    optim::BodyRegionSampleVerdict v;
    v.time_s = 0.25 * i;
    v.moving = i > 0;
    v.worst_ratio = 0.1 * i;
    check.samples.push_back(v);
  }
  check.worst_sample = 4;
  const std::vector<chart::GnuplotChart> charts = chart::BodyRegionTrajectoryCharts(check, {&chest, 1}, 2.0);
  REQUIRE(charts.size() == 1);
  const std::string s = Svg(charts.front());
  CHECK_THAT(s, Contains("$ratio << EOD\n0 0\n0.25 0.1\n0.5 0.2\n0.75 0.30000000000000004\n1 0.4\nEOD"));
  CHECK_THAT(s, Contains("set xlabel 'time [s]'"));
  CHECK_THAT(s, Contains("set ylabel 'governing ratio [-]'"));
  CHECK_THAT(s, Contains("limit 1/SF = 0.5"));
  CHECK_THAT(s, Contains("sets the scale: t = 1 s, chest (sternum)"));
  CHECK(chart::BodyRegionTrajectoryCharts({}, {&chest, 1}, 1.0).empty());
}
