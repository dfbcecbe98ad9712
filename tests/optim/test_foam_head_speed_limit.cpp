// The head's speed limit with a foam covering (docs/model.md §16): the limit found on the
// penetration axis against a brute-force bisection over the speed on the exact path, the premise
// of that method (every ratio non-decreasing in the speed), the design rule's name under the foam
// law, and the trends a covering must have: never below the bare robot, never lower when thicker.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/core/compressive_curve.hpp>
#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/optim/speed_limit.hpp>
#include <covopt/optim/verdicts.hpp>

#include "vn600_curve.hpp"

namespace {

using covopt::CompressiveCurve;
using covopt::ImpactModel;
using covopt::ImpactPeaks;
using covopt::Scene;
using covopt::optim::MaxSafeSpeed;
using covopt::optim::SpeedLimit;
using covopt::optim::SpeedLimitOptions;
using covopt::optim::SpeedLimitStatus;

std::shared_ptr<const CompressiveCurve> Vn600() { return covopt::testing::Vn600Curve(); }

Scene FoamScene(double thickness_m, double robot_radius_m = 0.015) {
  Scene scene;
  scene.robot.radius_m = robot_radius_m;
  scene.covering = covopt::CoveringSpec{
      .youngs_modulus_Pa = 1e6, .poisson_ratio = 0.0, .thickness_m = thickness_m, .compressive_curve = Vn600()};
  return scene;
}

/// The test's own admissibility of one impact: every injury ratio and, under the default
/// criterion, the strain reserve (strain × SF <= last strain, never used up).
bool Admissible(const Scene& base, double speed, const SpeedLimitOptions& options) {
  Scene scene = base;
  scene.robot.speed_m_per_s = speed;
  const ImpactModel model = ImpactModel::FromScene(scene);
  const ImpactPeaks p = covopt::ExactPeaks(model);
  const double sf = options.safety_factor;
  bool ok = sf * p.max_tensile_stress_Pa <= 1e6 && sf * p.max_energy_density_J_per_m2 <= 25200.0 &&
            sf * p.peak_force_N <= covopt::FractureLimit(options.limits, scene.head.area);
  if (!options.allow_full_compression && model.has_covering()) {
    ok = ok && !p.fully_compressed && sf * p.covering_strain_at_peak <= 0.49 * (1.0 + 1e-12);
  }
  return ok;
}

/// The largest admissible speed by bisection on the exact path (admissibility is monotone).
double BruteForceLimit(const Scene& scene, const SpeedLimitOptions& options) {
  double lo = 1e-6, hi = 100.0;
  if (!Admissible(scene, lo, options)) return 0.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = std::sqrt(lo * hi);
    (Admissible(scene, mid, options) ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace

TEST_CASE("foam head speed limit: the penetration axis agrees with a brute-force bisection", "[foam_head]") {
  for (double h : {0.003, 0.01, 0.04}) {
    for (double radius : {0.005, 0.015, covopt::kFlat}) {
      for (bool paper : {false, true}) {
        for (double sf : {1.0, 2.0}) {
          SpeedLimitOptions options;
          options.allow_full_compression = paper;
          options.safety_factor = sf;
          const Scene scene = FoamScene(h, radius);
          const SpeedLimit limit = MaxSafeSpeed(scene, options);
          CAPTURE(h, radius, paper, sf, limit.message);
          REQUIRE(limit.status == SpeedLimitStatus::kLimited);
          CHECK(limit.max_safe_speed_m_per_s == Approx(BruteForceLimit(scene, options)).epsilon(1e-9));
          // The answer is admissible, and a hair above it is not.
          CHECK(covopt::optim::JudgeImpact([&] {
                  Scene s = scene;
                  s.robot.speed_m_per_s = limit.max_safe_speed_m_per_s;
                  return s;
                }(), options).admissible);
          CHECK_FALSE(Admissible(scene, limit.max_safe_speed_m_per_s * (1.0 + 1e-6), options));
        }
      }
    }
  }
}

TEST_CASE("foam head speed limit: every ratio grows with the speed, within the curve and past it", "[foam_head]") {
  // The premise of the root on v: F, σ_t, e and the strain never fall as the speed rises.
  for (double h : {0.003, 0.02}) {
    ImpactPeaks previous;
    for (int k = 0; k <= 400; ++k) {
      Scene scene = FoamScene(h);
      scene.robot.speed_m_per_s = 0.01 * std::pow(1000.0, k / 400.0);  // 0.01 .. 10 m/s
      const ImpactPeaks p = covopt::ExactPeaks(ImpactModel::FromScene(scene));
      CAPTURE(h, scene.robot.speed_m_per_s);
      CHECK(p.peak_force_N >= previous.peak_force_N);
      CHECK(p.max_tensile_stress_Pa >= previous.max_tensile_stress_Pa);
      CHECK(p.max_energy_density_J_per_m2 >= previous.max_energy_density_J_per_m2);
      CHECK(p.covering_strain_at_peak >= previous.covering_strain_at_peak);
      previous = p;
    }
    CHECK(previous.fully_compressed);  // the scan reaches past the stop
  }
}

TEST_CASE("foam head speed limit: a covering never below the bare robot, never lower when thicker", "[foam_head]") {
  // The injury criteria only (the paper's criterion): the foam's benefit.
  SpeedLimitOptions options;
  options.allow_full_compression = true;
  Scene bare = FoamScene(0.0);
  const double bare_speed = MaxSafeSpeed(bare, options).max_safe_speed_m_per_s;
  double previous = bare_speed;
  for (double h : {0.002, 0.005, 0.01, 0.02, 0.04, 0.08}) {
    const SpeedLimit limit = MaxSafeSpeed(FoamScene(h), options);
    CAPTURE(h, bare_speed, limit.max_safe_speed_m_per_s);
    CHECK(limit.max_safe_speed_m_per_s >= previous * (1.0 - 1e-9));
    previous = limit.max_safe_speed_m_per_s;
  }
  CHECK(previous > 1.05 * bare_speed);  // 80 mm of it is worth more than rounding
}

TEST_CASE("foam head verdict: the travel rule is named within-curve under the foam law", "[foam_head]") {
  SpeedLimitOptions options;
  Scene foam = FoamScene(0.02);
  foam.robot.speed_m_per_s = 0.2;
  const ImpactPeaks peaks = covopt::ExactPeaks(ImpactModel::FromScene(foam));
  REQUIRE_FALSE(peaks.fully_compressed);
  const covopt::Verdict verdict = covopt::optim::HeadVerdict(foam, peaks, options);
  const covopt::Criterion* rule = verdict.Find(covopt::optim::kWithinCurveRule);
  REQUIRE(rule != nullptr);
  CHECK(verdict.Find(covopt::optim::kFullCompressionRule) == nullptr);
  CHECK(rule->value == Approx(peaks.covering_strain_at_peak / 0.49));
  CHECK(verdict.safe());
  // Used up (0.5 m/s brings more than the 20 mm layer stores): the rule fails, the injury
  // criteria pass, and the paper's criterion (injury only) calls it safe.
  foam.robot.speed_m_per_s = 0.5;
  const ImpactPeaks used_up = covopt::ExactPeaks(ImpactModel::FromScene(foam));
  REQUIRE(used_up.fully_compressed);
  CHECK_FALSE(covopt::optim::HeadVerdict(foam, used_up, options).safe());
  options.allow_full_compression = true;
  CHECK(covopt::optim::HeadVerdict(foam, used_up, options).safe());
  options.allow_full_compression = false;

  Scene hertz = foam;
  hertz.covering.law = covopt::CoveringLaw::kHertz;
  const covopt::Verdict hertz_verdict =
      covopt::optim::HeadVerdict(hertz, covopt::ExactPeaks(ImpactModel::FromScene(hertz)), options);
  CHECK(hertz_verdict.Find(covopt::optim::kFullCompressionRule) != nullptr);
  CHECK(hertz_verdict.Find(covopt::optim::kWithinCurveRule) == nullptr);
}
