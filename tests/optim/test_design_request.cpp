// The one-call design request (optim/design.hpp): candidates from a catalog by name and
// family with the CLI's messages for unknown ones, the same answer as the two problems it
// wraps, the headline and brief report, and the warnings an answer carries.
#include <catch2/catch.hpp>

#include <algorithm>
#include <string>
#include <vector>

#include <covopt/core/number_format.hpp>
#include <covopt/materials.hpp>
#include <covopt/optim.hpp>

using namespace covopt;
using namespace covopt::optim;

TEST_CASE("SelectCandidates takes names in the order given, families, and says what it does not know", "[design]") {
  const materials::Catalog catalog = materials::Catalog::BuiltIn();
  const std::vector<CandidateMaterial> all = SelectCandidates(catalog);
  REQUIRE(all.size() == catalog.size());
  CHECK(all.front().name == catalog.materials().front().name);

  const std::vector<std::string> names = {"polyurethane foam 62.1", "Polystyrene Foam 27.6"};
  const std::vector<CandidateMaterial> two = SelectCandidates(catalog, names);
  REQUIRE(two.size() == 2);
  CHECK(two[0].name == "polyurethane foam 62.1");
  CHECK(two[1].name == "polystyrene foam 27.6");
  CHECK(two[1].poisson_ratio == 0.22);
  CHECK(two[1].family == "foam");
  CHECK_FALSE(two[1].poisson_assumed);

  const std::vector<std::string> elastomers = {"ELASTOMER"};
  for (const CandidateMaterial& c : SelectCandidates(catalog, {}, elastomers)) CHECK(c.family == "elastomer");
  for (const CandidateMaterial& c : SelectCandidates(catalog)) {
    const materials::Material* m = catalog.Find(c.name);
    REQUIRE(m != nullptr);
    CHECK(c.poisson_assumed == !m->poisson_ratio.has_value());
    CHECK(c.poisson_ratio == materials::PoissonRatioOrDefault(*m));
  }

  const std::vector<std::string> typo = {"polystyrene"};
  CHECK_THROWS_WITH(SelectCandidates(catalog, typo),
                    "no material 'polystyrene' in the catalog; did you mean 'polystyrene foam 27.6' or "
                    "'polystyrene foam 48.3'?");
  CHECK(catalog.MissingMaterialMessage("polystyrene") ==
        "no material 'polystyrene' in the catalog; did you mean 'polystyrene foam 27.6' or 'polystyrene foam 48.3'?");
  const std::vector<std::string> cheese = {"cheese"};
  CHECK_THROWS_WITH(SelectCandidates(catalog, {}, cheese), Catch::StartsWith("no family 'cheese' in the catalog (families: foam"));
}

TEST_CASE("Design answers both problems as the functions it wraps, in one call", "[design]") {
  DesignRequest request;
  request.materials = SelectCandidates(materials::Catalog::BuiltIn());
  const DesignResult a = Design(request);
  const ThinnestSafeCovering direct = FindThinnestSafeCovering(request.scene, request.materials, request.options);
  CHECK(a.ok());
  CHECK(a.problem == DesignProblem::kThinnestSafeCovering);
  CHECK(a.verdict == direct.verdict);
  CHECK(a.continuous.score.design.thickness_m == direct.continuous.score.design.thickness_m);
  REQUIRE(a.recommendation.has_value());
  REQUIRE(a.candidates.size() == direct.candidates.size());
  // Design's default answer holds over each material's stated uncertainty (its curve scaled over
  // its band and rate factor): it only thickens or drops the function's answers. Every material it
  // finds admissible the function finds admissible, no thicker.
  for (const CandidateOutcome& c : a.candidates) {
    if (!c.safe) continue;
    const auto d = std::find_if(direct.candidates.begin(), direct.candidates.end(),
                                [&](const CandidateOutcome& x) { return x.material.name == c.material.name; });
    REQUIRE(d != direct.candidates.end());
    CHECK(d->safe);
    CHECK(*d->recommended_thickness_m <= *c.recommended_thickness_m);
  }
  const CandidateOutcome& recommended = a.candidates[*a.recommendation];
  CHECK(a.message == "Recommended: " + recommended.material.name + " at " +
                         FormatFixed(*recommended.recommended_thickness_m * 1e3, 2) + " mm.");
  CHECK(recommended.score.peaks.covering_law == CoveringLaw::kFoam);  // a catalog curve: the foam law
  // The old 16 mm of XPS Foamular 250 would crush (issue 21); the old 20 mm of elastomer Shore A60
  // is a solid elastomer beyond its Hertz law's validity (strain > 0.2): neither is recommended.
  for (const CandidateOutcome& c : a.candidates) {
    if (c.material.name != "elastomer Shore A60") continue;
    CHECK_FALSE(c.safe);
    CHECK_FALSE(c.score.validity.within);
    CHECK(c.score.governing(a.rule).criterion == LimitingCriterion::kLawValidity);
  }
  CHECK_THAT(a.BriefReport(), Catch::StartsWith("covering-found (no-full-compression): Recommended:"));
  CHECK(a.covering_needed());
  // It uses over 95 % of its curve: the near-the-curve's-end warning says so.
  REQUIRE(a.warnings.size() == 1);
  CHECK_THAT(a.warnings.front(), Catch::Contains("within 5 % of its measured curve's end"));

  request.thickness_m = 0.010;
  const DesignResult b = Design(request);
  CHECK(b.problem == DesignProblem::kLeastInjuryAtThickness);
  CHECK(b.verdict == DesignVerdict::kNothingSafe);
  CHECK_THAT(b.message, Catch::StartsWith("Nothing is admissible at 10.00 mm"));
}

TEST_CASE("A design answer says when it rests on a bottomed-out covering or needs none", "[design]") {
  DesignRequest request;
  request.scene.robot.mass_kg = 2.0;
  request.materials = SelectCandidates(materials::Catalog::BuiltIn());
  request.options.allow_full_compression = true;
  const DesignResult paper = Design(request);
  CHECK(paper.criterion == DesignCriterion::kPaper);
  REQUIRE(paper.warnings.size() >= 2);
  CHECK_THAT(paper.warnings[0], Catch::StartsWith("the recommended covering is fully compressed at the peak"));

  request.scene.robot.speed_m_per_s = 0.2;
  const DesignResult gentle = Design(request);
  CHECK_FALSE(gentle.covering_needed());
  CHECK(gentle.message == "The bare robot is already safe in this scene: no covering is needed.");
  CHECK_THAT(gentle.BriefReport(), !Catch::Contains("Continuous"));

  request.options.safety_factor = 0.5;
  CHECK_THROWS_WITH(Design(request), Catch::Contains("safety factor"));
}
