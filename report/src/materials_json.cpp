#include "covopt/report/materials_json.hpp"

#include <cstddef>
#include <vector>

#include <nlohmann/json.hpp>

namespace covopt::report {
namespace {

using Json = nlohmann::ordered_json;

Json MaterialObject(const materials::Material& m) {
  Json j;
  j["name"] = m.name;
  j["family"] = m.family;
  j["youngs_modulus_Pa"] = m.youngs_modulus_Pa;
  j["poisson_ratio"] = m.poisson_ratio ? Json(*m.poisson_ratio) : Json(nullptr);
  j["density_kg_per_m3"] = m.density_kg_per_m3 ? Json(*m.density_kg_per_m3) : Json(nullptr);
  j["modulus_basis"] = materials::ToString(m.modulus_basis);
  j["source"] = m.source;
  j["note"] = m.note.empty() ? Json(nullptr) : Json(m.note);
  j["defined_at"] = m.origin.empty() ? Json(nullptr) : Json(m.origin);
  return j;
}

/// 'a', 'b' or 'c'
std::string QuotedAlternatives(const std::vector<std::string>& words) {
  std::string joined;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) joined += (i + 1 == words.size()) ? " or " : ", ";
    joined += "'" + words[i] + "'";
  }
  return joined;
}

}  // namespace

std::string MaterialJson(const materials::Material& material, int indent) {
  return MaterialObject(material).dump(indent);
}

std::string MaterialsJson(std::span<const materials::Material* const> materials, int indent) {
  Json array = Json::array();
  for (const materials::Material* m : materials) array.push_back(MaterialObject(*m));
  return array.dump(indent);
}

std::string NoSuchMaterialMessage(const materials::Catalog& catalog, std::string_view name) {
  const std::vector<std::string> suggestions = catalog.Suggest(name);
  if (suggestions.empty()) {
    return "no material '" + std::string(name) +
           "' in the catalog; run 'covopt materials list' for the names";
  }
  return "no material '" + std::string(name) + "' in the catalog; did you mean " +
         QuotedAlternatives(suggestions) + "?";
}

}  // namespace covopt::report
