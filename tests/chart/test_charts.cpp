// The charts (chart/charts.hpp): several charts in one gnuplot run, each a whole SVG with its
// title and caption; the private scratch directory reported to the observer and removed; a
// missing gnuplot named with its package; a failing chart named; the design map's script has
// one contour per criterion at 1/safety factor and marks the chosen design. The drawing tests
// are skipped (with a warning) where gnuplot is not installed.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <covopt/core.hpp>
#include <covopt/materials.hpp>
#include <covopt/optim.hpp>

#include "covopt/chart/charts.hpp"

using namespace covopt;
using Catch::Matchers::Contains;

namespace {

report::SimulationReport HistoryReport() {
  TimeIntegrationOptions options;
  options.record_history = true;
  report::SimulationReport r;
  r.result = SimulateImpact(ImpactModel::FromScene(r.scene), options);
  r.verdict = optim::HeadVerdict(r.result.peaks, true, InjuryLimits{}, optim::DesignRule{});
  return r;
}

optim::DesignMap Map(double safety_factor) {
  optim::DesignRequest request;
  request.materials = optim::SelectCandidates(materials::Catalog::BuiltIn());
  request.options.safety_factor = safety_factor;
  return optim::ComputeDesignMap(request, optim::Design(request), {21, 16});
}

/// Sets an environment variable for a scope.
class ScopedPath {
 public:
  explicit ScopedPath(const std::string& value) {
    if (const char* old = std::getenv("PATH")) old_ = old;
    ::setenv("PATH", value.c_str(), 1);
  }
  ~ScopedPath() { ::setenv("PATH", old_ ? old_->c_str() : "", 1); }
  ScopedPath(const ScopedPath&) = delete;
  ScopedPath& operator=(const ScopedPath&) = delete;

 private:
  std::optional<std::string> old_;
};

}  // namespace

TEST_CASE("the design map's script draws one contour per criterion at 1/safety factor and marks the chosen design",
          "[charts]") {
  const optim::DesignMap map = Map(2.0);
  REQUIRE(map.chosen);
  const chart::GnuplotChart chart = chart::DesignMapChart(map);
  const std::string script = chart.script(chart::ChartFormat::kSvg, "it's.svg");
  CHECK_THAT(script, Contains("set terminal svg") && Contains("set output 'it''s.svg'") &&
                         Contains("set cntrparam levels discrete 0.5") && Contains("with image"));
  for (std::size_t k = 0; k < map.criteria.size(); ++k) {
    CHECK_THAT(script, Contains("set table $contour" + std::to_string(k)) &&
                           Contains(std::string(optim::ToString(map.criteria[k])) + " limit (ratio 0.5)"));
  }
  CHECK_THAT(script, Contains("chosen: " + map.chosen->label));
  CHECK_THAT(chart.caption, Contains(map.chosen->label) && Contains("1/safety factor = 0.5"));
  CHECK_THAT(chart.script(chart::ChartFormat::kPng, "m.png"), Contains("set terminal pngcairo"));
}

TEST_CASE("no charts need no gnuplot, and a missing gnuplot names its package", "[charts]") {
  CHECK(chart::DrawCharts({}, chart::ChartFormat::kSvg).empty());
  const std::filesystem::path empty = std::filesystem::temp_directory_path() / "covopt-test-no-gnuplot";
  std::filesystem::create_directories(empty);
  const ScopedPath path(empty.string());
  const chart::GnuplotChart chart = chart::HistoryChart(HistoryReport());
  int made = 0;
  const chart::ScratchObserver observer{[&](const std::string&) { return ++made; }, {}};
  CHECK_THROWS_WITH(chart::DrawCharts({&chart, 1}, chart::ChartFormat::kSvg, observer),
                    "gnuplot not found on PATH; install gnuplot-nox (Debian) to draw charts and reports");
  CHECK(made == 0);
  std::filesystem::remove(empty);
}

TEST_CASE("several charts are drawn in one gnuplot run into a private directory that is removed", "[charts]") {
  if (!report::FindOnPath("gnuplot")) {
    WARN("gnuplot is not on PATH; skipping the drawing test");
    return;
  }
  const std::vector<chart::GnuplotChart> charts = {chart::HistoryChart(HistoryReport()),
                                                    chart::DesignMapChart(Map(1.0))};
  std::map<int, std::string> live;
  std::vector<std::string> seen;
  int next = 0;
  const chart::ScratchObserver observer{[&](const std::string& p) {
                                           live[next] = p;
                                           seen.push_back(p);
                                           return next++;
                                         },
                                         [&](int token) { live.erase(token); }};
  const std::vector<report::SvgChart> svg = chart::DrawSvgCharts(charts, observer);
  REQUIRE(svg.size() == 2);
  for (std::size_t i = 0; i < svg.size(); ++i) {
    CHECK(svg[i].title == charts[i].title);
    CHECK(svg[i].caption == charts[i].caption);
    CHECK_THAT(svg[i].svg, Contains("<svg") && Contains("</svg>"));
  }
  CHECK_THAT(svg[0].svg, Contains("force [N]") && Contains("contusion limit 2.52 J/cm²"));
  CHECK_THAT(svg[1].svg, Contains("covering thickness [mm]") && Contains("full-compression limit (ratio 1)"));
  // The directory first, then its files (two charts, the script, the log); all removed.
  REQUIRE(seen.size() == 5);
  for (std::size_t i = 1; i < seen.size(); ++i) CHECK(std::filesystem::path(seen[i]).parent_path() == seen[0]);
  CHECK(live.empty());
  for (const std::string& p : seen) CHECK_FALSE(std::filesystem::exists(p));

  // A chart gnuplot cannot draw: named, and the scratch directory removed all the same.
  chart::GnuplotChart broken = charts[0];
  broken.title = "the broken chart";
  broken.script = [](chart::ChartFormat format, const std::string& output) {
    return chart::GnuplotTerminal(format, 200, 100) + "set output " + chart::GnuplotQuoted(output) +
           "\nplot no_such_function(x)\n";
  };
  const std::vector<chart::GnuplotChart> with_broken = {charts[0], broken};
  seen.clear();
  CHECK_THROWS_WITH(chart::DrawCharts(with_broken, chart::ChartFormat::kPng, observer),
                    Contains("gnuplot failed to draw 'the broken chart'") && Contains("no_such_function"));
  CHECK(live.empty());
  for (const std::string& p : seen) CHECK_FALSE(std::filesystem::exists(p));
}
