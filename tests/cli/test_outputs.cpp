// The files `covopt simulate` writes. These tests check that --history writes the documented
// CSV header and one row per sample of the library's history, with time non-decreasing from
// first contact to separation; that output files are replaced atomically and an unwritable
// target is exit 1; that --plot draws a PNG or an SVG through gnuplot (skipped with a
// warning when gnuplot is not installed); and that a missing gnuplot is exit 1 with the
// documented message and leaves no files behind.

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/core.hpp"
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
        "energy_density_J_per_m2");
  CHECK(lines.size() - 1 == json["solver"]["history_samples"].get<std::size_t>());

  double previous_time = -1.0;
  double max_penetration = 0.0;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const auto row = Columns(lines[i]);
    REQUIRE(row.size() == 6);
    CHECK(row[0] >= previous_time);
    previous_time = row[0];
    max_penetration = std::max(max_penetration, row[1]);
  }
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
  const auto result = covopt::SimulateImpact(covopt::ImpactModel::FromScene({}), options);
  REQUIRE(result.ok());
  const auto lines = SplitLines(covopt::cli::HistoryCsv(result.history));
  REQUIRE(lines.size() == result.history.size() + 1);
  for (std::size_t i = 0; i < result.history.size(); ++i) {
    const auto row = Columns(lines[i + 1]);
    const auto& h = result.history[i];
    CHECK(row == std::vector<double>{h.time_s, h.penetration_m, h.penetration_rate_m_per_s,
                                     h.force_N, h.compressive_stress_Pa,
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
  CHECK_THAT(text, Contains("<svg") && Contains("force [N]") &&
                       Contains("compressive stress [MPa]") && Contains("time [ms]"));
}

TEST_CASE("the gnuplot script labels both axes and carries the whole history", "[outputs][plot]") {
  covopt::TimeIntegrationOptions options;
  options.record_history = true;
  covopt::cli::SimulationReport report;
  report.result = covopt::SimulateImpact(covopt::ImpactModel::FromScene(report.scene), options);
  report.time_options = options;
  const std::string script =
      covopt::cli::GnuplotScript(report, covopt::cli::PlotFormat::kPng, "/tmp/it's.png");
  CHECK_THAT(script, Contains("set terminal pngcairo") && Contains("set output '/tmp/it''s.png'") &&
                         Contains("set xlabel 'time [ms]'") && Contains("'force [N]'") &&
                         Contains("'compressive stress [MPa]'") && Contains("axes x1y2"));
  const auto lines = SplitLines(script);
  const auto begin = std::find(lines.begin(), lines.end(), "$history << EOD");
  const auto end = std::find(lines.begin(), lines.end(), "EOD");
  REQUIRE(begin != lines.end());
  REQUIRE(end != lines.end());
  CHECK(static_cast<std::size_t>(end - begin - 1) == report.result.history.size());
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
  CHECK_THAT(run.err, Contains("gnuplot not found on PATH; install gnuplot-nox or drop --plot"));
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
