// Body regions of ISO/TS 15066 with the covering (optim/body_region_check.hpp): the verdict of
// one contact, the closed-form speed limit against an independent bisection on the verdict,
// Annex A exactly for the bare robot, the trends the model must show, the all-regions table,
// and the covering design for every region named (and the head).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/materials/body_regions.hpp>
#include <covopt/materials/catalog.hpp>
#include <covopt/optim/body_region_check.hpp>
#include <covopt/optim/design.hpp>

namespace {

using covopt::BodyContactScene;
using covopt::ContactType;
using covopt::materials::BodyLimits;
using covopt::materials::BodyRegionTable;
namespace co = covopt::optim;

const BodyRegionTable& Table() { return BodyRegionTable::BuiltIn(); }

BodyContactScene Robot(double mass_kg, double radius_m = 0.02) {
  BodyContactScene s;
  s.robot_mass_kg = mass_kg;
  s.robot_radius_m = radius_m;
  s.speed_m_per_s = 0.5;
  return s;
}

BodyContactScene Covered(BodyContactScene s, double modulus_Pa, double thickness_m, double poisson = 0.3) {
  s.covering = {modulus_Pa, poisson, thickness_m};
  return s;
}

/// The default criterion of these tests: the covering's travel counts (keep_travel, the rule
/// the shells apply today; without it the verdicts judge injury alone, test_body_region_foam.cpp).
co::BodyRegionOptions Options(double safety_factor, std::optional<co::CandidateMaterial> material = std::nullopt) {
  co::BodyRegionOptions o;
  o.rule.safety_factor = safety_factor;
  o.material = std::move(material);
  o.keep_travel = true;
  return o;
}

co::CandidateMaterial Material(covopt::materials::CrushBehaviour crush, double strength_Pa = 0.0) {
  co::CandidateMaterial m;
  m.name = "test foam";
  m.youngs_modulus_Pa = 3e6;
  m.poisson_ratio = 0.3;
  m.crush_behaviour = crush;
  m.compressive_strength_Pa = strength_Pa;
  return m;
}

bool AdmissibleAt(BodyContactScene scene, double speed, const BodyLimits& limits, const co::BodyRegionOptions& o) {
  scene.speed_m_per_s = speed;
  return co::JudgeBodyContact(scene, limits, o).admissible;
}

/// The ratio of the limit that binds, scaled by the safety factor.
double ScaledRatio(const co::BodyRegionJudgement& j, co::BodyLimitKind kind, double sf) {
  switch (kind) {
    case co::BodyLimitKind::kForce: return sf * j.force_ratio;
    case co::BodyLimitKind::kPressure: return sf * j.pressure_ratio.value();
    case co::BodyLimitKind::kFullCompression: return sf * j.compression_ratio;
    case co::BodyLimitKind::kCrush: return sf * j.crush_ratio;
    case co::BodyLimitKind::kLawValidity: return j.contact.validity.ratio;  // not derated
    case co::BodyLimitKind::kNone: break;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

double RelativeDifference(double a, double b) { return std::abs(a - b) / std::max(std::abs(a), std::abs(b)); }

TEST_CASE("the bare robot's speed limit is Annex A's F_lim / sqrt(mu k_H) for every region and mass", "[body_region]") {
  for (const ContactType contact : {ContactType::kTransient, ContactType::kClamped}) {
    for (const BodyLimits& limits : Table().AllLimits(contact)) {
      for (const double mass : {0.5, 10.0, 60.0, covopt::kFixed}) {
        if (contact == ContactType::kClamped && std::isinf(mass)) continue;
        const double m_h = limits.region->effective_mass_kg;
        const double mu = contact == ContactType::kClamped ? mass : 1.0 / (1.0 / mass + 1.0 / m_h);
        const double expected = limits.force_N / std::sqrt(mu * limits.region->stiffness_N_per_m);
        const co::BodyRegionSpeedLimit limit = co::MaxSafeSpeed(Robot(mass), limits, Options(1.0));
        INFO(limit.message);
        REQUIRE(limit.status == co::SpeedLimitStatus::kLimited);
        CHECK(limit.limited_by == co::BodyLimitKind::kForce);
        CHECK(RelativeDifference(limit.max_safe_speed_m_per_s, expected) < 1e-13);
        CHECK(limit.at_limit.force_ratio == Approx(1.0).epsilon(1e-12));
        CHECK(limit.at_limit.admissible);
        CHECK_FALSE(limit.at_limit.pressure_ratio.has_value());  // no area given
      }
    }
  }
  // docs/model.md §13's check number (C0): 10 kg on the chest, transient: 280 N / sqrt(8 kg · 25 kN/m).
  const co::BodyRegionSpeedLimit chest =
      co::MaxSafeSpeed(Robot(10.0), Table().Limits("chest", "", ContactType::kTransient), Options(1.0));
  CHECK(chest.max_safe_speed_m_per_s == Approx(0.626099).epsilon(1e-6));
  CHECK(chest.message.find("0.626099 m/s, limited by force") != std::string::npos);
  CHECK(chest.at_limit.scope.find("pressure not evaluated: no contact area given") != std::string::npos);
  CHECK(chest.at_limit.scope.find("280 N") != std::string::npos);
}

TEST_CASE("the bare robot's verdict is Annex A's force and F/A pressure", "[body_region]") {
  const BodyLimits chest = Table().Limits("chest", "", ContactType::kTransient);
  BodyContactScene s = Robot(10.0);
  s.speed_m_per_s = 0.3;
  s.contact_area_m2 = 1e-4;  // 1 cm²
  const co::BodyRegionJudgement j = co::JudgeBodyContact(s, chest, Options(2.0));
  const double force = 0.3 * std::sqrt(8.0 * 25e3);
  CHECK(j.force_ratio == Approx(force / 280.0).epsilon(1e-14));
  CHECK(j.pressure_ratio.value() == Approx(force / 1e-4 / chest.pressure_Pa).epsilon(1e-14));
  CHECK(j.compression_ratio == 0.0);
  CHECK(j.crush_check == co::CrushCheck::kNoMaterial);
  CHECK(j.margin == Approx(1.0 - 2.0 * j.governing_ratio).epsilon(1e-15));
  CHECK(j.admissible == (2.0 * j.governing_ratio <= 1.0));
  CHECK(j.scope.find("safety factor 2") != std::string::npos);
  CHECK(j.scope.find("pressure not evaluated") == std::string::npos);
}

/// Generated coverings, robots and rules: each speed limit against a bisection on the verdict.
struct Case {
  const char* what;
  double modulus_Pa;
  double thickness_m;  // 0: bare
  double radius_m;
  double area_m2;
  std::optional<co::CandidateMaterial> material;
};

TEST_CASE("the closed-form speed limit agrees with a bisection on JudgeBodyContact's verdict", "[body_region]") {
  using covopt::materials::CrushBehaviour;
  const std::vector<Case> cases = {
      {"bare", 0.0, 0.0, 0.02, 0.0, std::nullopt},
      {"bare with area", 0.0, 0.0, 0.02, 0.5e-4, std::nullopt},
      {"soft", 0.3e6, 0.012, 0.03, 0.0, std::nullopt},
      {"medium", 3e6, 0.008, 0.05, 0.0, std::nullopt},
      {"stiff", 60e6, 0.004, 0.05, 0.0, std::nullopt},
      {"small radius", 10e6, 0.003, 0.002, 0.0, std::nullopt},
      {"crushable", 3e6, 0.01, 0.05, 0.0, Material(CrushBehaviour::kCrushes, 0.6e6)},
      {"elastomer", 3e6, 0.01, 0.05, 0.0, Material(CrushBehaviour::kDoesNotCrush)},
  };
  const std::vector<std::pair<const char*, const char*>> regions = {
      {"chest", ""}, {"hands-fingers", "palm-dominant"}, {"neck", ""}, {"lower-legs", ""}, {"abdomen", ""}};
  std::set<co::BodyLimitKind> seen;
  for (const Case& c : cases) {
    for (const double mass : {2.0, 25.0}) {
      for (const double sf : {1.0, 2.0}) {
        for (const ContactType contact : {ContactType::kTransient, ContactType::kClamped}) {
          for (const auto& [region, area] : regions) {
            const BodyLimits limits = Table().Limits(region, area, contact);
            BodyContactScene s = Robot(mass, c.radius_m);
            s.contact_area_m2 = c.area_m2;
            if (c.thickness_m > 0.0) s = Covered(s, c.modulus_Pa, c.thickness_m);
            const co::BodyRegionOptions o = Options(sf, c.material);
            const co::BodyRegionSpeedLimit limit = co::MaxSafeSpeed(s, limits, o);
            INFO(c.what << ", " << mass << " kg, SF " << sf << ": " << limit.message);
            const double v = limit.max_safe_speed_m_per_s;
            if (AdmissibleAt(s, 100.0, limits, o)) {
              CHECK(limit.status == co::SpeedLimitStatus::kSafeUpToSearchLimit);
              CHECK(v == 100.0);
              continue;
            }
            REQUIRE(limit.status == co::SpeedLimitStatus::kLimited);
            seen.insert(limit.limited_by);
            // The bisection: lo admissible, hi not.
            double lo = 1e-6, hi = 100.0;
            REQUIRE(AdmissibleAt(s, lo, limits, o));
            while (hi - lo > 1e-14 * hi) {
              const double mid = 0.5 * (lo + hi);
              (AdmissibleAt(s, mid, limits, o) ? lo : hi) = mid;
            }
            CHECK(RelativeDifference(v, lo) < 1e-11);
            CHECK(limit.at_limit.admissible);
            CHECK_FALSE(AdmissibleAt(s, v * (1 + 1e-9), limits, o));
            for (const double f : {0.1, 0.5, 0.9, 0.999}) CHECK(AdmissibleAt(s, f * v, limits, o));
            // The binding ratio is 1/SF there, and no counted ratio is above it.
            CHECK(std::abs(ScaledRatio(limit.at_limit, limit.limited_by, sf) - 1.0) < 1e-12);
            CHECK(sf * limit.at_limit.governing_ratio <= 1.0);
          }
        }
      }
    }
  }
  // The cases exercise every kind of limit.
  CHECK(seen.count(co::BodyLimitKind::kForce) == 1);
  CHECK(seen.count(co::BodyLimitKind::kPressure) == 1);
  CHECK(seen.count(co::BodyLimitKind::kFullCompression) == 1);
  CHECK(seen.count(co::BodyLimitKind::kCrush) == 1);
}

TEST_CASE("a softer covering raises the speed limit while force binds, pressure binds stiff ones, compression soft ones",
          "[body_region]") {
  const BodyLimits chest = Table().Limits("chest", "", ContactType::kTransient);
  const BodyContactScene robot = Robot(10.0, 0.1);
  const double bare = co::MaxSafeSpeed(robot, chest, Options(1.0)).max_safe_speed_m_per_s;
  std::vector<co::BodyLimitKind> kinds;
  double previous_force_bound = 0.0;
  bool force_bound_above_bare = false;
  // E from 1 GPa down to 30 kPa, 10 mm thick.
  for (int i = 0; i <= 60; ++i) {
    const double modulus = 1e9 * std::pow(10.0, -4.5 * i / 60.0);
    const co::BodyRegionSpeedLimit limit = co::MaxSafeSpeed(Covered(robot, modulus, 0.01), chest, Options(1.0));
    INFO(modulus << " Pa: " << limit.message);
    REQUIRE(limit.status == co::SpeedLimitStatus::kLimited);
    if (kinds.empty() || kinds.back() != limit.limited_by) kinds.push_back(limit.limited_by);
    if (limit.limited_by == co::BodyLimitKind::kForce) {
      CHECK(limit.max_safe_speed_m_per_s > previous_force_bound);  // the covering stores more energy
      previous_force_bound = limit.max_safe_speed_m_per_s;
      force_bound_above_bare = force_bound_above_bare || limit.max_safe_speed_m_per_s > bare;
    }
  }
  // Stiff: the Hertz pressure binds; then force; soft: the covering bottoms out.
  CHECK(kinds == std::vector<co::BodyLimitKind>{co::BodyLimitKind::kPressure, co::BodyLimitKind::kForce,
                                                co::BodyLimitKind::kFullCompression});
  CHECK(force_bound_above_bare);
}

TEST_CASE("clamped contact is always stricter than transient, bare and covered", "[body_region]") {
  for (const BodyLimits& transient : Table().AllLimits(ContactType::kTransient)) {
    const BodyLimits clamped = Table().Limits(transient.region->name, transient.area->name, ContactType::kClamped);
    for (const double modulus : {0.0, 0.5e6, 5e6}) {
      BodyContactScene s = Robot(15.0, 0.04);
      if (modulus > 0.0) s = Covered(s, modulus, 0.01);
      const double v_transient = co::MaxSafeSpeed(s, transient, Options(1.0)).max_safe_speed_m_per_s;
      const double v_clamped = co::MaxSafeSpeed(s, clamped, Options(1.0)).max_safe_speed_m_per_s;
      INFO(transient.Describe() << ", E " << modulus);
      CHECK(v_clamped < v_transient);
    }
  }
}

TEST_CASE("a stiff covering on a small radius lets pressure bind below the bare force limit", "[body_region]") {
  const BodyLimits hand = Table().Limits("hands-fingers", "palm-dominant", ContactType::kTransient);
  const BodyContactScene robot = Robot(10.0, 0.002);
  const co::BodyRegionSpeedLimit bare = co::MaxSafeSpeed(robot, hand, Options(1.0));
  const co::BodyRegionSpeedLimit stiff = co::MaxSafeSpeed(Covered(robot, 100e6, 0.001), hand, Options(1.0));
  CHECK(bare.limited_by == co::BodyLimitKind::kForce);
  CHECK(stiff.limited_by == co::BodyLimitKind::kPressure);
  CHECK(stiff.max_safe_speed_m_per_s < bare.max_safe_speed_m_per_s);
  CHECK(stiff.at_limit.force_ratio < 1.0);
  CHECK(stiff.at_limit.pressure_ratio.value() == Approx(1.0).epsilon(1e-12));
}

TEST_CASE("crush binds for a weak crushable covering unless crushing is allowed", "[body_region]") {
  using covopt::materials::CrushBehaviour;
  const BodyLimits chest = Table().Limits("chest", "", ContactType::kTransient);
  const BodyContactScene s = Covered(Robot(10.0, 0.05), 3e6, 0.01);
  const co::BodyRegionSpeedLimit weak = co::MaxSafeSpeed(s, chest, Options(1.0, Material(CrushBehaviour::kCrushes, 0.2e6)));
  const co::BodyRegionSpeedLimit unchecked = co::MaxSafeSpeed(s, chest, Options(1.0));
  CHECK(weak.limited_by == co::BodyLimitKind::kCrush);
  CHECK(weak.at_limit.crush_check == co::CrushCheck::kChecked);
  CHECK(weak.at_limit.crush_ratio == Approx(1.0).epsilon(1e-12));
  CHECK(weak.max_safe_speed_m_per_s < unchecked.max_safe_speed_m_per_s);
  CHECK(unchecked.at_limit.crush_check == co::CrushCheck::kNoMaterial);
  // The crush ratio is p_max / strength, the covering's peak pressure as its stress.
  CHECK(weak.at_limit.crush_ratio ==
        Approx(*weak.at_limit.contact.peak_pressure_Pa / 0.2e6).epsilon(1e-15));
  // A sacrificial liner: crush reported, not counted.
  co::BodyRegionOptions liner = Options(1.0, Material(CrushBehaviour::kCrushes, 0.2e6));
  liner.rule.crushing_allowed = true;
  const co::BodyRegionSpeedLimit allowed = co::MaxSafeSpeed(s, chest, liner);
  CHECK(allowed.limited_by != co::BodyLimitKind::kCrush);
  CHECK(allowed.max_safe_speed_m_per_s == Approx(unchecked.max_safe_speed_m_per_s).epsilon(1e-14));
  CHECK(allowed.at_limit.crush_ratio > 1.0);
  CHECK(allowed.at_limit.scope.find("crushing allowed") != std::string::npos);
  // An elastomer does not crush: full compression is its limit.
  const co::BodyRegionSpeedLimit elastomer =
      co::MaxSafeSpeed(s, chest, Options(1.0, Material(CrushBehaviour::kDoesNotCrush)));
  CHECK(elastomer.at_limit.crush_check == co::CrushCheck::kDoesNotCrush);
  CHECK(elastomer.max_safe_speed_m_per_s == Approx(unchecked.max_safe_speed_m_per_s).epsilon(1e-14));
}

TEST_CASE("a covering of unknown strength is refused unless the rule allows it", "[body_region]") {
  using covopt::materials::CrushBehaviour;
  const BodyLimits chest = Table().Limits("chest", "", ContactType::kTransient);
  BodyContactScene s = Covered(Robot(10.0, 0.05), 3e6, 0.01);
  s.speed_m_per_s = 1e-3;
  const co::BodyRegionOptions refused = Options(1.0, Material(CrushBehaviour::kUnknown));
  const co::BodyRegionJudgement j = co::JudgeBodyContact(s, chest, refused);
  CHECK(j.crush_check == co::CrushCheck::kUnknownStrength);
  CHECK_FALSE(j.admissible);
  CHECK(j.margin > 0.0);  // the ratios hold: the strength is what is refused
  CHECK(j.scope.find("strength is unknown: refused") != std::string::npos);
  const co::BodyRegionSpeedLimit none = co::MaxSafeSpeed(s, chest, refused);
  CHECK(none.status == co::SpeedLimitStatus::kNoSafeValue);
  CHECK(none.max_safe_speed_m_per_s == 0.0);
  CHECK(none.message.find("unknown") != std::string::npos);

  co::BodyRegionOptions allowed = refused;
  allowed.rule.unknown_strength_allowed = true;
  CHECK(co::JudgeBodyContact(s, chest, allowed).admissible);
  const co::BodyRegionSpeedLimit limit = co::MaxSafeSpeed(s, chest, allowed);
  CHECK(limit.status == co::SpeedLimitStatus::kLimited);
  CHECK(limit.max_safe_speed_m_per_s == Approx(co::MaxSafeSpeed(s, chest, Options(1.0)).max_safe_speed_m_per_s).epsilon(1e-14));
  // The bare robot has no covering to crush: the material does not matter.
  BodyContactScene bare = s;
  bare.covering.thickness_m = 0.0;
  CHECK(co::JudgeBodyContact(bare, chest, refused).admissible);
}

TEST_CASE("a fully compressed covering is never admissible under the default criterion", "[body_region]") {
  const BodyLimits chest = Table().Limits("chest", "", ContactType::kTransient);
  BodyContactScene s = Covered(Robot(10.0, 0.1), 30e3, 0.01);  // very soft: bottoms out early
  s.speed_m_per_s = 0.2;
  const co::BodyRegionJudgement j = co::JudgeBodyContact(s, chest, Options(1.0));
  REQUIRE(j.contact.fully_compressed);
  CHECK_FALSE(j.admissible);
  co::BodyRegionOptions paper;
  paper.rule.criterion = co::DesignCriterion::kPaper;
  const co::BodyRegionJudgement p = co::JudgeBodyContact(s, chest, paper);
  CHECK(p.governing != co::BodyLimitKind::kFullCompression);
  CHECK(p.admissible == (p.governing_ratio <= 1.0));
  CHECK(p.scope.find("not fully compressed") == std::string::npos);
}

TEST_CASE("the all-regions table holds MaxSafeSpeed per area, bare and covered", "[body_region]") {
  const std::vector<BodyLimits> all = Table().AllLimits(ContactType::kTransient);
  const BodyContactScene s = Covered(Robot(10.0, 0.05), 2e6, 0.01);
  const std::vector<co::BodyRegionSpeedLimitRow> rows = co::BodyRegionSpeedLimitTable(s, all, Options(2.0));
  REQUIRE(rows.size() == all.size());
  BodyContactScene bare = s;
  bare.covering.thickness_m = 0.0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    INFO(rows[i].limits.Describe());
    CHECK(rows[i].limits.area == all[i].area);
    CHECK(rows[i].bare.max_safe_speed_m_per_s == co::MaxSafeSpeed(bare, all[i], Options(2.0)).max_safe_speed_m_per_s);
    REQUIRE(rows[i].covered.has_value());
    CHECK(rows[i].covered->max_safe_speed_m_per_s == co::MaxSafeSpeed(s, all[i], Options(2.0)).max_safe_speed_m_per_s);
    CHECK(rows[i].gain().value() == rows[i].covered->max_safe_speed_m_per_s / rows[i].bare.max_safe_speed_m_per_s);
  }
  // No covering: no covered column.
  const std::vector<co::BodyRegionSpeedLimitRow> bare_rows = co::BodyRegionSpeedLimitTable(bare, all, Options(1.0));
  CHECK_FALSE(bare_rows.front().covered.has_value());
  CHECK_FALSE(bare_rows.front().gain().has_value());
}

TEST_CASE("body-region verdicts refuse bad input, naming the field", "[body_region]") {
  const BodyLimits chest = Table().Limits("chest", "", ContactType::kTransient);
  CHECK_THROWS_WITH(co::JudgeBodyContact(Robot(10.0), chest, Options(0.5)), Catch::Contains("safety factor"));
  CHECK_THROWS_WITH(co::MaxSafeSpeed(Robot(10.0), BodyLimits{}), Catch::Contains("limits"));
  CHECK_THROWS_WITH(co::JudgeBodyContact(Covered(Robot(10.0, covopt::kFlat), 1e6, 0.01), chest),
                    Catch::Contains("robot.radius"));
  CHECK_THROWS_WITH(co::MaxSafeSpeed(Robot(10.0), chest,
                                     Options(1.0, Material(covopt::materials::CrushBehaviour::kCrushes, 0.0))),
                    Catch::Contains("compressive strength"));
  co::BodyRegionDesignRequest request;
  request.scene = Robot(10.0);
  CHECK_THROWS_WITH(co::DesignForBodyRegions(request), Catch::Contains("regions"));
  request.regions = {chest};
  request.scene.robot_radius_m = covopt::kFlat;
  CHECK_THROWS_WITH(co::DesignForBodyRegions(request), Catch::Contains("robot.radius"));
  request.scene.robot_radius_m = 0.02;
  request.min_thickness_m = 0.06;
  CHECK_THROWS_WITH(co::DesignForBodyRegions(request), Catch::Contains("min_thickness_m"));
}

/// Whether every region and the head (when judged) is safe with `material` at `thickness_m`,
/// under the request's covering law (a material with a measured curve: the foam law under auto).
bool EveryVerdictAdmissible(const co::BodyRegionDesignRequest& r, const co::CandidateMaterial& material,
                            double thickness_m, std::string* failing = nullptr) {
  BodyContactScene s = r.scene;
  s.covering = co::CoveringOf(material, thickness_m, r.covering_law);
  bool ok = true;
  for (const BodyLimits& limits : r.regions) {
    const co::BodyRegionJudgement j = co::JudgeBodyContact(s, limits, co::BodyRegionOptions{r.rule, material, r.rule.compression_counts()});
    if (!j.admissible && failing) *failing += limits.Describe() + "; ";
    ok = ok && j.admissible;
  }
  if (r.head) {
    covopt::Scene head = *r.head;
    head.robot.mass_kg = r.scene.robot_mass_kg;
    head.robot.radius_m = r.scene.robot_radius_m;
    head.robot.speed_m_per_s = r.scene.speed_m_per_s;
    const co::ExactPathOracle oracle(head, material.poisson_ratio);
    co::DesignScore score = oracle.ScoreCovering(co::CoveringOf(material, thickness_m, r.covering_law));
    co::CheckCrush(material, score);
    if (!score.admissible(r.rule) && failing) *failing += "head; ";
    ok = ok && score.admissible(r.rule);
  }
  return ok;
}

co::BodyRegionDesignRequest DesignRequest(bool head) {
  co::BodyRegionDesignRequest r;
  r.scene = Robot(10.0, 0.04);
  r.scene.speed_m_per_s = 0.8;
  r.regions = {Table().Limits("chest", "", ContactType::kTransient),
               Table().Limits("hands-fingers", "palm-dominant", ContactType::kTransient),
               Table().Limits("abdomen", "", ContactType::kTransient)};
  if (head) r.head = covopt::Scene{};
  r.materials = co::SelectCandidates(covopt::materials::Catalog::BuiltIn());
  return r;
}

TEST_CASE("the body-region design's recommendation is safe for every region, and 0.5 mm thinner is not",
          "[body_region][design]") {
  for (const bool head : {false, true}) {
    const co::BodyRegionDesignRequest r = DesignRequest(head);
    const co::BodyRegionDesignResult result = co::DesignForBodyRegions(r);
    INFO(result.message);
    CHECK_FALSE(result.bare_robot_safe);  // the chest's bare limit is 0.63 m/s
    REQUIRE(result.bare_robot.size() == r.regions.size());
    CHECK(result.bare_head.has_value() == head);
    REQUIRE(result.recommendation.has_value());
    CHECK(result.message.rfind("Recommended: ", 0) == 0);
    std::size_t admissible = 0;
    for (const co::BodyRegionDesignCandidate& c : result.candidates) {
      if (!c.admissible()) continue;
      ++admissible;
      INFO(c.material.name << " at " << *c.thickness_m);
      REQUIRE(c.regions.size() == r.regions.size());
      CHECK(c.head.has_value() == head);
      CHECK(EveryVerdictAdmissible(r, c.material, *c.thickness_m));
      // On the 0.5 mm stock grid: one step thinner fails somewhere.
      CHECK(std::abs(*c.thickness_m / 0.5e-3 - std::round(*c.thickness_m / 0.5e-3)) < 1e-9);
      if (*c.thickness_m - 0.5e-3 >= r.min_thickness_m) {
        CHECK_FALSE(EveryVerdictAdmissible(r, c.material, *c.thickness_m - 0.5e-3));
      }
    }
    REQUIRE(admissible > 0);
    // Ranked: admissible first, by thickness.
    for (std::size_t i = 1; i < admissible; ++i) {
      CHECK(*result.candidates[i - 1].thickness_m <= *result.candidates[i].thickness_m);
    }
    for (std::size_t i = admissible; i < result.candidates.size(); ++i) {
      CHECK_FALSE(result.candidates[i].admissible());
    }
    // The scope names the standard for each region, and Park et al. for the head.
    std::size_t iso = 0, park = 0;
    for (const std::string& line : result.scope) {
      iso += line.find("ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M, ") != std::string::npos;  // not the covering's
      park += line.find("Park et al.") != std::string::npos;
    }
    CHECK(iso == r.regions.size());
    CHECK((park > 0) == head);
  }
}

TEST_CASE("judging the head too makes the body-region design at least as thick", "[body_region][design]") {
  const co::BodyRegionDesignResult without = co::DesignForBodyRegions(DesignRequest(false));
  const co::BodyRegionDesignResult with = co::DesignForBodyRegions(DesignRequest(true));
  REQUIRE(without.recommendation.has_value());
  REQUIRE(with.recommendation.has_value());
  CHECK(*with.candidates[*with.recommendation].thickness_m >= *without.candidates[*without.recommendation].thickness_m);
  // Material by material too.
  for (const co::BodyRegionDesignCandidate& c : with.candidates) {
    if (!c.admissible()) continue;
    const auto other = std::find_if(without.candidates.begin(), without.candidates.end(),
                                    [&](const co::BodyRegionDesignCandidate& o) { return o.material.name == c.material.name; });
    REQUIRE(other != without.candidates.end());
    REQUIRE(other->admissible());
    CHECK(*c.thickness_m >= *other->thickness_m);
  }
  // The head alone is a design too (no region named).
  co::BodyRegionDesignRequest head_only = DesignRequest(true);
  head_only.regions.clear();
  const co::BodyRegionDesignResult head = co::DesignForBodyRegions(head_only);
  CHECK(head.bare_robot.empty());
  CHECK(head.bare_head.has_value());
}

}  // namespace

TEST_CASE("the bare robot is called safe only with its pressure checked", "[body_region][design]") {
  co::BodyRegionDesignRequest r = DesignRequest(false);
  r.scene.speed_m_per_s = 0.1;  // far below every region's bare force limit
  r.scene.robot_radius_m = 0.04;
  const co::BodyRegionDesignResult no_area = co::DesignForBodyRegions(r);
  for (const co::BodyRegionJudgement& j : no_area.bare_robot) CHECK(j.admissible);  // on the force alone
  CHECK_FALSE(no_area.bare_robot_safe);
  CHECK(no_area.message.find("no covering is needed") == std::string::npos);
  r.scene.contact_area_m2 = 10e-4;
  const co::BodyRegionDesignResult with_area = co::DesignForBodyRegions(r);
  CHECK(with_area.bare_robot_safe);
  CHECK(with_area.message.find("no covering is needed") != std::string::npos);
}
