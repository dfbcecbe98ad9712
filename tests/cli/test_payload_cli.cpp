// The payload flags (--payload-mass/--payload-com/--payload-inertia) and ISO/TS 15066's
// fallback (--robot-moving-mass M: robot mass M/2 + m_L) end to end, in-process: a point
// payload at the planar arm's contact point adds exactly its mass to the in-plane extremes; an offset
// payload with inertia is the library's chain.WithPayload and raises the mass; --payload-mass 0
// changes nothing, to the byte; a non-physical inertia, and every contradictory combination,
// is exit 2 with one line naming the flag; the ISO fallback's robot mass is M/2 + m_L exactly
// in simulate, optimize and speed-limit, head and body region, and its answer is --robot-mass
// M/2 + m_L's but for the warning that says where the mass came from.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/report/robot_json.hpp"
#include "covopt/robot.hpp"

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using nlohmann::json;

namespace {

const std::string kPlanar = std::string(COVOPT_ROBOT_TEST_DATA_DIR) + "/planar_2link.urdf";
const std::string kFr3 = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3.urdf";
const std::string kPick = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3_pick.csv";

std::vector<std::string> With(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

/// The planar arm at q = (0.3, 1.2) rad, along (1, 2, 0): a non-singular in-plane direction.
std::vector<std::string> Planar(const std::vector<std::string>& more = {}) {
  return With({"robot", "--urdf", kPlanar, "--tip", "tool", "--joints", "0.3,1.2", "--direction", "1,2,0"}, more);
}

/// "1.264 kg": a mass as the table prints it.
std::string FourDigits(double mass_kg) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g kg", mass_kg);
  return text;
}

json JsonOf(const CliRun& run) {
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(run.err.empty());
  return covopt::cli::testing::WithoutProvenance(json::parse(run.out));  // its command line differs by the flags
}

/// Exit 2, nothing on stdout, one line on stderr that contains every one of `parts`.
void RequireOneLineError(const std::vector<std::string>& args, const std::vector<std::string>& parts) {
  const CliRun run = Run(args);
  std::string typed;
  for (const std::string& a : args) typed += a + " ";
  INFO(typed << "-> " << run.err);
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  REQUIRE(!run.err.empty());
  CHECK(run.err.find('\n') == run.err.size() - 1);
  for (const std::string& part : parts) CHECK_THAT(run.err, Catch::Contains(part));
}

}  // namespace

TEST_CASE("a point payload at the planar arm's contact point raises its in-plane extreme masses by exactly its mass") {
  // In the plane the 2-link arm's J is square and invertible, so the operational-space
  // inertia is Λ = J^-T M J^-1; a point mass m at the contact point adds m J'J to M, hence m I
  // to Λ: the same principal directions, each principal (extreme) mass up by exactly m. Along
  // another direction u the mass 1/(u' Λ^-1 u) is a weighted harmonic mean of the principal
  // masses, and d/dm of the harmonic mean of (λ_i + m) is E[1/(λ+m)²] / E[1/(λ+m)]² >= 1: it
  // rises by at least m, by more off the principal directions.
  const json bare = JsonOf(Run(Planar({"--json"})));
  const json loaded = JsonOf(Run(Planar({"--payload-mass", "2.5", "--json"})));
  CHECK(bare["payload"].is_null());
  CHECK(loaded["min_reflected_mass_kg"].get<double>() ==
        Approx(bare["min_reflected_mass_kg"].get<double>() + 2.5).epsilon(1e-12));
  for (int i = 0; i < 3; ++i) {
    CHECK(std::abs(loaded["min_direction"][i].get<double>()) ==
          Approx(std::abs(bare["min_direction"][i].get<double>())).margin(1e-9));
  }
  CHECK(loaded["reflected_mass_kg"].get<double>() > bare["reflected_mass_kg"].get<double>() + 2.5 + 1e-6);
  // The payload block: what was mounted, and the masses without it, which are the bare run's.
  const json& payload = loaded["payload"];
  CHECK(payload["mass_kg"] == 2.5);
  CHECK(payload["center_of_mass_m"] == json::array({0.0, 0.0, 0.0}));
  CHECK(payload["inertia_kg_m2"] == json::parse("[[0,0,0],[0,0,0],[0,0,0]]"));
  CHECK(payload["without_payload"]["reflected_mass_kg"] == bare["reflected_mass_kg"]);
  CHECK(payload["without_payload"]["min_reflected_mass_kg"] == bare["min_reflected_mass_kg"]);
  CHECK(payload["without_payload"]["max_reflected_mass_kg"] == "fixed");  // out of the plane, with or without
  // Grams are read as such.
  CHECK(JsonOf(Run(Planar({"--payload-mass", "2500g", "--json"}))) == loaded);
}

TEST_CASE("an offset payload with inertia is the library's chain with that payload, and raises the mass") {
  const std::vector<std::string> flags = {"--payload-mass", "1.5", "--payload-com", "100mm,20mm,0",
                                          "--payload-inertia", "0.01,0.02,0.025,0.001,0,0"};
  const json got = JsonOf(Run(Planar(With(flags, {"--json"}))));
  covopt::robot::Payload payload;
  payload.mass_kg = 1.5;
  payload.center_of_mass_m = Eigen::Vector3d(0.1, 0.02, 0.0);
  payload.inertia_kg_m2 = covopt::robot::Payload::InertiaFromSix(0.01, 0.02, 0.025, 0.001, 0.0, 0.0);
  const auto bare_chain = covopt::robot::KinematicChain::FromUrdfFile(kPlanar, {"", "tool"});
  const auto chain = bare_chain.WithPayload(payload);
  const Eigen::Vector2d q(0.3, 1.2);
  const auto with = covopt::robot::ReflectedMass(chain, q, Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 2, 0));
  const auto without = covopt::robot::ReflectedMass(bare_chain, q, Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 2, 0));
  CHECK(got == json::parse(covopt::report::RobotJson(with, {}, 2, covopt::report::RobotPayload{payload, without})));
  CHECK(got["payload"]["inertia_kg_m2"][0][1] == 0.001);  // the tensor's own off-diagonal, symmetric
  CHECK(got["payload"]["inertia_kg_m2"][1][0] == 0.001);
  // More mass on the tip never lowers the reflected mass; here it raises it.
  CHECK(*with.reflected_mass_kg > *without.reflected_mass_kg + 0.1);
  CHECK(with.min_reflected_mass_kg > without.min_reflected_mass_kg);
  // The table says what was mounted, and both masses.
  const CliRun table = Run(Planar(flags));
  REQUIRE(table.exit_code == 0);
  CHECK_THAT(table.out, Catch::Contains("Payload  1.5 kg at (0.1, 0.02, 0) m (tip frame)") &&
                            Catch::Contains("without the payload") &&
                            Catch::Contains(FourDigits(*without.reflected_mass_kg)) &&
                            Catch::Contains(FourDigits(*with.reflected_mass_kg)));
}

TEST_CASE("a payload on the FR3's flange raises every moving sample's reflected mass along the pick move") {
  const std::vector<std::string> base = {"robot", "--urdf", kFr3, "--tip", "fr3_link8", "--trajectory", kPick,
                                         "--json"};
  const json bare = JsonOf(Run(base));
  const json loaded = JsonOf(Run(With(base, {"--payload-mass", "1.5", "--payload-com", "0,0,0.1"})));
  REQUIRE(bare["samples"].size() == loaded["samples"].size());
  int moving = 0;
  for (std::size_t i = 0; i < bare["samples"].size(); ++i) {
    const json& b = bare["samples"][i];
    const json& l = loaded["samples"][i];
    if (!b["moving"].get<bool>()) continue;
    ++moving;
    INFO("sample " << i);
    CHECK(l["reflected_mass_kg"].get<double>() > b["reflected_mass_kg"].get<double>());
    CHECK(l["speed_m_per_s"] == b["speed_m_per_s"]);  // the payload changes no kinematics
  }
  CHECK(moving > 50);
  CHECK(loaded["safe_speed_scale"].get<double>() < bare["safe_speed_scale"].get<double>());
}

TEST_CASE("a zero payload changes nothing, to the byte") {
  const std::vector<std::vector<std::string>> commands = {
      Planar(),
      Planar({"--json"}),
      {"simulate", "--json", "--urdf", kFr3, "--tip", "fr3_link8", "--joints", "0,-45deg,0,-135deg,0,90deg,45deg",
       "--direction", "1,0,0"},
      {"robot", "--urdf", kFr3, "--tip", "fr3_link8", "--trajectory", kPick, "--json"},
      {"simulate", "--json", "--robot-moving-mass", "30"},
  };
  for (const std::vector<std::string>& command : commands) {
    const CliRun bare = Run(command);
    INFO(command[0] << " " << command[1] << ": " << bare.err);
    REQUIRE(bare.exit_code == 0);
    using covopt::cli::testing::WithoutProvenance;
    CHECK(WithoutProvenance(Run(With(command, {"--payload-mass", "0"})).out) == WithoutProvenance(bare.out));
    if (command[0] == "robot") {  // all-zero centre of mass and inertia too
      CHECK(WithoutProvenance(Run(With(command, {"--payload-mass", "0", "--payload-com", "0,0,0", "--payload-inertia",
                                                 "0,0,0,0,0,0"}))
                                  .out) == WithoutProvenance(bare.out));
    }
  }
}

TEST_CASE("a non-physical payload is exit 2 with one line naming the flag, the value and the allowed range") {
  const auto inertia = [](const std::string& six) { return Planar({"--payload-mass", "1", "--payload-inertia", six}); };
  // Negative: the principal moments of a tensor must be >= 0.
  RequireOneLineError(inertia("-0.01,0.02,0.02,0,0,0"),
                      {"--payload-inertia", "smallest principal moment = -0.01", ">= 0 kg m²"});
  // The triangle inequality: no principal moment exceeds the sum of the other two.
  RequireOneLineError(inertia("0.01,0.01,0.03,0,0,0"),
                      {"--payload-inertia", "largest principal moment = 0.03", "triangle inequality"});
  // A product of inertia so large the tensor is indefinite, though its diagonal is positive.
  RequireOneLineError(inertia("0.01,0.01,0.01,0.02,0,0"), {"--payload-inertia", "principal moment", ">= 0 kg m²"});
  // Not a number.
  RequireOneLineError(inertia("nan,0.02,0.02,0,0,0"), {"--payload-inertia", "component 1", "'nan'", "finite"});
  RequireOneLineError(inertia("inf,0.02,0.02,0,0,0"), {"--payload-inertia", "component 1", "'inf'", "finite"});
  RequireOneLineError(inertia("0.01,0.02,0.02"), {"--payload-inertia", "expected 6", "got 3"});
  // The mass and the centre of mass.
  RequireOneLineError(Planar({"--payload-mass", "-1"}), {"--payload-mass", "mass = -1", "[0, 1e4] kg"});
  RequireOneLineError(Planar({"--payload-mass", "nan"}), {"--payload-mass", "nan"});
  RequireOneLineError(Planar({"--payload-mass", "2e8g"}), {"--payload-mass", "mass = 200000", "[0, 1e4] kg"});
  RequireOneLineError(Planar({"--payload-mass", "1", "--payload-com", "20000mm,0,0"}),
                      {"--payload-com", "centre of mass x = 20", "±10 m"});
  RequireOneLineError(Planar({"--payload-com", "0,0,0.1"}), {"--payload-com needs --payload-mass"});
  RequireOneLineError(Planar({"--payload-mass", "0", "--payload-inertia", "0.01,0.01,0.01,0,0,0"}),
                      {"--payload-inertia", "without a mass"});
}

TEST_CASE("the ISO/TS 15066 fallback's robot mass is M/2 + m_L exactly, head and body region") {
  const double expected = 30.0 / 2.0 + 2.5;
  const std::vector<std::string> iso = {"--robot-moving-mass", "30", "--payload-mass", "2.5"};
  const auto mass_note = [](const json& j) {
    const std::string first = j["warnings"][0].get<std::string>();
    CHECK_THAT(first, Catch::StartsWith("robot mass 17.5 kg: ISO/TS 15066") && Catch::Contains("M/2 + m_L") &&
                          Catch::Contains("not a reflected mass"));
  };
  for (const char* command : {"simulate", "optimize"}) {
    INFO(command);
    const json j = JsonOf(Run(With({command, "--json"}, iso)));
    CHECK(j["scene"]["robot"]["mass_kg"].get<double>() == expected);
    mass_note(j);
  }
  for (const char* command : {"simulate", "optimize"}) {
    INFO(command << " --body-region chest");
    const json j = JsonOf(Run(With({command, "--json", "--body-region", "chest"}, iso)));
    CHECK(j["scene"]["robot_mass_kg"].get<double>() == expected);
    mass_note(j);
  }
  for (const std::vector<std::string>& more : {std::vector<std::string>{}, {"--body-region", "chest"}}) {
    const json j = JsonOf(Run(With(With({"speed-limit", "--json"}, iso), more)));
    CHECK(j["rows"][0]["robot_mass_kg"].get<double>() == expected);
    mass_note(j);
  }
  // Without a payload: M/2.
  CHECK(JsonOf(Run({"simulate", "--json", "--robot-moving-mass", "30kg"}))["scene"]["robot"]["mass_kg"] == 15.0);
}

TEST_CASE("the ISO fallback answers as --robot-mass M/2 + m_L does, but for the warning that says so") {
  for (const std::vector<std::string>& command :
       {std::vector<std::string>{"simulate", "--json"}, {"simulate", "--json", "--body-region", "chest"},
        {"speed-limit", "--json"}}) {
    INFO(command[0] << " " << command.size());
    json iso = JsonOf(Run(With(command, {"--robot-moving-mass", "30", "--payload-mass", "2.5"})));
    json typed = JsonOf(Run(With(command, {"--robot-mass", "17.5"})));
    REQUIRE(iso["warnings"].size() == typed["warnings"].size() + 1);
    iso["warnings"].erase(0);
    // The robot model behind the mass: an input of its own, and the summary's robot.
    REQUIRE(iso.contains("robot_model"));
    CHECK(iso["robot_model"]["source"] == "iso-estimate");
    CHECK(iso["robot_model"]["moving_mass_kg"] == 30.0);
    CHECK(iso["robot_model"]["reflected_mass_kg"] == 17.5);
    CHECK_THAT(iso["summary"]["robot"]["motion"].get<std::string>(), Catch::Contains("M = 30 kg"));
    CHECK_FALSE(typed.contains("robot_model"));
    iso.erase("robot_model");
    iso["summary"]["robot"] = typed["summary"]["robot"];
    if (iso.contains("input_sources")) iso["input_sources"] = typed["input_sources"];  // --robot-moving-mass, not --robot-mass
    CHECK(iso == typed);
  }
}

TEST_CASE("contradictory robot-mass flags are exit 2 with one line") {
  const std::vector<std::string> iso = {"--robot-moving-mass", "30"};
  RequireOneLineError(With({"simulate", "--robot-mass", "10"}, iso), {"--robot-mass and --robot-moving-mass"});
  RequireOneLineError({"speed-limit", "--robot-mass", "5,10", "--robot-moving-mass", "30"},
                      {"--robot-mass and --robot-moving-mass"});
  RequireOneLineError({"speed-limit", "--solve-for", "mass", "--robot-moving-mass", "30"},
                      {"--robot-moving-mass gives the robot mass", "--solve-for mass"});
  RequireOneLineError(With({"simulate", "--urdf", kPlanar, "--tip", "tool", "--joints", "0.3,1.2", "--direction",
                            "1,2,0"},
                           iso),
                      {"--robot-moving-mass '30' and --urdf both give the robot mass"});
  // The ISO formula takes the payload's mass only: its centre of mass and inertia need a URDF.
  RequireOneLineError(With({"simulate", "--payload-mass", "2", "--payload-com", "0,0,0.1"}, iso),
                      {"--payload-com needs --urdf FILE"});
  RequireOneLineError(With({"optimize", "--payload-mass", "2", "--payload-inertia", "0.01,0.01,0.01,0,0,0"}, iso),
                      {"--payload-inertia needs --urdf FILE"});
  RequireOneLineError(With({"simulate", "--tip", "tool"}, iso), {"--tip needs --urdf FILE"});
  // A payload without a robot model or M: where would it go?
  RequireOneLineError({"simulate", "--payload-mass", "2"}, {"--payload-mass '2' needs --urdf FILE", "--robot-moving-mass"});
  RequireOneLineError({"simulate", "--robot-mass", "10", "--payload-mass", "2"},
                      {"--payload-mass '2' needs --urdf FILE", "payload included"});
  // The robot command computes a reflected mass: it needs the model.
  RequireOneLineError(With({"robot"}, iso), {"--robot-moving-mass '30'", "needs --urdf FILE"});
  // M itself.
  RequireOneLineError({"simulate", "--robot-moving-mass", "-3"}, {"--robot-moving-mass", "(0, 1e6] kg", "'-3'"});
  RequireOneLineError({"simulate", "--robot-moving-mass", "0"}, {"--robot-moving-mass", "(0, 1e6] kg"});
  RequireOneLineError({"simulate", "--robot-moving-mass", "3e7"}, {"--robot-moving-mass 3e7", "plausible range"});
}
