// Every error is one line, whatever value it echoes, and names the flag and its allowed range
// (issue 33): control characters and NUL bytes in an echoed value are shown escaped (a link
// name with line breaks, a trajectory cell holding a NUL); audit --design's --max-thickness
// and --thickness-step are checked against optimize's ranges by the flag's name.
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "cli_test_support.hpp"
#include "errors.hpp"

namespace {

using covopt::cli::ShortenLongWords;
using covopt::cli::testing::CliRun;
using covopt::cli::testing::ReadFile;
using covopt::cli::testing::Run;
using covopt::cli::testing::SplitLines;
using covopt::cli::testing::TempDir;
using Catch::Contains;

const std::string kFr3 = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3.urdf";
const std::string kPick = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3_pick.csv";

/// Exit 2, nothing on stdout, and one line on stderr.
void RequireOneLineBadInput(const CliRun& run) {
  INFO(run.err);
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK(SplitLines(run.err).size() == 1);
}

std::vector<std::string> Fr3Audit(std::vector<std::string> more) {
  std::vector<std::string> args = {"audit",           "--urdf",         kFr3,         "--tip",
                                   "fr3_link8",       "--trajectory",   kPick,        "--covering-thickness",
                                   "10mm",            "--covering-modulus", "0.5MPa", "--covering-poisson",
                                   "0.45",            "--contact-area", "1cm2",       "--flat-face-radius",
                                   "20mm"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

}  // namespace

TEST_CASE("an echoed value's control characters and NUL bytes are escaped", "[bad-input][messages]") {
  constexpr char kRaw[] = "a\nb\tc\rd\0e\x1b[0m\x7f";
  CHECK(ShortenLongWords(std::string(kRaw, sizeof kRaw - 1)) == "a\\nb\\tc\\rd\\0e\\x1b[0m\\x7f");
  CHECK(ShortenLongWords("plain text, 'quoted' and \xc3\xa9") == "plain text, 'quoted' and \xc3\xa9");
}

TEST_CASE("a link name with line breaks is one line, escaped", "[bad-input][messages]") {
  const CliRun run = Run({"robot", "--urdf", kFr3, "--tip", "a\nb\nc\nd", "--trajectory", kPick});
  RequireOneLineBadInput(run);
  CHECK_THAT(run.err, Contains("'a\\nb\\nc\\nd'"));
}

TEST_CASE("a value with a line break is one line, escaped, in the quantity parser's echo too",
          "[bad-input][messages]") {
  const CliRun run = Run({"simulate", "--speed", "2\nm/s"});
  RequireOneLineBadInput(run);
  CHECK_THAT(run.err, Contains("--speed"));
  CHECK_THAT(run.err, Contains("2\\nm/s"));
}

TEST_CASE("a NUL byte in a trajectory cell does not cut the message", "[bad-input][messages]") {
  const TempDir dir;
  std::string csv = ReadFile(kPick);
  // The first sample's first position: "<digits>" -> "<digits>\0x".
  std::size_t line = 0;
  while (csv[line] == '#' || csv.compare(line, 4, "time") == 0) line = csv.find('\n', line) + 1;
  const std::size_t comma = csv.find(',', line);
  csv.insert(csv.find(',', comma + 1), std::string("\0x", 2));
  const std::string file = dir.Write("nul.csv", csv).string();
  const CliRun run = Run({"robot", "--urdf", kFr3, "--tip", "fr3_link8", "--trajectory", file});
  RequireOneLineBadInput(run);
  CHECK_THAT(run.err, Contains("\\0x'"));
  CHECK_THAT(run.err, Contains("in decimal"));  // the message goes on past the NUL
}

TEST_CASE("a NUL in a scene file's value or key does not cut the message", "[bad-input][messages]") {
  const TempDir dir;
  const CliRun material =
      Run({"simulate", "--scene", dir.Write("m.toml", "[covering]\nmaterial = \"PORON\\u0000x\"\n").string()});
  RequireOneLineBadInput(material);
  CHECK_THAT(material.err, Contains("no material 'PORON\\0x' in the catalog"));
  const CliRun speed = Run({"simulate", "--scene", dir.Write("s.toml", "[robot]\nspeed = \"2\\u0000m/s\"\n").string()});
  RequireOneLineBadInput(speed);
  CHECK_THAT(speed.err, Contains("(got '2\\0m/s')"));
  const CliRun key = Run({"simulate", "--scene", dir.Write("k.toml", "[robot]\n\"spe\\u0000ed\" = 2\n").string()});
  RequireOneLineBadInput(key);
  CHECK_THAT(key.err, Contains("unknown key 'robot.spe\\0ed'; did you mean 'robot.speed'?"));
  const CliRun table = Run({"simulate", "--scene", dir.Write("t.toml", "[\"ro\\u0000bot\"]\nspeed = 2\n").string()});
  RequireOneLineBadInput(table);
  CHECK_THAT(table.err, Contains("unknown table 'ro\\0bot'"));
}

TEST_CASE("a NUL or a line break in a catalog's or a surface file's name does not cut or break the message",
          "[bad-input][messages]") {
  const TempDir dir;
  const std::string entry =
      "[[material]]\nname = \"soft\\u0000foam\"\nfamily = \"foam\"\nyoungs_modulus_Pa = 2.5e6\npoisson_ratio = 0.3\n"
      "density_kg_per_m3 = 30\nmodulus_basis = \"compressive\"\nsource = \"a datasheet\"\n";
  const CliRun twice =
      Run({"materials", "list", "--catalog", dir.Write("c.toml", entry + entry).string()});
  RequireOneLineBadInput(twice);
  CHECK_THAT(twice.err, Contains("duplicate material name 'soft\\0foam'"));
  const CliRun surface = Run(Fr3Audit(
      {"--surface-file",
       dir.Write("s.toml", "[[link]]\nname = \"fr3\\nlink3\\u0000x\"\n"
                           "points = [ { at_m = [0, 0, 0], radius_m = 0.05 } ]\n")
           .string()}));
  RequireOneLineBadInput(surface);
  CHECK_THAT(surface.err, Contains("link 'fr3\\nlink3\\0x'"));
}

TEST_CASE("audit --design's thickness flags name the flag, the value and the range", "[bad-input][messages]") {
  SECTION("--max-thickness 0") {
    const CliRun run = Run(Fr3Audit({"--design", "--max-thickness", "0"}));
    RequireOneLineBadInput(run);
    CHECK_THAT(run.err, Contains("--max-thickness must be in (0.1 mm, 1 m] (got '0')"));
    CHECK_THAT(run.err, !Contains("_m"));
  }
  SECTION("--thickness-step 1m") {
    const CliRun run = Run(Fr3Audit({"--design", "--thickness-step", "1m"}));
    RequireOneLineBadInput(run);
    CHECK_THAT(run.err, Contains("--thickness-step must be in [0, 10 mm] (got '1m')"));
  }
  SECTION("optimize: the same ranges and words") {
    const CliRun zero = Run({"optimize", "--max-thickness", "0"});
    RequireOneLineBadInput(zero);
    CHECK_THAT(zero.err, Contains("--max-thickness must be in (0.1 mm, 1 m] (got '0')"));
    const CliRun step = Run({"optimize", "--thickness-step", "1m"});
    RequireOneLineBadInput(step);
    CHECK_THAT(step.err, Contains("--thickness-step must be in [0, 10 mm] (got '1m')"));
  }
}
