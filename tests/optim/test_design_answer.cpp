// The default answer in Design() (optim/design_answer.hpp): a recommended curve material holds
// over its stated uncertainty at the recommended thickness, at least its nominal thinnest; when
// none can, the answer says so and carries the nearest changes.
#include <array>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/materials/catalog.hpp>
#include <covopt/optim/design.hpp>
#include <covopt/optim/material_range.hpp>

namespace {

using covopt::optim::Design;
using covopt::optim::DesignRequest;
using covopt::optim::DesignResult;

DesignRequest RequestFor(std::vector<std::string> names, double speed_m_per_s) {
  DesignRequest request;
  request.scene.robot.speed_m_per_s = speed_m_per_s;
  request.materials = covopt::optim::SelectCandidates(covopt::materials::Catalog::BuiltIn(), names);
  request.options.local_polish = false;  // the continuous optimum is not what is tested here
  return request;
}

}  // namespace

TEST_CASE("a recommended band material holds over its band, at least as thick as its nominal thinnest",
          "[design_answer]") {
  const std::string name = "neoprene sponge D1056 2C3";  // σ(25 %) band 62.1-89.6 kPa
  const DesignRequest request = RequestFor({name}, 1.2);  // the bare robot is unsafe above 1.09 m/s
  const DesignResult r = Design(request);
  REQUIRE(r.ok());
  REQUIRE(r.recommendation.has_value());
  const auto& c = r.candidates[*r.recommendation];
  CHECK(c.material.name == name);
  REQUIRE(r.material_range.has_value());
  CHECK(r.material_range->range.stated);
  CHECK(r.material_range->admissible());
  CHECK(r.material_range->thickness_m == *c.recommended_thickness_m);
  CHECK(r.material_range->scales.size() == 2);
  CHECK_FALSE(r.nearest_changes.has_value());
  const covopt::optim::RangedMaterial m = covopt::optim::RangedMaterialOf(c.material);
  const std::array<double, 1> nominal{1.0};
  const auto thinnest = covopt::optim::ThinnestAtScales(request.scene, m, request.options,
                                                        request.options.space.max_thickness_m, nominal);
  REQUIRE(thinnest.has_value());
  CHECK(*c.recommended_thickness_m >= *thinnest);
  CHECK(*c.recommended_thickness_m > *thinnest + 1e-4);  // the band's soft end needs more
  CHECK(c.safe);
  CHECK(c.margin == Approx(c.score.margin(r.rule)));
  CHECK(c.margin >= 0.0);
}

TEST_CASE("no material works: the answer says so and names the nearest changes", "[design_answer]") {
  const DesignRequest request = RequestFor({"neoprene sponge D1056 2C2", "vinyl-nitrile foam VN600"}, 3.0);
  const DesignResult r = Design(request);
  REQUIRE(r.ok());
  CHECK_FALSE(r.recommendation.has_value());
  CHECK(r.verdict != covopt::optim::DesignVerdict::kCoveringFound);
  REQUIRE(r.nearest_changes.has_value());
  CHECK(r.message.find(" No catalog material works for this scene; nearest changes for ") != std::string::npos);
  const auto& n = *r.nearest_changes;
  REQUIRE(n.speed.reachable);
  CHECK(n.speed.value < 3.0);
  CHECK(r.message.find(n.material) != std::string::npos);
  CHECK_FALSE(r.material_range.has_value());
}

TEST_CASE("under the Hertz law the curve's range is not used", "[design_answer]") {
  DesignRequest request = RequestFor({"neoprene sponge D1056 2C2"}, 0.2);
  request.scene.covering.law = covopt::CoveringLaw::kHertz;
  const DesignResult r = Design(request);
  REQUIRE(r.ok());
  for (const std::string& note : r.range_notes) CHECK(note.empty());
  if (r.material_range) {
    CHECK_FALSE(r.material_range->range.stated);
    CHECK(r.material_range->scales.size() == 1);
  }
}

TEST_CASE("at a given thickness the nearest speed and radius keep that thickness", "[design_answer]") {
  DesignRequest request = RequestFor({"neoprene sponge D1056 2C3", "vinyl-nitrile foam VN600"}, 1.5);
  request.thickness_m = 0.01;
  const DesignResult r = Design(request);
  REQUIRE(r.ok());
  CHECK_FALSE(r.recommendation.has_value());
  REQUIRE(r.nearest_changes.has_value());
  const auto& n = *r.nearest_changes;
  CHECK(n.at_thickness_m == 0.01);
  for (const std::string& note : r.range_notes) CHECK(note.find("not admissible over ") == 0);
  REQUIRE(n.speed.reachable);
  CHECK(n.speed.value < 1.5);
  // The speed found keeps 10 mm: admissible just below it there, not just above.
  const auto& catalog = covopt::materials::Catalog::BuiltIn();
  const covopt::optim::RangedMaterial m = covopt::optim::RangedMaterialOf(*catalog.Find(n.material));
  covopt::Scene below = request.scene, above = request.scene;
  below.robot.speed_m_per_s = n.speed.value * (1 - 1e-8);
  above.robot.speed_m_per_s = n.speed.value * (1 + 1e-8);
  CHECK(covopt::optim::CheckOverRange(below, m, 0.01, request.options).admissible());
  CHECK_FALSE(covopt::optim::CheckOverRange(above, m, 0.01, request.options).admissible());
  REQUIRE(n.thickness.reachable);
  CHECK(n.thickness.value > 0.01);
}
