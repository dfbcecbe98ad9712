// --limits FILE (issue 38): a body-region table of one's own. The example table (every force and
// pressure of ISO/TS 15066 Annex A × 0.8, k_H and m_H unchanged) scales every bare limit speed
// by exactly 0.8 (v = F/√(μk) is linear in the limit); with a Hertz covering the speed follows
// the covering's law instead (the library's own MaxSafeSpeed on the scaled limits), which is not
// 0.8× in general. Every verdict names the table and the SHA-256 of its bytes; a bad table is
// exit 2 with file:line:column.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/core/sha256.hpp"
#include "covopt/materials/body_regions.hpp"
#include "covopt/optim/body_region_check.hpp"

namespace {

using covopt::ContactType;
using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using covopt::cli::testing::SplitLines;
using covopt::materials::BodyRegionTable;
using nlohmann::json;

const std::string kCompany = COVOPT_COMPANY_LIMITS_TOML;

json JsonOf(const std::vector<std::string>& args) {
  const CliRun run = Run(args);
  INFO(fmt::format("{}", fmt::join(args, " ")) << " -> " << run.err);
  REQUIRE(run.exit_code == 0);
  return json::parse(run.out);
}

std::string Bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A file in the temporary directory holding `text`, removed at the end of the scope.
struct TempFile {
  std::filesystem::path path;
  TempFile(const std::string& name, const std::string& text)
      : path(std::filesystem::temp_directory_path() / name) {
    std::ofstream(path, std::ios::binary) << text;
  }
  ~TempFile() { std::filesystem::remove(path); }
};

}  // namespace

TEST_CASE("The --limits option with 0.8 x ISO: every bare limit speed is exactly 0.8x, force- or pressure-bound", "[limits]") {
  for (const std::string contact : {"transient", "clamped"}) {
    for (const std::string area : {"", "1cm2"}) {  // force-bound without an area; pressure-bound rows with one
      CAPTURE(contact, area);
      // The bare column: with the default covering and no area it is the force's alone.
      std::vector<std::string> args{"speed-limit", "--body-region", "all", "--contact", contact, "--robot-mass", "10kg",
                                    "--json"};
      if (!area.empty()) args.insert(args.end(), {"--contact-area", area});
      const json iso = JsonOf(args);
      args.insert(args.end(), {"--limits", kCompany});
      const json own = JsonOf(args);
      REQUIRE(iso["rows"].size() == own["rows"].size());
      std::size_t pressure_bound = 0;
      for (std::size_t i = 0; i < iso["rows"].size(); ++i) {
        const json& a = iso["rows"][i];
        const json& b = own["rows"][i];
        CAPTURE(a["region"], a["area"]);
        REQUIRE(a["region"] == b["region"]);
        if (a["region"] == "head") {  // Park et al.'s model: no table
          CHECK(a["bare_max_speed_m_per_s"] == b["bare_max_speed_m_per_s"]);
          continue;
        }
        CHECK(b["force_limit_N"].get<double>() == Approx(0.8 * a["force_limit_N"].get<double>()).epsilon(1e-12));
        CHECK(b["pressure_limit_Pa"].get<double>() ==
              Approx(0.8 * a["pressure_limit_Pa"].get<double>()).epsilon(1e-12));
        CHECK(b["bare_limited_by"] == a["bare_limited_by"]);
        if (a["bare_limited_by"] == "pressure") ++pressure_bound;
        CHECK(b["bare_max_speed_m_per_s"].get<double>() ==
              Approx(0.8 * a["bare_max_speed_m_per_s"].get<double>()).epsilon(1e-12));
      }
      if (area.empty()) CHECK(pressure_bound == 0);
      if (!area.empty()) CHECK(pressure_bound > 0);
    }
  }
}

TEST_CASE("The --limits option with 0.8 x ISO with a Hertz covering: the model's speeds, not 0.8x", "[limits]") {
  const std::vector<std::string> args{"speed-limit",          "--body-region",      "all",  "--robot-mass",
                                      "10kg",                 "--robot-radius",     "40mm", "--covering-modulus",
                                      "1MPa",                 "--covering-poisson", "0.4",  "--covering-thickness",
                                      "10mm",                 "--json"};
  const json iso = JsonOf(args);
  std::vector<std::string> with = args;
  with.insert(with.end(), {"--limits", kCompany});
  const json own = JsonOf(with);
  const BodyRegionTable& table = BodyRegionTable::Load(kCompany);
  const auto limits = table.AllLimits(ContactType::kTransient);
  covopt::BodyContactScene scene;
  scene.robot_mass_kg = 10.0;
  scene.robot_radius_m = 0.04;
  scene.covering = covopt::CoveringSpec{1e6, 0.4, 0.01};
  REQUIRE(own["rows"].size() == limits.size() + 1);  // and the head
  std::size_t not_scaled = 0;
  for (std::size_t i = 0; i < limits.size(); ++i) {
    const json& a = iso["rows"][i];
    const json& b = own["rows"][i];
    CAPTURE(limits[i].Describe(), b["covered_limited_by"]);
    const double model = covopt::optim::MaxSafeSpeed(scene, limits[i]).max_safe_speed_m_per_s;
    CHECK(b["covered_max_speed_m_per_s"].get<double>() == Approx(model).epsilon(1e-9));
    const double ratio = b["covered_max_speed_m_per_s"].get<double>() / a["covered_max_speed_m_per_s"].get<double>();
    // Hertz: F ∝ δ^1.5 in series with the body's spring, so the energy at the limit force grows as
    // F^(5/3) to F^2: a force-bound speed scales by 0.8 to 0.8^(5/6); the Hertz pressure grows as
    // F^(1/3), so a pressure-bound force scales by 0.8^3 and its speed by 0.512 to 0.512^(5/6).
    if (a["covered_limited_by"] == "force" && b["covered_limited_by"] == "force") {
      CHECK(ratio >= 0.8 - 1e-9);
      CHECK(ratio <= std::pow(0.8, 5.0 / 6.0) + 1e-9);
    } else if (a["covered_limited_by"] == "pressure" && b["covered_limited_by"] == "pressure") {
      CHECK(ratio >= 0.512 - 1e-9);
      CHECK(ratio <= std::pow(0.512, 5.0 / 6.0) + 1e-9);
    }
    if (std::abs(ratio - 0.8) > 0.01) ++not_scaled;
  }
  CHECK(not_scaled > 0);
}

TEST_CASE("The --limits option: the JSON, the text and body-regions name the table and its SHA-256", "[limits]") {
  const std::string digest = covopt::Sha256Hex(Bytes(kCompany));
  REQUIRE(digest.size() == 64);
  const json own = JsonOf({"simulate", "--body-region", "chest", "--limits", kCompany, "--robot-mass", "10kg",
                           "--json"});
  const json& tables = own["summary"]["limit_tables"];
  REQUIRE(tables.size() == 1);
  CHECK(tables[0]["source"] == kCompany);
  CHECK(tables[0]["sha256"] == digest);
  CHECK(tables[0]["edition"].get<std::string>().find("0.8") != std::string::npos);
  CHECK(own["summary"]["standards"][0] == tables[0]["edition"]);
  // The provenance hashes the same file.
  bool hashed = false;
  for (const json& input : own["provenance"]["inputs"]) hashed = hashed || (input["role"] == "limits" && input["sha256"] == digest);
  CHECK(hashed);

  const json iso = JsonOf({"simulate", "--body-region", "chest", "--robot-mass", "10kg", "--json"});
  const json& built_in = iso["summary"]["limit_tables"];
  REQUIRE(built_in.size() == 1);
  CHECK(built_in[0]["source"] == "built-in");
  CHECK(built_in[0]["edition"] == "ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M");
  CHECK(built_in[0]["sha256"] == covopt::Sha256Hex(Bytes(COVOPT_BODY_REGIONS_TOML)));
  CHECK(iso["summary"]["standards"][0] == "ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M");

  const CliRun text = Run({"simulate", "--body-region", "chest", "--limits", kCompany, "--robot-mass", "10kg"});
  REQUIRE(text.exit_code == 0);
  CHECK(text.out.find("Limits       Company limits") != std::string::npos);
  CHECK(text.out.find(digest) != std::string::npos);

  const json list = JsonOf({"body-regions", "list", "--limits", kCompany, "--json"});
  const json list_iso = JsonOf({"body-regions", "list", "--json"});
  REQUIRE(list.size() == list_iso.size());
  for (std::size_t i = 0; i < list.size(); ++i) {
    CHECK(list[i]["quasi_static_force_N"].get<double>() ==
          Approx(0.8 * list_iso[i]["quasi_static_force_N"].get<double>()).epsilon(1e-12));
    CHECK(list[i]["stiffness_N_per_m"] == list_iso[i]["stiffness_N_per_m"]);
    CHECK(list[i]["limit_table"]["sha256"] == digest);
  }
  const CliRun show = Run({"body-regions", "show", "chest", "--limits", kCompany});
  REQUIRE(show.exit_code == 0);
  CHECK(show.out.find("F_qs = 112 N") != std::string::npos);  // 0.8 × 140 N
  CHECK(show.out.find(digest) != std::string::npos);
}

TEST_CASE("The --limits option: a bad table or file is exit 2 with one line naming file:line:column", "[limits]") {
  std::string text = Bytes(kCompany);
  const std::string from = "quasi_static_force_N = 112";  // the chest
  REQUIRE(text.find(from) != std::string::npos);
  text.replace(text.find(from), from.size(), "quasi_static_force_N = -112");
  const TempFile bad("covopt_test_limits_negative.toml", text);
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"speed-limit", "--body-region", "chest", "--limits", bad.path.string()},
        std::vector<std::string>{"body-regions", "list", "--limits", bad.path.string()}}) {
    const CliRun run = Run(args);
    INFO(run.err);
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK(SplitLines(run.err).size() == 1);
    CHECK(run.err.find(bad.path.string() + ":") != std::string::npos);
    CHECK(run.err.find("quasi_static_force_N") != std::string::npos);
    CHECK(run.err.find("-112") != std::string::npos);
  }
  const CliRun missing = Run({"speed-limit", "--body-region", "chest", "--limits", "/nonexistent/limits.toml"});
  CHECK(missing.exit_code == 2);
  CHECK(missing.err.find("/nonexistent/limits.toml") != std::string::npos);
  // --limits judges body regions: without --body-region it is refused, not ignored.
  const CliRun alone = Run({"speed-limit", "--limits", kCompany});
  CHECK(alone.exit_code == 2);
  CHECK(alone.err.find("--limits") != std::string::npos);
}
