#pragma once
// What the CLI tests of `covopt audit` and `covopt retime` share: the FR3 pick move's command
// line, the JSON of a run that succeeded, and the check of a refused input.
#include <algorithm>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"

namespace covopt::cli::testing {

inline const std::string kFr3Urdf = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3.urdf";
inline const std::string kFr3Pick = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3_pick.csv";

/// `command` (audit or retime) of the FR3 along `trajectory` with a 10 mm covering of 0.5 MPa
/// (ν 0.45) on every link, a 1 cm² bare contact area and flat faces judged at 20 mm; then `more`.
inline std::vector<std::string> Fr3Command(const std::string& command, const std::string& trajectory,
                                           const std::vector<std::string>& more = {}) {
  std::vector<std::string> args = {command,  "--urdf",        kFr3Urdf, "--tip",           "fr3_link8",
                                   "--trajectory", trajectory, "--covering-thickness", "10mm",
                                   "--covering-modulus", "0.5MPa", "--covering-poisson", "0.45",
                                   "--contact-area", "1cm2", "--flat-face-radius", "20mm"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

/// The JSON object a run printed; it must have succeeded (exit 0).
inline nlohmann::json JsonOfRun(const CliRun& run) {
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  return nlohmann::json::parse(run.out);
}

/// A refused input: exit 2, nothing on stdout, one line on stderr naming `names` (and, when
/// `command` is given, starting "covopt <command>: error: ").
inline void RequireRefused(const CliRun& run, const std::string& names, const std::string& command = {}) {
  INFO(run.err);
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  if (!command.empty()) CHECK(run.err.rfind("covopt " + command + ": error: ", 0) == 0);
  CHECK(run.err.find(names) != std::string::npos);
}

}  // namespace covopt::cli::testing
