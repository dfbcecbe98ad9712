// `covopt robot` end to end, in-process: the table and the JSON are the library's answer
// (report::RobotJson of robot::ReflectedMass for the same inputs), the planar arm's
// closed-form mass, "fixed" for a direction the arm cannot move in, deg accepted, the
// extremes alone without --direction; --urdf on simulate, optimize and speed-limit sets
// scene.robot.mass_kg to the reflected mass; and bad input is exit 2 with one line naming the
// flag and nothing on stdout.
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/report/robot_json.hpp"
#include "covopt/robot.hpp"

using covopt::cli::testing::Run;
using covopt::cli::testing::TempDir;
using nlohmann::json;

namespace {

const std::string kPlanar = std::string(COVOPT_ROBOT_TEST_DATA_DIR) + "/planar_2link.urdf";
const std::string kFr3 = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3.urdf";

std::vector<std::string> Planar(std::vector<std::string> more = {}) {
  std::vector<std::string> args = {"robot", "--urdf", kPlanar, "--tip", "tool", "--joints", "0.3,1.2"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

}  // namespace

TEST_CASE("covopt robot --json prints the library's reflected mass of the same inputs") {
  const auto run = Run(Planar({"--direction", "1,2,0", "--point", "10mm,0,0", "--json"}));
  REQUIRE(run.exit_code == 0);
  CHECK(run.err.empty());
  const auto chain = covopt::robot::KinematicChain::FromUrdfFile(kPlanar, {"", "tool"});
  const auto expected = covopt::robot::ReflectedMass(chain, Eigen::Vector2d(0.3, 1.2),
                                                     Eigen::Vector3d(0.01, 0, 0), Eigen::Vector3d(1, 2, 0));
  CHECK(covopt::cli::testing::WithoutProvenance(json::parse(run.out)) ==
        json::parse(covopt::report::RobotJson(expected)));
  const json j = json::parse(run.out);
  CHECK(j["max_reflected_mass_kg"] == "fixed");  // a planar arm cannot move along z
  CHECK(j["reflected_mass_kg"].get<double>() > 0.0);
  CHECK(j["joint_names"] == json::array({"shoulder", "elbow"}));
  for (const char* key : {"min_reflected_mass_kg", "max_direction", "min_direction", "contact_point_m", "warnings"}) {
    CHECK(j.contains(key));
  }
}

TEST_CASE("covopt robot calls the stretched arm fixed along itself and gives the closed form across it") {
  // q = (0, 0): the tip at (1.8, 0, 0). Across the arm (y) the mass is 1 / (J M^-1 J')_yy
  // with J's y row (l1 + l2, l2) = (1.8, 0.8) and the 2x2 M of the closed form.
  const double M11 = 0.1 + 0.05 + 2.0 * 0.25 + 1.5 * (1.0 + 0.16 + 0.8);
  const double M12 = 0.05 + 1.5 * (0.16 + 0.4);
  const double M22 = 0.05 + 1.5 * 0.16;
  const double det = M11 * M22 - M12 * M12;
  const double jy1 = 1.8, jy2 = 0.8;
  const double inverse_yy = (jy1 * jy1 * M22 - 2 * jy1 * jy2 * M12 + jy2 * jy2 * M11) / det;
  const auto across = Run({"robot", "--urdf", kPlanar, "--tip", "tool", "--joints", "0deg,0", "--direction", "0,1,0",
                           "--json"});
  REQUIRE(across.exit_code == 0);
  CHECK(json::parse(across.out)["reflected_mass_kg"].get<double>() == Approx(1.0 / inverse_yy).epsilon(1e-12));
  const auto along = Run({"robot", "--urdf", kPlanar, "--tip", "tool", "--joints", "0,0", "--direction", "1,0,0"});
  REQUIRE(along.exit_code == 0);
  CHECK_THAT(along.out, Catch::Contains("fixed (infinite)") && Catch::Contains("Warnings"));
}

TEST_CASE("covopt robot without --direction gives the extremes only") {
  const auto table = Run(Planar());
  REQUIRE(table.exit_code == 0);
  CHECK_THAT(table.out, Catch::Contains("largest") && Catch::Contains("smallest"));
  CHECK(table.out.find("\n  along ") == std::string::npos);  // no directional row
  const json j = json::parse(Run(Planar({"--json"})).out);
  CHECK(j["reflected_mass_kg"].is_null());
  CHECK(j["direction"].is_null());
}

TEST_CASE("degrees and radians give the same answer") {
  const json rad = json::parse(Run({"robot", "--urdf", kPlanar, "--tip", "tool", "--joints", "0.5,-1", "--direction",
                                    "1,1,0", "--json"}).out);
  const std::string deg = std::to_string(0.5 * 180 / M_PI) + "deg," + std::to_string(-180 / M_PI) + "deg";
  const json in_deg = json::parse(Run({"robot", "--urdf", kPlanar, "--tip", "tool", "--joints", deg, "--direction",
                                       "1,1,0", "--json"}).out);
  CHECK(in_deg["reflected_mass_kg"].get<double>() == Approx(rad["reflected_mass_kg"].get<double>()).epsilon(1e-9));
}

TEST_CASE("the --urdf options on simulate, optimize and speed-limit put the reflected mass in scene.robot.mass_kg") {
  const std::vector<std::string> model = {"--urdf", kFr3, "--tip", "fr3_link8", "--joints",
                                          "0,-45deg,0,-135deg,0,90deg,45deg", "--direction", "1,0,0"};
  const auto chain = covopt::robot::KinematicChain::FromUrdfFile(kFr3, {"", "fr3_link8"});
  Eigen::VectorXd q(7);
  q << 0, -M_PI / 4, 0, -3 * M_PI / 4, 0, M_PI / 2, M_PI / 4;
  const double expected =
      *covopt::robot::ReflectedMass(chain, q, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()).reflected_mass_kg;
  CHECK(expected > 0.5);
  CHECK(expected < 16.0);  // below the arm's moving mass
  for (const std::string command : {"simulate", "optimize"}) {
    std::vector<std::string> args = {command, "--json"};
    args.insert(args.end(), model.begin(), model.end());
    const auto run = Run(args);
    INFO(command << ": " << run.err);
    REQUIRE(run.exit_code == 0);
    const json j = json::parse(run.out);
    CHECK(j["scene"]["robot"]["mass_kg"].get<double>() == Approx(expected).epsilon(1e-12));
    CHECK_THAT(j["warnings"][0].get<std::string>(), Catch::StartsWith("robot mass") && Catch::Contains("fr3_link8"));
  }
  std::vector<std::string> speed_limit = {"speed-limit", "--json"};
  speed_limit.insert(speed_limit.end(), model.begin(), model.end());
  const auto run = Run(speed_limit);
  REQUIRE(run.exit_code == 0);
  CHECK(json::parse(run.out)["rows"][0]["robot_mass_kg"].get<double>() == Approx(expected).epsilon(1e-12));
}

TEST_CASE("bad robot input is exit 2 with one line naming the flag and nothing on stdout") {
  TempDir dir;
  const std::string malformed = dir.Write("bad.urdf", "<robot name='x'><link").string();
  const std::string cycle = dir.Write("cycle.urdf",
                                      "<robot name='c'><link name='base'/><link name='a'/><link name='b'/>"
                                      "<joint name='j1' type='continuous'><parent link='base'/><child link='a'/></joint>"
                                      "<joint name='j2' type='continuous'><parent link='a'/><child link='b'/></joint>"
                                      "<joint name='j3' type='fixed'><parent link='b'/><child link='a'/></joint></robot>")
                                .string();
  const std::string floating =
      dir.Write("floating.urdf",
                "<robot name='x'><link name='a'/><link name='b'/><joint name='free' type='floating'>"
                "<parent link='a'/><child link='b'/></joint></robot>")
          .string();
  struct Case {
    std::vector<std::string> args;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {{"robot", "--tip", "tool", "--joints", "0,0"}, "--urdf FILE is required"},
      {{"robot", "--urdf", kPlanar, "--joints", "0,0"}, "--tip LINK is required"},
      {{"robot", "--urdf", kPlanar, "--tip", "tool"}, "--joints Q1,Q2,... is required"},
      {{"robot", "--urdf", "/nonexistent.urdf", "--tip", "tool", "--joints", "0,0"}, "no such URDF file"},
      {{"robot", "--urdf", malformed, "--tip", "a", "--joints", "0"}, "malformed URDF"},
      {{"robot", "--urdf", floating, "--tip", "b", "--joints", "0"}, "joint 'free' has type 'floating'"},
      {{"robot", "--urdf", kPlanar, "--tip", "hand", "--joints", "0,0"}, "tip link 'hand' is not in the URDF"},
      {{"robot", "--urdf", kPlanar, "--base", "world", "--tip", "tool", "--joints", "0,0"}, "base link 'world'"},
      {{"robot", "--urdf", kPlanar, "--base", "link2", "--tip", "link1", "--joints", "0"}, "not an ancestor"},
      {{"robot", "--urdf", kPlanar, "--tip", "tool", "--joints", "0,0,0"}, "--joints: 3 values given, but the chain base_link -> tool has 2 movable"},
      {{"robot", "--urdf", kPlanar, "--tip", "tool", "--joints", "0,nan"}, "--joints: joint 2 (elbow"},
      {{"robot", "--urdf", kPlanar, "--tip", "tool", "--joints", "0,abc"}, "expected an angle"},
      {{"robot", "--urdf", kPlanar, "--tip", "tool", "--joints", "0,3mm"}, "unit 'mm' does not fit"},
      {{"robot", "--urdf", kPlanar, "--tip", "tool", "--joints", "0,-135"},
       "joint 2 (elbow, continuous): a bare number is in radians (-135 rad is more than a full turn); write -135deg"},
      {Planar({"--direction", "0,0,0"}), "--direction: must be a non-zero vector"},
      {Planar({"--direction", "1,0"}), "--direction: expected 3 comma-separated numbers"},
      {Planar({"--direction", "1,x,0"}), "--direction: component 2 must be a finite number"},
      {Planar({"--point", "0.1,0"}), "--point: expected 3 comma-separated lengths"},
      {Planar({"--point", "0.1,0,nan"}), "--point"},
      {Planar({"--point", "100,0,0"}), "--point 100: a bare number is in metres"},
      {{"simulate", "--urdf", kPlanar, "--tip", "tool", "--joints", "0,1"}, "--direction X,Y,Z"},
      {{"simulate", "--robot-mass", "3kg", "--urdf", kPlanar, "--tip", "tool", "--joints", "0,1", "--direction",
        "0,1,0"},
       "--robot-mass and --urdf both give the robot mass"},
      {{"optimize", "--robot-mass", "3kg", "--urdf", kPlanar, "--tip", "tool", "--joints", "0,1", "--direction",
        "0,1,0"},
       "--robot-mass and --urdf both give the robot mass"},
      {{"speed-limit", "--robot-mass", "1kg,2kg", "--urdf", kPlanar, "--tip", "tool", "--joints", "0,1",
        "--direction", "0,1,0"},
       "--robot-mass and --urdf both give the robot mass"},
      // Inputs that once gave a wrong answer (issue 22).
      {{"robot", "--urdf", kFr3, "--tip", "fr3_link8", "--joints", "0,0,0,90deg,0,1.57,0"},
       "joint 4 (fr3_joint4): 1.5708 rad is not allowed (outside the URDF's limits [-3.0421, -0.1518] rad"},
      {{"speed-limit", "--urdf", kFr3, "--tip", "fr3_link8", "--joints", "0,0,0,90deg,0,1.57,0", "--direction",
        "1,0,0"},
       "fr3_joint4"},
      {{"robot", "--urdf", kPlanar, "--tip", "tool", "--joints", "0,1e300deg"},
       "--joints: joint 2 (elbow, continuous): '1e300deg' is not allowed (within a full turn"},
      {{"robot", "--urdf", kPlanar, "--tip", "tool", "--joints", "0,1e300rad"}, "'1e300rad' is not allowed"},
      {{"robot", "--urdf", kPlanar, "--base", "link2", "--tip", "link2", "--joints", ""}, "has no movable joint"},
      {{"robot", "--urdf", cycle, "--tip", "b", "--joints", "0,0"}, "link 'a' has two parents"},
      {{"robot", "--urdf", "/dev/zero", "--tip", "b", "--joints", "0,0"}, "larger than 16 MiB"},
      {Planar({"--point", "1e308,0,0"}), "--point"},
      {{"robot", "--ignore-joint-limits"}, "--urdf FILE is required"},
  };
  for (const Case& c : cases) {
    const auto run = Run(c.args);
    INFO(c.args[0] << " ... -> " << run.err);
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK_THAT(run.err, Catch::Contains(c.expected));
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  }
}

TEST_CASE("robot --ignore-joint-limits answers outside the URDF's limits and says so in a warning") {
  for (const std::string command : {"robot", "speed-limit"}) {
    std::vector<std::string> args = {command, "--urdf", kFr3, "--tip", "fr3_link8", "--joints", "0,0,0,90deg,0,1.57,0",
                                     "--direction", "1,0,0", "--ignore-joint-limits"};
    const auto run = Run(args);
    INFO(command << " -> " << run.err);
    CHECK(run.exit_code == 0);
    CHECK_THAT(run.out, Catch::Contains("were not checked (--ignore-joint-limits"));
  }
}

TEST_CASE("a direction of 1e308 components is the diagonal, not a fixed (0, 0, 0)") {
  const auto run = Run(Planar({"--direction", "1e308,1e308,0", "--json"}));
  REQUIRE(run.exit_code == 0);
  const json j = json::parse(run.out);
  CHECK(j["direction"][0].get<double>() == Approx(std::sqrt(0.5)));
  CHECK(j["direction"][1].get<double>() == Approx(std::sqrt(0.5)));
  CHECK(j["reflected_mass_kg"].is_number());
}
