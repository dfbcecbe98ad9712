// Body-region verdicts and speed limits with a foam covering (docs/model.md §15.6): the round
// check numbers of model.md §15.7 through MaxSafeSpeed, the closed-form limit against a bisection on the verdict,
// the covering used up reported as its own speed (not a limit, not UNSAFE) unless keep_travel,
// keep_travel reproducing the Hertz full-compression limits, a covering never below the bare
// robot's limit on a flat face, and thicker foam never lowering the limit.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/core/compressive_curve.hpp>
#include <covopt/materials/body_regions.hpp>
#include <covopt/optim/body_region_check.hpp>

namespace {

using covopt::BodyContactScene;
using covopt::CompressiveCurve;
using covopt::ContactType;
using covopt::StrainStressPoint;
using covopt::materials::BodyLimits;
using covopt::materials::BodyRegionTable;
namespace co = covopt::optim;

std::shared_ptr<const CompressiveCurve> Curve(const std::vector<StrainStressPoint>& points) {
  return std::make_shared<const CompressiveCurve>(CompressiveCurve::FromPoints(points));
}
/// VN600 vinyl-nitrile: the eleven rounded points of model.md §15.7, and the six the round numbers were computed with [Pa].
std::shared_ptr<const CompressiveCurve> Vn600() {
  static const auto curve = Curve({{0.02, 14.3e3}, {0.05, 22.0e3}, {0.10, 30.2e3}, {0.15, 37.4e3},
                                   {0.20, 45.9e3}, {0.25, 57.3e3}, {0.30, 72.2e3}, {0.35, 91.6e3},
                                   {0.40, 118.0e3}, {0.45, 153.2e3}, {0.49, 189.5e3}});
  return curve;
}
std::shared_ptr<const CompressiveCurve> Vn600SixPoints() {
  static const auto curve =
      Curve({{0.02, 14.3e3}, {0.05, 22.0e3}, {0.10, 30.2e3}, {0.25, 57.3e3}, {0.40, 118.0e3}, {0.49, 189.5e3}});
  return curve;
}

BodyLimits Hand(ContactType contact = ContactType::kTransient) {
  return BodyRegionTable::BuiltIn().Limits("hands-fingers", "palm-dominant", contact);
}

BodyContactScene Foam(double thickness_m, double radius_m = 0.015,
                      std::shared_ptr<const CompressiveCurve> curve = Vn600()) {
  BodyContactScene s;
  s.robot_mass_kg = 10.0;
  s.robot_radius_m = radius_m;
  s.covering = covopt::CoveringSpec{.youngs_modulus_Pa = 1e6, .poisson_ratio = 0.3, .thickness_m = thickness_m};
  s.covering.compressive_curve = std::move(curve);
  return s;
}

co::BodyRegionOptions Options(double safety_factor, bool keep_travel) {
  co::BodyRegionOptions o;
  o.rule.safety_factor = safety_factor;
  o.keep_travel = keep_travel;
  return o;
}

}  // namespace

TEST_CASE("foam body region: the round check numbers through MaxSafeSpeed (VN600, hand, 10 kg, transient)",
          "[body_region][foam]") {
  const co::BodyRegionOptions injury = Options(1.0, false);
  BodyContactScene bare = Foam(0.0);
  CHECK(co::MaxSafeSpeed(bare, Hand(), injury).max_safe_speed_m_per_s == Approx(1.35895).epsilon(1e-5));
  // 40 mm: force binds at 2.67 m/s; the covering is not used up below it.
  const co::BodyRegionSpeedLimit thick = co::MaxSafeSpeed(Foam(0.04, 0.015, Vn600SixPoints()), Hand(), injury);
  CHECK(thick.max_safe_speed_m_per_s == Approx(2.6727).epsilon(2e-4));
  CHECK(thick.limited_by == co::BodyLimitKind::kForce);
  CHECK(thick.message.find("used up") == std::string::npos);
  // 10 mm: used up at 0.62 m/s, reported as such; force-limited at 1.47 m/s (20 mm: 1.89 m/s).
  const co::BodyRegionSpeedLimit thin = co::MaxSafeSpeed(Foam(0.01, 0.015, Vn600SixPoints()), Hand(), injury);
  CHECK(thin.status == co::SpeedLimitStatus::kLimited);
  CHECK(thin.limited_by == co::BodyLimitKind::kForce);
  CHECK(thin.max_safe_speed_m_per_s == Approx(1.4670).epsilon(2e-4));
  REQUIRE(thin.covering_used_up_m_per_s);
  CHECK(*thin.covering_used_up_m_per_s == Approx(0.6154).epsilon(2e-4));
  CHECK(thin.message.find("covering used up at v = 0.6154") != std::string::npos);
  CHECK(thin.at_limit.admissible);
  CHECK(thin.at_limit.contact.fully_compressed);
  CHECK(co::MaxSafeSpeed(Foam(0.02, 0.015, Vn600SixPoints()), Hand(), injury).max_safe_speed_m_per_s ==
        Approx(1.8859).epsilon(2e-4));
  // keep_travel: the used-up speed is the limit, named full-compression (the design rule).
  const co::BodyRegionSpeedLimit kept =
      co::MaxSafeSpeed(Foam(0.01, 0.015, Vn600SixPoints()), Hand(), Options(1.0, true));
  CHECK(kept.limited_by == co::BodyLimitKind::kFullCompression);
  CHECK(kept.max_safe_speed_m_per_s == Approx(*thin.covering_used_up_m_per_s).epsilon(1e-12));
  // The eleven points give 2.694 / 0.6045 / 1.464 / 1.872 m/s.
  CHECK(co::MaxSafeSpeed(Foam(0.04), Hand(), injury).max_safe_speed_m_per_s == Approx(2.6935).epsilon(2e-4));
  CHECK(co::MaxSafeSpeed(Foam(0.01), Hand(), injury).max_safe_speed_m_per_s == Approx(1.4638).epsilon(2e-4));
  CHECK(co::MaxSafeSpeed(Foam(0.02), Hand(), injury).max_safe_speed_m_per_s == Approx(1.8720).epsilon(2e-4));
}

TEST_CASE("foam body region: the closed-form limit agrees with a bisection on the verdict", "[body_region][foam]") {
  struct Case {
    double thickness_m;
    double radius_m;
    double area_m2;
    const char* region;
    const char* area;
  };
  const Case cases[] = {{0.01, 0.015, 0.0, "hands-fingers", "palm-dominant"},
                        {0.03, 0.015, 1e-4, "chest", ""},
                        {0.005, 0.05, 2e-4, "abdomen", ""},
                        {0.02, covopt::kFlat, 4e-4, "hands-fingers", "palm-dominant"},
                        {0.01, covopt::kFlat, 1e-4, "lower-legs", ""}};
  for (const Case& c : cases) {
    for (ContactType contact : {ContactType::kTransient, ContactType::kClamped}) {
      for (double sf : {1.0, 2.0}) {
        for (bool keep : {false, true}) {
          BodyContactScene s = Foam(c.thickness_m, c.radius_m);
          s.contact_area_m2 = c.area_m2;
          const BodyLimits limits = BodyRegionTable::BuiltIn().Limits(c.region, c.area, contact);
          const co::BodyRegionOptions options = Options(sf, keep);
          const co::BodyRegionSpeedLimit limit = co::MaxSafeSpeed(s, limits, options);
          INFO(c.region << " thickness " << c.thickness_m << " radius " << c.radius_m << " "
                        << covopt::ToString(contact) << " SF " << sf << " keep_travel " << keep);
          REQUIRE(limit.status == co::SpeedLimitStatus::kLimited);
          // The verdict is safe at the limit and unsafe just above: bisect it independently.
          double lo = 1e-4, hi = 100.0;
          for (int i = 0; i < 200; ++i) {
            const double mid = std::sqrt(lo * hi);
            s.speed_m_per_s = mid;
            (co::JudgeBodyContact(s, limits, options).admissible ? lo : hi) = mid;
          }
          CHECK(limit.max_safe_speed_m_per_s == Approx(lo).epsilon(1e-9));
          CHECK(limit.at_limit.admissible);
        }
      }
    }
  }
}

TEST_CASE("foam body region: a used-up covering is judged by injury, or by keep_travel's design rule",
          "[body_region][foam]") {
  BodyContactScene s = Foam(0.01);
  s.speed_m_per_s = 1.0;  // past the 0.6 m/s at which 10 mm is used up, below the 1.46 m/s force limit
  const co::BodyRegionJudgement injury = co::JudgeBodyContact(s, Hand(), Options(1.0, false));
  CHECK(injury.contact.fully_compressed);
  CHECK(injury.admissible);
  const covopt::Criterion* travel = injury.verdict.Find("full-compression");
  REQUIRE(travel);
  CHECK_FALSE(travel->counted);
  CHECK_FALSE(travel->passed);
  CHECK(travel->part == covopt::CriterionPart::kDesignRule);
  CHECK(injury.scope.find("not fully compressed") == std::string::npos);
  const co::BodyRegionJudgement kept = co::JudgeBodyContact(s, Hand(), Options(1.0, true));
  CHECK_FALSE(kept.admissible);
  CHECK(kept.verdict.injury_safe());
  CHECK_FALSE(kept.verdict.design_rules_met());
}

TEST_CASE("foam body region: keep_travel reproduces a Hertz covering's full-compression limit, and without it the "
          "used-up speed is reported",
          "[body_region][foam]") {
  BodyContactScene s = Foam(0.01, 0.02);
  s.covering.compressive_curve.reset();  // Hertz
  s.covering.youngs_modulus_Pa = 0.2e6;  // soft: bottoms out below the force limit
  const BodyLimits chest = BodyRegionTable::BuiltIn().Limits("chest", "", ContactType::kTransient);
  for (double sf : {1.0, 1.5, 3.0}) {
    const co::BodyRegionSpeedLimit kept = co::MaxSafeSpeed(s, chest, Options(sf, true));
    CHECK(kept.limited_by == co::BodyLimitKind::kFullCompression);
    // Today's closed form: the speed at the force where δ_c = 0.8 b_c / SF.
    const covopt::BodyContactModel m = covopt::BodyContactModel::FromScene(co::WithRegion(s, chest));
    const double travel = 0.8 * 0.01 / sf;
    const double force = m.covering_stiffness() * travel * std::sqrt(travel);
    CHECK(kept.max_safe_speed_m_per_s == Approx(m.SpeedAtPeakForce(force)).epsilon(1e-14));
    // Without the travel rule a Hertz covering still may not bottom out: fully compressed it is
    // out of its law's validity ("law-validity", not derated), so its limit is the used-up speed.
    const co::BodyRegionSpeedLimit injury = co::MaxSafeSpeed(s, chest, Options(sf, false));
    CHECK(injury.limited_by == co::BodyLimitKind::kLawValidity);
    CHECK(injury.at_limit.verdict.governing_name() == "law-validity");
    CHECK(injury.max_safe_speed_m_per_s >= kept.max_safe_speed_m_per_s * (1.0 - 1e-12));
    if (sf > 1.0) CHECK(injury.max_safe_speed_m_per_s > kept.max_safe_speed_m_per_s);
    REQUIRE(injury.covering_used_up_m_per_s);
    CHECK(*injury.covering_used_up_m_per_s == Approx(m.SpeedAtPeakForce(m.bottom_out_force_N())).epsilon(1e-14));
    CHECK(injury.max_safe_speed_m_per_s == Approx(*injury.covering_used_up_m_per_s).epsilon(1e-12));
    // Not above the limit, so not reported as a used-up speed past it.
    CHECK(injury.message.find("covering used up at v =") == std::string::npos);
  }
  // The shells' options keep the travel rule only when asked (--keep-travel, keep_travel=True).
  CHECK_FALSE(co::BodyRegionOptionsOf(1.0, false, false, false, nullptr).keep_travel);
  CHECK(co::BodyRegionOptionsOf(1.0, false, false, false, nullptr, true).keep_travel);
  CHECK_FALSE(co::BodyRegionOptionsOf(1.0, true, false, false, nullptr, true).keep_travel);
}

TEST_CASE("foam body region: on a flat face the covered limit is never below the bare robot's", "[body_region][foam]") {
  for (const BodyLimits& limits : BodyRegionTable::BuiltIn().AllLimits(ContactType::kTransient)) {
    for (double thickness : {0.002, 0.01, 0.04}) {
      BodyContactScene s = Foam(thickness, covopt::kFlat);
      s.contact_area_m2 = 2e-4;
      const std::vector<co::BodyRegionSpeedLimitRow> rows =
          co::BodyRegionSpeedLimitTable(s, std::vector<BodyLimits>{limits}, Options(1.0, false));
      REQUIRE(rows.size() == 1);
      REQUIRE(rows[0].covered);
      INFO(limits.region->name << " " << limits.area->name << " thickness " << thickness);
      CHECK(rows[0].covered->max_safe_speed_m_per_s >= rows[0].bare.max_safe_speed_m_per_s);
    }
  }
}

TEST_CASE("foam body region: thicker foam never lowers the speed limit", "[body_region][foam]") {
  for (double radius : {0.01, 0.05, covopt::kFlat}) {
    for (bool keep : {false, true}) {
      double previous = 0.0;
      for (double thickness = 0.001; thickness <= 0.06; thickness *= 1.3) {
        BodyContactScene s = Foam(thickness, radius);
        s.contact_area_m2 = 3e-4;
        const double speed = co::MaxSafeSpeed(s, Hand(), Options(1.0, keep)).max_safe_speed_m_per_s;
        INFO("radius " << radius << " thickness " << thickness << " keep_travel " << keep);
        CHECK(speed >= previous);
        previous = speed;
      }
    }
  }
}

TEST_CASE("foam body region: a braking robot's limit is bracketed on the time path, at or above the unbraked one",
          "[body_region][foam][braking]") {
  for (bool keep : {false, true}) {
    BodyContactScene s = Foam(0.01);
    const double unbraked = co::MaxSafeSpeed(s, Hand(), Options(1.0, keep)).max_safe_speed_m_per_s;
    s.reaction_delay_s = 0.005;
    s.braking_m_per_s2 = 100.0;
    const co::BodyRegionSpeedLimit braked = co::MaxSafeSpeed(s, Hand(), Options(1.0, keep));
    INFO("keep_travel " << keep << ": " << braked.message);
    REQUIRE(braked.status == co::SpeedLimitStatus::kLimited);
    CHECK(braked.time_path_runs > 0);
    CHECK(braked.max_safe_speed_m_per_s >= unbraked * (1.0 - 1e-6));
    CHECK(braked.limited_by == (keep ? co::BodyLimitKind::kFullCompression : co::BodyLimitKind::kForce));
    // The verdict at the limit holds, and just above it does not.
    s.speed_m_per_s = braked.max_safe_speed_m_per_s;
    CHECK(co::JudgeBodyContact(s, Hand(), Options(1.0, keep)).admissible);
    s.speed_m_per_s = braked.max_safe_speed_m_per_s * 1.001;
    CHECK_FALSE(co::JudgeBodyContact(s, Hand(), Options(1.0, keep)).admissible);
  }
}

TEST_CASE("foam body region: past the stop without an area the crush check takes sigma_end, a lower bound",
          "[body_region][foam]") {
  BodyContactScene s = Foam(0.01);  // curved, no contact area: the pressure past the stop is not evaluated
  s.speed_m_per_s = 1.0;            // used up (0.6 m/s)
  co::BodyRegionOptions options = Options(1.0, false);
  options.material = co::CandidateMaterial{};
  options.material->name = "crushable foam";
  options.material->crush_behaviour = covopt::materials::CrushBehaviour::kCrushes;
  options.material->compressive_strength_Pa = 150e3;  // below σ_end = 189.5 kPa
  const co::BodyRegionJudgement j = co::JudgeBodyContact(s, Hand(), options);
  REQUIRE(j.contact.fully_compressed);
  CHECK_FALSE(j.contact.peak_pressure_Pa.has_value());
  CHECK(j.contact.covering_stress_Pa == 189.5e3);
  CHECK(j.crush_ratio == Approx(189.5 / 150.0));
  CHECK_FALSE(j.admissible);
  // The limit: where σ(d/h) reaches the strength, within the curve, below the used-up speed.
  const co::BodyRegionSpeedLimit limit = co::MaxSafeSpeed(s, Hand(), options);
  CHECK(limit.limited_by == co::BodyLimitKind::kCrush);
  CHECK(limit.max_safe_speed_m_per_s < *limit.covering_used_up_m_per_s);
  CHECK(limit.at_limit.crush_ratio == Approx(1.0).epsilon(1e-12));
}
