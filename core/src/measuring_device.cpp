// The reading of a biofidelic force-measuring device (docs/model.md §13.11): the robot's
// covering and the device's pad as one Hertz contact on the device's spring, answered by the
// body-region model's energy balance.
#include "covopt/core/measuring_device.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

#include "body_contact_time_path.hpp"
#include "covopt/core/number_format.hpp"
#include "covopt/core/physical_floors.hpp"
#include "range_check.hpp"

namespace covopt {

namespace {

constexpr double kMaxSpring_N_per_m = 1e9;
constexpr double kMaxPadThickness_m = 0.1;

constexpr std::array<std::string_view, 1> kAbdomen{"abdomen"};
constexpr std::array<std::string_view, 1> kChest{"chest"};
constexpr std::array<std::string_view, 1> kUpperArms{"upper-arms-elbows"};
constexpr std::array<std::string_view, 1> kBack{"back-shoulders"};
constexpr std::array<std::string_view, 1> kLowerArms{"lower-arms-wrists"};
constexpr std::array<std::string_view, 1> kThighs{"thighs-knees"};
constexpr std::array<std::string_view, 1> kLowerLegs{"lower-legs"};
constexpr std::array<std::string_view, 1> kHands{"hands-fingers"};

// The pairs of DGUV FB HM-080 (2017) with the region each is used for, as a public
// implementation of that procedure assigns them (github.com/AllenLin0806/ISO15066,
// frm_Report.cs / PublicEnum.cs); the spring is the region's k_H of ISO/TS 15066 Table A.3.
constexpr std::array<DevicePreset, 8> kPresets{{
    {"10+10", 10.0, 10.0, "green", kAbdomen},
    {"25+70", 25.0, 70.0, "red", kChest},
    {"30+30", 30.0, 30.0, "blue", kUpperArms},
    {"35+30", 35.0, 30.0, "blue", kBack},
    {"40+70", 40.0, 70.0, "red", kLowerArms},
    {"50+30", 50.0, 30.0, "blue", kThighs},
    {"60+30", 60.0, 30.0, "blue", kLowerLegs},
    {"75+70", 75.0, 70.0, "red", kHands},
}};

std::string Normalised(std::string_view text) {
  std::string out;
  for (const char c : text) {
    const char lower = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    out.push_back(lower == '_' || lower == ' ' || lower == '/' ? '-' : lower);
  }
  return out;
}

void CheckDevice(const MeasuringDevice& d) {
  internal::CheckPositive("device_spring", d.spring_N_per_m, kMaxSpring_N_per_m, "N/m");
  internal::CheckInRange("device_pad", d.pad_shore_a, 0.0, 100.0, "Shore A");
  internal::CheckInRange("device_pad_thickness", d.pad_thickness_m, kMinLayerThickness_m, kMaxPadThickness_m, "m");
}

/// The layer's limits under the Hertz law, with its own name in the note.
DeviceLayer Layer(std::string_view name, double modulus_Pa, double poisson, double thickness_m, double share,
                  double approach_m, double contact_radius_m, bool binding_stop, double fraction) {
  DeviceLayer l{.modulus_Pa = modulus_Pa, .poisson_ratio = poisson, .thickness_m = thickness_m, .share = share,
                .deflection_m = binding_stop ? fraction * thickness_m : share * approach_m, .strain = 0.0,
                .bottomed_out = binding_stop, .validity = {}};
  l.strain = l.deflection_m / thickness_m;
  l.validity.note = std::string(name) + ": Hertz law";
  ApplyHertzCoveringLimits({.poisson_ratio = poisson,
                            .thickness_m = thickness_m,
                            .strain = l.strain,
                            .contact_radius_m = contact_radius_m,
                            .travel_ratio = l.deflection_m / (fraction * thickness_m),
                            .fully_compressed = binding_stop},
                           l.validity);
  if (binding_stop) l.validity.note += "; bottomed out: past 0.8 of its thickness a rigid stop";
  return l;
}

/// "70ShA", "70 Shore A", "70": the Shore A hardness of a pad.
double ParseShoreA(std::string_view text) {
  std::string t = Normalised(text);
  for (const std::string_view unit : {"-shore-a", "shore-a", "shorea", "sha", "a"}) {
    if (t.size() > unit.size() && t.ends_with(unit)) {
      t.resize(t.size() - unit.size());
      break;
    }
  }
  while (!t.empty() && t.back() == '-') t.pop_back();  // a space before the unit
  double value = 0.0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (t.empty() || ec != std::errc() || end != t.data() + t.size() || !(value >= 0.0 && value <= 100.0)) {
    throw std::invalid_argument("device_pad: the hardness must be a Shore A number in [0, 100], e.g. 70ShA (got '" +
                                std::string(text) + "')");
  }
  return value;
}

}  // namespace

MeasuringDevice ResolveDevice(const DeviceChoice& c, std::string_view region) {
  if (c.preset && (c.spring_N_per_m || c.pad)) {
    throw std::invalid_argument("device: give a preset, or device_spring and device_pad, not both");
  }
  if (c.pad_thickness_m && !c.preset && (c.spring_N_per_m || c.pad)) {
    throw std::invalid_argument("device_pad_thickness goes with a preset; give the pad's thickness in device_pad "
                                "(HARDNESS,THICKNESS, e.g. 70ShA,7mm)");
  }
  if (!c.spring_N_per_m && !c.pad) {
    if (!c.preset && DevicePresetForRegion(region) == nullptr) {
      throw std::invalid_argument("device: no spring and pad pair stands for " + std::string(region) +
                                  "; give device (a pair, e.g. 25+70) or device_spring and device_pad");
    }
    return DeviceNamed(c.preset.value_or(std::string(region)), c.pad_thickness_m);
  }
  if (!c.spring_N_per_m || !c.pad) {
    throw std::invalid_argument(std::string(c.pad ? "device_spring" : "device_pad") +
                                ": device_spring and device_pad go together (e.g. 25N/mm and 70ShA,7mm)");
  }
  MeasuringDevice d;
  d.spring_N_per_m = *c.spring_N_per_m;
  const std::string_view pad = *c.pad;
  const std::size_t comma = pad.find(',');
  d.pad_shore_a = ParseShoreA(pad.substr(0, comma));
  d.pad_thickness_assumed = comma == std::string_view::npos;
  if (!d.pad_thickness_assumed) {
    d.pad_thickness_m = ParseQuantity(pad.substr(comma + 1), kPadThicknessSpec, "device_pad");
    internal::CheckInRange("device_pad's thickness", d.pad_thickness_m, kMinLayerThickness_m, kMaxPadThickness_m, "m");
  }
  CheckDevice(d);
  return d;
}

double ShoreAModulus_Pa(double shore_a) {
  internal::CheckInRange("device_pad", shore_a, 0.0, 100.0, "Shore A");
  return 1e6 * std::pow(10.0, 0.0235 * shore_a - 0.6403);
}

std::span<const DevicePreset> DevicePresets() noexcept { return kPresets; }

const DevicePreset* DevicePresetForRegion(std::string_view region) noexcept {
  const std::string key = Normalised(region);
  for (const DevicePreset& p : kPresets) {
    if (std::find(p.regions.begin(), p.regions.end(), key) != p.regions.end()) return &p;
  }
  return nullptr;
}

MeasuringDevice DeviceNamed(std::string_view name, std::optional<double> pad_thickness_m) {
  const std::string key = Normalised(name);
  const DevicePreset* preset = DevicePresetForRegion(key);
  for (const DevicePreset& p : kPresets) {
    if (p.name == key) preset = &p;
  }
  if (preset == nullptr) {
    std::string pairs, regions;
    for (const DevicePreset& p : kPresets) {
      pairs += (pairs.empty() ? "" : ", ") + std::string(p.name);
      for (const std::string_view r : p.regions) regions += (regions.empty() ? "" : ", ") + std::string(r);
    }
    throw std::invalid_argument("device: unknown preset '" + std::string(name) + "' (pairs N/mm+ShoreA: " + pairs +
                                "; or a region: " + regions + ")");
  }
  MeasuringDevice d{.spring_N_per_m = preset->spring_N_per_mm * 1e3,
                    .pad_shore_a = preset->pad_shore_a,
                    .pad_thickness_m = pad_thickness_m.value_or(kDefaultPadThickness_m),
                    .pad_thickness_assumed = !pad_thickness_m,
                    .name = std::string(preset->name)};
  CheckDevice(d);
  return d;
}

DeviceReading PredictDeviceReading(const BodyContactScene& robot, const MeasuringDevice& device,
                                   const SolveOptions& options) {
  CheckDevice(device);
  if (std::isinf(robot.robot_mass_kg)) {
    throw std::invalid_argument(
        "robot.mass: the device is fixed, so the robot must move, in [0.001, 1e+06] kg (got fixed)");
  }
  if (std::isinf(robot.robot_radius_m)) {
    throw std::invalid_argument(
        "robot.radius: the device's pad meets the robot in a Hertz contact, which needs the radius of the robot's "
        "surface, in [0.0001, 100] m (got a flat robot)");
  }
  const bool covered = robot.has_covering();
  if (covered && internal::ResolveCoveringLaw(robot.covering) == CoveringLaw::kFoam) {
    throw std::invalid_argument(
        "covering.law: the device prediction takes a Hertz covering; a foam covering's measured curve in series with "
        "the device's pad is not modelled (give --covering-law hertz)");
  }
  // Validates the robot's own fields (mass, speed, radius, covering, reaction) as a body contact.
  (void)BodyContactModel::FromScene(robot);

  DeviceReading reading;
  reading.device = device;
  const double pad_modulus = ShoreAModulus_Pa(device.pad_shore_a);
  const double nu_p = kDevicePadPoissonRatio;
  const double pad_compliance = (1.0 - nu_p * nu_p) / pad_modulus;
  const double cov_compliance =
      covered ? (1.0 - robot.covering.poisson_ratio * robot.covering.poisson_ratio) / robot.covering.youngs_modulus_Pa
              : 0.0;
  const double effective_modulus = 1.0 / (pad_compliance + cov_compliance);  // E*
  const double pad_share = pad_compliance * effective_modulus;
  const double cov_share = cov_compliance * effective_modulus;
  const double fraction = robot.full_compression_fraction;
  // The travel of the joint contact: the first layer to reach its own travel ends it.
  const double pad_travel = fraction * device.pad_thickness_m / pad_share;
  const double cov_travel = covered ? fraction * robot.covering.thickness_m / cov_share : pad_travel * 2.0;
  const double travel = std::min(pad_travel, cov_travel);
  const double outer_radius = robot.robot_radius_m + (covered ? robot.covering.thickness_m : 0.0);
  if (!(outer_radius - travel >= kMinRadius_m)) {
    throw std::invalid_argument("robot.radius: the layers' travel (" + FormatSignificant(travel * 1e3, 3) +
                                " mm) is not small against the robot's outer radius (" +
                                FormatSignificant(outer_radius * 1e3, 3) +
                                " mm): the Hertz contact of a sphere on the pad does not describe it (got " +
                                FormatSignificant(robot.robot_radius_m, 6) + " m)");
  }
  // The body-region model with the device for the region and the joint layer for the covering:
  // a layer of modulus E* (nu 0), thickness = travel, on a robot of radius R_c - travel, so that
  // its outer radius is R_c and its travel (fraction 1) the joint one.
  BodyContactScene scene = robot;
  scene.covering = CoveringSpec{.youngs_modulus_Pa = effective_modulus,
                                .poisson_ratio = 0.0,
                                .thickness_m = travel,
                                .compressive_curve = nullptr,
                                .law = CoveringLaw::kHertz};
  scene.robot_radius_m = outer_radius - travel;
  scene.full_compression_fraction = 1.0;
  scene.body_stiffness_N_per_m = device.spring_N_per_m;
  scene.contact = ContactType::kClamped;  // the device does not move: mu = m_R
  scene.contact_area_m2 = 0.0;
  reading.contact = Solve(scene, options);
  reading.stiff_pad_force_N = robot.speed_m_per_s * std::sqrt(robot.robot_mass_kg * device.spring_N_per_m);

  const double approach = reading.contact.covering_deflection_m;
  const double a = reading.contact.contact_radius_m;
  const bool stopped = reading.contact.fully_compressed;
  reading.pad = Layer("the pad", pad_modulus, nu_p, device.pad_thickness_m, pad_share, approach, a,
                      stopped && pad_travel <= cov_travel, fraction);
  reading.validity = reading.pad.validity;
  if (covered) {
    reading.covering = Layer("the covering", robot.covering.youngs_modulus_Pa, robot.covering.poisson_ratio,
                             robot.covering.thickness_m, cov_share, approach, a, stopped && cov_travel < pad_travel,
                             fraction);
    reading.validity.within = reading.validity.within && reading.covering->validity.within;
    reading.validity.ratio = std::max(reading.validity.ratio, reading.covering->validity.ratio);
    reading.validity.ratio_full_compression_allowed = std::max(
        reading.validity.ratio_full_compression_allowed, reading.covering->validity.ratio_full_compression_allowed);
    reading.validity.note += "; " + reading.covering->validity.note;
  }
  reading.contact.validity = reading.validity;

  auto& w = reading.warnings;
  if (device.pad_shore_a < kShoreAModulusMinHardness || device.pad_shore_a > kShoreAModulusMaxHardness) {
    w.push_back("the pad's hardness " + FormatSignificant(device.pad_shore_a, 3) +
                " Shore A is outside the Ruess correlation's range (Shore A 30-60): its modulus " +
                FormatSignificant(pad_modulus / 1e6, 3) + " MPa is extrapolated");
  }
  if (device.pad_thickness_assumed) {
    w.push_back("the pad's thickness was not given: " + FormatSignificant(device.pad_thickness_m * 1e3, 3) +
                " mm assumed (measure the pad)");
  }
  for (const DeviceLayer* layer : {&reading.pad, reading.covering ? &*reading.covering : nullptr}) {
    if (layer != nullptr && !layer->validity.within) w.push_back("outside the Hertz law: " + layer->validity.note);
  }
  if (!reading.validity.within) {
    w.push_back("the device's reading lies between the Hertz prediction " +
                FormatSignificant(reading.contact.peak_force_N, 4) + " N and the stiff pad's " +
                FormatSignificant(reading.stiff_pad_force_N, 4) + " N (the spring alone, v sqrt(m k_D))");
  }
  return reading;
}

}  // namespace covopt
