// ISO/TS 15066:2016 Annex A as data: reading the table (toml++, private to this file) and
// looking regions, areas and limits up. Every error of the reader names
// origin:line:column, the key and what is allowed.
#include "covopt/materials/body_regions.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "covopt/internal/toml.hpp"

#include "builtin_body_regions.hpp"
#include "covopt/core/number_format.hpp"
#include "covopt/core/physical_floors.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/core/sha256.hpp"
#include "covopt/internal/toml_text.hpp"
#include "text.hpp"

namespace covopt::materials {
namespace {

using covopt::internal::TypeName;
using covopt::internal::Where;
using internal::FormatNumber;

constexpr std::string_view kNotPermitted = "not permitted";

constexpr std::array<std::string_view, 4> kTopKeys{"title", "edition", "sources", "region"};
constexpr std::array<std::string_view, 8> kRegionKeys{
    "name",    "title", "quasi_static_force_N", "transient_factor", "stiffness_N_per_mm",
    "effective_mass_kg", "sources", "area"};
constexpr std::string_view kRegionRequired =
    "name, title, quasi_static_force_N, transient_factor, stiffness_N_per_mm, "
    "effective_mass_kg, sources, area";
constexpr std::array<std::string_view, 4> kAreaKeys{"name", "title", "number",
                                                    "quasi_static_pressure_N_per_cm2"};
constexpr std::string_view kAreaRequired = "name, title, number, quasi_static_pressure_N_per_cm2";

constexpr double kPaPerNPerCm2 = 1e4;  // 1 N/cm² = 1e4 Pa
constexpr double kNPerMPerNPerMm = 1e3;  // 1 N/mm = 1e3 N/m

/// The allowed range of one number of the table, in the file's unit.
struct NumberRange {
  double min;           ///< exclusive when min_open
  bool min_open;
  double max;           ///< inclusive
  std::string_view unit;
};

constexpr NumberRange kForceRange{0.0, true, 1e4, "N"};
constexpr NumberRange kFactorRange{1.0, false, 10.0, ""};
constexpr NumberRange kStiffnessRange{0.0, true, 1e6, "N/mm"};
constexpr NumberRange kMassRange{kMinMass_kg, false, 1e3, "kg"};  // the mass floor (physical_floors.hpp)
constexpr NumberRange kPressureRange{0.0, true, 1e4, "N/cm²"};

/// A name as looked up: lower case, "_", "/" and " " read as "-", outer blanks dropped.
std::string Normalised(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  text = text.substr(first, text.find_last_not_of(" \t") - first + 1);
  std::string name = internal::Lower(text);
  for (char& c : name) {
    if (c == '_' || c == '/' || c == ' ') c = '-';
  }
  return name;
}

/// Why `name` is not a table name (lower-case letters, digits and single inner hyphens).
std::optional<std::string> NameProblem(std::string_view name) {
  if (name.empty()) return "must not be empty";
  const bool chars_ok = std::all_of(name.begin(), name.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
  });
  if (!chars_ok || name.front() == '-' || name.back() == '-' ||
      name.find("--") != std::string_view::npos) {
    return "must be lower-case letters and digits joined by single hyphens, e.g. "
           "\"upper-arms-elbows\" (got \"" + std::string(name) + "\")";
  }
  return std::nullopt;
}

std::string Join(const std::vector<std::string_view>& words) {
  std::string joined;
  for (const std::string_view word : words) {
    if (!joined.empty()) joined += ", ";
    joined += word;
  }
  return joined;
}

template <std::size_t N>
std::string Join(const std::array<std::string_view, N>& words) {
  return Join(std::vector<std::string_view>(words.begin(), words.end()));
}

/// What the file wrote, for messages.
std::string Shown(const toml::node& node) {
  if (const auto* s = node.as_string()) return "\"" + s->get() + "\"";
  if (const auto* i = node.as_integer()) return std::to_string(i->get());
  if (const auto* f = node.as_floating_point()) return FormatNumber(f->get());
  return std::string(TypeName(node));
}

/// A number for messages and descriptions: up to 6 significant digits ("280", "0.6").
std::string Short(double value) { return FormatSignificant(value, 6); }

/// Reads one table file; every error is "origin:line:column: ...".
class TableReader {
 public:
  explicit TableReader(std::string_view origin) : origin_(origin) {}

  /// The table's title and edition (the top-level keys), after Read.
  const std::string& title() const noexcept { return title_; }
  const std::string& edition() const noexcept { return edition_; }

  std::vector<BodyRegion> Read(std::string_view text) {
    toml::table root;
    try {
      root = toml::parse(text, origin_);
    } catch (const toml::parse_error& e) {
      throw std::runtime_error(Where(origin_, e.source().begin) +
                               ": TOML syntax error: " + std::string(e.description()));
    }
    RejectUnknownKeys(root, kTopKeys, "", "the top level of a body-region table");
    title_ = TopText(root, "title");
    edition_ = TopText(root, "edition");
    ReadSources(root);

    const toml::node* regions = root.get("region");
    if (regions == nullptr || !regions->is_array_of_tables()) {
      const std::string where =
          regions == nullptr ? origin_ + ":1:1" : Where(origin_, regions->source().begin);
      throw std::runtime_error(where + ": region must be a list of [[region]] tables" +
                               (regions == nullptr ? std::string(", and there is none")
                                                   : ", got " + std::string(TypeName(*regions))));
    }
    std::vector<BodyRegion> table;
    std::size_t index = 0;
    for (const toml::node& node : *regions->as_array()) {
      ++index;
      table.push_back(ReadRegion(*node.as_table(), index));
    }
    return table;
  }

 private:
  [[noreturn]] void Fail(const toml::node& node, std::string_view label, std::string_view key,
                         const std::string& problem) const {
    throw std::runtime_error(Where(origin_, node.source().begin) + ": " + std::string(label) +
                             ": " + std::string(key) + " " + problem);
  }

  [[noreturn]] void Missing(const toml::table& table, std::string_view label,
                            std::string_view key, std::string_view required) const {
    throw std::runtime_error(Where(origin_, table.source().begin) + ": " + std::string(label) +
                             " has no '" + std::string(key) + "' (required keys: " +
                             std::string(required) + ")");
  }

  /// The first unknown key of `table` in file order, with the closest known key.
  template <std::size_t N>
  void RejectUnknownKeys(const toml::table& table, const std::array<std::string_view, N>& keys,
                         std::string_view label, std::string_view what) const {
    const toml::key* first = covopt::internal::FirstUnknownKey(table, keys);
    if (first == nullptr) return;
    const std::vector<std::string_view> candidates(keys.begin(), keys.end());
    const auto near = internal::Closest(first->str(), candidates);
    throw std::runtime_error(
        Where(origin_, first->source().begin) + ": " +
        (label.empty() ? std::string() : std::string(label) + ": ") + "unknown key '" +
        std::string(first->str()) + "' in " + std::string(what) + "; " +
        (near ? "did you mean '" + std::string(*near) + "'?" : "the keys are " + Join(keys)));
  }

  /// A required top-level string (title, edition).
  std::string TopText(const toml::table& root, std::string_view key) const {
    const toml::node* node = root.get(key);
    if (node == nullptr) {
      throw std::runtime_error(origin_ + ":1:1: the table has no top-level '" + std::string(key) +
                               "' (required: title, edition, [sources], [[region]]; e.g. edition = "
                               "\"ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M\")");
    }
    const auto* text = node->as_string();
    if (text == nullptr || text->get().find_first_not_of(" \t") == std::string::npos) {
      Fail(*node, "the table", key, "must be a non-blank string, got " + Shown(*node));
    }
    return text->get();
  }

  void ReadSources(const toml::table& root) {
    const toml::node* node = root.get("sources");
    if (node == nullptr) {
      throw std::runtime_error(origin_ + ":1:1: the table has no [sources] (one key per "
                                         "source, its value the citation)");
    }
    if (!node->is_table()) {
      Fail(*node, "the table", "sources",
           "must be a table [sources] of citations, got " + std::string(TypeName(*node)));
    }
    for (const auto& [key, value] : *node->as_table()) {
      const auto* text = value.as_string();
      if (text == nullptr || text->get().find_first_not_of(" \t") == std::string::npos) {
        Fail(value, "[sources]", key.str(),
             "must be a non-blank citation string, got " + Shown(value));
      }
      sources_.emplace(std::string(key.str()), text->get());
    }
  }

  std::string Text(const toml::table& table, std::string_view label, std::string_view key,
                   std::string_view required) const {
    const toml::node* node = table.get(key);
    if (node == nullptr) Missing(table, label, key, required);
    const auto* text = node->as_string();
    if (text == nullptr) Fail(*node, label, key, "must be a string, got " + Shown(*node));
    if (text->get().find_first_not_of(" \t") == std::string::npos) {
      Fail(*node, label, key, "must not be blank");
    }
    return text->get();
  }

  std::string Name(const toml::table& table, std::string_view label,
                   std::string_view required) const {
    std::string name = Text(table, label, "name", required);
    if (auto problem = NameProblem(name)) Fail(*table.get("name"), label, "name", *problem);
    return name;
  }

  /// A number in `range` (the file's unit), or the node if it is "not permitted" and
  /// `not_permitted_allowed`: then nullopt.
  std::optional<double> Number(const toml::table& table, std::string_view label,
                               std::string_view key, const NumberRange& range,
                               std::string_view required, bool not_permitted_allowed = false) const {
    const toml::node* node = table.get(key);
    if (node == nullptr) Missing(table, label, key, required);
    std::optional<double> value;
    if (const auto* i = node->as_integer()) value = static_cast<double>(i->get());
    if (const auto* f = node->as_floating_point()) value = f->get();
    const std::string unit = range.unit.empty() ? std::string() : " " + std::string(range.unit);
    const std::string allowed =
        "must be a number " + std::string(range.min_open ? "> " : ">= ") + Short(range.min) +
        " and <= " + Short(range.max) + unit +
        (not_permitted_allowed ? ", or \"" + std::string(kNotPermitted) + "\"" : std::string());
    if (!value) {
      const auto* text = node->as_string();
      if (not_permitted_allowed && text != nullptr && text->get() == kNotPermitted) {
        return std::nullopt;
      }
      Fail(*node, label, key, allowed + " (got " + Shown(*node) + ")");
    }
    const bool low = range.min_open ? !(*value > range.min) : !(*value >= range.min);
    if (!std::isfinite(*value) || low || *value > range.max) {
      Fail(*node, label, key, allowed + " (got " + Shown(*node) + ")");
    }
    return value;
  }

  /// "<kind> 'name'" when the table has a string name, else "<kind> #index".
  static std::string Label(const toml::table& table, std::string_view kind, std::size_t index) {
    if (const auto* name = table.get_as<std::string>("name")) {
      return std::string(kind) + " '" + name->get() + "'";
    }
    return std::string(kind) + " #" + std::to_string(index);
  }

  BodyRegion ReadRegion(const toml::table& table, std::size_t index) {
    std::string label = Label(table, "region", index);
    RejectUnknownKeys(table, kRegionKeys, label, "a [[region]]");
    BodyRegion region;
    region.name = Name(table, label, kRegionRequired);
    label = "region '" + region.name + "'";
    if (const auto seen = region_origins_.find(region.name); seen != region_origins_.end()) {
      Fail(*table.get("name"), label, "name",
           "is defined twice: already at " + seen->second);
    }
    region_origins_.emplace(region.name, Where(origin_, table.get("name")->source().begin));
    region.title = Text(table, label, "title", kRegionRequired);
    region.quasi_static_force_N =
        *Number(table, label, "quasi_static_force_N", kForceRange, kRegionRequired);
    const auto factor =
        Number(table, label, "transient_factor", kFactorRange, kRegionRequired, true);
    region.transient_factor = factor.value_or(0.0);
    region.stiffness_N_per_m =
        *Number(table, label, "stiffness_N_per_mm", kStiffnessRange, kRegionRequired) *
        kNPerMPerNPerMm;
    region.effective_mass_kg =
        *Number(table, label, "effective_mass_kg", kMassRange, kRegionRequired);
    region.sources = ReadRegionSources(table, label);

    const toml::node* areas = table.get("area");
    if (areas == nullptr) Missing(table, label, "area", kRegionRequired);
    if (!areas->is_array_of_tables() || areas->as_array()->empty()) {
      Fail(*areas, label, "area",
           "must be a list of [[region.area]] tables, at least one (got " +
               std::string(TypeName(*areas)) + ")");
    }
    for (const toml::node& node : *areas->as_array()) {
      region.areas.push_back(ReadArea(*node.as_table(), region.name));
    }
    return region;
  }

  std::vector<std::string> ReadRegionSources(const toml::table& table, std::string_view label) {
    const toml::node* node = table.get("sources");
    if (node == nullptr) Missing(table, label, "sources", kRegionRequired);
    std::vector<std::string_view> known;
    for (const auto& [key, citation] : sources_) known.push_back(key);
    const std::string allowed = "must be a non-empty list of the [sources] keys (" +
                                Join(known) + ")";
    const auto* list = node->as_array();
    if (list == nullptr || list->empty()) Fail(*node, label, "sources", allowed + ", got " + Shown(*node));
    std::vector<std::string> citations;
    for (const toml::node& item : *list) {
      const auto* key = item.as_string();
      const auto found = key == nullptr ? sources_.end() : sources_.find(key->get());
      if (found == sources_.end()) {
        Fail(item, label, "sources", allowed + "; " + Shown(item) + " is not one of them");
      }
      citations.push_back(found->second);
    }
    return citations;
  }

  BodyArea ReadArea(const toml::table& table, std::string_view region_name) {
    const std::string of = " of region '" + std::string(region_name) + "'";
    std::string label = Label(table, "area", area_count_ + 1) + of;
    RejectUnknownKeys(table, kAreaKeys, label, "a [[region.area]]");
    BodyArea area;
    area.name = Name(table, label, kAreaRequired);
    label = "area '" + area.name + "'" + of;
    const toml::node* name = table.get("name");
    if (const auto seen = area_origins_.find(area.name); seen != area_origins_.end()) {
      Fail(*name, label, "name",
           "is defined twice: already at " + seen->second + " (area names are unique over "
           "the table)");
    }
    area_origins_.emplace(area.name, Where(origin_, name->source().begin));
    area.title = Text(table, label, "title", kAreaRequired);

    const toml::node* number = table.get("number");
    if (number == nullptr) Missing(table, label, "number", kAreaRequired);
    const int expected = static_cast<int>(area_count_) + 1;
    const auto* integer = number->as_integer();
    if (integer == nullptr || integer->get() != expected) {
      Fail(*number, label, "number",
           "must be " + std::to_string(expected) +
               " (the areas are numbered 1, 2, ... in table order), got " + Shown(*number));
    }
    area.number = expected;
    area.quasi_static_pressure_Pa = *Number(table, label, "quasi_static_pressure_N_per_cm2",
                                            kPressureRange, kAreaRequired) *
                                    kPaPerNPerCm2;
    ++area_count_;
    return area;
  }

  std::string origin_;
  std::string title_;
  std::string edition_;
  std::map<std::string, std::string, std::less<>> sources_;  // key -> citation
  std::map<std::string, std::string, std::less<>> region_origins_;  // name -> where
  std::map<std::string, std::string, std::less<>> area_origins_;    // name -> where
  std::size_t area_count_ = 0;
};

/// The region names of `table`, in order.
std::vector<std::string_view> RegionNames(const std::vector<BodyRegion>& table) {
  std::vector<std::string_view> names;
  for (const BodyRegion& r : table) names.push_back(r.name);
  return names;
}

std::vector<std::string_view> AreaNames(const BodyRegion& region) {
  std::vector<std::string_view> names;
  for (const BodyArea& a : region.areas) names.push_back(a.name);
  return names;
}

std::string DidYouMean(std::string_view typed, const std::vector<std::string_view>& names) {
  const auto near = internal::Closest(typed, names);
  return near ? "; did you mean '" + std::string(*near) + "'?" : std::string();
}

}  // namespace

const BodyArea& BodyRegion::LowestPressureArea() const {
  if (areas.empty()) throw std::logic_error("body region '" + name + "' has no areas");
  return *std::min_element(areas.begin(), areas.end(), [](const BodyArea& a, const BodyArea& b) {
    return a.quasi_static_pressure_Pa < b.quasi_static_pressure_Pa;
  });
}

std::string BodyLimits::Describe() const {
  if (region == nullptr || area == nullptr) return "no body region";
  // Appended into one buffer: the all-regions table writes this for every row.
  std::string text;
  text.reserve(120);
  text.append(Citation()).append(", ");
  if (contact == ContactType::kTransient) {
    text.append("transient (").append(Short(region->transient_factor)).append("× quasi-static)");
  } else {
    text.append("quasi-static");
  }
  text.append(", ").append(region->name).append(" (").append(area->name).append("): ");
  text.append(Short(force_N)).append(" N, ").append(Short(pressure_Pa / kPaPerNPerCm2)).append(" N/cm²");
  return text;
}

std::string LimitTableInfo::NoTransientClause() const {
  return built_in() ? "ISO/TS 15066:2016 A.3.2 (= ISO 10218-2:2025 Annex M)" : edition;
}

std::string BodyLimits::Citation() const {
  return region != nullptr && region->table ? region->table->edition : BuiltInEdition();
}

double BodyLimits::effective_mass_kg() const noexcept {
  return contact == ContactType::kClamped ? kFixed : region->effective_mass_kg;
}

const BodyRegionTable& BodyRegionTable::BuiltIn() {
  static const BodyRegionTable table =
      FromTomlText(internal::kBuiltInBodyRegionsToml, internal::kBuiltInBodyRegionsName);
  return table;
}

BodyRegionTable BodyRegionTable::FromTomlText(std::string_view text, std::string_view origin) {
  BodyRegionTable table;
  TableReader reader(origin);
  table.regions_ = reader.Read(text);
  const bool built_in = origin == internal::kBuiltInBodyRegionsName;
  table.info_ = std::make_shared<const LimitTableInfo>(LimitTableInfo{.title = reader.title(),
                                                                      .edition = reader.edition(),
                                                                      .source = built_in ? "built-in" : std::string(origin),
                                                                      .text = std::string(text),
                                                                      .sha256 = Sha256Hex(text)});
  for (BodyRegion& region : table.regions_) region.table = table.info_;
  return table;
}

const BodyRegionTable& BodyRegionTable::Load(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  if (!in || !(bytes << in.rdbuf())) {
    throw std::runtime_error("cannot read the limit table '" + path.string() +
                             "' (a body-region table in TOML: docs/guide/limits.md)");
  }
  const std::string text = bytes.str();
  // Kept for the program's life (BodyLimits point into them); the same file read again with
  // the same bytes is the same table.
  static std::mutex mutex;
  static std::deque<BodyRegionTable> loaded;
  const std::lock_guard lock(mutex);
  for (const BodyRegionTable& table : loaded) {
    if (table.info().source == path.string() && table.info().text == text) return table;
  }
  loaded.push_back(FromTomlText(text, path.string()));
  return loaded.back();
}

const std::string& BuiltInEdition() { return BodyRegionTable::BuiltIn().info().edition; }

std::size_t BodyRegionTable::area_count() const noexcept {
  std::size_t count = 0;
  for (const BodyRegion& r : regions_) count += r.areas.size();
  return count;
}

const BodyRegion& BodyRegionTable::Region(std::string_view name) const {
  const std::string wanted = Normalised(name);
  for (const BodyRegion& r : regions_) {
    if (r.name == wanted || Normalised(r.title) == wanted) return r;
  }
  const std::vector<std::string_view> names = RegionNames(regions_);
  const std::string head =
      wanted == "head" ? " (the head as a whole is judged by Park et al.'s skin model: "
                         "body.region=head)"
                       : std::string();
  // An area's name given for a region: say whose it is.
  for (const BodyRegion& r : regions_) {
    for (const BodyArea& a : r.areas) {
      if (a.name == wanted) {
        throw BodyRegionError("body region '" + std::string(name) + "' is not in " +
                              info_->edition + ": it is an area of '" + r.name +
                              "' (regions: " + Join(names) + ")");
      }
    }
  }
  throw BodyRegionError("body region '" + std::string(name) + "' is not in " +
                        info_->edition + head +
                        DidYouMean(wanted, names) + " (regions: " + Join(names) + ")");
}

BodyLimits BodyRegionTable::Limits(std::string_view region_name, std::string_view area_name,
                                   ContactType contact) const {
  const BodyRegion& region = Region(region_name);
  const BodyArea* area = nullptr;
  const std::string wanted = Normalised(area_name);
  if (wanted.empty()) {
    area = &region.LowestPressureArea();
  } else {
    for (const BodyArea& a : region.areas) {
      if (a.name == wanted || Normalised(a.title) == wanted) area = &a;
    }
  }
  if (area == nullptr) {
    const std::vector<std::string_view> names = AreaNames(region);
    std::string elsewhere;
    for (const BodyRegion& r : regions_) {
      for (const BodyArea& a : r.areas) {
        if (a.name == wanted) elsewhere = " (it is an area of '" + r.name + "')";
      }
    }
    throw BodyRegionError("body area '" + std::string(area_name) + "' is not an area of '" +
                          region.name + "' in " + info_->edition +
                          elsewhere + DidYouMean(wanted, names) + " (areas of " + region.name +
                          ": " + Join(names) + ")");
  }
  if (contact == ContactType::kTransient && !region.transient_permitted()) {
    throw BodyRegionError(info_->NoTransientClause() +
                          " does not permit transient contact with the " + region.name +
                          "; use body.contact=clamped, or judge the head with Park et al.'s skin "
                          "model (body.region=head)");
  }
  BodyLimits limits;
  limits.region = &region;
  limits.area = area;
  limits.contact = contact;
  const double factor = contact == ContactType::kTransient ? region.transient_factor : 1.0;
  limits.force_N = region.quasi_static_force_N * factor;
  limits.pressure_Pa = area->quasi_static_pressure_Pa * factor;
  return limits;
}

std::vector<BodyLimits> BodyRegionTable::AllLimits(ContactType contact) const {
  std::vector<BodyLimits> all;
  for (const BodyRegion& region : regions_) {
    if (contact == ContactType::kTransient && !region.transient_permitted()) continue;
    const double factor = contact == ContactType::kTransient ? region.transient_factor : 1.0;
    for (const BodyArea& area : region.areas) {
      all.push_back(BodyLimits{&region, &area, contact, region.quasi_static_force_N * factor,
                               area.quasi_static_pressure_Pa * factor});
    }
  }
  return all;
}

}  // namespace covopt::materials
