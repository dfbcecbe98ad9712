// Bad input through the real command line (issue 6): every flag of simulate, optimize and
// materials with a missing, malformed, negative, zero, NaN, infinite, absurdly large or
// wrong-unit value, or a bare number that is implausible in SI (a unit slip: "--robot-radius
// 40" is 40 m); unknown flags; broken scene files and catalogs. Each must give exit code
// 2, nothing on stdout, and exactly one line on stderr that names the field or flag, repeats
// the offending value, and says what is allowed.
#include <charconv>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "cli_test_support.hpp"
#include "scene_fields.hpp"

namespace {

using covopt::cli::QuantityKind;
using covopt::cli::SceneField;
using covopt::cli::SceneFields;
using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using covopt::cli::testing::TempDir;
using Catch::Matchers::Contains;

struct BadCase {
  std::vector<std::string> args;
  /// Every one of these must appear in the message (the field or flag, the value, what is
  /// allowed).
  std::vector<std::string> mentions;
};

void CheckRejected(const BadCase& c) {
  const CliRun run = Run(c.args);
  std::string command;
  for (const std::string& a : c.args) command += "'" + a + "' ";
  INFO("covopt " << command);
  INFO("stderr: " << run.err);
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  // One message: one line, ending in a newline, no stray blank lines.
  REQUIRE_FALSE(run.err.empty());
  CHECK(run.err.back() == '\n');
  CHECK(run.err.find('\n') == run.err.size() - 1);
  CHECK_THAT(run.err, Contains(": error: "));
  CHECK_THAT(run.err, !Contains("internal error"));
  // No computed NaN in the message (unless the input itself was a NaN: it is quoted back).
  const bool typed_nan = command.find("nan") != std::string::npos;
  if (!typed_nan) CHECK_THAT(run.err, !Contains("nan") && !Contains("NaN"));
  for (const std::string& m : c.mentions) CHECK_THAT(run.err, Contains(m));
}

/// A value of the field's kind with a unit, for building wrong values.
std::string WithUnit(QuantityKind kind, const std::string& number) {
  switch (kind) {
    case QuantityKind::kMass: return number + "kg";
    case QuantityKind::kLength: return number + "mm";
    case QuantityKind::kSpeed: return number + "m/s";
    case QuantityKind::kModulus: return number + "MPa";
    case QuantityKind::kDensity: return number + "kg/m3";
    case QuantityKind::kDimensionless: return number;
    case QuantityKind::kEnergyDensity: return number + "J/m2";
    case QuantityKind::kTime: return number + "s";
    case QuantityKind::kAcceleration: return number + "m/s2";
    case QuantityKind::kDampingCoefficient: return number + "s/m";
    case QuantityKind::kStiffness: return number + "N/m";
    case QuantityKind::kViscousDamping: return number + "N*s/m";
    case QuantityKind::kArea: return number + "m2";
  }
  return number;
}

/// The shortest text that reads back as `value`: "1000", "1e+15".
std::string Shortest(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

/// A unit of another kind than `kind`.
std::string WrongUnit(QuantityKind kind) {
  return kind == QuantityKind::kSpeed ? "2kg" : "2m/s";
}

/// The bad values every scene flag must reject, for `command` (simulate or optimize).
std::vector<BadCase> SceneFlagCases(const std::string& command) {
  std::vector<BadCase> cases;
  for (const SceneField& field : SceneFields()) {
    if (command == "optimize" && field.table == "covering") continue;  // not offered there
    const std::string flag(field.flag);
    const std::string name = field.dotted_name();
    const QuantityKind kind = field.spec.kind;
    const bool ratio = kind == QuantityKind::kDimensionless;
    cases.push_back({{command, flag}, {flag, "missing value"}});
    cases.push_back({{command, flag, "abc"}, {flag, "not a number", "'abc'"}});
    cases.push_back({{command, flag, "nan"}, {flag, "not a finite number", "'nan'"}});
    cases.push_back({{command, flag, "-inf"}, {flag, "not a finite number", "'-inf'"}});
    cases.push_back({{command, flag, "1e999"}, {flag, "out of range", "'1e999'"}});
    cases.push_back({{command, flag, "1,5"}, {flag, "decimal separator", "'1,5'"}});
    cases.push_back({{command, flag, WrongUnit(kind)}, {flag, "unit", WrongUnit(kind)}});
    cases.push_back({{command, flag, ""}, {flag, "empty value"}});
    // Out of the model's range: the library's check names the field, the value and the range.
    cases.push_back({{command, flag, WithUnit(kind, "1e30")}, {name, "must be", "1e+"}});
    cases.push_back({{command, flag, WithUnit(kind, "-3")}, {name, "must be", "-"}});
    // Zero is allowed where it means "none": no covering, and the inputs of the scenes
    // beyond the two-mass model (no damping, no braking, no neck).
    const bool zero_means_none = name == "covering.thickness" || name == "model.damping" ||
                                 field.table == "robot" && (field.key == "reaction_delay" ||
                                                            field.key == "braking") ||
                                 field.table == "head" && field.key != "mass" &&
                                     field.key != "radius";
    if (!ratio && !zero_means_none) {
      cases.push_back({{command, flag, WithUnit(kind, "0")}, {name, "must be", "(got 0)"}});
    }
    if (ratio) cases.push_back({{command, flag, "0.6"}, {name, "(-1, 0.5]", "0.6"}});
    // A bare number far beyond the plausible range (a unit slip): refused before the model
    // sees it, naming the flag, the number, its SI reading and how to write it.
    if (field.spec.has_plausible_range()) {
      const std::string slip = Shortest(field.spec.plausible_max * 1000);
      cases.push_back({{command, flag, slip},
                       {flag + " " + slip + ": a bare number is in", "write "}});
    }
    if (!field.spec.allow_fixed) cases.push_back({{command, flag, "fixed"}, {flag, "'fixed'"}});
    if (!field.spec.allow_flat) cases.push_back({{command, flag, "flat"}, {flag, "'flat'"}});
  }
  return cases;
}

}  // namespace

TEST_CASE("every scene flag of simulate rejects bad values with one clear message",
          "[bad-input]") {
  for (const BadCase& c : SceneFlagCases("simulate")) CheckRejected(c);
}

TEST_CASE("every scene flag of optimize rejects bad values with one clear message",
          "[bad-input]") {
  for (const BadCase& c : SceneFlagCases("optimize")) CheckRejected(c);
}

TEST_CASE("simulate's other flags reject bad values", "[bad-input]") {
  const std::vector<BadCase> cases = {
      {{"simulate", "--method"}, {"--method", "missing value"}},
      {{"simulate", "--method", "rk4"}, {"--method", "rk4", "exact"}},
      {{"simulate", "--cvode-method", "euler"}, {"--cvode-method", "euler", "adams"}},
      {{"simulate", "--thresholds", "strict"}, {"--thresholds", "strict", "cumulative"}},
      {{"simulate", "--method", "cvode", "--rtol", "0"}, {"--rtol: relative_tolerance", "(got 0)", "1e-14"}},
      {{"simulate", "--method", "cvode", "--rtol", "-1e-8"}, {"rtol", "-1e-08", "1e-14"}},
      {{"simulate", "--method", "cvode", "--rtol", "nan"}, {"--rtol", "not a finite number"}},
      {{"simulate", "--method", "cvode", "--rtol", "inf"}, {"--rtol", "not a finite number"}},
      {{"simulate", "--method", "cvode", "--rtol", "1e300"}, {"rtol", "1e+300", "1e-2"}},
      {{"simulate", "--method", "cvode", "--rtol", "1mm"}, {"--rtol", "'mm'", "plain number"}},
      {{"simulate", "--method", "cvode", "--atol", "0"}, {"--atol", "> 0", "'0'"}},
      {{"simulate", "--method", "cvode", "--atol", "-1"}, {"--atol", "> 0", "'-1'"}},
      {{"simulate", "--method", "cvode", "--atol", "inf"}, {"--atol", "not a finite number"}},
      {{"simulate", "--method", "cvode", "--max-steps", "0"}, {"--max-steps: max_steps", ">= 10", "0"}},
      {{"simulate", "--method", "cvode", "--max-steps", "-5"}, {"max_steps", ">= 10", "-5"}},
      {{"simulate", "--method", "cvode", "--max-steps", "abc"}, {"--max-steps", "whole number", "'abc'"}},
      {{"simulate", "--method", "cvode", "--max-steps", "1e99"}, {"--max-steps", "whole number", "'1e99'"}},
      {{"simulate", "--method", "cvode", "--max-steps", "2.5"}, {"--max-steps", "whole number", "'2.5'"}},
      {{"simulate", "--material", "unobtainium"}, {"--material", "unobtainium", "materials list"}},
      {{"simulate", "--material", "polystyrene"}, {"--material", "polystyrene", "did you mean"}},
      {{"simulate", "--material", "polystyrene foam 27.6", "--covering-modulus", "1MPa"},
       {"--material", "--covering-modulus"}},
      {{"simulate", "--scene", "/nonexistent/scene.toml"}, {"/nonexistent/scene.toml", "No such file"}},
      {{"simulate", "--catalog", "/nonexistent/catalog.toml", "--material", "x"},
       {"/nonexistent/catalog.toml", "No such file"}},
      {{"simulate", "--catalog", "/nonexistent/catalog.toml"}, {"--catalog", "--material"}},
      {{"simulate", "--no-builtin", "--material", "x"}, {"--no-builtin", "--catalog"}},
      {{"simulate", "--plot", "chart.jpg"}, {"--plot", "chart.jpg", ".png or", ".svg"}},
      {{"simulate", "--bogus"}, {"unknown option '--bogus'"}},
      {{"simulate", "--sped", "2"}, {"'--sped'", "did you mean '--speed'?"}},
      {{"simulate", "--robot-mas", "2"}, {"'--robot-mas'", "did you mean '--robot-mass'?"}},
      {{"simulate", "2m/s"}, {"unexpected argument '2m/s'", "--speed 2m/s"}},
      {{"simulate", "--speed", "1", "--speed", "2"}, {"--speed"}},
      {{"simulate", "--laceration-limit"}, {"--laceration-limit", "missing value"}},
      {{"simulate", "--laceration-limit", "abc"}, {"--laceration-limit", "not a number", "'abc'"}},
      {{"simulate", "--laceration-limit", "nan"}, {"--laceration-limit", "not a finite number"}},
      {{"simulate", "--laceration-limit", "0"}, {"--laceration-limit", "[1000, 1e+13] Pa", "'0'"}},
      {{"simulate", "--laceration-limit", "-1MPa"}, {"--laceration-limit", "[1000, 1e+13] Pa", "'-1MPa'"}},
      {{"simulate", "--laceration-limit", "1"},
       {"--laceration-limit 1: a bare number is in pascals (1 Pa); write 1MPa or 1Pa"}},
      {{"simulate", "--laceration-limit", "1J/m2"}, {"--laceration-limit", "unit 'J/m2'", "MPa"}},
      {{"simulate", "--contusion-limit", "2.52"},
       {"--contusion-limit 2.52: a bare number is in joules per square metre (2.52 J/m2); write "
        "2.52J/cm2 or 2.52J/m2"}},
      {{"simulate", "--contusion-limit", "2.52MPa"}, {"--contusion-limit", "unit 'MPa'", "J/cm2"}},
      {{"simulate", "--contusion-limit", "-inf"}, {"--contusion-limit", "not a finite number"}},
      {{"simulate", "--contusion-limit", "0J/cm2"}, {"--contusion-limit", "[1, 1e+13] J/m2", "'0J/cm2'"}},
      {{"simulate", "--safety-factor", "0.5"}, {"--safety-factor", "[1, 100]", "'0.5'"}},
      {{"simulate", "--safety-factor", "1e9"}, {"--safety-factor", "[1, 100]", "'1e9'"}},
      {{"simulate", "--safety-factor", "2mm"}, {"--safety-factor", "'mm'", "plain number"}},
      {{"simulate", "--safety-factor", "nan"}, {"--safety-factor", "not a finite number"}},
      {{"sweep", "--x", "speed=1..2:3", "--laceration-limit", "1"},
       {"--laceration-limit 1: a bare number is in pascals"}},
      {{"sweep", "--x", "speed=1..2:3", "--contusion-limit", "-2J/cm2"},
       {"--contusion-limit", "[1, 1e+13] J/m2"}},
      {{"sweep", "--x", "speed=1..2:3", "--safety-factor", "2"},
       {"unknown option '--safety-factor'"}},
      {{"sweep", "--x", "robot-radius=15..40"},
       {"--x 15: a bare number is in metres (15 m); write 15mm or 15m"}},
      {{"frobnicate"}, {"frobnicate"}},
  };
  for (const BadCase& c : cases) CheckRejected(c);
}

TEST_CASE("optimize's design flags reject bad values", "[bad-input]") {
  const std::vector<BadCase> cases = {
      {{"optimize", "--max-thickness", "0"}, {"--max-thickness", "(0.1 mm, 1 m]", "'0'"}},
      {{"optimize", "--max-thickness", "-5mm"}, {"--max-thickness", "(0.1 mm, 1 m]", "'-5mm'"}},
      {{"optimize", "--max-thickness", "2m"}, {"--max-thickness", "(0.1 mm, 1 m]", "'2m'"}},
      {{"optimize", "--max-thickness", "nan"}, {"--max-thickness", "not a finite number"}},
      {{"optimize", "--max-thickness", "10kg"}, {"--max-thickness", "unit 'kg'", "a length"}},
      {{"optimize", "--max-thickness"}, {"--max-thickness", "missing value"}},
      {{"optimize", "--min-modulus", "0"}, {"--min-modulus", "0 < min < max", "0 Pa"}},
      {{"optimize", "--min-modulus", "-1MPa"}, {"--min-modulus", "0 < min < max", "-1000000 Pa"}},
      {{"optimize", "--max-modulus", "1e20Pa"}, {"--max-modulus", "<= 1e13 Pa", "1e+20 Pa"}},
      {{"optimize", "--min-modulus", "2GPa"}, {"--min-modulus", "min < max", "2000000000 Pa"}},
      {{"optimize", "--max-modulus", "2m/s"}, {"--max-modulus", "unit 'm/s'"}},
      {{"optimize", "--safety-factor", "0.5"}, {"--safety-factor", "[1, 100]", "'0.5'"}},
      {{"optimize", "--safety-factor", "0"}, {"--safety-factor", "[1, 100]", "'0'"}},
      {{"optimize", "--safety-factor", "1e9"}, {"--safety-factor", "[1, 100]", "'1e9'"}},
      {{"optimize", "--safety-factor", "inf"}, {"--safety-factor", "not a finite number"}},
      {{"optimize", "--thickness", "0"}, {"--thickness", "[0.1 mm, 1 m]", "'0'"}},
      {{"optimize", "--thickness", "-1mm"}, {"--thickness", "[0.1 mm, 1 m]", "'-1mm'"}},
      {{"optimize", "--thickness", "5m"}, {"--thickness", "[0.1 mm, 1 m]", "'5m'"}},
      {{"optimize", "--thickness", "abc"}, {"--thickness", "not a number", "'abc'"}},
      {{"optimize", "--covering-poisson", "0.6"}, {"--covering-poisson", "(-1, 0.5]", "'0.6'"}},
      {{"optimize", "--covering-poisson", "-1"}, {"--covering-poisson", "(-1, 0.5]", "'-1'"}},
      {{"optimize", "--thickness-step", "-1mm"}, {"--thickness-step", "[0, 10 mm]", "'-1mm'"}},
      {{"optimize", "--thickness-step", "1m"}, {"--thickness-step", "[0, 10 mm]", "'1m'"}},
      {{"optimize", "--global", "anneal"}, {"--global", "direct-l", "'anneal'"}},
      {{"optimize", "--seed", "-1"}, {"--seed", "whole number", "'-1'"}},
      {{"optimize", "--seed", "abc"}, {"--seed", "whole number", "'abc'"}},
      {{"optimize", "--seed", "99999999999999999999999"}, {"--seed", "whole number", "99999999999999999999999"}},
      {{"optimize", "--top", "-1"}, {"--top", "whole number", "'-1'"}},
      {{"optimize", "--top", "1e9"}, {"--top", "whole number", "'1e9'"}},
      {{"optimize", "--top", "3.5"}, {"--top", "whole number", "'3.5'"}},
      {{"optimize", "--threads", "-1"}, {"--threads", "[0, 256]", "'-1'"}},
      {{"optimize", "--threads", "257"}, {"--threads", "[0, 256]", "'257'"}},
      {{"optimize", "--threads", "-2"}, {"--threads", "[0, 256]", "'-2'"}},
      {{"optimize", "--threads", "100000"}, {"--threads", "[0, 256]", "'100000'"}},
      {{"optimize", "--threads", "two"}, {"--threads", "[0, 256]", "'two'"}},
      {{"optimize", "--material", "polystyrene"}, {"--material", "'polystyrene'", "did you mean"}},
      {{"optimize", "--family", "metal"}, {"--family", "'metal'", "foam"}},
      {{"optimize", "--catalog", "/nonexistent.toml"}, {"/nonexistent.toml", "No such file"}},
      {{"optimize", "--thresholds", "strict"}, {"--thresholds", "strict", "literal"}},
      {{"optimize", "--covering-thickness", "1mm"},
       {"unknown option '--covering-thickness'", "did you mean '--thickness'?"}},
      {{"optimize", "--covering-modulus", "1MPa"}, {"unknown option '--covering-modulus'"}},
      {{"optimize", "--max-thicknes", "1mm"}, {"did you mean '--max-thickness'?"}},
      {{"optimize", "--robot-mass", "fixed", "--head-mass", "fixed"},
       {"robot.mass", "head.mass", "both fixed", "[0.001, 1e+06] kg"}},
  };
  for (const BadCase& c : cases) CheckRejected(c);
}

TEST_CASE("materials' flags reject bad values", "[bad-input]") {
  const std::vector<BadCase> cases = {
      {{"materials", "show", "polystyrene"}, {"'polystyrene'", "did you mean"}},
      {{"materials", "show"}, {"name", "required"}},
      {{"materials", "find", "--modulus", "10MPa"}, {"--modulus", "LO..HI", "'10MPa'"}},
      {{"materials", "find", "--modulus", "abc..1GPa"}, {"--modulus", "not a number", "'abc'"}},
      {{"materials", "find", "--modulus", "10kg..20kg"}, {"--modulus", "'kg'"}},
      {{"materials", "find", "--modulus", "nan..1GPa"}, {"--modulus", "not a finite number"}},
      {{"materials", "find", "--modulus", "100MPa..10MPa"}, {"--modulus", "100MPa..10MPa"}},
      {{"materials", "find", "--poisson", "0.3mm..0.4"}, {"--poisson", "'mm'"}},
      {{"materials", "find", "--density", "1g..2g"}, {"--density", "'g'"}},
      {{"materials", "find", "--family", "metal"}, {"--family", "'metal'", "foam"}},
      {{"materials", "find", "--basis", "guessed"}, {"--basis", "'guessed'", "compressive"}},
      {{"materials", "find", "--modulus"}, {"--modulus", "missing value"}},
      {{"materials", "list", "--bogus"}, {"unknown option '--bogus'"}},
      {{"materials", "list", "--catalog", "/nonexistent.toml"}, {"/nonexistent.toml", "No such file"}},
      {{"materials", "list", "--no-builtin"}, {"--no-builtin", "--catalog"}},
  };
  for (const BadCase& c : cases) CheckRejected(c);
}

TEST_CASE("broken scene files are rejected with file:line:column and the key", "[bad-input]") {
  TempDir dir;
  struct FileCase {
    std::string name, text;
    std::vector<std::string> mentions;
  };
  const std::vector<FileCase> cases = {
      {"truncated.toml", "[robot]\nmass = \"10", {"truncated.toml:2:", "TOML syntax error"}},
      {"not_toml.toml", "this is not toml at all\n", {"not_toml.toml:1:", "TOML syntax error"}},
      {"binary.toml", std::string("\x00\x01\x02\xff", 4), {"binary.toml:1:", "TOML syntax error"}},
      {"unknown_key.toml", "[robot]\nmas = 10\n", {"unknown_key.toml:2:1", "'robot.mas'", "did you mean 'robot.mass'?"}},
      {"unknown_table.toml", "[robto]\nmass = 10\n", {"unknown_table.toml:1:", "'robto'", "did you mean 'robot'?"}},
      {"top_level.toml", "speed = 2\n", {"top_level.toml:1:1", "'speed'", "[robot]"}},
      {"far_key.toml", "[head]\ncolour = \"red\"\n", {"'head.colour'", "[head] takes mass, radius"}},
      {"wrong_type.toml", "[robot]\nmass = true\n", {"wrong_type.toml:2:8", "robot.mass", "a boolean", "10 kg"}},
      {"array.toml", "[robot]\nspeed = [1, 2]\n", {"robot.speed", "an array"}},
      {"table_value.toml", "robot = 3\n", {"'robot' must be a table", "an integer"}},
      {"duplicate_key.toml", "[robot]\nmass = 1\nmass = 2\n", {"duplicate_key.toml:3:", "TOML syntax error", "mass"}},
      {"duplicate_table.toml", "[robot]\nmass = 1\n[robot]\nspeed = 2\n", {"duplicate_table.toml:3:", "robot"}},
      {"bad_unit.toml", "[robot]\nspeed = \"2 kg\"\n", {"bad_unit.toml:2:9", "robot.speed", "unit 'kg'", "m/s"}},
      {"nan.toml", "[robot]\nspeed = nan\n", {"nan.toml:2:9", "robot.speed", "not a finite number"}},
      {"inf.toml", "[head]\nmass = inf\n", {"inf.toml:2:8", "head.mass", "not a finite number"}},
      {"negative.toml", "[robot]\nmass = -10\n", {"robot.mass", "must be in [0.001, 1e+06] kg", "(got -10)"}},
      {"zero.toml", "[head]\nradius = 0\n", {"head.radius", "must be in", "(got 0)"}},
      {"huge.toml", "[robot]\nspeed = \"1e6 km/h\"\n", {"robot.speed", "[1e-06, 100] m/s", "(got 277777.77"}},
      {"thick.toml", "[covering]\nthickness = \"2 m\"\n", {"covering.thickness", "[0.0001, 1] m", "(got 2)"}},
      {"both_fixed.toml", "[robot]\nmass = \"fixed\"\n[head]\nmass = \"fixed\"\n", {"both fixed"}},
      {"thresholds.toml", "[model]\nthresholds = \"strict\"\n", {"thresholds.toml:2:", "model.thresholds", "'strict'", "literal"}},
      {"thresholds_type.toml", "[model]\nthresholds = 1\n", {"model.thresholds", "expected a string", "an integer"}},
      {"poisson.toml", "[skull]\npoisson = 0.7\n", {"skull.poisson", "(-1, 0.5]", "0.7"}},
      {"slip_radius.toml", "[robot]\nradius = 40\n",
       {"slip_radius.toml:2:10: robot.radius 40: a bare number is in metres (40 m); write \"40mm\" or \"40m\""}},
      {"slip_modulus.toml", "[skull]\nmodulus = 6.5\n",
       {"slip_modulus.toml:2:11", "skull.modulus 6.5", "write \"6.5GPa\" or \"6.5Pa\""}},
      {"slip_mass.toml", "[head]\nmass = 4500\n", {"head.mass 4500", "\"4500g\""}},
  };
  for (const FileCase& f : cases) {
    const auto path = dir.Write(f.name, f.text);
    BadCase c{{"simulate", "--scene", path.string()}, f.mentions};
    CheckRejected(c);
    c.args[0] = "optimize";
    if (f.name != "thick.toml") CheckRejected(c);  // optimize ignores the file's covering
  }
  // An empty scene file is valid (every key is optional): the paper's scene.
  const auto empty = dir.Write("empty.toml", "");
  CHECK(Run({"simulate", "--scene", empty.string()}).exit_code == 0);
  // A directory is not a scene file.
  CheckRejected({{"simulate", "--scene", dir.path().string()}, {"is a directory"}});
}

TEST_CASE("broken catalogs are rejected with file:line:column and the key", "[bad-input]") {
  TempDir dir;
  const std::string entry =
      "[[material]]\nname = \"soft\"\nfamily = \"foam\"\nyoungs_modulus_Pa = 2e6\n"
      "modulus_basis = \"compressive\"\nsource = \"test\"\n";
  struct FileCase {
    std::string name, text;
    std::vector<std::string> mentions;
  };
  const std::vector<FileCase> cases = {
      {"duplicate.toml", entry + entry, {"duplicate.toml:8:", "duplicate material name 'soft'", "duplicate.toml:1:1"}},
      {"builtin_clash.toml",
       "[[material]]\nname = \"Polystyrene Foam 27.6\"\nfamily = \"foam\"\nyoungs_modulus_Pa = 2e6\n"
       "modulus_basis = \"compressive\"\nsource = \"test\"\n",
       {"polystyrene foam 27.6", "ignoring case"}},
      {"missing.toml", "[[material]]\nname = \"soft\"\nfamily = \"foam\"\n", {"missing.toml:1:1", "'youngs_modulus_Pa'", "required"}},
      {"no_name.toml", "[[material]]\nfamily = \"foam\"\n", {"no_name.toml:1:1", "'name'"}},
      {"nu_big.toml", entry + "poisson_ratio = 0.7\n", {"nu_big.toml:7:17", "poisson_ratio", "(-1, 0.5]", "0.7"}},
      {"nu_nan.toml", entry + "poisson_ratio = nan\n", {"poisson_ratio", "(-1, 0.5]"}},
      {"e_zero.toml",
       "[[material]]\nname = \"soft\"\nfamily = \"foam\"\nyoungs_modulus_Pa = 0\n"
       "modulus_basis = \"compressive\"\nsource = \"test\"\n",
       {"e_zero.toml:4:21", "youngs_modulus_Pa", "[1000, 1e+12] Pa", "(got 0)"}},
      {"e_negative.toml",
       "[[material]]\nname = \"soft\"\nfamily = \"foam\"\nyoungs_modulus_Pa = -5e6\n"
       "modulus_basis = \"compressive\"\nsource = \"test\"\n",
       {"youngs_modulus_Pa", "[1000, 1e+12] Pa", "-5"}},
      {"e_inf.toml",
       "[[material]]\nname = \"soft\"\nfamily = \"foam\"\nyoungs_modulus_Pa = inf\n"
       "modulus_basis = \"compressive\"\nsource = \"test\"\n",
       {"youngs_modulus_Pa", "[1000, 1e+12] Pa"}},
      {"e_unit.toml",
       "[[material]]\nname = \"soft\"\nfamily = \"foam\"\nyoungs_modulus_Pa = \"2 kg\"\n"
       "modulus_basis = \"compressive\"\nsource = \"test\"\n",
       {"e_unit.toml:4:21", "youngs_modulus_Pa", "unit 'kg' is not a modulus", "'2 kg'"}},
      {"e_bare.toml",
       "[[material]]\nname = \"soft\"\nfamily = \"foam\"\nyoungs_modulus_Pa = 27.6\n"
       "modulus_basis = \"compressive\"\nsource = \"test\"\n",
       {"e_bare.toml:4:21: material 'soft': youngs_modulus_Pa 27.6: a bare number is in pascals "
        "(27.6 Pa); write \"27.6MPa\" or \"27.6Pa\""}},
      {"e_bool.toml",
       "[[material]]\nname = \"soft\"\nfamily = \"foam\"\nyoungs_modulus_Pa = true\n"
       "modulus_basis = \"compressive\"\nsource = \"test\"\n",
       {"youngs_modulus_Pa", "a string with a unit", "27.6MPa"}},
      {"density_bare.toml", entry + "density_kg_per_m3 = 1.05\n",
       {"density_kg_per_m3 1.05: a bare number is in kilograms per cubic metre", "\"1.05g/cm3\""}},
      {"density.toml", entry + "density_kg_per_m3 = -1\n", {"density_kg_per_m3", "> 0", "-1"}},
      {"unknown_key.toml", entry + "poisson = 0.3\n", {"unknown key 'poisson'", "did you mean 'poisson_ratio'?"}},
      {"basis.toml",
       "[[material]]\nname = \"soft\"\nfamily = \"foam\"\nyoungs_modulus_Pa = 2e6\n"
       "modulus_basis = \"compresive\"\nsource = \"test\"\n",
       {"modulus_basis", "\"compresive\"", "did you mean 'compressive'?"}},
      {"single_bracket.toml", "[material]\nname = \"x\"\n", {"[[material]]", "double brackets"}},
      {"top_key.toml", "name = \"x\"\n", {"top_key.toml:1:1", "'name'", "[[material]]"}},
      {"truncated.toml", "[[material]]\nname = \"so", {"truncated.toml:2:", "TOML syntax error"}},
      {"dup_key.toml", entry + "name = \"again\"\n", {"dup_key.toml:7:", "TOML syntax error"}},
      {"empty_name.toml",
       "[[material]]\nname = \"  \"\nfamily = \"foam\"\nyoungs_modulus_Pa = 2e6\n"
       "modulus_basis = \"compressive\"\nsource = \"test\"\n",
       {"name", "must not be empty"}},
  };
  for (const FileCase& f : cases) {
    const std::string path = dir.Write(f.name, f.text).string();
    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"materials", "list", "--catalog", path},
          std::vector<std::string>{"optimize", "--catalog", path},
          std::vector<std::string>{"simulate", "--catalog", path, "--material", "soft"}}) {
      CheckRejected({args, f.mentions});
    }
  }
}

TEST_CASE("a covering thicker than the model's bound is rejected, at the bound accepted",
          "[bad-input]") {
  // The bound is the library's (ImpactModel::FromScene): covering.thickness 0 or in [0.0001, 1] m.
  CheckRejected({{"simulate", "--covering-thickness", "1.001m"}, {"covering.thickness", "[0.0001, 1] m", "(got 1.001)"}});
  CheckRejected({{"simulate", "--covering-thickness", "1e300m"}, {"covering.thickness", "[0.0001, 1] m"}});
  CheckRejected({{"optimize", "--thickness", "1.5m"}, {"--thickness", "[0.1 mm, 1 m]"}});
  CheckRejected({{"optimize", "--max-thickness", "1001mm"}, {"--max-thickness", "1 m]"}});
  const CliRun at_bound = Run({"simulate", "--covering-thickness", "1m", "--json"});
  CHECK(at_bound.exit_code == 0);
  CHECK_THAT(covopt::cli::testing::WithoutProvenance(at_bound.out),  // "provenance" has a "nan"
             !Contains("nan") && Contains("\"contact_duration_s\": 0."));
}

TEST_CASE("a speed too small to impact is rejected instead of printing NaN", "[bad-input]") {
  // Found while hardening: 1e-300 m/s passed validation and printed "contact duration -nan".
  CheckRejected({{"simulate", "--speed", "1e-300"}, {"robot.speed", "[1e-06, 100] m/s", "1e-300"}});
  CheckRejected({{"simulate", "--speed", "1e-200", "--json"}, {"robot.speed", "[1e-06, 100] m/s"}});
  CheckRejected({{"optimize", "--speed", "1e-9mm/s"}, {"robot.speed", "[1e-06, 100] m/s"}});
  const CliRun slowest = Run({"simulate", "--speed", "1e-6", "--json"});
  CHECK(slowest.exit_code == 0);
  CHECK_THAT(covopt::cli::testing::WithoutProvenance(slowest.out),
             !Contains("nan") && !Contains("\"contact_duration_s\": null"));
}
