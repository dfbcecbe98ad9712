// The design oracle: which path `auto` chooses and why (the exact path for the paper's scene,
// the time path for a braking robot or a neck), `exact` refused where there is no energy
// integral; the time-path oracle scores and differentiates the paper's scene like the exact
// one to its tolerance (CVODES forward sensitivities; a central difference for braking,
// checked where braking starts after the contact and so changes nothing); the
// thinnest-safe-covering search on the time path reproduces the exact path's optimum within a
// bound from rtol; failed time-path evaluations are counted and never an answer; the speed
// limit on a braking scene is bracketed on the time path and agrees with a brute-force scan;
// a sweep solves braking points on the time path.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <covopt/core/sweep.hpp>
#include <covopt/optim/covering_design.hpp>
#include <covopt/optim/design.hpp>
#include <covopt/optim/design_work_precision.hpp>
#include <covopt/optim/oracle.hpp>
#include <covopt/optim/speed_limit.hpp>

using namespace covopt;
using namespace covopt::optim;

namespace {

Scene Braking(double delay_s = 0.0, double braking_m_per_s2 = 50.0) {
  Scene scene;
  scene.robot.reaction_delay_s = delay_s;
  scene.robot.braking_m_per_s2 = braking_m_per_s2;
  return scene;
}

Scene Neck() {
  Scene scene;
  scene.head.torso_mass_kg = 30.0;
  scene.head.neck_stiffness_N_per_m = 2e4;
  scene.head.neck_damping_N_s_per_m = 50.0;
  return scene;
}

double Relative(double value, double reference) { return std::abs(value / reference - 1.0); }

/// |a - b| relative to the larger of |b| and `floor` (a gradient entry near zero).
double GradientError(double a, double b, double floor) { return std::abs(a - b) / std::max(std::abs(b), floor); }

}  // namespace

TEST_CASE("auto takes the exact path for the paper's scene and the time path for braking or a neck", "[oracle]") {
  const OracleSelection paper = ChooseOracle(Scene{}, OracleChoice::kAuto);
  CHECK(paper.kind == OracleKind::kExact);
  CHECK(paper.gradient == GradientSource::kAnalytic);
  CHECK_THAT(paper.reason, Catch::Contains("conservative two-mass") && Catch::Contains("energy integral"));

  const OracleSelection braking = ChooseOracle(Braking(), OracleChoice::kAuto);
  CHECK(braking.kind == OracleKind::kTimePath);
  CHECK(braking.gradient == GradientSource::kCentralDifference);
  CHECK_THAT(braking.reason, Catch::Contains("brakes") && Catch::Contains("only the time path"));

  const OracleSelection neck = ChooseOracle(Neck(), OracleChoice::kAuto);
  CHECK(neck.kind == OracleKind::kTimePath);
  CHECK_THAT(neck.reason, Catch::Contains("neck"));

  Scene damped;  // the exact path answers damping (docs/model.md §10.1), without an analytic gradient
  damped.model.damping_s_per_m = 0.2;
  const OracleSelection damping = ChooseOracle(damped, OracleChoice::kAuto);
  CHECK(damping.kind == OracleKind::kExact);
  CHECK(damping.gradient == GradientSource::kCentralDifference);
  CHECK_THAT(damping.reason, Catch::Contains("damped"));
  CHECK(ChooseOracle(damped, OracleChoice::kTimePath).gradient == GradientSource::kForwardSensitivities);

  const OracleSelection asked = ChooseOracle(Scene{}, OracleChoice::kTimePath);
  CHECK(asked.kind == OracleKind::kTimePath);
  CHECK(asked.gradient == GradientSource::kForwardSensitivities);
  CHECK_THAT(asked.reason, Catch::Contains("as asked"));
}

TEST_CASE("oracle exact is refused on a scene without an energy integral", "[oracle]") {
  CHECK_THROWS_WITH(ChooseOracle(Braking(), OracleChoice::kExact),
                    Catch::Contains("the exact path needs an energy integral") && Catch::Contains("brakes"));
  CHECK_THROWS_WITH(ChooseOracle(Neck(), OracleChoice::kExact), Catch::Contains("neck"));
  DesignOptions options;
  options.oracle.choice = OracleChoice::kExact;
  CHECK_THROWS_AS(FindThinnestSafeCovering(Braking(), {}, options), std::invalid_argument);
  SpeedLimitOptions limits;
  limits.oracle.choice = OracleChoice::kExact;
  CHECK_THROWS_AS(MaxSafeSpeed(Neck(), limits), std::invalid_argument);
}

TEST_CASE("the time-path oracle's options are checked, naming the field", "[oracle]") {
  TimeIntegrationOptions bad;
  bad.relative_tolerance = 0.0;
  CHECK_THROWS_WITH(TimePathOracle(Scene{}, 0.25, {}, bad), Catch::Contains("oracle.time_path.relative_tolerance"));
  bad = {};
  bad.method = ComputationMethod::kExact;
  CHECK_THROWS_WITH(TimePathOracle(Scene{}, 0.25, {}, bad), Catch::Contains("oracle.time_path.method"));
  CHECK(ParseOracleChoice("time-path") == OracleChoice::kTimePath);
  CHECK_FALSE(ParseOracleChoice("foo").has_value());
}

TEST_CASE("the time-path oracle scores and differentiates like the exact one, to its tolerance", "[oracle]") {
  for (const double rtol : {1e-6, 1e-8, 1e-10}) {
    TimeIntegrationOptions time;
    time.relative_tolerance = rtol;
    const ExactPathOracle exact(Scene{}, 0.25);
    const TimePathOracle integrated(Scene{}, 0.25, {}, time);
    for (const CoveringDesign design : {CoveringDesign{16.11e6, 0.0150585}, CoveringDesign{27.6e6, 0.015},
                                        CoveringDesign{200e6, 0.002}, CoveringDesign{1e6, 0.04}}) {
      RatioGradient g_exact, g_time;
      const DesignScore a = exact.Score(design, g_exact);
      const DesignScore b = integrated.Score(design, g_time);
      INFO("rtol " << rtol << ", E_c " << design.youngs_modulus_Pa << " Pa, b_c " << design.thickness_m << " m");
      REQUIRE_FALSE(b.failed);
      // The peaks' global error stays within ~10 rtol (docs/numerics.md); the gradient's
      // within 40 rtol (tests/core/test_time_path_sensitivity.cpp).
      CHECK(Relative(b.laceration_ratio, a.laceration_ratio) <= 100 * rtol);
      CHECK(Relative(b.contusion_ratio, a.contusion_ratio) <= 100 * rtol);
      CHECK(Relative(b.compression_ratio, a.compression_ratio) <= 100 * rtol);
      CHECK(b.peaks.fully_compressed == a.peaks.fully_compressed);
      for (int i = 0; i < 2; ++i) {
        const double per = i == 0 ? 1.0 : design.thickness_m;  // to d/d ln b_c
        CHECK(GradientError(g_time.laceration[i] * per, g_exact.laceration[i] * per, a.laceration_ratio) <= 100 * rtol);
        CHECK(GradientError(g_time.contusion[i] * per, g_exact.contusion[i] * per, a.contusion_ratio) <= 100 * rtol);
        CHECK(GradientError(g_time.compression[i] * per, g_exact.compression[i] * per, a.compression_ratio) <=
              100 * rtol);
      }
    }
    CHECK(integrated.Report().gradient == GradientSource::kForwardSensitivities);
    CHECK(integrated.Report().gradient_evaluations == 4);
    CHECK(integrated.failed_evaluations() == 0);
  }
}

TEST_CASE("the central-difference gradient of a braking scene is checked by two steps", "[oracle]") {
  // Braking that starts long after the contact has ended changes nothing: the time path's
  // central difference must then reproduce the exact path's analytic gradient.
  TimeIntegrationOptions time;
  time.relative_tolerance = 1e-10;
  const Scene late = Braking(/*delay_s=*/1.0);
  const TimePathOracle integrated(late, 0.25, {}, time);
  REQUIRE(integrated.Report().gradient == GradientSource::kCentralDifference);
  const ExactPathOracle exact(Scene{}, 0.25);
  // The optimum (δ_max 2e-5 below t2): the points on one side bottom out, so the difference
  // there is one-sided from the other (a central one straddling the kink was off by 77 % in
  // dσ/db_c).
  for (const CoveringDesign design :
       {CoveringDesign{27.6e6, 0.015}, CoveringDesign{5e6, 0.03}, CoveringDesign{16.11e6, 0.0150585}}) {
    RatioGradient g_exact, g_time;
    const DesignScore a = exact.Score(design, g_exact);
    const DesignScore b = integrated.Score(design, g_time);
    REQUIRE_FALSE(b.failed);
    INFO("E_c " << design.youngs_modulus_Pa << " Pa, b_c " << design.thickness_m << " m");
    for (int i = 0; i < 2; ++i) {
      const double per = i == 0 ? 1.0 : design.thickness_m;
      // Step cbrt(10 rtol) ~ 1e-3: truncation ~1e-6, noise ~1e-9 / 1e-3.
      CHECK(GradientError(g_time.laceration[i] * per, g_exact.laceration[i] * per, a.laceration_ratio) <= 1e-4);
      CHECK(GradientError(g_time.contusion[i] * per, g_exact.contusion[i] * per, a.contusion_ratio) <= 1e-4);
      CHECK(GradientError(g_time.compression[i] * per, g_exact.compression[i] * per, a.compression_ratio) <= 1e-4);
    }
  }
  const OracleReport report = integrated.Report();
  CHECK(report.gradient_step_disagreement > 0.0);
  CHECK(report.gradient_step_disagreement < 1e-2);
  CHECK(report.evaluations == 3 * (1 + 8));  // each gradient: the point, then steps h and 2h both ways
}

TEST_CASE("the thinnest safe covering on the time path reproduces the exact path's optimum", "[oracle][design]") {
  // The paper's optimum: 15.0585 mm at 16.11 MPa, where contusion and full compression bind
  // together; b_c* is sharp, E_c* flat (defined to ~1e-3). Measured at rtol 1e-8 (ERK 5(4)):
  // b_c* within ~1e-8 relative of the exact path's; asserted within 1e-6.
  const ThinnestSafeCovering exact = FindThinnestSafeCovering(Scene{}, {}, {});
  REQUIRE(exact.continuous.feasible);
  REQUIRE(exact.oracle.kind == OracleKind::kExact);
  DesignOptions options;
  options.oracle.choice = OracleChoice::kTimePath;
  options.oracle.time_path.relative_tolerance = 1e-8;
  const ThinnestSafeCovering time = FindThinnestSafeCovering(Scene{}, {}, options);
  REQUIRE(time.continuous.feasible);
  CHECK(time.oracle.kind == OracleKind::kTimePath);
  CHECK(time.oracle.failed_evaluations == 0);
  CHECK(time.oracle.evaluations == time.evaluations);
  CHECK(Relative(time.continuous.score.design.thickness_m, exact.continuous.score.design.thickness_m) <= 1e-6);
  CHECK(Relative(time.continuous.score.design.youngs_modulus_Pa, exact.continuous.score.design.youngs_modulus_Pa) <=
        2e-2);
  CHECK(exact.continuous.score.design.thickness_m == Approx(0.0150585).epsilon(1e-4));
}

TEST_CASE("a looser tolerance moves the time-path optimum further, as its tolerance predicts", "[oracle][design]") {
  DesignWorkPrecisionOptions options;
  options.methods = {ComputationMethod::kArkodeErk54};
  options.relative_tolerances = {1e-4, 1e-9};
  options.design.local_polish = false;  // the bracket alone: its error is the oracle's
  const DesignWorkPrecisionResult study = MeasureDesignWorkPrecision(Scene{}, options);
  REQUIRE(study.IsUsable());
  REQUIRE(study.points.size() == 3);
  const DesignWorkPrecisionPoint& loose = study.points[1];
  const DesignWorkPrecisionPoint& tight = study.points[2];
  INFO(study.message);
  CHECK(loose.error_thickness <= 100 * 1e-4);
  CHECK(tight.error_thickness <= 100 * 1e-9);
  CHECK(tight.error_thickness < loose.error_thickness);
  CHECK(tight.evaluations > 0);
  CHECK(tight.seconds > 0.0);
}

TEST_CASE("a failed time-path evaluation is counted and never an answer", "[oracle]") {
  TimeIntegrationOptions starved;
  starved.max_steps = 10;  // no impact fits in 10 steps
  const TimePathOracle oracle(Scene{}, 0.25, {}, starved);
  const DesignScore score = oracle.Score({27.6e6, 0.015});
  CHECK(score.failed);
  CHECK(std::isinf(score.worst_ratio()));
  CHECK_FALSE(score.admissible(1.0, DesignCriterion::kPaper));
  CHECK(oracle.failed_evaluations() == 1);
  CHECK_THAT(oracle.Report().first_failure, Catch::Contains("step"));

  DesignRequest request;
  request.options.oracle.choice = OracleChoice::kTimePath;
  request.options.oracle.time_path.max_steps = 10;
  request.options.global_evaluations = 20;
  request.options.bracket_thickness_points = 4;
  request.options.modulus_points_per_decade = 2;
  request.options.local_polish = false;
  const DesignResult result = Design(request);
  CHECK(result.status == DesignStatus::kOracleFailed);
  CHECK_FALSE(result.ok());
  CHECK(result.oracle.failed_evaluations == result.oracle.evaluations);
  CHECK_THAT(result.message, Catch::Contains("failed"));
}

TEST_CASE("the speed limit of a braking robot is bracketed on the time path and agrees with a scan",
          "[oracle][speed-limit]") {
  const Scene scene = Braking(/*delay_s=*/0.002, /*braking=*/200.0);
  const SpeedLimit limit = MaxSafeSpeed(scene, {});
  CHECK(limit.oracle.kind == OracleKind::kTimePath);
  CHECK_THAT(limit.oracle.reason, Catch::Contains("brakes"));
  CHECK(limit.oracle.evaluations > 10);
  REQUIRE(limit.status == SpeedLimitStatus::kLimited);
  const double v = limit.max_safe_speed_m_per_s;
  // A brute-force scan: every speed below the limit is safe, just above it is not; the
  // ratios rise with the speed on the way (the monotonicity the bisection relies on).
  SpeedLimitOptions options;
  double previous_worst = 0.0;
  for (int k = 1; k <= 60; ++k) {
    Scene probe = scene;
    probe.robot.speed_m_per_s = v * k / 60.0;
    const ImpactJudgement at = JudgeImpact(probe, options);
    INFO("speed " << probe.robot.speed_m_per_s << " m/s");
    CHECK(at.admissible);
    const double worst = std::max(at.ratios.laceration_ratio, at.ratios.contusion_ratio);
    CHECK(worst >= previous_worst);
    previous_worst = worst;
  }
  Scene above = scene;
  above.robot.speed_m_per_s = v * (1 + 1e-6);
  CHECK_FALSE(JudgeImpact(above, options).admissible);
}

TEST_CASE("the speed limit of a damped contact is bracketed on the exact path", "[oracle][speed-limit]") {
  // Damping keeps the exact path, but neither are the peaks functions of δ_max alone nor δ_max
  // of ½ μ v0²: no δ axis, a bisection on the exact path's judgements instead.
  Scene damped;
  damped.model.damping_s_per_m = 0.5;
  const SpeedLimit limit = MaxSafeSpeed(damped, {});
  CHECK(limit.oracle.kind == OracleKind::kExact);
  CHECK(limit.bracketed);
  REQUIRE(limit.status == SpeedLimitStatus::kLimited);
  const double v = limit.max_safe_speed_m_per_s;
  for (int k = 1; k <= 40; ++k) {
    Scene probe = damped;
    probe.robot.speed_m_per_s = v * k / 40.0;
    INFO("speed " << probe.robot.speed_m_per_s << " m/s");
    CHECK(JudgeImpact(probe, {}).admissible);
  }
  Scene above = damped;
  above.robot.speed_m_per_s = v * (1 + 1e-6);
  CHECK_FALSE(JudgeImpact(above, {}).admissible);
  CHECK_FALSE(MaxSafeSpeed(Scene{}, {}).bracketed);  // the conservative scene: the δ axis
}

TEST_CASE("braking that starts after the contact gives the exact path's speed limit", "[oracle][speed-limit]") {
  SpeedLimitOptions options;
  options.oracle.time_path.relative_tolerance = 1e-10;
  const SpeedLimit exact = MaxSafeSpeed(Scene{}, options);
  const SpeedLimit late = MaxSafeSpeed(Braking(/*delay_s=*/1.0), options);
  CHECK(exact.oracle.kind == OracleKind::kExact);
  CHECK(late.oracle.kind == OracleKind::kTimePath);
  REQUIRE(late.status == SpeedLimitStatus::kLimited);
  CHECK(late.limited_by == exact.limited_by);
  CHECK(Relative(late.max_safe_speed_m_per_s, exact.max_safe_speed_m_per_s) <= 1e-7);
  const MassLimit exact_mass = MaxSafeMass(Scene{}, options);
  const MassLimit late_mass = MaxSafeMass(Braking(/*delay_s=*/1.0), options);
  REQUIRE(late_mass.status == exact_mass.status);
  if (exact_mass.status == SpeedLimitStatus::kLimited) {
    CHECK(Relative(late_mass.max_safe_mass_kg, exact_mass.max_safe_mass_kg) <= 1e-7);
  }
}

TEST_CASE("a sweep solves the points without an energy integral on the time path", "[oracle][sweep]") {
  SweepSpec spec;
  spec.scene = Braking(0.0, 0.0);  // braking on the y axis: 0 (exact path) and 100 m/s²
  spec.x = {"speed", {1.0, 2.0}};
  spec.y = SweepAxis{"braking", {0.0, 100.0}};
  std::vector<SweepRow> rows;
  const SweepResult result = Sweep(spec, {}, [&](std::span<const SweepRow> block) {
    rows.insert(rows.end(), block.begin(), block.end());
  });
  REQUIRE(rows.size() == 4);
  CHECK(result.time_path_rows == 2);
  for (const SweepRow& row : rows) {
    INFO("speed " << row.x << ", braking " << row.y);
    CHECK(row.valid);
    CHECK((row.method == ComputationMethod::kExact) == (row.y == 0.0));
  }
  CHECK_THAT(result.BriefReport(), Catch::Contains("2 on the time path"));
}

TEST_CASE("a strong brake with no delay raises the speed limit above the unbraked one, as a scan shows",
          "[oracle][speed-limit]") {
  // 200 m/s² from first contact: at very low speeds the robot stops after v0²/(2a) and the tiny
  // contact unloads slowly; every evaluation must still end in a separation, from 1e-6 m/s up.
  const Scene scene = Braking(/*delay_s=*/0.0, /*braking=*/200.0);
  const SpeedLimit unbraked = MaxSafeSpeed(Scene{}, {});
  REQUIRE(unbraked.status == SpeedLimitStatus::kLimited);
  CHECK(unbraked.max_safe_speed_m_per_s == Approx(1.775).epsilon(1e-3));
  const SpeedLimit limit = MaxSafeSpeed(scene, {});
  INFO(limit.message);
  REQUIRE(limit.status == SpeedLimitStatus::kLimited);
  CHECK(limit.oracle.failed_evaluations == 0);
  const double v = limit.max_safe_speed_m_per_s;
  CHECK(v > unbraked.max_safe_speed_m_per_s);
  // Brute force on the time path: 100 speeds per decade upward from 1e-6 m/s; all admissible
  // below the first inadmissible one, and the limit between it and its predecessor.
  double last_safe = 0.0;
  double first_unsafe = 0.0;
  for (int k = 0; k <= 800; ++k) {
    Scene probe = scene;
    probe.robot.speed_m_per_s = 1e-6 * std::pow(10.0, k / 100.0);
    const ImpactJudgement at = JudgeImpact(probe, {});
    INFO("speed " << probe.robot.speed_m_per_s << " m/s");
    REQUIRE_FALSE(at.failed);
    if (!at.admissible) {
      first_unsafe = probe.robot.speed_m_per_s;
      break;
    }
    last_safe = probe.robot.speed_m_per_s;
  }
  REQUIRE(first_unsafe > 0.0);
  CHECK(last_safe <= v);
  CHECK(v < first_unsafe);
}

TEST_CASE("a failed evaluation ends the speed-limit search with its status, never read as unsafe",
          "[oracle][speed-limit][failure]") {
  SpeedLimitOptions options;
  options.oracle.time_path.max_steps = 10;  // the smallest allowed: too few to separate
  const SpeedLimit limit = MaxSafeSpeed(Braking(/*delay_s=*/0.0, /*braking=*/200.0), options);
  CHECK(limit.status == SpeedLimitStatus::kEvaluationFailed);
  CHECK(std::string(ToString(limit.status)) == "evaluation-failed");
  CHECK(limit.max_safe_speed_m_per_s == 0.0);
  CHECK(limit.limited_by == LimitingCriterion::kNone);
  CHECK(limit.oracle.evaluations == 1);  // the search stops at the first failure
  CHECK(limit.oracle.failed_evaluations == 1);
  CHECK_THAT(limit.message, Catch::Contains("the oracle failed at 1e-06 m/s"));
  CHECK_THAT(limit.message, Catch::Contains("step-limit"));
  const MassLimit mass = MaxSafeMass(Braking(/*delay_s=*/0.0, /*braking=*/200.0), options);
  CHECK(mass.status == SpeedLimitStatus::kEvaluationFailed);
  CHECK_THAT(mass.message, Catch::Contains("the oracle failed at"));
}
