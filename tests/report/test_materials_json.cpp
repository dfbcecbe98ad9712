// covopt::report::MaterialJson and MaterialsJson: one object per catalog entry with the
// documented keys; what the source does not give (ν, density, strength) is null.

#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "covopt/materials/catalog.hpp"
#include "covopt/report/materials_json.hpp"

namespace {

using Json = nlohmann::json;

const covopt::materials::Material& Entry(const std::string& name) {
  const auto* m = covopt::materials::Catalog::BuiltIn().Find(name);
  REQUIRE(m != nullptr);
  return *m;
}

}  // namespace

TEST_CASE("MaterialJson has every documented key and the entry's numbers exactly", "[report][json][materials]") {
  const auto& m = Entry("polystyrene foam 27.6");
  const Json j = Json::parse(covopt::report::MaterialJson(m));
  for (const char* key : {"name", "family", "youngs_modulus_Pa", "poisson_ratio", "density_kg_per_m3",
                          "modulus_basis", "source", "note", "crush_behaviour", "compressive_strength_Pa",
                          "strength_method", "strength_source", "defined_at"}) {
    INFO(key);
    CHECK(j.contains(key));
  }
  CHECK(j["name"] == "polystyrene foam 27.6");
  CHECK(j["youngs_modulus_Pa"].get<double>() == m.youngs_modulus_Pa);
  REQUIRE(m.poisson_ratio.has_value());
  CHECK(j["poisson_ratio"].get<double>() == *m.poisson_ratio);
  // The paper gives no strength for its foams: unknown is null, not 0.
  CHECK_FALSE(m.compressive_strength_Pa.has_value());
  CHECK(j["compressive_strength_Pa"].is_null());
}

TEST_CASE("MaterialJson: an unknown Poisson ratio is null, a known strength a number", "[report][json][materials]") {
  const auto& m = Entry("XPS Foamular 250");
  const Json j = Json::parse(covopt::report::MaterialJson(m));
  CHECK_FALSE(m.poisson_ratio.has_value());
  CHECK(j["poisson_ratio"].is_null());
  REQUIRE(m.compressive_strength_Pa.has_value());
  CHECK(j["compressive_strength_Pa"].get<double>() == *m.compressive_strength_Pa);
}

TEST_CASE("MaterialsJson is an array of the same objects, in the order given", "[report][json][materials]") {
  const auto& catalog = covopt::materials::Catalog::BuiltIn();
  std::vector<const covopt::materials::Material*> all;
  for (const auto& m : catalog.materials()) all.push_back(&m);
  const Json j = Json::parse(covopt::report::MaterialsJson(all));
  REQUIRE(j.is_array());
  REQUIRE(j.size() == all.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    CHECK(j[i] == Json::parse(covopt::report::MaterialJson(*all[i])));
  }
}
