// Failures after the input was accepted (issue 6), through the real command line: a time
// path that hits its step limit is exit 1 with the integrator's status on stderr, and no
// output file is half-written or clobbered — not by a failed computation, not by an
// unwritable target, not by a gnuplot that is missing or fails.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "cli_test_support.hpp"
#include "covopt/core/impact_model.hpp"
#include "covopt/core/time_integration.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::ReadFile;
using covopt::cli::testing::Run;
using covopt::cli::testing::TempDir;
using Catch::Matchers::Contains;
using covopt::cli::testing::ScopedEnv;

namespace fs = std::filesystem;

/// The names in a directory, sorted.
std::vector<std::string> Listing(const fs::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

const std::string kGoodCsv = "time_s,a previous good history\n0,1\n";
const std::string kGoodPng = "\x89PNG previous good chart";

}  // namespace

TEST_CASE("a step-limited time path is exit 1 with the solver's status and message",
          "[faults][cli]") {
  covopt::TimeIntegrationOptions options;
  options.method = covopt::ComputationMethod::kCvodeAdams;
  options.max_steps = 10;
  const auto expected = covopt::SimulateImpact(covopt::ImpactModel::FromScene({}), options);
  REQUIRE(expected.status == covopt::SolveStatus::kStepLimit);
  for (const bool json : {false, true}) {
    std::vector<std::string> args = {"simulate", "--method", "cvode", "--max-steps", "10"};
    if (json) args.push_back("--json");
    const CliRun run = Run(args);
    CAPTURE(json, run.err);
    CHECK(run.exit_code == 1);
    CHECK(run.out.empty());
    CHECK_THAT(run.err, Contains("step-limit") && Contains("cvode-adams") && Contains(expected.message));
    CHECK(run.err.find('\n') == run.err.size() - 1);  // one line
  }
}

TEST_CASE("a run that fails after outputs were requested leaves existing files untouched",
          "[faults][cli][outputs]") {
  TempDir dir;
  const fs::path csv = dir.Write("h.csv", kGoodCsv);
  const fs::path png = dir.Write("p.png", kGoodPng);
  const CliRun run = Run({"simulate", "--method", "cvode", "--max-steps", "10", "--history",
                          csv.string(), "--plot", png.string()});
  CAPTURE(run.err);
  CHECK(run.exit_code == 1);
  CHECK(run.out.empty());
  CHECK(ReadFile(csv) == kGoodCsv);
  CHECK(ReadFile(png) == kGoodPng);
  CHECK(Listing(dir.path()) == std::vector<std::string>{"h.csv", "p.png"});  // no temporaries

  // Nor does a run whose new output files would be created: none appear.
  TempDir fresh;
  const CliRun again = Run({"simulate", "--method", "cvode", "--max-steps", "10", "--history",
                            (fresh / "h.csv").string(), "--plot", (fresh / "p.png").string()});
  CHECK(again.exit_code == 1);
  CHECK(fs::is_empty(fresh.path()));
}

TEST_CASE("bad input with outputs requested writes nothing", "[faults][cli][outputs]") {
  TempDir dir;
  const fs::path csv = dir.Write("h.csv", kGoodCsv);
  const CliRun run = Run({"simulate", "--history", csv.string(), "--speed", "-1"});
  CHECK(run.exit_code == 2);
  CHECK(ReadFile(csv) == kGoodCsv);
  CHECK(Listing(dir.path()) == std::vector<std::string>{"h.csv"});
}

TEST_CASE("an unwritable history target is exit 1 and creates nothing", "[faults][cli][outputs]") {
  TempDir dir;
  // A missing directory, and a path through a regular file (ENOTDIR, even for root).
  const fs::path file = dir.Write("file", "x");
  for (const fs::path& target : {dir / "missing" / "h.csv", file / "h.csv"}) {
    CAPTURE(target.string());
    const CliRun run = Run({"simulate", "--method", "cvode", "--history", target.string()});
    CHECK(run.exit_code == 1);
    CHECK(run.out.empty());
    CHECK_THAT(run.err, Contains("h.csv"));
  }
  // A directory where the file should go: not replaced, not emptied.
  fs::create_directory(dir / "h.csv");
  dir.Write("h.csv/keep", "kept");
  const CliRun run = Run({"simulate", "--method", "cvode", "--history", (dir / "h.csv").string()});
  CHECK(run.exit_code == 1);
  CHECK(ReadFile(dir / "h.csv" / "keep") == "kept");
  CHECK(Listing(dir.path()) == std::vector<std::string>{"file", "h.csv"});
}

TEST_CASE("a gnuplot that fails or is missing leaves the existing chart and no temporaries",
          "[faults][cli][outputs]") {
  TempDir dir;
  const fs::path png = dir.Write("p.png", kGoodPng);
  const fs::path csv = dir.Write("h.csv", kGoodCsv);

  SECTION("gnuplot missing from PATH") {
    TempDir empty_bin;
    const ScopedEnv path("PATH", empty_bin.path().string());
    const CliRun run = Run({"simulate", "--plot", png.string(), "--history", csv.string()});
    CHECK(run.exit_code == 1);
    CHECK(run.out.empty());
    CHECK_THAT(run.err, Contains("gnuplot"));
  }
  SECTION("a gnuplot that writes half a file and fails") {
    TempDir bin;
    // It writes half a PNG into the output the script names (covopt's temporary), then
    // exits 3, as a gnuplot killed mid-draw would.
    const fs::path fake = bin.Write("gnuplot",
                                    "#!/bin/sh\n"
                                    "out=$(sed -n \"s/^set output '\\(.*\\)'$/\\1/p\" \"$1\")\n"
                                    "printf 'half a chart' > \"$out\"\n"
                                    "echo 'gnuplot: fake failure' >&2\n"
                                    "exit 3\n");
    fs::permissions(fake, fs::perms::owner_all);
    const ScopedEnv path("PATH", bin.path().string() + ":/usr/bin:/bin");
    const CliRun run = Run({"simulate", "--plot", png.string()});
    CAPTURE(run.err);
    CHECK(run.exit_code == 1);
    CHECK(run.out.empty());
    CHECK_THAT(run.err, Contains("gnuplot"));
  }
  SECTION("a gnuplot that exits 0 without drawing anything") {
    TempDir bin;
    const fs::path fake = bin.Write("gnuplot", "#!/bin/sh\nexit 0\n");
    fs::permissions(fake, fs::perms::owner_all);
    const ScopedEnv path("PATH", bin.path().string() + ":/usr/bin:/bin");
    const CliRun run = Run({"simulate", "--plot", png.string()});
    CAPTURE(run.err);
    CHECK(run.exit_code == 1);
    CHECK_THAT(run.err, Contains("empty output"));
  }
  CHECK(ReadFile(png) == kGoodPng);
  CHECK(ReadFile(csv) == kGoodCsv);
  CHECK(Listing(dir.path()) == std::vector<std::string>{"h.csv", "p.png"});
}

TEST_CASE("sweep --csv: bad input and unwritable targets leave files untouched",
          "[faults][cli][outputs]") {
  TempDir dir;
  const fs::path csv = dir.Write("s.csv", kGoodCsv);
  // Bad input: nothing written, the old file intact.
  const CliRun bad = Run({"sweep", "--x", "speed=1m/s..2kg", "--csv", csv.string()});
  CHECK(bad.exit_code == 2);
  CHECK(ReadFile(csv) == kGoodCsv);
  // An unwritable target: exit 1, nothing created.
  const fs::path missing = dir / "missing" / "s.csv";
  const CliRun unwritable = Run({"sweep", "--x", "speed=1m/s..2m/s:3", "--csv", missing.string()});
  CHECK(unwritable.exit_code == 1);
  CHECK_THAT(unwritable.err, Contains("s.csv"));
  CHECK(Listing(dir.path()) == std::vector<std::string>{"s.csv"});
  // A good run replaces the file whole, with no temporary left behind.
  const CliRun good = Run({"sweep", "--x", "speed=1m/s..2m/s:3", "--csv", csv.string()});
  CAPTURE(good.err);
  REQUIRE(good.exit_code == 0);
  CHECK(ReadFile(csv) != kGoodCsv);
  CHECK(ReadFile(csv).find("speed") != std::string::npos);
  CHECK(Listing(dir.path()) == std::vector<std::string>{"s.csv"});
}
