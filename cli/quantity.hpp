#pragma once
/// @file quantity.hpp
/// Values with units, as a user types them: "10kg", "2 m/s", "15mm", "27.6MPa", "0.3".
///
/// A value is a decimal number (std::from_chars, so the decimal separator is always '.'),
/// optionally followed by spaces and a unit that fits the quantity's kind. A bare number is
/// SI. The words "fixed" (masses: covopt::kFixed) and "flat" (the robot radius:
/// covopt::kFlat) stand for the infinite values where the spec allows them.
///
///     mass       kg, g, t
///     length     m, cm, mm, um, µm
///     speed      m/s, mm/s, cm/s, km/h
///     modulus    Pa, kPa, MPa, GPa, N/m2, N/mm2  (also N/m², N/mm²)
///     density    kg/m3, g/cm3  (also kg/m³, kg/m^3, g/cm³, g/cm^3)
///     dimensionless (Poisson ratios, tolerances): a plain number
///
/// Non-finite numbers (nan, inf, overflow) are rejected here; range checks are the
/// library's (ImpactModel::FromScene).

#include <string>
#include <string_view>

namespace covopt::cli {

/// What a value measures; decides which units fit.
enum class QuantityKind { kMass, kLength, kSpeed, kModulus, kDensity, kDimensionless };

/// How to read one value.
struct QuantitySpec {
  QuantityKind kind = QuantityKind::kDimensionless;
  bool allow_fixed = false;  ///< accept "fixed" -> covopt::kFixed (masses)
  bool allow_flat = false;   ///< accept "flat" -> covopt::kFlat (the robot radius)
};

/// Parses `text` into an SI value.
/// @param name how messages call the value: a flag ("--speed") or a field ("robot.speed").
/// @throws InputError "<name>: <problem> (got '<text>')", e.g.
///         "--speed: unit 'kg' is not a speed; use m/s, mm/s, cm/s or km/h (got '2kg')".
double ParseQuantity(std::string_view text, const QuantitySpec& spec, std::string_view name);

/// "a mass", "a length", "a speed", "a modulus or pressure", "a density", "dimensionless".
std::string_view Describe(QuantityKind kind) noexcept;

/// The units that fit a kind, for messages and help: "kg, g or t"; "" for dimensionless.
std::string UnitList(QuantityKind kind);

/// An SI value for people, in a form ParseQuantity reads back (6 significant digits):
/// "10 kg", "fixed", "15 mm", "flat", "2 m/s", "27.6 MPa", "6.5 GPa", "50 kg/m³", "0.3".
/// Lengths are shown in mm, moduli in the largest of Pa/kPa/MPa/GPa not above the value.
std::string FormatQuantity(double si_value, QuantityKind kind);

}  // namespace covopt::cli
