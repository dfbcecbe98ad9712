// The compressive-curve chart (`materials show --plot`): its script carries every point of the
// curve from the origin with W at each, the rigid stop at the last strain, σ(25 %) and a grade
// band; a material without a curve is refused.

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/core.hpp>
#include <covopt/materials.hpp>

#include "covopt/chart/curve_chart.hpp"

using Catch::Matchers::Contains;

namespace {

/// printf's %.<digits>g, as the chart writes its numbers.
std::string G(double value, int digits = 9) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

}  // namespace

TEST_CASE("the curve chart's script holds the points, W, the rigid stop and the rating", "[charts][curve]") {
  const auto* m = covopt::materials::Catalog::BuiltIn().Find("neoprene sponge D1056 2C2");
  REQUIRE(m != nullptr);
  const std::string script =
      covopt::chart::CompressiveCurveChart(*m).script(covopt::chart::ChartFormat::kSvg, "out.svg");
  CHECK_THAT(script, Contains("$curve << EOD\n0 0 0\n"));
  for (const auto& p : m->compressive_curve->points()) {
    CHECK_THAT(script, Contains(G(100.0 * p.strain) + " " + G(p.stress_Pa / 1e3) + " " +
                                G(m->compressive_curve->EnergyDensityAt(p.strain) / 1e3) + "\n"));
  }
  const std::string stop = G(100.0 * m->compressive_curve->last_strain(), 6);
  CHECK_THAT(script, Contains("set arrow from " + stop + ", graph 0 to " + stop + ", graph 1"));
  CHECK_THAT(script, Contains("$rated << EOD\n25 " + G(*covopt::materials::StressAt25Pa(*m) / 1e3) + "\nEOD"));
  CHECK_THAT(script, Contains("grade band at 25 %: 34.47 to 62.05 kPa"));
  CHECK_THAT(script, Contains("set output 'out.svg'"));
}

TEST_CASE("a material without a curve has no curve chart", "[charts][curve]") {
  const auto* m = covopt::materials::Catalog::BuiltIn().Find("polystyrene foam 27.6");
  REQUIRE(m != nullptr);
  CHECK_THROWS_AS(covopt::chart::CompressiveCurveChart(*m), std::invalid_argument);
}

TEST_CASE("the working-point chart marks the result's strain and the curve's stress there", "[charts][curve]") {
  const auto* m = covopt::materials::Catalog::BuiltIn().Find("neoprene sponge D1056 2C2");
  REQUIRE(m != nullptr);
  const covopt::CompressiveCurve& curve = *m->compressive_curve;
  const double strain = 0.5 * curve.last_strain();
  const covopt::chart::WorkingPoint point{"", strain};
  const covopt::chart::GnuplotChart chart = covopt::chart::FoamWorkingPointChart(curve, m->name, {&point, 1});
  const std::string script = chart.script(covopt::chart::ChartFormat::kSvg, "out.svg");
  CHECK_THAT(script, Contains("$points << EOD\n" + G(100.0 * strain) + " " + G(curve.StressAt(strain) / 1e3)));
  CHECK_THAT(script, Contains("set xlabel 'nominal strain of the covering [%]'"));
  CHECK_THAT(script, Contains("set ylabel 'nominal stress σ [kPa]'"));
  CHECK_THAT(chart.caption, Contains("[kPa]") && Contains("[%]"));
  CHECK_THROWS_AS(covopt::chart::FoamWorkingPointChart(curve, m->name, {}), std::invalid_argument);
}

TEST_CASE("a simulation's report charts: the history, and the working point for a foam covering", "[charts][curve]") {
  const auto* foam = covopt::materials::Catalog::BuiltIn().Find("neoprene sponge D1056 2C2");
  const auto* hertz = covopt::materials::Catalog::BuiltIn().Find("polystyrene foam 27.6");
  REQUIRE((foam != nullptr && hertz != nullptr));
  for (const auto* m : {foam, hertz}) {
    covopt::report::SimulationReport report;
    report.scene.robot.speed_m_per_s = 0.5;
    report.scene.covering = covopt::materials::CoveringOf(*m, 0.01);
    covopt::TimeIntegrationOptions options;
    options.record_history = true;
    report.result = covopt::SimulateImpact(covopt::ImpactModel::FromScene(report.scene), options);
    report.covering_material = m->name;
    REQUIRE(report.result.ok());
    const std::vector<covopt::chart::GnuplotChart> charts = covopt::chart::SimulationCharts(report);
    CAPTURE(m->name);
    REQUIRE(charts.size() == (m == foam ? 2u : 1u));
    if (m == foam) {
      const double strain = report.result.peaks.covering_strain_at_peak;
      CHECK(strain > 0.0);
      CHECK_THAT(charts[1].script(covopt::chart::ChartFormat::kSvg, "o.svg"),
                 Contains("$points << EOD\n" + G(100.0 * strain)));
    }
  }
}
