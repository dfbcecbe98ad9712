// Reading catalogs from TOML (toml++, private to this file): the built-in one and users'.
// Every error names source:line:column, the key, and what is allowed.
#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <span>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "covopt/internal/toml.hpp"

#include "builtin_catalog.hpp"
#include "covopt/internal/toml_text.hpp"
#include "covopt/core/quantity.hpp"
#include "covopt/materials/catalog.hpp"
#include "text.hpp"
#include "validation.hpp"

namespace covopt::materials {
namespace {

using covopt::internal::TypeName;
using covopt::internal::Where;
using internal::FormatNumber;

constexpr std::array<std::string_view, 18> kKeys{
    internal::kKeyName,     internal::kKeyFamily,         internal::kKeyModulus,
    internal::kKeyPoisson,  internal::kKeyDensity,        internal::kKeyBasis,
    internal::kKeySource,   internal::kKeyNote,           internal::kKeyStrength,
    internal::kKeyStrengthMethod, internal::kKeyStrengthSource, internal::kKeyCurve,
    internal::kKeyCurveSource, internal::kKeyCurveRate,   internal::kKeyRecovers,
    internal::kKeyRateFactor, internal::kKeyBand,         internal::kKeyShape};

/// A compressive strength without a unit is read as pascals and must be plausible.
constexpr QuantitySpec kStrengthSpec{QuantityKind::kModulus,   false, false,
                                     kPlausibleStrengthMin_Pa, kPlausibleStrengthMax_Pa,
                                     {"kPa", "MPa"},           "compressive strength"};
/// A curve's stress and a band's bounds: a string with a unit, 1 Pa to 10 GPa.
constexpr QuantitySpec kCurveStressSpec{QuantityKind::kModulus, false, false, kMinCurveStress_Pa,
                                        kMaxCurveStress_Pa,      {"kPa", "MPa"}, "curve stress"};
constexpr std::string_view kRequiredKeys =
    "name, family, youngs_modulus_Pa, modulus_basis, source";

/// Keys people are likely to write for ours, beyond typos.
constexpr std::array<std::pair<std::string_view, std::string_view>, 33> kKeyAliases{{
    {"curve", internal::kKeyCurve},
    {"stress_strain", internal::kKeyCurve},
    {"stress_strain_curve", internal::kKeyCurve},
    {"rate", internal::kKeyCurveRate},
    {"strain_rate", internal::kKeyCurveRate},
    {"recovery", internal::kKeyRecovers},
    {"band", internal::kKeyBand},
    {"grade_band", internal::kKeyBand},
    {"shape", internal::kKeyShape},
    {"e", internal::kKeyModulus},
    {"modulus", internal::kKeyModulus},
    {"young", internal::kKeyModulus},
    {"youngs_modulus", internal::kKeyModulus},
    {"elastic_modulus", internal::kKeyModulus},
    {"nu", internal::kKeyPoisson},
    {"poisson", internal::kKeyPoisson},
    {"rho", internal::kKeyDensity},
    {"density", internal::kKeyDensity},
    {"basis", internal::kKeyBasis},
    {"reference", internal::kKeySource},
    {"ref", internal::kKeySource},
    {"url", internal::kKeySource},
    {"citation", internal::kKeySource},
    {"notes", internal::kKeyNote},
    {"comment", internal::kKeyNote},
    {"strength", internal::kKeyStrength},
    {"compressive_strength", internal::kKeyStrength},
    {"crush_strength", internal::kKeyStrength},
    {"sigma_c", internal::kKeyStrength},
    {"crush", internal::kKeyStrength},
    {"method", internal::kKeyStrengthMethod},
    {"test_method", internal::kKeyStrengthMethod},
    {"strength_reference", internal::kKeyStrengthSource},
}};

/// What the user wrote, for messages: a string in quotes, a number as a number.
std::string Shown(const toml::node& node) {
  if (const auto* s = node.as_string()) return "\"" + s->get() + "\"";
  if (const auto* i = node.as_integer()) return std::to_string(i->get());
  if (const auto* f = node.as_floating_point()) return FormatNumber(f->get());
  return std::string(TypeName(node));
}

std::optional<double> AsNumber(const toml::node& node) {
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  if (const auto* f = node.as_floating_point()) return f->get();
  return std::nullopt;
}

/// The key `unknown` was probably meant to be, if any.
std::optional<std::string_view> KeySuggestion(std::string_view unknown) {
  const std::string lower = internal::Lower(unknown);
  for (const auto& [alias, key] : kKeyAliases) {
    if (lower == alias) return key;
  }
  const std::vector<std::string_view> keys(kKeys.begin(), kKeys.end());
  if (auto closest = internal::Closest(unknown, keys)) return closest;
  if (lower.size() >= 3) {
    for (const std::string_view key : kKeys) {
      if (internal::Lower(key).find(lower) != std::string::npos) return key;
    }
  }
  return std::nullopt;
}

std::string KeyList() {
  std::string list;
  for (const std::string_view key : kKeys) {
    if (!list.empty()) list += ", ";
    list += key;
  }
  return list;
}

/// Reads the [[material]] table number `index` (1-based) of `source`.
class EntryReader {
 public:
  EntryReader(const toml::table& table, std::string_view source, std::size_t index)
      : table_(table), source_(source), label_("material #" + std::to_string(index)) {}

  Material Read() {
    RejectUnknownKeys();
    Material m;
    m.origin = Where(source_, table_.source().begin);
    m.name = RequiredText(internal::kKeyName, true);
    label_ = "material '" + m.name + "'";
    m.family = RequiredText(internal::kKeyFamily, false);
    m.youngs_modulus_Pa = ReadModulus();
    m.poisson_ratio = ReadPoisson();
    m.density_kg_per_m3 = ReadDensity();
    m.modulus_basis = ReadBasis();
    m.source = RequiredText(internal::kKeySource, false);
    if (const toml::node* note = table_.get(internal::kKeyNote)) {
      if (!note->is_string()) Fail(*note, internal::kKeyNote, "must be a string, got " + Shown(*note));
      m.note = note->as_string()->get();
    }
    ReadStrength(m);
    ReadCurve(m);
    return m;
  }

 private:
  [[noreturn]] void Fail(const toml::node& node, std::string_view key, const std::string& problem) {
    const std::string where = Where(source_, node.source().begin);
    throw CatalogError(where + ": " + label_ + ": " + std::string(key) + " " + problem, where,
                       std::string(key));
  }

  [[noreturn]] void Missing(std::string_view key) {
    const std::string where = Where(source_, table_.source().begin);
    throw CatalogError(where + ": " + label_ + " has no '" + std::string(key) +
                           "' (required keys: " + std::string(kRequiredKeys) + ")",
                       where, std::string(key));
  }

  /// The first unknown key in file order is reported.
  void RejectUnknownKeys() {
    const toml::key* first = covopt::internal::FirstUnknownKey(table_, kKeys);
    if (first == nullptr) return;
    const std::string where = Where(source_, first->source().begin);
    const auto suggestion = KeySuggestion(first->str());
    throw CatalogError(
        where + ": " + label_ + ": unknown key '" + std::string(first->str()) + "'; " +
            (suggestion ? "did you mean '" + std::string(*suggestion) + "'?"
                        : "the keys are " + KeyList()),
        where, std::string(first->str()));
  }

  std::string RequiredText(std::string_view key, bool is_name) {
    const toml::node* node = table_.get(key);
    if (node == nullptr) Missing(key);
    if (!node->is_string()) Fail(*node, key, "must be a string, got " + Shown(*node));
    std::string text = node->as_string()->get();
    if (auto problem = internal::TextProblem(text, is_name)) Fail(*node, key, *problem);
    return text;
  }

  /// A number (SI, which must be plausible for `spec`) or a string with a unit, as in scene
  /// files; empty for another type, which the caller reports.
  std::optional<double> ReadQuantity(const toml::node& node, std::string_view key,
                                     const QuantitySpec& spec) {
    try {
      if (const auto value = AsNumber(node)) {
        CheckBareNumber(*value, Shown(node), spec, key, "\"");
        return value;
      }
      if (const auto* text = node.as_string()) return ParseQuantity(text->get(), spec, key);
    } catch (const std::invalid_argument& e) {
      const std::string where = Where(source_, node.source().begin);
      throw CatalogError(where + ": " + label_ + ": " + e.what(), where, std::string(key));
    }
    return std::nullopt;
  }

  double ReadModulus() {
    const std::string_view key = internal::kKeyModulus;
    const toml::node* node = table_.get(key);
    if (node == nullptr) Missing(key);
    const auto value = ReadQuantity(*node, key, quantity_specs::kCoveringModulus);
    if (!value) {
      Fail(*node, key,
           "must be a number in Pa or a string with a unit, e.g. 27.6e6 or \"27.6MPa\" (got " +
               Shown(*node) + ")");
    }
    if (auto problem = internal::ModulusProblem(*value)) Fail(*node, key, *problem);
    return *value;
  }

  std::optional<double> ReadPoisson() {
    const std::string_view key = internal::kKeyPoisson;
    const toml::node* node = table_.get(key);
    if (node == nullptr) return std::nullopt;
    if (const auto* text = node->as_string(); text != nullptr && text->get() == "unknown") {
      return std::nullopt;
    }
    const auto value = AsNumber(*node);
    if (!value) {
      Fail(*node, key, "must be a number in (-1, 0.5], or \"unknown\" (got " + Shown(*node) + ")");
    }
    if (auto problem = internal::PoissonProblem(*value)) Fail(*node, key, *problem);
    return value;
  }

  std::optional<double> ReadDensity() {
    const std::string_view key = internal::kKeyDensity;
    const toml::node* node = table_.get(key);
    if (node == nullptr) return std::nullopt;
    const auto* text = node->as_string();
    const auto value = text != nullptr && text->get() == "unknown"
                           ? std::nullopt
                           : ReadQuantity(*node, key, quantity_specs::kMaterialDensity);
    if (!value) {
      Fail(*node, key, "must be a number in kg/m³ or a string with a unit, e.g. 50 or "
                       "\"0.05g/cm3\"; leave it out if unknown (got " +
                           Shown(*node) + ")");
    }
    if (auto problem = internal::DensityProblem(*value)) Fail(*node, key, *problem);
    return value;
  }

  ModulusBasis ReadBasis() {
    const std::string_view key = internal::kKeyBasis;
    const toml::node* node = table_.get(key);
    if (node == nullptr) Missing(key);
    std::vector<std::string> names;
    std::vector<std::string_view> views;
    for (const ModulusBasis b : {ModulusBasis::kCompressive, ModulusBasis::kTensile,
                                 ModulusBasis::kBending, ModulusBasis::kFitted,
                                 ModulusBasis::kAsPrinted, ModulusBasis::kHardness}) {
      names.emplace_back(ToString(b));
      views.push_back(ToString(b));
    }
    const std::string allowed = "must be " + internal::JoinAlternatives(names, false);
    if (!node->is_string()) Fail(*node, key, allowed + " (got " + Shown(*node) + ")");
    const std::string& text = node->as_string()->get();
    if (const auto basis = ParseModulusBasis(text)) return *basis;
    const auto near = internal::Closest(text, views);
    Fail(*node, key,
         allowed + " (got " + Shown(*node) + ")" +
             (near ? "; did you mean '" + std::string(*near) + "'?" : std::string()));
  }

  /// strength_method or strength_source: absent (empty) or non-blank text.
  std::string OptionalText(std::string_view key) {
    const toml::node* node = table_.get(key);
    if (node == nullptr) return {};
    if (!node->is_string()) Fail(*node, key, "must be a string, got " + Shown(*node));
    std::string text = node->as_string()->get();
    if (auto problem = internal::TextProblem(text, false)) Fail(*node, key, *problem);
    return text;
  }

  /// compressive_strength_Pa, strength_method and strength_source. An absent
  /// compressive_strength_Pa is "unknown" (catalogs written before it existed).
  void ReadStrength(Material& m) {
    const std::string_view key = internal::kKeyStrength;
    const toml::node* node = table_.get(key);
    const toml::node* method = table_.get(internal::kKeyStrengthMethod);
    const toml::node* source = table_.get(internal::kKeyStrengthSource);
    m.strength_method = OptionalText(internal::kKeyStrengthMethod);
    m.strength_source = OptionalText(internal::kKeyStrengthSource);

    const std::string allowed = "must be " + std::string(internal::kStrengthAllowed);
    if (node == nullptr) {
      m.crush_behaviour = CrushBehaviour::kUnknown;
    } else if (const auto* text = node->as_string();
               text != nullptr && text->get() == internal::kDoesNotCrush) {
      m.crush_behaviour = CrushBehaviour::kDoesNotCrush;
    } else if (text != nullptr && text->get() == internal::kUnknownStrength) {
      m.crush_behaviour = CrushBehaviour::kUnknown;
    } else if (text != nullptr && !StartsLikeANumber(text->get())) {
      const auto near = internal::Closest(
          text->get(), {internal::kDoesNotCrush, internal::kUnknownStrength, "does-not-crush"});
      std::string hint;
      if (near) {
        hint = "; did you mean '" +
               std::string(*near == "does-not-crush" ? internal::kDoesNotCrush : *near) + "'?";
      }
      Fail(*node, key, allowed + " (got " + Shown(*node) + ")" + hint);
    } else {
      const auto value = ReadQuantity(*node, key, kStrengthSpec);
      if (!value) Fail(*node, key, allowed + " (got " + Shown(*node) + ")");
      if (auto problem = internal::StrengthProblem(*value)) Fail(*node, key, *problem);
      m.crush_behaviour = CrushBehaviour::kCrushes;
      m.compressive_strength_Pa = *value;
    }

    // What the value asks of strength_method and strength_source.
    const std::string shown = node == nullptr ? std::string() : Shown(*node);
    switch (m.crush_behaviour) {
      case CrushBehaviour::kCrushes:
      case CrushBehaviour::kDoesNotCrush: {
        const bool crushes = m.crush_behaviour == CrushBehaviour::kCrushes;
        if (m.strength_method.empty()) {
          Fail(*node, key,
               shown + " needs a strength_method: " +
                   (crushes ? "the test method and what it measures, e.g. \"ASTM D1621, at "
                              "yield or 10 % strain\""
                            : "why it does not crush, e.g. \"flexible open-cell foam: "
                              "densifies, no crush strength\""));
        }
        if (m.strength_source.empty()) {
          Fail(*node, key,
               shown + " needs a strength_source: a URL or a citation for " +
                   (crushes ? "the strength" : "\"does not crush\""));
        }
        break;
      }
      case CrushBehaviour::kUnknown: {
        const toml::node* extra = method != nullptr ? method : source;
        if (extra != nullptr) {
          const std::string_view extra_key =
              method != nullptr ? internal::kKeyStrengthMethod : internal::kKeyStrengthSource;
          Fail(*extra, extra_key,
               std::string("is given but compressive_strength_Pa is ") +
                   (node == nullptr ? "missing (unknown)" : "\"unknown\"") +
                   "; give the strength (with a unit) or \"does not crush\", or leave " +
                   std::string(extra_key) + " out (a note may say why it is unknown)");
        }
        break;
      }
    }
  }

  /// compressive_curve and the keys that go with it (curve_source, curve_rate, recovers,
  /// rate_factor, stress_at_25_band, curve_shape); their rules are internal::CurveFieldsProblem's.
  void ReadCurve(Material& m) {
    const toml::node* curve = table_.get(internal::kKeyCurve);
    if (curve != nullptr) m.compressive_curve = std::make_shared<const CompressiveCurve>(ReadCurvePoints(*curve));
    m.curve_source = OptionalText(internal::kKeyCurveSource);
    m.curve_shape = OptionalText(internal::kKeyShape);
    if (const toml::node* rate = table_.get(internal::kKeyCurveRate)) ReadCurveRate(*rate, m);
    if (const toml::node* recovers = table_.get(internal::kKeyRecovers)) {
      if (!recovers->is_boolean()) {
        Fail(*recovers, internal::kKeyRecovers,
             "must be true (a flexible foam that recovers) or false (a crushable liner) (got " + Shown(*recovers) + ")");
      }
      m.recovers = recovers->as_boolean()->get();
    }
    if (const toml::node* factor = table_.get(internal::kKeyRateFactor)) {
      const auto [low, high] = ReadPair(*factor, internal::kKeyRateFactor, nullptr);
      m.rate_factor = Bounds{low, high};
    }
    if (const toml::node* band = table_.get(internal::kKeyBand)) {
      const auto [low, high] = ReadPair(*band, internal::kKeyBand, &kCurveStressSpec);
      m.stress_at_25_band_Pa = Bounds{low, high};
    }
    if (const auto problem = internal::CurveFieldsProblem(m)) {
      const toml::node* at = table_.get(problem->first);
      if (at == nullptr) at = curve;
      if (at == nullptr) at = &table_;
      Fail(*at, problem->first, problem->second);
    }
  }

  /// curve_rate: "quasi-static", "unknown" or a rate with its unit.
  void ReadCurveRate(const toml::node& node, Material& m) {
    const std::string_view key = internal::kKeyCurveRate;
    const std::string allowed = "must be " + std::string(internal::kCurveRateAllowed);
    if (!node.is_string()) Fail(node, key, allowed + " (got " + Shown(node) + ")");
    const std::string& text = node.as_string()->get();
    if (text == internal::kQuasiStatic || text == internal::kUnknownRate) {
      m.curve_rate = text;
      return;
    }
    const auto rate = internal::ParseCurveRate(text);
    if (!rate) Fail(node, key, allowed + " (got " + Shown(node) + ")");
    if (!(*rate > 0.0 && *rate <= internal::kMaxCurveRate_per_s)) {
      Fail(node, key, "must be a strain rate in (0, 1e6] 1/s (got " + Shown(node) + ")");
    }
    m.curve_rate = text;
    m.curve_rate_per_s = *rate;
  }

  /// [low, high]: two numbers (spec null), or two stresses with their units (spec set).
  std::pair<double, double> ReadPair(const toml::node& node, std::string_view key, const QuantitySpec* spec) {
    const std::string shape = spec != nullptr ? "[low, high] with units, e.g. [\"34.5kPa\", \"62.1kPa\"]"
                                              : "[low, high], e.g. [1, 3]";
    const auto* array = node.as_array();
    if (array == nullptr || array->size() != 2) Fail(node, key, "must be " + shape + " (got " + Shown(node) + ")");
    double values[2] = {0.0, 0.0};
    for (std::size_t i = 0; i < 2; ++i) {
      const toml::node& item = *array->get(i);
      const auto value = spec != nullptr ? ReadStress(item, key) : AsNumber(item);
      if (!value) Fail(item, key, "must be " + shape + " (got " + Shown(item) + " in it)");
      values[i] = *value;
    }
    return {values[0], values[1]};
  }

  /// A curve stress: a string with a unit ("57.3kPa"); a bare number is refused.
  std::optional<double> ReadStress(const toml::node& node, std::string_view key) {
    if (AsNumber(node)) {
      Fail(node, key, "stress " + Shown(node) + " needs its unit, e.g. \"" + Shown(node) +
                          "kPa\" or \"" + Shown(node) + " Pa\" (a curve's stresses are written with units)");
    }
    if (!node.is_string()) return std::nullopt;
    return ReadQuantity(node, key, kCurveStressSpec);
  }

  /// A curve strain: a fraction in (0, 1) or a percentage ("25%").
  double ReadStrain(const toml::node& node) {
    const std::string_view key = internal::kKeyCurve;
    if (const auto value = AsNumber(node)) return *value;
    if (const auto* text = node.as_string()) {
      std::string t = text->get();
      while (!t.empty() && t.back() == ' ') t.pop_back();
      if (!t.empty() && t.back() == '%') {
        t.pop_back();
        try {
          std::size_t used = 0;
          const double percent = std::stod(t, &used);
          if (t.find_first_not_of(' ', used) == std::string::npos) return percent / 100.0;
        } catch (const std::exception&) {
        }
      }
    }
    Fail(node, key, "strain must be a fraction in (0, 1) or a percentage such as \"25%\" (got " + Shown(node) + ")");
  }

  /// The points of compressive_curve, checked by CompressiveCurve::FromPoints; its message is
  /// placed at the offending point.
  CompressiveCurve ReadCurvePoints(const toml::node& node) {
    const std::string_view key = internal::kKeyCurve;
    const std::string shape = "must be a list of [strain, \"stress with unit\"] points, e.g. [[0.1, \"30kPa\"], "
                              "[0.25, \"57.3kPa\"]] (the origin is implied)";
    const auto* array = node.as_array();
    if (array == nullptr || array->empty()) Fail(node, key, shape + " (got " + Shown(node) + ")");
    std::vector<StrainStressPoint> points;
    for (const toml::node& item : *array) {
      const auto* pair = item.as_array();
      if (pair == nullptr || pair->size() != 2) Fail(item, key, shape + " (got " + Shown(item) + " as a point)");
      const double strain = ReadStrain(*pair->get(0));
      const auto stress = ReadStress(*pair->get(1), key);
      if (!stress) Fail(*pair->get(1), key, "stress must be a string with a unit, e.g. \"57.3kPa\" (got " + Shown(*pair->get(1)) + ")");
      points.push_back({strain, *stress});
    }
    try {
      return CompressiveCurve::FromPoints(points, key);
    } catch (const std::invalid_argument& e) {
      // The first point whose prefix is refused is the offending one (prefix validity is monotone).
      std::size_t lo = 1, hi = points.size();
      while (lo < hi) {
        const std::size_t mid = (lo + hi) / 2;
        try {
          (void)CompressiveCurve::FromPoints(std::span(points).first(mid), key);
          lo = mid + 1;
        } catch (const std::invalid_argument&) {
          hi = mid;
        }
      }
      Fail(*array->get(lo - 1), key, std::string(e.what()).substr(key.size() + 2));
    }
  }

  /// Whether a string value is meant as a number ("172 kPa", "-1MPa", ".5 MPa", "nan").
  static bool StartsLikeANumber(std::string_view text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos) return false;
    const char c = text[first];
    if ((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+') return true;
    const std::string lower = internal::Lower(text.substr(first, 3));
    return lower == "nan" || lower == "inf";
  }

  const toml::table& table_;
  std::string_view source_;
  std::string label_;
};

}  // namespace

Catalog Catalog::FromTomlString(std::string_view toml_text, std::string_view source_name) {
  toml::table root;
  try {
    root = toml::parse(toml_text, source_name);
  } catch (const toml::parse_error& e) {
    const std::string where = Where(source_name, e.source().begin);
    throw CatalogError(where + ": TOML syntax error: " + std::string(e.description()), where, "");
  }

  for (const auto& [key, node] : root) {
    if (key.str() == "material") continue;
    const std::string where = Where(source_name, key.source().begin);
    std::string hint;
    if (std::find(kKeys.begin(), kKeys.end(), key.str()) != kKeys.end()) {
      hint = "; put it under a [[material]] header";
    } else if (internal::Closest(key.str(), {"material"}) ||
               internal::Lower(key.str()).find("material") != std::string::npos) {
      hint = "; did you mean 'material' (each entry starts with [[material]])?";
    } else {
      hint = "; a catalog is a list of [[material]] tables";
    }
    throw CatalogError(where + ": unknown top-level key '" + std::string(key.str()) + "'" + hint,
                       where, std::string(key.str()));
  }

  Catalog catalog;
  const toml::node* entries = root.get("material");
  if (entries == nullptr) return catalog;  // an empty catalog
  const std::string where = Where(source_name, entries->source().begin);
  if (entries->is_table()) {
    throw CatalogError(where + ": 'material' must be a list of tables: write [[material]] "
                               "(double brackets), not [material]",
                       where, "material");
  }
  if (!entries->is_array()) {
    throw CatalogError(where + ": 'material' must be a list of [[material]] tables, got " +
                           std::string(TypeName(*entries)),
                       where, "material");
  }

  std::unordered_map<std::string, const Material*> seen;  // lower-case name -> entry
  std::size_t index = 0;
  for (const toml::node& entry : *entries->as_array()) {
    ++index;
    if (!entry.is_table()) {
      const std::string at = Where(source_name, entry.source().begin);
      throw CatalogError(at + ": material #" + std::to_string(index) +
                             " must be a table ([[material]]), got " +
                             std::string(TypeName(entry)),
                         at, "material");
    }
    Material material = EntryReader(*entry.as_table(), source_name, index).Read();
    if (const Material* existing = catalog.Find(material.name)) {
      const toml::node* name_node = entry.as_table()->get(internal::kKeyName);
      const std::string at = Where(source_name, name_node->source().begin);
      throw CatalogError(at + ": duplicate material name '" + material.name +
                             "': already defined at " + existing->origin +
                             (existing->name != material.name ? " as '" + existing->name + "'"
                                                              : std::string()) +
                             " (names are compared ignoring case)",
                         at, std::string(internal::kKeyName));
    }
    catalog.materials_.push_back(std::move(material));
  }
  return catalog;
}

Catalog Catalog::FromTomlFile(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw CatalogError("cannot read catalog file '" + name + "': it is a directory", name, "");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw CatalogError("cannot read catalog file '" + name + "': " + std::strerror(errno), name,
                       "");
  }
  // At most kMaxCatalogFileBytes + 1 bytes: a device or FIFO is never read forever.
  std::string text(kMaxCatalogFileBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) throw CatalogError("cannot read catalog file '" + name + "'", name, "");
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxCatalogFileBytes) {
    throw CatalogError("catalog file '" + name + "' is larger than " + std::to_string(kMaxCatalogFileBytes >> 20) +
                           " MiB, the most a catalog may be",
                       name, "");
  }
  return FromTomlString(text, name);
}

const Catalog& Catalog::BuiltIn() {
  static const Catalog built_in =
      FromTomlString(internal::kBuiltInCatalogToml, internal::kBuiltInCatalogName);
  return built_in;
}

}  // namespace covopt::materials
