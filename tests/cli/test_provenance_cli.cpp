// Every JSON object a covopt command prints ends with the same provenance block
// (covopt/report/provenance.hpp): this build's version and commit, the command line, the date
// and the SHA-256 of every input file the flags named, with its role.
#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/report/provenance.hpp"
#include "run_context.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using covopt::cli::testing::ScopedEnv;
using covopt::cli::testing::TempDir;
using Json = nlohmann::ordered_json;

const std::string kFr3 = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3.urdf";
const std::string kPick = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3_pick.csv";
const std::string kPaperScene = std::string(COVOPT_CLI_EXAMPLES_DIR) + "/paper_scene.toml";

/// The version `covopt --version` prints.
std::string Version() {
  const CliRun run = Run({"--version"});
  REQUIRE(run.exit_code == 0);
  std::string text = run.out.substr(run.out.rfind(' ') + 1);
  while (!text.empty() && text.back() == '\n') text.pop_back();
  return text;
}

/// The command line of `covopt args...` as the provenance writes it.
std::string CommandOf(const std::vector<std::string>& args) {
  std::vector<const char*> argv{"covopt"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  return covopt::report::CommandLine(argv);
}

/// Runs the command and checks its JSON object's provenance: the last key, once in the whole
/// text, this build's version and commit, the command line, and `inputs` (role, path) with the
/// files' digests and sizes, in any order.
Json RequireProvenance(const std::vector<std::string>& args, std::vector<std::pair<std::string, std::string>> inputs) {
  const CliRun run = Run(args);
  INFO(CommandOf(args));
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const Json j = Json::parse(run.out);
  REQUIRE(j.is_object());
  CHECK(j.items().begin() != j.items().end());
  std::string last;
  for (const auto& item : j.items()) last = item.key();
  CHECK(last == "provenance");
  // Once: a command run inside another (the head of --body-region all) adds none.
  const std::size_t first = run.out.find("\"provenance\"");
  CHECK(run.out.find("\"provenance\"", first + 1) == std::string::npos);
  const Json& p = j["provenance"];
  std::vector<std::string> keys;
  for (const auto& item : p.items()) keys.push_back(item.key());
  CHECK(keys == std::vector<std::string>{"software", "version", "commit", "command", "date_utc", "inputs"});
  CHECK(p["software"] == "covopt");
  CHECK(p["version"] == Version());
  CHECK(p["commit"] == covopt::report::CovoptCommit());
  CHECK(p["command"] == CommandOf(args));
  std::vector<std::pair<std::string, std::string>> got;
  for (const Json& f : p["inputs"]) {
    got.emplace_back(f["role"], f["path"]);
    const std::string path = f["path"];
    CHECK(f["sha256"] == covopt::report::Sha256OfFile(path));
    CHECK(f["size_bytes"] == static_cast<long long>(std::filesystem::file_size(path)));
  }
  std::sort(got.begin(), got.end());
  std::sort(inputs.begin(), inputs.end());
  CHECK(got == inputs);
  return j;
}

}  // namespace

TEST_CASE("simulate --json in every mode ends with the provenance block", "[provenance]") {
  RequireProvenance({"simulate", "--json"}, {});
  RequireProvenance({"simulate", "--scene", kPaperScene, "--json"}, {{"scene", kPaperScene}});
  RequireProvenance({"simulate", "--head-mass", "3.7kg..5.8kg", "--json"}, {});
  RequireProvenance({"simulate", "--sensitivities", "--json"}, {});
  RequireProvenance({"simulate", "--robot-mass", "10kg", "--speed", "0.5m/s", "--body-region", "chest", "--json"}, {});
  // The head's object nested in the regions' carries none of its own.
  const Json all = RequireProvenance({"simulate", "--robot-mass", "10kg", "--speed", "0.5m/s", "--body-region", "all",
                                      "--contact-area", "1cm2", "--scene", kPaperScene, "--json"},
                                     {{"scene", kPaperScene}});
  CHECK(all.contains("head"));
}

TEST_CASE("optimize, speed-limit, robot, audit, materials and body-regions --json carry it", "[provenance]") {
  const TempDir dir;
  RequireProvenance({"optimize", "--json", "--material", "PU foam PORON 4701-30 320"}, {});
  RequireProvenance({"speed-limit", "--json", "--material", "PU foam PORON 4701-30 320", "--robot-mass", "5kg,10kg"}, {});
  RequireProvenance({"robot", "--urdf", kFr3, "--tip", "fr3_link8", "--joints", "0,0,0,-1.5,0,1.5,0.8", "--json"},
                    {{"urdf", kFr3}});
  RequireProvenance({"robot", "--urdf", kFr3, "--tip", "fr3_link8", "--trajectory", kPick, "--json"},
                    {{"urdf", kFr3}, {"trajectory", kPick}});
  const std::string links =
      dir.Write("links.toml", "[[link]]\nname = \"fr3_link4\"\nmodulus = \"0.2MPa\"\npoisson = 0.45\n"
                              "thickness = \"30mm\"\n")
          .string();
  RequireProvenance({"audit", "--urdf", kFr3, "--tip", "fr3_link8", "--trajectory", kPick, "--covering-thickness",
                     "10mm", "--covering-modulus", "0.5MPa", "--covering-poisson", "0.45", "--contact-area", "1cm2",
                     "--flat-face-radius", "20mm", "--body-region", "chest", "--link-coverings", links, "--json"},
                    {{"urdf", kFr3}, {"trajectory", kPick}, {"link-coverings", links}});
  const std::string catalog = dir.Write("my catalog.toml", "[[material]]\nname = \"Test foam\"\nfamily = \"foam\"\n"
                                                           "youngs_modulus_Pa = 5e5\nmodulus_basis = \"hardness\"\n"
                                                           "source = \"a test\"\n")
                                  .string();
  const Json material = RequireProvenance(
      {"materials", "show", "Test foam", "--no-builtin", "--catalog", catalog, "--json"}, {{"catalog", catalog}});
  CHECK(material["name"] == "Test foam");
  RequireProvenance({"body-regions", "show", "chest", "--json"}, {});
}

TEST_CASE("a JSON array stays an array, without provenance", "[provenance]") {
  for (const std::vector<std::string>& args : {std::vector<std::string>{"materials", "list", "--json"},
                                               std::vector<std::string>{"body-regions", "list", "--json"}}) {
    const CliRun run = Run(args);
    REQUIRE(run.exit_code == 0);
    CHECK(Json::parse(run.out).is_array());
  }
}

TEST_CASE("SOURCE_DATE_EPOCH fixes the date, and without it the date is now", "[provenance]") {
  const ScopedEnv epoch("SOURCE_DATE_EPOCH", "1700000000");
  const Json j = RequireProvenance({"simulate", "--json"}, {});
  CHECK(j["provenance"]["date_utc"] == "2023-11-14T22:13:20Z");
  // Two runs of the same input print the same bytes.
  CHECK(Run({"simulate", "--json"}).out == Run({"simulate", "--json"}).out);
}

TEST_CASE("the input-file flags and their roles", "[provenance]") {
  using covopt::cli::InputFileRole;
  CHECK(InputFileRole("--scene") == "scene");
  CHECK(InputFileRole("--catalog") == "catalog");
  CHECK(InputFileRole("--urdf") == "urdf");
  CHECK(InputFileRole("--trajectory") == "trajectory");
  CHECK(InputFileRole("--surface-file") == "surface");
  CHECK(InputFileRole("--link-coverings") == "link-coverings");
  for (const char* output : {"--csv", "--plot", "--history", "--report", "--samples-csv", "--json", "--material"}) {
    CHECK(InputFileRole(output).empty());
  }
}
