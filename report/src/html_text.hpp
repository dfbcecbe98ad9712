#pragma once
/// @file html_text.hpp
/// The HTML report's text helpers (private to covopt_report): escaping, the reading of numbers
/// and their units, and access to the --json object it is rendered from.

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace covopt::report::internal::html {

using Json = nlohmann::ordered_json;

/// Appends `text` HTML-escaped (safe in element content and in quoted attribute values).
void Escape(std::string& out, std::string_view text);

/// The JSON text of a scalar as the JSON holds it: a string's own characters, a number's
/// shortest round-trip text (nlohmann's, as --json prints it), true/false/null.
std::string ScalarText(const Json& value);

/// `value` with about `significant` digits, for reading (the exact JSON text is kept beside it):
/// plain decimals from 1e-3 to 1e7 (trailing zeros dropped), an exponent beyond.
std::string Significant(double value, int significant = 4);

bool EndsWith(std::string_view text, std::string_view tail);

// Units: the SI unit in a JSON key's suffix, and the display unit the CLI uses for it.

struct Unit {
  std::string si;       ///< "m", "Pa", ...; empty when the key carries none
  std::string display;  ///< "mm", "MPa", "J/cm²", "N/cm²", "cm²"; empty when SI is shown as is
  double factor = 1.0;  ///< display value = SI value × factor
};

Unit UnitOfKey(std::string_view key);
/// `key` without its unit suffix: "mass" for "mass_kg", "thickness" for "thickness_m".
std::string_view WithoutUnit(std::string_view key);

/// The unit of a value named by the CLI's quantity ("kg", "m", "Pa", ...), as in uncertain_inputs.
Unit UnitOfName(std::string_view si);

/// "1.526 kN"-style reading of a value in its display unit, or in SI.
std::string Reading(double value, const Unit& unit);

// JSON access

const Json* Find(const Json& object, std::string_view key);
const Json* FindPath(const Json& object, std::initializer_list<std::string_view> keys);
std::string StringAt(const Json& object, std::string_view key, std::string fallback = "");
std::optional<double> NumberAt(const Json& object, std::string_view key);
bool TrueAt(const Json& object, std::string_view key);

}  // namespace covopt::report::internal::html
