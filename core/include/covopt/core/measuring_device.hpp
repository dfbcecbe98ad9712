#pragma once
/// @file measuring_device.hpp
/// What a biofidelic force-measuring device reads when the robot strikes it (docs/model.md
/// §13.11). Power-and-force-limited applications are verified by measurement: a load cell on a
/// spring k_D, fixed to the ground, under a pad of a given Shore A hardness (e.g. GTE
/// CoboSafe-CBSF: pads of 10, 30 and 70 Shore A on springs of 10 to 75 N/mm, one pair per body
/// region, after DGUV FB HM-080 (2017)). The device is not the body model: it does not move
/// (the robot's whole reflected mass strikes it, mu = m_R), and its pad is a solid elastomer.
///
///     the pad (E_p from its hardness, nu_p = 0.49) and the robot's covering (E_c, nu_c, b_c) are
///     two elastic bodies in one Hertz contact on the robot's outer radius R_c = R_r + b_c:
///       1/E* = (1 - nu_c²)/E_c + (1 - nu_p²)/E_p        (bare robot: the pad's term only)
///       K = 4/3 E* sqrt(R_c),  delta(F) = (F/K)^(2/3),  a² = R_c delta,  p = 3F/(2 pi a²)
///     each layer takes its share s_i = E* (1 - nu_i²)/E_i of the approach delta; the first
///     layer to reach 0.8 of its thickness ends the law (a rigid stop past it);
///     mu v²/2 = F²/(2 k_D) + 2/5 F delta(F),  mu = m_R
///
/// This is the body-region model (body_contact.hpp) with the region replaced by the device:
/// k_H -> k_D, m_H -> fixed, and the covering by the two layers' one Hertz contact; its energy
/// balance and peak solver answer it.
///
/// Shore A -> Young's modulus: the Ruess correlation the material catalog uses for its solid
/// elastomers (log10(E/MPa) = 0.0235 H - 0.6403, stated for about Shore A 30 to 60;
/// https://josephborrello.com/shore-a-to-modulus). Outside that range the modulus is an
/// extrapolation and the reading says so.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/body_contact.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/quantity.hpp"

namespace covopt {

/// The Ruess correlation's stated range of Shore A hardness [-].
inline constexpr double kShoreAModulusMinHardness = 30.0;
inline constexpr double kShoreAModulusMaxHardness = 60.0;
/// The source of the Shore A -> modulus correlation.
inline constexpr std::string_view kShoreAModulusSource =
    "Ruess correlation log10(E/MPa) = 0.0235 ShoreA - 0.6403 (https://josephborrello.com/shore-a-to-modulus), "
    "the material catalog's hardness basis";
/// The pad's Poisson ratio [-]: a solid elastomer, as the catalog stores its elastomers.
inline constexpr double kDevicePadPoissonRatio = 0.49;
/// The pad's thickness [m] when none is given: an assumption (the maker's manual cited gives the
/// hardness, not the thickness); every reading that takes it says so.
inline constexpr double kDefaultPadThickness_m = 0.007;

/// How the device's spring and pad thickness are read with units (ParseQuantity): a bare
/// number is N/m, believable from 1 kN/m to 10 MN/m ("25" is a slip for 25 N/mm), and m,
/// believable up to 0.1 m.
inline constexpr QuantitySpec kDeviceSpringSpec{QuantityKind::kStiffness, false, false, 1e3, 1e7, {"N/mm", "kN/m"},
                                                "device spring"};
inline constexpr QuantitySpec kPadThicknessSpec{QuantityKind::kLength, false, false, 0.0, 0.1, {"mm", "cm"},
                                                "pad thickness"};

/// Young's modulus [Pa] of a solid elastomer of Shore A hardness `shore_a` (Ruess).
/// @throws std::invalid_argument "device_pad must be in [0, 100] Shore A (got ...)".
double ShoreAModulus_Pa(double shore_a);

/// One spring and pad pair of a biofidelic measuring device.
struct MeasuringDevice {
  /// The spring k_D [N/m], in (0, 1e9].
  double spring_N_per_m = 25e3;
  /// The pad's Shore A hardness [-], in [0, 100].
  double pad_shore_a = 70.0;
  /// The pad's thickness [m], in [1e-4, 0.1].
  double pad_thickness_m = kDefaultPadThickness_m;
  /// The thickness was not given: kDefaultPadThickness_m was taken (the reading warns).
  bool pad_thickness_assumed = false;
  /// Its name: the preset's ("25+70") or "custom".
  std::string name = "custom";
};

/// A spring and pad pair used in practice (N/mm + Shore A), after DGUV FB HM-080 (2017), with
/// the body regions it stands for (by their spring constant, ISO/TS 15066:2016 Table A.3).
struct DevicePreset {
  std::string_view name;            ///< "25+70"
  double spring_N_per_mm = 0.0;     ///< 25
  double pad_shore_a = 0.0;         ///< 70
  std::string_view pad_colour;      ///< CoboSafe-CBSF's colour: "green" 10, "blue" 30, "red" 70
  /// The regions (ISO/TS 15066 names) whose k_H it reproduces, e.g. {"chest", "pelvis"}.
  std::span<const std::string_view> regions;
};

/// The eight pairs: 10+10, 25+70, 30+30, 35+30, 40+70, 50+30, 60+30, 75+70.
std::span<const DevicePreset> DevicePresets() noexcept;

/// The device named `name`: a pair ("25+70") or a region it stands for ("chest"), with the
/// pad `pad_thickness_m` thick (empty: kDefaultPadThickness_m, marked assumed).
/// @throws std::invalid_argument "device: unknown preset '...' (pairs: 10+10, ...; regions: ...)".
MeasuringDevice DeviceNamed(std::string_view name, std::optional<double> pad_thickness_m = std::nullopt);

/// The preset for the body region named `region` (its ISO name), if one stands for it.
const DevicePreset* DevicePresetForRegion(std::string_view region) noexcept;

/// The device as `covopt measure` and covopt.predict_measurement name it: a preset, or a spring
/// with a pad, or nothing (the region's own pair).
struct DeviceChoice {
  std::optional<std::string> preset;         ///< device: a pair ("25+70") or a region ("chest")
  std::optional<double> spring_N_per_m;      ///< device_spring [N/m]
  /// device_pad: the pad's Shore A hardness and, after a comma, its thickness with a unit:
  /// "70ShA,7mm", "70 Shore A", "70".
  std::optional<std::string> pad;
  std::optional<double> pad_thickness_m;     ///< device_pad_thickness [m], with a preset
};

/// The device `choice` names for the region `region` (its ISO name): the preset; or the spring
/// and the pad (both needed); or, with neither, the region's own pair.
/// @throws std::invalid_argument naming device, device_spring, device_pad or
///         device_pad_thickness, e.g. "device_pad: the hardness must be a Shore A number in
///         [0, 100], e.g. 70ShA (got '170ShA')", or "device: no spring and pad pair stands for
///         pelvis; give device (a pair) or device_spring and device_pad".
MeasuringDevice ResolveDevice(const DeviceChoice& choice, std::string_view region);

/// One layer of the device's contact at the peak.
struct DeviceLayer {
  double modulus_Pa = 0.0;       ///< E [Pa]
  double poisson_ratio = 0.0;    ///< nu [-]
  double thickness_m = 0.0;      ///< b [m]
  double share = 0.0;            ///< its share s of the approach [-]
  double deflection_m = 0.0;     ///< s delta at the peak [m]
  double strain = 0.0;           ///< deflection / thickness [-]
  bool bottomed_out = false;     ///< it reached 0.8 of its thickness (the rigid stop)
  CoveringValidity validity;     ///< the Hertz law's limits on it (a solid elastomer's 20 %, a <= b)
};

/// What the device shows.
struct DeviceReading {
  MeasuringDevice device;
  /// The contact against the device (the body-region model's result with k_D, mu = m_R and the
  /// two layers' one Hertz contact): peak_force_N is what the device shows, peak_pressure_Pa
  /// the Hertz peak pressure a pressure film on the pad shows, contact_radius_m its radius.
  /// Its covering fields (deflection, strain, validity) are those of the two layers together.
  BodyContactResult contact;
  DeviceLayer pad;
  /// The robot's covering; empty for a bare robot.
  std::optional<DeviceLayer> covering;
  /// The reading with a rigid pad and no covering [N]: v sqrt(m_R k_D), the spring alone. Every
  /// compliant layer lowers the reading, so it bounds it from above (without braking): where
  /// a layer leaves the Hertz law (a thin bonded pad is stiffer than the half-space), the true
  /// reading lies between contact.peak_force_N and this.
  double stiff_pad_force_N = 0.0;
  /// Both layers within the Hertz law (the pad's and the covering's limits together).
  CoveringValidity validity;
  /// For people: the hardness outside the correlation's range, an assumed thickness, a layer
  /// bottomed out, a layer outside the Hertz law.
  std::vector<std::string> warnings;
};

/// The reading of `device` struck by the robot of `robot` (its mass, speed, radius, covering
/// and reaction; its region fields, contact type and contact area are not read).
/// @throws std::invalid_argument naming the field: a device field out of range, a fixed robot
///         ("robot.mass: the device is fixed ..."), a flat robot ("robot.radius: ..."), a foam
///         covering ("covering.law: ..."), or a robot field the body-region model refuses.
DeviceReading PredictDeviceReading(const BodyContactScene& robot, const MeasuringDevice& device,
                                   const SolveOptions& options = {});

}  // namespace covopt
