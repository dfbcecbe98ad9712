// `covopt simulate/speed-limit/optimize --body-region` run in-process (issue 24): the bare
// robot's speed limit is Annex A's F_lim / sqrt(mu k_H) from the table's own values, the
// all-regions table has one row per permitted area plus the head, clamped is stricter than
// transient for every area, the verdicts are the library's (a bare force v sqrt(mu k), a
// pressure F/A), the head keeps simulate's own answer, and bad input is exit 2 with one line
// on stderr naming the choices and nothing on stdout.
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "cli_test_support.hpp"
#include "covopt/core/quantity.hpp"
#include "covopt/materials/body_regions.hpp"
#include "plot.hpp"

namespace {

using covopt::ContactType;
using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using covopt::cli::testing::SplitLines;
using covopt::materials::BodyRegionTable;
using nlohmann::json;

json JsonOf(const std::vector<std::string>& args) {
  const CliRun run = Run(args);
  INFO(fmt::format("{}", fmt::join(args, " ")) << " -> " << run.err);
  REQUIRE(run.exit_code == 0);
  return json::parse(run.out);
}

/// Each case is bad input: exit 2, nothing on stdout, one line on stderr containing every
/// string of `named`.
void ExpectRefused(const std::vector<std::string>& args, const std::vector<std::string>& named) {
  const CliRun run = Run(args);
  INFO(fmt::format("{}", fmt::join(args, " ")) << " -> " << run.err);
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK(SplitLines(run.err).size() == 1);
  for (const std::string& text : named) CHECK(run.err.find(text) != std::string::npos);
}

/// Annex A's bare-robot speed limit from the table's values: F_lim / sqrt(mu k_H).
double AnnexASpeed(double robot_mass_kg, const covopt::materials::BodyLimits& limits) {
  const double mu = limits.contact == ContactType::kClamped
                        ? robot_mass_kg
                        : 1.0 / (1.0 / robot_mass_kg + 1.0 / limits.region->effective_mass_kg);
  return limits.force_N / std::sqrt(mu * limits.region->stiffness_N_per_m);
}

}  // namespace

TEST_CASE("speed-limit --body-region all: one row per permitted area and the head, bare speeds are Annex A's",
          "[body_regions]") {
  const BodyRegionTable& table = BodyRegionTable::BuiltIn();
  const auto permitted = table.AllLimits(ContactType::kTransient);
  const json j = JsonOf({"speed-limit", "--body-region", "all", "--robot-mass", "10kg", "--json"});
  const json& rows = j["rows"];
  REQUIRE(rows.size() == permitted.size() + 1);
  // The standard forbids transient contact with three areas (skull/forehead and face): 26 + head.
  CHECK(rows.size() == table.area_count() - 3 + 1);
  for (std::size_t i = 0; i < permitted.size(); ++i) {
    CAPTURE(permitted[i].Describe());
    CHECK(rows[i]["region"] == permitted[i].region->name);
    CHECK(rows[i]["area"] == permitted[i].area->name);
    CHECK(rows[i]["force_limit_N"].get<double>() == permitted[i].force_N);
    // No contact area: the bare robot's limit is the force's, in closed form.
    CHECK(rows[i]["bare_limited_by"] == "force");
    CHECK(rows[i]["bare_max_speed_m_per_s"].get<double>() ==
          Approx(AnnexASpeed(10.0, permitted[i])).epsilon(1e-12));
    CHECK(rows[i]["criteria"].get<std::string>().find(permitted[i].Describe()) != std::string::npos);
    CHECK(rows[i]["covered_max_speed_m_per_s"].is_number());
  }
  const json& head = rows.back();
  CHECK(head["region"] == "head");
  CHECK(head["area"].is_null());
  CHECK(head["criteria"].get<std::string>().find("Park et al. 2011") != std::string::npos);
  // The head's row is speed-limit's own answer for the paper's scene and for the bare robot.
  const json plain = JsonOf({"speed-limit", "--robot-mass", "10kg", "--json"});
  CHECK(head["covered_max_speed_m_per_s"] == plain["rows"][0]["max_safe_speed_m_per_s"]);
  const json bare = JsonOf({"speed-limit", "--robot-mass", "10kg", "--covering-thickness", "0", "--json"});
  CHECK(head["bare_max_speed_m_per_s"] == bare["rows"][0]["max_safe_speed_m_per_s"]);
}

TEST_CASE("speed-limit --body-region chest: the chest's bare limit at 10 kg is 0.6261 m/s in the table",
          "[body_regions]") {
  const CliRun run = Run({"speed-limit", "--body-region", "chest", "--robot-mass", "10kg"});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(run.out.find("0.6261") != std::string::npos);
  CHECK(run.out.find("ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M, transient") != std::string::npos);
  CHECK(run.out.find("chest (sternum): 280 N, 240 N/cm²") != std::string::npos);
  // 280 N / sqrt(8 kg × 25 kN/m), independently of the table's reader.
  CHECK(280.0 / std::sqrt(8.0 * 25e3) == Approx(0.6261).margin(5e-5));
  // With a contact area the sternum's pressure limit (240 N/cm² at 1 cm² = 240 N) binds first.
  const json j = JsonOf({"speed-limit", "--body-region", "chest", "--robot-mass", "10kg", "--contact-area", "1cm2",
                         "--json"});
  CHECK(j["rows"][0]["bare_limited_by"] == "pressure");
  CHECK(j["rows"][0]["bare_max_speed_m_per_s"].get<double>() == Approx(240.0 / std::sqrt(8.0 * 25e3)).epsilon(1e-12));
  CHECK(j["scene"]["contact_area_m2"].get<double>() == 1e-4);
}

TEST_CASE("speed-limit: clamped contact is stricter than transient for every area and covering", "[body_regions]") {
  for (const std::string thickness : {"0", "10mm"}) {
    const json transient = JsonOf({"speed-limit", "--body-region", "all", "--covering-thickness", thickness,
                                   "--covering-modulus", "1MPa", "--contact-area", "10cm2", "--json"});
    const json clamped = JsonOf({"speed-limit", "--body-region", "all", "--contact", "clamped", "--covering-thickness",
                                 thickness, "--covering-modulus", "1MPa", "--contact-area", "10cm2", "--json"});
    // Clamped: every area (the skull, forehead and face too), no head row.
    CHECK(clamped["rows"].size() == BodyRegionTable::BuiltIn().area_count());
    for (const json& c : clamped["rows"]) {
      for (const json& t : transient["rows"]) {
        if (t["region"] != c["region"] || t["area"] != c["area"]) continue;
        CAPTURE(thickness, c["region"], c["area"]);
        CHECK(c["bare_max_speed_m_per_s"].get<double>() < t["bare_max_speed_m_per_s"].get<double>());
        if (thickness != "0") {
          CHECK(c["covered_max_speed_m_per_s"].get<double>() < t["covered_max_speed_m_per_s"].get<double>());
        }
      }
    }
  }
}

TEST_CASE("speed-limit --body-region: several masses give one block each, and --csv - the same rows",
          "[body_regions]") {
  const json j = JsonOf({"speed-limit", "--body-region", "chest,hands-fingers", "--robot-mass", "5kg,20kg", "--json"});
  REQUIRE(j["rows"].size() == 4);
  CHECK(j["rows"][0]["robot_mass_kg"] == 5.0);
  CHECK(j["rows"][2]["robot_mass_kg"] == 20.0);
  // A heavier robot is slower.
  CHECK(j["rows"][2]["bare_max_speed_m_per_s"].get<double>() < j["rows"][0]["bare_max_speed_m_per_s"].get<double>());
  const CliRun text = Run({"speed-limit", "--body-region", "chest,hands-fingers", "--robot-mass", "5kg,20kg"});
  REQUIRE(text.exit_code == 0);
  CHECK(text.out.find("robot mass 5 kg") != std::string::npos);
  CHECK(text.out.find("robot mass 20 kg") != std::string::npos);
  const CliRun csv = Run({"speed-limit", "--body-region", "chest,hands-fingers", "--robot-mass", "5kg,20kg", "--csv", "-"});
  REQUIRE(csv.exit_code == 0);
  const auto lines = SplitLines(csv.out);
  REQUIRE(lines.size() == 5);
  CHECK(lines[0].rfind("material,robot_mass_kg,region,area,contact,force_limit_N", 0) == 0);
}

TEST_CASE("simulate --body-region: the bare robot's peaks are Annex A's and the pressure F/A", "[body_regions]") {
  const json j = JsonOf({"simulate", "--body-region", "chest", "--covering-thickness", "0", "--speed", "0.5m/s",
                         "--robot-mass", "10kg", "--contact-area", "10cm2", "--json"});
  REQUIRE(j["regions"].size() == 1);
  const json& chest = j["regions"][0];
  const double force = 0.5 * std::sqrt(8.0 * 25e3);
  CHECK(chest["peak_force_N"].get<double>() == Approx(force).epsilon(1e-12));
  CHECK(chest["peak_pressure_Pa"].get<double>() == Approx(force / 10e-4).epsilon(1e-12));
  CHECK(chest["pressure"]["evaluated"] == true);
  CHECK(chest["force"]["ratio"].get<double>() == Approx(force / 280.0).epsilon(1e-12));
  CHECK(chest["scope"] == "ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M, transient (2× quasi-static), chest (sternum): 280 N, 240 N/cm²");
  CHECK(chest["admissible"] == true);
  CHECK(j["safe"] == true);

  const json area = JsonOf({"simulate", "--body-region", "chest", "--covering-thickness", "0", "--speed", "0.5m/s",
                            "--robot-mass", "10kg", "--contact-area", "2cm2", "--json"});
  CHECK(area["regions"][0]["peak_pressure_Pa"].get<double>() == Approx(force / 2e-4).epsilon(1e-12));
  // Past the force limit: not safe, governed by force.
  const json fast = JsonOf({"simulate", "--body-region", "chest", "--covering-thickness", "0", "--speed", "1m/s",
                            "--robot-mass", "10kg", "--contact-area", "10cm2", "--json"});
  CHECK(fast["regions"][0]["admissible"] == false);
  CHECK(fast["regions"][0]["governing"] == "force");
  CHECK(fast["safe"] == false);

  const CliRun text = Run({"simulate", "--body-region", "chest", "--covering-thickness", "0", "--speed", "0.5m/s",
                           "--contact-area", "10cm2"});
  REQUIRE(text.exit_code == 0);
  CHECK(text.out.find("Scope      ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M, transient (2× quasi-static), chest (sternum)") !=
        std::string::npos);
  // The bare robot's own verdict needs its pressure, hence its contact area.
  ExpectRefused({"simulate", "--body-region", "chest", "--covering-thickness", "0", "--speed", "0.5m/s"},
                {"--contact-area is needed for the bare robot on chest", "1cm2"});
}

TEST_CASE("simulate --body-region with the head: the head is simulate's own answer", "[body_regions]") {
  const json both = JsonOf({"simulate", "--body-region", "hands-fingers,head", "--speed", "1m/s", "--json"});
  const json head = JsonOf({"simulate", "--speed", "1m/s", "--json"});
  CHECK(both["head"] == covopt::cli::testing::WithoutProvenance(head));  // the regions' object carries it
  REQUIRE(both["regions"].size() == 1);
  CHECK(both["regions"][0]["region"] == "hands-fingers");
  // A head input is taken when the head is named, refused when only ISO regions are.
  CHECK(Run({"simulate", "--body-region", "chest,head", "--head-mass", "5kg"}).exit_code == 0);
  ExpectRefused({"simulate", "--body-region", "chest", "--head-mass", "5kg"}, {"head.mass", "--body-region head"});
  ExpectRefused({"simulate", "--body-region", "chest", "--laceration-limit", "2MPa"}, {"limits.laceration"});
}

TEST_CASE("optimize --body-region --speed: every region named is safe at the recommended thickness",
          "[body_regions]") {
  const json j = JsonOf({"optimize", "--body-region", "chest,head", "--speed", "1m/s", "--json"});
  REQUIRE(j["recommendation"].is_object());
  const json& rec = j["recommendation"];
  CHECK(rec["admissible"] == true);
  REQUIRE(rec["regions"].size() == 1);
  CHECK(rec["regions"][0]["admissible"] == true);
  CHECK(rec["head"]["criteria"].get<std::string>().find("Park et al. 2011") != std::string::npos);
  // The bare robot exceeds the chest's 280 N at 1 m/s (1 × sqrt(8 × 25000) = 447 N).
  CHECK(j["bare_robot"]["safe"] == false);
  CHECK(j["bare_robot"]["regions"][0]["force"]["value_N"].get<double>() == Approx(std::sqrt(8.0 * 25e3)).epsilon(1e-12));
  // The same recommendation, checked by simulate at that thickness and material.
  const json check = JsonOf({"simulate", "--body-region", "chest", "--speed", "1m/s", "--material",
                             rec["material"].get<std::string>(), "--covering-thickness",
                             fmt::format("{}m", rec["thickness_m"].get<double>()), "--json"});
  CHECK(check["regions"][0]["admissible"] == true);
  CHECK(check["regions"][0]["peak_force_N"].get<double>() ==
        Approx(rec["regions"][0]["peak_force_N"].get<double>()).epsilon(1e-12));
  const CliRun text = Run({"optimize", "--body-region", "chest", "--speed", "1m/s"});
  REQUIRE(text.exit_code == 0);
  CHECK(text.out.find("Recommended") != std::string::npos);
  CHECK(text.out.find("Scope") != std::string::npos);
}

TEST_CASE("the contact area is read with its unit", "[body_regions][quantity]") {
  namespace specs = covopt::quantity_specs;
  CHECK(covopt::ParseQuantity("1cm2", specs::kContactArea, "--contact-area") == 1e-4);
  CHECK(covopt::ParseQuantity("100 mm2", specs::kContactArea, "--contact-area") == 1e-4);
  CHECK(covopt::ParseQuantity("2cm²", specs::kContactArea, "--contact-area") == 2e-4);
  CHECK(covopt::ParseQuantity("0.0001", specs::kContactArea, "--contact-area") == 1e-4);
  CHECK_THROWS_WITH(covopt::ParseQuantity("5", specs::kContactArea, "--contact-area"),
                    "--contact-area 5: a bare number is in square metres (5 m2); write 5cm2 or 5m2");
  CHECK_THROWS(covopt::ParseQuantity("1cm", specs::kContactArea, "--contact-area"));
}

TEST_CASE("body-region bad input is exit 2 with one line naming the choices", "[body_regions]") {
  for (const std::string command : {"simulate", "speed-limit", "optimize"}) {
    CAPTURE(command);
    ExpectRefused({command, "--body-region", "face"}, {"A.3.2", "face", "--contact clamped"});
    ExpectRefused({command, "--body-region", "skull-forehead", "--contact", "transient"}, {"A.3.2"});
    ExpectRefused({command, "--body-region", "chset"}, {"'chset'", "did you mean 'chest'", "hands-fingers", "head"});
    ExpectRefused({command, "--body-region", "chest,hands-fingers", "--body-area", "sternum"},
                  {"--body-area", "exactly one --body-region"});
    ExpectRefused({command, "--body-region", "chest", "--body-area", "knee"}, {"knee", "sternum", "pectoral-muscle"});
    ExpectRefused({command, "--body-region", "chest", "--contact", "sideways"}, {"--contact", "transient", "clamped"});
    ExpectRefused({command, "--contact", "clamped"}, {"--contact", "--body-region"});
    ExpectRefused({command, "--body-region", "chest", "--contact-area", "5"}, {"--contact-area", "5cm2"});
    ExpectRefused({command, "--body-region", "chest", "--robot-radius", "flat"}, {"--robot-radius", "finite"});
  }
  ExpectRefused({"speed-limit", "--body-region", "head", "--contact", "clamped"}, {"head", "--head-mass fixed"});
  ExpectRefused({"speed-limit", "--body-region", "chest", "--solve-for", "mass"}, {"--solve-for mass"});
  // A bare flat robot is Annex A's: no refusal.
  CHECK(Run({"simulate", "--body-region", "chest", "--robot-radius", "flat", "--covering-thickness", "0",
             "--contact-area", "1cm2"})
            .exit_code == 0);
  // face and skull-forehead are judged clamped.
  const json face = JsonOf({"simulate", "--body-region", "face", "--contact", "clamped", "--covering-thickness", "0",
                            "--contact-area", "1cm2", "--speed", "0.1m/s", "--json"});
  CHECK(face["regions"][0]["contact"] == "clamped");
}

TEST_CASE("robot --trajectory --body-region: the speed scale is Annex A's limit over each sample's speed",
          "[body_regions][trajectory]") {
  const std::string urdf = COVOPT_ROBOT_MODELS_DIR "/franka_fr3.urdf";
  const std::string csv = COVOPT_ROBOT_MODELS_DIR "/franka_fr3_pick.csv";
  const json j = JsonOf({"robot", "--urdf", urdf, "--tip", "fr3_link8", "--trajectory", csv, "--body-region", "chest",
                         "--covering-thickness", "0", "--contact-area", "10cm2", "--json"});
  const auto chest = BodyRegionTable::BuiltIn().Limits("chest", "", ContactType::kTransient);
  double scale = std::numeric_limits<double>::infinity();
  std::size_t worst = 0;
  const json& samples = j["samples"];
  REQUIRE(samples.size() > 10);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (!samples[i]["moving"].get<bool>()) continue;
    const double mass = samples[i]["reflected_mass_kg"].get<double>();
    const double v_max = AnnexASpeed(mass, chest);
    CHECK(samples[i]["max_safe_speed_m_per_s"].get<double>() == Approx(v_max).epsilon(1e-12));
    const double s = v_max / samples[i]["speed_m_per_s"].get<double>();
    if (s < scale) scale = s, worst = i;
  }
  CHECK(j["safe_speed_scale"].get<double>() == Approx(scale).epsilon(1e-12));
  CHECK(j["worst_sample"] == worst);
  CHECK(j["status"] == (scale >= 1.0 ? "safe" : "unsafe"));
  // The head is judged by its own check when named, and its scale is the plain trajectory check's.
  const json with_head = JsonOf({"robot", "--urdf", urdf, "--tip", "fr3_link8", "--trajectory", csv, "--body-region",
                                 "chest,head", "--covering-thickness", "0", "--contact-area", "10cm2", "--json"});
  const json plain = JsonOf({"robot", "--urdf", urdf, "--tip", "fr3_link8", "--trajectory", csv,
                             "--covering-thickness", "0", "--json"});
  CHECK(with_head["head"]["safe_speed_scale"] == plain["safe_speed_scale"]);
  ExpectRefused({"robot", "--urdf", urdf, "--tip", "fr3_link8", "--trajectory", csv, "--body-region", "chest",
                 "--head-mass", "5kg"},
                {"head.mass"});
  ExpectRefused({"robot", "--urdf", urdf, "--tip", "fr3_link8", "--body-region", "chest"}, {"--body-region"});
}

TEST_CASE("sweep --body-region: one CSV row per point, each the body contact simulate reports", "[body_regions][sweep]") {
  const CliRun run = Run({"sweep", "--x", "speed=0.2..1.2:6", "--y", "covering-thickness=0,10mm", "--covering-modulus",
                          "1MPa", "--body-region", "chest", "--contact-area", "10cm2", "--csv", "-"});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  const auto lines = SplitLines(run.out);
  REQUIRE(lines.size() == 1 + 12);
  CHECK(lines[0].rfind("speed [m/s],covering-thickness [m],peak_force_N,peak_pressure_Pa", 0) == 0);
  // The bare rows (thickness 0) are Annex A's force v sqrt(mu k); a covered row is simulate's.
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::string& line = lines[i];
    const std::size_t c1 = line.find(','), c2 = line.find(',', c1 + 1), c3 = line.find(',', c2 + 1);
    const std::string speed = line.substr(0, c1), thickness = line.substr(c1 + 1, c2 - c1 - 1);
    const double force = std::stod(line.substr(c2 + 1, c3 - c2 - 1));
    CAPTURE(line);
    if (thickness == "0") {
      CHECK(force == Approx(std::stod(speed) * std::sqrt(8.0 * 25e3)).epsilon(1e-12));
    } else {
      const json j = JsonOf({"simulate", "--body-region", "chest", "--speed", speed, "--covering-thickness",
                             thickness + "m", "--covering-modulus", "1MPa", "--json"});
      CHECK(force == Approx(j["regions"][0]["peak_force_N"].get<double>()).epsilon(1e-12));
    }
  }
  // Without a contact area the bare points are not judged (each says why); the covered ones are.
  const CliRun no_area = Run({"sweep", "--x", "speed=0.2..1.2:6", "--y", "covering-thickness=0,10mm",
                              "--covering-modulus", "1MPa", "--body-region", "chest", "--csv", "-"});
  REQUIRE(no_area.exit_code == 0);
  std::size_t unjudged = 0;
  for (const std::string& line : SplitLines(no_area.out)) {
    if (line.find("none is given; this bare point is not judged") != std::string::npos) ++unjudged;
  }
  CHECK(unjudged == 6);
  ExpectRefused({"sweep", "--x", "head-mass=3kg..5kg:3", "--body-region", "chest"}, {"head-mass", "does not read"});
  ExpectRefused({"sweep", "--x", "speed=1..2:3", "--body-region", "chest,head"}, {"one ISO region"});
}

TEST_CASE("sweep --body-region --plot draws the governing ratio", "[body_regions][sweep][plot]") {
  if (!covopt::cli::FindOnPath("gnuplot")) {
    WARN("gnuplot not on PATH: chart not drawn");
    return;
  }
  covopt::cli::testing::TempDir dir;
  for (const std::string y : {"", "covering-thickness=5mm..30mm:4"}) {
    const std::string chart = (dir / (y.empty() ? "line.svg" : "map.svg")).string();
    std::vector<std::string> args{"sweep", "--x", "covering-modulus=0.5MPa..50MPa:log:5", "--body-region", "chest",
                                  "--speed", "1m/s", "--plot", chart};
    if (!y.empty()) args.insert(args.end(), {"--y", y});
    const CliRun run = Run(args);
    INFO(run.err);
    REQUIRE(run.exit_code == 0);
    const std::string svg = covopt::cli::testing::ReadFile(chart);
    CHECK(svg.find("<svg") != std::string::npos);
    CHECK(svg.find("chest (sternum): 280 N") != std::string::npos);
  }
}

// The body-region time path's self-check (docs/numerics.md, "The body-region path's
// self-check"): C1 of docs/model.md §13.9 at 0.403 m/s. SDIRK 4(3) at rtol 1e-3 gave 179 N for
// the exact 117 N (a stale Jacobian), silently; ERK 6(5) at rtol 1e-8 misses its tolerance and
// says so in a warning naming the region.
TEST_CASE("simulate --body-region: the time path's energy self-check and the implicit methods at rtol 1e-3",
          "[body_regions][numerics]") {
  const std::vector<std::string> c1 = {"simulate", "--body-region", "chest", "--speed", "0.403m/s", "--robot-mass", "10kg",
                                       "--robot-radius", "40mm", "--covering-thickness", "10mm", "--covering-modulus",
                                       "0.5MPa", "--covering-poisson", "0.3"};
  const auto run_with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = c1;
    args.insert(args.end(), extra.begin(), extra.end());
    const CliRun run = Run(args);
    INFO(fmt::format("{}", fmt::join(args, " ")) << " -> " << run.err);
    REQUIRE(run.exit_code == 0);
    return run.out;
  };
  /// The "Time path" line's relative difference to the exact path and its energy residual.
  const auto time_path_numbers = [](const std::string& out) {
    const std::size_t line = out.find("  Time path  force ");
    REQUIRE(line != std::string::npos);
    const std::string text = out.substr(line, out.find('\n', line) - line);
    INFO(text);
    const std::string difference = "relative difference to the exact path ", residual = "energy residual ";
    REQUIRE(text.find(difference) != std::string::npos);
    REQUIRE(text.find(residual) != std::string::npos);
    return std::pair{std::stod(text.substr(text.find(difference) + difference.size())),
                     std::stod(text.substr(text.find(residual) + residual.size()))};
  };
  for (const char* method : {"arkode-sdirk43", "arkode-esdirk54", "cvode-bdf"}) {
    const std::string out = run_with({"--method", method, "--rtol", "1e-3"});
    INFO(out);
    const auto [difference, residual] = time_path_numbers(out);
    CHECK(difference <= 0.1);  // 100 rtol
    CHECK(residual <= 0.1);
    CHECK(out.find("did not keep its tolerance") == std::string::npos);
  }
  const std::string loose = run_with({"--method", "arkode-erk65", "--rtol", "1e-8"});
  INFO(loose);
  CHECK(time_path_numbers(loose).second > 1e-6);
  CHECK(loose.find("Warning: chest (sternum): the time path did not keep its tolerance: energy residual ") !=
        std::string::npos);
  const json j = JsonOf([&] {
    std::vector<std::string> args = c1;
    for (const char* extra : {"--method", "arkode-erk65", "--rtol", "1e-8", "--json"}) args.emplace_back(extra);
    return args;
  }());
  bool warned = false;
  for (const json& w : j["warnings"]) {
    warned = warned || w.get<std::string>().starts_with("chest (sternum): the time path did not keep its tolerance");
  }
  CHECK(warned);
}
