// The physical floors (covopt/core/physical_floors.hpp, docs/guide/inputs-and-errors.md
// "Physical floors"): every length, area, mass, time and modulus below its floor is refused
// with the field, the value and the range; at and just above the floor the model answers
// with finite numbers. And the property behind them: for inputs drawn over each field's whole
// allowed range (log-uniform, plus the exact ends and values just above and below the floors),
// every number the library answers is finite, or the input is refused with
// std::invalid_argument. A denormal robot radius once gave NaN peaks and "safe up to 100 m/s".
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/core/body_contact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/core/physical_floors.hpp>
#include <covopt/core/solve.hpp>
#include <covopt/materials/body_regions.hpp>
#include <covopt/optim/body_region_check.hpp>
#include <covopt/optim/speed_limit.hpp>

namespace {

using covopt::BodyContactScene;
using covopt::ContactType;
using covopt::ImpactModel;
using covopt::ImpactPeaks;
using covopt::Scene;
namespace co = covopt::optim;

constexpr double kDenormal = 5e-324;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// The message FromScene throws for `scene`, or "" if it takes it.
std::string Refusal(const Scene& scene) {
  try {
    (void)ImpactModel::FromScene(scene);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return {};
}

std::string Refusal(const BodyContactScene& scene) {
  try {
    (void)covopt::BodyContactModel::FromScene(scene);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return {};
}

/// A scene with every extended input that `field` needs to be read.
Scene WithNeck() {
  Scene s;
  s.head.torso_mass_kg = 40.0;
  s.head.neck_stiffness_N_per_m = 1e4;
  return s;
}

Scene WithBraking() {
  Scene s;
  s.robot.reaction_delay_s = 0.01;
  s.robot.braking_m_per_s2 = 10.0;
  return s;
}

struct Floor {
  const char* field;
  double floor;
  Scene base;
  std::function<void(Scene&, double)> set;
  const char* range;  // the allowed range as the message states it
};

std::vector<Floor> SceneFloors() {
  using namespace covopt;
  return {
      {"robot.radius", kMinRadius_m, Scene{}, [](Scene& s, double v) { s.robot.radius_m = v; },
       "must be in [0.0001, 100] m, or flat (infinite)"},
      {"covering.thickness", kMinLayerThickness_m, Scene{}, [](Scene& s, double v) { s.covering.thickness_m = v; },
       "must be 0 (no covering) or in [0.0001, 1] m"},
      {"scalp.thickness", kMinLayerThickness_m, Scene{}, [](Scene& s, double v) { s.scalp.thickness_m = v; },
       "must be in [0.0001, 1] m"},
      {"head.radius", kMinRadius_m, Scene{},
       [](Scene& s, double v) {
         s.head.radius_m = v;
         s.scalp.thickness_m = 0.0;  // refused first unless thinner than the head: set below
       },
       "must be in [0.0001, 10] m"},
      {"robot.mass", kMinMass_kg, Scene{}, [](Scene& s, double v) { s.robot.mass_kg = v; },
       "must be in [0.001, 1e+06] kg, or fixed (infinite)"},
      {"head.mass", kMinMass_kg, Scene{}, [](Scene& s, double v) { s.head.mass_kg = v; },
       "must be in [0.001, 1e+06] kg, or fixed (infinite)"},
      {"head.torso_mass", kMinMass_kg, WithNeck(), [](Scene& s, double v) { s.head.torso_mass_kg = v; },
       "must be in [0.001, 1e+06] kg, or fixed (infinite), or 0 for no neck"},
      {"robot.reaction_delay", kMinTime_s, WithBraking(), [](Scene& s, double v) { s.robot.reaction_delay_s = v; },
       "must be 0 (brake at contact) or in [1e-06, 10] s"},
      {"robot.modulus", kMinModulus_Pa, Scene{}, [](Scene& s, double v) { s.robot.youngs_modulus_Pa = v; },
       "must be in [1000, 1e+13] Pa"},
      {"covering.modulus", kMinModulus_Pa, Scene{}, [](Scene& s, double v) { s.covering.youngs_modulus_Pa = v; },
       "must be in [1000, 1e+13] Pa"},
      {"scalp.modulus", kMinModulus_Pa, Scene{}, [](Scene& s, double v) { s.scalp.youngs_modulus_Pa = v; },
       "must be in [1000, 1e+13] Pa"},
      {"skull.modulus", kMinModulus_Pa, Scene{}, [](Scene& s, double v) { s.skull.youngs_modulus_Pa = v; },
       "must be in [1000, 1e+13] Pa"},
  };
}

bool Finite(const ImpactPeaks& p) {
  return std::isfinite(p.max_penetration_m) && std::isfinite(p.peak_force_N) &&
         std::isfinite(p.max_compressive_stress_Pa) && std::isfinite(p.max_tensile_stress_Pa) &&
         std::isfinite(p.max_energy_density_J_per_m2) && std::isfinite(p.full_compression_penetration_m) &&
         std::isfinite(p.covering_travel_start_m) && std::isfinite(p.covering_compression_ratio());
}

bool Finite(const co::LimitRatios& r) {
  return std::isfinite(r.laceration_ratio) && std::isfinite(r.contusion_ratio) && std::isfinite(r.compression_ratio) &&
         std::isfinite(r.crush_ratio) && std::isfinite(r.max_penetration_m);
}

bool Finite(const co::BodyRegionJudgement& j) {
  const covopt::BodyContactResult& c = j.contact;
  return std::isfinite(j.force_ratio) && (!j.pressure_ratio || std::isfinite(*j.pressure_ratio)) &&
         std::isfinite(j.compression_ratio) && std::isfinite(j.crush_ratio) && std::isfinite(j.governing_ratio) &&
         std::isfinite(j.margin) && std::isfinite(c.peak_force_N) &&
         (!c.peak_pressure_Pa || std::isfinite(*c.peak_pressure_Pa)) && std::isfinite(c.max_approach_m) &&
         std::isfinite(c.covering_deflection_m) && std::isfinite(c.compression_ratio) &&
         (!c.contact_duration_s || std::isfinite(*c.contact_duration_s));
}

/// Draws a value of one field: log-uniform over [min, max], and now and then exactly min or
/// max, just above min, just below min (to be refused), a denormal, 0 or +inf where allowed.
class Draw {
 public:
  explicit Draw(std::uint64_t seed) : rng_(seed) {}

  double operator()(double min, double max, bool zero_ok = false, bool inf_ok = false) {
    const double u = Uniform(0.0, 1.0);
    if (u < 0.05) return min;
    if (u < 0.08) return max;
    if (u < 0.12) return min * (1.0 + 1e-9);
    if (u < 0.13) return std::nextafter(min, 0.0);
    if (u < 0.14) return kDenormal;
    if (zero_ok && u < 0.30) return 0.0;
    if (inf_ok && u < 0.36) return kInf;
    return std::exp(Uniform(std::log(min), std::log(max)));
  }
  double Poisson() {
    const double u = Uniform(0.0, 1.0);
    if (u < 0.05) return 0.5;
    if (u < 0.08) return std::nextafter(-1.0, 0.0);
    return Uniform(-0.99, 0.5);
  }
  double Uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
  bool Chance(double p) { return Uniform(0.0, 1.0) < p; }
  std::size_t Index(std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_); }

 private:
  std::mt19937_64 rng_;
};

Scene RandomScene(Draw& draw, bool extended) {
  Scene s;
  s.robot.mass_kg = draw(1e-3, 1e6, false, true);
  s.robot.speed_m_per_s = draw(1e-6, 100.0);
  s.robot.radius_m = draw(1e-4, 100.0, false, true);
  s.robot.youngs_modulus_Pa = draw(1e3, 1e13);
  s.robot.poisson_ratio = draw.Poisson();
  s.covering.thickness_m = draw(1e-4, 1.0, true);
  s.covering.youngs_modulus_Pa = draw(1e3, 1e13);
  s.covering.poisson_ratio = draw.Poisson();
  s.head.mass_kg = draw(1e-3, 1e6, false, true);
  s.head.radius_m = draw(2e-4, 10.0);
  s.scalp.thickness_m = draw(1e-4, s.head.radius_m);  // refused when the skull is left thinner than its floor
  s.scalp.youngs_modulus_Pa = draw(1e3, 1e13);
  s.scalp.poisson_ratio = draw.Poisson();
  s.skull.youngs_modulus_Pa = draw(1e3, 1e13);
  s.skull.poisson_ratio = draw.Poisson();
  if (extended) {
    if (draw.Chance(0.5)) {
      s.robot.reaction_delay_s = draw(1e-6, 10.0, true);
      s.robot.braking_m_per_s2 = draw(1e-3, 1e4, true);
    }
    if (draw.Chance(0.5)) {
      s.head.torso_mass_kg = draw(1e-3, 1e6, true, true);
      s.head.neck_stiffness_N_per_m = draw(1e-3, 1e9, true);
      s.head.neck_damping_N_s_per_m = draw(1e-3, 1e7, true);
    }
    if (draw.Chance(0.3)) s.model.damping_s_per_m = draw(1e-6, 1e3, true);
  }
  return s;
}

}  // namespace

TEST_CASE("every length, mass, time and modulus below its floor is refused, naming it", "[floors]") {
  for (const Floor& f : SceneFloors()) {
    for (const double below : {kDenormal, 2.3e-308, 1e-300, std::nextafter(f.floor, 0.0)}) {
      Scene s = f.base;
      f.set(s, below);
      if (std::string(f.field) == "head.radius") s.scalp.thickness_m = below / 2;
      const std::string message = Refusal(s);
      INFO(f.field << " = " << below << ": '" << message << "'");
      CHECK_THAT(message, Catch::StartsWith(std::string(f.field) + " " + f.range + " (got "));
    }
  }
  SECTION("the message, as the issue quotes it") {
    Scene s;
    s.robot.radius_m = kDenormal;
    s.covering.thickness_m = 0.0;
    CHECK(Refusal(s) == "robot.radius must be in [0.0001, 100] m, or flat (infinite) (got 5e-324)");
  }
  SECTION("the skull's radius, head.radius - scalp.thickness, has the radius floor") {
    Scene s;
    s.head.radius_m = 0.08;
    s.scalp.thickness_m = 0.08 - 0.5e-4;
    CHECK_THAT(Refusal(s), Catch::StartsWith("head.radius must be at least scalp.thickness + 0.0001 m (the skull's least radius) = 0.08005 m (got 0.08)"));
    s.scalp.thickness_m = 0.0799;  // a skull of radius 0.1 mm: taken
    CHECK(Refusal(s).empty());
  }
}

TEST_CASE("at the floors the model answers with finite numbers", "[floors]") {
  using namespace covopt;
  SECTION("each floor alone, on the paper's scene") {
    for (const Floor& f : SceneFloors()) {
      Scene s = f.base;
      f.set(s, f.floor);
      if (std::string(f.field) == "head.radius") continue;  // needs a thinner scalp than its floor allows
      INFO(f.field);
      REQUIRE(Refusal(s).empty());
      const ImpactResult r = Solve(s);
      CHECK(r.status == SolveStatus::kSuccess);
      CHECK(Finite(r.peaks));
    }
  }
  SECTION("the sharpest bare robot at the model's top speed and mass") {
    Scene s;
    s.robot.radius_m = kMinRadius_m;
    s.covering.thickness_m = 0.0;
    s.robot.mass_kg = 1e6;
    s.robot.speed_m_per_s = 100.0;
    const ImpactResult r = Solve(s);
    CHECK(r.status == SolveStatus::kSuccess);
    CHECK(Finite(r.peaks));
    const co::SpeedLimit limit = co::MaxSafeSpeed(s);
    CHECK(std::isfinite(limit.max_safe_speed_m_per_s));
    CHECK(Finite(limit.at_limit));
  }
  SECTION("a 1 us reaction delay with the strongest braking, on the time path") {
    Scene s;
    s.robot.reaction_delay_s = kMinTime_s;
    s.robot.braking_m_per_s2 = 1e4;
    const ImpactResult r = Solve(s);
    CHECK(r.status == SolveStatus::kSuccess);
    CHECK(Finite(r.peaks));
  }
  SECTION("a 1 g torso on the stiffest neck with the most damping the time floor allows") {
    Scene s;
    s.head.torso_mass_kg = kMinMass_kg;
    s.head.neck_stiffness_N_per_m = 1e9;
    // The damper relaxes head against torso in μ/c: at least 1 µs, so c <= μ / 1 µs (~1e3).
    const double mu = 1.0 / (1.0 / s.head.mass_kg + 1.0 / s.head.torso_mass_kg);
    s.head.neck_damping_N_s_per_m = mu / kMinTime_s;
    const ImpactResult r = Solve(s);
    INFO(r.message);
    CHECK(r.status == SolveStatus::kSuccess);
    CHECK(Finite(r.peaks));
    // 1e7 N*s/m (τ = 1e-10 s) ran out of the time path's steps: refused, naming the damper.
    s.head.neck_damping_N_s_per_m = 1e7;
    CHECK_THAT(Refusal(s), Catch::StartsWith("head.neck_damping must be in [0, 999.778] N*s/m for head.mass 4.5 kg "
                                             "and head.torso_mass 0.001 kg"));
  }
}

TEST_CASE("a denormal robot radius is refused, not read as safe up to 100 m/s", "[floors]") {
  Scene s;
  s.robot.radius_m = kDenormal;
  s.covering.thickness_m = 0.0;
  s.robot.mass_kg = 10.0;
  CHECK_THROWS_WITH(co::MaxSafeSpeed(s), Catch::StartsWith("robot.radius must be in [0.0001, 100] m"));
  CHECK_THROWS_AS(co::MaxSafeMass(s), std::invalid_argument);
}

TEST_CASE("a speed limit's mass search starts at the mass floor", "[floors]") {
  Scene s;  // the paper's scene at a speed where only a light robot is safe
  s.robot.speed_m_per_s = 100.0;
  s.covering.thickness_m = 0.0;
  const co::MassLimit limit = co::MaxSafeMass(s);
  CHECK(limit.status == co::SpeedLimitStatus::kNoSafeValue);
  CHECK_THAT(limit.message, Catch::Contains("0.001 kg"));
  co::SpeedLimitOptions below;
  below.max_mass_kg = 1e-4;
  CHECK_THROWS_WITH(co::MaxSafeMass(Scene{}, below), Catch::StartsWith("max_mass_kg must be in [0.001, 1e+06] kg"));
  co::SpeedLimitOptions weak;
  weak.covering_compressive_strength_Pa = kDenormal;
  CHECK_THROWS_WITH(co::MaxSafeSpeed(Scene{}, weak),
                    Catch::StartsWith("covering_compressive_strength_Pa must be 0 (no crush check) or in [1000, 1e+13] Pa"));
}

TEST_CASE("a body region's contact area, mass and robot radius have the floors", "[floors]") {
  BodyContactScene s;
  s.contact_area_m2 = 1e-7;
  CHECK(Refusal(s) == "contact_area must be 0 (not given) or in [1e-06, 1] m2 (got 1e-07)");
  s.contact_area_m2 = covopt::kMinContactArea_m2;
  CHECK(Refusal(s).empty());
  s.body_mass_kg = kDenormal;
  CHECK_THAT(Refusal(s), Catch::StartsWith("body.mass must be in [0.001, 1e+06] kg (got 5e-324)"));
  s = BodyContactScene{};
  s.robot_radius_m = 1e-310;
  CHECK_THAT(Refusal(s), Catch::StartsWith("robot.radius must be in [0.0001, 100] m"));
  s = BodyContactScene{};
  s.robot_mass_kg = kDenormal;
  CHECK_THAT(Refusal(s), Catch::StartsWith("robot.mass must be in [0.001, 1e+06] kg"));
  s = BodyContactScene{};
  s.reaction_delay_s = 1e-300;
  s.braking_m_per_s2 = 1e4;
  CHECK_THAT(Refusal(s), Catch::StartsWith("robot.reaction_delay must be 0 (brake at contact) or in [1e-06, 10] s"));
}

TEST_CASE("property: every head scene the validator takes gives finite numbers", "[floors][property]") {
  Draw draw(20260612);
  int taken = 0, refused = 0, time_path = 0, failed = 0;
  for (int i = 0; i < 4000; ++i) {
    const bool extended = i % 8 == 0;
    Scene s = RandomScene(draw, extended);
    std::optional<ImpactModel> model;
    try {
      model = ImpactModel::FromScene(s);
    } catch (const std::invalid_argument&) {
      ++refused;
      continue;
    }
    ++taken;
    INFO("scene " << i << ": robot " << s.robot.mass_kg << " kg, " << s.robot.speed_m_per_s << " m/s, R "
                  << s.robot.radius_m << " m, E " << s.robot.youngs_modulus_Pa << "; covering " << s.covering.thickness_m
                  << " m, E " << s.covering.youngs_modulus_Pa << ", nu " << s.covering.poisson_ratio << "; head "
                  << s.head.mass_kg << " kg, R " << s.head.radius_m << "; scalp " << s.scalp.thickness_m << " m, E "
                  << s.scalp.youngs_modulus_Pa << "; skull E " << s.skull.youngs_modulus_Pa << "; delay "
                  << s.robot.reaction_delay_s << " s, braking " << s.robot.braking_m_per_s2 << "; torso "
                  << s.head.torso_mass_kg << " kg, neck " << s.head.neck_stiffness_N_per_m << " N/m, "
                  << s.head.neck_damping_N_s_per_m << " Ns/m; damping " << s.model.damping_s_per_m);
    const covopt::ImpactResult r = covopt::Solve(*model);
    if (r.method != covopt::ComputationMethod::kExact) ++time_path;
    if (r.status != covopt::SolveStatus::kSuccess) {
      // A time-path run that fails says so (exit 1 on the CLI); it never answers NaN.
      ++failed;
      CHECK(!r.message.empty());
      continue;
    }
    CHECK(Finite(r.peaks));
    if (r.contact_duration_s) CHECK(std::isfinite(*r.contact_duration_s));
    // Bounded too, at the limits' floors (1 kPa, 1 J/m²): a ratio printed "%.3f" is never
    // a 300-digit number (the largest seen is about 5e13).
    const covopt::InjuryAssessment worst = covopt::Assess(r.peaks, {covopt::kMinModulus_Pa, covopt::kMinEnergyDensity_J_per_m2});
    CHECK(worst.laceration.ratio < 1e15);
    CHECK(worst.contusion.ratio < 1e15);
    if (!extended) {
      co::SpeedLimitOptions options;
      if (draw.Chance(0.3)) options.covering_compressive_strength_Pa = draw(1e3, 1e12);
      co::SpeedLimit speed;
      try {
        speed = co::MaxSafeSpeed(s, options);
      } catch (const std::invalid_argument& e) {  // only the drawn strength may be refused here
        CHECK_THAT(e.what(), Catch::StartsWith("covering_compressive_strength_Pa"));
        continue;
      }
      CHECK(std::isfinite(speed.max_safe_speed_m_per_s));
      CHECK(Finite(speed.at_limit));
      const co::MassLimit mass = co::MaxSafeMass(s, options);
      CHECK(!std::isnan(mass.max_safe_mass_kg));
      CHECK(Finite(mass.at_limit));
    }
  }
  INFO(taken << " taken, " << refused << " refused, " << time_path << " on the time path, " << failed << " failed");
  CHECK(taken > 1000);
  CHECK(refused > 100);
  WARN(taken << " scenes taken (" << time_path << " on the time path, " << failed << " failed runs), " << refused
             << " refused");
}

TEST_CASE("property: every body-region contact the validator takes gives finite numbers", "[floors][property]") {
  Draw draw(15066);
  const auto& table = covopt::materials::BodyRegionTable::BuiltIn();
  const std::vector<covopt::materials::BodyLimits> transient = table.AllLimits(ContactType::kTransient);
  const std::vector<covopt::materials::BodyLimits> clamped = table.AllLimits(ContactType::kClamped);
  int taken = 0, refused = 0;
  for (int i = 0; i < 3000; ++i) {
    const bool is_clamped = draw.Chance(0.3);
    const auto& limits = is_clamped ? clamped[draw.Index(clamped.size())] : transient[draw.Index(transient.size())];
    BodyContactScene s;
    s.contact = is_clamped ? ContactType::kClamped : ContactType::kTransient;
    s.robot_mass_kg = draw(1e-3, 1e6, false, true);
    s.speed_m_per_s = draw(1e-6, 100.0);
    s.robot_radius_m = draw(1e-4, 100.0, false, true);
    s.covering = {draw(1e3, 1e13), draw.Poisson(), draw(1e-4, 1.0, true)};
    s.contact_area_m2 = draw(1e-6, 1.0, true);
    if (i % 10 == 0) {
      s.reaction_delay_s = draw(1e-6, 10.0, true);
      s.braking_m_per_s2 = draw(1e-3, 1e4, true);
    }
    co::BodyRegionOptions options;
    if (draw.Chance(0.3)) {
      co::CandidateMaterial m;
      m.name = "drawn";
      m.youngs_modulus_Pa = s.covering.youngs_modulus_Pa;
      m.crush_behaviour = covopt::materials::CrushBehaviour::kCrushes;
      m.compressive_strength_Pa = draw(1e3, 1e12);
      options.material = m;
    }
    s = co::WithRegion(s, limits);
    if (!Refusal(s).empty()) {
      ++refused;
      continue;
    }
    if (!s.has_covering() && s.contact_area_m2 == 0.0) s.contact_area_m2 = 1e-4;  // the CLI asks for it
    ++taken;
    INFO("contact " << i << ": robot " << s.robot_mass_kg << " kg, " << s.speed_m_per_s << " m/s, R "
                    << s.robot_radius_m << " m; covering " << s.covering.thickness_m << " m, E "
                    << s.covering.youngs_modulus_Pa << "; area " << s.contact_area_m2 << " m2; delay "
                    << s.reaction_delay_s << " s, braking " << s.braking_m_per_s2 << "; " << limits.Describe());
    co::BodyRegionJudgement j;
    try {
      j = co::JudgeBodyContact(s, limits, options);
    } catch (const std::invalid_argument& e) {  // only the drawn strength may be refused here
      CHECK_THAT(e.what(), Catch::Contains("compressive strength must be in [1000, 1e13] Pa"));
      ++refused;
      --taken;
      continue;
    }
    if (!j.contact.ok()) {
      CHECK(!j.contact.message.empty());  // a failed braking run is reported, never NaN
      continue;
    }
    CHECK(Finite(j));
    const co::BodyRegionSpeedLimit limit = co::MaxSafeSpeed(s, limits, options);
    CHECK(std::isfinite(limit.max_safe_speed_m_per_s));
    if (limit.status != co::SpeedLimitStatus::kEvaluationFailed && limit.at_limit.contact.ok()) {
      CHECK(Finite(limit.at_limit));
    }
  }
  CHECK(taken > 1000);
  CHECK(refused > 50);
}
