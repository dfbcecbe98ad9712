#include "covopt/core/quantity.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "covopt/internal/text.hpp"

#include "covopt/core/number_format.hpp"
#include "covopt/core/scene.hpp"
#include "numeric_format.hpp"

namespace covopt {
namespace {

using internal::FormatNumber;

/// One unit. Decimal units shift the decimal exponent of the typed number (exact to the
/// last bit: "18mm" reads as 18e-3); the others divide by `divisor`.
struct Unit {
  std::string_view symbol;
  QuantityKind kind;
  int decimal_exponent;  ///< SI value of one unit = 10^decimal_exponent / divisor
  double divisor;
  bool listed;  ///< shown in messages (false for alternative spellings)
};

// µ is U+00B5 MICRO SIGN, μ is U+03BC GREEK SMALL LETTER MU; both are typed in practice.
constexpr std::array kUnits{
    Unit{"kg", QuantityKind::kMass, 0, 1.0, true},
    Unit{"g", QuantityKind::kMass, -3, 1.0, true},
    Unit{"t", QuantityKind::kMass, 3, 1.0, true},
    Unit{"m", QuantityKind::kLength, 0, 1.0, true},
    Unit{"cm", QuantityKind::kLength, -2, 1.0, true},
    Unit{"mm", QuantityKind::kLength, -3, 1.0, true},
    Unit{"um", QuantityKind::kLength, -6, 1.0, true},
    Unit{"\u00b5m", QuantityKind::kLength, -6, 1.0, true},
    Unit{"\u03bcm", QuantityKind::kLength, -6, 1.0, false},
    Unit{"m/s", QuantityKind::kSpeed, 0, 1.0, true},
    Unit{"mm/s", QuantityKind::kSpeed, -3, 1.0, true},
    Unit{"cm/s", QuantityKind::kSpeed, -2, 1.0, true},
    Unit{"km/h", QuantityKind::kSpeed, 0, 3.6, true},
    Unit{"Pa", QuantityKind::kModulus, 0, 1.0, true},
    Unit{"kPa", QuantityKind::kModulus, 3, 1.0, true},
    Unit{"MPa", QuantityKind::kModulus, 6, 1.0, true},
    Unit{"GPa", QuantityKind::kModulus, 9, 1.0, true},
    Unit{"N/m2", QuantityKind::kModulus, 0, 1.0, true},
    Unit{"N/mm2", QuantityKind::kModulus, 6, 1.0, true},
    Unit{"N/m\u00b2", QuantityKind::kModulus, 0, 1.0, false},
    Unit{"N/mm\u00b2", QuantityKind::kModulus, 6, 1.0, false},
    Unit{"kg/m3", QuantityKind::kDensity, 0, 1.0, true},
    Unit{"g/cm3", QuantityKind::kDensity, 3, 1.0, true},
    Unit{"kg/m\u00b3", QuantityKind::kDensity, 0, 1.0, false},
    Unit{"kg/m^3", QuantityKind::kDensity, 0, 1.0, false},
    Unit{"g/cm\u00b3", QuantityKind::kDensity, 3, 1.0, false},
    Unit{"g/cm^3", QuantityKind::kDensity, 3, 1.0, false},
    Unit{"J/m2", QuantityKind::kEnergyDensity, 0, 1.0, true},
    Unit{"J/cm2", QuantityKind::kEnergyDensity, 4, 1.0, true},
    Unit{"kJ/m2", QuantityKind::kEnergyDensity, 3, 1.0, true},
    Unit{"J/m\u00b2", QuantityKind::kEnergyDensity, 0, 1.0, false},
    Unit{"J/cm\u00b2", QuantityKind::kEnergyDensity, 4, 1.0, false},
    Unit{"kJ/m\u00b2", QuantityKind::kEnergyDensity, 3, 1.0, false},
    Unit{"s", QuantityKind::kTime, 0, 1.0, true},
    Unit{"ms", QuantityKind::kTime, -3, 1.0, true},
    Unit{"m/s2", QuantityKind::kAcceleration, 0, 1.0, true},
    Unit{"mm/s2", QuantityKind::kAcceleration, -3, 1.0, true},
    Unit{"m/s\u00b2", QuantityKind::kAcceleration, 0, 1.0, false},
    Unit{"m/s^2", QuantityKind::kAcceleration, 0, 1.0, false},
    Unit{"s/m", QuantityKind::kDampingCoefficient, 0, 1.0, true},
    Unit{"ms/m", QuantityKind::kDampingCoefficient, -3, 1.0, true},
    Unit{"N/m", QuantityKind::kStiffness, 0, 1.0, true},
    Unit{"kN/m", QuantityKind::kStiffness, 3, 1.0, true},
    Unit{"N/mm", QuantityKind::kStiffness, 3, 1.0, true},
    Unit{"N*s/m", QuantityKind::kViscousDamping, 0, 1.0, true},
    Unit{"Ns/m", QuantityKind::kViscousDamping, 0, 1.0, true},
    Unit{"kN*s/m", QuantityKind::kViscousDamping, 3, 1.0, true},
    Unit{"N\u00b7s/m", QuantityKind::kViscousDamping, 0, 1.0, false},
    Unit{"m2", QuantityKind::kArea, 0, 1.0, true},
    Unit{"cm2", QuantityKind::kArea, -4, 1.0, true},
    Unit{"mm2", QuantityKind::kArea, -6, 1.0, true},
    Unit{"m\u00b2", QuantityKind::kArea, 0, 1.0, false},
    Unit{"cm\u00b2", QuantityKind::kArea, -4, 1.0, false},
    Unit{"mm\u00b2", QuantityKind::kArea, -6, 1.0, false},
};

constexpr std::string_view kSpaces = " \t";

std::string_view Trim(std::string_view s) {
  const auto first = s.find_first_not_of(kSpaces);
  if (first == std::string_view::npos) return {};
  return s.substr(first, s.find_last_not_of(kSpaces) - first + 1);
}

char Lower(char c) { return (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c; }

bool EqualsIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(),
                                            [](char x, char y) { return Lower(x) == Lower(y); });
}

bool StartsWithIgnoringCase(std::string_view s, std::string_view prefix) {
  return s.size() >= prefix.size() && EqualsIgnoringCase(s.substr(0, prefix.size()), prefix);
}

bool IsLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
/// A unit starts with a letter or with µ/μ (lead bytes 0xC2 / 0xCE in UTF-8).
bool StartsUnit(std::string_view rest) {
  const auto c = static_cast<unsigned char>(rest.front());
  return IsLetter(rest.front()) || c == 0xC2 || c == 0xCE;
}

const Unit* FindUnit(std::string_view symbol) {
  const auto unit = std::find_if(kUnits.begin(), kUnits.end(),
                                 [&](const Unit& u) { return u.symbol == symbol; });
  return unit == kUnits.end() ? nullptr : &*unit;
}

std::string_view Example(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::kMass: return "10kg";
    case QuantityKind::kLength: return "15mm";
    case QuantityKind::kSpeed: return "2m/s";
    case QuantityKind::kModulus: return "27.6MPa";
    case QuantityKind::kDensity: return "50kg/m3";
    case QuantityKind::kDimensionless: return "0.3";
    case QuantityKind::kEnergyDensity: return "2.52J/cm2";
    case QuantityKind::kTime: return "20ms";
    case QuantityKind::kAcceleration: return "20m/s2";
    case QuantityKind::kDampingCoefficient: return "0.2s/m";
    case QuantityKind::kStiffness: return "20kN/m";
    case QuantityKind::kViscousDamping: return "50N*s/m";
    case QuantityKind::kArea: return "1cm2";
  }
  return "";
}

/// "metres" etc.: how messages name the SI unit a bare number is read in.
std::string_view SiUnitName(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::kMass: return "kilograms";
    case QuantityKind::kLength: return "metres";
    case QuantityKind::kSpeed: return "metres per second";
    case QuantityKind::kModulus: return "pascals";
    case QuantityKind::kDensity: return "kilograms per cubic metre";
    case QuantityKind::kDimensionless: return "plain numbers";
    case QuantityKind::kEnergyDensity: return "joules per square metre";
    case QuantityKind::kTime: return "seconds";
    case QuantityKind::kAcceleration: return "metres per second squared";
    case QuantityKind::kDampingCoefficient: return "seconds per metre";
    case QuantityKind::kStiffness: return "newtons per metre";
    case QuantityKind::kViscousDamping: return "newton-seconds per metre";
    case QuantityKind::kArea: return "square metres";
  }
  return "SI units";
}

/// "use m/s, mm/s, cm/s or km/h" / "give a plain number".
std::string Advice(QuantityKind kind) {
  if (kind == QuantityKind::kDimensionless) return "give a plain number, e.g. 0.3";
  return "use " + UnitList(kind);
}

/// A user's text as a message echoes it, control characters escaped
/// (internal::EscapeControlCharacters): whole up to 80 bytes; a longer one (a 100,000-digit number)
/// as its first 40 bytes (not cutting a UTF-8 character), "…" and its length, so that an
/// error stays one readable line.
std::string Shortened(std::string_view raw_text) {
  constexpr std::size_t kWhole = 80, kKept = 40;
  const std::string escaped = internal::EscapeControlCharacters(raw_text);
  const std::string_view text = escaped;
  if (text.size() <= kWhole) return escaped;
  std::size_t keep = kKept;
  while (keep > 0 && (static_cast<unsigned char>(text[keep]) & 0xC0) == 0x80) --keep;
  return std::string(text.substr(0, keep)) + "… (" + std::to_string(raw_text.size()) + " characters)";
}

std::string Quoted(std::string_view text) {
  if (internal::EscapeControlCharacters(text).size() <= 80) return "'" + internal::EscapeControlCharacters(text) + "'";
  const std::string shortened = Shortened(text);
  const std::size_t ellipsis = shortened.find("… (");
  return "'" + shortened.substr(0, ellipsis) + "…'" + shortened.substr(ellipsis + std::string_view("…").size());
}

[[noreturn]] void Fail(std::string_view name, const std::string& problem, std::string_view text) {
  throw std::invalid_argument(std::string(name) + ": " + problem + " (got " + Quoted(text) + ")");
}

std::string WhatIsExpected(QuantityKind kind) {
  return std::string(kind == QuantityKind::kDimensionless ? "a number" : Describe(kind)) +
         " such as " + std::string(Example(kind));
}

/// `number` (as from_chars accepted it) times the unit, rounded once: a decimal unit moves
/// the decimal exponent of the text ("18" with mm -> "18e-3"). Empty when out of range.
std::optional<double> ApplyUnit(std::string_view number, double value, const Unit& unit) {
  if (!number.empty() && number.front() == '+') number.remove_prefix(1);
  if (unit.decimal_exponent != 0) {
    const std::size_t e = number.find_first_of("eE");
    const std::string_view mantissa = number.substr(0, e);
    long long exponent = 0;
    if (e != std::string_view::npos) {
      std::string_view digits = number.substr(e + 1);
      const bool negative = !digits.empty() && digits.front() == '-';
      if (!digits.empty() && (digits.front() == '+' || digits.front() == '-')) {
        digits.remove_prefix(1);
      }
      const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), exponent);
      if (ec != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
      if (negative) exponent = -exponent;
    }
    exponent += unit.decimal_exponent;
    const std::string shifted = std::string(mantissa) + "e" + std::to_string(exponent);
    double scaled = 0.0;
    const auto [end, ec] =
        std::from_chars(shifted.data(), shifted.data() + shifted.size(), scaled);
    if (ec != std::errc() || end != shifted.data() + shifted.size()) return std::nullopt;
    value = scaled;
  }
  const double si = value / unit.divisor;
  if (!std::isfinite(si)) return std::nullopt;
  return si;
}

}  // namespace

std::string_view Describe(QuantityKind kind) noexcept {
  switch (kind) {
    case QuantityKind::kMass: return "a mass";
    case QuantityKind::kLength: return "a length";
    case QuantityKind::kSpeed: return "a speed";
    case QuantityKind::kModulus: return "a modulus or pressure";
    case QuantityKind::kDensity: return "a density";
    case QuantityKind::kDimensionless: return "dimensionless";
    case QuantityKind::kEnergyDensity: return "an energy density";
    case QuantityKind::kTime: return "a time";
    case QuantityKind::kAcceleration: return "an acceleration";
    case QuantityKind::kDampingCoefficient: return "a damping coefficient";
    case QuantityKind::kStiffness: return "a stiffness";
    case QuantityKind::kViscousDamping: return "a viscous damping";
    case QuantityKind::kArea: return "an area";
  }
  return "unknown";
}

std::string_view SiUnit(QuantityKind kind) noexcept {
  switch (kind) {
    case QuantityKind::kMass: return "kg";
    case QuantityKind::kLength: return "m";
    case QuantityKind::kSpeed: return "m/s";
    case QuantityKind::kModulus: return "Pa";
    case QuantityKind::kDensity: return "kg/m3";
    case QuantityKind::kDimensionless: return "";
    case QuantityKind::kEnergyDensity: return "J/m2";
    case QuantityKind::kTime: return "s";
    case QuantityKind::kAcceleration: return "m/s2";
    case QuantityKind::kDampingCoefficient: return "s/m";
    case QuantityKind::kStiffness: return "N/m";
    case QuantityKind::kViscousDamping: return "N*s/m";
    case QuantityKind::kArea: return "m2";
  }
  return "";
}

std::string UnitList(QuantityKind kind) {
  std::vector<std::string_view> symbols;
  for (const Unit& unit : kUnits) {
    if (unit.kind == kind && unit.listed) symbols.push_back(unit.symbol);
  }
  std::string list;
  for (std::size_t i = 0; i < symbols.size(); ++i) {
    if (i > 0) list += (i + 1 == symbols.size()) ? " or " : ", ";
    list += symbols[i];
  }
  return list;
}

std::string FormatQuantity(double si_value, QuantityKind kind) {
  if (std::isinf(si_value) && si_value > 0) {
    if (kind == QuantityKind::kMass) return "fixed";
    if (kind == QuantityKind::kLength) return "flat";
  }
  switch (kind) {
    case QuantityKind::kMass: return FormatSignificant(si_value) + " kg";
    case QuantityKind::kLength: return FormatSignificant(si_value * 1e3) + " mm";
    case QuantityKind::kSpeed: return FormatSignificant(si_value) + " m/s";
    case QuantityKind::kModulus: {
      const double magnitude = std::abs(si_value);
      if (magnitude >= 1e9) return FormatSignificant(si_value / 1e9) + " GPa";
      if (magnitude >= 1e6) return FormatSignificant(si_value / 1e6) + " MPa";
      if (magnitude >= 1e3) return FormatSignificant(si_value / 1e3) + " kPa";
      return FormatSignificant(si_value) + " Pa";
    }
    case QuantityKind::kDensity: return FormatSignificant(si_value) + " kg/m\u00b3";
    case QuantityKind::kDimensionless: return FormatSignificant(si_value);
    case QuantityKind::kEnergyDensity: return FormatSignificant(si_value / 1e4) + " J/cm\u00b2";
    case QuantityKind::kTime:
      if (std::abs(si_value) < 1.0) return FormatSignificant(si_value * 1e3) + " ms";
      return FormatSignificant(si_value) + " s";
    case QuantityKind::kAcceleration: return FormatSignificant(si_value) + " m/s\u00b2";
    case QuantityKind::kDampingCoefficient: return FormatSignificant(si_value) + " s/m";
    case QuantityKind::kStiffness:
      if (std::abs(si_value) >= 1e3) return FormatSignificant(si_value / 1e3) + " kN/m";
      return FormatSignificant(si_value) + " N/m";
    case QuantityKind::kViscousDamping: return FormatSignificant(si_value) + " N\u00b7s/m";
    case QuantityKind::kArea: return FormatSignificant(si_value * 1e4) + " cm\u00b2";
  }
  return FormatSignificant(si_value);
}

void CheckBareNumber(double si_value, std::string_view typed, const QuantitySpec& spec,
                     std::string_view name, std::string_view quote) {
  if (!spec.has_plausible_range() || !std::isfinite(si_value) || !(si_value > 0.0)) return;
  if (si_value >= spec.plausible_min && si_value <= spec.plausible_max) return;

  const std::string_view si_unit = SiUnit(spec.kind);
  const std::string head = std::string(name) + " " + Shortened(typed) +
                           ": a bare number is in " + std::string(SiUnitName(spec.kind)) + " (" +
                           FormatNumber(si_value) + " " + std::string(si_unit) + ")";
  std::string likely_units;
  for (const std::string_view likely : spec.likely_units) {
    if (!likely.empty()) likely_units += std::string(likely_units.empty() ? "" : ", ") + std::string(likely);
  }
  const auto spelled = [&](std::string_view unit) {
    return std::string(quote) + Shortened(typed) + std::string(unit) + std::string(quote);
  };
  for (const std::string_view likely : spec.likely_units) {
    const Unit* unit = likely.empty() ? nullptr : FindUnit(likely);
    if (unit == nullptr) continue;
    const std::optional<double> reading = ApplyUnit(typed, si_value, *unit);
    if (reading && *reading >= spec.plausible_min && *reading <= spec.plausible_max) {
      throw std::invalid_argument(head + "; write " + spelled(likely) + " or " +
                                  spelled(si_unit));
    }
  }
  throw std::invalid_argument(
      head + ", outside the plausible range for the " +
      std::string(spec.what.empty() ? std::string_view("value") : spec.what) + " (" +
      FormatQuantity(spec.plausible_min, spec.kind) + " to " +
      FormatQuantity(spec.plausible_max, spec.kind) + "); write it with a unit, e.g. " +
      likely_units + " or " + std::string(si_unit));
}

double ParseQuantity(std::string_view text, const QuantitySpec& spec, std::string_view name) {
  const std::string_view s = Trim(text);
  if (s.empty()) Fail(name, "empty value; expected " + WhatIsExpected(spec.kind), text);

  if (EqualsIgnoringCase(s, "fixed")) {
    if (!spec.allow_fixed) Fail(name, "'fixed' is only allowed for a mass", text);
    return covopt::kFixed;
  }
  if (EqualsIgnoringCase(s, "flat")) {
    if (!spec.allow_flat) Fail(name, "'flat' is only allowed for the robot radius", text);
    return covopt::kFlat;
  }

  // The number. from_chars takes no '+' and no leading spaces; a '-' is left to it.
  std::string_view number = s;
  if (number.front() == '+' && number.size() > 1 && number[1] != '-') number.remove_prefix(1);
  const std::string_view unsigned_part = number.substr(number.front() == '-' ? 1 : 0);
  if (StartsWithIgnoringCase(unsigned_part, "nan") || StartsWithIgnoringCase(unsigned_part, "inf")) {
    Fail(name, "not a finite number", text);
  }
  double value = 0.0;
  const char* const begin = number.data();
  const char* const end = number.data() + number.size();
  const auto [stop, ec] = std::from_chars(begin, end, value, std::chars_format::general);
  if (ec == std::errc::invalid_argument) {
    Fail(name, "not a number; expected " + WhatIsExpected(spec.kind), text);
  }
  if (ec == std::errc::result_out_of_range) Fail(name, "number out of range", text);
  const std::string_view digits = number.substr(0, static_cast<std::size_t>(stop - begin));

  // The unit.
  const std::string_view rest = Trim(number.substr(digits.size()));
  if (rest.empty()) {
    CheckBareNumber(value, Trim(s.substr(0, s.size() - number.size() + digits.size())), spec,
                    name);
    return value;
  }
  if (!StartsUnit(rest)) {
    Fail(name,
         rest.front() == ',' ? "malformed number; use '.' as the decimal separator"
                             : "malformed number",
         text);
  }
  const Unit* unit = FindUnit(rest);
  if (unit == nullptr) {
    // A case slip ("mpa", "KG") gets a suggestion among the fitting units.
    const auto near = std::find_if(kUnits.begin(), kUnits.end(), [&](const Unit& u) {
      return u.kind == spec.kind && EqualsIgnoringCase(u.symbol, rest);
    });
    if (near != kUnits.end()) {
      Fail(name, "unknown unit '" + Shortened(rest) + "'; did you mean '" +
                     std::string(near->symbol) + "'?",
           text);
    }
    // "3.7kg-5.8kg": a range written with a dash.
    const std::size_t dash = rest.find('-');
    if (dash != std::string_view::npos && dash + 1 < rest.size() &&
        (std::isdigit(static_cast<unsigned char>(rest[dash + 1])) || rest[dash + 1] == '.')) {
      const std::string low = std::string(s.substr(0, s.size() - rest.size())) + std::string(rest.substr(0, dash));
      Fail(name, "a range is written LO..HI with two dots, e.g. '" + Shortened(low + ".." + std::string(rest.substr(dash + 1))) +
                     "' (a dash reads as part of a unit)",
           text);
    }
    if (spec.kind == QuantityKind::kDimensionless) {
      Fail(name, "unexpected '" + Shortened(rest) + "' after the number; " + Advice(spec.kind),
           text);
    }
    Fail(name, "unknown unit '" + Shortened(rest) + "' for " + std::string(Describe(spec.kind)) +
                   "; " + Advice(spec.kind),
         text);
  }
  if (unit->kind != spec.kind) {
    if (spec.kind == QuantityKind::kDimensionless) {
      Fail(name, "unit '" + Shortened(rest) + "' does not fit a dimensionless value; " +
                     Advice(spec.kind),
           text);
    }
    Fail(name, "unit '" + Shortened(rest) + "' is not " + std::string(Describe(spec.kind)) +
                   "; " + Advice(spec.kind),
         text);
  }
  const std::optional<double> si = ApplyUnit(digits, value, *unit);
  if (!si) Fail(name, "number out of range", text);
  return *si;
}

}  // namespace covopt
