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
  j["crush_behaviour"] = materials::ToString(m.crush_behaviour);
  j["compressive_strength_Pa"] =
      m.compressive_strength_Pa ? Json(*m.compressive_strength_Pa) : Json(nullptr);
  j["strength_method"] = m.strength_method.empty() ? Json(nullptr) : Json(m.strength_method);
  j["strength_source"] = m.strength_source.empty() ? Json(nullptr) : Json(m.strength_source);
  j["defined_at"] = m.origin.empty() ? Json(nullptr) : Json(m.origin);
  return j;
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

}  // namespace covopt::report
