#include "covopt/report/materials_json.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace covopt::report {
namespace {

using Json = nlohmann::ordered_json;

Json TextOrNull(const std::string& text) { return text.empty() ? Json(nullptr) : Json(text); }

Json BoundsOrNull(const std::optional<materials::Bounds>& bounds) {
  return bounds ? Json::array({bounds->low, bounds->high}) : Json(nullptr);
}

/// The compressive curve's keys (null without a curve).
void AddCurve(Json& j, const materials::Material& m) {
  const CompressiveCurve* curve = m.compressive_curve.get();
  Json points = nullptr;
  if (curve != nullptr) {
    points = Json::array();
    for (const StrainStressPoint& p : curve->points()) points.push_back(Json::array({p.strain, p.stress_Pa}));
  }
  j["compressive_curve"] = std::move(points);
  const auto stress_at_25 = materials::StressAt25Pa(m);
  j["stress_at_25_Pa"] = stress_at_25 ? Json(*stress_at_25) : Json(nullptr);
  j["curve_energy_density_J_per_m3"] = curve != nullptr ? Json(curve->total_energy_density_J_per_m3()) : Json(nullptr);
  j["curve_source"] = TextOrNull(m.curve_source);
  j["curve_rate"] = TextOrNull(m.curve_rate);
  j["curve_rate_per_s"] = m.curve_rate_per_s ? Json(*m.curve_rate_per_s) : Json(nullptr);
  j["recovers"] = m.recovers ? Json(*m.recovers) : Json(nullptr);
  j["rate_factor"] = BoundsOrNull(m.rate_factor);
  j["stress_at_25_band_Pa"] = BoundsOrNull(m.stress_at_25_band_Pa);
  j["curve_shape"] = TextOrNull(m.curve_shape);
}

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
  AddCurve(j, m);
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
