// Outputs never touch inputs or each other (issue 33): every output file of a run (--report,
// --csv, --samples-csv, --history, --plot, --tolerance-plot) is compared by file identity
// (device and inode after following links; directory and name for a file not made yet) with
// every input file (--scene, --catalog, --urdf, --trajectory, --surface-file,
// --link-coverings) and every other output. A clash is one exit-2 line naming both flags and
// the path, before anything runs or is written.
#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

#include <catch2/catch.hpp>

#include "cli_test_support.hpp"
#include "run_context.hpp"

namespace {

namespace fs = std::filesystem;
using covopt::cli::InputFileRole;
using covopt::cli::IsOutputFileFlag;
using covopt::cli::testing::CliRun;
using covopt::cli::testing::ReadFile;
using covopt::cli::testing::Run;
using covopt::cli::testing::SplitLines;
using covopt::cli::testing::TempDir;
using Catch::Contains;

const std::string kFr3 = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3.urdf";
const std::string kPick = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3_pick.csv";

/// A clash: exit 2, nothing on stdout, one line on stderr naming both flags and `path`.
void RequireClash(const CliRun& run, const std::string& first_flag, const std::string& second_flag,
                  const std::string& path) {
  INFO(run.err);
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK(SplitLines(run.err).size() == 1);
  CHECK_THAT(run.err, Contains(first_flag + " and " + second_flag + " name the same file"));
  CHECK_THAT(run.err, Contains("'" + path + "'"));
}

/// The audit of the FR3 pick move with a 10 mm covering (test_audit.cpp's).
std::vector<std::string> Fr3Audit(const std::string& urdf, const std::string& trajectory,
                                  std::vector<std::string> more) {
  std::vector<std::string> args = {"audit",           "--urdf",         urdf,         "--tip",
                                   "fr3_link8",       "--trajectory",   trajectory,   "--covering-thickness",
                                   "10mm",            "--covering-modulus", "0.5MPa", "--covering-poisson",
                                   "0.45",            "--contact-area", "1cm2",       "--flat-face-radius",
                                   "20mm"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

}  // namespace

TEST_CASE("an output naming an input is refused before anything runs, and the input is kept",
          "[outputs][identity]") {
  const TempDir dir;
  const std::string robot_model = ReadFile(kFr3), trajectory = ReadFile(kPick);
  const std::string urdf = dir.Write("robot.html", robot_model).string();
  const std::string pick = dir.Write("t.csv", trajectory).string();

  SECTION("--report over the --urdf") {
    RequireClash(Run({"robot", "--urdf", urdf, "--tip", "fr3_link8", "--trajectory", pick, "--report", urdf}),
                 "--urdf", "--report", urdf);
  }
  SECTION("--csv over the --trajectory") {
    RequireClash(Run({"robot", "--urdf", urdf, "--tip", "fr3_link8", "--trajectory", pick, "--csv", pick}),
                 "--trajectory", "--csv", pick);
  }
  SECTION("--report over a trajectory named .html") {
    const std::string html_pick = dir.Write("t.html", trajectory).string();
    RequireClash(Run({"robot", "--urdf", urdf, "--tip", "fr3_link8", "--trajectory", html_pick, "--report",
                      html_pick}),
                 "--trajectory", "--report", html_pick);
    CHECK(ReadFile(html_pick) == trajectory);
  }
  SECTION("another spelling of the same path: ./, dir/../") {
    fs::create_directory(dir / "sub");
    const std::string dotted = (dir.path() / "." / "robot.html").string();
    const std::string up = (dir.path() / "sub" / ".." / "robot.html").string();
    const CliRun a = Run({"robot", "--urdf", urdf, "--tip", "fr3_link8", "--trajectory", pick, "--report", dotted});
    RequireClash(a, "--urdf", "--report", dotted);
    CHECK_THAT(a.err, Contains("'" + urdf + "' and '" + dotted + "'"));
    RequireClash(Run({"robot", "--urdf", urdf, "--tip", "fr3_link8", "--trajectory", pick, "--report", up}),
                 "--urdf", "--report", up);
  }
  SECTION("a symbolic link to the input") {
    const fs::path link = dir / "link.html";
    fs::create_symlink(urdf, link);
    RequireClash(Run({"robot", "--urdf", urdf, "--tip", "fr3_link8", "--trajectory", pick, "--report",
                      link.string()}),
                 "--urdf", "--report", link.string());
    CHECK(fs::is_symlink(link));
  }
  SECTION("a hard link to the input") {
    const fs::path hard = dir / "hard.html";
    fs::create_hard_link(urdf, hard);
    RequireClash(Run({"robot", "--urdf", urdf, "--tip", "fr3_link8", "--trajectory", pick, "--report",
                      hard.string()}),
                 "--urdf", "--report", hard.string());
    CHECK(ReadFile(hard) == robot_model);
  }
  SECTION("a scene file and a catalog") {
    const std::string scene = dir.Write("scene.toml", "[robot]\nspeed = \"1 m/s\"\n").string();
    RequireClash(Run({"simulate", "--scene", scene, "--history", scene}), "--scene", "--history", scene);
    CHECK(ReadFile(scene) == "[robot]\nspeed = \"1 m/s\"\n");
    const std::string catalog = dir.Write("catalog.toml", "# no materials\n").string();
    RequireClash(Run({"optimize", "--catalog", catalog, "--csv", catalog}), "--catalog", "--csv", catalog);
    CHECK(ReadFile(catalog) == "# no materials\n");
  }
  CHECK(ReadFile(urdf) == robot_model);
  CHECK(ReadFile(pick) == trajectory);
}

TEST_CASE("two outputs naming one file are refused before anything is written", "[outputs][identity]") {
  const TempDir dir;
  SECTION("--report and --history") {
    const std::string file = (dir / "r.html").string();
    RequireClash(Run({"simulate", "--history", file, "--report", file}), "--history", "--report", file);
    CHECK_FALSE(fs::exists(file));
  }
  SECTION("--report and --csv") {
    const std::string file = (dir / "r.html").string();
    RequireClash(Run({"speed-limit", "--csv", file, "--report", file}), "--csv", "--report", file);
    CHECK_FALSE(fs::exists(file));
  }
  SECTION("--csv and --samples-csv") {
    const std::string file = (dir / "a.csv").string();
    RequireClash(Run(Fr3Audit(kFr3, kPick, {"--csv", file, "--samples-csv", file})), "--csv", "--samples-csv",
                 file);
    CHECK_FALSE(fs::exists(file));
  }
  SECTION("a file not made yet, named through a dangling symbolic link") {
    const fs::path link = dir / "link.html";
    fs::create_symlink("new.html", link);
    const std::string file = (dir / "new.html").string();
    RequireClash(Run({"simulate", "--history", link.string(), "--report", file}), "--history", "--report", file);
    CHECK_FALSE(fs::exists(file));
  }
  SECTION("an existing file kept as it was") {
    const std::string file = dir.Write("old.html", "the previous report").string();
    RequireClash(Run({"simulate", "--history", file, "--report", file}), "--history", "--report", file);
    CHECK(ReadFile(file) == "the previous report");
  }
}

TEST_CASE("distinct files and /dev/null twice run as before", "[outputs][identity]") {
  const TempDir dir;
  const CliRun run = Run({"simulate", "--history", (dir / "h.csv").string(), "--report", (dir / "r.html").string()});
  INFO(run.err);
  CHECK(run.exit_code == 0);
  CHECK(fs::exists(dir / "h.csv"));
  CHECK(fs::exists(dir / "r.html"));
  // A character device may take any number of outputs.
  const CliRun devices = Run(Fr3Audit(kFr3, kPick, {"--csv", "/dev/null", "--samples-csv", "/dev/null"}));
  INFO(devices.err);
  CHECK(devices.exit_code == 0);
}

TEST_CASE("every FILE flag of every subcommand is an input or an output of the identity check",
          "[outputs][identity]") {
  // The subcommands as `covopt --help` lists them, and their own subcommands (materials list, ...).
  std::vector<std::vector<std::string>> commands;
  const std::regex subcommand_line(R"(^  ([a-z][a-z-]+)\s{2,}\S)");
  std::vector<std::vector<std::string>> pending = {{}};
  while (!pending.empty()) {
    const std::vector<std::string> command = pending.back();
    pending.pop_back();
    std::vector<std::string> args = command;
    args.push_back("--help");
    const CliRun help = Run(args);
    REQUIRE(help.exit_code == 0);
    commands.push_back(command);
    bool in_subcommands = false;
    for (const std::string& line : SplitLines(help.out)) {
      if (line.rfind("SUBCOMMANDS", 0) == 0 || line.rfind("Subcommands", 0) == 0) {
        in_subcommands = true;
        continue;
      }
      if (in_subcommands && !line.empty() && line.front() != ' ') in_subcommands = false;
      std::smatch m;
      if (in_subcommands && std::regex_search(line, m, subcommand_line)) {
        std::vector<std::string> sub = command;
        sub.push_back(m[1]);
        pending.push_back(sub);
      }
    }
  }
  REQUIRE(commands.size() >= 10);
  const std::regex file_flag(R"((--[a-z][a-z-]+)(?:,\s*-\w)?\s+(?:\[?)FILE)");
  std::set<std::string> seen;
  for (const std::vector<std::string>& command : commands) {
    std::vector<std::string> args = command;
    args.push_back("--help");
    for (const std::string& line : SplitLines(Run(args).out)) {
      std::smatch m;
      if (!std::regex_search(line, m, file_flag)) continue;
      const std::string flag = m[1];
      INFO(flag);
      CHECK((!InputFileRole(flag).empty() || IsOutputFileFlag(flag)));
      seen.insert(flag);
    }
  }
  for (const char* flag : {"--report", "--csv", "--samples-csv", "--history", "--plot", "--tolerance-plot",
                           "--scene", "--catalog", "--urdf", "--trajectory", "--surface-file", "--link-coverings"}) {
    INFO(flag);
    CHECK(seen.count(flag) == 1);
  }
}
