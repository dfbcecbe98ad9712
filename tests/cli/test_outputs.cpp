// The files `covopt simulate` writes. These tests check that --history writes the documented
// CSV header and one row per sample of the library's history, with time non-decreasing from
// first contact to separation and the tensile stress σ_t = σ_c (1 - 2ν_t)/3 beside the
// compressive one; that output files are replaced atomically and an unwritable target is
// exit 1; that --plot draws a PNG or an SVG through gnuplot (skipped with a warning when
// gnuplot is not installed) with the laceration limit on the tensile-stress axis and the
// contusion limit on the energy-density panel; that a missing gnuplot is exit 1 with the
// documented message and leaves no files behind; that the scene headline says which body
// moves; and that JSON numbers are printed in their shortest round-trip form.

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/core.hpp"
#include "covopt/optim/verdicts.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "plot.hpp"

using covopt::cli::testing::CliRun;
using covopt::cli::testing::ReadFile;
using covopt::cli::testing::Run;
using covopt::cli::testing::SplitLines;
using covopt::cli::testing::TempDir;
using Catch::Matchers::Contains;
using covopt::cli::testing::ScopedEnv;
using Catch::Matchers::StartsWith;

namespace {

std::vector<double> Columns(const std::string& row) {
  std::vector<double> values;
  std::istringstream in(row);
  for (std::string cell; std::getline(in, cell, ',');) values.push_back(std::stod(cell));
  return values;
}

}  // namespace

TEST_CASE("simulate --history writes the CSV header and one row per history sample", "[outputs]") {
  TempDir dir;
  const auto csv = dir / "h.csv";
  const CliRun run = Run({"simulate", "--history", csv.string(), "--json"});
  REQUIRE(run.exit_code == 0);
  const auto json = nlohmann::json::parse(run.out);
  CHECK(json["method"] == "arkode-erk54");  // a history makes the time path (its default) run

  const auto lines = SplitLines(ReadFile(csv));
  REQUIRE(lines.size() > 10);
  CHECK(lines.front() == covopt::cli::kHistoryCsvHeader);
  CHECK(lines.front() ==
        "time_s,penetration_m,penetration_rate_m_per_s,force_N,compressive_stress_Pa,"
        "tensile_stress_Pa,energy_density_J_per_m2");
  CHECK(lines.size() - 1 == json["solver"]["history_samples"].get<std::size_t>());

  // Eq. (5) with the scene's ν_t (0.42): σ_t = σ_c (1 - 2 ν_t)/3.
  const double tensile_per_compressive = (1.0 - 2.0 * 0.42) / 3.0;
  double previous_time = -1.0;
  double max_penetration = 0.0;
  double max_tensile = 0.0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto row = Columns(lines[i]);
    REQUIRE(row.size() == 7);
    CHECK(row[0] >= previous_time);
    previous_time = row[0];
    max_penetration = std::max(max_penetration, row[1]);
    CHECK(row[5] == Approx(row[4] * tensile_per_compressive).epsilon(1e-12));
    max_tensile = std::max(max_tensile, row[5]);
  }
  // The history passes through the maximum compression, where σ_t peaks.
  CHECK(max_tensile == Approx(json["max_tensile_stress_Pa"].get<double>()).epsilon(1e-9));
  const auto first = Columns(lines[1]);
  CHECK(first[0] == 0.0);
  CHECK(first[1] == 0.0);
  // Up to contact end: the last sample is the separation.
  CHECK(previous_time == Approx(json["contact_duration_s"].get<double>()).epsilon(1e-9));
  CHECK(max_penetration == Approx(json["max_penetration_m"].get<double>()).epsilon(1e-9));
}

TEST_CASE("the history CSV has full-precision numbers that read back exactly", "[outputs]") {
  covopt::TimeIntegrationOptions options;
  options.record_history = true;
  const auto model = covopt::ImpactModel::FromScene({});
  const auto result = covopt::SimulateImpact(model, options);
  REQUIRE(result.ok());
  const auto lines = SplitLines(covopt::cli::HistoryCsv(model, result.history));
  REQUIRE(lines.size() == result.history.size() + 1);
  for (std::size_t i = 0; i < result.history.size(); ++i) {
    const auto row = Columns(lines[i + 1]);
    const auto& h = result.history[i];
    CHECK(row == std::vector<double>{h.time_s, h.penetration_m, h.penetration_rate_m_per_s,
                                     h.force_N, h.compressive_stress_Pa,
                                     model.TensileFromCompressive(h.compressive_stress_Pa),
                                     h.energy_density_J_per_m2});
  }
}

TEST_CASE("an existing history file is replaced whole, with no temporary left", "[outputs]") {
  TempDir dir;
  const auto csv = dir.Write("h.csv", "old content\n");
  REQUIRE(Run({"simulate", "--history", csv.string()}).exit_code == 0);
  CHECK_THAT(ReadFile(csv), StartsWith("time_s,"));
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir.path())) ++files;
  CHECK(files == 1);
}

TEST_CASE("an unwritable history file is an output failure, exit 1", "[outputs]") {
  TempDir dir;
  const auto csv = dir / "no-such-dir" / "h.csv";
  const CliRun run = Run({"simulate", "--history", csv.string()});
  CHECK(run.exit_code == 1);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Contains("h.csv"));
  CHECK_THROWS_AS(covopt::cli::WriteFileAtomically(csv, "x"), covopt::cli::OutputError);
}

TEST_CASE("simulate --plot draws a PNG with gnuplot", "[outputs][plot]") {
  if (!covopt::cli::FindOnPath("gnuplot")) {
    WARN("gnuplot is not on PATH; skipping the plot test");
    return;
  }
  TempDir dir;
  const auto png = dir / "p.png";
  const auto csv = dir / "h.csv";
  const CliRun run = Run({"simulate", "--history", csv.string(), "--plot", png.string()});
  CAPTURE(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("Method  arkode-erk54"));
  const std::string bytes = ReadFile(png);
  REQUIRE(bytes.size() > 1000);
  CHECK(bytes.substr(0, 8) == std::string("\x89PNG\r\n\x1a\n", 8));
  CHECK(std::filesystem::exists(csv));
}

TEST_CASE("simulate --plot draws an SVG for a .svg name", "[outputs][plot]") {
  if (!covopt::cli::FindOnPath("gnuplot")) {
    WARN("gnuplot is not on PATH; skipping the plot test");
    return;
  }
  TempDir dir;
  const auto svg = dir / "chart.SVG";
  const CliRun run = Run({"simulate", "--plot", svg.string(), "--method", "cvode",
                          "--cvode-method", "bdf"});
  CAPTURE(run.err);
  REQUIRE(run.exit_code == 0);
  const std::string text = ReadFile(svg);
  CHECK_THAT(text, Contains("<svg") && Contains("force [N]") && Contains("tensile stress") &&
                       Contains("energy density [J/cm²]") && Contains("time [ms]") &&
                       Contains("laceration limit 1 MPa (tensile)") &&
                       Contains("contusion limit 2.52 J/cm²"));
}

TEST_CASE("the gnuplot script labels both axes and carries the whole history", "[outputs][plot]") {
  covopt::TimeIntegrationOptions options;
  options.record_history = true;
  covopt::cli::SimulationReport report;
  const auto model = covopt::ImpactModel::FromScene(report.scene);
  report.result = covopt::SimulateImpact(model, options);
  report.verdict = covopt::optim::HeadVerdict(report.result.peaks, true, {}, covopt::optim::DesignRule{});
  report.time_options = options;
  const std::string script =
      covopt::chart::HistoryChart(report).script(covopt::chart::ChartFormat::kPng, "/tmp/it's.png");
  CHECK_THAT(script, Contains("set terminal pngcairo") && Contains("set output '/tmp/it''s.png'") &&
                         Contains("set xlabel 'time [ms]'") && Contains("'force [N]'") &&
                         Contains("tensile stress σ_t [MPa]") && Contains("axes x1y2") &&
                         Contains("energy density [J/cm²]"));
  // The label converts back to the compressive stress: 3/(1 - 2 × 0.42) = 18.75.
  CHECK_THAT(script, Contains("compressive σ_c = 18.75 σ_t"));
  const auto lines = SplitLines(script);
  const auto begin = std::find(lines.begin(), lines.end(), "$history << EOD");
  const auto end = std::find(lines.begin(), lines.end(), "EOD");
  REQUIRE(begin != lines.end());
  REQUIRE(end != lines.end());
  CHECK(static_cast<std::size_t>(end - begin - 1) == report.result.history.size());
  // Columns: time [ms], force [N], tensile stress [MPa], energy density [J/cm²].
  for (std::size_t i = 0; i < report.result.history.size(); i += 37) {
    const auto& h = report.result.history[i];
    std::istringstream row(*(begin + 1 + static_cast<std::ptrdiff_t>(i)));
    double t = 0, f = 0, tensile = 0, e = 0;
    row >> t >> f >> tensile >> e;
    CHECK(t == Approx(h.time_s * 1e3));
    CHECK(f == Approx(h.force_N));
    CHECK(tensile == Approx(h.compressive_stress_Pa * (1.0 - 2.0 * 0.42) / 3.0 / 1e6));
    CHECK(e == Approx(h.energy_density_J_per_m2 / 1e4));
  }
}

TEST_CASE("the force/stress chart marks both limits, and the derated ones with a safety factor",
          "[outputs][plot]") {
  covopt::TimeIntegrationOptions options;
  options.record_history = true;
  covopt::cli::SimulationReport report;
  report.result = covopt::SimulateImpact(covopt::ImpactModel::FromScene(report.scene), options);
  covopt::InjuryLimits limits;
  limits.laceration_tensile_stress_Pa = 2e6;
  limits.contusion_energy_density_J_per_m2 = 3e4;
  report.verdict = covopt::optim::HeadVerdict(report.result.peaks, true, limits, covopt::optim::DesignRule{});
  std::string script = covopt::chart::HistoryChart(report).script(covopt::chart::ChartFormat::kSvg, "c.svg");
  // The laceration limit on the tensile axis (MPa), the contusion limit on the energy
  // density panel (J/cm²): the verdict's limits, not the defaults.
  CHECK_THAT(script, Contains("     2 axes x1y2 with lines") &&
                         Contains("'laceration limit 2 MPa (tensile)'") &&
                         Contains("     3 with lines") &&
                         Contains("'contusion limit 3 J/cm²'"));
  CHECK_THAT(script, !Contains("derated"));

  report.verdict = covopt::optim::HeadVerdict(report.result.peaks, true, limits, covopt::optim::DesignRule{2.0});
  script = covopt::chart::HistoryChart(report).script(covopt::chart::ChartFormat::kSvg, "c.svg");
  CHECK_THAT(script, Contains("1 axes x1y2 with lines") &&
                         Contains("'derated limit 1 MPa (limit / safety factor 2)'") &&
                         Contains("'derated limit 1.5 J/cm² (limit / safety factor 2)'"));
}

TEST_CASE("the scene headline says which body moves at the impact speed", "[outputs]") {
  using covopt::cli::SceneHeadline;
  covopt::Scene scene;
  CHECK(SceneHeadline(scene) == "10 kg at 2 m/s, R 15 mm; covering 15 mm, 27.6 MPa; head 4.5 kg");

  // A fixed robot: the head is dropped onto it; the robot is not "fixed at 2.2 m/s".
  scene.robot.mass_kg = covopt::kFixed;
  scene.robot.speed_m_per_s = 2.2;
  CHECK(SceneHeadline(scene) ==
        "fixed robot, R 15 mm; covering 15 mm, 27.6 MPa; head 4.5 kg dropped onto it at 2.2 m/s");

  // A fixed head is hit by the robot.
  scene = covopt::Scene{};
  scene.head.mass_kg = covopt::kFixed;
  CHECK(SceneHeadline(scene) ==
        "10 kg at 2 m/s, R 15 mm; covering 15 mm, 27.6 MPa; head fixed, hit by the robot");

  // Swept fields are left out; a swept mass makes neither body "fixed".
  scene.robot.mass_kg = covopt::kFixed;
  scene.head.mass_kg = 4.5;
  const std::vector<std::string_view> swept{"robot.mass", "covering.modulus"};
  CHECK(SceneHeadline(scene, swept) == "robot at 2 m/s, R 15 mm; covering 15 mm; head 4.5 kg");
  const std::vector<std::string_view> covering{"covering.thickness", "covering.modulus",
                                               "robot.speed"};
  CHECK(SceneHeadline(scene, covering) ==
        "fixed robot, R 15 mm; head 4.5 kg dropped onto it");

  // The table says it too.
  const CliRun run = Run({"simulate", "--robot-mass", "fixed", "--speed", "2.2m/s"});
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("Scene   fixed robot, R 15 mm") &&
                          Contains("head 4.5 kg dropped onto the robot at 2.2 m/s, R 80 mm") &&
                          !Contains("fixed at"));
  const CliRun held = Run({"simulate", "--head-mass", "fixed"});
  REQUIRE(held.exit_code == 0);
  CHECK_THAT(held.out, Contains("Scene   robot 10 kg at 2 m/s, R 15 mm") &&
                           Contains("head fixed (hit by the robot), R 80 mm"));
}

TEST_CASE("scene inputs beyond the headline are listed when they differ from the paper's",
          "[outputs]") {
  covopt::Scene scene;
  CHECK(covopt::cli::SceneDetailsBeyondHeadline(scene).empty());
  scene.scalp.thickness_m = 0.004;
  scene.model.thresholds = covopt::ThresholdReading::kLiteral;
  scene.covering.thickness_m = 0.02;  // in the headline: not repeated
  CHECK(covopt::cli::SceneDetailsBeyondHeadline(scene) ==
        std::vector<std::string>{"scalp-thickness 4 mm", "literal thresholds"});
  const std::vector<std::string_view> swept{"scalp.thickness"};
  CHECK(covopt::cli::SceneDetailsBeyondHeadline(scene, swept) ==
        std::vector<std::string>{"literal thresholds"});
}

TEST_CASE("JSON numbers are the shortest decimals that read back exactly", "[outputs][json]") {
  // 2.2 and 0.018 are exact inputs; nothing may print them with 17 digits.
  const CliRun run =
      Run({"simulate", "--json", "--speed", "2.2m/s", "--covering-thickness", "0.018"});
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(run.out, Contains("\"speed_m_per_s\": 2.2,") && Contains("\"thickness_m\": 0.018"));
  CHECK_THAT(run.out, !Contains("2.2000000000000002") && !Contains("0.018000000000000002"));
  // Every number reads back to the value simulate computed (see test_simulate.cpp); here,
  // the printed form of each is no longer than the shortest round-trip form.
  const auto json = nlohmann::json::parse(run.out);
  const double force = json["peak_force_N"].get<double>();
  CHECK_THAT(run.out, Contains(fmt::format("\"peak_force_N\": {},", force)));
}

TEST_CASE("a missing gnuplot is exit 1 with the documented message and writes nothing",
          "[outputs][plot]") {
  TempDir dir;
  TempDir empty_bin;
  const ScopedEnv path("PATH", empty_bin.path().string());
  const auto csv = dir / "h.csv";
  const CliRun run =
      Run({"simulate", "--history", csv.string(), "--plot", (dir / "p.png").string()});
  CHECK(run.exit_code == 1);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Contains("gnuplot not found on PATH; install gnuplot-nox (Debian) to draw charts and reports"));
  CHECK(std::filesystem::is_empty(dir.path()));
}

TEST_CASE("an unknown plot extension is bad input", "[outputs][plot]") {
  const CliRun run = Run({"simulate", "--plot", "chart.pdf"});
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Contains("--plot") && Contains("chart.pdf"));
  CHECK(covopt::cli::PlotFormatFor("a/b.Png") == covopt::cli::PlotFormat::kPng);
  CHECK_FALSE(covopt::cli::PlotFormatFor("png").has_value());
}
