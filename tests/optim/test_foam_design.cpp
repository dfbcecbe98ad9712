// The design commands take the foam law for catalog materials with a measured curve (issue 35,
// issue 35): the design's score is an independent exact-path impact of the material's
// covering under the foam law; a thicker layer is never less safe; the Hertz law, when asked
// for, is the curve-less design of before exactly; foam without a curve is refused naming the
// material; a design out of its law's validity is not admissible; robust design and the
// elasticities run with a foam layer (central differences: the analytic ones are the Hertz law's).
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/core/impact_result.hpp>
#include <covopt/core/time_integration.hpp>
#include <covopt/materials/catalog.hpp>
#include <covopt/optim/design.hpp>
#include <covopt/optim/robust_design.hpp>
#include <covopt/optim/robust_sensitivity.hpp>

namespace {

using Catch::Matchers::Contains;
using covopt::CoveringLaw;
using covopt::Scene;
namespace co = covopt::optim;
namespace cm = covopt::materials;

constexpr const char* kVn600 = "vinyl-nitrile foam VN600";
constexpr const char* kPoron = "PU foam PORON (NIST hyperfoam fit)";

const cm::Material& Material(const char* name) {
  const cm::Material* m = cm::Catalog::BuiltIn().Find(name);
  REQUIRE(m != nullptr);
  return *m;
}

std::vector<co::CandidateMaterial> Candidates(std::vector<std::string> names) {
  return co::SelectCandidates(cm::Catalog::BuiltIn(), names);
}

/// The injury ratios of `scene` with `covering`, computed here without the oracle: the exact
/// path's peaks and Assess.
covopt::InjuryAssessment Independent(Scene scene, const covopt::CoveringSpec& covering) {
  scene.covering = covering;
  const covopt::ImpactModel model = covopt::ImpactModel::FromScene(scene);
  return covopt::Assess(covopt::ExactPeaks(model), {}, scene.head.area);
}

}  // namespace

TEST_CASE("optimize designs a curve material under the foam law: its score is the material's own foam impact",
          "[design][foam]") {
  co::DesignRequest request;  // the paper's scene, 2 m/s
  request.materials = Candidates({kVn600, kPoron});
  const co::DesignResult r = co::Design(request);
  REQUIRE(r.ok());
  REQUIRE(r.candidates.size() == 2);
  for (const co::CandidateOutcome& c : r.candidates) {
    INFO(c.material.name);
    REQUIRE(c.material.compressive_curve != nullptr);
    CHECK(c.score.peaks.covering_law == CoveringLaw::kFoam);
    CHECK(c.score.validity.within);
    CHECK_THAT(c.score.validity.note, Contains("foam law"));
    // The same material and thickness from the catalog's own covering (materials::CoveringOf,
    // law auto): the exact path, judged here.
    const double b = c.score.design.thickness_m;
    const covopt::InjuryAssessment a = Independent(request.scene, cm::CoveringOf(Material(c.material.name.c_str()), b));
    CHECK(c.score.laceration_ratio == Approx(a.laceration.ratio).epsilon(1e-12));
    CHECK(c.score.contusion_ratio == Approx(a.contusion.ratio).epsilon(1e-12));
    CHECK(c.score.fracture_ratio == Approx(a.fracture.ratio).epsilon(1e-12));
    // The time path of the same foam impact agrees to its tolerance.
    Scene covered = request.scene;
    covered.covering = cm::CoveringOf(Material(c.material.name.c_str()), b);
    covopt::TimeIntegrationOptions t;
    t.relative_tolerance = 1e-10;
    const covopt::ImpactResult timed = covopt::SimulateImpact(covopt::ImpactModel::FromScene(covered), t);
    REQUIRE(timed.ok());
    CHECK(timed.peaks.max_tensile_stress_Pa ==
          Approx(c.score.laceration_ratio * covopt::InjuryLimits{}.laceration_tensile_stress_Pa).epsilon(1e-5));
    // Where admissible, the design rule within-curve holds: the strain at the peak within the curve.
    if (c.safe) {
      CHECK_FALSE(c.score.peaks.fully_compressed);
      CHECK(c.score.compression_ratio <= 1.0);
      CHECK(c.score.peaks.covering_strain_at_peak <= c.material.compressive_curve->last_strain());
    }
  }
  // The governing criterion of the travel is named for the foam law.
  CHECK(co::ToString(co::LimitingCriterion::kFullCompression, CoveringLaw::kFoam) == "within-curve");
  CHECK(co::ToString(co::LimitingCriterion::kFullCompression, CoveringLaw::kHertz) == "full-compression");
}

TEST_CASE("a thicker layer of a curve material is never less safe under the foam law", "[design][foam]") {
  for (const char* name : {kVn600, kPoron}) {
    const co::CandidateMaterial material = Candidates({name}).front();
    int admissible_count = 0;
    for (const double speed : {0.5, 1.0, 2.0}) {
      Scene scene;
      scene.robot.speed_m_per_s = speed;
      const co::ExactPathOracle oracle(scene, 0.25);
      double previous_worst = 1e300;
      bool was_admissible = false, was_within = false;
      const co::DesignRule rule;
      for (int i = 1; i <= 60; ++i) {
        const double b = 1e-3 * i;  // 1 .. 60 mm
        const co::DesignScore s = oracle.ScoreCovering(co::CoveringOf(material, b, CoveringLaw::kAuto));
        INFO(name << " at " << speed << " m/s, " << b * 1e3 << " mm");
        REQUIRE(s.peaks.covering_law == CoveringLaw::kFoam);
        // Admissibility (the design rule within-curve) only grows with the thickness.
        CHECK((s.admissible(rule) || !was_admissible));
        admissible_count += s.admissible(rule) ? 1 : 0;
        // Within the curve the injury ratios fall with the thickness. (A used-up layer is not:
        // its stop carries F = 2π R h W(ε_end), which grows with h, so just past the stop a
        // thicker used-up layer can read slightly worse; the design rule never admits one.)
        const bool within = !s.peaks.fully_compressed;
        if (within && was_within) CHECK(s.worst_ratio() <= previous_worst * (1 + 1e-12));
        CHECK((within || !was_within));  // once within the curve, thicker stays within
        previous_worst = s.worst_ratio();
        was_admissible = s.admissible(rule);
        was_within = within;
      }
    }
    CHECK(admissible_count > 0);
  }
}

TEST_CASE("covering law hertz designs curve materials exactly as the curve-less design of before",
          "[design][foam][hertz]") {
  co::DesignRequest hertz;
  hertz.materials = Candidates({kVn600, kPoron, "elastomer Shore A40", "polystyrene foam 27.6"});
  hertz.options.covering_law = CoveringLaw::kHertz;
  co::DesignRequest before = hertz;  // the candidates as main had them: no curve, law auto
  before.options.covering_law = CoveringLaw::kAuto;
  for (co::CandidateMaterial& m : before.materials) m.compressive_curve = nullptr;
  const co::DesignResult a = co::Design(hertz), b = co::Design(before);
  REQUIRE(a.candidates.size() == b.candidates.size());
  CHECK(a.message == b.message);
  for (std::size_t i = 0; i < a.candidates.size(); ++i) {
    const co::CandidateOutcome &x = a.candidates[i], &y = b.candidates[i];
    INFO(x.material.name);
    CHECK(x.material.name == y.material.name);
    CHECK(x.score.peaks.covering_law == CoveringLaw::kHertz);
    CHECK(x.score.laceration_ratio == y.score.laceration_ratio);
    CHECK(x.score.contusion_ratio == y.score.contusion_ratio);
    CHECK(x.score.compression_ratio == y.score.compression_ratio);
    CHECK(x.score.design.thickness_m == y.score.design.thickness_m);
    CHECK(x.min_safe_thickness_m == y.min_safe_thickness_m);
    CHECK(x.margin == y.margin);
  }
  // Under auto the curve materials read otherwise (the foam law).
  co::DesignRequest automatic = hertz;
  automatic.options.covering_law = CoveringLaw::kAuto;
  const co::DesignResult c = co::Design(automatic);
  for (const co::CandidateOutcome& x : c.candidates) {
    CHECK(x.score.peaks.covering_law == (x.material.compressive_curve ? CoveringLaw::kFoam : CoveringLaw::kHertz));
  }
}

TEST_CASE("covering law foam refuses a material without a curve, naming it, and keeps the curve materials",
          "[design][foam]") {
  co::DesignRequest request;
  request.materials = Candidates({kVn600, "elastomer Shore A40"});
  request.options.covering_law = CoveringLaw::kFoam;
  CHECK_THROWS_WITH(co::Design(request), Contains("material 'elastomer Shore A40' has no compressive_curve"));
  co::KeepCandidatesForLaw(request.materials, CoveringLaw::kFoam);
  REQUIRE(request.materials.size() == 1);
  CHECK(request.materials.front().name == kVn600);
  std::vector<co::CandidateMaterial> all = Candidates({kVn600, "elastomer Shore A40"});
  co::KeepCandidatesForLaw(all, CoveringLaw::kAuto);
  CHECK(all.size() == 2);
  const co::DesignResult r = co::Design(request);
  CHECK(r.candidates.front().score.peaks.covering_law == CoveringLaw::kFoam);
  // CandidateOf carries the material's curve and its stated uncertainty.
  const co::CandidateMaterial band = co::CandidateOf(Material("neoprene sponge D1056 2C2"));
  CHECK(band.compressive_curve != nullptr);
  CHECK(band.stress_at_25_band_Pa.has_value());
  CHECK(band.recovers.has_value());
}

TEST_CASE("a design out of its law's validity is never admissible and the paper's criterion accepts Hertz full "
          "compression", "[design][validity]") {
  co::DesignScore s;
  s.design = {1e6, 0.01};
  s.laceration_ratio = 0.5;
  s.contusion_ratio = 0.4;
  s.peaks.covering_law = CoveringLaw::kHertz;
  const co::DesignRule rule;
  REQUIRE(s.admissible(rule));
  // Within, the law's validity counts as how far along its limits (not derated by the SF).
  s.validity = {true, "solid elastomer under the Hertz law: within its limits", 0.7, 0.7};
  const co::DesignRule sf2{2.0};
  CHECK(s.governing(sf2).criterion == co::LimitingCriterion::kLaceration);  // 2 x 0.5 > 0.7
  s.validity.ratio = s.validity.ratio_full_compression_allowed = 0.9;
  CHECK(s.admissible(rule));
  CHECK(s.governing(rule).criterion == co::LimitingCriterion::kLawValidity);
  CHECK(s.margin(rule) == Approx(0.1));
  s.validity = {false, "solid elastomer under the Hertz law: peak strain 0.43 > 0.20", 2.15, 2.15};
  CHECK_FALSE(s.admissible(rule));
  CHECK(s.governing(rule).criterion == co::LimitingCriterion::kLawValidity);
  CHECK(s.margin(rule) == Approx(1.0 - 2.15));
  CHECK(s.margin(sf2) == Approx(1.0 - 2.15));  // the model's range: not derated
  co::DesignRule paper = rule;
  paper.criterion = co::DesignCriterion::kPaper;
  CHECK_FALSE(s.admissible(paper));  // not fully compressed: the elastomer's limit counts
  // Fully compressed (travel ratio 1.3) within the elastomer's limits: Park's phase 3, accepted by
  // the paper's criterion, not by the default one.
  s.peaks.fully_compressed = true;
  s.validity = {false, "Hertz law: fully compressed", 1.3, 0.3};
  CHECK(s.admissible(paper));
  CHECK(s.margin(paper) == Approx(0.5));  // the injuries govern: the travel is no limit there
  CHECK(s.judged_validity(paper).within);
  CHECK_FALSE(s.admissible(rule));   // the default rule: the travel and the law's validity both refuse it
  CHECK(s.governing(rule).ratio == Approx(1.3));
  s.validity.ratio_full_compression_allowed = 1.2;  // and beyond the elastomer's limits: refused by both
  CHECK_FALSE(s.admissible(paper));
  CHECK_FALSE(s.judged_validity(paper).within);
  CHECK(s.governing(paper).criterion == co::LimitingCriterion::kLawValidity);
  CHECK(co::ToString(co::LimitingCriterion::kLawValidity) == "law-validity");
}

TEST_CASE("robust design with a curve material judges its foam layer over the box", "[robust][foam]") {
  const Scene scene;
  const co::UncertaintyBox box =
      co::UncertaintyBox::FromScene(scene, std::vector<co::UncertainInput>{{"head-mass", 3.7, 5.8}});
  co::RobustDesignOptions options;
  const co::RobustThinnestCovering robust = co::FindRobustThinnestCovering(box, Candidates({kVn600}), options);
  REQUIRE(robust.candidates.size() == 1);
  const co::RobustCandidate& c = robust.candidates.front();
  CHECK(c.worst_case.scene.covering.compressive_curve != nullptr);
  CHECK(c.worst_case.scene.covering.law == CoveringLaw::kFoam);
  if (c.outcome.safe) {
    // Admissible at the worst case of the box, and at the box's nominal scene too.
    const co::ExactPathOracle oracle(box.nominal(), 0.25);
    const co::DesignScore nominal =
        oracle.ScoreCovering(co::CoveringOf(c.outcome.material, *c.outcome.recommended_thickness_m, CoveringLaw::kAuto));
    CHECK(nominal.admissible(options.design.rule()));
  }
}

TEST_CASE("elasticities of a foam-covered scene are central differences", "[robust][foam][elasticities]") {
  Scene scene;
  scene.covering = cm::CoveringOf(Material(kVn600), 0.02);
  scene.robot.speed_m_per_s = 0.3;  // within the curve
  const co::ElasticityTable table = co::ComputeElasticities(scene);
  bool thickness_seen = false;
  for (const co::InputElasticity& row : table.rows) {
    if (row.field != "covering-thickness") continue;
    thickness_seen = true;
    CHECK(row.method != co::DerivativeMethod::kAnalytic);
    CHECK(row.reliable);
    CHECK(row.laceration < 0.0);  // a thicker foam layer lowers the peak stress
  }
  CHECK(thickness_seen);
}
