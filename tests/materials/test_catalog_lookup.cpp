// Looking materials up: Find (exact name, ignoring case), Suggest ("did you mean" by edit
// distance and by words), Filter (closed ranges on E, nu and density, families, bases, a
// name part, and what happens to unknown nu/density), Range, and families(). A small
// hand-written catalog makes the expected answers obvious; a few checks run on the
// built-in catalog as a user would.

#include <algorithm>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "covopt/materials.hpp"

using covopt::materials::Catalog;
using covopt::materials::Material;
using covopt::materials::MaterialFilter;
using covopt::materials::ModulusBasis;
using covopt::materials::Range;

namespace {

const Catalog& Sample() {
  static const Catalog catalog = Catalog::FromTomlString(R"(
[[material]]
name = "soft foam"
family = "foam"
youngs_modulus_Pa = 1e6
density_kg_per_m3 = 20
modulus_basis = "compressive"
source = "s"

[[material]]
name = "stiff foam"
family = "Foam"
youngs_modulus_Pa = 50e6
poisson_ratio = 0.25
density_kg_per_m3 = 100
modulus_basis = "bending"
source = "s"

[[material]]
name = "rubber"
family = "elastomer"
youngs_modulus_Pa = 3e6
poisson_ratio = 0.49
modulus_basis = "tensile"
source = "s"

[[material]]
name = "hard shell"
family = "thermoplastic"
youngs_modulus_Pa = 3e9
poisson_ratio = 0.4
density_kg_per_m3 = 1100
modulus_basis = "as-printed"
source = "s"
)",
                                                                 "sample.toml");
  return catalog;
}

std::vector<std::string> Names(const std::vector<const Material*>& materials) {
  std::vector<std::string> names;
  for (const Material* m : materials) names.push_back(m->name);
  return names;
}

std::vector<std::string> Filtered(const MaterialFilter& filter) {
  return Names(Sample().Filter(filter));
}

using Names_ = std::vector<std::string>;

}  // namespace

TEST_CASE("Find matches whole names ignoring case", "[lookup]") {
  const Catalog& c = Sample();
  REQUIRE(c.Find("rubber") != nullptr);
  CHECK(c.Find("rubber")->youngs_modulus_Pa == 3e6);
  CHECK(c.Find("SOFT Foam") == &c.materials()[0]);
  CHECK(c.Find("soft") == nullptr);
  CHECK(c.Find("soft foam ") == nullptr);
  CHECK(c.Find("") == nullptr);
  CHECK(Catalog().Find("rubber") == nullptr);
}

TEST_CASE("Suggest offers close names, best first", "[lookup]") {
  const Catalog& c = Sample();
  CHECK(c.Suggest("rubbr") == Names_{"rubber"});
  CHECK(c.Suggest("Soft Fome") == Names_{"soft foam"});
  // Every word of the query in a name: "foam" is in two, the closer first.
  CHECK(c.Suggest("foam") == Names_{"soft foam", "stiff foam"});
  CHECK(c.Suggest("shell hard") == Names_{"hard shell"});
  CHECK(c.Suggest("titanium").empty());
  CHECK(c.Suggest("foam", 1) == Names_{"soft foam"});
}

TEST_CASE("Suggest finds built-in entries from partial names", "[lookup]") {
  const Catalog& catalog = Catalog::BuiltIn();
  CHECK(catalog.Suggest("polystyrene") ==
        Names_{"polystyrene foam 27.6", "polystyrene foam 48.3"});
  CHECK(catalog.Suggest("polystyrene 27.6").front() == "polystyrene foam 27.6");
  CHECK(catalog.Suggest("EPS 15") == Names_{"EPS geofoam EPS15"});
  CHECK(catalog.Suggest("plastazote") == Names_{"PE foam Plastazote LD33"});
  CHECK(catalog.Suggest("XPS Foamular 205").front() == "XPS Foamular 250");
}

TEST_CASE("Range is closed and unbounded where no bound is set", "[lookup]") {
  CHECK(Range{}.unbounded());
  CHECK(Range{}.Contains(-1e300));
  const Range r{1.0, 2.0};
  CHECK(r.Contains(1.0));
  CHECK(r.Contains(2.0));
  CHECK_FALSE(r.Contains(0.999));
  CHECK_FALSE(r.Contains(2.001));
  CHECK(Range{1.0, std::nullopt}.Contains(1e9));
  CHECK(Range{std::nullopt, 1.0}.Contains(-5.0));
}

TEST_CASE("Filter keeps entries in every range that is set", "[lookup]") {
  MaterialFilter f;
  CHECK(Filtered(f) == Names_{"soft foam", "stiff foam", "rubber", "hard shell"});

  f.youngs_modulus_Pa = {1e6, 50e6};  // closed at both ends
  CHECK(Filtered(f) == Names_{"soft foam", "stiff foam", "rubber"});
  f.youngs_modulus_Pa = {std::nullopt, 10e6};
  CHECK(Filtered(f) == Names_{"soft foam", "rubber"});

  f = {};
  f.density_kg_per_m3 = {std::nullopt, 150.0};
  CHECK(Filtered(f) == Names_{"soft foam", "stiff foam"});  // rubber's density is unknown
}

TEST_CASE("an unknown nu or density fails a bounded range unless unknowns are included",
          "[lookup]") {
  MaterialFilter f;
  f.poisson_ratio = {0.2, 0.45};
  CHECK(Filtered(f) == Names_{"stiff foam", "hard shell"});
  f.include_unknown = true;
  CHECK(Filtered(f) == Names_{"soft foam", "stiff foam", "hard shell"});

  f = {};
  f.density_kg_per_m3 = {10.0, std::nullopt};
  CHECK(Filtered(f) == Names_{"soft foam", "stiff foam", "hard shell"});
  f.include_unknown = true;
  CHECK(Filtered(f) == Names_{"soft foam", "stiff foam", "rubber", "hard shell"});
}

TEST_CASE("Filter by family ignores case, by basis and by a part of the name", "[lookup]") {
  MaterialFilter f;
  f.families = {"FOAM"};
  CHECK(Filtered(f) == Names_{"soft foam", "stiff foam"});
  f.families = {"foam", "elastomer"};
  CHECK(Filtered(f) == Names_{"soft foam", "stiff foam", "rubber"});
  f.families = {"metal"};
  CHECK(Filtered(f).empty());

  f = {};
  f.bases = {ModulusBasis::kBending, ModulusBasis::kTensile};
  CHECK(Filtered(f) == Names_{"stiff foam", "rubber"});

  f = {};
  f.name_contains = "FOAM";
  CHECK(Filtered(f) == Names_{"soft foam", "stiff foam"});

  f.youngs_modulus_Pa = {10e6, std::nullopt};
  CHECK(Filtered(f) == Names_{"stiff foam"});
}

TEST_CASE("families are distinct ignoring case, in order of first appearance", "[lookup]") {
  CHECK(Sample().families() == Names_{"foam", "elastomer", "thermoplastic"});
}

TEST_CASE("the built-in catalog answers a designer's range query", "[lookup]") {
  // Foams around the paper's optimum (10-100 MPa) light enough for a robot arm.
  MaterialFilter f;
  f.families = {"foam"};
  f.youngs_modulus_Pa = {10e6, 100e6};
  f.density_kg_per_m3 = {std::nullopt, 60.0};
  const std::vector<const Material*> found = Catalog::BuiltIn().Filter(f);
  REQUIRE(!found.empty());
  for (const Material* m : found) {
    CAPTURE(m->name);
    CHECK(m->family == "foam");
    CHECK(m->youngs_modulus_Pa >= 10e6);
    CHECK(m->youngs_modulus_Pa <= 100e6);
    REQUIRE(m->density_kg_per_m3.has_value());
    CHECK(*m->density_kg_per_m3 <= 60.0);
  }
  const auto names = Names(found);
  CHECK(std::find(names.begin(), names.end(), "polystyrene foam 27.6") != names.end());
  CHECK(std::find(names.begin(), names.end(), "polystyrene foam 48.3") == names.end());  // 100 kg/m³
}

TEST_CASE("Filter keeps known strengths in range and selects crush behaviours", "[filter][strength]") {
  using covopt::materials::CrushBehaviour;
  const Catalog& catalog = Catalog::BuiltIn();
  covopt::materials::MaterialFilter strong;
  strong.compressive_strength_Pa = {150e3, 300e3};
  const auto kept = catalog.Filter(strong);
  REQUIRE(!kept.empty());
  std::vector<std::string> names;
  for (const Material* m : kept) {
    names.push_back(m->name);
    REQUIRE(m->compressive_strength_Pa.has_value());
    CHECK(*m->compressive_strength_Pa >= 150e3);
    CHECK(*m->compressive_strength_Pa <= 300e3);
  }
  // FOAMULAR 250 (172 kPa), 400 (276 kPa), EPS29 (200 kPa), EPS39 (276 kPa), LB-X (300 kPa),
  // the hard helmet pad's FE card (yield 210 kPa).
  CHECK(names == std::vector<std::string>{"EPS geofoam EPS29", "EPS geofoam EPS39",
                                          "XPS Foamular 250", "XPS Foamular 400",
                                          "XPS Styrofoam LB-X", "helmet pad hard (FE card)"});
  // Unknown strengths never pass a strength range, not even with include_unknown.
  strong.include_unknown = true;
  CHECK(catalog.Filter(strong).size() == kept.size());

  covopt::materials::MaterialFilter soft;
  soft.crush_behaviours = {CrushBehaviour::kDoesNotCrush};
  const auto no_crush = catalog.Filter(soft);
  CHECK(no_crush.size() >= 20);
  for (const Material* m : no_crush) CHECK(m->crush_behaviour == CrushBehaviour::kDoesNotCrush);
  soft.crush_behaviours.push_back(CrushBehaviour::kUnknown);
  const auto either = catalog.Filter(soft);
  CHECK(either.size() > no_crush.size());
  soft.compressive_strength_Pa = {1.0, std::nullopt};  // a range and no crushing material: none
  CHECK(catalog.Filter(soft).empty());
}
