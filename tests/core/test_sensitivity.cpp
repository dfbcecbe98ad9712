// Analytic design derivatives of the exact peaks match central finite differences, in every
// phase the peak can lie in (covering on scalp, on bone, robot on bone), for curved and flat
// robots and for both threshold readings, also where the literal reading's maximum lies at a
// switch before δ_max.
#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

#include "test_helpers.hpp"

using namespace covopt;
using covopt::test::PaperScene;

namespace {

ImpactPeaks PeaksAt(Scene scene, double modulus, double thickness) {
  scene.covering.youngs_modulus_Pa = modulus;
  scene.covering.thickness_m = thickness;
  return ExactPeaks(ImpactModel::FromScene(scene));
}

void CheckAgainstFiniteDifferences(const Scene& scene, const std::string& name) {
  const double modulus = scene.covering.youngs_modulus_Pa;
  const double thickness = scene.covering.thickness_m;
  const ImpactModel model = ImpactModel::FromScene(scene);
  const ImpactPeaks peaks = ExactPeaks(model);
  const PeakSensitivities analytic = ExactPeakSensitivities(model, peaks);
  const double h_e = modulus * 1e-6;
  const double h_b = thickness * 1e-6;
  const ImpactPeaks e_up = PeaksAt(scene, modulus + h_e, thickness);
  const ImpactPeaks e_down = PeaksAt(scene, modulus - h_e, thickness);
  const ImpactPeaks b_up = PeaksAt(scene, modulus, thickness + h_b);
  const ImpactPeaks b_down = PeaksAt(scene, modulus, thickness - h_b);
  auto check = [&](const char* what, double derivative, double up, double down, double h,
                   double scale) {
    const double numeric = (up - down) / (2 * h);
    INFO(name << ", " << what << ": analytic " << derivative << ", finite difference " << numeric);
    CHECK(std::abs(derivative - numeric) <= 1e-5 * std::abs(numeric) + 1e-9 * scale);
  };
  const PeakDerivatives& de = analytic.per_covering_modulus;
  const PeakDerivatives& db = analytic.per_covering_thickness;
  check("dδ/dE", de.max_penetration, e_up.max_penetration_m, e_down.max_penetration_m, h_e,
        peaks.max_penetration_m / modulus);
  check("dF/dE", de.peak_force, e_up.peak_force_N, e_down.peak_force_N, h_e, peaks.peak_force_N / modulus);
  check("dσ/dE", de.max_compressive_stress, e_up.max_compressive_stress_Pa,
        e_down.max_compressive_stress_Pa, h_e, peaks.max_compressive_stress_Pa / modulus);
  check("de/dE", de.max_energy_density, e_up.max_energy_density_J_per_m2,
        e_down.max_energy_density_J_per_m2, h_e, peaks.max_energy_density_J_per_m2 / modulus);
  check("dδ/db", db.max_penetration, b_up.max_penetration_m, b_down.max_penetration_m, h_b,
        peaks.max_penetration_m / thickness);
  check("dF/db", db.peak_force, b_up.peak_force_N, b_down.peak_force_N, h_b, peaks.peak_force_N / thickness);
  check("dσ/db", db.max_compressive_stress, b_up.max_compressive_stress_Pa,
        b_down.max_compressive_stress_Pa, h_b, peaks.max_compressive_stress_Pa / thickness);
  check("dσt/db", db.max_tensile_stress, b_up.max_tensile_stress_Pa, b_down.max_tensile_stress_Pa,
        h_b, peaks.max_tensile_stress_Pa / thickness);
  check("de/db", db.max_energy_density, b_up.max_energy_density_J_per_m2,
        b_down.max_energy_density_J_per_m2, h_b, peaks.max_energy_density_J_per_m2 / thickness);
}

}  // namespace

TEST_CASE("Design derivatives match finite differences in every phase", "[sensitivity]") {
  CheckAgainstFiniteDifferences(PaperScene(0.015, 27.6e6, 0.22), "peak in phase 2");
  CheckAgainstFiniteDifferences(PaperScene(0.005, 27.6e6, 0.22), "peak in phase 3");
  Scene slow = PaperScene(0.015, 27.6e6, 0.22);
  slow.robot.speed_m_per_s = 0.1;
  CheckAgainstFiniteDifferences(slow, "peak in phase 1");
  CheckAgainstFiniteDifferences(PaperScene(0.02, 1e9, 0.25), "stiff covering");
  CheckAgainstFiniteDifferences(PaperScene(0.03, 0.5e6, 0.25), "soft covering, bottomed out");
  Scene flat = PaperScene(0.01, 10e6, 0.25);
  flat.robot.radius_m = kFlat;
  CheckAgainstFiniteDifferences(flat, "flat robot");
  Scene literal = PaperScene(0.015, 27.6e6, 0.22);
  literal.model.thresholds = ThresholdReading::kLiteral;
  literal.covering.thickness_m = 0.006;
  CheckAgainstFiniteDifferences(literal, "literal thresholds");
  literal.covering.thickness_m = 0.002;
  CheckAgainstFiniteDifferences(literal, "literal thresholds, ill-ordered");
  // F_max at t1, before the drop: its derivative is phase 1's at t1.
  Scene drop = PaperScene(0.0065, 100e6, 0.25);
  drop.scalp.thickness_m = 0.010;
  drop.robot.speed_m_per_s = 1.5;
  drop.model.thresholds = ThresholdReading::kLiteral;
  const ImpactModel drop_model = ImpactModel::FromScene(drop);
  const ImpactPeaks drop_peaks = ExactPeaks(drop_model);
  REQUIRE(drop_peaks.peak_force_N > drop_model.StateAt(drop_peaks.max_penetration_m).force_N);
  CheckAgainstFiniteDifferences(drop, "literal thresholds, force maximum before the drop");
  // σ_c,max at t1 too: no covering is not differentiable in the design, so a 2.8 mm covering
  // (0.8 b_c = 2.24 mm just below t1 = 2.4 mm: F and σ drop at t1) just past its drop.
  Scene stress_drop = PaperScene(0.0028, 27.6e6, 0.25);
  stress_drop.model.thresholds = ThresholdReading::kLiteral;
  {  // the speed that takes δ_max to 1.05 t1: U(δ) = ½ m v²
    const ImpactModel model = ImpactModel::FromScene(stress_drop);
    stress_drop.robot.speed_m_per_s = std::sqrt(
        2.0 * model.StateAt(1.05 * 0.0024).potential_energy_J / model.effective_mass_kg());
  }
  const ImpactModel stress_model = ImpactModel::FromScene(stress_drop);
  const ImpactPeaks stress_peaks = ExactPeaks(stress_model);
  REQUIRE(stress_peaks.max_compressive_stress_Pa >
          stress_model.StateAt(stress_peaks.max_penetration_m).compressive_stress_Pa);
  CheckAgainstFiniteDifferences(stress_drop, "literal thresholds, stress maximum before the drop");
}

TEST_CASE("Design derivatives need a covering", "[sensitivity]") {
  const ImpactModel bare = ImpactModel::FromScene(PaperScene(0.0));
  CHECK_THROWS_AS(ExactPeakSensitivities(bare, ExactPeaks(bare)), std::invalid_argument);
}
