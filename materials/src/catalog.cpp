// Catalog: adding entries (with the duplicate-name rule), lookup, suggestions, filters.
// Reading TOML is in catalog_toml.cpp.
#include "covopt/materials/catalog.hpp"

#include <algorithm>
#include <tuple>
#include <utility>

#include "text.hpp"
#include "validation.hpp"

namespace covopt::materials {

using internal::EqualsIgnoringCase;
using internal::Lower;

CatalogError::CatalogError(const std::string& message, std::string location, std::string key)
    : std::runtime_error(covopt::internal::EscapeControlCharacters(message)),  // a name's NUL or newline: one line, whole
      location_(std::move(location)), key_(std::move(key)) {}

bool Range::Contains(double value) const noexcept {
  if (min && !(value >= *min)) return false;
  if (max && !(value <= *max)) return false;
  return true;
}

namespace {

std::string OriginOrCode(const Material& material) {
  return material.origin.empty() ? std::string("(added in code)") : material.origin;
}

/// The error for `added` whose name `existing` already has.
CatalogError DuplicateError(const Material& existing, const Material& added) {
  std::string message;
  if (!added.origin.empty()) message = added.origin + ": ";
  message += "duplicate material name '" + added.name + "': already defined at " +
             OriginOrCode(existing);
  if (existing.name != added.name) message += " as '" + existing.name + "'";
  message += " (names are compared ignoring case)";
  return CatalogError(message, added.origin, std::string(internal::kKeyName));
}

/// The words of a query: runs of ASCII letters and digits, lower case.
std::vector<std::string> Words(std::string_view text) {
  std::vector<std::string> words;
  std::string word;
  for (const char c : text) {
    const bool alnum = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    if (alnum) {
      word += c;
    } else if (!word.empty()) {
      words.push_back(Lower(word));
      word.clear();
    }
  }
  if (!word.empty()) words.push_back(Lower(word));
  return words;
}

bool OptionalInRange(const std::optional<double>& value, const Range& range,
                     bool include_unknown) {
  if (range.unbounded()) return true;
  if (!value) return include_unknown;
  return range.Contains(*value);
}

}  // namespace

void Catalog::Add(const Catalog& other) {
  for (const Material& added : other.materials_) {
    if (const Material* existing = Find(added.name)) throw DuplicateError(*existing, added);
  }
  materials_.insert(materials_.end(), other.materials_.begin(), other.materials_.end());
}

void Catalog::Add(Material material) {
  if (const auto problem = internal::FirstProblem(material)) {
    std::string message;
    if (!material.origin.empty()) message = material.origin + ": ";
    message += (problem->first == internal::kKeyName ? std::string("material")
                                                     : internal::Describe(material)) +
               ": " + problem->first + " " + problem->second;
    throw CatalogError(message, material.origin, problem->first);
  }
  if (const Material* existing = Find(material.name)) throw DuplicateError(*existing, material);
  materials_.push_back(std::move(material));
}

const Material* Catalog::Find(std::string_view name) const noexcept {
  for (const Material& material : materials_) {
    if (EqualsIgnoringCase(material.name, name)) return &material;
  }
  return nullptr;
}

std::string Catalog::MissingMaterialMessage(std::string_view name) const {
  const std::vector<std::string> suggestions = Suggest(name);
  std::string message = "no material '" + covopt::internal::EscapeControlCharacters(name) + "' in the catalog";
  if (suggestions.empty()) return message + "; run 'covopt materials list' for the names";
  message += "; did you mean ";
  for (std::size_t i = 0; i < suggestions.size(); ++i) {
    if (i > 0) message += (i + 1 == suggestions.size()) ? " or " : ", ";
    message += "'" + suggestions[i] + "'";
  }
  return message + "?";
}

std::vector<std::string> Catalog::Suggest(std::string_view name, std::size_t max_count) const {
  const std::string query = Lower(name);
  const std::vector<std::string> words = Words(name);
  const std::size_t tolerance = internal::TypoTolerance(query);

  std::vector<std::tuple<std::size_t, std::size_t>> candidates;  // (distance, index)
  for (std::size_t i = 0; i < materials_.size(); ++i) {
    const std::string candidate = Lower(materials_[i].name);
    const std::size_t distance = internal::EditDistance(query, candidate);
    const bool has_every_word =
        !words.empty() && std::all_of(words.begin(), words.end(), [&](const std::string& w) {
          return candidate.find(w) != std::string::npos;
        });
    if (distance <= tolerance || has_every_word) candidates.emplace_back(distance, i);
  }
  std::sort(candidates.begin(), candidates.end());

  std::vector<std::string> names;
  for (const auto& [distance, index] : candidates) {
    if (names.size() >= max_count) break;
    names.push_back(materials_[index].name);
  }
  return names;
}

std::vector<const Material*> Catalog::Filter(const MaterialFilter& filter) const {
  const std::string name_part = Lower(filter.name_contains);
  std::vector<const Material*> kept;
  for (const Material& m : materials_) {
    if (!filter.youngs_modulus_Pa.Contains(m.youngs_modulus_Pa)) continue;
    if (!OptionalInRange(m.poisson_ratio, filter.poisson_ratio, filter.include_unknown)) continue;
    if (!OptionalInRange(m.density_kg_per_m3, filter.density_kg_per_m3,
                         filter.include_unknown)) {
      continue;
    }
    if (!filter.families.empty() &&
        std::none_of(filter.families.begin(), filter.families.end(),
                     [&](const std::string& f) { return EqualsIgnoringCase(f, m.family); })) {
      continue;
    }
    if (!filter.bases.empty() &&
        std::find(filter.bases.begin(), filter.bases.end(), m.modulus_basis) ==
            filter.bases.end()) {
      continue;
    }
    if (!name_part.empty() && Lower(m.name).find(name_part) == std::string::npos) continue;
    if (!filter.compressive_strength_Pa.unbounded() &&
        !(m.compressive_strength_Pa && filter.compressive_strength_Pa.Contains(*m.compressive_strength_Pa))) {
      continue;
    }
    if (!filter.crush_behaviours.empty() &&
        std::find(filter.crush_behaviours.begin(), filter.crush_behaviours.end(),
                  m.crush_behaviour) == filter.crush_behaviours.end()) {
      continue;
    }
    if (filter.has_curve && !m.compressive_curve) continue;
    if (!filter.stress_at_25_Pa.unbounded()) {
      const auto stress = StressAt25Pa(m);
      if (!stress || !filter.stress_at_25_Pa.Contains(*stress)) continue;
    }
    kept.push_back(&m);
  }
  return kept;
}

std::size_t Catalog::ExcludedForWantOfCurve(const MaterialFilter& filter) const {
  if (!filter.needs_curve()) return 0;
  MaterialFilter others = filter;
  others.has_curve = false;
  others.stress_at_25_Pa = Range{};
  std::size_t excluded = 0;
  for (const Material* m : Filter(others)) {
    const bool lacks = filter.stress_at_25_Pa.unbounded() ? !m->compressive_curve : !StressAt25Pa(*m);
    if (lacks) ++excluded;
  }
  return excluded;
}

std::vector<std::string> Catalog::families() const {
  std::vector<std::string> families;
  for (const Material& m : materials_) {
    if (std::none_of(families.begin(), families.end(),
                     [&](const std::string& f) { return EqualsIgnoringCase(f, m.family); })) {
      families.push_back(m.family);
    }
  }
  return families;
}

}  // namespace covopt::materials
