// `covopt simulate/speed-limit --body-region` with a braking robot (--reaction-delay,
// --braking; docs/model.md §13.10), run in-process: the verdicts and the limits are the
// library's on the time path, with the integrator the flags name; the braked peaks are below
// the unbraked ones and the braked limits above; --method exact, a fixed robot that brakes and
// --method without braking are bad input (exit 2, one line); a time path that fails is exit 1.
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/materials/body_regions.hpp"
#include "covopt/optim/body_region_check.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using covopt::cli::testing::SplitLines;
using nlohmann::json;

json JsonOf(const std::vector<std::string>& args) {
  const CliRun run = Run(args);
  INFO(fmt::format("{}", fmt::join(args, " ")) << " -> " << run.err);
  REQUIRE(run.exit_code == 0);
  return json::parse(run.out);
}

/// The robot of the commands below: 10 kg at 1 m/s, 20 mm radius, 10 mm of 3 MPa foam,
/// braking 100 m/s² after 5 ms.
covopt::BodyContactScene Scene(bool braking) {
  covopt::BodyContactScene s;
  s.robot_mass_kg = 10.0;
  s.speed_m_per_s = 1.0;
  s.robot_radius_m = 0.02;
  s.covering = {3e6, 0.25, 0.01};
  if (braking) {
    s.reaction_delay_s = 5e-3;
    s.braking_m_per_s2 = 100.0;
  }
  return s;
}

const std::vector<std::string> kRobot{"--robot-mass",       "10",   "--robot-radius",     "20mm",
                                      "--covering-thickness", "10mm", "--covering-modulus", "3MPa",
                                      "--covering-poisson",   "0.25"};
const std::vector<std::string> kBrake{"--braking", "100m/s2", "--reaction-delay", "5ms"};

/// `head` (the command first), the robot (at 1 m/s for simulate), the brake if `braking`, `tail`.
std::vector<std::string> Args(std::vector<std::string> head, bool braking, std::vector<std::string> tail = {}) {
  if (head.front() == "simulate") head.insert(head.end(), {"--speed", "1"});
  head.insert(head.end(), kRobot.begin(), kRobot.end());
  if (braking) head.insert(head.end(), kBrake.begin(), kBrake.end());
  head.insert(head.end(), tail.begin(), tail.end());
  return head;
}

void ExpectExit(const std::vector<std::string>& args, int code, const std::string& named) {
  const CliRun run = Run(args);
  INFO(fmt::format("{}", fmt::join(args, " ")) << " -> " << run.err);
  CHECK(run.exit_code == code);
  CHECK(run.out.empty());
  CHECK(SplitLines(run.err).size() == 1);
  CHECK(run.err.find(named) != std::string::npos);
}

}  // namespace

TEST_CASE("simulate --body-region with --braking: the library's time-path verdict, below the unbraked one",
          "[body_regions][braking]") {
  const covopt::materials::BodyLimits chest =
      covopt::materials::BodyRegionTable::BuiltIn().Limits("chest", "", covopt::ContactType::kTransient);
  const json braked = JsonOf(Args({"simulate", "--body-region", "chest", "--json"}, true));
  const json unbraked = JsonOf(Args({"simulate", "--body-region", "chest", "--json"}, false));
  REQUIRE(braked["regions"].size() == 1);
  const json& region = braked["regions"][0];
  const covopt::optim::BodyRegionJudgement expected = covopt::optim::JudgeBodyContact(Scene(true), chest);
  CHECK(region["method"] == "time path (arkode-erk54, rtol 1e-08)");
  CHECK(region["peak_force_N"].get<double>() == expected.contact.peak_force_N);
  CHECK(region["governing_ratio"].get<double>() == expected.governing_ratio);
  CHECK(region["peak_force_N"].get<double>() < unbraked["regions"][0]["peak_force_N"].get<double>());
  CHECK(braked["scene"]["braking"]["braking_m_per_s2"] == 100.0);
  CHECK(braked["scene"]["braking"]["reaction_delay_s"] == 0.005);
  CHECK_FALSE(unbraked["scene"].contains("braking"));

  // The flags choose the integrator; the text names the brake and the path.
  const json bdf = JsonOf(Args({"simulate", "--body-region", "chest", "--json"}, true,
                               {"--method", "cvode-bdf", "--rtol", "1e-10"}));
  CHECK(bdf["regions"][0]["method"] == "time path (cvode-bdf, rtol 1e-10)");
  CHECK(std::abs(bdf["regions"][0]["peak_force_N"].get<double>() / expected.contact.peak_force_N - 1.0) <= 1e-6);
  const CliRun text = Run(Args({"simulate", "--body-region", "chest"}, true));
  REQUIRE(text.exit_code == 0);
  CHECK(text.out.find("Braking      100 m/s² after 5 ms") != std::string::npos);
}

TEST_CASE("speed-limit --body-region with --braking: the library's bracketed limits, above the unbraked ones",
          "[body_regions][braking]") {
  const covopt::materials::BodyLimits chest =
      covopt::materials::BodyRegionTable::BuiltIn().Limits("chest", "", covopt::ContactType::kTransient);
  const std::vector<std::string> area{"--contact-area", "1cm2"};
  const json braked = JsonOf(Args({"speed-limit", "--body-region", "chest", "--json"}, true, area));
  const json unbraked = JsonOf(Args({"speed-limit", "--body-region", "chest", "--json"}, false, area));
  REQUIRE(braked["rows"].size() == 1);
  const json& row = braked["rows"][0];
  const covopt::optim::BodyRegionSpeedLimit expected = covopt::optim::MaxSafeSpeed(Scene(true), chest);
  CHECK(row["covered_max_speed_m_per_s"].get<double>() == expected.max_safe_speed_m_per_s);
  CHECK(row["covered_status"] == "limited");
  CHECK(row["covered_max_speed_m_per_s"].get<double>() >
        unbraked["rows"][0]["covered_max_speed_m_per_s"].get<double>());
  CHECK(row["bare_max_speed_m_per_s"].get<double>() > unbraked["rows"][0]["bare_max_speed_m_per_s"].get<double>());
  // --method/--rtol set the time path of a braking robot's limits.
  const json bdf = JsonOf(Args({"speed-limit", "--body-region", "chest", "--json"}, true,
                               {"--contact-area", "1cm2", "--method", "cvode-bdf", "--rtol", "1e-10"}));
  CHECK(std::abs(bdf["rows"][0]["covered_max_speed_m_per_s"].get<double>() / expected.max_safe_speed_m_per_s - 1.0) <=
        1e-5);
}

TEST_CASE("a braking robot on a body region: bad input is exit 2, a failed time path exit 1", "[body_regions][braking]") {
  ExpectExit(Args({"simulate", "--body-region", "chest"}, true, {"--method", "exact"}), 2, "--method exact");
  ExpectExit({"simulate", "--body-region", "chest", "--robot-mass", "fixed", "--braking", "100m/s2",
              "--covering-thickness", "0", "--contact-area", "1cm2"},
             2, "robot.braking needs a robot that moves");
  ExpectExit(Args({"speed-limit", "--body-region", "chest"}, false, {"--method", "cvode-bdf"}), 2,
             "closed form on the energy balance");
  ExpectExit(Args({"speed-limit", "--body-region", "chest"}, true, {"--oracle", "exact"}), 2, "--oracle exact");
  ExpectExit(Args({"speed-limit", "--body-region", "chest"}, true, {"--max-steps", "10"}), 1,
             "no answer: the time path failed at");
  ExpectExit(Args({"simulate", "--body-region", "chest"}, true, {"--max-steps", "10"}), 1, "the time path failed on chest");
}
