#include "covopt/scene_file/scene_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include <fmt/format.h>
#include "covopt/internal/toml.hpp"

#include "covopt/core/quantity.hpp"
#include "covopt/core/scene_fields.hpp"
#include "covopt/internal/text.hpp"
#include "covopt/internal/toml_text.hpp"
#include "toml_input.hpp"

namespace covopt::scene_file {
namespace {

using covopt::internal::Closest;
using covopt::internal::TypeName;
using covopt::internal::Where;
using internal::NumberText;
using internal::ReadQuantity;
using internal::Shown;

std::string JoinQuoted(const std::vector<std::string_view>& words) {
  std::string joined;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) joined += ", ";
    joined += words[i];
  }
  return joined;
}

std::vector<std::string_view> KeysOf(std::string_view table) {
  std::vector<std::string_view> keys;
  for (const SceneField& field : SceneFields()) {
    if (field.table == table) keys.push_back(field.key);
  }
  if (table == "covering") {
    keys.push_back("material");
    keys.push_back("law");
  }
  if (table == "model") keys.push_back("thresholds");
  if (table == "head") keys.push_back("area");
  if (table == "limits") {
    for (const LimitField& field : LimitFields()) keys.push_back(field.key);
  }
  if (table == "report") {
    for (const std::string_view key : ReportKeys()) keys.push_back(key);
  }
  return keys;
}

/// What one file sets, before it is applied: the scene (a copy) and the extras.
struct Reading {
  Scene scene;
  SceneFileExtras extras;
  std::vector<std::string> set_fields;
  /// The first of covering.modulus / covering.poisson the file sets, for the clash with
  /// covering.material.
  std::optional<std::string> covering_elastic_field;
  bool sets_covering_material = false;
};

[[noreturn]] void UnknownKey(std::string_view source, const toml::key& key,
                             std::string_view table_name) {
  const std::vector<std::string_view> keys = KeysOf(table_name);
  const auto suggestion = Closest(key.str(), keys);
  throw std::invalid_argument(fmt::format(
      "{}: unknown key '{}.{}'; {}", Where(source, key.source()), table_name,
      covopt::internal::EscapeControlCharacters(key.str()),
      suggestion ? fmt::format("did you mean '{}.{}'?", table_name, *suggestion)
                 : fmt::format("[{}] takes {}", table_name, JoinQuoted(keys))));
}

/// Refuses what only SceneFileExtras can hold when the caller gave none.
[[noreturn]] void RefuseExtra(std::string_view where, std::string_view name) {
  throw std::invalid_argument(fmt::format("{}: {} is not read by this command; remove it", where, name));
}

/// The keys that name a choice: model.thresholds, head.area and covering.law. False for any
/// other key.
bool ApplyNamedChoice(std::string_view table_name, std::string_view key_name, const toml::node& node,
                      const std::string& where, Reading& reading) {
  const bool thresholds = table_name == "model" && key_name == "thresholds";
  const bool area = table_name == "head" && key_name == "area";
  const bool law = table_name == "covering" && key_name == "law";
  if (!thresholds && !area && !law) return false;
  const std::string name = fmt::format("{}.{}", table_name, key_name);
  if (!node.is_string()) {
    throw std::invalid_argument(fmt::format("{}: {}: expected a string, {}, got {}", where, name,
                                            thresholds ? "\"cumulative\" or \"literal\""
                                            : law      ? "\"auto\", \"foam\" or \"hertz\""
                                                       : "one of " + HeadAreaChoices(),
                                            TypeName(node)));
  }
  try {
    if (thresholds) reading.scene.model.thresholds = ParseThresholds(**node.as_string(), name);
    if (area) reading.scene.head.area = ParseHeadAreaOrThrow(name, **node.as_string());
    if (law) reading.scene.covering.law = ParseCoveringLawOrThrow(**node.as_string(), name);
    reading.set_fields.push_back(name);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("{}: {}", where, e.what()));
  }
  return true;
}

void ApplyLimits(const toml::table& table, std::string_view source, bool extras_wanted,
                 Reading& reading) {
  const auto fields = LimitFields();
  for (const auto& [key, node] : table) {
    const std::string_view key_name = key.str();  // a structured binding is not captured
    const auto field = std::find_if(fields.begin(), fields.end(),
                                    [&](const LimitField& f) { return f.key == key_name; });
    if (field == fields.end()) UnknownKey(source, key, "limits");
    const std::string name = field->dotted_name();
    const std::string where = Where(source, node.source());
    if (!extras_wanted) RefuseExtra(where, name);
    const double value = ReadQuantity(node, field->spec, name,
                                      field->key == "laceration"  ? "1MPa"
                                      : field->key == "contusion" ? "2.52J/cm2"
                                                                  : "1.5",
                                      source);
    try {
      CheckLimitValue(*field, value, name, Shown(node));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(fmt::format("{}: {}", where, e.what()));
    }
    if (field->key == "laceration") reading.extras.laceration_limit_Pa = value;
    if (field->key == "contusion") reading.extras.contusion_limit_J_per_m2 = value;
    if (field->key == "safety_factor") reading.extras.safety_factor = value;
    reading.set_fields.push_back(name);
  }
}

/// The [report] table: known keys, each a string (margin_threshold also a number); the values
/// are read by the report's settings reader (covopt/report/report_settings.hpp).
void ApplyReport(const toml::table& table, std::string_view source, bool extras_wanted, Reading& reading) {
  const auto keys = ReportKeys();
  for (const auto& [key, node] : table) {
    const std::string_view key_name = key.str();
    if (std::find(keys.begin(), keys.end(), key_name) == keys.end()) UnknownKey(source, key, "report");
    const std::string name = fmt::format("report.{}", key_name);
    const std::string where = Where(source, node.source());
    if (!extras_wanted) RefuseExtra(where, name);
    const bool threshold = key_name == "margin_threshold";
    ReportSetting setting{std::string(key_name), 0.0, fmt::format("{}: {}", where, name)};
    if (node.is_string()) {
      setting.value = **node.as_string();
    } else if (threshold && (node.is_integer() || node.is_floating_point())) {
      setting.value = *node.value<double>();
    } else {
      throw std::invalid_argument(fmt::format("{}: expected {}, got {}", setting.name,
                                              threshold ? "a share, 0.1 or \"10%\"" : "a string", TypeName(node)));
    }
    reading.extras.report.push_back(std::move(setting));
    reading.set_fields.push_back(name);
  }
}

void ApplyTable(std::string_view table_name, const toml::table& table, std::string_view source,
                bool extras_wanted, Reading& reading) {
  if (table_name == "limits") {
    ApplyLimits(table, source, extras_wanted, reading);
    return;
  }
  if (table_name == "report") {
    ApplyReport(table, source, extras_wanted, reading);
    return;
  }
  const auto fields = SceneFields();
  const Scene defaults;
  for (const auto& [key, node] : table) {
    const std::string_view key_name = key.str();
    const std::string where = Where(source, node.source());
    if (ApplyNamedChoice(table_name, key_name, node, where, reading)) continue;
    if (table_name == "covering" && key_name == "material") {
      if (!extras_wanted) RefuseExtra(where, "covering.material");
      if (!node.is_string()) {
        throw std::invalid_argument(fmt::format("{}: covering.material: expected a string, a catalog "
                                     "material's name such as \"polystyrene foam 27.6\", got {}",
                                     where, TypeName(node)));
      }
      const std::string& name = **node.as_string();
      if (name.find_first_not_of(" \t") == std::string::npos) {
        throw std::invalid_argument(fmt::format("{}: covering.material: empty name; give a catalog "
                                     "material's name (see 'covopt materials list')",
                                     where));
      }
      reading.extras.covering_material = name;
      reading.extras.covering_material_where = where;
      reading.sets_covering_material = true;
      reading.set_fields.emplace_back("covering.material");
      continue;
    }
    const auto field = std::find_if(fields.begin(), fields.end(), [&](const SceneField& f) {
      return f.table == table_name && f.key == key_name;
    });
    if (field == fields.end()) UnknownKey(source, key, table_name);
    if (node.is_string() && IsRangeText(**node.as_string())) {
      const std::string name = fmt::format("{}: {}", where, field->dotted_name());
      if (!extras_wanted) {
        throw std::invalid_argument(fmt::format("{}: a range (an uncertain input) is taken by simulate, optimize and "
                                     "speed-limit only (got '{}')",
                                     name, **node.as_string()));
      }
      reading.extras.ranges.push_back(ParseSceneRange(**node.as_string(), *field, name));
      reading.set_fields.push_back(field->dotted_name());
      continue;
    }
    Scene example = defaults;
    field->field(reading.scene) =
        ReadQuantity(node, field->spec, field->dotted_name(),
                     FormatQuantity(field->field(example), field->spec.kind), source);
    reading.set_fields.push_back(field->dotted_name());
    if (table_name == "covering" && (key_name == "modulus" || key_name == "poisson") &&
        !reading.covering_elastic_field) {
      reading.covering_elastic_field = field->dotted_name();
    }
  }
}

}  // namespace

std::vector<std::string> ApplySceneToml(std::string_view toml_text, std::string_view source,
                                        Scene& scene, SceneFileExtras* extras) {
  toml::table root;
  try {
    root = toml::parse(toml_text, source);
  } catch (const toml::parse_error& e) {
    throw std::invalid_argument(fmt::format("{}: TOML syntax error: {}", Where(source, e.source()),
                                 e.description()));
  }

  // Work on copies so that a bad file leaves `scene` and `extras` untouched.
  Reading reading{scene, extras ? *extras : SceneFileExtras{}, {}, std::nullopt, false};
  const auto tables = SceneTables();
  const std::vector<std::string_view> table_names(tables.begin(), tables.end());
  for (const auto& [key, node] : root) {
    const std::string_view name = key.str();
    if (std::find(tables.begin(), tables.end(), name) == tables.end()) {
      // A known field at the top level is probably missing its table header.
      std::string hint;
      for (const SceneField& field : SceneFields()) {
        if (field.key == name) {
          hint = fmt::format("; put '{}' under a table such as [{}]", name, field.table);
          break;
        }
      }
      for (const LimitField& field : LimitFields()) {
        if (hint.empty() && field.key == name) {
          hint = fmt::format("; put '{}' under [limits]", name);
        }
      }
      if (hint.empty()) {
        const auto suggestion = Closest(name, table_names);
        hint = suggestion ? fmt::format("; did you mean '{}'?", *suggestion)
                          : fmt::format("; the tables are {}", JoinQuoted(table_names));
      }
      throw std::invalid_argument(
          fmt::format("{}: unknown table '{}'{}", Where(source, key.source()),
                      covopt::internal::EscapeControlCharacters(name), hint));
    }
    if (!node.is_table()) {
      throw std::invalid_argument(fmt::format("{}: '{}' must be a table ([{}]), got {}",
                                   Where(source, node.source()), name, name, TypeName(node)));
    }
    ApplyTable(name, *node.as_table(), source, extras != nullptr, reading);
  }
  if (reading.sets_covering_material && reading.covering_elastic_field) {
    throw std::invalid_argument(fmt::format(
        "{}: covering.material '{}' sets the covering's modulus and Poisson ratio; give "
        "either covering.material or {}, not both",
        reading.extras.covering_material_where, *reading.extras.covering_material,
        *reading.covering_elastic_field));
  }
  scene = reading.scene;
  if (extras) *extras = reading.extras;
  return reading.set_fields;
}

std::vector<std::string> ApplySceneFile(const std::filesystem::path& path, Scene& scene,
                                        SceneFileExtras* extras) {
  const std::string text = internal::ReadBoundedFile(path, "scene file", kMaxSceneFileBytes);
  return ApplySceneToml(text, path.string(), scene, extras);
}

}  // namespace covopt::scene_file
