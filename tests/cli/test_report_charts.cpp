// Every kind and mode of --report holds at least one chart (<figure class="chart">), and the
// body-region modes' charts name what they draw. Skipped (with a warning) without gnuplot.
#include <filesystem>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "cli_test_support.hpp"
#include "plot.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::ReadFile;
using covopt::cli::testing::Run;
using covopt::cli::testing::TempDir;

const std::string kFr3 = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3.urdf";
const std::string kPick = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3_pick.csv";

std::size_t Count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

/// The report of `args` (run with --report FILE.html), which must succeed.
std::string Report(std::vector<std::string> args) {
  const TempDir dir;
  const std::string file = (dir / "r.html").string();
  args.insert(args.end(), {"--report", file});
  const CliRun run = Run(args);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  return ReadFile(file);
}

struct Mode {
  std::string name;
  std::vector<std::string> args;
  std::size_t charts;  ///< how many charts the report holds
  std::vector<std::string> shows;  ///< text its charts must carry
};

}  // namespace

TEST_CASE("Every kind and mode of --report holds its charts", "[report][chart]") {
  if (!covopt::cli::FindOnPath("gnuplot")) {
    WARN("gnuplot not on PATH: charts not drawn");
    return;
  }
  const std::vector<std::string> body = {"--robot-mass", "10kg", "--speed", "0.5m/s", "--contact-area", "1cm2"};
  const auto with = [&](std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
  };
  const std::vector<Mode> modes = {
      {"simulate", {"simulate"}, 1, {}},
      {"simulate, ranges", {"simulate", "--head-mass", "3.7kg..5.8kg"}, 1, {"force [N]"}},
      {"simulate, foam covering", {"simulate", "--material", "neoprene sponge D1056 2C2", "--covering-thickness", "10mm"},
       2, {"nominal strain of the covering [%]"}},
      {"simulate, one region, foam covering",
       with({"simulate", "--body-region", "chest", "--material", "neoprene sponge D1056 2C2", "--covering-thickness",
             "10mm"},
            body),
       2, {"force (limit 280 N)", "working point"}},
      {"simulate, one region", with({"simulate", "--body-region", "chest"}, body), 1, {"force (limit 280 N)"}},
      {"simulate, all regions", with({"simulate", "--body-region", "all"}, body), 1, {"chest (sternum)", "hands-fingers"}},
      {"optimize", {"optimize", "--material", "PU foam PORON 4701-30 320"}, 1, {}},
      {"optimize, all regions",
       {"optimize", "--body-region", "all", "--robot-mass", "10kg", "--speed", "0.3m/s", "--contact-area", "1cm2",
        "--material", "PU foam PORON 4701-30 320"},
       1,
       {"bare robot", "covered"}},
      {"speed-limit", {"speed-limit", "--material", "PU foam PORON 4701-30 320"}, 1, {}},
      {"speed-limit, all regions",
       {"speed-limit", "--body-region", "all", "--robot-mass", "10kg", "--contact-area", "1cm2", "--material",
        "PU foam PORON 4701-30 320"},
       1,
       {"largest safe impact speed [m/s]"}},
      {"robot --trajectory", {"robot", "--urdf", kFr3, "--tip", "fr3_link8", "--trajectory", kPick}, 1, {}},
      {"robot --trajectory, regions",
       {"robot", "--urdf", kFr3, "--tip", "fr3_link8", "--trajectory", kPick, "--body-region", "chest,hands-fingers",
        "--contact-area", "1cm2"},
       1,
       {"largest ratio over the regions", "time [s]"}},
      {"audit",
       {"audit", "--urdf", kFr3, "--tip", "fr3_link8", "--trajectory", kPick, "--covering-thickness", "10mm",
        "--covering-modulus", "0.5MPa", "--covering-poisson", "0.45", "--contact-area", "1cm2", "--flat-face-radius",
        "20mm", "--body-region", "chest,hands-fingers"},
       2,
       {"Governing ratio per link and region", "fr3_link7"}},
  };
  for (const Mode& mode : modes) {
    INFO(mode.name);
    const std::string html = Report(mode.args);
    CHECK(Count(html, "<figure class=\"chart\"") == mode.charts);
    for (const std::string& text : mode.shows) CHECK(html.find(text) != std::string::npos);
  }
}
