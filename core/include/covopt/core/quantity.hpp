#pragma once
/// @file quantity.hpp
/// Values with units, as people type them ("10kg", "2 m/s", "15mm", "27.6MPa", "0.3"), read
/// into SI. Shared by the command line, scene files and catalog files.
///
/// A value is a decimal number (std::from_chars, so the decimal separator is always '.'),
/// optionally followed by spaces and a unit that fits the quantity's kind. The words
/// "fixed" (masses: covopt::kFixed) and "flat" (the robot radius: covopt::kFlat) stand for
/// the infinite values where the spec allows them.
///
///     mass            kg, g, t
///     length          m, cm, mm, um, µm
///     speed           m/s, mm/s, cm/s, km/h
///     modulus/stress  Pa, kPa, MPa, GPa, N/m2, N/mm2  (also N/m², N/mm²)
///     density         kg/m3, g/cm3  (also kg/m³, kg/m^3, g/cm³, g/cm^3)
///     energy density  J/m2, J/cm2, kJ/m2  (also J/m², J/cm², kJ/m²)
///     time            s, ms
///     acceleration    m/s2, mm/s2  (also m/s², m/s^2)
///     damping coefficient (Hunt-Crossley) s/m, ms/m
///     stiffness       N/m, kN/m, N/mm
///     viscous damping N*s/m, Ns/m, kN*s/m  (also N·s/m)
///     area            m2, cm2, mm2  (also m², cm², mm²)
///     dimensionless   (Poisson ratios, tolerances, safety factors): a plain number
///
/// Decimal units are applied to the decimal number itself, not by a multiplication in
/// binary: "18mm" is read as 18e-3 and gives exactly the double nearest 0.018 (18 * 1e-3
/// would give 0.018000000000000002).
///
/// A bare number (no unit) is SI. Where a spec carries a plausible range, a bare positive
/// number outside it is refused as a likely unit slip (a length typed in mm, a modulus in
/// MPa, a mass in g):
///
///     --robot-radius 40: a bare number is in metres (40 m); write 40mm or 40m
///
/// An explicit unit is the user's intent: "40m" is taken as 40 m, and only the model's own
/// ranges (ImpactModel::FromScene) apply. Zero and negative bare numbers are left to those
/// ranges too. Non-finite numbers (nan, inf, overflow) are always refused.

#include <array>
#include <limits>
#include <string>
#include <string_view>

namespace covopt {

/// What a value measures; decides which units fit.
enum class QuantityKind {
  kMass,           ///< [kg]
  kLength,         ///< [m]
  kSpeed,          ///< [m/s]
  kModulus,        ///< a modulus, stress or pressure [Pa]
  kDensity,        ///< [kg/m³]
  kDimensionless,  ///< [-]
  kEnergyDensity,  ///< energy per area [J/m²] (the contusion criterion)
  kTime,           ///< [s]
  kAcceleration,   ///< [m/s²]
  /// Hunt-Crossley damping coefficient d [s/m]: the contact force is F_el (1 + d δ').
  kDampingCoefficient,
  kStiffness,       ///< a spring's stiffness [N/m]
  kViscousDamping,  ///< a dashpot's coefficient [N·s/m]
  kArea,            ///< an area [m²] (the bare robot's contact area)
};

/// How to read one value.
struct QuantitySpec {
  QuantityKind kind = QuantityKind::kDimensionless;
  bool allow_fixed = false;  ///< accept "fixed" -> covopt::kFixed (masses)
  bool allow_flat = false;   ///< accept "flat" -> covopt::kFlat (the robot radius)
  /// Where a bare (unit-less) positive number is believable, in SI units of `kind`:
  /// [plausible_min, plausible_max]. A bare positive number outside it is refused as a
  /// likely unit slip. The defaults accept every bare number.
  double plausible_min = 0.0;
  double plausible_max = std::numeric_limits<double>::infinity();
  /// The units a refused bare number was probably meant in, most likely first; the message
  /// suggests the first whose reading is plausible ("" entries are unused).
  std::array<std::string_view, 2> likely_units{};
  /// What the value is, for messages and the documented table: "robot radius".
  std::string_view what{};

  /// True when a bare number is checked against a plausible range.
  constexpr bool has_plausible_range() const noexcept {
    return plausible_min > 0.0 || plausible_max < std::numeric_limits<double>::infinity();
  }
};

/// Parses `text` into an SI value.
/// @param name how messages call the value: a flag ("--speed") or a field ("robot.speed").
/// @throws std::invalid_argument "<name>: <problem> (got '<text>')", e.g.
///         "--speed: unit 'kg' is not a speed; use m/s, mm/s, cm/s or km/h (got '2kg')", or
///         for an implausible bare number (see CheckBareNumber)
///         "--robot-radius 40: a bare number is in metres (40 m); write 40mm or 40m".
double ParseQuantity(std::string_view text, const QuantitySpec& spec, std::string_view name);

/// Checks a number that came without a unit (typed bare, or a TOML number) against the
/// spec's plausible range; does nothing for zero, negative or non-finite values, or when the
/// spec has no range.
/// @param si_value the number, read as SI.
/// @param typed the number as written, repeated in the message ("40").
/// @param quote put around the suggested spellings: "" on a command line, "\"" in a TOML
///        file (where a value with a unit is a string).
/// @throws std::invalid_argument
///         "<name> <typed>: a bare number is in metres (40 m); write 40mm or 40m", or, when no
///         likely unit gives a plausible value, "--head-radius 2000: a bare number is in
///         metres (2000 m), outside the plausible range for the head radius (0 mm to 500 mm);
///         write it with a unit, e.g. mm, cm or m".
void CheckBareNumber(double si_value, std::string_view typed, const QuantitySpec& spec,
                     std::string_view name, std::string_view quote = "");

/// "a mass", "a length", "a speed", "a modulus or pressure", "a density", "dimensionless",
/// "an energy density", "a time", "an acceleration", "a damping coefficient", "a stiffness",
/// "a viscous damping", "an area".
std::string_view Describe(QuantityKind kind) noexcept;

/// The units that fit a kind, for messages and help: "kg, g or t"; "" for dimensionless.
std::string UnitList(QuantityKind kind);

/// The SI unit of a kind as typed: "kg", "m", "m/s", "Pa", "kg/m3", "J/m2"; "" for
/// dimensionless.
std::string_view SiUnit(QuantityKind kind) noexcept;

/// An SI value for people, in a form ParseQuantity reads back (6 significant digits):
/// "10 kg", "fixed", "15 mm", "flat", "2 m/s", "27.6 MPa", "6.5 GPa", "50 kg/m³",
/// "2.52 J/cm²", "0.3". Lengths are shown in mm, moduli in the largest of Pa/kPa/MPa/GPa
/// not above the value, energy densities in J/cm².
std::string FormatQuantity(double si_value, QuantityKind kind);

/// The named specs of every quantity covopt reads: one place for the plausible ranges of
/// bare numbers (cli/README.md documents this table). Chosen so that every realistic value
/// passes and the classic slips fail: a length typed in mm, a modulus or stress in MPa
/// (27.6 read as 27.6 Pa), a mass in g, a speed in mm/s, an energy density in J/cm².
namespace quantity_specs {

using Kind = QuantityKind;
inline constexpr double kNoUpperBound = std::numeric_limits<double>::infinity();

// clang-format off
// Scene fields.
inline constexpr QuantitySpec kRobotMass{Kind::kMass, true, false, 0.0, 1000.0, {"g"}, "robot mass"};
inline constexpr QuantitySpec kHeadMass{Kind::kMass, true, false, 0.0, 100.0, {"g"}, "head mass"};
inline constexpr QuantitySpec kSpeed{Kind::kSpeed, false, false, 0.0, 20.0, {"mm/s", "cm/s"}, "impact speed"};
inline constexpr QuantitySpec kRobotRadius{Kind::kLength, false, true, 0.0, 1.0, {"mm", "cm"}, "robot radius"};
inline constexpr QuantitySpec kHeadRadius{Kind::kLength, false, false, 0.0, 0.5, {"mm", "cm"}, "head radius"};
inline constexpr QuantitySpec kScalpThickness{Kind::kLength, false, false, 0.0, 0.05, {"mm"}, "scalp thickness"};
inline constexpr QuantitySpec kRobotModulus{Kind::kModulus, false, false, 1e5, 1e12, {"GPa", "MPa"}, "robot modulus"};
inline constexpr QuantitySpec kScalpModulus{Kind::kModulus, false, false, 1e4, 1e10, {"MPa", "kPa"}, "scalp modulus"};
inline constexpr QuantitySpec kSkullModulus{Kind::kModulus, false, false, 1e7, 1e12, {"GPa", "MPa"}, "skull modulus"};
inline constexpr QuantitySpec kPoissonRatio{Kind::kDimensionless, false, false, 0.0, kNoUpperBound, {}, "Poisson ratio"};
// The covering: scene fields, and optimize's design space and catalog entries.
/// Covering thickness: covering.thickness, optimize --thickness and --max-thickness. 0 = none.
inline constexpr QuantitySpec kCoveringThickness{Kind::kLength, false, false, 0.0, 0.2, {"mm", "cm"}, "covering thickness"};
/// optimize --thickness-step, the stock thickness the design is rounded up to.
inline constexpr QuantitySpec kThicknessStep{Kind::kLength, false, false, 0.0, 0.01, {"mm"}, "thickness step"};
/// Covering modulus: covering.modulus, optimize --min-modulus/--max-modulus, a catalog's
/// youngs_modulus_Pa.
inline constexpr QuantitySpec kCoveringModulus{Kind::kModulus, false, false, 1e4, 1e12, {"MPa", "kPa"}, "covering modulus"};
/// A catalog material's density_kg_per_m3.
inline constexpr QuantitySpec kMaterialDensity{Kind::kDensity, false, false, 3.0, 25000.0, {"g/cm3"}, "material density"};
// Injury limits and the safety factor.
/// Laceration limit: the skin's ultimate tensile stress [Pa] (default 1 MPa).
inline constexpr QuantitySpec kLacerationLimit{Kind::kModulus, false, false, 1e4, 1e9, {"MPa", "kPa"}, "laceration limit"};
/// Contusion limit: the largest energy density [J/m²] (default 2.52 J/cm² = 25 200 J/m²).
inline constexpr QuantitySpec kContusionLimit{Kind::kEnergyDensity, false, false, 100.0, 1e7, {"J/cm2", "kJ/m2"}, "contusion limit"};
/// The safety factor the limits are divided by [-], in [1, 100] (checked by its reader).
inline constexpr QuantitySpec kSafetyFactor{Kind::kDimensionless, false, false, 0.0, kNoUpperBound, {}, "safety factor"};
// The scenes beyond the conservative two-mass model (docs/model.md §10).
/// Hunt-Crossley contact damping d [s/m] (model.damping), >= 0; 0 = none.
inline constexpr QuantitySpec kContactDamping{Kind::kDampingCoefficient, false, false, 0.0, 10.0, {"ms/m"}, "contact damping"};
/// The robot's reaction delay after first contact [s] (robot.reaction_delay).
inline constexpr QuantitySpec kReactionDelay{Kind::kTime, false, false, 0.0, 2.0, {"ms"}, "reaction delay"};
/// The robot's braking deceleration [m/s²] (robot.braking); 0 = the robot does not brake.
inline constexpr QuantitySpec kBraking{Kind::kAcceleration, false, false, 0.0, 1000.0, {"mm/s2"}, "braking deceleration"};
/// The torso the head hangs on by the neck [kg] (head.torso_mass); 0 = no neck.
inline constexpr QuantitySpec kTorsoMass{Kind::kMass, true, false, 0.0, 500.0, {"g"}, "torso mass"};
/// The neck's stiffness [N/m] (head.neck_stiffness).
inline constexpr QuantitySpec kNeckStiffness{Kind::kStiffness, false, false, 0.0, 1e8, {"kN/m", "N/mm"}, "neck stiffness"};
/// The neck's damping [N·s/m] (head.neck_damping).
inline constexpr QuantitySpec kNeckDamping{Kind::kViscousDamping, false, false, 0.0, 1e5, {"kN*s/m"}, "neck damping"};
// ISO/TS 15066 body regions (covopt/core/body_contact.hpp).
/// The bare robot's contact area [m²] (--contact-area): 1 mm² to 1000 cm².
inline constexpr QuantitySpec kContactArea{Kind::kArea, false, false, 1e-6, 1e-1, {"cm2", "mm2"}, "contact area"};
/// Integrator tolerances [-].
inline constexpr QuantitySpec kTolerance{Kind::kDimensionless, false, false, 0.0, kNoUpperBound, {}, "tolerance"};
// clang-format on

/// Every named spec with a plausible range, in the order of the documented table.
inline constexpr std::array kWithPlausibleRange{
    &kRobotMass,       &kHeadMass,        &kSpeed,           &kRobotRadius,
    &kHeadRadius,      &kCoveringThickness, &kScalpThickness, &kThicknessStep,
    &kRobotModulus,    &kCoveringModulus, &kScalpModulus,    &kSkullModulus,
    &kMaterialDensity, &kLacerationLimit, &kContusionLimit,
    &kContactDamping,  &kReactionDelay,   &kBraking,         &kTorsoMass,
    &kNeckStiffness,   &kNeckDamping,     &kContactArea,
};

}  // namespace quantity_specs
}  // namespace covopt
