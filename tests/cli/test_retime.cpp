// `covopt retime` run in-process: the FR3 pick move re-timed is safe when `covopt audit` audits
// the --output CSV again; its cycle time is no worse than the uniform slow-down's (strictly
// better, since the limit is local); the joints' limits hold at every sample of the CSV; the
// JSON has its documented keys; thicker coverings never lengthen the cycle; bad input is exit 2
// with one line on stderr naming the flag and nothing on stdout.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "audit_test_support.hpp"
#include "cli_test_support.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using covopt::cli::testing::TempDir;
using nlohmann::json;

const std::string& kFr3 = covopt::cli::testing::kFr3Urdf;
const std::string& kPick = covopt::cli::testing::kFr3Pick;

/// The FR3 pick move with a 10 mm covering of 0.5 MPa on every link, a coarse surface (quick).
std::vector<std::string> Fr3(const std::string& command, std::vector<std::string> more = {}) {
  more.insert(more.begin(), {"--surface-spacing", "100mm"});
  return covopt::cli::testing::Fr3Command(command, kPick, more);
}

json JsonOf(const CliRun& run) { return covopt::cli::testing::JsonOfRun(run); }

void RequireBadInput(const CliRun& run, const std::string& names) {
  covopt::cli::testing::RequireRefused(run, names, "retime");
}

/// The numbers of a trajectory CSV's data lines.
std::vector<std::vector<double>> CsvRows(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 't') continue;
    std::vector<double> v;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) v.push_back(std::stod(cell));
    rows.push_back(std::move(v));
  }
  return rows;
}

}  // namespace

TEST_CASE("retime of the FR3 pick move is safe when audited again and beats the uniform slow-down", "[cli][retime]") {
  const TempDir dir;
  const std::string csv = (dir / "retimed.csv").string();
  const json j = JsonOf(Run(Fr3("retime", {"--joint-accel-limit", "10", "--output", csv, "--json"})));
  for (const char* key : {"status", "message", "summary", "cycle_time_s", "original_cycle_time_s",
                          "uniform_cycle_time_s", "uniform_speed_scale", "joint_speed_limits_rad_per_s",
                          "joint_acceleration_limits_rad_per_s2", "slowdowns", "samples", "before", "after", "thickness_sweep",
                          "scope", "warnings", "input_sources", "provenance"}) {
    CHECK(j.contains(key));
  }
  REQUIRE(j["status"] == "safe");
  CHECK(j["summary"]["command"] == "retime");
  CHECK(j["summary"]["safe"] == true);
  const double uniform_scale = j["uniform_speed_scale"].get<double>();
  const double cycle = j["cycle_time_s"].get<double>();
  const double uniform = j["uniform_cycle_time_s"].get<double>();
  const double original = j["original_cycle_time_s"].get<double>();
  CHECK(original == Approx(1.5));
  REQUIRE(uniform_scale < 1.0);  // the original program is unsafe: the comparison means something
  CHECK(uniform == Approx(original / uniform_scale).epsilon(1e-9));
  CHECK(cycle < uniform);   // strictly better: one link at one instant set the uniform scale
  CHECK(cycle > original);  // it had to slow somewhere
  CHECK_FALSE(j["slowdowns"].empty());
  const std::size_t n = j["sample_count"].get<std::size_t>();
  for (const char* key : {"original_time_s", "time_s", "safe_path_speed", "path_speed", "bound", "limiting_link"}) {
    CHECK(j["samples"][key].size() == n);
  }
  // The chosen speed never exceeds the safe one or the programmed one.
  for (std::size_t i = 0; i < n; ++i) {
    const double chosen = j["samples"]["path_speed"][i].get<double>();
    CHECK(chosen <= 1.0 + 1e-9);
    if (!j["samples"]["safe_path_speed"][i].is_null()) {
      CHECK(chosen <= j["samples"]["safe_path_speed"][i].get<double>() * (1.0 + 1e-6));
    }
  }

  // The re-timed CSV: same joints and samples, the cycle time, the joints' limits at every sample.
  const auto rows = CsvRows(csv);
  REQUIRE(rows.size() == n);
  CHECK(rows.back().front() == Approx(cycle).epsilon(1e-9));
  const std::vector<double> speed_limits = [&] {
    std::vector<double> v;
    for (const json& x : j["joint_speed_limits_rad_per_s"]) v.push_back(x.is_null() ? INFINITY : x.get<double>());
    return v;
  }();
  REQUIRE(speed_limits.size() == 7);
  for (const auto& row : rows) {
    REQUIRE(row.size() == 15);
    for (std::size_t k = 0; k < 7; ++k) CHECK(std::abs(row[8 + k]) <= speed_limits[k] * (1.0 + 1e-6));
  }
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) {  // the acceleration between samples, by differences
    const double dt = rows[i + 1][0] - rows[i][0];
    REQUIRE(dt > 0.0);
    for (std::size_t k = 0; k < 7; ++k) CHECK(std::abs(rows[i + 1][8 + k] - rows[i][8 + k]) / dt <= 10.0 * (1.0 + 1e-3));
  }

  // `covopt audit` of the re-timed program: safe at every sample, within the tolerance.
  std::vector<std::string> audit = Fr3("audit", {"--json"});
  std::replace(audit.begin(), audit.end(), kPick, csv);
  const json after = JsonOf(Run(audit));
  CHECK(after["safe_speed_scale"].get<double>() >= 1.0 - 1e-6);
}

TEST_CASE("retime's cycle time against thickness never grows with a thicker covering", "[cli][retime]") {
  const json j = JsonOf(Run(Fr3("retime", {"--joint-accel-limit", "10", "--thickness", "5mm,20mm", "--json"})));
  const json& sweep = j["thickness_sweep"];
  REQUIRE(sweep["points"].size() == 2);
  const json& thin = sweep["points"][0];
  const json& thick = sweep["points"][1];
  CHECK(thin["thickness_m"].get<double>() == Approx(0.005));
  CHECK(thick["thickness_m"].get<double>() == Approx(0.020));
  REQUIRE(thin["status"] == "safe");
  REQUIRE(thick["status"] == "safe");
  CHECK(thick["cycle_time_s"].get<double>() <= thin["cycle_time_s"].get<double>() * (1.0 + 1e-9));
  CHECK(thick["safe_speed_scale"].get<double>() >= thin["safe_speed_scale"].get<double>());
  for (const json* p : {&thin, &thick}) {
    CHECK((*p)["cycle_time_s"].get<double>() <= (*p)["uniform_cycle_time_s"].get<double>() * (1.0 + 1e-9));
  }
}

TEST_CASE("retime refuses bad joint limits, thicknesses and outputs naming the flag", "[cli][retime]") {
  RequireBadInput(Run(Fr3("retime")), "--joint-accel-limit");
  RequireBadInput(Run(Fr3("retime", {"--joint-accel-limit", "-10"})), "--joint-accel-limit");
  RequireBadInput(Run(Fr3("retime", {"--joint-accel-limit", "nan"})), "--joint-accel-limit");
  RequireBadInput(Run(Fr3("retime", {"--joint-accel-limit", "10,10"})), "--joint-accel-limit");
  RequireBadInput(Run(Fr3("retime", {"--joint-accel-limit", "ten"})), "--joint-accel-limit");
  RequireBadInput(Run(Fr3("retime", {"--joint-accel-limit", "10", "--joint-speed-limit", "0"})), "--joint-speed-limit");
  RequireBadInput(Run(Fr3("retime", {"--joint-accel-limit", "10", "--thickness", "0..40mm:1"})), "--thickness");
  RequireBadInput(Run(Fr3("retime", {"--joint-accel-limit", "10", "--thickness", "banana"})), "--thickness");
  RequireBadInput(Run(Fr3("retime", {"--joint-accel-limit", "10", "--max-speed-scale", "0"})), "--max-speed-scale");
  RequireBadInput(Run(Fr3("retime", {"--joint-accel-limit", "10", "--output", "/nonexistent-dir/x.csv"})), "--output");
}
