// The command-line shell around the subcommands (cli/app.cpp, cli/parse_errors.hpp): a
// single-value option given more than once is covopt's own one-line message naming the flag
// and every value typed, exit 2 and nothing on stdout, never CLI11's "At Most 1 required
// but received 2". The options are read from each subcommand's --help, so an option added
// later is covered too; nested subcommands ("materials find") are named in full.

#include <regex>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include "cli_test_support.hpp"

using Catch::Matchers::Contains;
using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using covopt::cli::testing::SplitLines;

namespace {

std::vector<std::string> Words(const std::string& text) {
  std::vector<std::string> words;
  std::string word;
  for (const char c : text) {
    if (c == ' ') {
      if (!word.empty()) words.push_back(word);
      word.clear();
    } else {
      word += c;
    }
  }
  if (!word.empty()) words.push_back(word);
  return words;
}

/// A long option that takes one value, as --help lists it: the flag and two values it
/// accepts before any conversion (the first two of a {a,b,...} set, else "1" and "2").
struct SingleValueOption {
  std::string flag;
  std::string first;
  std::string second;
};

/// The single-value options of `covopt <command> --help`: "  --flag TYPE  help" lines,
/// skipping flags (no TYPE) and repeatable options (TYPE followed by "...").
std::vector<SingleValueOption> SingleValueOptions(const std::string& command) {
  std::vector<std::string> args = Words(command);
  args.emplace_back("--help");
  const CliRun help = Run(args);
  REQUIRE(help.exit_code == 0);
  // The flag, exactly one space, the type name, then the rest of the line.
  const std::regex line(R"(^\s+(?:-\w,)?(--[\w-]+) (\S+)(.*)$)");
  const std::regex members(R"(\{([^,}]+),([^,}]+)[,}])");
  std::vector<SingleValueOption> options;
  for (const std::string& text : SplitLines(help.out)) {
    std::smatch m;
    if (!std::regex_match(text, m, line)) continue;
    const std::string rest = m[3];
    if (rest.rfind(" ...", 0) == 0) continue;  // repeatable
    SingleValueOption option{m[1], "1", "2"};
    const std::string type = m[2];
    std::smatch set;
    if (std::regex_search(type, set, members)) {
      option.first = set[1];
      option.second = set[2];
    } else if (type.rfind("FILE.html", 0) == 0) {  // --report checks its extension first
      option.first = "1.html";
      option.second = "2.html";
    } else if (type == "SHARE") {  // --margin-threshold: a bare 1 is refused as a likely percentage
      option.first = "1%";
      option.second = "2%";
    }
    options.push_back(option);
  }
  return options;
}

}  // namespace

TEST_CASE("a single-value option given twice names the flag and both values, in every subcommand",
          "[cli][errors]") {
  const std::vector<std::string> commands = {"simulate",       "optimize",       "sweep",
                                             "workprecision",  "materials list", "materials show",
                                             "materials find"};
  std::size_t checked = 0;
  for (const std::string& command : commands) {
    const std::vector<SingleValueOption> options = SingleValueOptions(command);
    for (const SingleValueOption& option : options) {
      std::vector<std::string> args = Words(command);
      args.insert(args.end(), {option.flag, option.first, option.flag, option.second});
      const CliRun run = Run(args);
      INFO("covopt " << command << ' ' << option.flag << ": " << run.err);
      CHECK(run.exit_code == 2);
      CHECK(run.out.empty());
      CHECK(run.err == fmt::format("covopt {}: error: {} given twice ('{}' and '{}'); give it "
                                   "once\n",
                                   command, option.flag, option.first, option.second));
      CHECK_THAT(run.err, !Contains("At Most"));
      ++checked;
    }
  }
  // The help of every subcommand was read: scene flags alone are 15 per scene command.
  CHECK(checked > 60);
}

TEST_CASE("repeated options: the brief's example, three values, and the = spelling",
          "[cli][errors]") {
  CliRun run = Run({"simulate", "--speed", "1", "--speed", "2"});
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK(run.err ==
        "covopt simulate: error: --speed given twice ('1' and '2'); give it once\n");

  run = Run({"optimize", "--top", "3", "--top=4", "--top", "5"});
  CHECK(run.exit_code == 2);
  CHECK(run.err ==
        "covopt optimize: error: --top given 3 times ('3', '4' and '5'); give it once\n");

  run = Run({"sweep", "--x", "speed=1m/s..2m/s", "--x=speed=1m/s..3m/s"});
  CHECK(run.exit_code == 2);
  CHECK(run.err == "covopt sweep: error: --x given twice ('speed=1m/s..2m/s' and "
                   "'speed=1m/s..3m/s'); give it once\n");
}

TEST_CASE("errors inside a nested subcommand name it in full and point at its help",
          "[cli][errors]") {
  const CliRun run = Run({"materials", "find", "--min-modulus", "1MPa"});
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Contains("covopt materials find: error: unknown option '--min-modulus'; "
                               "did you mean '--modulus'?"));
  const CliRun extra = Run({"materials", "list", "foam"});
  CHECK(extra.exit_code == 2);
  CHECK_THAT(extra.err, Contains("covopt materials list: error:") &&
                            Contains("covopt materials list --help"));
}

TEST_CASE("flags given twice are harmless: the answer is the same", "[cli]") {
  const CliRun once = Run({"simulate", "--json"});
  const CliRun twice = Run({"simulate", "--json", "--json"});
  REQUIRE(once.exit_code == 0);
  CHECK(twice.exit_code == 0);
  CHECK(covopt::cli::testing::WithoutProvenance(twice.out) == covopt::cli::testing::WithoutProvenance(once.out));
}
