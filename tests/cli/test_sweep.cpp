// `covopt sweep` end to end, in-process: the CSV has one row per point with the swept
// quantities and the numeric keys of `simulate --json` (checked against simulate's own JSON,
// key by key and value by value at the same scene); physical trends hold along an axis;
// the results do not depend on the number of threads; invalid scenes are reported as such,
// never as NaN; charts are drawn; bad axis specs are exit 2 naming the flag and the value.
// The CSV streams (SweepCsvWriter): the same text to a file as to stdout, handed to its
// sink in bounded pieces, and an unwritable file costs no computation and leaves no file.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/core/sweep.hpp>

#include "cli_test_support.hpp"
#include "plot.hpp"
#include "sweep.hpp"
#include "covopt/report/sweep_csv.hpp"

using Catch::Matchers::Contains;
using covopt::cli::testing::ReadFile;
using covopt::cli::testing::Run;
using covopt::cli::testing::TempDir;
using nlohmann::json;

namespace {

/// One CSV record split into fields; "..." fields may hold commas and doubled quotes.
std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

struct Csv {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  std::size_t Column(const std::string& name) const {
    const auto it = std::find(header.begin(), header.end(), name);
    REQUIRE(it != header.end());
    return static_cast<std::size_t>(it - header.begin());
  }
  double Number(std::size_t row, const std::string& name) const {
    return std::stod(rows.at(row).at(Column(name)));
  }
};

Csv ParseCsv(const std::string& text) {
  Csv csv;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    const std::string line = text.substr(start, end - start);
    start = end == std::string::npos ? text.size() : end + 1;
    if (csv.header.empty()) {
      csv.header = SplitCsvLine(line);
    } else {
      csv.rows.push_back(SplitCsvLine(line));
    }
  }
  return csv;
}

/// `covopt sweep ARGS --csv -`, checked to succeed, parsed.
Csv SweepCsv(std::vector<std::string> args) {
  args.insert(args.begin(), "sweep");
  args.insert(args.end(), {"--csv", "-"});
  const auto run = Run(args);
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  return ParseCsv(run.out);
}

}  // namespace

TEST_CASE("sweep CSV has the swept quantities, status, the result columns and one row per point",
          "[sweep]") {
  const Csv csv = SweepCsv({"--x", "speed=1m/s..3m/s:5", "--y", "covering-thickness=5mm,10mm,20mm"});
  std::vector<std::string> expected = {"speed", "covering-thickness", "status"};
  for (const auto column : covopt::report::SweepResultColumns()) expected.emplace_back(column);
  expected.insert(expected.end(), {"warnings", "error"});
  CHECK(csv.header == expected);
  REQUIRE(csv.rows.size() == 15);
  for (const auto& row : csv.rows) CHECK(row.size() == expected.size());
  // x varies slowest; values in SI.
  CHECK(csv.Number(0, "speed") == 1.0);
  CHECK(csv.Number(14, "speed") == 3.0);
  CHECK(csv.Number(0, "covering-thickness") == Approx(0.005));
  CHECK(csv.Number(1, "covering-thickness") == Approx(0.010));
  CHECK(csv.Number(3, "speed") == 1.5);
  CHECK(csv.Number(3, "covering-thickness") == Approx(0.005));
}

TEST_CASE("sweep result columns are the numeric keys of simulate --json plus the ratios",
          "[sweep]") {
  const auto run = Run({"simulate", "--json"});
  REQUIRE(run.exit_code == 0);
  const json j = json::parse(run.out);
  std::set<std::string> numeric_keys;
  for (const auto& [key, value] : j.items()) {
    if (value.is_number() || value.is_boolean()) numeric_keys.insert(key);
  }
  std::set<std::string> columns;
  for (const auto column : covopt::report::SweepResultColumns()) columns.emplace(column);
  std::set<std::string> expected = numeric_keys;
  expected.insert({"laceration_ratio", "contusion_ratio", "worst_ratio"});
  CHECK(columns == expected);
}

TEST_CASE("a sweep point agrees exactly with simulate --json at the same scene", "[sweep]") {
  // speed = 1 + (3 - 1) * 2/4 = 2 m/s exactly at the middle point.
  const Csv csv = SweepCsv({"--x", "speed=1m/s..3m/s:5", "--robot-mass", "5kg",
                            "--covering-modulus", "12MPa"});
  REQUIRE(csv.Number(2, "speed") == 2.0);
  const auto run = Run({"simulate", "--json", "--speed", "2m/s", "--robot-mass", "5kg",
                        "--covering-modulus", "12MPa"});
  REQUIRE(run.exit_code == 0);
  const json j = json::parse(run.out);
  for (const auto column : covopt::report::SweepResultColumns()) {
    const std::string key(column);
    INFO(key);
    const double value = csv.Number(2, key);
    if (key == "laceration_ratio") {
      CHECK(value == j["laceration"]["ratio"].get<double>());
    } else if (key == "contusion_ratio") {
      CHECK(value == j["contusion"]["ratio"].get<double>());
    } else if (key == "worst_ratio") {
      CHECK(value == std::max(j["laceration"]["ratio"].get<double>(),
                              j["contusion"]["ratio"].get<double>()));
    } else if (key == "safe") {
      // The sweep maps the skin ratios: its `safe` is the injury verdict, simulate's
      // verdict.injury_safe (simulate's own `safe` also needs the covering's design rules).
      CHECK(value == (j["verdict"]["injury_safe"].get<bool>() ? 1.0 : 0.0));
    } else if (j[key].is_boolean()) {
      CHECK(value == (j[key].get<bool>() ? 1.0 : 0.0));
    } else {
      CHECK(value == j[key].get<double>());
    }
  }
  CHECK(csv.rows[2][csv.Column("status")] == "ok");
}

TEST_CASE("along speed, peaks and ratios rise and the contact gets shorter", "[sweep]") {
  // A stiffening force law (exponents > 1, stiffer phases later): more energy means a deeper
  // penetration, so every peak grows with speed, and a hardening spring rebounds sooner.
  const Csv csv = SweepCsv({"--x", "speed=0.1m/s..5m/s:40"});
  for (std::size_t i = 1; i < csv.rows.size(); ++i) {
    INFO("row " << i);
    for (const char* key : {"max_penetration_m", "peak_force_N", "max_compressive_stress_Pa",
                            "max_energy_density_J_per_m2", "laceration_ratio", "contusion_ratio"}) {
      CHECK(csv.Number(i, key) > csv.Number(i - 1, key));
    }
    CHECK(csv.Number(i, "contact_duration_s") < csv.Number(i - 1, "contact_duration_s"));
    // No dissipation: the rebound speed is the impact speed.
    CHECK(csv.Number(i, "rebound_speed_m_per_s") == csv.Number(i, "speed"));
  }
}

TEST_CASE("along the robot mass, the peak force rises (the effective mass grows)", "[sweep]") {
  const Csv csv = SweepCsv({"--x", "robot-mass=0.5kg,1kg,2kg,5kg,10kg,50kg,fixed"});
  REQUIRE(csv.rows.size() == 7);
  CHECK(csv.rows[6][0] == "fixed");
  for (std::size_t i = 1; i < csv.rows.size(); ++i) {
    CHECK(csv.Number(i, "peak_force_N") > csv.Number(i - 1, "peak_force_N"));
  }
}

TEST_CASE("sweep results are identical whatever the number of threads", "[sweep]") {
  const std::vector<std::string> axes = {"--x", "covering-modulus=1MPa..300MPa:log:23", "--y",
                                         "covering-thickness=0..40mm:29"};
  auto one = axes, two = axes, three = axes;
  one.insert(one.end(), {"--threads", "1"});
  two.insert(two.end(), {"--threads", "2"});
  three.insert(three.end(), {"--threads", "3"});
  const Csv a = SweepCsv(one);
  const Csv b = SweepCsv(two);
  const Csv c = SweepCsv(three);
  CHECK(a.rows.size() == 23u * 29u);
  CHECK(a.rows == b.rows);
  CHECK(a.rows == c.rows);
}

TEST_CASE("invalid scenes in a sweep are reported by name, never as NaN", "[sweep]") {
  const auto run = Run({"sweep", "--x", "head-radius=0..100mm:11", "--csv", "-"});
  REQUIRE(run.exit_code == 0);
  const Csv csv = ParseCsv(run.out);
  REQUIRE(csv.rows.size() == 11);
  CHECK(csv.rows[0][csv.Column("status")] == "invalid");
  CHECK_THAT(csv.rows[0][csv.Column("error")], Contains("head.radius"));
  CHECK(csv.rows[0][csv.Column("peak_force_N")].empty());
  CHECK(csv.rows[5][csv.Column("status")] == "ok");
  std::string lower = run.out;
  std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
  CHECK(lower.find("nan") == std::string::npos);
  CHECK(lower.find("inf") == std::string::npos);

  const auto summary = Run({"sweep", "--x", "head-radius=0..100mm:11"});
  REQUIRE(summary.exit_code == 0);
  CHECK_THAT(summary.out, Contains("1 invalid"));
  CHECK_THAT(summary.out, Contains("head.radius"));
}

TEST_CASE("sweep writes the CSV file and draws a map or line families", "[sweep][plot]") {
  TempDir dir;
  const auto csv_path = dir / "grid.csv";
  const auto map_path = dir / "map.png";
  auto run = Run({"sweep", "--x", "covering-modulus=1MPa..100MPa:log:12", "--y",
                  "covering-thickness=5mm..40mm:10", "--csv", csv_path.string(), "--plot",
                  map_path.string()});
  if (!covopt::cli::FindOnPath("gnuplot")) {
    WARN("gnuplot is not on PATH; skipping the plot checks");
    CHECK(run.exit_code == 1);
    return;
  }
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  CHECK(ParseCsv(ReadFile(csv_path)).rows.size() == 120);
  CHECK(ReadFile(map_path).substr(1, 3) == "PNG");
  CHECK_THAT(run.out, Contains("Wrote"));

  const auto lines_path = dir / "lines.svg";
  run = Run({"sweep", "--x", "speed=0.5m/s..3m/s:20", "--y", "robot-mass=2kg,10kg",
             "--plot", lines_path.string()});
  REQUIRE(run.exit_code == 0);
  const std::string svg = ReadFile(lines_path);
  CHECK_THAT(svg, Contains("<svg"));
  CHECK_THAT(svg, Contains("robot-mass 2 kg"));

  const auto stress_path = dir / "stress.svg";
  run = Run({"sweep", "--x", "speed=0.5m/s..3m/s:20", "--plot", stress_path.string(),
             "--plot-quantity", "max_compressive_stress_Pa"});
  REQUIRE(run.exit_code == 0);
  CHECK_THAT(ReadFile(stress_path), Contains("max_compressive_stress_Pa [MPa]"));
}

TEST_CASE("bad sweep specs are exit 2 naming the flag, the value and what is allowed",
          "[sweep]") {
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"--x", "foo=1..2"}, "--x: unknown quantity 'foo'; the quantities are robot-mass, speed"},
      {{"--x", "speed"}, "--x: expected NAME=LO..HI"},
      {{"--x", "speed=1m/s..2kg"}, "not a speed"},
      {{"--x", "speed=2m/s..1m/s"}, "--x: the lower end is above the upper end"},
      {{"--x", "speed=1m/s..1m/s"}, "--x: the range's low end must be below its high end"},
      {{"--x", "speed=1m/s..2m/s:1"}, "count after ':' must be in 2..100000"},
      {{"--x", "speed=1m/s..2m/s:abc"}, "expected ':lin', ':log' or a count ':N', not ':abc'"},
      {{"--x", "covering-modulus=0..1GPa:log"}, "a :log range needs a low end above 0"},
      {{"--x", "covering-modulus=1..2MPa"}, "--x: give the unit on both ends"},
      {{"--x", "robot-mass=1kg..fixed"}, "finite ends"},
      {{"--x", "speed=1m/s,,2m/s"}, "empty value"},
      {{"--x", "speed=1m/s..2m/s", "--speed", "3m/s"}, "--speed '3m/s' sets robot.speed, which --x sweeps"},
      {{"--x", "speed=1m/s..2m/s", "--y", "speed=1m/s..3m/s"}, "--y: speed is already swept by --x"},
      {{"--x", "covering-modulus=1MPa..2MPa", "--material", "polystyrene foam 27.6"},
       "--material 'polystyrene foam 27.6' sets covering.modulus"},
      {{"--x", "speed=1m/s..2m/s", "--threads", "-1"}, "--threads must be in 0..4096, 0 = all cores (got -1)"},
      {{"--x", "speed=1m/s..2m/s", "--plot", "chart.pdf"}, "--plot: cannot tell the format"},
      {{"--x", "speed=1m/s..2m/s:1000", "--y", "covering-thickness=0..1mm:1001"}, "at most 1000000"},
      {{"--x", "speed=1m/s..2m/s", "--plot", "a.png", "--plot-quantity", "force"},
       "--plot-quantity: no result column 'force'; the columns are max_penetration_m"},
      {{"--x", "speed=1m/s..2m/s", "--plot-quantity", "peak_force_N"}, "only with --plot"},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"sweep"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto run = Run(args);
    INFO(run.err);
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK_THAT(run.err, Contains(c.message));
  }
  // The value is quoted back.
  const auto run = Run({"sweep", "--x", "speed=1m/s..2m/s:abc"});
  CHECK_THAT(run.err, Contains("(got 'speed=1m/s..2m/s:abc')"));
}

TEST_CASE("a sweep axis may mix ranges and listed values", "[sweep]") {
  using covopt::cli::ParseSweepAxis;
  // The example: ten log-spaced radii, then a flat robot.
  const auto radius = ParseSweepAxis("robot-radius=2mm..500mm:log:10,flat", "--x");
  REQUIRE(radius.values.size() == 11);
  CHECK(radius.values.front() == Approx(0.002));
  CHECK(radius.values[9] == Approx(0.5));
  CHECK(std::isinf(radius.values.back()));
  for (std::size_t i = 1; i < 9; ++i) {  // equal ratios: log spacing
    CHECK(radius.values[i + 1] / radius.values[i] == Approx(radius.values[1] / radius.values[0]));
  }
  CHECK(radius.log);
  REQUIRE(radius.parts.size() == 2);
  CHECK(radius.parts[0].range);
  CHECK(radius.parts[0].count == 10);
  CHECK_FALSE(radius.parts[1].range);

  // Values and ranges in any order, each range expanded in place.
  const auto speed = ParseSweepAxis("speed=0.5m/s, 1m/s..2m/s:3 ,3m/s", "--x");
  CHECK(speed.values == std::vector<double>{0.5, 1.0, 1.5, 2.0, 3.0});
  CHECK_FALSE(speed.log);

  // A log axis only when every finite value can sit on one.
  CHECK_FALSE(ParseSweepAxis("covering-thickness=0,1mm..50mm:log:5", "--y").log);
  CHECK(ParseSweepAxis("covering-thickness=1mm..50mm:log:5,0.5mm", "--y").log);
  // The old forms are unchanged.
  CHECK(ParseSweepAxis("speed=1m/s..3m/s:5", "--x").values.size() == 5);
  CHECK(ParseSweepAxis("speed=1m/s..3m/s", "--x").values.size() == 50);
  CHECK(ParseSweepAxis("robot-mass=1kg,fixed", "--x").values.size() == 2);

  // End to end: one CSV row per value, in the order typed; the summary describes the items.
  const Csv csv = SweepCsv({"--x", "robot-radius=2mm..500mm:log:10,flat"});
  REQUIRE(csv.rows.size() == 11);
  CHECK(csv.rows.back()[0] == "flat");
  CHECK(csv.Number(0, "robot-radius") == Approx(0.002));
  const auto summary = Run({"sweep", "--x", "robot-radius=2mm..500mm:log:10,flat"});
  REQUIRE(summary.exit_code == 0);
  CHECK_THAT(summary.out, Contains("robot-radius: 11 values: 2 mm .. 500 mm (10, log), flat"));

  // Mistakes in one item are named like those of a whole spec.
  for (const auto& [spec, message] : std::vector<std::pair<std::string, std::string>>{
           {"robot-radius=2mm..500mm:log:10,,flat", "empty value in the list"},
           {"speed=1m/s..2m/s:1,3m/s", "count after ':' must be in 2..100000"},
           {"speed=1m/s..2m/s:lin:log,3m/s", "give the spacing (lin or log) once per range"},
           {"speed=3m/s,2m/s..1m/s", "lower end is above the upper end"},
           {"robot-radius=0..5mm:log,flat", "a :log range needs a low end above 0"},
           {"speed=1m/s,2m/s:5", "--x"},
       }) {
    const auto run = Run({"sweep", "--x", spec});
    INFO(spec << ": " << run.err);
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK_THAT(run.err, Contains(message) && Contains("'" + spec + "'"));
  }
}

TEST_CASE("the sweep CSV's fully_compressed column is the robot reaching bone (δ_max > t2)",
          "[sweep]") {
  // With the cumulative thresholds the robot reaches bone past t2 = 0.8 b_s + 0.8 b_c.
  const Csv csv = SweepCsv({"--x", "covering-modulus=0.3MPa..300MPa:log:9", "--y",
                            "covering-thickness=2mm..40mm:9"});
  std::size_t compressed = 0, not_compressed = 0;
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    const double t2 = 0.8 * 0.003 + 0.8 * csv.Number(i, "covering-thickness");
    const bool beyond = csv.Number(i, "max_penetration_m") > t2;
    CHECK(csv.Number(i, "fully_compressed") == (beyond ? 1.0 : 0.0));
    (beyond ? compressed : not_compressed) += 1;
  }
  CHECK(compressed > 0);  // both sides of the boundary are on this grid
  CHECK(not_compressed > 0);

  // The summary counts them, and counts the designs a user may take: safe and not fully
  // compressed.
  const auto summary = Run({"sweep", "--x", "covering-modulus=0.3MPa..300MPa:log:9", "--y",
                            "covering-thickness=2mm..40mm:9"});
  REQUIRE(summary.exit_code == 0);
  std::size_t admissible = 0;
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    if (csv.Number(i, "safe") == 1.0 && csv.Number(i, "fully_compressed") == 0.0) ++admissible;
  }
  CHECK_THAT(summary.out,
             Contains(fmt::format("covering fully compressed at {} of 81 covered points",
                                  compressed)) &&
                 Contains(fmt::format("safe and not fully compressed at {} (", admissible)));
}

TEST_CASE("sweep charts name only the quantities not swept and draw the full-compression "
          "boundary",
          "[sweep][plot]") {
  if (!covopt::cli::FindOnPath("gnuplot")) {
    WARN("gnuplot is not on PATH; skipping the plot checks");
    return;
  }
  TempDir dir;
  const auto map_path = dir / "map.svg";
  auto run = Run({"sweep", "--x", "covering-modulus=0.3MPa..300MPa:log:20", "--y",
                  "covering-thickness=2mm..40mm:20", "--plot", map_path.string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  std::string svg = ReadFile(map_path);
  // The scene line has the robot and the head, not the covering that is swept.
  CHECK_THAT(svg, Contains("scene: 10 kg at 2 m/s, R 15 mm; head 4.5 kg"));
  CHECK_THAT(svg, !Contains("27.6 MPa") && !Contains("covering 15 mm"));
  CHECK_THAT(run.out, Contains("Scene   10 kg at 2 m/s, R 15 mm; head 4.5 kg\n"));
  // Both limits and the full-compression boundary are in the key.
  CHECK_THAT(svg, Contains("laceration limit (ratio 1)") && Contains("contusion limit (ratio 1)") &&
                      Contains("full-compression boundary (δ_max = t2)") &&
                      Contains("fully compressed (dots)"));
  CHECK_THAT(svg, !Contains("never fully compressed") && !Contains("fully compressed everywhere"));

  // A grid that never bottoms out says so in the title; the speed is swept, so the title
  // leaves it out, and a non-default input beyond the headline is named.
  const auto soft_path = dir / "soft.svg";
  run = Run({"sweep", "--x", "speed=0.2m/s..0.5m/s:10", "--y", "covering-thickness=30mm..40mm:10",
             "--scalp-thickness", "4mm", "--plot", soft_path.string()});
  REQUIRE(run.exit_code == 0);
  svg = ReadFile(soft_path);
  CHECK_THAT(svg, Contains("never fully compressed"));
  CHECK_THAT(svg, Contains("scene: 10 kg, R 15 mm; covering 27.6 MPa; head 4.5 kg; "
                           "scalp-thickness 4 mm"));
  CHECK_THAT(svg, !Contains("m/s;"));

  // Line families: the swept family and axis are not in the scene line either.
  const auto lines_path = dir / "lines.svg";
  run = Run({"sweep", "--x", "speed=0.5m/s..3m/s:20", "--y", "robot-mass=2kg,10kg,fixed",
             "--plot", lines_path.string()});
  REQUIRE(run.exit_code == 0);
  svg = ReadFile(lines_path);
  CHECK_THAT(svg, Contains("scene: robot, R 15 mm; covering 15 mm, 27.6 MPa; head 4.5 kg"));
  CHECK_THAT(svg, Contains("fully compressed (δ_max &gt; t2)") || Contains("fully compressed (δ_max > t2)"));

  // With a safety factor the limit lines sit at the derated limits, and say so.
  const auto scene = dir.Write("sf.toml", "[limits]\nsafety_factor = 1.5\n");
  const auto derated_path = dir / "derated.svg";
  run = Run({"sweep", "--scene", scene.string(), "--x", "covering-modulus=0.3MPa..300MPa:log:20",
             "--y", "covering-thickness=2mm..40mm:20", "--plot", derated_path.string()});
  INFO(run.err);
  REQUIRE(run.exit_code == 0);
  svg = ReadFile(derated_path);
  CHECK_THAT(svg, Contains("laceration limit / 1.5 (ratio 0.6667)") &&
                      Contains("contusion limit / 1.5 (ratio 0.6667)"));
}

TEST_CASE("the sweep CSV streams: the same text to a file as to stdout, in bounded pieces",
          "[sweep]") {
  const std::vector<std::string> axes = {"--x", "covering-modulus=1MPa..300MPa:log:60", "--y",
                                         "covering-thickness=0..40mm:60"};
  auto to_stdout = axes;
  to_stdout.insert(to_stdout.begin(), "sweep");
  to_stdout.insert(to_stdout.end(), {"--csv", "-"});
  const auto printed = Run(to_stdout);
  REQUIRE(printed.exit_code == 0);

  TempDir dir;
  const auto path = dir / "grid.csv";
  auto to_file = axes;
  to_file.insert(to_file.begin(), "sweep");
  to_file.insert(to_file.end(), {"--csv", path.string()});
  const auto written = Run(to_file);
  REQUIRE(written.exit_code == 0);
  CHECK(ReadFile(path) == printed.out);
  CHECK(ParseCsv(printed.out).rows.size() == 3600);
  REQUIRE(printed.out.size() > (std::size_t{1} << 20));  // more than one piece

  // The writer alone, fed the library's rows block by block: the pieces it hands on are
  // whole rows of at most about 1 MiB, and together they are the CLI's text.
  const auto x = covopt::cli::ParseSweepAxis(axes[1], "--x");
  const auto y = covopt::cli::ParseSweepAxis(axes[3], "--y");
  std::string text;
  std::size_t pieces = 0;
  covopt::report::SweepCsvWriter writer(x, &y, [&](std::string_view piece) {
    ++pieces;
    CHECK(piece.size() < (std::size_t{1} << 20) + 4096);
    CHECK(piece.back() == '\n');
    text += piece;
  });
  covopt::SweepOptions options;
  options.block_rows = 37;
  covopt::Sweep(covopt::cli::MakeSweepSpec(x, &y, covopt::cli::SimulationPlan{}), options,
                [&](std::span<const covopt::SweepRow> rows) { writer.Write(rows); });
  writer.Finish();
  CHECK(pieces >= 2);
  CHECK(text == printed.out);
}

TEST_CASE("an unwritable sweep CSV is exit 1 naming the file, nothing on stdout", "[sweep]") {
  TempDir dir;
  const auto missing = dir / "no-such-dir" / "grid.csv";
  const auto run = Run({"sweep", "--x", "speed=1m/s..3m/s:5", "--csv", missing.string()});
  CHECK(run.exit_code == 1);
  CHECK(run.out.empty());
  CHECK_THAT(run.err, Contains("cannot write '" + missing.string() + "'"));
}

TEST_CASE("a swept covering field is given: no note that the default covering is assumed", "[sweep]") {
  const auto swept = Run({"sweep", "--x", "covering-thickness=5mm..20mm:4"});
  REQUIRE(swept.exit_code == 0);
  CHECK(swept.out.find("the default is assumed") == std::string::npos);
  // Sweeping another field leaves the covering the assumed default, and the note says so.
  const auto speed = Run({"sweep", "--x", "speed=1..2:3"});
  REQUIRE(speed.exit_code == 0);
  CHECK(speed.out.find("no covering given: the default is assumed") != std::string::npos);
}
