// The force law of docs/model.md §2: the check numbers of its §8, continuity at the phase
// switches, U' = F and e' = σ (the integrals really are integrals), the phase structure a scene
// needs (two phases without a covering), the literal-threshold reading, and the
// cancellation-free energy difference.
#include <catch2/catch.hpp>

#include "test_helpers.hpp"

using namespace covopt;
using covopt::test::PaperScene;
using covopt::test::RelativeError;

TEST_CASE("docs/model.md check numbers: no covering", "[law]") {
  const ImpactModel model = ImpactModel::FromScene(PaperScene(0.0));
  CHECK(model.effective_mass_kg() == Approx(3.103448).epsilon(1e-6));
  REQUIRE(model.segment_count() == 2);
  CHECK(model.segment(0).phase == Phase::kRobotOnScalp);
  CHECK(model.segment(1).phase == Phase::kRobotOnBone);
  CHECK(model.segment(0).stiffness == Approx(3.037758e6).epsilon(1e-6));
  CHECK(model.segment(1).stiffness == Approx(9.372328e8).epsilon(1e-6));
  const ContactState at_t1 = model.StateAt(0.0024);
  CHECK(at_t1.force_N == Approx(144.5113).epsilon(1e-6));
  CHECK(at_t1.potential_energy_J == Approx(0.1308781).epsilon(1e-6));
  CHECK(at_t1.compressive_stress_Pa == Approx(2.276011e6).epsilon(1e-6));
  CHECK(at_t1.energy_density_J_per_m2 == Approx(3310.561).epsilon(1e-6));
}

TEST_CASE("docs/model.md check numbers: 15 mm, 27.6 MPa, nu 0.22 covering", "[law]") {
  const ImpactModel model = ImpactModel::FromScene(PaperScene(0.015, 27.6e6, 0.22));
  REQUIRE(model.segment_count() == 3);
  CHECK(model.segment(0).stiffness == Approx(2.350318e6).epsilon(1e-6));
  CHECK(model.segment(1).stiffness == Approx(5.658057e6).epsilon(1e-6));
  CHECK(model.segment(2).start_m == Approx(0.0144).epsilon(1e-12));
  const ContactState at_t2 = model.StateAt(0.0144);
  CHECK(at_t2.force_N == Approx(2085.111).epsilon(1e-6));
  CHECK(at_t2.compressive_stress_Pa == Approx(4.656350e6).epsilon(1e-6));
  CHECK(at_t2.energy_density_J_per_m2 == Approx(37962.57).epsilon(1e-6));
}

TEST_CASE("F, U, sigma and e are continuous and non-decreasing across the switches", "[law]") {
  const double thickness = GENERATE(0.0, 0.002, 0.015, 0.04);
  const ImpactModel model = ImpactModel::FromScene(PaperScene(thickness, 10e6, 0.3));
  for (std::size_t i = 1; i < model.segment_count(); ++i) {
    const double t = model.segment(i).start_m;
    const ContactState below = model.StateInSegment(i - 1, t);
    const ContactState above = model.StateInSegment(i, t);
    CHECK(above.force_N == Approx(below.force_N).epsilon(1e-14));
    CHECK(above.potential_energy_J == Approx(below.potential_energy_J).epsilon(1e-14));
    CHECK(above.compressive_stress_Pa == Approx(below.compressive_stress_Pa).epsilon(1e-14));
    CHECK(above.energy_density_J_per_m2 == Approx(below.energy_density_J_per_m2).epsilon(1e-14));
  }
  ContactState previous = model.StateAt(0.0);
  for (int k = 1; k <= 400; ++k) {
    const ContactState state = model.StateAt(0.05 * k / 400.0);
    CHECK(state.force_N >= previous.force_N);
    CHECK(state.compressive_stress_Pa >= previous.compressive_stress_Pa);
    CHECK(state.potential_energy_J > previous.potential_energy_J);
    previous = state;
  }
}

TEST_CASE("U is the integral of F and e the integral of sigma", "[law]") {
  const ImpactModel model = ImpactModel::FromScene(PaperScene(0.015, 27.6e6, 0.22));
  // Central differences away from the switches (2.4 mm, 14.4 mm).
  for (double delta : {0.001, 0.005, 0.010, 0.018}) {
    const double h = 1e-7;
    const ContactState up = model.StateAt(delta + h);
    const ContactState down = model.StateAt(delta - h);
    const ContactState here = model.StateAt(delta);
    CHECK((up.potential_energy_J - down.potential_energy_J) / (2 * h) ==
          Approx(here.force_N).epsilon(1e-6));
    CHECK((up.energy_density_J_per_m2 - down.energy_density_J_per_m2) / (2 * h) ==
          Approx(here.compressive_stress_Pa).epsilon(1e-6));
    CHECK((up.force_N - down.force_N) / (2 * h) == Approx(here.stiffness_N_per_m).epsilon(1e-5));
  }
}

TEST_CASE("A fixed head, a fixed robot and a flat robot change only 1/m and 1/R", "[law]") {
  Scene flat = PaperScene(0.0);
  flat.robot.radius_m = kFlat;
  const ImpactModel model = ImpactModel::FromScene(flat);
  CHECK(model.segment(0).curvature_per_m == Approx(1.0 / 0.08).epsilon(1e-15));
  CHECK(model.segment(1).curvature_per_m == Approx(1.0 / 0.077).epsilon(1e-15));
  Scene fixed_head = PaperScene(0.0);
  fixed_head.head.mass_kg = kFixed;
  CHECK(ImpactModel::FromScene(fixed_head).effective_mass_kg() == 10.0);
}

TEST_CASE("Literal thresholds put phase 3 at 0.8 b_c and make the force jump when ill-ordered",
          "[law][literal]") {
  Scene scene = PaperScene(0.015, 27.6e6, 0.22);
  scene.model.thresholds = ThresholdReading::kLiteral;
  const ImpactModel literal = ImpactModel::FromScene(scene);
  REQUIRE(literal.segment_count() == 3);
  CHECK(literal.segment(2).start_m == Approx(0.012).epsilon(1e-12));  // 0.8 * 15 mm

  scene.covering.thickness_m = 0.001;  // 0.8 b_c = 0.8 mm < 0.8 b_s = 2.4 mm
  const ImpactModel ill = ImpactModel::FromScene(scene);
  REQUIRE(ill.segment_count() == 2);
  CHECK(ill.segment(1).phase == Phase::kRobotOnBone);
  CHECK(ill.segment(1).start_m == Approx(0.0024));
  CHECK(ill.segment(1).origin_m == Approx(0.0008));
  const double t1 = 0.0024;
  const double below = ill.StateInSegment(0, t1).force_N;
  const double above = ill.StateInSegment(1, t1).force_N;
  CHECK(std::abs(above - below) > 1.0);  // eq. (2) read literally is discontinuous here
  // U stays continuous (it is the integral of F).
  CHECK(ill.StateInSegment(1, t1).potential_energy_J ==
        Approx(ill.StateInSegment(0, t1).potential_energy_J).epsilon(1e-14));

  // No covering (0.8 b_c = 0): phase 3 from t1, measured from 0 (test_literal_reading.cpp).
  Scene bare = PaperScene(0.0);
  bare.model.thresholds = ThresholdReading::kLiteral;
  const ImpactModel bare_literal = ImpactModel::FromScene(bare);
  REQUIRE(bare_literal.segment_count() == 2);
  CHECK(bare_literal.segment(1).start_m == Approx(0.0024));
  CHECK(bare_literal.segment(1).origin_m == 0.0);
}

TEST_CASE("The energy difference stays accurate for tiny gaps", "[law]") {
  const ImpactModel model = ImpactModel::FromScene(PaperScene(0.015, 27.6e6, 0.22));
  const double upper = 0.010;  // in phase 2
  const std::size_t i = model.SegmentIndexAt(upper);
  REQUIRE(i == 1);
  for (double gap : {1e-3, 1e-6, 1e-9, 1e-12}) {
    const double direct = model.EnergyDifferenceInSegment(i, upper, gap);
    // First-order Taylor: F(upper) gap - F'(upper) gap²/2.
    const ContactState s = model.StateAt(upper);
    const double taylor = s.force_N * gap - 0.5 * s.stiffness_N_per_m * gap * gap;
    // The Taylor remainder is ~(gap/x)² relative; rounding must not add more than that.
    if (gap <= 1e-6) CHECK(RelativeError(direct, taylor) < 1e-7);
    if (gap <= 1e-9) CHECK(RelativeError(direct, taylor) < 1e-12);
    CHECK(direct > 0.0);
  }
  CHECK(model.EnergyDifferenceInSegment(i, upper, upper - model.segment(i).start_m) ==
        Approx(model.StateAt(upper).potential_energy_J - model.StateAt(0.0024).potential_energy_J)
            .epsilon(1e-12));
}
