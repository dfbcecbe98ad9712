// The HTML report's text helpers (html_text.hpp).
#include "html_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace covopt::report::internal::html {

// ---------------------------------------------------------------------------------------------
// Text

/// Appends `text` HTML-escaped (safe in element content and in quoted attribute values).
void Escape(std::string& out, std::string_view text) {
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
}

/// The JSON text of a scalar as the JSON holds it: a string's own characters, a number's
/// shortest round-trip text (nlohmann's, as --json prints it), true/false/null.
std::string ScalarText(const Json& value) {
  if (value.is_string()) return value.get<std::string>();
  return value.dump();
}

/// `value` with about `significant` digits, for reading (the exact JSON text is kept beside it):
/// plain decimals from 1e-3 to 1e7 (trailing zeros dropped), an exponent beyond.
std::string Significant(double value, int significant) {
  if (!std::isfinite(value)) return value > 0 ? "∞" : (value < 0 ? "−∞" : "NaN");
  char buffer[64];
  const double magnitude = std::fabs(value);
  if (value == 0.0 || (magnitude >= 1e-3 && magnitude < 1e7)) {
    const int exponent = value == 0.0 ? 0 : static_cast<int>(std::floor(std::log10(magnitude)));
    const int decimals = std::max(0, significant - 1 - exponent);
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    std::string text = buffer;
    if (text.find('.') != std::string::npos) {
      while (text.back() == '0') text.pop_back();
      if (text.back() == '.') text.pop_back();
    }
    return text == "-0" ? "0" : text;
  }
  std::snprintf(buffer, sizeof buffer, "%.*g", significant, value);
  return buffer;
}

bool EndsWith(std::string_view text, std::string_view tail) {
  return text.size() >= tail.size() && text.substr(text.size() - tail.size()) == tail;
}

// ---------------------------------------------------------------------------------------------
// Units: the SI unit in a JSON key's suffix, and the display unit the CLI uses for it.

namespace {

struct Suffix {
  std::string_view tail;
  Unit unit;
};

/// The unit suffix `key` ends with, or nullptr.
const Suffix* SuffixOf(std::string_view key) {
  static const Suffix kSuffixes[] = {
      {"_N_s_per_m", {"N·s/m", "", 1.0}},
      {"_N_per_m", {"N/m", "", 1.0}},
      {"_m_per_s2", {"m/s²", "", 1.0}},
      {"_m_per_s", {"m/s", "", 1.0}},
      {"_s_per_m", {"s/m", "", 1.0}},
      {"_J_per_m2", {"J/m²", "J/cm²", 1e-4}},
      {"_kg_per_m3", {"kg/m³", "", 1.0}},
      {"_m2", {"m²", "cm²", 1e4}},
      {"_kg", {"kg", "", 1.0}},
      {"_Pa", {"Pa", "MPa", 1e-6}},
      {"_m", {"m", "mm", 1e3}},
      {"_s", {"s", "", 1.0}},
      {"_N", {"N", "", 1.0}},
      {"_J", {"J", "", 1.0}},
  };
  for (const Suffix& s : kSuffixes) {
    if (EndsWith(key, s.tail)) return &s;
  }
  return nullptr;
}

}  // namespace

Unit UnitOfKey(std::string_view key) {
  const Suffix* s = SuffixOf(key);
  if (!s) return {};
  // ISO/TS 15066's pressures read in N/cm², as the standard and the CLI give them.
  if (s->unit.si == "Pa" && key.find("pressure") != std::string_view::npos) return {"Pa", "N/cm²", 1e-4};
  return s->unit;
}

std::string_view WithoutUnit(std::string_view key) {
  const Suffix* s = SuffixOf(key);
  return s ? key.substr(0, key.size() - s->tail.size()) : key;
}

/// The unit of a value named by the CLI's quantity ("kg", "m", "Pa", ...), as in uncertain_inputs.
Unit UnitOfName(std::string_view si) {
  if (si == "m") return {"m", "mm", 1e3};
  if (si == "Pa") return {"Pa", "MPa", 1e-6};
  if (si.empty() || si == "-" || si == "1") return {};
  return {std::string(si), "", 1.0};
}

/// "1.526 kN"-style reading of a value in its display unit, or in SI.
std::string Reading(double value, const Unit& unit) {
  if (!unit.display.empty()) return Significant(value * unit.factor) + " " + unit.display;
  if (!unit.si.empty()) return Significant(value) + " " + unit.si;
  return Significant(value);
}

// ---------------------------------------------------------------------------------------------
// JSON access

const Json* Find(const Json& object, std::string_view key) {
  if (!object.is_object()) return nullptr;
  const auto it = object.find(std::string(key));
  return it == object.end() ? nullptr : &*it;
}

const Json* FindPath(const Json& object, std::initializer_list<std::string_view> keys) {
  const Json* at = &object;
  for (const std::string_view key : keys) {
    at = Find(*at, key);
    if (!at) return nullptr;
  }
  return at;
}

std::string StringAt(const Json& object, std::string_view key, std::string fallback) {
  const Json* v = Find(object, key);
  return v && v->is_string() ? v->get<std::string>() : fallback;
}

std::optional<double> NumberAt(const Json& object, std::string_view key) {
  const Json* v = Find(object, key);
  if (v && v->is_number()) return v->get<double>();
  return std::nullopt;
}

bool TrueAt(const Json& object, std::string_view key) {
  const Json* v = Find(object, key);
  return v && v->is_boolean() && v->get<bool>();
}

}  // namespace covopt::report::internal::html
