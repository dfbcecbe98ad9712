// `covopt robot --trajectory` run in-process: that the answer is the library's check of the
// same trajectory to the bit (ReadJointTrajectory -> ContactMotion -> CheckTrajectory,
// report::TrajectoryCheckJson); that the trajectory with every velocity multiplied by its
// safe_speed_scale comes out with scale 1 and safe, a hair faster unsafe; that --json, --csv
// and the table agree; the scene flags, material, safety factor and criterion reach the check;
// a point at rest; --plot with and without gnuplot; and that bad input is exit 2 with one
// line on stderr naming the flag and nothing on stdout.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/materials/catalog.hpp"
#include "covopt/optim/trajectory_check.hpp"
#include "covopt/report/trajectory_json.hpp"
#include "covopt/robot.hpp"
#include "plot.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::ReadFile;
using covopt::cli::testing::Run;
using covopt::cli::testing::ScopedEnv;
using covopt::cli::testing::SplitLines;
using covopt::cli::testing::TempDir;
using nlohmann::json;

const std::string kFr3 = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3.urdf";
const std::string kPick = std::string(COVOPT_ROBOT_MODELS_DIR) + "/franka_fr3_pick.csv";
const std::string kPlanar = std::string(COVOPT_ROBOT_TEST_DATA_DIR) + "/planar_2link.urdf";

std::vector<std::string> Fr3(const std::string& trajectory, std::vector<std::string> more = {}) {
  std::vector<std::string> args = {"robot", "--urdf", kFr3, "--tip", "fr3_link8", "--trajectory", trajectory};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

json JsonOf(const CliRun& run) {
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(run.err.empty());
  return json::parse(run.out);
}

/// The samples of a trajectory CSV: time, 7 positions, 7 velocities per row.
std::vector<std::vector<double>> ReadRows(const std::string& path) {
  std::vector<std::vector<double>> rows;
  bool header = true;
  for (const std::string& line : SplitLines(ReadFile(path))) {
    if (line.empty() || line.front() == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

/// The shipped trajectory with every joint velocity multiplied by `factor` (exact decimal
/// round trip: 17 significant digits).
std::string ScaledTrajectory(const TempDir& dir, double factor) {
  std::string text = "time_s,q1,q2,q3,q4,q5,q6,q7,qd1,qd2,qd3,qd4,qd5,qd6,qd7\n";
  for (const std::vector<double>& row : ReadRows(kPick)) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      text += fmt::format("{}{:.17g}", c ? "," : "", c >= 8 ? row[c] * factor : row[c]);
    }
    text += '\n';
  }
  return dir.Write(fmt::format("scaled-{:.17g}.csv", factor), text).string();
}

}  // namespace

TEST_CASE("robot --trajectory --json is the library's check of the same trajectory, to the bit", "[trajectory]") {
  // --keep-travel: the library's default options (the travel rule kept).
  const json j = JsonOf(Run(Fr3(kPick, {"--keep-travel", "--json"})));
  const auto chain = covopt::robot::KinematicChain::FromUrdfFile(kFr3, {"", "fr3_link8"});
  const auto motion = covopt::robot::ContactMotion(chain, covopt::robot::ReadJointTrajectory(kPick, 7),
                                                   Eigen::Vector3d::Zero());
  const auto check = covopt::optim::CheckTrajectory(covopt::Scene{}, covopt::optim::MotionSamples(motion.samples));
  // No covering was given: the CLI says the default is assumed.
  const std::vector<std::string> warnings = j["warnings"].get<std::vector<std::string>>();
  REQUIRE(warnings.size() == 1);
  CHECK_THAT(warnings.front(), Catch::StartsWith("no covering given"));
  CHECK(covopt::cli::testing::WithoutProvenance(j) ==
        json::parse(covopt::report::TrajectoryCheckJson(check, motion, covopt::Scene{}, std::nullopt, {}, warnings)));
  // The numbers themselves, not only their JSON.
  REQUIRE(j["samples"].size() == 101);
  CHECK(j["safe_speed_scale"].get<double>() == check.safe_speed_scale);
  REQUIRE(check.worst_sample.has_value());
  CHECK(j["worst_sample"]["index"] == *check.worst_sample);
  CHECK(j["status"] == "safe");
  CHECK(j["criterion"]["parts"] == json::array({"laceration", "contusion", "fracture", "full-compression", "crush", "law-validity"}));
  CHECK(j["joint_names"].size() == 7);
  CHECK(j["joint_names"][0] == "fr3_joint1");
  CHECK(j["scene"]["robot"].count("mass_kg") == 0);
  CHECK(j["scene"]["robot"].count("speed_m_per_s") == 0);
  for (std::size_t i = 0; i < check.samples.size(); ++i) {
    const json& s = j["samples"][i];
    CHECK(s["speed_m_per_s"].get<double>() == motion.samples[i].speed_m_per_s);
    CHECK(s["reflected_mass_kg"].get<double>() == motion.samples[i].reflected_mass_kg);
    CHECK(s["max_safe_speed_m_per_s"].get<double>() == check.samples[i].speed_limit.max_safe_speed_m_per_s);
    CHECK(s["contusion_ratio"].get<double>() == check.samples[i].contusion_ratio);
  }
  // Both ends are at rest: no scale, ratios 0.
  CHECK(j["samples"][0]["moving"] == false);
  CHECK(j["samples"][0]["speed_scale"].is_null());
  CHECK(j["samples"][100]["moving"] == false);
}

TEST_CASE("robot --trajectory: the trajectory sped up by its safe speed scale is exactly at the limit",
          "[trajectory]") {
  const TempDir dir;
  const double k = JsonOf(Run(Fr3(kPick, {"--json"})))["safe_speed_scale"].get<double>();
  REQUIRE(k > 1.0);
  // Sped up 3x the pick move exceeds FR3's joint velocity limits (2.62 rad/s): the covering's
  // limit is what this test checks, so the URDF's limits are set aside.
  const json at_limit = JsonOf(Run(Fr3(ScaledTrajectory(dir, k), {"--json", "--ignore-joint-limits"})));
  CHECK(at_limit["safe_speed_scale"].get<double>() == Approx(1.0).margin(1e-9));
  CHECK(at_limit["status"] == "safe");
  CHECK(at_limit["unsafe_sample_count"] == 0);
  const json beyond = JsonOf(Run(Fr3(ScaledTrajectory(dir, k * (1.0 + 1e-6)), {"--json", "--ignore-joint-limits"})));
  CHECK(beyond["status"] == "unsafe");
  CHECK(beyond["safe_speed_scale"].get<double>() < 1.0);
  CHECK(beyond["unsafe_sample_count"].get<int>() >= 1);
  CHECK(beyond["worst_sample"]["safe"] == false);
  // Slower by half: twice the scale (the max safe speeds do not change, the speeds halve).
  const json slower = JsonOf(Run(Fr3(ScaledTrajectory(dir, 0.5), {"--json"})));
  CHECK(slower["safe_speed_scale"].get<double>() == Approx(2.0 * k).epsilon(1e-12));
}

TEST_CASE("robot --trajectory: --json, --csv and the table agree", "[trajectory]") {
  const TempDir dir;
  const auto csv = dir / "samples.csv";
  const CliRun json_run = Run(Fr3(kPick, {"--json", "--csv", csv.string()}));
  const json j = JsonOf(json_run);
  const std::vector<std::string> lines = SplitLines(ReadFile(csv));
  REQUIRE(lines.size() == 102);
  CHECK(lines[0] ==
        "time_s,speed_m_per_s,reflected_mass_kg,moving,max_safe_speed_m_per_s,speed_scale,limited_by,"
        "laceration_ratio,contusion_ratio,fracture_ratio,compression_ratio,safe,within_law");
  const auto columns = covopt::report::TrajectorySampleColumns();
  for (std::size_t i = 0; i < 101; ++i) {
    std::vector<std::string> cells;
    std::istringstream in(lines[i + 1]);
    for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
    if (lines[i + 1].back() == ',') cells.emplace_back();
    REQUIRE(cells.size() == columns.size());
    const json& sample = j["samples"][i];
    for (std::size_t c = 0; c < columns.size(); ++c) {
      const json& value = sample[std::string(columns[c])];
      INFO("sample " << i << ", column " << columns[c]);
      if (value.is_null()) CHECK(cells[c].empty());
      else if (value.is_string()) CHECK(cells[c] == value.get<std::string>());
      else if (value.is_boolean()) CHECK(cells[c] == (value.get<bool>() ? "true" : "false"));
      else CHECK(std::stod(cells[c]) == value.get<double>());
    }
  }
  // --csv - prints the same text instead of the table.
  const CliRun to_stdout = Run(Fr3(kPick, {"--csv", "-"}));
  REQUIRE(to_stdout.exit_code == 0);
  CHECK(to_stdout.out == ReadFile(csv));

  const CliRun table = Run(Fr3(kPick));
  REQUIRE(table.exit_code == 0);
  CHECK(table.err.empty());
  CHECK(table.out.find("Verdict    " + j["message"].get<std::string>()) != std::string::npos);
  const int worst = j["worst_sample"]["index"].get<int>();
  CHECK(table.out.find(fmt::format("Worst      sample {} at t = {:.4g} s", worst,
                                   j["worst_sample"]["time_s"].get<double>())) != std::string::npos);
  CHECK(table.out.find("(10 of 101 samples") != std::string::npos);
  // The rows are the 10 moving samples with the smallest speed scale, in time order.
  std::vector<std::pair<double, int>> scales;
  for (int i = 0; i < 101; ++i) {
    const json& s = j["samples"][static_cast<std::size_t>(i)];
    if (s["moving"].get<bool>()) scales.emplace_back(s["speed_scale"].get<double>(), i);
  }
  std::sort(scales.begin(), scales.end());
  std::vector<int> expected;
  for (std::size_t r = 0; r < 10; ++r) expected.push_back(scales[r].second);
  std::sort(expected.begin(), expected.end());
  std::vector<int> shown;
  const std::vector<std::string> table_lines = SplitLines(table.out);
  const auto header = std::find_if(table_lines.begin(), table_lines.end(),
                                   [](const std::string& l) { return l.find("max safe [m/s]") != std::string::npos; });
  REQUIRE(header != table_lines.end());
  for (auto line = header + 1; line != table_lines.end() && !line->empty() && line->find('(') == std::string::npos;
       ++line) {
    shown.push_back(std::stoi(*line));
  }
  CHECK(shown == expected);
  CHECK(std::find(shown.begin(), shown.end(), worst) != shown.end());
  CHECK(table.out.find("Warning: no covering given") != std::string::npos);
}

TEST_CASE("robot --trajectory: the covering, material, safety factor and criterion reach the check",
          "[trajectory]") {
  const double covered = JsonOf(Run(Fr3(kPick, {"--json"})))["safe_speed_scale"].get<double>();
  const json bare = JsonOf(Run(Fr3(kPick, {"--covering-thickness", "0", "--json"})));
  CHECK(bare["safe_speed_scale"].get<double>() < covered);
  CHECK(bare["scene"]["covering"]["thickness_m"] == 0.0);

  const json derated = JsonOf(Run(Fr3(kPick, {"--safety-factor", "2", "--json"})));
  CHECK(derated["safety_factor"] == 2.0);
  CHECK(derated["safe_speed_scale"].get<double>() < covered);
  CHECK(derated["warnings"].size() == 2);  // the safety factor's input warning, the assumed covering
  const json paper = JsonOf(Run(Fr3(kPick, {"--allow-full-compression", "--json"})));
  CHECK(paper["criterion"]["parts"] == json::array({"laceration", "contusion", "fracture", "crush", "law-validity"}));

  const json material = JsonOf(Run(Fr3(kPick, {"--material", "XPS Foamular 250", "--json"})));
  CHECK(material["scene"]["covering"]["material"] == "XPS Foamular 250");
  covopt::Scene scene;
  scene.covering.youngs_modulus_Pa = material["scene"]["covering"]["youngs_modulus_Pa"].get<double>();
  scene.covering.poisson_ratio = material["scene"]["covering"]["poisson_ratio"].get<double>();
  const auto chain = covopt::robot::KinematicChain::FromUrdfFile(kFr3, {"", "fr3_link8"});
  const auto motion = covopt::robot::ContactMotion(chain, covopt::robot::ReadJointTrajectory(kPick, 7),
                                                   Eigen::Vector3d::Zero());
  // XPS crushes (25 psi): its strength reaches the check and sets a very low scale.
  covopt::optim::TrajectoryCheckOptions crush;
  crush.limit.covering_compressive_strength_Pa =
      *covopt::materials::Catalog::BuiltIn().Find("XPS Foamular 250")->compressive_strength_Pa;
  const auto checked = covopt::optim::CheckTrajectory(scene, covopt::optim::MotionSamples(motion.samples), crush);
  CHECK(material["safe_speed_scale"].get<double>() == checked.safe_speed_scale);
  CHECK(checked.safe_speed_scale < 0.1);

  // A contact point 10 cm out of the flange: its own speeds and masses.
  const json offset = JsonOf(Run(Fr3(kPick, {"--point", "0,0,100mm", "--json"})));
  CHECK(offset["safe_speed_scale"].get<double>() != covered);
}

TEST_CASE("robot --trajectory: a point that never moves is at rest, and a short trajectory lists every sample",
          "[trajectory]") {
  const TempDir dir;
  const auto still = dir.Write("still.csv", "t,q1,q2,qd1,qd2\n0,0.3,1.2,0,0\n0.1,0.3,1.2,0,0\n");
  const json j = JsonOf(Run({"robot", "--urdf", kPlanar, "--tip", "tool", "--trajectory", still.string(), "--json"}));
  CHECK(j["status"] == "at-rest");
  CHECK(j["safe_speed_scale"].is_null());
  CHECK(j["worst_sample"].is_null());
  CHECK(j["joint_names"] == json::array({"shoulder", "elbow"}));

  const auto moving =
      dir.Write("moving.csv", "t,q1,q2,qd1,qd2\n0,0.3,1.2,0,0\n0.1,0.3,1.2,0.5,-0.2\n0.2,0.35,1.18,1,0\n");
  const CliRun table = Run({"robot", "--urdf", kPlanar, "--tip", "tool", "--trajectory", moving.string()});
  INFO(table.err);
  REQUIRE(table.exit_code == 0);
  CHECK(table.out.find("at rest") != std::string::npos);  // sample 0 is listed
  CHECK(table.out.find("samples:") == std::string::npos);  // no "(N of M samples: ...)" note
}

TEST_CASE("robot --trajectory --plot draws the chart, and a missing gnuplot is exit 1", "[trajectory][plot]") {
  const TempDir dir;
  const auto png = dir / "trajectory.png";
  {
    const ScopedEnv no_path("PATH", dir.path().string());
    const CliRun missing = Run(Fr3(kPick, {"--plot", png.string()}));
    CHECK(missing.exit_code == 1);
    CHECK(missing.err.find("gnuplot") != std::string::npos);
    CHECK(!std::filesystem::exists(png));
  }
  if (!covopt::cli::FindOnPath("gnuplot")) {
    WARN("gnuplot is not on PATH; skipping the chart");
    return;
  }
  const CliRun run = Run(Fr3(kPick, {"--plot", png.string()}));
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const std::string image = ReadFile(png);
  REQUIRE(image.size() > 8);
  CHECK(image.substr(1, 3) == "PNG");
  const auto svg = dir / "trajectory.svg";
  REQUIRE(Run(Fr3(kPick, {"--plot", svg.string(), "--covering-thickness", "0"})).exit_code == 0);
  CHECK(ReadFile(svg).find("<svg") != std::string::npos);
}

TEST_CASE("robot --trajectory bad input: exit 2, one line naming the flag, nothing on stdout", "[trajectory]") {
  const TempDir dir;
  const std::string header = "t,q1,q2,q3,q4,q5,q6,q7,qd1,qd2,qd3,qd4,qd5,qd6,qd7\n";
  const std::string row = "0,0,-0.78,0,-2.35,0,1.57,0.78,0,0,0,0,0,0,0\n";
  const std::string columns = dir.Write("columns.csv", header + "0,0,-0.78,0,-2.35,0,1.57,0.78,0,0,0\n").string();
  const std::string nan =
      dir.Write("nan.csv", header + row + "0.1,0,-0.78,0,-2.35,0,1.57,0.78,nan,0,0,0,0,0,0\n").string();
  const std::string backwards =
      dir.Write("backwards.csv", header + "1" + row.substr(1) + row).string();
  const std::string too_fast =
      dir.Write("fast.csv", header + "0,0,-0.78,0,-2.35,0,1.57,0.78,1000,0,0,0,0,0,0\n").string();
  const std::string missing = (dir / "no-such-file.csv").string();
  const std::string degrees = dir.Write("degrees.csv", header + "0,0,-45,0,-135,0,90,45,0,0,0,0,0,0,0\n").string();
  const std::string hex = dir.Write("hex.csv", header + "0,0x1p3,-0.78,0,-2.35,0,1.57,0.78,0,0,0,0,0,0,0\n").string();
  const std::string beyond_limit = dir.Write("limit.csv", header + "0,0,-0.78,0,1.57,0,1.57,0.78,0,0,0,0,0,0,0\n").string();
  struct Case {
    std::vector<std::string> args;
    std::string named;
  };
  const std::vector<Case> cases = {
      {Fr3(columns), "11 columns, expected 15"},
      {Fr3(nan), "column 9 (qd1 [rad/s])"},
      {Fr3(backwards), "time goes backwards"},
      {Fr3(too_fast, {"--ignore-joint-limits"}), "--trajectory '" + too_fast + "': trajectory sample 1: speed_m_per_s"},
      {Fr3(too_fast), "column 9 (qd1 [rad/s], joint 'fr3_joint1'): 1000 rad/s is not allowed (outside the URDF's "
                      "velocity limit [-2.62, 2.62] rad/s"},
      {Fr3(degrees), "column 3 (q2 [rad], joint 'fr3_joint2'): -45 rad is not allowed (within a full turn"},
      {Fr3(hex), "column 2 (q1 [rad]): expected a finite number (got '0x1p3'), in decimal"},
      {Fr3(beyond_limit), "outside the URDF's limits [-3.0421, -0.1518] rad of joint 'fr3_joint4'"},
      {Fr3("/dev/zero"), "larger than 64 MiB, the limit for a trajectory file"},
      {Fr3(missing), "no such trajectory file"},
      {Fr3(kPick, {"--joints", "0,0,0,0,0,0,0"}), "--joints"},
      {Fr3(kPick, {"--direction", "1,0,0"}), "--direction"},
      {Fr3(kPick, {"--robot-mass", "3kg"}), "--robot-mass"},
      {Fr3(kPick, {"--speed", "1m/s"}), "--speed"},
      {Fr3(kPick, {"--covering-thickness", "-1mm"}), "covering.thickness"},
      {Fr3(kPick, {"--plot", "chart.pdf"}), "--plot"},
      {Fr3(kPick, {"--json", "--csv", "-"}), "--csv"},
      {Fr3(kPick, {"--safety-factor", "0.5"}), "--safety-factor"},
      {Fr3(""), "--trajectory"},
      {{"robot", "--urdf", kFr3, "--trajectory", kPick}, "--tip"},
      {{"robot", "--urdf", kFr3, "--tip", "fr3_link8", "--joints", "0,0,0,0,0,0,0", "--covering-thickness", "2mm"},
       "--covering-thickness applies with --trajectory"},
      {{"robot", "--urdf", kFr3, "--tip", "fr3_link8", "--joints", "0,0,0,0,0,0,0", "--csv", "x.csv"},
       "--csv applies with --trajectory"},
  };
  for (const Case& c : cases) {
    const CliRun run = Run(c.args);
    INFO(fmt::format("{}", fmt::join(c.args, " ")) << " -> " << run.err);
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK(SplitLines(run.err).size() == 1);
    CHECK(run.err.find(c.named) != std::string::npos);
  }
}

TEST_CASE("robot --trajectory: a file without a header is read from its first row, with a warning", "[trajectory]") {
  const TempDir dir;
  // The first row moves fastest: dropping it as a header would hide it.
  const std::string rows = "0,0,-0.78,0,-2.35,0,1.57,0.78,2.5,0,0,0,0,0,0\n"
                           "0.1,0,-0.78,0,-2.35,0,1.57,0.78,0.1,0,0,0,0,0,0\n";
  const std::string headerless = dir.Write("headerless.csv", rows).string();
  const std::string with_header =
      dir.Write("header.csv", "t,q1,q2,q3,q4,q5,q6,q7,qd1,qd2,qd3,qd4,qd5,qd6,qd7\n" + rows).string();
  const json a = JsonOf(Run(Fr3(headerless, {"--json"})));
  const json b = JsonOf(Run(Fr3(with_header, {"--json"})));
  CHECK(a["sample_count"] == 2);
  CHECK(a["safe_speed_scale"] == b["safe_speed_scale"]);
  CHECK(a["worst_sample"]["index"] == 0);
  CHECK_THAT(a["warnings"].dump(), Catch::Contains("no header line"));
  CHECK_THAT(b["warnings"].dump(), !Catch::Contains("no header line"));
}

TEST_CASE("robot --trajectory --ignore-joint-limits checks a motion outside the URDF's limits, with a warning",
          "[trajectory]") {
  const TempDir dir;
  const std::string beyond = dir.Write("beyond.csv", "t,q1,q2,q3,q4,q5,q6,q7,qd1,qd2,qd3,qd4,qd5,qd6,qd7\n"
                                                     "0,0,-0.78,0,1.57,0,1.57,0.78,0.5,0,0,0,0,0,0\n").string();
  const json j = JsonOf(Run(Fr3(beyond, {"--json", "--ignore-joint-limits"})));
  CHECK_THAT(j["warnings"].dump(), Catch::Contains("were not checked"));
}
