// Link-covering files (covopt audit --link-coverings, covopt.audit(link_coverings=...)).
#include "covopt/scene_file/link_coverings.hpp"

#include <array>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>
#include "covopt/internal/toml.hpp"

#include "covopt/core/quantity.hpp"
#include "covopt/internal/text.hpp"
#include "covopt/internal/toml_text.hpp"
#include "toml_input.hpp"

namespace covopt::scene_file {
namespace {

using covopt::internal::Closest;
using covopt::internal::FirstUnknownKey;
using covopt::internal::TypeName;
using covopt::internal::Where;

constexpr std::array<std::string_view, 5> kLinkKeys{"name", "material", "modulus", "poisson", "thickness"};

LinkCoveringEntry ReadLink(const toml::table& table, const std::string& source, std::size_t index) {
  LinkCoveringEntry entry;
  entry.where = Where(source, table.source());
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
    if (!(*entry.poisson_ratio >= 0.0 && *entry.poisson_ratio < 0.5)) {
      throw std::invalid_argument(fmt::format("{}: {} poisson must be in [0, 0.5) (got {})",
                                              Where(source, poisson->source()), prefix, internal::Shown(*poisson)));
    }
  }
  if (entry.thickness_m > 0.0 && !entry.material && !entry.modulus_Pa) {
    throw std::invalid_argument(fmt::format("{}: {} has a covering {} thick but neither material nor modulus; give "
                                            "one (or thickness = 0 for the bare link)",
                                            entry.where, prefix, FormatQuantity(entry.thickness_m, QuantityKind::kLength)));
  }
  return entry;
}

}  // namespace

std::vector<LinkCoveringEntry> ParseLinkCoverings(const std::string& toml_text, const std::string& source_name) {
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

std::vector<LinkCoveringEntry> ReadLinkCoverings(const std::filesystem::path& path) {
  return ParseLinkCoverings(internal::ReadBoundedFile(path, "link-covering file", kMaxLinkCoveringsFileBytes),
                            path.string());
}

}  // namespace covopt::scene_file
