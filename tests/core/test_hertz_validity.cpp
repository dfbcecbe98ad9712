// A covering's validity under the Hertz law (docs/model.md §12.2): a solid elastomer
// (ν >= 0.45, nearly incompressible) bonded as a layer is within the half-space law only while
// its peak nominal strain δ_c/b_c <= 0.20 and its contact radius a_c <= b_c; a fully compressed
// Hertz covering is not within, on the head and on a body region. Each threshold is checked
// against an independent closed form of the speed at which it is reached (the energy balance at
// that compression), just below and just above, and against a bisection on the speed over the
// `within` flag; a foam-like ν below 0.45 keeps today's reading.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <covopt/core.hpp>
#include <covopt/core/body_contact.hpp>
#include <covopt/core/number_format.hpp>

#include "test_helpers.hpp"

namespace {

using covopt::BodyContactResult;
using covopt::BodyContactScene;
using covopt::CoveringValidity;
using covopt::ImpactModel;
using covopt::ImpactResult;
using covopt::Scene;

constexpr double kA60Modulus_Pa = 5.884e6;  // the catalog's "elastomer Shore A60"
constexpr double kA60Poisson = 0.49;

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// The paper's scene (10 kg at 2 m/s, R_r 15 mm, free 4.5 kg head) with a covering.
Scene HeadScene(double modulus_Pa, double poisson, double thickness_m, double speed_m_per_s = 2.0) {
  Scene scene = covopt::test::PaperScene(thickness_m, modulus_Pa, poisson);
  scene.robot.speed_m_per_s = speed_m_per_s;
  return scene;
}

CoveringValidity HeadValidity(const Scene& scene) { return covopt::SolveExact(ImpactModel::FromScene(scene)).validity; }

/// The head's covering compression and phase-2 contact radius at δ, written out from the
/// thresholds (docs/model.md §2.3): t1 = 0.8 b_s, t2 = t1 + 0.8 b_c, c2 = 1/R_c + 1/(R_s − b_s).
struct HeadCoveringAt {
  double strain;
  double contact_radius_m;
};
HeadCoveringAt HeadCovering(const Scene& s, double delta_m) {
  const double t1 = 0.8 * s.scalp.thickness_m;
  const double t2 = t1 + 0.8 * s.covering.thickness_m;
  const double x = std::max(std::min(delta_m, t2) - t1, 0.0);
  const double c2 = 1.0 / (s.robot.radius_m + s.covering.thickness_m) + 1.0 / (s.head.radius_m - s.scalp.thickness_m);
  return {x / s.covering.thickness_m, std::sqrt(x / c2)};
}

/// The speed at which the head's δ_max is `delta_m` (½ m v² = U(δ)).
double HeadSpeedAt(const Scene& s, double delta_m) {
  return covopt::test::WithMaxPenetration(s, delta_m).robot.speed_m_per_s;
}

/// Bisection on the speed over `within(v)`, from a within and an out speed: where it flips.
template <class Within>
double FlipSpeed(Within within, double low, double high) {
  REQUIRE(within(low));
  REQUIRE_FALSE(within(high));
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (low + high);
    (within(mid) ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

/// The hand (Table A.3: 75 kN/m, 0.6 kg), transient, a 10 kg robot of radius R_r with a covering.
BodyContactScene HandScene(double modulus_Pa, double poisson, double thickness_m, double radius_m, double speed) {
  BodyContactScene s;
  s.robot_mass_kg = 10.0;
  s.speed_m_per_s = speed;
  s.body_stiffness_N_per_m = 75e3;
  s.body_mass_kg = 0.6;
  s.robot_radius_m = radius_m;
  s.covering = {.youngs_modulus_Pa = modulus_Pa, .poisson_ratio = poisson, .thickness_m = thickness_m};
  return s;
}

/// The body region's speed at which the Hertz covering's deflection is δ_c, in closed form:
/// F = K_c δ_c^1.5 (K_c = 4/3 E/(1 − ν²) √R_c), E = F²/(2k) + 2/5 F δ_c = ½ μ v².
double HandSpeedAt(const BodyContactScene& s, double deflection_m) {
  const double outer = s.robot_radius_m + s.covering.thickness_m;
  const double nu = s.covering.poisson_ratio;
  const double k_c = 4.0 / 3.0 * s.covering.youngs_modulus_Pa / (1.0 - nu * nu) * std::sqrt(outer);
  const double force = k_c * std::pow(deflection_m, 1.5);
  const double energy = force * force / (2.0 * s.body_stiffness_N_per_m) + 0.4 * force * deflection_m;
  const double mu = 1.0 / (1.0 / s.robot_mass_kg + 1.0 / s.body_mass_kg);
  return std::sqrt(2.0 * energy / mu);
}

BodyContactResult HandAt(BodyContactScene s, double speed) {
  s.speed_m_per_s = speed;
  return covopt::Solve(s);
}

}  // namespace

TEST_CASE("hertz validity: the default optimize answer, elastomer A60 20 mm at 2 m/s, is out of validity",
          "[hertz_validity]") {
  const Scene scene = HeadScene(kA60Modulus_Pa, kA60Poisson, 0.020);
  const ImpactResult result = covopt::SolveExact(ImpactModel::FromScene(scene));
  const HeadCoveringAt independent = HeadCovering(scene, result.peaks.max_penetration_m);
  // The optimiser's answer uses most of its travel: strain far beyond 0.20, contact within b_c.
  CHECK(independent.strain > 0.7);
  CHECK(independent.contact_radius_m < 0.020);
  CHECK(result.peaks.covering_strain_at_peak == Approx(independent.strain).epsilon(1e-12));
  CHECK_FALSE(result.peaks.fully_compressed);
  CHECK_FALSE(result.validity.within);
  CHECK(result.validity.ratio == Approx(independent.strain / 0.20).epsilon(1e-12));
  CHECK(result.validity.ratio_full_compression_allowed == result.validity.ratio);
  CHECK(Contains(result.validity.note, "solid elastomer (ν 0.49) under the Hertz law: peak strain " +
                                           covopt::FormatSignificant(independent.strain, 3) + " > 0.2"));
  CHECK(Contains(result.validity.note, "bulges"));
  CHECK_FALSE(Contains(result.validity.note, "contact radius"));
  // The time path reports the same.
  covopt::SolveOptions timed;
  timed.path = covopt::PathChoice::kTimePath;
  const ImpactResult time_path = covopt::Solve(scene, timed);
  REQUIRE(time_path.ok());
  CHECK_FALSE(time_path.validity.within);
  CHECK(time_path.validity.ratio == Approx(result.validity.ratio).epsilon(1e-5));
}

TEST_CASE("hertz validity: the paper's covering (ν 0.25) keeps today's reading", "[hertz_validity]") {
  for (const double speed : {0.5, 1.0, 2.0, 4.0, 8.0}) {
    const Scene scene = HeadScene(27.6e6, 0.25, 0.015, speed);
    const ImpactResult r = covopt::SolveExact(ImpactModel::FromScene(scene));
    INFO("v = " << speed << ": " << r.validity.note);
    CHECK(r.validity.within == !r.peaks.fully_compressed);
    CHECK_FALSE(Contains(r.validity.note, "elastomer"));
    CHECK(r.validity.note.rfind(r.peaks.fully_compressed ? "hertz law: fully compressed" : "hertz law: not fully compressed",
                                0) == 0);
    CHECK(r.validity.ratio_full_compression_allowed == 0.0);
    CHECK(r.validity.ratio == Approx(r.peaks.covering_compression_ratio()).epsilon(1e-12));
    CHECK((r.validity.ratio <= 1.0) == r.validity.within);
  }
  // ν just below the elastomer limit: a strain far beyond 0.20 is within the law (not compressed
  // fully); at the limit it is not.
  const Scene nu044 = HeadScene(kA60Modulus_Pa, 0.44, 0.020, 1.5);
  const ImpactResult r044 = covopt::SolveExact(ImpactModel::FromScene(nu044));
  CHECK(r044.peaks.covering_strain_at_peak > 0.4);
  CHECK(r044.validity.within);
  CHECK_FALSE(Contains(r044.validity.note, "elastomer"));
  CHECK_FALSE(HeadValidity(HeadScene(kA60Modulus_Pa, 0.45, 0.020, 1.5)).within);
}

TEST_CASE("hertz validity: a 2 mm A60 layer on the head is out by its contact radius before its strain",
          "[hertz_validity]") {
  const Scene base = HeadScene(kA60Modulus_Pa, kA60Poisson, 0.002);
  const double t1 = 0.8 * base.scalp.thickness_m;
  // a_c = b_c at x = b_c² c2: strain b_c c2 = 0.002 (1/0.017 + 1/0.077) = 0.14 < 0.20.
  const double c2 = 1.0 / 0.017 + 1.0 / 0.077;
  const double x_radius = 0.002 * 0.002 * c2;
  REQUIRE(x_radius / 0.002 < 0.20);
  const double v_radius = HeadSpeedAt(base, t1 + x_radius);
  auto within = [&](double v) { return HeadValidity(HeadScene(kA60Modulus_Pa, kA60Poisson, 0.002, v)).within; };
  CHECK(within(v_radius * (1.0 - 1e-6)));
  CHECK_FALSE(within(v_radius * (1.0 + 1e-6)));
  CHECK(FlipSpeed(within, 0.5 * v_radius, 2.0 * v_radius) == Approx(v_radius).epsilon(1e-9));
  // Just past it: out by the contact radius alone, the strain still below 0.20.
  const Scene past = HeadScene(kA60Modulus_Pa, kA60Poisson, 0.002, v_radius * 1.01);
  const ImpactResult r = covopt::SolveExact(ImpactModel::FromScene(past));
  const HeadCoveringAt independent = HeadCovering(past, r.peaks.max_penetration_m);
  CHECK(independent.strain < 0.20);
  CHECK(independent.contact_radius_m > 0.002);
  CHECK(r.validity.ratio == Approx(independent.contact_radius_m / 0.002).epsilon(1e-9));
  CHECK(Contains(r.validity.note, "contact radius " + covopt::FormatSignificant(independent.contact_radius_m * 1e3, 3) +
                                      " mm > the layer's thickness 2 mm"));
  CHECK_FALSE(Contains(r.validity.note, "bulges"));
  // The paper's scene at 2 m/s takes it far beyond both.
  const CoveringValidity at_2 = HeadValidity(base);
  CHECK_FALSE(at_2.within);
  CHECK(Contains(at_2.note, "hertz law: fully compressed"));
}

TEST_CASE("hertz validity: the head's strain threshold is sharp", "[hertz_validity]") {
  const Scene base = HeadScene(kA60Modulus_Pa, kA60Poisson, 0.020);
  const double delta_limit = 0.8 * base.scalp.thickness_m + 0.20 * 0.020;
  REQUIRE(HeadCovering(base, delta_limit).contact_radius_m < 0.020);  // the strain binds first
  const double v_limit = HeadSpeedAt(base, delta_limit);
  auto within = [&](double v) { return HeadValidity(HeadScene(kA60Modulus_Pa, kA60Poisson, 0.020, v)).within; };
  CHECK(within(v_limit * (1.0 - 1e-6)));
  CHECK_FALSE(within(v_limit * (1.0 + 1e-6)));
  CHECK(FlipSpeed(within, 0.1, 2.0) == Approx(v_limit).epsilon(1e-9));
  const CoveringValidity below = HeadValidity(HeadScene(kA60Modulus_Pa, kA60Poisson, 0.020, 0.9 * v_limit));
  CHECK(Contains(below.note, "within its limits, peak strain"));
  CHECK(below.ratio < 1.0);
  CHECK(below.ratio > 0.5);
}

TEST_CASE("hertz validity: a body region's elastomer, strain and contact radius thresholds", "[hertz_validity]") {
  SECTION("20 mm on R_r 15 mm: the strain binds (a_c = b_c only at strain b_c/R_c = 0.57)") {
    const BodyContactScene s = HandScene(kA60Modulus_Pa, kA60Poisson, 0.020, 0.015, 1.0);
    const double v_limit = HandSpeedAt(s, 0.20 * 0.020);
    auto within = [&](double v) { return HandAt(s, v).validity.within; };
    CHECK(within(v_limit * (1.0 - 1e-6)));
    CHECK_FALSE(within(v_limit * (1.0 + 1e-6)));
    CHECK(FlipSpeed(within, 0.5 * v_limit, 2.0 * v_limit) == Approx(v_limit).epsilon(1e-9));
    const BodyContactResult past = HandAt(s, 1.5 * v_limit);
    CHECK(past.validity.ratio == Approx(past.covering_deflection_m / 0.020 / 0.20).epsilon(1e-12));
    CHECK(Contains(past.validity.note, "solid elastomer (ν 0.49) under the Hertz law: peak strain"));
    CHECK_FALSE(past.fully_compressed);
    // The same layer at ν 0.44 is within.
    CHECK(HandAt(HandScene(kA60Modulus_Pa, 0.44, 0.020, 0.015, 1.5 * v_limit), 1.5 * v_limit).validity.within);
  }
  SECTION("2 mm on R_r 15 mm: the contact radius binds (a_c² = R_c δ_c = b_c² at strain 0.118)") {
    const BodyContactScene s = HandScene(kA60Modulus_Pa, kA60Poisson, 0.002, 0.015, 0.1);
    const double deflection = 0.002 * 0.002 / 0.017;
    const double v_limit = HandSpeedAt(s, deflection);
    auto within = [&](double v) { return HandAt(s, v).validity.within; };
    CHECK(within(v_limit * (1.0 - 1e-6)));
    CHECK_FALSE(within(v_limit * (1.0 + 1e-6)));
    CHECK(FlipSpeed(within, 0.5 * v_limit, 2.0 * v_limit) == Approx(v_limit).epsilon(1e-9));
    const BodyContactResult past = HandAt(s, 1.05 * v_limit);
    CHECK(past.peak_strain < 0.20);
    CHECK(Contains(past.validity.note, "contact radius"));
    CHECK(past.validity.ratio == Approx(std::sqrt(0.017 * past.covering_deflection_m) / 0.002).epsilon(1e-12));
  }
}

TEST_CASE("hertz validity: a fully compressed Hertz covering is not within, head and body region",
          "[hertz_validity]") {
  // The paper's covering (ν 0.25): only the travel counts, and the paper's criterion waives it.
  const BodyContactScene s = HandScene(27.6e6, 0.25, 0.005, 0.015, 1.0);
  const double v_full = HandSpeedAt(s, 0.8 * 0.005);
  const BodyContactResult below = HandAt(s, 0.99 * v_full);
  const BodyContactResult above = HandAt(s, 1.01 * v_full);
  CHECK_FALSE(below.fully_compressed);
  CHECK(below.validity.within);
  CHECK(below.validity.ratio == Approx(below.compression_ratio).epsilon(1e-12));
  REQUIRE(above.fully_compressed);
  CHECK_FALSE(above.validity.within);
  CHECK(above.validity.ratio > 1.0);
  CHECK(above.validity.ratio_full_compression_allowed == 0.0);
  CHECK(Contains(above.validity.note, "fully compressed"));
  const ImpactResult head = covopt::SolveExact(ImpactModel::FromScene(HeadScene(27.6e6, 0.25, 0.005, 6.0)));
  REQUIRE(head.peaks.fully_compressed);
  CHECK_FALSE(head.validity.within);
  CHECK(head.validity.ratio > 1.0);
  CHECK(head.validity.ratio_full_compression_allowed == 0.0);
}

TEST_CASE("hertz validity: a foam's ratio on a body region is its contact's share of the face's cap",
          "[hertz_validity]") {
  // The foam law's one limit on a curved face is d <= R_c/2 (docs/model.md §15.5); an elastomer's
  // Poisson ratio plays no part under the foam law.
  static const std::vector<covopt::StrainStressPoint> kPoints{{0.05, 20e3}, {0.5, 60e3}, {0.8, 2e6}};
  BodyContactScene s = HandScene(kA60Modulus_Pa, kA60Poisson, 0.040, 0.015, 1.0);
  s.covering.compressive_curve =
      std::make_shared<const covopt::CompressiveCurve>(covopt::CompressiveCurve::FromPoints(kPoints));
  for (const double speed : {0.2, 0.5, 1.0, 2.0, 4.0}) {
    const BodyContactResult r = HandAt(s, speed);
    INFO("v = " << speed << ": " << r.validity.note);
    REQUIRE(r.covering_law == covopt::CoveringLaw::kFoam);
    CHECK(r.validity.ratio == Approx(r.covering_deflection_m / (0.5 * 0.055)).epsilon(1e-12));
    CHECK(r.validity.ratio_full_compression_allowed == r.validity.ratio);
    CHECK(r.validity.within == (r.validity.ratio <= 1.0));
    CHECK_FALSE(Contains(r.validity.note, "elastomer"));
  }
}
