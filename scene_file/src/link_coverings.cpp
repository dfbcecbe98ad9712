// Link-covering files (covopt audit --link-coverings, covopt.audit(link_coverings=...)).
#include "covopt/scene_file/link_coverings.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>
#include "covopt/internal/toml.hpp"

#include "covopt/core/physical_floors.hpp"
#include "covopt/core/poisson_ratio.hpp"
#include "covopt/core/quantity.hpp"
#include "covopt/internal/text.hpp"
#include "covopt/internal/toml_text.hpp"
#include "toml_input.hpp"

namespace covopt::scene_file {
namespace {

using covopt::internal::Closest;
using covopt::internal::FirstUnknownKey;
using covopt::internal::EscapeControlCharacters;
using covopt::internal::TypeName;
using covopt::internal::Where;

constexpr std::array<std::string_view, 5> kLinkKeys{"name", "material", "modulus", "poisson", "thickness"};

LinkCoveringEntry ReadLink(const toml::table& table, const std::string& source, std::size_t index) {
  LinkCoveringEntry entry;
  entry.where = EscapeControlCharacters(Where(source, table.source()));  // echoed by the callers: one line
  if (const toml::key* key = FirstUnknownKey(table, kLinkKeys)) {
    const auto suggestion = Closest(key->str(), std::vector<std::string_view>(kLinkKeys.begin(), kLinkKeys.end()));
    throw std::invalid_argument(fmt::format("{}: unknown key '{}' in [[link]] {}; {}", Where(source, key->source()),
                                            key->str(), index + 1,
                                            suggestion ? fmt::format("did you mean '{}'?", *suggestion)
                                                       : std::string("a link takes name, material or modulus "
                                                                     "(and poisson), thickness")));
  }
  const toml::node* name = table.get("name");
  if (name == nullptr || !name->is_string() || name->as_string()->get().empty()) {
    throw std::invalid_argument(fmt::format("{}: [[link]] {} needs name = \"LINK\" (a link of the chain){}",
                                            entry.where, index + 1,
                                            name ? fmt::format(", got {}", TypeName(*name)) : std::string()));
  }
  entry.link = name->as_string()->get();
  if (auto problem = NameProblem("link name", entry.link)) {
    throw std::invalid_argument(fmt::format("{}: [[link]] {} name: {}", Where(source, name->source()), index + 1,
                                            *problem));
  }
  const std::string prefix = fmt::format("link '{}'", entry.link);
  const toml::node* thickness = table.get("thickness");
  if (thickness == nullptr) {
    throw std::invalid_argument(fmt::format("{}: {} needs thickness (e.g. \"10mm\"; 0 for the bare link)",
                                            entry.where, prefix));
  }
  entry.thickness_m = internal::ReadQuantity(*thickness, quantity_specs::kCoveringThickness,
                                             prefix + " thickness", "10mm", source);
  if (const toml::node* material = table.get("material")) {
    if (!material->is_string() || material->as_string()->get().empty()) {
      throw std::invalid_argument(fmt::format("{}: {} material: expected a catalog name (a string), got {}",
                                              Where(source, material->source()), prefix, TypeName(*material)));
    }
    entry.material = material->as_string()->get();
    if (auto problem = NameProblem("material name", *entry.material)) {
      throw std::invalid_argument(fmt::format("{}: {} material: {}", Where(source, material->source()), prefix,
                                              *problem));
    }
  }
  if (const toml::node* modulus = table.get("modulus")) {
    if (entry.material) {
      throw std::invalid_argument(fmt::format("{}: {}: material '{}' sets the modulus and Poisson ratio; give "
                                              "either material or modulus, not both",
                                              Where(source, modulus->source()), prefix, *entry.material));
    }
    entry.modulus_Pa = internal::ReadQuantity(*modulus, quantity_specs::kCoveringModulus, prefix + " modulus",
                                              "0.5MPa", source);
  }
  if (const toml::node* poisson = table.get("poisson")) {
    if (!entry.modulus_Pa) {
      throw std::invalid_argument(fmt::format("{}: {} poisson is given with modulus only{}",
                                              Where(source, poisson->source()), prefix,
                                              entry.material ? " (the material has its own)" : ""));
    }
    entry.poisson_ratio =
        internal::ReadQuantity(*poisson, quantity_specs::kPoissonRatio, prefix + " poisson", "0.45", source);
  }
  if (auto problem = CheckLinkCovering(entry)) {
    const toml::node* node = table.get(problem->key);
    throw std::invalid_argument(fmt::format("{}: {} {}", Where(source, node->source()), prefix, problem->message));
  }
  if (entry.thickness_m > 0.0 && !entry.material && !entry.modulus_Pa) {
    throw std::invalid_argument(fmt::format("{}: {} has a covering {} thick but neither material nor modulus; give "
                                            "one (or thickness = 0 for the bare link)",
                                            entry.where, prefix, FormatQuantity(entry.thickness_m, QuantityKind::kLength)));
  }
  return entry;
}

std::vector<LinkCoveringEntry> Parse(const std::string& toml_text, const std::string& source_name) {
  toml::table root;
  try {
    root = toml::parse(toml_text, source_name);
  } catch (const toml::parse_error& e) {
    throw std::invalid_argument(fmt::format("{}: not a TOML link-covering file: {}", Where(source_name, e.source()),
                                            e.description()));
  }
  for (const auto& [key, node] : root) {
    if (key.str() != "link") {
      throw std::invalid_argument(fmt::format("{}: unknown key '{}'; a link-covering file has [[link]] tables only",
                                              Where(source_name, key.source()), key.str()));
    }
  }
  std::vector<LinkCoveringEntry> entries;
  const toml::node* links = root.get("link");
  if (links == nullptr) return entries;
  if (!links->is_array_of_tables()) {
    throw std::invalid_argument(fmt::format("{}: link: expected [[link]] tables, got {}",
                                            Where(source_name, links->source()), TypeName(*links)));
  }
  const toml::array& array = *links->as_array();
  for (std::size_t i = 0; i < array.size(); ++i) {
    LinkCoveringEntry entry = ReadLink(*array[i].as_table(), source_name, i);
    for (const LinkCoveringEntry& seen : entries) {
      if (seen.link == entry.link) {
        throw std::invalid_argument(fmt::format("{}: link '{}' is given twice (first at {})", entry.where, entry.link,
                                                seen.where));
      }
    }
    entries.push_back(std::move(entry));
  }
  return entries;
}

}  // namespace

std::vector<LinkCoveringEntry> ParseLinkCoverings(const std::string& toml_text, const std::string& source_name) {
  try {
    return Parse(toml_text, source_name);
  } catch (const std::invalid_argument& e) {
    // Every message on one line, whatever it echoes (a key, a value, a name or the source's
    // name with a newline in it).
    throw std::invalid_argument(EscapeControlCharacters(e.what()));
  }
}

std::optional<LinkCoveringProblem> CheckLinkCovering(const LinkCoveringEntry& entry) {
  const double t = entry.thickness_m;
  if (!(t == 0.0 || (t >= kMinLayerThickness_m && t <= kMaxLinkCoveringThickness_m))) {
    return LinkCoveringProblem{
        "thickness", fmt::format("thickness must be 0 (bare) or in [{}, {}] (got {})",
                                 FormatQuantity(kMinLayerThickness_m, QuantityKind::kLength),
                                 FormatQuantity(kMaxLinkCoveringThickness_m, QuantityKind::kLength),
                                 FormatQuantity(t, QuantityKind::kLength))};
  }
  if (entry.modulus_Pa) {
    const double e = *entry.modulus_Pa;
    if (!(e >= kMinModulus_Pa && e <= kMaxLinkCoveringModulus_Pa)) {
      return LinkCoveringProblem{"modulus", fmt::format("modulus must be in [{}, {}] (got {})",
                                                        FormatQuantity(kMinModulus_Pa, QuantityKind::kModulus),
                                                        FormatQuantity(kMaxLinkCoveringModulus_Pa, QuantityKind::kModulus),
                                                        FormatQuantity(e, QuantityKind::kModulus))};
    }
  }
  if (entry.poisson_ratio && !IsPoissonRatio(*entry.poisson_ratio)) {
    return LinkCoveringProblem{"poisson", fmt::format("poisson must be in {}, as covering.poisson (got {})",
                                                      kPoissonRatioRange, *entry.poisson_ratio)};
  }
  return std::nullopt;
}

std::optional<std::string> NameProblem(std::string_view what, const std::string& name) {
  if (name.empty()) return fmt::format("a {} is not empty", what);
  const bool control = std::any_of(name.begin(), name.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return byte < 0x20 || byte == 0x7f;
  });
  if (!control) return std::nullopt;
  return fmt::format("a {} has no control characters such as a newline (got '{}')", what, EscapeControlCharacters(name));
}

std::vector<LinkCoveringEntry> ReadLinkCoverings(const std::filesystem::path& path) {
  std::string text;
  try {
    text = internal::ReadBoundedFile(path, "link-covering file", kMaxLinkCoveringsFileBytes);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(EscapeControlCharacters(e.what()));  // a path with a newline: still one line
  }
  return ParseLinkCoverings(text, path.string());
}

}  // namespace covopt::scene_file
