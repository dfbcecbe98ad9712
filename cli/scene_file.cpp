#include "scene_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "errors.hpp"
#include "parse_errors.hpp"
#include "quantity.hpp"
#include "scene_fields.hpp"

namespace covopt::cli {
namespace {

using parse_errors_detail::EditDistance;

/// The closest candidate, if it is close enough to be a likely typo.
std::optional<std::string_view> Closest(std::string_view word,
                                        const std::vector<std::string_view>& candidates) {
  std::optional<std::string_view> best;
  std::size_t best_distance = std::numeric_limits<std::size_t>::max();
  for (const std::string_view candidate : candidates) {
    const std::size_t d = EditDistance(word, candidate);
    if (d < best_distance) {
      best_distance = d;
      best = candidate;
    }
  }
  const std::size_t tolerance = std::max<std::size_t>(2, word.size() / 3);
  if (best && best_distance <= tolerance) return best;
  return std::nullopt;
}

std::string JoinQuoted(const std::vector<std::string_view>& words) {
  std::string joined;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) joined += ", ";
    joined += words[i];
  }
  return joined;
}

std::string Where(std::string_view source, const toml::source_region& region) {
  return fmt::format("{}:{}:{}", source, region.begin.line, region.begin.column);
}

std::string_view TypeName(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a floating-point number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    case toml::node_type::none: break;
  }
  return "nothing";
}

std::vector<std::string_view> KeysOf(std::string_view table) {
  std::vector<std::string_view> keys;
  for (const SceneField& field : SceneFields()) {
    if (field.table == table) keys.push_back(field.key);
  }
  if (table == "model") keys.push_back("thresholds");
  return keys;
}

/// Reads one numeric field: a TOML number (SI) or a string with a unit.
double ReadQuantity(const toml::node& node, const SceneField& field, std::string_view source) {
  const std::string name = field.dotted_name();
  const std::string where = Where(source, node.source());
  if (node.is_integer() || node.is_floating_point()) {
    const double value = node.is_integer() ? static_cast<double>(**node.as_integer())
                                           : **node.as_floating_point();
    if (!std::isfinite(value)) {
      throw InputError(fmt::format("{}: {}: not a finite number (got {})", where, name, value));
    }
    return value;
  }
  if (node.is_string()) {
    try {
      return ParseQuantity(**node.as_string(), field.spec, name);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", where, e.what()));
    }
  }
  Scene defaults;
  throw InputError(fmt::format(
      "{}: {}: expected a number (SI) or a string with a unit such as \"{}\", got {}", where,
      name, FormatQuantity(field.field(defaults), field.spec.kind), TypeName(node)));
}

void ApplyTable(std::string_view table_name, const toml::table& table, std::string_view source,
                Scene& scene, std::vector<std::string>& set_fields) {
  const auto fields = SceneFields();
  for (const auto& [key, node] : table) {
    const std::string_view key_name = key.str();
    if (table_name == "model" && key_name == "thresholds") {
      const std::string where = Where(source, node.source());
      if (!node.is_string()) {
        throw InputError(fmt::format(
            "{}: model.thresholds: expected a string, \"cumulative\" or \"literal\", got {}",
            where, TypeName(node)));
      }
      try {
        scene.model.thresholds = ParseThresholds(**node.as_string(), "model.thresholds");
        set_fields.emplace_back("model.thresholds");
      } catch (const InputError& e) {
        throw InputError(fmt::format("{}: {}", where, e.what()));
      }
      continue;
    }
    const auto field = std::find_if(fields.begin(), fields.end(), [&](const SceneField& f) {
      return f.table == table_name && f.key == key_name;
    });
    if (field == fields.end()) {
      const std::vector<std::string_view> keys = KeysOf(table_name);
      const auto suggestion = Closest(key_name, keys);
      throw InputError(fmt::format(
          "{}: unknown key '{}.{}'; {}", Where(source, key.source()), table_name, key_name,
          suggestion ? fmt::format("did you mean '{}.{}'?", table_name, *suggestion)
                     : fmt::format("[{}] takes {}", table_name, JoinQuoted(keys))));
    }
    field->field(scene) = ReadQuantity(node, *field, source);
    set_fields.push_back(field->dotted_name());
  }
}

}  // namespace

std::vector<std::string> ApplySceneToml(std::string_view toml_text, std::string_view source,
                                        Scene& scene) {
  toml::table root;
  try {
    root = toml::parse(toml_text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(fmt::format("{}: TOML syntax error: {}", Where(source, e.source()),
                                 e.description()));
  }

  // Work on a copy so that a bad file leaves `scene` untouched.
  Scene result = scene;
  std::vector<std::string> set_fields;
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
      if (hint.empty()) {
        const auto suggestion = Closest(name, table_names);
        hint = suggestion ? fmt::format("; did you mean '{}'?", *suggestion)
                          : fmt::format("; the tables are {}", JoinQuoted(table_names));
      }
      throw InputError(
          fmt::format("{}: unknown table '{}'{}", Where(source, key.source()), name, hint));
    }
    if (!node.is_table()) {
      throw InputError(fmt::format("{}: '{}' must be a table ([{}]), got {}",
                                   Where(source, node.source()), name, name, TypeName(node)));
    }
    ApplyTable(name, *node.as_table(), source, result, set_fields);
  }
  scene = result;
  return set_fields;
}

std::vector<std::string> ApplySceneFile(const std::filesystem::path& path, Scene& scene) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(fmt::format("cannot read scene file '{}': it is a directory", path.string()));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InputError(fmt::format("cannot read scene file '{}': {}", path.string(),
                                 std::strerror(errno)));
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) {
    throw InputError(fmt::format("cannot read scene file '{}'", path.string()));
  }
  return ApplySceneToml(text.str(), path.string(), scene);
}

}  // namespace covopt::cli
