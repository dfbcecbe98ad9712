// The default answer (optim/material_range.hpp): a material's verdict over its stated
// uncertainty (its curve's scale over the band and the rate factor), the thinnest thickness
// admissible over it, and the nearest changes when no material works. Checked against brute
// force (21 interior scales), the one-scale thinnest thickness, the speed limit of each end
// (MaxSafeSpeed) and the change of verdict on either side of each nearest change.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/materials/catalog.hpp>
#include <covopt/optim/material_range.hpp>
#include <covopt/optim/speed_limit.hpp>

namespace {

using covopt::Scene;
using covopt::Verdict;
using covopt::optim::CheckOverRange;
using covopt::optim::DesignOptions;
using covopt::optim::RangedMaterial;
using covopt::optim::RangedMaterialOf;
using covopt::optim::RangeVerdictAt;

const covopt::materials::Material& Entry(const std::string& name) {
  const covopt::materials::Material* m = covopt::materials::Catalog::BuiltIn().Find(name);
  REQUIRE(m != nullptr);
  return *m;
}

constexpr const char* kBandMaterial = "neoprene sponge D1056 2C2";  // σ(25 %) band 34.5-62.1 kPa
constexpr const char* kRateMaterial = "vinyl-nitrile foam VN600";   // rate factor [1, 4]

/// The paper's scene at `speed`, with a robot of `radius`.
Scene SceneAt(double speed_m_per_s, double radius_m = 0.015) {
  Scene s;
  s.robot.speed_m_per_s = speed_m_per_s;
  s.robot.radius_m = radius_m;
  return s;
}

double CriterionRatio(const Verdict& v, std::string_view name) {
  const covopt::Criterion* c = v.Find(name);
  REQUIRE(c != nullptr);
  return c->ratio;
}

}  // namespace

TEST_CASE("the curve's scale range is the band over sigma25 times the rate factor", "[material_range]") {
  const covopt::materials::Material& band = Entry(kBandMaterial);
  const auto r = covopt::optim::CurveScaleRangeOf(band);
  REQUIRE(r.stated);
  REQUIRE(band.stress_at_25_band_Pa.has_value());
  const double s25 = band.compressive_curve->StressAt(0.25);
  const double rate_lo = band.rate_factor ? band.rate_factor->low : 1.0;
  const double rate_hi = band.rate_factor ? band.rate_factor->high : 1.0;
  CHECK(r.low == Approx(band.stress_at_25_band_Pa->low / s25 * rate_lo).epsilon(1e-14));
  CHECK(r.high == Approx(band.stress_at_25_band_Pa->high / s25 * rate_hi).epsilon(1e-14));
  CHECK(r.low < 1.0);
  CHECK(r.high > 1.0);
  CHECK(r.Describe().find("34.5–62.1 kPa") != std::string::npos);

  const auto vn = covopt::optim::CurveScaleRangeOf(Entry(kRateMaterial));
  CHECK(vn.stated);
  CHECK(vn.low == 1.0);
  CHECK(vn.high == 4.0);
  CHECK(vn.Describe().find("rate factor 1–4") != std::string::npos);

  // No band, no rate factor: scale 1 only, and said so.
  const covopt::CompressiveCurve plain = *Entry(kRateMaterial).compressive_curve;
  const auto none = covopt::optim::CurveScaleRangeOf(&plain, std::nullopt, std::nullopt);
  CHECK_FALSE(none.stated);
  CHECK(none.low == 1.0);
  CHECK(none.high == 1.0);
  CHECK(none.Describe().find("not stated") != std::string::npos);
  // Under the Hertz law the curve (and its range) is not used.
  const RangedMaterial hertz = RangedMaterialOf(Entry(kRateMaterial), covopt::CoveringLaw::kHertz);
  CHECK_FALSE(hertz.foam());
  CHECK_FALSE(hertz.range.stated);
}

TEST_CASE("the ends of the scale range govern: no interior scale is worse (brute force over 21 scales)",
          "[material_range]") {
  const DesignOptions options;  // the default rule: the covering's travel counts
  int within_cases = 0;
  for (const char* name : {kBandMaterial, kRateMaterial}) {
    const RangedMaterial m = RangedMaterialOf(Entry(name));
    REQUIRE(m.foam());
    for (double speed : {0.05, 0.2, 0.6}) {
      for (double thickness : {0.005, 0.02, 0.05}) {
        CAPTURE(name, speed, thickness);
        const Scene scene = SceneAt(speed);
        const auto check = CheckOverRange(scene, m, thickness, options);
        REQUIRE(check.scales.size() == 2);
        const double worst = check.worst().governing_ratio();
        const bool within_at_low = CriterionRatio(check.at_low(), "within-curve") <= 1.0;
        within_cases += within_at_low;
        for (int k = 1; k <= 21; ++k) {
          const double s = m.range.low * std::pow(m.range.high / m.range.low, k / 22.0);
          CAPTURE(s);
          const Verdict v = RangeVerdictAt(scene, m, thickness, s, options);
          CHECK(v.governing_ratio() <= worst * (1.0 + 1e-12));
          if (check.admissible()) CHECK(v.safe());
          // The share of the curve used falls with the scale.
          CHECK(CriterionRatio(v, "within-curve") <= CriterionRatio(check.at_low(), "within-curve") * (1.0 + 1e-12));
          if (!within_at_low) continue;
          // Within the curve every injury rises with the scale: the high end bounds it.
          for (std::string_view injury : {"laceration", "contusion", "fracture"}) {
            CHECK(CriterionRatio(v, injury) <= CriterionRatio(check.at_high(), injury) * (1.0 + 1e-12));
            CHECK(CriterionRatio(v, injury) >= CriterionRatio(check.at_low(), injury) * (1.0 - 1e-12));
          }
        }
      }
    }
  }
  CHECK(within_cases >= 4);
}

TEST_CASE("under the paper's criterion the range check scans inside the range, where a used-up layer can be worst",
          "[material_range]") {
  DesignOptions paper;
  paper.allow_full_compression = true;
  const RangedMaterial m = RangedMaterialOf(Entry(kRateMaterial));
  const Scene scene = SceneAt(0.6);
  const auto check = CheckOverRange(scene, m, 0.02, paper);
  REQUIRE(check.scales.size() == 2 + covopt::optim::kInteriorRangeScales);
  CHECK(std::is_sorted(check.scales.begin(), check.scales.end()));
  // VN600 at 20 mm and 0.6 m/s: used up at its quasi-static curve, within it at 4x; the
  // laceration peaks where the layer is just used up, inside the range.
  CHECK(CriterionRatio(check.at_low(), "within-curve") > 1.0);
  CHECK(CriterionRatio(check.at_high(), "within-curve") < 1.0);
  double interior = 0.0;
  for (std::size_t i = 1; i + 1 < check.verdicts.size(); ++i) {
    interior = std::max(interior, CriterionRatio(check.verdicts[i], "laceration"));
  }
  CHECK(interior > 1.05 * std::max(CriterionRatio(check.at_low(), "laceration"),
                                   CriterionRatio(check.at_high(), "laceration")));
  CHECK(check.worst().governing_ratio() >= interior);
}

TEST_CASE("a band material's thickness over its range is at least its nominal thinnest, and brackets the verdict",
          "[material_range]") {
  DesignOptions options;
  options.thickness_step_m = 0.0;  // the exact thinnest, to check the bracket
  const RangedMaterial m = RangedMaterialOf(Entry(kBandMaterial));
  const Scene scene = SceneAt(0.2);
  const std::array<double, 1> nominal_scale{1.0};
  const auto nominal = covopt::optim::ThinnestAtScales(scene, m, options, options.space.max_thickness_m, nominal_scale);
  const auto robust = covopt::optim::ThinnestOverRange(scene, m, options, options.space.max_thickness_m);
  REQUIRE(nominal.has_value());
  REQUIRE(robust.has_value());
  CHECK(*robust >= *nominal);
  CHECK(*robust > *nominal + 1e-4);  // the band's soft end needs more travel in this scene
  CHECK(CheckOverRange(scene, m, *robust, options).admissible());
  CHECK_FALSE(CheckOverRange(scene, m, *robust - 2 * options.thickness_resolution_m, options).admissible());
  CHECK_FALSE(CheckOverRange(scene, m, *nominal, options).admissible());
}

TEST_CASE("the nearest speed is the lower of the two ends' speed limits", "[material_range]") {
  DesignOptions options;
  const std::vector<RangedMaterial> one{RangedMaterialOf(Entry(kBandMaterial))};
  const Scene scene = SceneAt(2.0);
  const auto changes = covopt::optim::FindNearestChanges(scene, one, options);
  REQUIRE(changes.has_value());
  CHECK(changes->material == kBandMaterial);
  REQUIRE(changes->speed.reachable);
  // MaxSafeSpeed of each end with the design rule as a limit (the travel counts: keep-travel).
  double lowest = 1e300;
  for (double s : {one[0].range.low, one[0].range.high}) {
    Scene end = scene;
    end.covering = one[0].covering;
    end.covering.thickness_m = options.space.max_thickness_m;
    end.covering.law = covopt::CoveringLaw::kFoam;
    end.covering.compressive_curve = std::make_shared<const covopt::CompressiveCurve>(one[0].covering.compressive_curve->Scaled(s));
    covopt::optim::SpeedLimitOptions limit_options;  // no full compression: the travel rule is a limit
    const auto limit = covopt::optim::MaxSafeSpeed(end, limit_options);
    REQUIRE(limit.status == covopt::optim::SpeedLimitStatus::kLimited);
    lowest = std::min(lowest, limit.max_safe_speed_m_per_s);
  }
  CHECK(changes->speed.value == Approx(lowest).epsilon(1e-8));
  // The verdict changes across it.
  Scene below = scene, above = scene;
  below.robot.speed_m_per_s = changes->speed.value * (1 - 1e-8);
  above.robot.speed_m_per_s = changes->speed.value * (1 + 1e-8);
  CHECK(CheckOverRange(below, one[0], options.space.max_thickness_m, options).admissible());
  CHECK_FALSE(CheckOverRange(above, one[0], options.space.max_thickness_m, options).admissible());
}

TEST_CASE("the nearest thickness and radius bracket the change of verdict", "[material_range]") {
  DesignOptions options;
  options.thickness_step_m = 0.0;
  const std::vector<RangedMaterial> one{RangedMaterialOf(Entry(kRateMaterial))};
  const Scene scene = SceneAt(2.5);
  const auto changes = covopt::optim::FindNearestChanges(scene, one, options);
  REQUIRE(changes.has_value());
  REQUIRE_FALSE(CheckOverRange(scene, one[0], options.space.max_thickness_m, options).admissible());
  REQUIRE(changes->thickness.reachable);
  const double b = changes->thickness.value;
  CHECK(b > options.space.max_thickness_m);
  CHECK(b <= covopt::optim::kNearestChangeMaxThickness_m);
  CHECK(CheckOverRange(scene, one[0], b, options).admissible());
  CHECK_FALSE(CheckOverRange(scene, one[0], b - 2 * options.thickness_resolution_m, options).admissible());
  if (changes->radius.reachable) {
    const double r = changes->radius.value;
    CHECK(r > scene.robot.radius_m);
    Scene at = scene, below = scene;
    at.robot.radius_m = r;
    below.robot.radius_m = r * (1 - 1e-8);
    CHECK(CheckOverRange(at, one[0], options.space.max_thickness_m, options).admissible());
    CHECK_FALSE(CheckOverRange(below, one[0], options.space.max_thickness_m, options).admissible());
  } else {
    // Not reachable: not admissible at the largest radius considered.
    Scene at = scene;
    at.robot.radius_m = covopt::optim::kNearestChangeMaxRadius_m;
    CHECK_FALSE(CheckOverRange(at, one[0], options.space.max_thickness_m, options).admissible());
    CHECK(changes->radius.note.find("not reachable") != std::string::npos);
  }
}

TEST_CASE("a change that cannot help is not reachable", "[material_range]") {
  const DesignOptions options;
  const std::vector<RangedMaterial> one{RangedMaterialOf(Entry(kBandMaterial))};
  Scene scene = SceneAt(20.0);
  scene.robot.mass_kg = 100.0;
  const auto changes = covopt::optim::FindNearestChanges(scene, one, options);
  REQUIRE(changes.has_value());
  CHECK(changes->speed.reachable);  // slower always helps
  CHECK_FALSE(changes->thickness.reachable);
  CHECK(changes->thickness.note.find("not reachable") != std::string::npos);
  Scene thickest = scene;
  CHECK_FALSE(CheckOverRange(thickest, one[0], covopt::optim::kNearestChangeMaxThickness_m, options).admissible());
  CHECK_FALSE(changes->radius.reachable);
  CHECK(changes->Describe().find("nearest changes for") != std::string::npos);
}

TEST_CASE("the nearest changes are those of the material nearest to admissible", "[material_range]") {
  const DesignOptions options;
  const std::vector<RangedMaterial> two{RangedMaterialOf(Entry(kBandMaterial)), RangedMaterialOf(Entry(kRateMaterial))};
  const Scene scene = SceneAt(1.5);
  const auto changes = covopt::optim::FindNearestChanges(scene, two, options);
  REQUIRE(changes.has_value());
  double best = 1e300;
  std::string name;
  for (const RangedMaterial& m : two) {
    const double ratio = CheckOverRange(scene, m, options.space.max_thickness_m, options).worst().governing_ratio();
    if (ratio < best) {
      best = ratio;
      name = m.name;
    }
  }
  CHECK(changes->material == name);
  CHECK(changes->worst_ratio_at_thickness == Approx(best).epsilon(1e-14));
  CHECK_FALSE(covopt::optim::FindNearestChanges(scene, std::vector<RangedMaterial>{}, options).has_value());
}
