// `covopt simulate` on scenes beyond the conservative two-mass model (docs/model.md §10): a
// braking robot, contact damping and a head on a neck. These tests check which path --method
// auto chooses (the time path for braking or a neck), that --method exact is refused on such a
// scene with one line on stderr, that the table shows the new inputs, the rebound speed and the
// coefficient of restitution, that the JSON carries the library's numbers (compared with
// covopt::SimulateImpact on the same Scene) and the new keys, that the history CSV gains the
// bodies' speeds, that --plot draws, that bad values exit 2 naming the flag, and that the new
// units (s/m, N/m, kN/m, N*s/m, Ns/m, m/s2, ms, s) reach the Scene.

#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/core.hpp"
#include "output.hpp"
#include "plot.hpp"

using covopt::cli::testing::CliRun;
using covopt::cli::testing::ReadFile;
using covopt::cli::testing::Run;
using covopt::cli::testing::SplitLines;
using covopt::cli::testing::TempDir;
using Catch::Matchers::Contains;
using Json = nlohmann::json;

namespace {

/// The paper's scene with a robot braking at 100 m/s² from 2 ms after first contact.
covopt::Scene BrakingScene() {
  covopt::Scene scene;
  scene.robot.braking_m_per_s2 = 100.0;
  scene.robot.reaction_delay_s = 0.002;
  return scene;
}

const std::vector<std::string> kBrakingFlags{"--braking", "100m/s2", "--reaction-delay", "2ms"};
const std::vector<std::string> kNeckFlags{"--torso-mass", "30kg", "--neck-stiffness", "30kN/m",
                                          "--neck-damping", "100Ns/m"};

std::vector<std::string> Args(std::vector<std::string> head, const std::vector<std::string>& tail) {
  head.insert(head.end(), tail.begin(), tail.end());
  return head;
}

void CheckBadInput(const std::vector<std::string>& args, const std::vector<std::string>& named) {
  const CliRun run = Run(args);
  CAPTURE(args, run.err);
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK(SplitLines(run.err).size() == 1);
  for (const std::string& part : named) CHECK_THAT(run.err, Contains(part));
}

}  // namespace

TEST_CASE("simulate takes the time path for a braking robot and reports the library's numbers",
          "[extended][run][json]") {
  const CliRun run = Run(Args({"simulate", "--json"}, kBrakingFlags));
  CAPTURE(run.err);
  REQUIRE(run.exit_code == 0);
  const Json json = Json::parse(run.out);
  CHECK(json["method"] == "arkode-erk54");
  const covopt::ImpactResult expected =
      covopt::SimulateImpact(covopt::ImpactModel::FromScene(BrakingScene()));
  REQUIRE(expected.ok());
  CHECK(json["max_penetration_m"].get<double>() == expected.peaks.max_penetration_m);
  CHECK(json["peak_force_N"].get<double>() == expected.peaks.peak_force_N);
  CHECK(json["max_energy_density_J_per_m2"].get<double>() == expected.peaks.max_energy_density_J_per_m2);
  CHECK(json["contact_duration_s"].get<double>() == *expected.contact_duration_s);
  CHECK(json["rebound_speed_m_per_s"].get<double>() == *expected.rebound_speed_m_per_s);
  CHECK(json["coefficient_of_restitution"].get<double>() == *expected.coefficient_of_restitution);
  CHECK(json["solver"]["energy_residual"].get<double>() == *expected.energy_residual);
  CHECK(json["scene"]["robot"]["braking_m_per_s2"].get<double>() == 100.0);
  CHECK(json["scene"]["robot"]["reaction_delay_s"].get<double>() == 0.002);
}

TEST_CASE("simulate's table shows the new inputs, the rebound and the restitution",
          "[extended][run]") {
  SECTION("braking") {
    const CliRun run = Run(Args({"simulate"}, kBrakingFlags));
    CAPTURE(run.err);
    REQUIRE(run.exit_code == 0);
    CHECK_THAT(run.out, Contains("the robot brakes at 100 m/s² from 2 ms after first contact"));
    CHECK_THAT(run.out, Contains("rebound speed") && Contains("coefficient of restitution"));
    CHECK_THAT(run.out, Contains("Method  arkode-erk54"));
  }
  SECTION("a neck") {
    const CliRun run = Run(Args({"simulate"}, kNeckFlags));
    CAPTURE(run.err);
    REQUIRE(run.exit_code == 0);
    CHECK_THAT(run.out, Contains("neck to a torso 30 kg: stiffness 30 kN/m, damping 100 N·s/m"));
    CHECK_THAT(run.out, Contains("coefficient of restitution"));
  }
  SECTION("the paper's scene shows neither") {
    const CliRun run = Run({"simulate"});
    REQUIRE(run.exit_code == 0);
    CHECK_THAT(run.out, !Contains("coefficient of restitution") && !Contains("brakes") &&
                            !Contains("neck"));
  }
}

TEST_CASE("simulate with damping reports a restitution below 1", "[extended][run][damping]") {
  const CliRun run = Run({"simulate", "--json", "--damping", "0.2s/m"});
  CAPTURE(run.err);
  REQUIRE(run.exit_code == 0);
  const Json json = Json::parse(run.out);
  CHECK(json["scene"]["model"]["damping_s_per_m"].get<double>() == 0.2);
  const double restitution = json["coefficient_of_restitution"].get<double>();
  CHECK(restitution < 1.0);
  CHECK(restitution > 0.5);
  CHECK(restitution == Approx(json["rebound_speed_m_per_s"].get<double>() / 2.0).epsilon(1e-15));
  // The time path answers the same scene within its tolerance.
  const CliRun time_path = Run({"simulate", "--json", "--damping", "0.2s/m", "--method", "cvode-bdf", "--rtol", "1e-10"});
  REQUIRE(time_path.exit_code == 0);
  const Json simulated = Json::parse(time_path.out);
  CHECK(simulated["method"] == "cvode-bdf");
  CHECK(simulated["coefficient_of_restitution"].get<double>() == Approx(restitution).epsilon(1e-6));
  CHECK(simulated["peak_force_N"].get<double>() == Approx(json["peak_force_N"].get<double>()).epsilon(1e-6));
}

TEST_CASE("simulate on a neck runs any integrator, and the history gains the bodies' speeds",
          "[extended][run][outputs]") {
  TempDir dir;
  const auto csv = dir / "neck.csv";
  const CliRun run = Run(Args({"simulate", "--json", "--method", "cvode-adams", "--history", csv.string()}, kNeckFlags));
  CAPTURE(run.err);
  REQUIRE(run.exit_code == 0);
  const Json json = Json::parse(run.out);
  CHECK(json["method"] == "cvode-adams");
  CHECK(json["scene"]["head"]["torso_mass_kg"].get<double>() == 30.0);
  CHECK(json["scene"]["head"]["neck_stiffness_N_per_m"].get<double>() == 30000.0);
  CHECK(json["scene"]["head"]["neck_damping_N_s_per_m"].get<double>() == 100.0);
  const auto lines = SplitLines(ReadFile(csv));
  REQUIRE(lines.size() > 300);  // ~400 samples over the contact
  CHECK(lines.front() == std::string(covopt::cli::kHistoryCsvHeader) +
                             std::string(covopt::cli::kHistoryCsvExtendedColumns));
  CHECK(lines.size() - 1 == json["solver"]["history_samples"].get<std::size_t>());
}

TEST_CASE("simulate --plot draws a braking robot's contact", "[extended][outputs][plot]") {
  if (!covopt::cli::FindOnPath("gnuplot")) {
    WARN("gnuplot is not on PATH; skipping the plot test");
    return;
  }
  TempDir dir;
  const auto png = dir / "brake.png";
  const CliRun run = Run(Args({"simulate", "--plot", png.string()}, kBrakingFlags));
  CAPTURE(run.err);
  REQUIRE(run.exit_code == 0);
  const std::string bytes = ReadFile(png);
  REQUIRE(bytes.size() > 1000);
  CHECK(bytes.substr(0, 8) == std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST_CASE("simulate refuses --method exact on a braking or neck scene", "[extended][bad-input]") {
  const std::string message =
      "--method exact: the exact path needs an energy integral; a scene with braking or a neck "
      "has only the time path; use --method auto or a time integrator";
  CheckBadInput(Args({"simulate", "--method", "exact"}, kBrakingFlags), {message});
  CheckBadInput(Args({"simulate", "--method", "exact"}, kNeckFlags), {message});
  // auto, the default, is accepted by name; a damped scene keeps the exact path.
  CHECK(Run(Args({"simulate", "--method", "auto"}, kBrakingFlags)).exit_code == 0);
  const CliRun damped = Run({"simulate", "--json", "--method", "exact", "--damping", "0.2s/m"});
  CAPTURE(damped.err);
  REQUIRE(damped.exit_code == 0);
  CHECK(Json::parse(damped.out)["method"] == "exact");
}

TEST_CASE("bad values of the new inputs exit 2 naming the flag", "[extended][bad-input]") {
  CheckBadInput({"simulate", "--braking", "-1m/s2"}, {"--braking", "-1"});
  CheckBadInput({"simulate", "--damping", "-0.1s/m"}, {"--damping", "-0.1"});
  CheckBadInput({"simulate", "--reaction-delay", "-2ms"}, {"--reaction-delay", "-2"});
  CheckBadInput({"simulate", "--neck-stiffness", "30kN/m"}, {"head.torso_mass", "neck"});
  CheckBadInput({"simulate", "--torso-mass", "30kg"}, {"head.torso_mass", "neither stiffness nor damping"});
  CheckBadInput({"simulate", "--torso-mass", "-3kg", "--neck-stiffness", "1kN/m"}, {"head.torso_mass", "-3"});
  CheckBadInput({"simulate", "--braking", "10m/s2", "--robot-mass", "fixed"}, {"robot.braking", "fixed"});
  CheckBadInput({"simulate", "--robot-mass", "fixed", "--torso-mass", "fixed", "--neck-stiffness", "30kN/m"},
                {"robot.mass", "head.torso_mass", "both fixed"});
  CheckBadInput({"simulate", "--braking", "10kg"}, {"--braking", "kg"});
  CheckBadInput({"simulate", "--neck-damping", "100N/m", "--torso-mass", "30kg"}, {"--neck-damping", "N/m"});
}

TEST_CASE("the new units reach the Scene in SI", "[extended][units]") {
  struct Case {
    std::vector<std::string> flags;
    const char* object;
    const char* key;
    double si;
  };
  const std::vector<Case> cases{
      {{"--damping", "0.2 s/m"}, "model", "damping_s_per_m", 0.2},
      {{"--braking", "50 m/s2"}, "robot", "braking_m_per_s2", 50.0},
      {{"--braking", "50m/s2", "--reaction-delay", "2 ms"}, "robot", "reaction_delay_s", 0.002},
      {{"--braking", "50m/s2", "--reaction-delay", "0.002 s"}, "robot", "reaction_delay_s", 0.002},
      {{"--torso-mass", "30kg", "--neck-stiffness", "30000 N/m"}, "head", "neck_stiffness_N_per_m", 3e4},
      {{"--torso-mass", "30kg", "--neck-stiffness", "30 kN/m"}, "head", "neck_stiffness_N_per_m", 3e4},
      {{"--torso-mass", "30kg", "--neck-damping", "100 N*s/m"}, "head", "neck_damping_N_s_per_m", 100.0},
      {{"--torso-mass", "30kg", "--neck-damping", "100 Ns/m"}, "head", "neck_damping_N_s_per_m", 100.0},
      {{"--torso-mass", "fixed", "--neck-damping", "100Ns/m"}, "head", "neck_damping_N_s_per_m", 100.0},
  };
  for (const Case& c : cases) {
    const CliRun run = Run(Args({"simulate", "--json"}, c.flags));
    CAPTURE(c.flags, run.err);
    REQUIRE(run.exit_code == 0);
    CHECK(Json::parse(run.out)["scene"][c.object][c.key].get<double>() == Approx(c.si).epsilon(1e-15));
  }
}
