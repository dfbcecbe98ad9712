#include "quantity.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "covopt/core/scene.hpp"
#include "errors.hpp"

namespace covopt::cli {
namespace {

struct Unit {
  std::string_view symbol;
  QuantityKind kind;
  double factor;  ///< SI value of one unit
  bool listed;    ///< shown in messages (false for alternative spellings)
};

// µ is U+00B5 MICRO SIGN, μ is U+03BC GREEK SMALL LETTER MU; both are typed in practice.
constexpr std::array kUnits{
    Unit{"kg", QuantityKind::kMass, 1.0, true},
    Unit{"g", QuantityKind::kMass, 1e-3, true},
    Unit{"t", QuantityKind::kMass, 1e3, true},
    Unit{"m", QuantityKind::kLength, 1.0, true},
    Unit{"cm", QuantityKind::kLength, 1e-2, true},
    Unit{"mm", QuantityKind::kLength, 1e-3, true},
    Unit{"um", QuantityKind::kLength, 1e-6, true},
    Unit{"\u00b5m", QuantityKind::kLength, 1e-6, true},
    Unit{"\u03bcm", QuantityKind::kLength, 1e-6, false},
    Unit{"m/s", QuantityKind::kSpeed, 1.0, true},
    Unit{"mm/s", QuantityKind::kSpeed, 1e-3, true},
    Unit{"cm/s", QuantityKind::kSpeed, 1e-2, true},
    Unit{"km/h", QuantityKind::kSpeed, 1.0 / 3.6, true},
    Unit{"Pa", QuantityKind::kModulus, 1.0, true},
    Unit{"kPa", QuantityKind::kModulus, 1e3, true},
    Unit{"MPa", QuantityKind::kModulus, 1e6, true},
    Unit{"GPa", QuantityKind::kModulus, 1e9, true},
    Unit{"N/m2", QuantityKind::kModulus, 1.0, true},
    Unit{"N/mm2", QuantityKind::kModulus, 1e6, true},
    Unit{"N/m\u00b2", QuantityKind::kModulus, 1.0, false},
    Unit{"N/mm\u00b2", QuantityKind::kModulus, 1e6, false},
    Unit{"kg/m3", QuantityKind::kDensity, 1.0, true},
    Unit{"g/cm3", QuantityKind::kDensity, 1e3, true},
    Unit{"kg/m\u00b3", QuantityKind::kDensity, 1.0, false},
    Unit{"kg/m^3", QuantityKind::kDensity, 1.0, false},
    Unit{"g/cm\u00b3", QuantityKind::kDensity, 1e3, false},
    Unit{"g/cm^3", QuantityKind::kDensity, 1e3, false},
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

std::string_view Example(QuantityKind kind) {
  switch (kind) {
    case QuantityKind::kMass: return "10kg";
    case QuantityKind::kLength: return "15mm";
    case QuantityKind::kSpeed: return "2m/s";
    case QuantityKind::kModulus: return "27.6MPa";
    case QuantityKind::kDensity: return "50kg/m3";
    case QuantityKind::kDimensionless: return "0.3";
  }
  return "";
}

/// "use m/s, mm/s, cm/s or km/h" / "give a plain number".
std::string Advice(QuantityKind kind) {
  if (kind == QuantityKind::kDimensionless) return "give a plain number, e.g. 0.3";
  return "use " + UnitList(kind);
}

[[noreturn]] void Fail(std::string_view name, std::string_view problem, std::string_view text) {
  throw InputError(fmt::format("{}: {} (got '{}')", name, problem, text));
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
  }
  return "unknown";
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
    case QuantityKind::kMass: return fmt::format("{:g} kg", si_value);
    case QuantityKind::kLength: return fmt::format("{:g} mm", si_value * 1e3);
    case QuantityKind::kSpeed: return fmt::format("{:g} m/s", si_value);
    case QuantityKind::kModulus: {
      const double magnitude = std::abs(si_value);
      if (magnitude >= 1e9) return fmt::format("{:g} GPa", si_value / 1e9);
      if (magnitude >= 1e6) return fmt::format("{:g} MPa", si_value / 1e6);
      if (magnitude >= 1e3) return fmt::format("{:g} kPa", si_value / 1e3);
      return fmt::format("{:g} Pa", si_value);
    }
    case QuantityKind::kDensity: return fmt::format("{:g} kg/m³", si_value);
    case QuantityKind::kDimensionless: return fmt::format("{:g}", si_value);
  }
  return fmt::format("{:g}", si_value);
}

double ParseQuantity(std::string_view text, const QuantitySpec& spec, std::string_view name) {
  const std::string_view s = Trim(text);
  if (s.empty()) {
    Fail(name, fmt::format("empty value; expected {} such as {}",
                           spec.kind == QuantityKind::kDimensionless ? "a number" : Describe(spec.kind),
                           Example(spec.kind)),
         text);
  }

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
    Fail(name, fmt::format("not a number; expected {} such as {}",
                           spec.kind == QuantityKind::kDimensionless ? "a number" : Describe(spec.kind),
                           Example(spec.kind)),
         text);
  }
  if (ec == std::errc::result_out_of_range) Fail(name, "number out of range", text);

  // The unit.
  const std::string_view rest = Trim(number.substr(static_cast<std::size_t>(stop - begin)));
  double factor = 1.0;
  if (!rest.empty()) {
    if (!StartsUnit(rest)) {
      Fail(name,
           rest.front() == ',' ? "malformed number; use '.' as the decimal separator"
                               : "malformed number",
           text);
    }
    const auto unit = std::find_if(kUnits.begin(), kUnits.end(),
                                   [&](const Unit& u) { return u.symbol == rest; });
    if (unit == kUnits.end()) {
      // A case slip ("mpa", "KG") gets a suggestion among the fitting units.
      const auto near = std::find_if(kUnits.begin(), kUnits.end(), [&](const Unit& u) {
        return u.kind == spec.kind && EqualsIgnoringCase(u.symbol, rest);
      });
      if (near != kUnits.end()) {
        Fail(name, fmt::format("unknown unit '{}'; did you mean '{}'?", rest, near->symbol), text);
      }
      if (spec.kind == QuantityKind::kDimensionless) {
        Fail(name, fmt::format("unexpected '{}' after the number; {}", rest, Advice(spec.kind)),
             text);
      }
      Fail(name, fmt::format("unknown unit '{}' for {}; {}", rest, Describe(spec.kind),
                             Advice(spec.kind)),
           text);
    }
    if (unit->kind != spec.kind) {
      if (spec.kind == QuantityKind::kDimensionless) {
        Fail(name, fmt::format("unit '{}' does not fit a dimensionless value; {}", rest,
                               Advice(spec.kind)),
             text);
      }
      Fail(name, fmt::format("unit '{}' is not {}; {}", rest, Describe(spec.kind),
                             Advice(spec.kind)),
           text);
    }
    factor = unit->factor;
  }

  const double si = value * factor;
  if (!std::isfinite(si)) Fail(name, "number out of range", text);
  return si;
}

}  // namespace covopt::cli
