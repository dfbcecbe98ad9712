// Exposure-zone files (covopt audit --exposure, covopt.audit(exposure=...)).
#include "covopt/scene_file/exposure_file.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include "covopt/internal/toml.hpp"

#include "covopt/materials/body_regions.hpp"
#include "covopt/internal/text.hpp"
#include "covopt/internal/toml_text.hpp"
#include "toml_input.hpp"

namespace covopt::scene_file {
namespace {

using covopt::internal::Closest;
using covopt::internal::EscapeControlCharacters;
using covopt::internal::FirstUnknownKey;
using covopt::internal::TypeName;
using covopt::internal::Where;

constexpr std::array<std::string_view, 3> kTopKeys{"title", "source", "zone"};
constexpr std::array<std::string_view, 4> kZoneKeys{"name", "min_m", "max_m", "regions"};

[[noreturn]] void UnknownKey(const toml::key& key, const std::string& source, std::string_view where_in,
                             const std::vector<std::string_view>& known) {
  const auto suggestion = Closest(key.str(), known);
  throw std::invalid_argument(fmt::format("{}: unknown key '{}' {}; {}", Where(source, key.source()), key.str(), where_in,
                                          suggestion ? fmt::format("did you mean '{}'?", *suggestion)
                                                     : fmt::format("the keys are {}", fmt::join(known, ", "))));
}

std::string ReadString(const toml::node& node, const std::string& source, const std::string& what) {
  if (!node.is_string()) {
    throw std::invalid_argument(
        fmt::format("{}: {}: expected a string, got {}", Where(source, node.source()), what, TypeName(node)));
  }
  return node.as_string()->get();
}

std::array<double, 3> ReadCorner(const toml::node& node, const std::string& source, const std::string& what) {
  const toml::array* array = node.as_array();
  if (array == nullptr || array->size() != 3) {
    throw std::invalid_argument(fmt::format("{}: {}: expected three numbers [x, y, z] in m, got {}",
                                            Where(source, node.source()), what,
                                            array ? fmt::format("{} values", array->size()) : TypeName(node)));
  }
  std::array<double, 3> out{};
  for (std::size_t k = 0; k < 3; ++k) {
    const toml::node& value = *array->get(k);
    const std::optional<double> x = value.value<double>();
    if (!x || !value.is_number() || !std::isfinite(*x) || std::abs(*x) > kMaxExposureCoordinate_m) {
      throw std::invalid_argument(fmt::format("{}: {}[{}]: expected a finite number of metres within ±{:g} m, got {}",
                                              Where(source, value.source()), what, k, kMaxExposureCoordinate_m,
                                              value.is_number() ? fmt::format("{}", *x) : TypeName(value)));
    }
    out[k] = *x;
  }
  return out;
}

ExposureZoneEntry ReadZone(const toml::table& table, const std::string& source, std::size_t index) {
  ExposureZoneEntry zone;
  zone.where = EscapeControlCharacters(Where(source, table.source()));
  const std::string label = fmt::format("[[zone]] {}", index + 1);
  if (const toml::key* key = FirstUnknownKey(table, kZoneKeys)) {
    UnknownKey(*key, source, "in " + label, {kZoneKeys.begin(), kZoneKeys.end()});
  }
  for (const std::string_view key : kZoneKeys) {
    if (table.get(key) == nullptr) {
      throw std::invalid_argument(fmt::format("{}: {} needs {} (name, min_m = [x, y, z], max_m = [x, y, z], "
                                              "regions = [...])",
                                              zone.where, label, key));
    }
  }
  zone.name = ReadString(*table.get("name"), source, label + " name");
  if (zone.name.empty() || EscapeControlCharacters(zone.name) != zone.name) {
    throw std::invalid_argument(fmt::format("{}: {} name: a zone's name is not empty and has no control characters "
                                            "(got '{}')",
                                            Where(source, table.get("name")->source()), label,
                                            EscapeControlCharacters(zone.name)));
  }
  const std::string prefix = fmt::format("zone '{}'", zone.name);
  zone.min_m = ReadCorner(*table.get("min_m"), source, prefix + " min_m");
  zone.max_m = ReadCorner(*table.get("max_m"), source, prefix + " max_m");
  for (std::size_t k = 0; k < 3; ++k) {
    if (zone.min_m[k] > zone.max_m[k]) {
      throw std::invalid_argument(fmt::format("{}: {} min_m [{}] lies above max_m [{}] along {} (min_m <= max_m on "
                                              "every axis)",
                                              Where(source, table.get("min_m")->source()), prefix,
                                              fmt::join(zone.min_m, ", "), fmt::join(zone.max_m, ", "), "xyz"[k]));
    }
  }
  const toml::node& regions = *table.get("regions");
  const toml::array* array = regions.as_array();
  if (array == nullptr || array->empty()) {
    throw std::invalid_argument(fmt::format("{}: {} regions: expected a non-empty list of body regions, got {}",
                                            Where(source, regions.source()), prefix,
                                            array ? std::string("[]") : TypeName(regions)));
  }
  for (const toml::node& region : *array) {
    std::string name = ReadString(region, source, prefix + " regions");
    if (auto problem = ExposureRegionProblem(name)) {
      throw std::invalid_argument(fmt::format("{}: {} regions: {}", Where(source, region.source()), prefix, *problem));
    }
    zone.regions.push_back(std::move(name));
  }
  return zone;
}

ExposureFile Parse(const std::string& toml_text, const std::string& source_name) {
  toml::table root;
  try {
    root = toml::parse(toml_text, source_name);
  } catch (const toml::parse_error& e) {
    throw std::invalid_argument(
        fmt::format("{}: not a TOML exposure file: {}", Where(source_name, e.source()), e.description()));
  }
  for (const auto& [key, node] : root) {
    if (std::find(kTopKeys.begin(), kTopKeys.end(), key.str()) == kTopKeys.end()) {
      UnknownKey(key, source_name, "at the top", {kTopKeys.begin(), kTopKeys.end()});
    }
  }
  ExposureFile file;
  if (const toml::node* title = root.get("title")) file.title = ReadString(*title, source_name, "title");
  if (const toml::node* source = root.get("source")) file.source = ReadString(*source, source_name, "source");
  const toml::node* zones = root.get("zone");
  if (zones == nullptr || !zones->is_array_of_tables()) {
    throw std::invalid_argument(fmt::format("{}: zone: expected [[zone]] tables (name, min_m, max_m, regions), got {}",
                                            zones ? Where(source_name, zones->source()) : source_name,
                                            zones ? TypeName(*zones) : std::string("none")));
  }
  const toml::array& array = *zones->as_array();
  for (std::size_t i = 0; i < array.size(); ++i) {
    ExposureZoneEntry zone = ReadZone(*array[i].as_table(), source_name, i);
    for (const ExposureZoneEntry& seen : file.zones) {
      if (seen.name == zone.name) {
        throw std::invalid_argument(
            fmt::format("{}: zone '{}' is named twice (first at {})", zone.where, zone.name, seen.where));
      }
    }
    file.zones.push_back(std::move(zone));
  }
  return file;
}

std::string Lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

std::optional<std::string> ExposureRegionProblem(const std::string& name) {
  const std::string key = Lower(name);
  if (key == "all" || key == "head" || key == "head (park et al. 2011)") return std::nullopt;
  const std::size_t open = key.find(" (");
  const std::string region = key.substr(0, open);
  const materials::BodyRegion* found = nullptr;
  try {
    found = &materials::BodyRegionTable::BuiltIn().Region(region);
  } catch (const std::invalid_argument& e) {
    return fmt::format("'{}' is not a body region ({}; or 'head', 'all')", EscapeControlCharacters(name), e.what());
  }
  if (open == std::string::npos) return std::nullopt;
  const std::string area = key.substr(open + 2, key.size() - open - 2 - (key.ends_with(")") ? 1 : 0));
  std::vector<std::string_view> areas;
  for (const materials::BodyArea& a : found->areas) {
    if (a.name == area) return std::nullopt;
    areas.push_back(a.name);
  }
  return fmt::format("'{}': {} has no area '{}' (its areas: {})", EscapeControlCharacters(name), found->name, area,
                     fmt::join(areas, ", "));
}

ExposureFile ParseExposureFile(const std::string& toml_text, const std::string& source_name) {
  try {
    return Parse(toml_text, source_name);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(EscapeControlCharacters(e.what()));
  }
}

ExposureFile ReadExposureFile(const std::filesystem::path& path) {
  std::string text;
  try {
    text = internal::ReadBoundedFile(path, "exposure file", kMaxExposureFileBytes);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(EscapeControlCharacters(e.what()));
  }
  return ParseExposureFile(text, path.string());
}

}  // namespace covopt::scene_file
