// `covopt audit` run in-process: that --json is the library's audit of the same input to the
// bit (audit::Audit, report::AuditJson) and has the documented shape; that the scale is the
// minimum over links and regions; that --csv and the streamed --samples-csv agree with it; that
// a link covering reaches its link only; that the same path at half the speed raises no
// ratio; that the per-link design is safe when audited again; --plot; and that bad input is
// exit 2 with one line on stderr naming the flag and nothing on stdout.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "audit_test_support.hpp"
#include "cli_test_support.hpp"
#include "covopt/materials/body_regions.hpp"
#include "covopt/audit/audit.hpp"
#include "covopt/report/audit_json.hpp"
#include "covopt/robot.hpp"
#include "plot.hpp"

namespace {

using covopt::cli::testing::CliRun;
using covopt::cli::testing::ReadFile;
using covopt::cli::testing::Run;
using covopt::cli::testing::SplitLines;
using covopt::cli::testing::TempDir;
using nlohmann::json;

const std::string& kFr3 = covopt::cli::testing::kFr3Urdf;
const std::string& kPick = covopt::cli::testing::kFr3Pick;

/// The FR3 pick move with a 10 mm covering of 0.5 MPa on every link, every region and the head.
std::vector<std::string> Fr3(const std::string& trajectory, const std::vector<std::string>& more = {}) {
  return covopt::cli::testing::Fr3Command("audit", trajectory, more);
}

json JsonOf(const CliRun& run) { return covopt::cli::testing::JsonOfRun(run); }

void RequireBadInput(const CliRun& run, const std::string& names) {
  covopt::cli::testing::RequireRefused(run, names, "audit");
}

/// The pick move with time stretched by `stretch` and velocities divided by it.
std::string Stretched(const TempDir& dir, double stretch) {
  std::ifstream in(kPick);
  std::ostringstream out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 't') {
      out << line << '\n';
      continue;
    }
    std::vector<double> v;
    std::stringstream cells(line);
    std::string cell;
    while (std::getline(cells, cell, ',')) v.push_back(std::stod(cell));
    for (std::size_t i = 0; i < v.size(); ++i) {
      const double x = i == 0 ? v[i] * stretch : i >= 8 ? v[i] / stretch : v[i];
      out << (i ? "," : "") << fmt::format("{:.17g}", x);
    }
    out << '\n';
  }
  return dir.Write(fmt::format("pick_{}.csv", stretch), out.str()).string();
}

}  // namespace

TEST_CASE("audit --json is the library's audit of the same input, to the bit, in the documented shape", "[audit]") {
  const json j = JsonOf(Run(Fr3(kPick, {"--json"})));

  const auto chain = covopt::robot::KinematicChain::FromUrdfFile(kFr3, {"", "fr3_link8"});
  covopt::robot::SurfaceOptions surface_options;
  covopt::audit::AuditSetup setup(chain, covopt::robot::SurfaceFromUrdfFile(kFr3, chain, surface_options));
  setup.covering.covering = covopt::CoveringSpec{0.5e6, 0.45, 0.010};
  setup.regions = covopt::materials::BodyRegionTable::BuiltIn().AllLimits(covopt::ContactType::kTransient);
  setup.head = covopt::Scene{};
  setup.head->covering = setup.covering.covering;
  setup.contact_area_m2 = 1e-4;
  setup.flat_face_radius_m = 0.020;
  // A covering given by its modulus has no known strength: judged without the crush check.
  setup.rule.unknown_strength_allowed = true;
  const auto trajectory = covopt::robot::ReadJointTrajectory(kPick, chain.joint_count());
  const covopt::audit::AuditResult result = covopt::audit::Audit(setup, trajectory);
  const json library = json::parse(covopt::report::AuditJson(setup, result));
  for (const auto& [key, value] : library.items()) {
    INFO(key);
    if (key != "warnings") CHECK(j.at(key) == value);
  }
  // The CLI's warnings about its input (the covering's unknown strength) come first.
  REQUIRE(j["warnings"].size() == library["warnings"].size() + 1);
  CHECK(j["warnings"][0].get<std::string>().find("crushing is not checked") != std::string::npos);
  CHECK(json(std::vector<json>(j["warnings"].begin() + 1, j["warnings"].end())) == library["warnings"]);
  CHECK(j.size() == library.size() + 2);  // and where its inputs came from and the run's provenance, last
  CHECK(j.contains("input_sources"));
  CHECK(j.contains("provenance"));

  for (const char* key : {"status", "message", "safe_speed_scale", "limiting", "criterion", "safety_factor",
                          "contact_area_m2", "reaction_delay_s", "braking_m_per_s2", "robot", "surface",
                          "sample_count", "regions", "scope", "coverings", "cells", "ratio_over_time",
                          "link_designs", "warnings"}) {
    CHECK(j.contains(key));
  }
  const std::size_t links = j["surface"]["links"].size();
  const std::size_t regions = j["regions"].size();
  CHECK(regions == setup.regions.size() + 1);
  CHECK(j["regions"].back() == "head (Park et al. 2011)");
  REQUIRE(j["cells"].size() == links * regions);
  CHECK(j["sample_count"] == trajectory.size());
  CHECK(j["ratio_over_time"]["ratio"].size() == trajectory.size());
  CHECK(j["coverings"].size() == links);
  // The scale is the minimum over links and regions of the cells' scales, set by `limiting`.
  double least = std::numeric_limits<double>::infinity();
  const json* least_cell = nullptr;
  for (const json& cell : j["cells"]) {
    CHECK(cell.size() == covopt::report::AuditCellColumns().size() - 6 + 2);  // the points as vectors
    if (cell["speed_scale"].is_number() && cell["speed_scale"].get<double>() < least) {
      least = cell["speed_scale"].get<double>();
      least_cell = &cell;
    }
    if (cell["sample"].is_null()) {
      CHECK(cell["governing_ratio"] == 0.0);  // a link that never moves never limits
    }
  }
  REQUIRE(least_cell != nullptr);
  CHECK(j["safe_speed_scale"].get<double>() == least);
  CHECK(j["limiting"]["link"] == (*least_cell)["link"]);
  CHECK(j["limiting"]["region"] == (*least_cell)["region"]);
  CHECK(j["status"] == (least >= 1.0 ? "safe" : "unsafe"));
  // The base link never moves.
  CHECK(j["cells"][0]["link"] == "fr3_link0");
  CHECK(j["cells"][0]["sample"].is_null());
}

TEST_CASE("audit: --csv and the streamed --samples-csv agree with --json and the table names the limit", "[audit]") {
  const TempDir dir;
  const auto cells_csv = dir / "cells.csv";
  const auto samples_csv = dir / "samples.csv";
  const json j = JsonOf(Run(Fr3(kPick, {"--json", "--csv", cells_csv.string()})));
  const std::vector<std::string> rows = SplitLines(ReadFile(cells_csv));
  REQUIRE(rows.size() == j["cells"].size() + 1);
  CHECK(rows[0].rfind("link,region,governing_ratio,binding,sample,time_s,point,point_in_link_x_m", 0) == 0);

  const CliRun streamed = Run(Fr3(kPick, {"--samples-csv", samples_csv.string()}));
  REQUIRE(streamed.exit_code == 0);
  const std::vector<std::string> lines = SplitLines(ReadFile(samples_csv));
  REQUIRE(lines.size() == j["sample_count"].get<std::size_t>() + 1);
  // Per link the largest streamed ratio is the largest governing ratio over its regions.
  const std::size_t links = j["surface"]["links"].size();
  std::vector<double> streamed_max(links, 0.0);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    std::vector<std::string> cells;
    std::stringstream s(lines[i]);
    std::string cell;
    while (std::getline(s, cell, ',')) cells.push_back(cell);
    REQUIRE(cells.size() >= 2 + 2 * links - 1);
    for (std::size_t l = 0; l < links; ++l) streamed_max[l] = std::max(streamed_max[l], std::stod(cells[2 + 2 * l]));
  }
  const std::size_t regions = j["regions"].size();
  for (std::size_t l = 0; l < links; ++l) {
    double cell_max = 0.0;
    for (std::size_t r = 0; r < regions; ++r) {
      cell_max = std::max(cell_max, j["cells"][l * regions + r]["governing_ratio"].get<double>());
    }
    CHECK(streamed_max[l] == Approx(cell_max).epsilon(1e-12));
  }

  const CliRun table = Run(Fr3(kPick));
  REQUIRE(table.exit_code == 0);
  CHECK(table.out.find("Verdict    " + j["message"].get<std::string>()) != std::string::npos);
  CHECK(table.out.find(j["limiting"]["link"].get<std::string>()) != std::string::npos);
}

TEST_CASE("audit: the same path at half the speed raises no ratio", "[audit]") {
  const TempDir dir;
  const json full = JsonOf(Run(Fr3(kPick, {"--json"})));
  const json half = JsonOf(Run(Fr3(Stretched(dir, 2.0), {"--json"})));
  REQUIRE(full["cells"].size() == half["cells"].size());
  for (std::size_t i = 0; i < full["cells"].size(); ++i) {
    CHECK(half["cells"][i]["governing_ratio"].get<double>() <= full["cells"][i]["governing_ratio"].get<double>());
  }
  CHECK(half["safe_speed_scale"].get<double>() >= full["safe_speed_scale"].get<double>());
}

TEST_CASE("audit: a braking robot is judged with its brake for the regions and the head, and raises no ratio", "[audit]") {
  const std::vector<std::string> regions = {"--body-region", "chest,head", "--json"};
  std::vector<std::string> braking = regions;
  braking.insert(braking.end(), {"--reaction-delay", "5ms", "--braking", "100"});
  const json free = JsonOf(Run(Fr3(kPick, regions)));
  const json braked = JsonOf(Run(Fr3(kPick, braking)));
  CHECK(braked["braking_m_per_s2"].get<double>() == 100.0);
  CHECK(braked["reaction_delay_s"].get<double>() == Approx(0.005));
  REQUIRE(free["cells"].size() == braked["cells"].size());
  bool some_lower = false;
  for (std::size_t i = 0; i < free["cells"].size(); ++i) {
    const double unbraked_ratio = free["cells"][i]["governing_ratio"].get<double>();
    const double braked_ratio = braked["cells"][i]["governing_ratio"].get<double>();
    CHECK(braked_ratio <= unbraked_ratio * (1.0 + 1e-9));
    some_lower = some_lower || braked_ratio < 0.99 * unbraked_ratio;
  }
  CHECK(some_lower);
  CHECK(braked["safe_speed_scale"].get<double>() > free["safe_speed_scale"].get<double>());
}

TEST_CASE("audit --link-coverings: a link's own covering changes its cells only", "[audit]") {
  const TempDir dir;
  const json all = JsonOf(Run(Fr3(kPick, {"--json"})));
  const std::string link = all["limiting"]["link"];
  const auto file = dir.Write("links.toml", fmt::format("[[link]]\nname = \"{}\"\nmodulus = \"0.2MPa\"\n"
                                                        "poisson = 0.45\nthickness = \"30mm\"\n",
                                                        link));
  const json own = JsonOf(Run(Fr3(kPick, {"--json", "--link-coverings", file.string()})));
  const std::size_t regions = all["regions"].size();
  bool changed = false;
  for (std::size_t i = 0; i < all["cells"].size(); ++i) {
    if (all["cells"][i]["link"] == link) {
      changed = changed || own["cells"][i]["governing_ratio"] != all["cells"][i]["governing_ratio"];
    } else {
      CHECK(own["cells"][i] == all["cells"][i]);
    }
  }
  CHECK(changed);
  (void)regions;
  for (const json& covering : own["coverings"]) {
    CHECK(covering["from"] == (covering["link"] == link ? "link file" : "all links"));
  }
}

TEST_CASE("audit --design: each link's design is safe at full speed when audited again", "[audit]") {
  const TempDir dir;
  const json j = JsonOf(Run(Fr3(kPick, {"--json", "--design", "--family", "foam", "--allow-unknown-strength"})));
  REQUIRE(!j["link_designs"].empty());
  std::string file;
  for (const json& d : j["link_designs"]) {
    if (d["material"].is_null()) continue;
    file += fmt::format("[[link]]\nname = \"{}\"\nmaterial = \"{}\"\nthickness = {}\n\n", d["link"].get<std::string>(),
                        d["material"].get<std::string>(), d["thickness_m"].get<double>());
  }
  REQUIRE(!file.empty());
  const auto path = dir.Write("designed.toml", file);
  const json again = JsonOf(Run(Fr3(kPick, {"--json", "--link-coverings", path.string()})));
  for (const json& d : j["link_designs"]) {
    if (d["material"].is_null()) continue;
    for (const json& cell : again["cells"]) {
      if (cell["link"] == d["link"]) CHECK(cell["governing_ratio"].get<double>() <= 1.0);
    }
  }
}

TEST_CASE("audit --plot draws the heat map", "[audit]") {
  const TempDir dir;
  const auto png = dir / "map.png";
  const CliRun run = Run(Fr3(kPick, {"--plot", png.string()}));
  INFO(run.err);
  if (covopt::cli::FindOnPath("gnuplot")) {
    REQUIRE(run.exit_code == 0);
    CHECK(ReadFile(png).substr(0, 8) == std::string("\x89PNG\r\n\x1a\n", 8));
  } else {
    CHECK(run.exit_code == 1);  // gnuplot missing: said so
    CHECK(run.err.find("gnuplot") != std::string::npos);
  }
}

TEST_CASE("audit: bad input is exit 2 with one line naming the flag", "[audit]") {
  const TempDir dir;
  RequireBadInput(Run({"audit", "--urdf", kFr3, "--tip", "fr3_link8"}), "--trajectory");
  RequireBadInput(Run(Fr3(kPick, {"--joints", "0,0,0,0,0,0,0"})), "--joints");
  RequireBadInput(Run(Fr3(kPick, {"--robot-mass", "10kg"})), "--robot-mass");
  RequireBadInput(Run(Fr3(kPick, {"--speed", "1"})), "--speed");
  RequireBadInput(Run(Fr3(kPick, {"--contact", "clamped", "--body-region", "chest"})), "--contact");
  RequireBadInput(Run(Fr3(kPick, {"--family", "foam"})), "--family");
  RequireBadInput(Run(Fr3(kPick, {"--plot", (dir / "map.jpg").string()})), "--plot");
  RequireBadInput(Run(Fr3(kPick, {"--json", "--csv", "-"})), "--json");
  RequireBadInput(Run(Fr3(kPick, {"--surface-spacing", "0.1mm"})), "spacing");
  // A payload with a non-physical inertia (its largest moment above the sum of the others).
  RequireBadInput(Run(Fr3(kPick, {"--payload-mass", "1", "--payload-inertia", "1,1,5,0,0,0"})), "payload");
  // The coverings file: a link not on the surface, an unknown key, a material not in the catalog.
  RequireBadInput(Run(Fr3(kPick, {"--link-coverings",
                                  dir.Write("a.toml", "[[link]]\nname = \"fr3_hand\"\nthickness = 0\n").string()})),
                  "fr3_hand");
  RequireBadInput(Run(Fr3(kPick, {"--link-coverings",
                                  dir.Write("b.toml", "[[link]]\nname = \"fr3_link3\"\nthikness = 0\n").string()})),
                  "thickness");
  RequireBadInput(Run(Fr3(kPick, {"--link-coverings", dir.Write("c.toml", "[[link]]\nname = \"fr3_link3\"\n"
                                                                          "material = \"no such foam\"\n"
                                                                          "thickness = \"5mm\"\n")
                                                          .string()})),
                  "no such foam");
  // A surface file naming a link that is not on the chain.
  RequireBadInput(Run(Fr3(kPick, {"--surface-file", dir.Write("s.toml", "[[link]]\nname = \"fr3_hand\"\n"
                                                                       "points = [ { at_m = [0, 0, 0], radius_m = 0.02 } ]\n")
                                                             .string()})),
                  "fr3_hand");
  // A mesh without a surface file.
  const std::string mesh_urdf = R"(<robot name="m">
  <link name="base"/>
  <link name="arm"><inertial><mass value="2"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><mesh filename="arm.stl"/></geometry></collision></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="10" velocity="2"/></joint>
</robot>)";
  const auto urdf = dir.Write("mesh.urdf", mesh_urdf);
  const auto csv = dir.Write("one.csv", "time_s,q,qd\n0,0,0.5\n0.1,0.05,0.5\n");
  RequireBadInput(Run({"audit", "--urdf", urdf.string(), "--tip", "arm", "--trajectory", csv.string(),
                       "--covering-thickness", "0", "--contact-area", "1cm2"}),
                  "mesh");
}
