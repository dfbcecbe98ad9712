// --report FILE.html|FILE.pdf (cli/report_option.hpp): the extension checked before any
// computation, the report written only after a run that succeeded, beside --json or the table.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/report/provenance.hpp"
#include "report_option.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::ReadFile;
using covopt::cli::testing::Run;
using covopt::cli::testing::TempDir;
using Catch::Contains;

const std::string kFr3 = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3.urdf";
const std::string kPick = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3_pick.csv";

std::vector<std::string> With(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

/// Runs `args` with --report FILE.html and checks that the report is an HTML document naming
/// this build's commit, and that stdout is what the same run prints without --report (but for
/// the wall times in it: digits are dropped).
void RequireReport(const std::vector<std::string>& args) {
  const TempDir dir;
  const std::string file = (dir / "report.html").string();
  const CliRun plain = Run(args);
  const CliRun reported = Run(With(args, {"--report", file}));
  INFO(reported.err);
  REQUIRE(reported.exit_code == 0);
  REQUIRE(std::filesystem::exists(file));
  const std::string html = ReadFile(file);
  CHECK_THAT(html.substr(0, 15), Catch::Contains("<!DOCTYPE html", Catch::CaseSensitive::No));
  CHECK_THAT(html, Catch::Contains(covopt::report::CovoptCommit()));
  const auto without_digits = [](std::string text) {
    text.erase(std::remove_if(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }), text.end());
    return text;
  };
  if (std::find(args.begin(), args.end(), "--json") == args.end()) {
    CHECK(without_digits(reported.out) == without_digits(plain.out));
  }
}

}  // namespace

TEST_CASE("The --report FILE.html on simulate, optimize, speed-limit, robot --trajectory and audit", "[report]") {
  RequireReport({"simulate"});
  RequireReport({"simulate", "--json"});
  RequireReport({"simulate", "--head-mass", "3.7kg..5.8kg"});
  RequireReport({"simulate", "--robot-mass", "10kg", "--speed", "0.5m/s", "--body-region", "chest"});
  RequireReport({"simulate", "--speed", "8m/s"});  // UNSAFE is a result, and is reported
  RequireReport({"optimize", "--material", "PU foam PORON 4701-30 320"});
  RequireReport({"speed-limit", "--material", "PU foam PORON 4701-30 320", "--json"});
  RequireReport({"robot", "--urdf", kFr3, "--tip", "fr3_link8", "--trajectory", kPick});
  RequireReport({"audit", "--urdf", kFr3, "--tip", "fr3_link8", "--trajectory", kPick, "--covering-thickness",
                 "10mm", "--covering-modulus", "0.5MPa", "--covering-poisson", "0.45", "--contact-area", "1cm2",
                 "--flat-face-radius", "20mm", "--body-region", "chest"});
}

TEST_CASE("The --report option: another extension is bad input before any computation", "[report]") {
  const TempDir dir;
  for (const std::string& name : {std::string("r.txt"), std::string("r.svg"), std::string("report"),
                                  std::string("r.html.bak")}) {
    const std::string file = (dir / name).string();
    // --max-steps 1 would fail the computation: the flag is refused before it runs.
    const CliRun run = Run({"simulate", "--method", "cvode", "--max-steps", "1", "--report", file});
    INFO(run.err);
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK_THAT(run.err, Catch::Contains("--report") && Catch::Contains(file));
    CHECK(!std::filesystem::exists(file));
  }
  for (const std::string& name : {std::string("R.HTML"), std::string("r.htm")}) {
    const CliRun run = Run({"simulate", "--report", (dir / name).string()});
    CHECK(run.exit_code == 0);
    CHECK(std::filesystem::exists(dir / name));
  }
}

TEST_CASE("The --report option: a run that failed writes no report", "[report]") {
  const TempDir dir;
  const std::string file = (dir / "report.html").string();
  // The computation fails: the integrator's step limit.
  const CliRun failed = Run({"simulate", "--method", "cvode", "--max-steps", "10", "--report", file});
  CHECK(failed.exit_code == 1);
  // Bad input found after parsing.
  const CliRun bad = Run({"simulate", "--speed", "-1m/s", "--report", file});
  CHECK(bad.exit_code == 2);
  const CliRun optimize = Run({"optimize", "--material", "no such foam", "--report", file});
  CHECK(optimize.exit_code == 2);
  CHECK(!std::filesystem::exists(file));
  // --report is the trajectory check's: refused on robot's reflected mass.
  const CliRun robot = Run({"robot", "--urdf", kFr3, "--tip", "fr3_link8", "--joints", "0,0,0,-1.5,0,1.5,0.8",
                            "--report", file});
  CHECK(robot.exit_code == 2);
  CHECK_THAT(robot.err, Catch::Contains("--report applies with --trajectory"));
  CHECK(!std::filesystem::exists(file));
}

TEST_CASE("The sign-off flags need --report, on every command that has it", "[report]") {
  const std::vector<std::vector<std::string>> commands{
      {"simulate"},
      {"optimize"},
      {"speed-limit"},
      {"robot", "--urdf", kFr3, "--tip", "fr3_link8", "--trajectory", kPick},
      {"audit", "--urdf", kFr3, "--tip", "fr3_link8", "--trajectory", kPick}};
  for (const std::vector<std::string>& command : commands) {
    for (const std::string flag : {"--project", "--cell", "--assessor", "--note", "--margin-threshold",
                                   "--report-appendix"}) {
      const CliRun run = Run(With(command, {flag, flag == "--report-appendix" ? "full" : "0.2"}));
      CAPTURE(command.front(), flag);
      CHECK(run.exit_code == 2);
      CHECK(run.out.empty());
      CHECK_THAT(run.err, Contains(flag + " requires --report"));
    }
  }
}

TEST_CASE("Bad sign-off values are refused before any computation, naming the flag", "[report]") {
  const TempDir dir;
  const std::string file = (dir / "report.html").string();
  const auto refused = [&](const std::string& flag, const std::string& value) {
    // --max-steps 1 would fail the computation: the flag is refused before it runs.
    const CliRun run = Run({"simulate", "--method", "cvode", "--max-steps", "1", "--report", file, flag, value});
    CAPTURE(flag, value);
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK(!std::filesystem::exists(file));
    return run.err;
  };
  CHECK_THAT(refused("--margin-threshold", "10"), Contains("--margin-threshold: a bare number is a share in [0, 1); "
                                                           "write 10% for 10 per cent (got '10')"));
  CHECK_THAT(refused("--margin-threshold", "100%"), Contains("--margin-threshold: must be a share in [0, 1)"));
  CHECK_THAT(refused("--margin-threshold", "lots"), Contains("--margin-threshold: expected a share"));
  CHECK_THAT(refused("--report-appendix", "all"), Contains("--report-appendix: the appendix must be none, summary or full"));
  CHECK_THAT(refused("--project", std::string(2001, 'p')), Contains("--project: 2001 characters"));
  CHECK_THAT(refused("--cell", "a\nb"), Contains("--cell: a control character"));
  CHECK_THAT(refused("--assessor", "\x1b[1m"), Contains("--assessor: a control character"));
}

TEST_CASE("The scene file's [report] table: checked before any computation, the flags win over it", "[report]") {
  const TempDir dir;
  const std::string scene = (dir / "s.toml").string();
  const std::string file = (dir / "report.html").string();
  const auto write_scene = [&](const std::string& text) {
    std::ofstream(scene) << text;
  };
  write_scene("[report]\nmargin_threshold = \"150%\"\n");
  for (const std::string command : {"simulate", "optimize", "speed-limit"}) {
    const CliRun run = Run({command, "--scene", scene, "--report", file});
    CAPTURE(command);
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.err, Contains(scene + ":2:20: report.margin_threshold: must be a share in [0, 1)"));
    CHECK(!std::filesystem::exists(file));
  }
  write_scene("[report]\nprojct = \"x\"\n");
  CHECK_THAT(Run({"simulate", "--scene", scene}).err, Contains("did you mean 'report.project'?"));

  // The settings the report is made with: the defaults, the file's, then the flags'.
  covopt::cli::ResultInputs inputs;
  inputs.file_report = {{"project", std::string("From the file"), "s.toml:2:11: report.project"},
                        {"note", std::string("kept\nfrom the file"), "s.toml:3:8: report.note"},
                        {"margin_threshold", 0.3, "s.toml:4:20: report.margin_threshold"}};
  covopt::cli::ReportFlags flags;
  CHECK(covopt::cli::ReportInfoOf(flags, {}).margin_threshold == covopt::kDefaultMarginThreshold);
  flags.project = "From the flag";
  flags.cell = "C2";
  flags.margin_threshold = "5%";
  flags.appendix = "none";
  const covopt::report::ReportInfo info = covopt::cli::ReportInfoOf(flags, inputs);
  CHECK(info.project == "From the flag");
  CHECK(info.cell == "C2");
  CHECK(info.note == "kept\nfrom the file");
  CHECK(info.assessor.empty());
  CHECK(info.margin_threshold == Approx(0.05));
  CHECK(info.appendix == covopt::report::ReportAppendix::kNone);

  // A good table and every flag: the report is written.
  write_scene("[report]\nproject = \"Line 4\"\nassessor = \"A. Person\"\nappendix = \"full\"\n");
  const CliRun run = Run({"simulate", "--scene", scene, "--report", file, "--project", "Line 5", "--cell", "C2",
                          "--note", "first line\nsecond line", "--margin-threshold", "20%", "--report-appendix", "none"});
  INFO(run.err);
  CHECK(run.exit_code == 0);
  CHECK(std::filesystem::exists(file));
}
