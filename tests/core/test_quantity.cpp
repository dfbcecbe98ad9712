// Values with units (covopt/core/quantity.hpp), the parser shared by the command line, scene
// files and catalog files. These tests check every unit of every kind, that decimal units
// give the double nearest the decimal value (no float noise: "18mm" is exactly 0.018), the
// optional space, the words fixed/flat only where allowed, that every bad value is rejected
// with a message naming the value, and the plausible ranges of bare numbers: every realistic
// value passes, the classic slips (mm typed as m, MPa as Pa, g as kg, mm/s as m/s, J/cm² as
// J/m²) are refused with the message "<flag> <n>: a bare number is in <SI unit> (<SI
// reading>); write <n><likely unit> or <n><SI unit>", and an explicit unit is always taken.

#include <catch2/catch.hpp>

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "covopt/core/quantity.hpp"
#include "covopt/core/scene.hpp"

using covopt::FormatQuantity;
using covopt::ParseQuantity;
using covopt::QuantityKind;
using covopt::QuantitySpec;
using Catch::Matchers::Contains;
namespace specs = covopt::quantity_specs;

namespace {

// Specs without a plausible range: the units and the number format alone.
constexpr QuantitySpec kMass{QuantityKind::kMass, true, false};
constexpr QuantitySpec kLength{QuantityKind::kLength};
constexpr QuantitySpec kRadius{QuantityKind::kLength, false, true};
constexpr QuantitySpec kSpeed{QuantityKind::kSpeed};
constexpr QuantitySpec kModulus{QuantityKind::kModulus};
constexpr QuantitySpec kRatio{QuantityKind::kDimensionless};
constexpr QuantitySpec kDensity{QuantityKind::kDensity};
constexpr QuantitySpec kEnergyDensity{QuantityKind::kEnergyDensity};

/// The message ParseQuantity throws for `text`, or "" if it accepts it.
std::string ErrorFor(const std::string& text, const QuantitySpec& spec,
                     const std::string& name = "--value") {
  try {
    ParseQuantity(text, spec, name);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

/// The double nearest the decimal `text`, as the C++ library reads it.
double Decimal(const std::string& text) {
  double value = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

std::string Shortest(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

}  // namespace

TEST_CASE("every unit of every kind converts to SI, decimal units exactly", "[quantity]") {
  struct Case {
    const char* text;
    QuantitySpec spec;
    double si;  // the double nearest the SI value
  };
  const auto c = GENERATE(values<Case>({
      {"10kg", kMass, 10.0},
      {"4500g", kMass, 4.5},
      {"0.01t", kMass, 10.0},
      {"1.5m", kLength, 1.5},
      {"8cm", kLength, 0.08},
      {"15mm", kLength, 0.015},
      {"300um", kLength, 300e-6},
      {"300\u00b5m", kLength, 300e-6},
      {"300\u03bcm", kLength, 300e-6},
      {"2m/s", kSpeed, 2.0},
      {"250mm/s", kSpeed, 0.25},
      {"50cm/s", kSpeed, 0.5},
      {"1000Pa", kModulus, 1000.0},
      {"16.7kPa", kModulus, 16.7e3},
      {"27.6MPa", kModulus, 27.6e6},
      {"6.5GPa", kModulus, 6.5e9},
      {"5N/m2", kModulus, 5.0},
      {"2N/mm2", kModulus, 2e6},
      {"2N/mm\u00b2", kModulus, 2e6},
      {"50kg/m3", kDensity, 50.0},
      {"50 kg/m\u00b3", kDensity, 50.0},
      {"50kg/m^3", kDensity, 50.0},
      {"1.05g/cm3", kDensity, 1050.0},
      {"1.05g/cm\u00b3", kDensity, 1050.0},
      {"0.03g/cm^3", kDensity, 30.0},
      {"25200J/m2", kEnergyDensity, 25200.0},
      {"2.52J/cm2", kEnergyDensity, 25200.0},
      {"2.52J/cm\u00b2", kEnergyDensity, 25200.0},
      {"25.2kJ/m2", kEnergyDensity, 25200.0},
      {"25.2kJ/m\u00b2", kEnergyDensity, 25200.0},
      {"7J/m\u00b2", kEnergyDensity, 7.0},
      {"0.3", kRatio, 0.3},
  }));
  CAPTURE(c.text);
  CHECK(ParseQuantity(c.text, c.spec, "--value") == c.si);
  // km/h is no decimal unit: divided by 3.6.
  CHECK(ParseQuantity("7.2km/h", kSpeed, "--speed") == Approx(2.0).epsilon(1e-15));
}

TEST_CASE("sub-units carry no float noise", "[quantity]") {
  // The regression: multiplying by 1e-3 in binary gives 0.018000000000000002.
  REQUIRE(18 * 1e-3 != 0.018);
  CHECK(ParseQuantity("18mm", kLength, "--thickness") == 0.018);
  CHECK(Shortest(ParseQuantity("18mm", kLength, "--thickness")) == "0.018");
  CHECK(Shortest(ParseQuantity("12.7 mm", kLength, "--thickness")) == "0.0127");
  CHECK(ParseQuantity("0.5mm", kLength, "--thickness-step") == 0.0005);
  CHECK(Shortest(ParseQuantity("1.5e1mm", kLength, "--thickness")) == "0.015");
  CHECK(Shortest(ParseQuantity("1500E-2cm", kLength, "--thickness")) == "0.15");
  CHECK(Shortest(ParseQuantity("27.6MPa", kModulus, "--covering-modulus")) == "27600000");
  CHECK(Shortest(ParseQuantity("2.52J/cm2", kEnergyDensity, "--contusion-limit")) == "25200");
  CHECK(ParseQuantity("-0.7mm", kLength, "--thickness") == -0.0007);

  // Every thickness a user types in steps of 0.1 mm up to 100 mm reads as the nearest double
  // of its SI value, so it prints back as typed.
  for (int tenths = 1; tenths <= 1000; ++tenths) {
    const std::string mm = std::to_string(tenths / 10) + "." + std::to_string(tenths % 10);
    const std::string metres = mm + "e-3";
    CAPTURE(mm);
    CHECK(ParseQuantity(mm + "mm", kLength, "--thickness") == Decimal(metres));
  }
}

TEST_CASE("a bare number is SI and number formats follow from_chars", "[quantity]") {
  CHECK(ParseQuantity("10", kMass, "--robot-mass") == 10.0);
  CHECK(ParseQuantity("0.015", kLength, "--robot-radius") == 0.015);
  CHECK(ParseQuantity("2.76e7", kModulus, "--covering-modulus") == 2.76e7);
  CHECK(ParseQuantity("1E-3m", kLength, "--covering-thickness") == 1e-3);
  CHECK(ParseQuantity(".5", kRatio, "--robot-poisson") == 0.5);
  CHECK(ParseQuantity("+2m/s", kSpeed, "--speed") == 2.0);
  CHECK(ParseQuantity("+15mm", kLength, "--thickness") == 0.015);
  // Negative values are read; their range is the library's business.
  CHECK(ParseQuantity("-10kg", kMass, "--robot-mass") == -10.0);
}

TEST_CASE("a space between number and unit, and around the value, is allowed", "[quantity]") {
  CHECK(ParseQuantity("15 mm", kLength, "--covering-thickness") == 0.015);
  CHECK(ParseQuantity("  2 m/s ", kSpeed, "--speed") == 2.0);
  CHECK(ParseQuantity("27.6\tMPa", kModulus, "--covering-modulus") == 27.6e6);
}

TEST_CASE("fixed and flat are infinite, and only where the spec allows them", "[quantity]") {
  CHECK(ParseQuantity("fixed", kMass, "--head-mass") == covopt::kFixed);
  CHECK(ParseQuantity("Fixed", specs::kHeadMass, "--head-mass") == covopt::kFixed);
  CHECK(ParseQuantity("flat", specs::kRobotRadius, "--robot-radius") == covopt::kFlat);

  CHECK_THAT(ErrorFor("flat", specs::kHeadRadius, "--head-radius"),
             Contains("--head-radius") && Contains("'flat' is only allowed for the robot radius"));
  CHECK_THAT(ErrorFor("fixed", kSpeed, "--speed"),
             Contains("--speed") && Contains("'fixed' is only allowed for a mass"));
  CHECK_THAT(ErrorFor("flat", kMass, "--robot-mass"), Contains("--robot-mass"));
  CHECK_THAT(ErrorFor("fixed", kRadius, "--robot-radius"), Contains("--robot-radius"));
}

TEST_CASE("a unit of the wrong kind names the kind and lists the units that fit",
          "[quantity]") {
  CHECK(ErrorFor("2kg", kSpeed, "--speed") ==
        "--speed: unit 'kg' is not a speed; use m/s, mm/s, cm/s or km/h (got '2kg')");
  CHECK_THAT(ErrorFor("15m/s", kLength, "--covering-thickness"),
             Contains("unit 'm/s' is not a length") && Contains("m, cm, mm, um or µm"));
  CHECK_THAT(ErrorFor("10mm", kMass, "--robot-mass"),
             Contains("is not a mass") && Contains("kg, g or t"));
  CHECK_THAT(ErrorFor("27.6mm", kModulus, "--covering-modulus"),
             Contains("is not a modulus or pressure") &&
                 Contains("Pa, kPa, MPa, GPa, N/m2 or N/mm2"));
  CHECK(ErrorFor("50kg", kDensity, "--density") ==
        "--density: unit 'kg' is not a density; use kg/m3 or g/cm3 (got '50kg')");
  CHECK(ErrorFor("2.52MPa", kEnergyDensity, "--contusion-limit") ==
        "--contusion-limit: unit 'MPa' is not an energy density; use J/m2, J/cm2 or kJ/m2 "
        "(got '2.52MPa')");
  CHECK_THAT(ErrorFor("1J/m2", kModulus, "--laceration-limit"),
             Contains("is not a modulus or pressure"));
  CHECK_THAT(ErrorFor("50kg/m3", kModulus, "--modulus"), Contains("is not a modulus or pressure"));
  CHECK_THAT(ErrorFor("50KG/M3", kDensity, "--density"), Contains("did you mean 'kg/m3'?"));
  CHECK_THAT(ErrorFor("2.52j/cm2", kEnergyDensity, "--contusion-limit"),
             Contains("did you mean 'J/cm2'?"));
  CHECK_THAT(ErrorFor("0.3MPa", kRatio, "--robot-poisson"),
             Contains("--robot-poisson") && Contains("dimensionless") &&
                 Contains("plain number"));
}

TEST_CASE("an unknown unit is rejected, with a suggestion for a case slip", "[quantity]") {
  CHECK_THAT(ErrorFor("2 furlongs", kSpeed, "--speed"),
             Contains("--speed") && Contains("unknown unit 'furlongs'") &&
                 Contains("m/s, mm/s, cm/s or km/h") && Contains("(got '2 furlongs')"));
  CHECK_THAT(ErrorFor("27.6mpa", kModulus, "--covering-modulus"),
             Contains("did you mean 'MPa'?"));
  CHECK_THAT(ErrorFor("0.3 x", kRatio, "--skull-poisson"),
             Contains("--skull-poisson") && Contains("plain number"));
}

TEST_CASE("malformed numbers are rejected naming the flag and the value", "[quantity]") {
  for (const char* text : {"abc", "kg", "-", "1..5mm", "2,5m/s", "1.5.3", "0x10", "++2", "e5"}) {
    CAPTURE(text);
    const std::string message = ErrorFor(text, kLength, "--head-radius");
    CHECK_THAT(message, Contains("--head-radius") && Contains(std::string("'") + text + "'"));
  }
  CHECK_THAT(ErrorFor("2,5", kRatio), Contains("use '.' as the decimal separator"));
}

TEST_CASE("nan, inf and overflowing values are rejected as not finite", "[quantity]") {
  for (const char* text : {"nan", "NaN", "-nan", "inf", "-inf", "Infinity", "infm/s"}) {
    CAPTURE(text);
    CHECK_THAT(ErrorFor(text, kSpeed, "--speed"),
               Contains("--speed") && Contains("not a finite number"));
  }
  CHECK_THAT(ErrorFor("1e999", kSpeed, "--speed"), Contains("out of range"));
  // Finite as typed, infinite or zero in SI.
  CHECK_THAT(ErrorFor("1e300GPa", kModulus, "--skull-modulus"),
             Contains("--skull-modulus") && Contains("out of range"));
  CHECK_THAT(ErrorFor("1e-320um", kLength, "--thickness"), Contains("out of range"));
  CHECK_THAT(ErrorFor("1e99999999999999999999mm", kLength, "--thickness"),
             Contains("out of range"));
}

TEST_CASE("an empty value is rejected with an example", "[quantity]") {
  CHECK_THAT(ErrorFor("", kSpeed, "--speed"),
             Contains("--speed: empty value") && Contains("2m/s"));
  CHECK_THAT(ErrorFor("   ", kMass, "robot.mass"), Contains("robot.mass: empty value"));
  CHECK_THAT(ErrorFor("", kEnergyDensity, "--contusion-limit"), Contains("2.52J/cm2"));
}

TEST_CASE("formatted quantities read back to the same value", "[quantity]") {
  CHECK(FormatQuantity(10.0, QuantityKind::kMass) == "10 kg");
  CHECK(FormatQuantity(covopt::kFixed, QuantityKind::kMass) == "fixed");
  CHECK(FormatQuantity(covopt::kFlat, QuantityKind::kLength) == "flat");
  CHECK(FormatQuantity(0.015, QuantityKind::kLength) == "15 mm");
  CHECK(FormatQuantity(27.6e6, QuantityKind::kModulus) == "27.6 MPa");
  CHECK(FormatQuantity(70e9, QuantityKind::kModulus) == "70 GPa");
  CHECK(FormatQuantity(38.4, QuantityKind::kDensity) == "38.4 kg/m³");
  CHECK(FormatQuantity(25200.0, QuantityKind::kEnergyDensity) == "2.52 J/cm²");
  for (const auto& [value, spec] : {std::pair{4.5, kMass}, std::pair{0.003, kLength},
                                    std::pair{2.0, kSpeed}, std::pair{16.7e6, kModulus},
                                    std::pair{0.42, kRatio}, std::pair{covopt::kFlat, kRadius},
                                    std::pair{28.8, kDensity}, std::pair{25200.0, kEnergyDensity}}) {
    CHECK(ParseQuantity(FormatQuantity(value, spec.kind), spec, "x") == Approx(value));
  }
}

TEST_CASE("the classic unit slips in a bare number are refused with the likely unit",
          "[quantity][plausible]") {
  struct Slip {
    const char* text;
    const QuantitySpec* spec;
    const char* flag;
    const char* message;
  };
  const auto slip = GENERATE(values<Slip>({
      {"40", &specs::kRobotRadius, "--robot-radius",
       "--robot-radius 40: a bare number is in metres (40 m); write 40mm or 40m"},
      {"15", &specs::kCoveringThickness, "--covering-thickness",
       "--covering-thickness 15: a bare number is in metres (15 m); write 15mm or 15m"},
      {"15", &specs::kCoveringThickness, "--max-thickness",
       "--max-thickness 15: a bare number is in metres (15 m); write 15mm or 15m"},
      {"0.5", &specs::kThicknessStep, "--thickness-step",
       "--thickness-step 0.5: a bare number is in metres (0.5 m); write 0.5mm or 0.5m"},
      {"3", &specs::kScalpThickness, "--scalp-thickness",
       "--scalp-thickness 3: a bare number is in metres (3 m); write 3mm or 3m"},
      {"80", &specs::kHeadRadius, "--head-radius",
       "--head-radius 80: a bare number is in metres (80 m); write 80mm or 80m"},
      {"4500", &specs::kHeadMass, "--head-mass",
       "--head-mass 4500: a bare number is in kilograms (4500 kg); write 4500g or 4500kg"},
      {"10000", &specs::kRobotMass, "--robot-mass",
       "--robot-mass 10000: a bare number is in kilograms (10000 kg); write 10000g or 10000kg"},
      {"250", &specs::kSpeed, "--speed",
       "--speed 250: a bare number is in metres per second (250 m/s); write 250mm/s or 250m/s"},
      {"27.6", &specs::kCoveringModulus, "--covering-modulus",
       "--covering-modulus 27.6: a bare number is in pascals (27.6 Pa); write 27.6MPa or 27.6Pa"},
      {"16.7", &specs::kScalpModulus, "--scalp-modulus",
       "--scalp-modulus 16.7: a bare number is in pascals (16.7 Pa); write 16.7MPa or 16.7Pa"},
      {"70", &specs::kRobotModulus, "--robot-modulus",
       "--robot-modulus 70: a bare number is in pascals (70 Pa); write 70GPa or 70Pa"},
      {"6.5", &specs::kSkullModulus, "--skull-modulus",
       "--skull-modulus 6.5: a bare number is in pascals (6.5 Pa); write 6.5GPa or 6.5Pa"},
      // 6500 GPa is implausible too: the second likely unit.
      {"6500", &specs::kSkullModulus, "--skull-modulus",
       "--skull-modulus 6500: a bare number is in pascals (6500 Pa); write 6500MPa or 6500Pa"},
      {"1", &specs::kLacerationLimit, "--laceration-limit",
       "--laceration-limit 1: a bare number is in pascals (1 Pa); write 1MPa or 1Pa"},
      {"2.52", &specs::kContusionLimit, "--contusion-limit",
       "--contusion-limit 2.52: a bare number is in joules per square metre (2.52 J/m2); "
       "write 2.52J/cm2 or 2.52J/m2"},
      {"1.05", &specs::kMaterialDensity, "density_kg_per_m3",
       "density_kg_per_m3 1.05: a bare number is in kilograms per cubic metre (1.05 kg/m3); "
       "write 1.05g/cm3 or 1.05kg/m3"},
      {"27.6", &specs::kCoveringModulus, "--min-modulus",
       "--min-modulus 27.6: a bare number is in pascals (27.6 Pa); write 27.6MPa or 27.6Pa"},
  }));
  CAPTURE(slip.text, slip.flag);
  CHECK(ErrorFor(slip.text, *slip.spec, slip.flag) == slip.message);
  // Both suggested spellings are read as written: the likely unit is plausible, the SI unit
  // is the user's explicit intent (the model's ranges judge it then).
  const std::string message = slip.message;
  const std::size_t write = message.rfind("; write ");
  const std::size_t or_at = message.rfind(" or ");
  const std::string likely = message.substr(write + 8, or_at - write - 8);
  const std::string si = message.substr(or_at + 4);
  CHECK_NOTHROW(ParseQuantity(likely, *slip.spec, slip.flag));
  CHECK(ParseQuantity(si, *slip.spec, slip.flag) == Decimal(slip.text));
}

TEST_CASE("an explicit unit is taken as meant, however large", "[quantity][plausible]") {
  CHECK(ParseQuantity("40m", specs::kRobotRadius, "--robot-radius") == 40.0);
  CHECK(ParseQuantity("40mm", specs::kRobotRadius, "--robot-radius") == 0.04);
  CHECK(ParseQuantity("15m", specs::kCoveringThickness, "--covering-thickness") == 15.0);
  CHECK(ParseQuantity("27.6Pa", specs::kCoveringModulus, "--covering-modulus") == 27.6);
  CHECK(ParseQuantity("4500kg", specs::kHeadMass, "--head-mass") == 4500.0);
  CHECK(ParseQuantity("2.52J/m2", specs::kContusionLimit, "--contusion-limit") == 2.52);
}

TEST_CASE("zero, negative and non-finite bare numbers are left to the model's ranges",
          "[quantity][plausible]") {
  // 0 means "no covering" for a thickness; other zeros are the model's to refuse.
  CHECK(ParseQuantity("0", specs::kCoveringThickness, "--covering-thickness") == 0.0);
  CHECK(ParseQuantity("0", specs::kCoveringModulus, "--covering-modulus") == 0.0);
  CHECK(ParseQuantity("-40", specs::kRobotRadius, "--robot-radius") == -40.0);
  CHECK_NOTHROW(covopt::CheckBareNumber(std::nan(""), "nan", specs::kSpeed, "--speed"));
  CHECK_NOTHROW(covopt::CheckBareNumber(HUGE_VAL, "inf", specs::kSpeed, "--speed"));
}

TEST_CASE("a bare number with no plausible reading says the range and asks for a unit",
          "[quantity][plausible]") {
  CHECK(ErrorFor("2000", specs::kHeadRadius, "--head-radius") ==
        "--head-radius 2000: a bare number is in metres (2000 m), outside the plausible range "
        "for the head radius (0 mm to 500 mm); write it with a unit, e.g. mm, cm or m");
  CHECK_THAT(ErrorFor("1e20", specs::kCoveringModulus, "--max-modulus"),
             Contains("--max-modulus 1e20: a bare number is in pascals (1e+20 Pa), outside the "
                      "plausible range for the covering modulus (10 kPa to 1000 GPa)"));
}

TEST_CASE("a TOML number is checked the same way, with quoted suggestions",
          "[quantity][plausible]") {
  CHECK_THROWS_WITH(
      covopt::CheckBareNumber(40.0, "40", specs::kRobotRadius, "robot.radius", "\""),
      "robot.radius 40: a bare number is in metres (40 m); write \"40mm\" or \"40m\"");
  CHECK_NOTHROW(covopt::CheckBareNumber(0.04, "0.04", specs::kRobotRadius, "robot.radius", "\""));
}

TEST_CASE("every realistic bare value passes its named spec", "[quantity][plausible]") {
  struct Realistic {
    const QuantitySpec* spec;
    std::vector<double> values;  // SI
  };
  const covopt::Scene paper;
  const covopt::InjuryLimits limits;
  const std::vector<Realistic> cases = {
      // The paper's scene (the defaults), then the range of robots and heads covopt is for.
      {&specs::kRobotMass, {paper.robot.mass_kg, 0.5, 2.0, 35.0, 250.0}},
      {&specs::kHeadMass, {paper.head.mass_kg, 1.0, 5.5, 40.0}},
      {&specs::kSpeed, {paper.robot.speed_m_per_s, 1e-6, 0.05, 0.25, 4.0, 10.0}},
      {&specs::kRobotRadius, {paper.robot.radius_m, 0.001, 0.005, 0.05, 0.3}},
      {&specs::kHeadRadius, {paper.head.radius_m, 0.06, 0.12, 0.2}},
      {&specs::kCoveringThickness, {paper.covering.thickness_m, 0.0, 0.0001, 0.005, 0.05, 0.1}},
      {&specs::kScalpThickness, {paper.scalp.thickness_m, 0.002, 0.008}},
      {&specs::kThicknessStep, {0.0005, 0.0001, 0.001, 0.005}},
      {&specs::kRobotModulus, {paper.robot.youngs_modulus_Pa, 1e6, 2.5e9, 210e9}},
      {&specs::kCoveringModulus, {paper.covering.youngs_modulus_Pa, 20e3, 96.2e3, 1e6, 3.3e9, 70e9}},
      {&specs::kScalpModulus, {paper.scalp.youngs_modulus_Pa, 1e5, 1e6, 100e6}},
      {&specs::kSkullModulus, {paper.skull.youngs_modulus_Pa, 1e9, 15e9}},
      {&specs::kMaterialDensity, {11.2, 50.0, 328.0, 1200.0, 7850.0}},
      {&specs::kLacerationLimit, {limits.laceration_tensile_stress_Pa, 0.5e6, 20e6}},
      {&specs::kContusionLimit, {limits.contusion_energy_density_J_per_m2, 1e4, 1e5}},
  };
  for (const Realistic& c : cases) {
    for (const double value : c.values) {
      CAPTURE(c.spec->what, value);
      CHECK_NOTHROW(covopt::CheckBareNumber(value, Shortest(value), *c.spec, "x"));
      CHECK(ParseQuantity(Shortest(value), *c.spec, "x") == value);
    }
  }
}

TEST_CASE("the named specs are consistent", "[quantity][plausible]") {
  for (const QuantitySpec* spec : specs::kWithPlausibleRange) {
    CAPTURE(spec->what);
    CHECK(spec->has_plausible_range());
    CHECK(spec->plausible_min < spec->plausible_max);
    CHECK_FALSE(spec->what.empty());
    CHECK_FALSE(spec->likely_units[0].empty());
    for (const std::string_view unit : spec->likely_units) {
      if (unit.empty()) continue;
      // A likely unit is a unit of the spec's kind, and the SI unit is not among them.
      std::string one = "1";
      one += unit;
      CHECK(ErrorFor(one, QuantitySpec{spec->kind}) == "");
      CHECK(unit != covopt::SiUnit(spec->kind));
    }
  }
  for (const QuantitySpec* spec : {&specs::kPoissonRatio, &specs::kSafetyFactor, &specs::kTolerance}) {
    CHECK_FALSE(spec->has_plausible_range());
  }
  CHECK_FALSE(QuantitySpec{QuantityKind::kLength}.has_plausible_range());
  CHECK(specs::kRobotRadius.allow_flat);
  CHECK(specs::kRobotMass.allow_fixed);
  CHECK(specs::kHeadMass.allow_fixed);
}

TEST_CASE("the energy density kind describes itself", "[quantity]") {
  CHECK(covopt::Describe(QuantityKind::kEnergyDensity) == "an energy density");
  CHECK(covopt::UnitList(QuantityKind::kEnergyDensity) == "J/m2, J/cm2 or kJ/m2");
  CHECK(covopt::SiUnit(QuantityKind::kEnergyDensity) == "J/m2");
}

TEST_CASE("a 100,000-character value is echoed short in the message", "[quantity]") {
  // Issue 22: the whole value was echoed, a 100 kB error line.
  const QuantitySpec mass{QuantityKind::kMass};
  for (const std::string& text : {std::string(100000, '7'), "1" + std::string(99999, '0') + "kg",
                                  "5" + std::string(100000, 'q'), "5kg" + std::string(100000, 'x'),
                                  "3.7kg-" + std::string(100000, '5') + "kg"}) {
    CAPTURE(text.substr(0, 20));
    try {
      ParseQuantity(text, mass, "robot.mass");
      FAIL("accepted");
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      CHECK(message.size() < 300);
      CHECK_THAT(message, Contains("robot.mass"));
      CHECK_THAT(message, Contains("characters)"));
      CHECK_THAT(message, Contains(text.substr(0, 20)));
    }
  }
  // A short value is still echoed whole.
  try {
    ParseQuantity("12 parsecs", mass, "robot.mass");
    FAIL("accepted");
  } catch (const std::invalid_argument& e) {
    CHECK_THAT(std::string(e.what()), Contains("(got '12 parsecs')"));
  }
}
