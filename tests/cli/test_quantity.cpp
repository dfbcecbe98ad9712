// The quantity parser reads what users type for a value ("10kg", "15 mm", "27.6MPa",
// "fixed") into SI. These tests check every unit of every kind, the optional space, the
// words fixed/flat only where they are allowed, and that every bad value (wrong unit,
// malformed number, nan/inf, overflow, empty) is rejected with a message that names the
// flag, shows the value, and for a wrong unit lists the units that fit.

#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include "covopt/core/scene.hpp"
#include "errors.hpp"
#include "quantity.hpp"

using covopt::cli::FormatQuantity;
using covopt::cli::InputError;
using covopt::cli::ParseQuantity;
using covopt::cli::QuantityKind;
using covopt::cli::QuantitySpec;
using Catch::Matchers::Contains;

namespace {

constexpr QuantitySpec kMass{QuantityKind::kMass, true, false};
constexpr QuantitySpec kLength{QuantityKind::kLength};
constexpr QuantitySpec kRadius{QuantityKind::kLength, false, true};
constexpr QuantitySpec kSpeed{QuantityKind::kSpeed};
constexpr QuantitySpec kModulus{QuantityKind::kModulus};
constexpr QuantitySpec kRatio{QuantityKind::kDimensionless};
constexpr QuantitySpec kDensity{QuantityKind::kDensity};

/// The message ParseQuantity throws for `text`, or "" if it accepts it.
std::string ErrorFor(const std::string& text, const QuantitySpec& spec,
                     const std::string& name = "--value") {
  try {
    ParseQuantity(text, spec, name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("every unit of every kind converts to SI", "[quantity]") {
  struct Case {
    const char* text;
    QuantitySpec spec;
    double si;
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
      {"7.2km/h", kSpeed, 2.0},
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
      {"0.3", kRatio, 0.3},
  }));
  CAPTURE(c.text);
  CHECK(ParseQuantity(c.text, c.spec, "--value") == Approx(c.si).epsilon(1e-14));
}

TEST_CASE("a bare number is SI and number formats follow from_chars", "[quantity]") {
  CHECK(ParseQuantity("10", kMass, "--robot-mass") == 10.0);
  CHECK(ParseQuantity("0.015", kLength, "--robot-radius") == 0.015);
  CHECK(ParseQuantity("2.76e7", kModulus, "--covering-modulus") == 2.76e7);
  CHECK(ParseQuantity("1E-3m", kLength, "--covering-thickness") == Approx(1e-3));
  CHECK(ParseQuantity(".5", kRatio, "--robot-poisson") == 0.5);
  CHECK(ParseQuantity("+2m/s", kSpeed, "--speed") == 2.0);
  // Negative values are read; their range is the library's business.
  CHECK(ParseQuantity("-10kg", kMass, "--robot-mass") == -10.0);
}

TEST_CASE("a space between number and unit, and around the value, is allowed", "[quantity]") {
  CHECK(ParseQuantity("15 mm", kLength, "--covering-thickness") == Approx(0.015));
  CHECK(ParseQuantity("  2 m/s ", kSpeed, "--speed") == 2.0);
  CHECK(ParseQuantity("27.6\tMPa", kModulus, "--covering-modulus") == Approx(27.6e6));
}

TEST_CASE("fixed and flat are infinite, and only where the spec allows them", "[quantity]") {
  CHECK(ParseQuantity("fixed", kMass, "--head-mass") == covopt::kFixed);
  CHECK(ParseQuantity("Fixed", kMass, "--head-mass") == covopt::kFixed);
  CHECK(ParseQuantity("flat", kRadius, "--robot-radius") == covopt::kFlat);

  CHECK_THAT(ErrorFor("flat", kLength, "--head-radius"),
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
  CHECK_THAT(ErrorFor("50kg/m3", kModulus, "--modulus"), Contains("is not a modulus or pressure"));
  CHECK_THAT(ErrorFor("50KG/M3", kDensity, "--density"), Contains("did you mean 'kg/m3'?"));
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
  // Finite as typed, infinite in SI.
  CHECK_THAT(ErrorFor("1e300GPa", kModulus, "--skull-modulus"),
             Contains("--skull-modulus") && Contains("out of range"));
}

TEST_CASE("an empty value is rejected with an example", "[quantity]") {
  CHECK_THAT(ErrorFor("", kSpeed, "--speed"),
             Contains("--speed: empty value") && Contains("2m/s"));
  CHECK_THAT(ErrorFor("   ", kMass, "robot.mass"), Contains("robot.mass: empty value"));
}

TEST_CASE("formatted quantities read back to the same value", "[quantity]") {
  CHECK(FormatQuantity(10.0, QuantityKind::kMass) == "10 kg");
  CHECK(FormatQuantity(covopt::kFixed, QuantityKind::kMass) == "fixed");
  CHECK(FormatQuantity(covopt::kFlat, QuantityKind::kLength) == "flat");
  CHECK(FormatQuantity(0.015, QuantityKind::kLength) == "15 mm");
  CHECK(FormatQuantity(27.6e6, QuantityKind::kModulus) == "27.6 MPa");
  CHECK(FormatQuantity(70e9, QuantityKind::kModulus) == "70 GPa");
  CHECK(FormatQuantity(38.4, QuantityKind::kDensity) == "38.4 kg/m³");
  for (const auto& [value, spec] : {std::pair{4.5, kMass}, std::pair{0.003, kLength},
                                    std::pair{2.0, kSpeed}, std::pair{16.7e6, kModulus},
                                    std::pair{0.42, kRatio}, std::pair{covopt::kFlat, kRadius},
                                    std::pair{28.8, kDensity}}) {
    CHECK(ParseQuantity(FormatQuantity(value, spec.kind), spec, "x") == Approx(value));
  }
}
