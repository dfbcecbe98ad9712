// Robust design with a braking robot (docs/model.md §11, "A braking robot"): the claim the
// screening rests on (braking never raises a ratio), the worst case and the robust design
// against brute force on the time path, the limits (a brake after the peak, no brake), and a
// failed time-path run reported, never read as safe.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/core/time_integration.hpp>
#include <covopt/optim/robust_design.hpp>

using namespace covopt;
using namespace covopt::optim;
using Catch::Matchers::Contains;

namespace {

/// The paper's scene with a robot braking at `a` m/s² from `delay` s after first contact.
Scene Braking(double a, double delay, double covering_m = 0.015) {
  Scene scene;
  scene.covering = {27.6e6, 0.22, covering_m};
  scene.robot.braking_m_per_s2 = a;
  scene.robot.reaction_delay_s = delay;
  return scene;
}

/// g of one scene judged in full on the time path (the exact path without braking).
struct Ratios {
  double laceration = 0.0, contusion = 0.0, compression = 0.0, governing = 0.0;
  bool fully_compressed = false;
};
Ratios Judge(const Scene& scene) {
  const ImpactModel model = ImpactModel::FromScene(scene);
  ImpactPeaks peaks;
  if (scene.robot_brakes()) {
    const ImpactResult r = SimulateImpact(model);
    REQUIRE(r.ok());
    peaks = r.peaks;
  } else {
    peaks = ExactPeaks(model);
  }
  const InjuryLimits limits;
  Ratios out;
  out.laceration = peaks.max_tensile_stress_Pa / limits.laceration_tensile_stress_Pa;
  out.contusion = peaks.max_energy_density_J_per_m2 / limits.contusion_energy_density_J_per_m2;
  out.compression = model.has_covering() ? peaks.covering_compression_ratio() : 0.0;
  out.fully_compressed = model.has_covering() && peaks.fully_compressed;
  out.governing = std::max({out.laceration, out.contusion, out.compression});
  return out;
}

/// Two compressible Hertz coverings (ν 0.3: no solid elastomer's strain limit, so the law's
/// validity is the covering not fully compressed, which Judge checks).
std::vector<CandidateMaterial> HertzCoverings() {
  std::vector<CandidateMaterial> m = {{"soft", 3.4e6, 0.3}, {"stiff", 5.9e6, 0.3}};
  for (CandidateMaterial& c : m) c.crush_behaviour = covopt::materials::CrushBehaviour::kDoesNotCrush;
  return m;
}

const std::vector<UncertainInput> kHeads = {{"head-mass", 3.7, 5.8}, {"scalp-thickness", 0.002, 0.005}};

}  // namespace

TEST_CASE("braking never raises a ratio: the exact path's unbraked impact bounds the braked one",
          "[robust][braking]") {
  // The screening's premise (docs/model.md §11): while the brake acts in the loading,
  // d/dt(½ μ δ'² + U(δ)) = −μ a δ' <= 0, so U(δ_max) <= ½ μ v0² and every peak, a
  // non-decreasing function of δ_max, is no larger. A dense scan over speeds, delays, decelerations
  // and coverings (bare, thin, thick; free and fixed head).
  int braked_lower = 0, scenes = 0;
  for (double speed : {0.2, 0.5, 1.0, 2.0, 3.5}) {
    for (double delay : {0.0, 0.5e-3, 2e-3, 5e-3, 20e-3}) {
      for (double a : {1.0, 20.0, 100.0, 1000.0}) {
        for (double b : {0.0, 0.004, 0.015, 0.04}) {
          for (bool fixed_head : {false, true}) {
            Scene braked = Braking(a, delay, b);
            braked.robot.speed_m_per_s = speed;
            if (fixed_head) braked.head.mass_kg = kFixed;
            Scene free = braked;
            free.robot.braking_m_per_s2 = 0.0;
            free.robot.reaction_delay_s = 0.0;
            const Ratios rb = Judge(braked), ru = Judge(free);
            INFO("v0 " << speed << " t_d " << delay << " a " << a << " b_c " << b << " fixed head " << fixed_head);
            // The time path's own error at rtol 1e-8 is far below 1e-6.
            CHECK(rb.laceration <= ru.laceration * (1 + 1e-6));
            CHECK(rb.contusion <= ru.contusion * (1 + 1e-6));
            CHECK(rb.compression <= ru.compression * (1 + 1e-6) + 1e-12);
            CHECK((!rb.fully_compressed || ru.fully_compressed));
            ++scenes;
            braked_lower += rb.contusion < ru.contusion * (1 - 1e-4);
          }
        }
      }
    }
  }
  // The scan is not vacuous: braking lowers the ratios in most of it.
  CHECK(braked_lower > scenes / 3);
}

TEST_CASE("the worst case of a box with a braking robot is the brute-force maximum on the time path",
          "[robust][braking]") {
  const UncertaintyBox box = UncertaintyBox::FromScene(Braking(100.0, 0.002), kHeads);
  CHECK(box.brakes());
  const WorstCase worst = FindWorstCase(box);
  CHECK(worst.time_path.runs > 0);
  CHECK(worst.time_path.failed == 0);
  // The point kept is judged in full: its ratio is the time path's at that scene.
  CHECK(worst.governing_ratio == Approx(Judge(worst.scene).governing).epsilon(1e-12));
  // No point of a 9 x 9 grid, each simulated, is worse (the head mass is searched, not pinned).
  double grid_max = 0.0;
  for (int i = 0; i <= 8; ++i) {
    for (int j = 0; j <= 8; ++j) {
      const std::vector<double> values{3.7 + 2.1 * i / 8, 0.002 + 0.003 * j / 8};
      grid_max = std::max(grid_max, Judge(box.SceneAt(values)).governing);
    }
  }
  CHECK(worst.governing_ratio >= grid_max * (1 - 1e-9));
  CHECK(worst.governing_ratio <= grid_max * 1.05);  // a smooth landscape: the grid comes close
  // Braking lowers the worst case below the unbraked one.
  const WorstCase unbraked = FindWorstCase(UncertaintyBox::FromScene(Braking(0.0, 0.0), kHeads));
  CHECK(worst.governing_ratio < unbraked.governing_ratio);
}

TEST_CASE("a robust design with a braking robot holds for every scene of the box, re-simulated, and is no thicker",
          "[robust][braking]") {
  RobustDesignOptions options;
  options.continuous = false;
  options.design.thickness_scan_points = 60;
  options.design.thickness_resolution_m = 1e-5;
  const UncertaintyBox braked_box = UncertaintyBox::FromScene(Braking(100.0, 0.002), kHeads);
  const UncertaintyBox free_box = UncertaintyBox::FromScene(Braking(0.0, 0.0), kHeads);
  const RobustThinnestCovering braked = FindRobustThinnestCovering(braked_box, HertzCoverings(), options);
  const RobustThinnestCovering free = FindRobustThinnestCovering(free_box, HertzCoverings(), options);
  REQUIRE(braked.recommendation);
  REQUIRE(free.recommendation);
  CHECK(braked.time_path.runs > 0);
  CHECK(braked.time_path.failed == 0);
  CHECK(free.time_path.runs == 0);
  for (const RobustCandidate& c : braked.candidates) {
    const std::string name = c.outcome.material.name;
    INFO(name);
    const auto twin = std::find_if(free.candidates.begin(), free.candidates.end(),
                                   [&](const RobustCandidate& f) { return f.outcome.material.name == name; });
    REQUIRE(twin != free.candidates.end());
    REQUIRE(c.outcome.min_safe_thickness_m);
    REQUIRE(twin->outcome.min_safe_thickness_m);
    // Braking makes the design no thicker (to the bisection's resolution).
    CHECK(*c.outcome.min_safe_thickness_m <= *twin->outcome.min_safe_thickness_m + 1e-5);
    // Every scene of a 7 x 7 grid over the box, simulated at the thinnest design, is admissible ...
    Scene designed = braked_box.nominal();
    designed.covering = {c.outcome.material.youngs_modulus_Pa, c.outcome.material.poisson_ratio,
                         *c.outcome.min_safe_thickness_m};
    double grid_max = 0.0;
    for (int i = 0; i <= 6; ++i) {
      for (int j = 0; j <= 6; ++j) {
        Scene s = designed;
        s.head.mass_kg = 3.7 + 2.1 * i / 6;
        s.scalp.thickness_m = 0.002 + 0.003 * j / 6;
        const Ratios r = Judge(s);
        grid_max = std::max(grid_max, r.governing);
        CHECK_FALSE(r.fully_compressed);
      }
    }
    CHECK(grid_max <= 1.0 + 1e-9);
    // ... and the design is tight: its worst case binds.
    REQUIRE(c.worst_case_at_thinnest);
    CHECK(c.worst_case_at_thinnest->governing_ratio > 0.99);
    // A thinner covering fails somewhere in the box, re-simulated at the reported worst point.
    Scene thinner = c.worst_case_at_thinnest->scene;
    thinner.covering.thickness_m -= 2e-4;
    CHECK(Judge(thinner).governing > 1.0);
  }
}

TEST_CASE("a brake that starts after the peak, or none, gives the unbraked robust answer", "[robust][braking]") {
  RobustDesignOptions options;
  options.continuous = false;
  options.design.thickness_scan_points = 60;
  options.design.thickness_resolution_m = 1e-5;
  const RobustThinnestCovering free =
      FindRobustThinnestCovering(UncertaintyBox::FromScene(Braking(0.0, 0.0), kHeads), HertzCoverings(), options);
  // A reaction delay far beyond any contact: every impact is the exact path's (brake after the
  // peak), and the answer is the unbraked one exactly, whatever the search order.
  const UncertaintyBox late = UncertaintyBox::FromScene(Braking(100.0, 1.0), kHeads);
  const RobustThinnestCovering delayed = FindRobustThinnestCovering(late, HertzCoverings(), options);
  CHECK(delayed.time_path.runs == 0);
  CHECK(delayed.time_path.brake_after_peak > 0);
  // A vanishing deceleration: the time path runs, and the answer tends to the unbraked one.
  const RobustThinnestCovering weak =
      FindRobustThinnestCovering(UncertaintyBox::FromScene(Braking(1e-6, 0.0), kHeads), HertzCoverings(), options);
  REQUIRE(free.candidates.size() == delayed.candidates.size());
  for (std::size_t i = 0; i < free.candidates.size(); ++i) {
    const CandidateOutcome& f = free.candidates[i].outcome;
    INFO(f.material.name);
    CHECK(delayed.candidates[i].outcome.material.name == f.material.name);
    REQUIRE(f.min_safe_thickness_m);
    CHECK(*delayed.candidates[i].outcome.min_safe_thickness_m == Approx(*f.min_safe_thickness_m).margin(1e-5));
    CHECK(delayed.candidates[i].worst_case.governing_ratio ==
          Approx(free.candidates[i].worst_case.governing_ratio).epsilon(1e-9));
    CHECK(*weak.candidates[i].outcome.min_safe_thickness_m == Approx(*f.min_safe_thickness_m).margin(2e-5));
  }
}

TEST_CASE("the injury probability with a braking robot counts what the time path finds, sample by sample",
          "[robust][braking]") {
  Scene scene = Braking(100.0, 0.002, 0.012);
  const UncertaintyBox box = UncertaintyBox::FromScene(scene, kHeads);
  InjuryProbabilityOptions options;
  options.samples = 300;
  options.threads = 2;
  const InjuryProbability p = EstimateInjuryProbability(box, options);
  std::uint64_t contusion = 0, inadmissible = 0;
  for (std::uint64_t i = 0; i < options.samples; ++i) {
    const Ratios r = Judge(box.SceneAt(DrawInputs(box, options.seed, i)));
    contusion += r.contusion > 1.0;
    inadmissible += r.governing > 1.0 || r.fully_compressed;
  }
  CHECK(p.contusion.count == contusion);
  CHECK(p.inadmissible.count == inadmissible);
  CHECK(p.time_path.runs + p.time_path.screened + p.time_path.brake_after_peak == 300);
  // Not vacuous, and braking helps: the unbraked box injures more.
  const InjuryProbability unbraked = EstimateInjuryProbability(UncertaintyBox::FromScene(Braking(0, 0, 0.012), kHeads), options);
  CHECK(inadmissible > 0);
  CHECK(unbraked.inadmissible.count > p.inadmissible.count);
}

TEST_CASE("a failed time-path run in a robust search is reported and never read as safe", "[robust][braking]") {
  // Ten steps cannot integrate a contact: every time-path run fails with the step limit.
  const UncertaintyBox box = UncertaintyBox::FromScene(Braking(100.0, 0.002, 0.04), kHeads);
  WorstCaseOptions options;
  options.time_path.max_steps = 10;
  const WorstCase worst = FindWorstCase(box, options);
  CHECK(worst.time_path.failed > 0);
  CHECK_THAT(worst.time_path.first_failure, Contains("time path at"));
  CHECK_FALSE(worst.admissible);
  CHECK(std::isinf(worst.governing_ratio));
  // The same 40 mm covering is admissible with working runs: the failure, not the scene, fails it.
  CHECK(FindWorstCase(box).admissible);

  RobustDesignOptions design;
  design.continuous = false;
  design.design.thickness_scan_points = 20;
  design.design.oracle.time_path.max_steps = 10;
  const RobustThinnestCovering robust = FindRobustThinnestCovering(box, HertzCoverings(), design);
  CHECK_FALSE(robust.recommendation);
  CHECK(robust.time_path.failed > 0);
  for (const RobustCandidate& c : robust.candidates) CHECK_FALSE(c.outcome.safe);

  InjuryProbabilityOptions sampling;
  sampling.samples = 50;
  sampling.time_path.max_steps = 10;
  const InjuryProbability p = EstimateInjuryProbability(box, sampling);
  CHECK(p.time_path.failed == static_cast<long>(p.time_path.runs));
  CHECK(p.inadmissible.count >= static_cast<std::uint64_t>(p.time_path.failed));
}

TEST_CASE("elasticities with a braking robot are differences on the time path", "[robust][braking]") {
  const Scene scene = Braking(100.0, 0.002);
  const ElasticityTable table = ComputeElasticities(scene);
  const Ratios at = Judge(scene);
  CHECK(table.contusion_ratio == Approx(at.contusion).epsilon(1e-12));
  bool saw_braking = false, saw_delay = false;
  for (const InputElasticity& row : table.rows) {
    INFO(row.field);
    CHECK(row.method != DerivativeMethod::kAnalytic);
    if (row.field == "braking") {
      saw_braking = true;
      CHECK(row.contusion < 0.0);  // a stronger brake lowers the contusion ratio
    }
    if (row.field == "reaction-delay") {
      saw_delay = true;
      CHECK(row.contusion > 0.0);  // a later brake raises it
    }
    if (row.field == "speed") {
      // An independent central difference of the time path's own values.
      const double h = 0.01;
      Scene up = scene, down = scene;
      up.robot.speed_m_per_s *= std::exp(h);
      down.robot.speed_m_per_s *= std::exp(-h);
      const double expected = (std::log(Judge(up).contusion) - std::log(Judge(down).contusion)) / (2 * h);
      CHECK(row.contusion == Approx(expected).epsilon(1e-3));
    }
  }
  CHECK(saw_braking);
  CHECK(saw_delay);
  Scene damped = scene;
  damped.model.damping_s_per_m = 0.1;
  CHECK_THROWS_WITH(ComputeElasticities(damped), Contains("contact damping or a neck"));
}
