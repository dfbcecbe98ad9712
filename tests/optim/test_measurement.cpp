// What a biofidelic measuring device reads (core/measuring_device.hpp) beside the body model
// (optim/measurement.hpp): the reading against an independent closed form (an energy balance
// solved by bisection here), the spring-only limit of a stiff pad, the trends (a softer pad
// reads less, a heavier robot more, the fixed device more than a recoiling region), the
// presets, and the refusals.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include <catch2/catch.hpp>

#include <covopt/core/measuring_device.hpp>
#include <covopt/materials/body_regions.hpp>
#include <covopt/optim/measurement.hpp>

namespace {

using covopt::BodyContactScene;
using covopt::ContactType;
using covopt::MeasuringDevice;
using covopt::materials::BodyRegionTable;

BodyContactScene Robot(double mass_kg = 10.0, double speed_m_per_s = 0.25, double radius_m = 0.05) {
  BodyContactScene s;
  s.robot_mass_kg = mass_kg;
  s.speed_m_per_s = speed_m_per_s;
  s.robot_radius_m = radius_m;
  s.covering.thickness_m = 0.0;
  return s;
}

MeasuringDevice Device(double spring_N_per_mm, double shore_a, double thickness_m = 0.007) {
  return MeasuringDevice{.spring_N_per_m = spring_N_per_mm * 1e3,
                         .pad_shore_a = shore_a,
                         .pad_thickness_m = thickness_m,
                         .pad_thickness_assumed = false,
                         .name = "custom"};
}

/// The closed form, written out here: a Hertz sphere of radius R on the pad (and the covering)
/// in series with the spring k, mass m at speed v on a fixed base:
///   m v²/2 = F²/(2k) + 2/5 K^(-2/3) F^(5/3),  K = 4/3 E* sqrt(R),
/// solved by bisection on F in [0, v sqrt(m k)] (the spring alone bounds it).
struct ClosedForm {
  double force_N;
  double pressure_Pa;
};
ClosedForm Independent(double m, double v, double k, double R, double effective_modulus) {
  const double K = 4.0 / 3.0 * effective_modulus * std::sqrt(R);
  const double energy = 0.5 * m * v * v;
  auto stored = [&](double F) { return F * F / (2.0 * k) + 0.4 * std::pow(F / K, 2.0 / 3.0) * F; };
  double lo = 0.0, hi = v * std::sqrt(m * k);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (stored(mid) < energy ? lo : hi) = mid;
  }
  const double F = 0.5 * (lo + hi);
  const double a2 = R * std::pow(F / K, 2.0 / 3.0);
  return {F, 3.0 * F / (2.0 * std::numbers::pi * a2)};
}

double PadStarModulus(double shore_a) {
  const double E = 1e6 * std::pow(10.0, 0.0235 * shore_a - 0.6403);  // Ruess
  return E / (1.0 - 0.49 * 0.49);
}

}  // namespace

TEST_CASE("a bare robot on spring and pad reads the closed form of the energy balance", "[measure]") {
  // The pairs in use (N/mm + Shore A).
  for (const auto& [k, shore] : {std::pair{10.0, 10.0}, {25.0, 70.0}, {35.0, 30.0}, {60.0, 30.0}, {75.0, 70.0}}) {
    {
      const covopt::DeviceReading r = covopt::PredictDeviceReading(Robot(), Device(k, shore));
      const ClosedForm expected = Independent(10.0, 0.25, k * 1e3, 0.05, PadStarModulus(shore));
      INFO("shore " << shore << ", k " << k);
      REQUIRE_FALSE(r.contact.fully_compressed);
      CHECK(r.contact.peak_force_N == Approx(expected.force_N).epsilon(1e-9));
      REQUIRE(r.contact.peak_pressure_Pa);
      CHECK(*r.contact.peak_pressure_Pa == Approx(expected.pressure_Pa).epsilon(1e-8));
      CHECK(r.contact.reduced_mass_kg == 10.0);  // the device is fixed: mu = m_R
      CHECK(r.pad.share == 1.0);
      CHECK_FALSE(r.covering);
    }
  }
}

TEST_CASE("a covered robot on the pad: the two layers are one Hertz contact on the outer radius", "[measure]") {
  BodyContactScene robot = Robot(8.0, 0.4, 0.04);
  robot.covering = {.youngs_modulus_Pa = 2e6, .poisson_ratio = 0.3, .thickness_m = 0.01,
                    .compressive_curve = nullptr, .law = covopt::CoveringLaw::kAuto};
  const covopt::DeviceReading r = covopt::PredictDeviceReading(robot, Device(25.0, 70.0));
  const double cov = (1.0 - 0.3 * 0.3) / 2e6, pad = 1.0 / PadStarModulus(70.0);
  const ClosedForm expected = Independent(8.0, 0.4, 25e3, 0.05, 1.0 / (cov + pad));
  REQUIRE_FALSE(r.contact.fully_compressed);
  CHECK(r.contact.peak_force_N == Approx(expected.force_N).epsilon(1e-9));
  CHECK(*r.contact.peak_pressure_Pa == Approx(expected.pressure_Pa).epsilon(1e-8));
  REQUIRE(r.covering);
  // Each layer takes its compliance's share of the approach; together the whole of it.
  CHECK(r.pad.share + r.covering->share == Approx(1.0));
  CHECK(r.covering->share == Approx(cov / (cov + pad)));
  CHECK(r.pad.deflection_m + r.covering->deflection_m == Approx(r.contact.covering_deflection_m));
  // The soft covering takes most of it: the pad barely deflects.
  CHECK(r.covering->deflection_m > 5.0 * r.pad.deflection_m);
}

TEST_CASE("a stiff pad reads the spring alone: F = v sqrt(m k)", "[measure]") {
  const double spring_only = 0.25 * std::sqrt(10.0 * 25e3);
  double previous = 0.0;
  for (const double shore : {10.0, 30.0, 50.0, 70.0, 90.0, 100.0}) {
    const double F = covopt::PredictDeviceReading(Robot(10.0, 0.25, 0.2), Device(25.0, shore)).contact.peak_force_N;
    CHECK(F > previous);  // a softer pad reads less
    CHECK(F < spring_only);
    previous = F;
  }
  CHECK(previous == Approx(spring_only).epsilon(0.05));
}

TEST_CASE("a heavier or faster robot reads more on the device", "[measure]") {
  const MeasuringDevice d = Device(25.0, 70.0);
  const double base = covopt::PredictDeviceReading(Robot(10.0, 0.25), d).contact.peak_force_N;
  CHECK(covopt::PredictDeviceReading(Robot(20.0, 0.25), d).contact.peak_force_N > base);
  CHECK(covopt::PredictDeviceReading(Robot(10.0, 0.35), d).contact.peak_force_N > base);
}

TEST_CASE("the fixed device reads more than the recoiling region at equal stiffness", "[measure]") {
  const auto limits = BodyRegionTable::BuiltIn().Limits("chest", "", ContactType::kTransient);
  // A stiff pad: the device is the region's spring with mu = m_R > m_R m_H/(m_R + m_H).
  const covopt::optim::MeasurementPrediction p =
      covopt::optim::PredictMeasurement(Robot(10.0, 0.25, 0.2), limits, Device(25.0, 100.0, 0.002));
  const double mu_body = 10.0 * 40.0 / 50.0;
  CHECK(p.body.contact.reduced_mass_kg == Approx(mu_body));
  CHECK(p.body.contact.peak_force_N == Approx(0.25 * std::sqrt(mu_body * 25e3)));
  CHECK(p.force_ratio > 1.0);
  CHECK(p.force_difference_N == Approx(p.device.contact.peak_force_N - p.body.contact.peak_force_N));
  CHECK(p.device_force_ratio == Approx(p.device.contact.peak_force_N / limits.force_N));
  CHECK(p.device_verdict.Find("force") != nullptr);
  // The preset for the region has its spring: no warning about the spring.
  const covopt::optim::MeasurementPrediction preset =
      covopt::optim::PredictMeasurement(Robot(), limits, covopt::DeviceNamed("chest", 0.007));
  for (const std::string& w : preset.warnings) CHECK(w.find("spring") == std::string::npos);
  const covopt::optim::MeasurementPrediction other =
      covopt::optim::PredictMeasurement(Robot(), limits, covopt::DeviceNamed("75+70", 0.007));
  REQUIRE_FALSE(other.warnings.empty());
  CHECK(other.warnings.back().find("not the region's k_H") != std::string::npos);
  const covopt::ResultSummary s = covopt::optim::SummarizeMeasurement(Robot(), "", preset);
  CHECK(s.targets.size() == 2);
  CHECK(s.command == "measure");
}

TEST_CASE("device presets: the pairs and the regions they stand for", "[measure]") {
  CHECK(covopt::DevicePresets().size() == 8);
  const MeasuringDevice chest = covopt::DeviceNamed("chest");
  CHECK(chest.name == "25+70");
  CHECK(chest.spring_N_per_m == 25e3);
  CHECK(chest.pad_shore_a == 70.0);
  CHECK(chest.pad_thickness_assumed);
  CHECK(covopt::DeviceNamed("10+10", 0.005).pad_thickness_m == 0.005);
  CHECK_FALSE(covopt::DeviceNamed("10+10", 0.005).pad_thickness_assumed);
  CHECK(covopt::DeviceNamed("Hands_Fingers").name == "75+70");
  CHECK_THROWS_WITH(covopt::DeviceNamed("elbow"), Catch::Contains("device: unknown preset 'elbow'") &&
                                                     Catch::Contains("25+70"));
  CHECK(covopt::DevicePresetForRegion("pelvis") == nullptr);
  // Warnings: the assumed thickness, and a hardness outside the correlation's Shore A 30-60.
  const covopt::DeviceReading r = covopt::PredictDeviceReading(Robot(), chest);
  CHECK(r.warnings.size() >= 2);
  CHECK(r.warnings[0].find("outside the Ruess correlation's range") != std::string::npos);
  CHECK(r.warnings[1].find("7 mm assumed") != std::string::npos);
  CHECK(covopt::PredictDeviceReading(Robot(), Device(35.0, 30.0)).warnings.empty() ==
        covopt::PredictDeviceReading(Robot(), Device(35.0, 30.0)).validity.within);
}

TEST_CASE("the device a command names: a preset, a spring with a pad, or the region's pair", "[measure]") {
  using covopt::DeviceChoice;
  const MeasuringDevice own = covopt::ResolveDevice({}, "lower-legs");
  CHECK((own.name == "60+30" && own.spring_N_per_m == 60e3 && own.pad_shore_a == 30.0));
  const MeasuringDevice pad = covopt::ResolveDevice(
      {.preset = std::nullopt, .spring_N_per_m = 25e3, .pad = "70 Shore A,5mm", .pad_thickness_m = std::nullopt}, "chest");
  CHECK((pad.pad_shore_a == 70.0 && pad.pad_thickness_m == Approx(0.005) && !pad.pad_thickness_assumed));
  CHECK(covopt::ResolveDevice({.preset = std::nullopt, .spring_N_per_m = 25e3, .pad = "30ShA", .pad_thickness_m = std::nullopt},
                              "chest").pad_thickness_assumed);
  const MeasuringDevice thin = covopt::ResolveDevice(
      {.preset = "25+70", .spring_N_per_m = std::nullopt, .pad = std::nullopt, .pad_thickness_m = 0.004}, "face");
  CHECK(thin.pad_thickness_m == 0.004);
  auto refused = [](const DeviceChoice& c, const char* named) {
    INFO(named);
    CHECK_THROWS_WITH(covopt::ResolveDevice(c, "chest"), Catch::Contains(named));
  };
  refused({.preset = std::nullopt, .spring_N_per_m = 25e3, .pad = "170ShA", .pad_thickness_m = std::nullopt}, "device_pad: the hardness");
  refused({.preset = std::nullopt, .spring_N_per_m = 25e3, .pad = "hard", .pad_thickness_m = std::nullopt}, "device_pad: the hardness");
  refused({.preset = std::nullopt, .spring_N_per_m = 25e3, .pad = "70ShA,0mm", .pad_thickness_m = std::nullopt}, "device_pad's thickness");
  refused({.preset = std::nullopt, .spring_N_per_m = 25e3, .pad = "70ShA,7kg", .pad_thickness_m = std::nullopt}, "device_pad");
  refused({.preset = std::nullopt, .spring_N_per_m = 25e3, .pad = std::nullopt, .pad_thickness_m = std::nullopt}, "device_pad: device_spring and device_pad go together");
  refused({.preset = "25+70", .spring_N_per_m = 25e3, .pad = std::nullopt, .pad_thickness_m = std::nullopt}, "not both");
  refused({.preset = std::nullopt, .spring_N_per_m = -1.0, .pad = "70", .pad_thickness_m = std::nullopt}, "device_spring");
  CHECK_THROWS_WITH(covopt::ResolveDevice({}, "pelvis"), Catch::Contains("device: no spring and pad pair stands for pelvis"));
}

TEST_CASE("the Shore A modulus is the catalog's Ruess correlation", "[measure]") {
  // The catalog stores elastomer Shore A30 at 1.161 MPa and A60 at 5.884 MPa.
  CHECK(covopt::ShoreAModulus_Pa(30.0) == Approx(1.161e6).epsilon(1e-3));
  CHECK(covopt::ShoreAModulus_Pa(60.0) == Approx(5.884e6).epsilon(1e-3));
  CHECK_THROWS_WITH(covopt::ShoreAModulus_Pa(101.0), Catch::Contains("device_pad"));
}

TEST_CASE("bad devices and robots are refused naming the field", "[measure]") {
  CHECK_THROWS_WITH(covopt::PredictDeviceReading(Robot(), Device(0.0, 70.0)), Catch::Contains("device_spring"));
  CHECK_THROWS_WITH(covopt::PredictDeviceReading(Robot(), Device(-5.0, 70.0)), Catch::Contains("device_spring"));
  CHECK_THROWS_WITH(covopt::PredictDeviceReading(Robot(), Device(25.0, -1.0)), Catch::Contains("device_pad"));
  CHECK_THROWS_WITH(covopt::PredictDeviceReading(Robot(), Device(25.0, NAN)), Catch::Contains("device_pad"));
  CHECK_THROWS_WITH(covopt::PredictDeviceReading(Robot(), Device(25.0, 70.0, 0.0)),
                    Catch::Contains("device_pad_thickness"));
  CHECK_THROWS_WITH(covopt::PredictDeviceReading(Robot(), Device(25.0, 70.0, 0.5)),
                    Catch::Contains("device_pad_thickness"));
  CHECK_THROWS_WITH(covopt::PredictDeviceReading(Robot(covopt::kFixed), Device(25.0, 70.0)),
                    Catch::Contains("robot.mass"));
  CHECK_THROWS_WITH(covopt::PredictDeviceReading(Robot(10.0, 0.25, covopt::kFlat), Device(25.0, 70.0)),
                    Catch::Contains("robot.radius"));
  // A robot edge far smaller than the pad's travel.
  CHECK_THROWS_WITH(covopt::PredictDeviceReading(Robot(10.0, 0.25, 0.001), Device(10.0, 10.0, 0.05)),
                    Catch::Contains("robot.radius"));
}
