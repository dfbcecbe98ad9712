#include "covopt/report/body_regions_json.hpp"

#include <nlohmann/json.hpp>

#include "covopt/core/number_format.hpp"

namespace covopt::report {
namespace {

using Json = nlohmann::ordered_json;

Json RegionObject(const materials::BodyRegion& r) {
  const bool transient = r.transient_permitted();
  Json j;
  j["name"] = r.name;
  j["title"] = r.title;
  j["quasi_static_force_N"] = r.quasi_static_force_N;
  j["transient_permitted"] = transient;
  j["transient_factor"] = transient ? Json(r.transient_factor) : Json(nullptr);
  j["transient_force_N"] =
      transient ? Json(r.transient_factor * r.quasi_static_force_N) : Json(nullptr);
  j["transient_rule"] = TransientRule(r);
  j["stiffness_N_per_m"] = r.stiffness_N_per_m;
  j["effective_mass_kg"] = r.effective_mass_kg;
  j["default_area"] = r.LowestPressureArea().name;
  Json areas = Json::array();
  for (const materials::BodyArea& a : r.areas) {
    Json area;
    area["name"] = a.name;
    area["title"] = a.title;
    area["number"] = a.number;
    area["quasi_static_pressure_Pa"] = a.quasi_static_pressure_Pa;
    area["transient_pressure_Pa"] =
        transient ? Json(r.transient_factor * a.quasi_static_pressure_Pa) : Json(nullptr);
    areas.push_back(std::move(area));
  }
  j["areas"] = std::move(areas);
  j["sources"] = r.sources;
  if (r.table) {
    j["limit_table"] = {{"title", r.table->title}, {"edition", r.table->edition}, {"source", r.table->source},
                        {"sha256", r.table->sha256}};
  }
  return j;
}

}  // namespace

std::string TransientRule(const materials::BodyRegion& region) {
  if (!region.transient_permitted()) {
    const materials::LimitTableInfo& table =
        region.table ? *region.table : materials::BodyRegionTable::BuiltIn().info();
    return "not permitted (" + table.NoTransientClause() + ")";
  }
  return FormatSignificant(region.transient_factor, 6) + "× the quasi-static limits";
}

std::string BodyRegionJson(const materials::BodyRegion& region, int indent) {
  return RegionObject(region).dump(indent);
}

std::string BodyRegionsJson(std::span<const materials::BodyRegion> regions, int indent) {
  Json array = Json::array();
  for (const materials::BodyRegion& r : regions) array.push_back(RegionObject(r));
  return array.dump(indent);
}

}  // namespace covopt::report
