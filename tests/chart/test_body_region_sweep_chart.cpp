// The body-region sweep chart (chart/body_region_sweep_chart.hpp): an axis of few values is drawn
// as lines, one per value, two long axes as a map; units on every axis, the thickness in mm.
#include <catch2/catch.hpp>

#include <cstddef>
#include <string>

#include <covopt/core.hpp>
#include <covopt/materials.hpp>
#include <covopt/optim.hpp>

#include "chart_test_support.hpp"
#include "covopt/chart/body_region_sweep_chart.hpp"
#include "covopt/scene_file/sweep_axis.hpp"

using namespace covopt;
using Catch::Matchers::Contains;
using covopt::chart::testing::Count;
using covopt::chart::testing::CoveredScene;

TEST_CASE("body-region sweep chart: a 3-value axis gives 3 lines, units on every axis", "[chart][regions][sweep]") {
  const materials::BodyLimits chest = materials::BodyRegionTable::BuiltIn().Limits("chest", "", ContactType::kTransient);
  const BodyContactScene scene = CoveredScene();
  const TypedSweepAxis x = scene_file::ParseSweepAxis("speed=0.2..1:9", "--x");
  const TypedSweepAxis mass = scene_file::ParseSweepAxis("robot-mass=2,10,40", "--y");
  const auto grid = optim::SweepBodyRegion(scene, SweepAxis{x.field->dotted_name(), x.values},
                                           SweepAxis{mass.field->dotted_name(), mass.values}, chest, {});
  REQUIRE(chart::BodyRegionSweepChartKindOf(x, &mass) == chart::BodyRegionSweepChartKind::kLines);
  const std::string s = chart::BodyRegionSweepChart(grid, x, &mass, chest, 2.0, chart::ChartFormat::kSvg, "o.svg");
  CHECK(Count(s, "<< EOD") == 3);
  for (const char* line : {"title 'robot-mass = 2 kg'", "title 'robot-mass = 10 kg'", "title 'robot-mass = 40 kg'"}) {
    CHECK_THAT(s, Contains(line));
  }
  CHECK_THAT(s, Contains("set xlabel 'speed [m/s]'"));
  CHECK_THAT(s, Contains("set ylabel 'governing ratio [-]'"));
  CHECK_THAT(s, Contains("limit 1/SF = 0.5"));
  CHECK_THAT(s, Contains("chest (sternum): 280 N"));
  // Lines run over the longer axis: with the thickness as x (3 values) and the speed as y (9).
  const TypedSweepAxis thickness = scene_file::ParseSweepAxis("covering-thickness=5mm..15mm:3", "--x");
  const auto grid2 = optim::SweepBodyRegion(scene, SweepAxis{thickness.field->dotted_name(), thickness.values},
                                            SweepAxis{x.field->dotted_name(), x.values}, chest, {});
  const std::string t = chart::BodyRegionSweepChart(grid2, thickness, &x, chest, 1.0, chart::ChartFormat::kSvg, "o.svg");
  CHECK(Count(t, "<< EOD") == 3);
  CHECK_THAT(t, Contains("title 'covering-thickness = 5 mm'"));
  CHECK_THAT(t, Contains("set xlabel 'speed [m/s]'"));
  // The thickness in mm on an axis of its own.
  const auto grid1 = optim::SweepBodyRegion(scene, SweepAxis{thickness.field->dotted_name(), thickness.values},
                                            std::nullopt, chest, {});
  const std::string u = chart::BodyRegionSweepChart(grid1, thickness, nullptr, chest, 1.0, chart::ChartFormat::kSvg, "o.svg");
  CHECK(Count(u, "<< EOD") == 1);
  CHECK_THAT(u, Contains("set xlabel 'covering-thickness [mm]'"));
  CHECK_THAT(u, Contains("title 'governing ratio'"));
  // Two long axes: the map.
  const TypedSweepAxis t11 = scene_file::ParseSweepAxis("covering-thickness=5mm..15mm:11", "--x");
  const TypedSweepAxis v11 = scene_file::ParseSweepAxis("speed=0.2..1:11", "--y");
  const auto grid3 = optim::SweepBodyRegion(scene, SweepAxis{t11.field->dotted_name(), t11.values},
                                            SweepAxis{v11.field->dotted_name(), v11.values}, chest, {});
  REQUIRE(chart::BodyRegionSweepChartKindOf(t11, &v11) == chart::BodyRegionSweepChartKind::kMap);
  const std::string m = chart::BodyRegionSweepChart(grid3, t11, &v11, chest, 1.0, chart::ChartFormat::kSvg, "o.svg");
  CHECK_THAT(m, Contains("set xlabel 'covering-thickness [mm]'"));
  CHECK_THAT(m, Contains("set ylabel 'speed [m/s]'"));
  CHECK_THAT(m, Contains("set cblabel 'governing ratio [-]'"));
}
