// The damped exact path (Hunt-Crossley contact damping, docs/model.md §10.1): against a
// brute-force fixed-step RK4 integration of the damped δ-ODE written here; the energy stored
// at δ_max and the rebound in closed form; d -> 0 recovering the conservative path; the peak
// force before δ_max against a dense scan of the loading branch; the coefficient of
// restitution's trends; bad input and the scenes the exact path refuses.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "test_helpers.hpp"

using namespace covopt;
using covopt::test::PaperScene;
using covopt::test::RelativeError;
using covopt::test::SetEveryExponent;

namespace {

Scene Damped(Scene scene, double damping_s_per_m, double speed_m_per_s = 2.0) {
  scene.model.damping_s_per_m = damping_s_per_m;
  scene.robot.speed_m_per_s = speed_m_per_s;
  return scene;
}

/// What the brute force measures.
struct BruteForce {
  double max_penetration_m = 0.0;
  double peak_force_N = 0.0;
  double max_compressive_stress_Pa = 0.0;
  double max_energy_density_J_per_m2 = 0.0;
  double time_of_max_compression_s = 0.0;
  double contact_duration_s = 0.0;
  double rebound_speed_m_per_s = 0.0;
};

/// Integrates δ'' = -F_el(δ)(1 + d δ')/m and e' = σ_el(δ)(1 + d δ') δ' with classical RK4 at
/// `steps_per_loading` fixed steps per (conservative) loading time, from first contact to
/// separation. F and σ_c are maximised over the steps of the loading, plus their values where
/// δ crosses a phase switch (v interpolated linearly in δ there); δ_max and e_A come from a
/// Taylor step to v = 0, the separation from linear interpolation to δ = 0.
BruteForce IntegrateDampedImpact(const ImpactModel& model, int steps_per_loading) {
  const double m = model.effective_mass_kg();
  const double d = model.scene().model.damping_s_per_m;
  const double v0 = model.impact_speed_m_per_s();
  Scene conservative_scene = model.scene();
  conservative_scene.model.damping_s_per_m = 0.0;
  const ImpactModel conservative = ImpactModel::FromScene(conservative_scene);
  const double h = 0.5 * ExactContactDuration(conservative, ExactPeaks(conservative)) / steps_per_loading;

  struct State {
    double delta, v, e;
  };
  auto rate = [&](const State& y) {
    const ContactState c = model.StateAt(y.delta);
    const double damping_factor = 1.0 + d * y.v;
    return State{y.v, -c.force_N * damping_factor / m, c.compressive_stress_Pa * damping_factor * y.v};
  };
  auto add = [](const State& y, const State& k, double f) {
    return State{y.delta + f * k.delta, y.v + f * k.v, y.e + f * k.e};
  };
  BruteForce out;
  State y{0.0, v0, 0.0};
  double t = 0.0;
  bool loading = true;
  for (long step = 0; step < 200L * steps_per_loading; ++step) {
    const State k1 = rate(y);
    const State k2 = rate(add(y, k1, 0.5 * h));
    const State k3 = rate(add(y, k2, 0.5 * h));
    const State k4 = rate(add(y, k3, h));
    State next{y.delta + h / 6 * (k1.delta + 2 * k2.delta + 2 * k3.delta + k4.delta),
               y.v + h / 6 * (k1.v + 2 * k2.v + 2 * k3.v + k4.v),
               y.e + h / 6 * (k1.e + 2 * k2.e + 2 * k3.e + k4.e)};
    if (loading) {
      for (std::size_t j = 1; j < model.segment_count(); ++j) {  // switches crossed
        const double t_j = model.segment(j).start_m;
        if (y.delta < t_j && next.delta >= t_j && next.v > 0.0) {
          const double v = y.v + (next.v - y.v) * (t_j - y.delta) / (next.delta - y.delta);
          for (std::size_t side : {j - 1, j}) {
            const ContactState c = model.StateInSegment(side, t_j);
            out.peak_force_N = std::max(out.peak_force_N, c.force_N * (1 + d * v));
            out.max_compressive_stress_Pa =
                std::max(out.max_compressive_stress_Pa, c.compressive_stress_Pa * (1 + d * v));
          }
        }
      }
      if (next.v <= 0.0) {
        // Taylor from y: δ'' = -A, v reaches 0 after v/A.
        const double deceleration = -k1.v;
        const double tau = y.v / deceleration;
        out.max_penetration_m = y.delta + 0.5 * y.v * tau;
        out.max_energy_density_J_per_m2 = y.e + 0.5 * k1.e * tau;
        out.time_of_max_compression_s = t + tau;
        loading = false;
      } else {
        const ContactState c = model.StateAt(next.delta);
        out.peak_force_N = std::max(out.peak_force_N, c.force_N * (1 + d * next.v));
        out.max_compressive_stress_Pa =
            std::max(out.max_compressive_stress_Pa, c.compressive_stress_Pa * (1 + d * next.v));
      }
    }
    if (!loading && next.delta <= 0.0) {
      const double fraction = y.delta / (y.delta - next.delta);
      out.contact_duration_s = t + fraction * h;
      out.rebound_speed_m_per_s = -(y.v + fraction * (next.v - y.v));
      return out;
    }
    y = next;
    t += h;
  }
  FAIL("the brute-force integration did not reach separation");
  return out;
}

/// Loading speed v >= 0 at energy gap G = U(δ_max) - U(δ) [J]: m φ(d v)/d² = G with
/// φ(w) = w - ln(1 + w), by bisection in long double (independent of the library's solver).
double LoadingSpeedByBisection(double gap_J, double mass_kg, double damping_s_per_m, double v0) {
  const long double target = static_cast<long double>(gap_J) * damping_s_per_m * damping_s_per_m / mass_kg;
  long double lower = 0.0L, upper = 2.0L * v0 * damping_s_per_m + 1.0L;  // in w = d v
  for (int i = 0; i < 90; ++i) {
    const long double w = 0.5L * (lower + upper);
    (w - std::log1p(w) < target ? lower : upper) = w;
  }
  return static_cast<double>(0.5L * (lower + upper) / damping_s_per_m);
}

}  // namespace

TEST_CASE("The damped exact path agrees with a brute-force RK4 integration of the damped ODE",
          "[exact][damping]") {
  struct Case {
    const char* name;
    Scene scene;
  };
  const std::vector<Case> cases = {
      {"paper scene, 15 mm covering, d 0.2 s/m", Damped(PaperScene(0.015, 27.6e6, 0.22), 0.2)},
      {"paper scene, 15 mm covering, d 1 s/m, 4 m/s", Damped(PaperScene(0.015, 27.6e6, 0.22), 1.0, 4.0)},
      {"bare robot, d 0.5 s/m", Damped(PaperScene(0.0), 0.5)},
      {"bare robot, d 3 s/m, slow", Damped(PaperScene(0.0), 3.0, 0.4)},
      {"2 mm covering bottoming out, d 0.3 s/m", Damped(PaperScene(0.002, 27.6e6, 0.22), 0.3)},
      {"30 mm soft covering, d 0.1 s/m, 6 m/s", Damped(PaperScene(0.03, 5e6, 0.3), 0.1, 6.0)},
  };
  for (const Case& c : cases) {
    const ImpactModel model = ImpactModel::FromScene(c.scene);
    const ImpactResult exact = SolveExact(model);
    const BruteForce brute = IntegrateDampedImpact(model, 100000);
    INFO(c.name);
    const ImpactPeaks& p = exact.peaks;
    CHECK(RelativeError(p.max_penetration_m, brute.max_penetration_m) < 1e-6);
    CHECK(RelativeError(p.peak_force_N, brute.peak_force_N) < 1e-6);
    CHECK(RelativeError(p.max_compressive_stress_Pa, brute.max_compressive_stress_Pa) < 1e-6);
    CHECK(RelativeError(p.max_energy_density_J_per_m2, brute.max_energy_density_J_per_m2) < 1e-6);
    CHECK(RelativeError(*exact.contact_duration_s, brute.contact_duration_s) < 1e-6);
    CHECK(RelativeError(*exact.time_of_max_compression_s, brute.time_of_max_compression_s) < 1e-6);
    CHECK(RelativeError(*exact.rebound_speed_m_per_s, brute.rebound_speed_m_per_s) < 1e-6);
    CHECK(*exact.coefficient_of_restitution == *exact.rebound_speed_m_per_s / c.scene.robot.speed_m_per_s);
    CHECK(p.max_tensile_stress_Pa == model.TensileFromCompressive(p.max_compressive_stress_Pa));
  }
}

TEST_CASE("The brute-force reference is sharp enough for a 1e-6 bar", "[exact][damping]") {
  // Two step sizes agree far below the bar.
  const ImpactModel model = ImpactModel::FromScene(Damped(PaperScene(0.015, 27.6e6, 0.22), 0.5));
  const BruteForce fine = IntegrateDampedImpact(model, 100000);
  const BruteForce coarse = IntegrateDampedImpact(model, 50000);
  CHECK(RelativeError(coarse.peak_force_N, fine.peak_force_N) < 1e-8);
  CHECK(RelativeError(coarse.max_energy_density_J_per_m2, fine.max_energy_density_J_per_m2) < 1e-8);
  CHECK(RelativeError(coarse.contact_duration_s, fine.contact_duration_s) < 1e-8);
  // and a 1e-5 change of the damping moves the peaks by more than the bar.
  const ImpactPeaks exact = ExactPeaks(model);
  const ImpactPeaks nudged =
      ExactPeaks(ImpactModel::FromScene(Damped(PaperScene(0.015, 27.6e6, 0.22), 0.5 * (1 + 1e-4))));
  CHECK(RelativeError(nudged.peak_force_N, exact.peak_force_N) > 1e-6);
}

TEST_CASE("The energy stored at delta_max is m (v0/d - ln(1 + d v0)/d^2)", "[exact][damping]") {
  const double exponent = GENERATE(1.0, 1.65, 3.0);
  const ThresholdReading reading = GENERATE(ThresholdReading::kCumulative, ThresholdReading::kLiteral);
  const double thickness = GENERATE(0.0, 0.002, 0.015);
  const double damping = GENERATE(1e-3, 0.2, 5.0);
  const double speed = GENERATE(0.3, 2.0, 7.0);
  Scene scene = Damped(PaperScene(thickness, 27.6e6, 0.25), damping, speed);
  scene.model.thresholds = reading;
  SetEveryExponent(scene, exponent);
  const ImpactModel model = ImpactModel::FromScene(scene);
  const ImpactPeaks peaks = ExactPeaks(model);
  const long double w0 = static_cast<long double>(damping) * speed;
  const long double stored = model.effective_mass_kg() * (w0 - std::log1p(w0)) / (static_cast<long double>(damping) * damping);
  CAPTURE(exponent, reading == ThresholdReading::kLiteral, thickness, damping, speed);
  CHECK(RelativeError(model.StateAt(peaks.max_penetration_m).potential_energy_J, static_cast<double>(stored)) < 1e-12);
  CHECK(peaks.max_penetration_m < ExactPeaks(ImpactModel::FromScene(Damped(scene, 0.0, speed))).max_penetration_m);
}

TEST_CASE("A linear spring stores the damped energy in closed form", "[exact][damping]") {
  // One phase with n = 1: U = K δ²/2, so δ_max = sqrt(2 m (w0 - ln(1 + w0)) / (K d²)).
  Scene scene = Damped(PaperScene(0.0), 0.8, 0.1);
  scene.model.exponent_covering_scalp = 1.0;
  const ImpactModel model = ImpactModel::FromScene(scene);
  const ImpactPeaks peaks = ExactPeaks(model);
  REQUIRE(peaks.phase_at_max == Phase::kRobotOnScalp);
  const double w0 = 0.08;
  const double stored = model.effective_mass_kg() * (w0 - std::log1p(w0)) / (0.8 * 0.8);
  CHECK(RelativeError(peaks.max_penetration_m, std::sqrt(2 * stored / model.segment(0).stiffness)) < 1e-13);
  // σ_el is constant in a linear phase, so σ_c = σ_el (1 + d v) is largest at first contact.
  const double kc = 3 / (2 * std::numbers::pi) * model.segment(0).stiffness * model.segment(0).curvature_per_m;
  CHECK(RelativeError(peaks.max_compressive_stress_Pa, kc * (1 + w0)) < 1e-14);
}

TEST_CASE("The coefficient of restitution depends on d v0 alone and solves phi(-e w0) = phi(w0)",
          "[exact][damping]") {
  // On the unloading m φ(d v)/d² = U(δ_max) = m φ(d v0)/d²: the rebound w_r = -e w0 solves
  // φ(w_r) = φ(w0) whatever the force law and the masses.
  const double w0 = GENERATE(1e-4, 1e-3, 0.01, 0.4, 2.0, 30.0);
  std::vector<double> restitution;
  for (const auto& [thickness, exponent, speed, head] :
       std::vector<std::tuple<double, double, double, double>>{
           {0.0, 1.65, 2.0, 4.5}, {0.015, 1.65, 0.5, 4.5}, {0.002, 1.0, 5.0, kFixed}, {0.03, 4.0, 1.0, 2.0}}) {
    Scene scene = Damped(PaperScene(thickness, 27.6e6, 0.25), w0 / speed, speed);
    scene.model.exponent_covering_scalp = exponent;
    scene.head.mass_kg = head;
    const ImpactResult result = SolveExact(ImpactModel::FromScene(scene));
    restitution.push_back(*result.coefficient_of_restitution);
  }
  CAPTURE(w0);
  for (double e : restitution) CHECK(RelativeError(e, restitution.front()) < 1e-13);
  // The rebound solves φ(w_r) = φ(w0), -1 < w_r < 0: with 1 + w_r = exp(z), exp(z) - z = 1 + φ(w0),
  // by bisection in long double (well conditioned in z also where w_r is close to -1; for
  // w0 < 0.01 the series e = 1 - 2/3 w0 + 4/9 w0² - 0.3256 w0³ + ... instead).
  const long double w = w0;
  const long double phi0 = w - std::log1p(w);
  long double lower = -phi0 - 2.0L, upper = 0.0L;
  for (int i = 0; i < 200; ++i) {
    const long double z = 0.5L * (lower + upper);
    (std::exp(z) - z > 1.0L + phi0 ? lower : upper) = z;
  }
  const long double reference = -std::expm1(0.5L * (lower + upper)) / w;
  const double e = restitution.front();
  if (w0 >= 0.01) CHECK(RelativeError(e, static_cast<double>(reference)) < 1e-13);
  if (w0 < 0.01) CHECK(std::abs(e - (1 - 2 * w0 / 3 + 4 * w0 * w0 / 9)) < 0.34 * w0 * w0 * w0);
  CHECK(e < 1.0);
}

TEST_CASE("The coefficient of restitution falls with the damping and with the impact speed",
          "[exact][damping]") {
  const Scene base = PaperScene(0.015, 27.6e6, 0.22);
  std::vector<double> speeds = {0.2, 0.5, 1.0, 2.0, 4.0, 8.0};
  std::vector<double> dampings = {0.01, 0.05, 0.1, 0.2, 0.5, 1.0, 3.0};
  std::vector<std::vector<double>> grid;
  for (double d : dampings) {
    grid.emplace_back();
    for (double v : speeds) {
      const ImpactResult r = SolveExact(ImpactModel::FromScene(Damped(base, d, v)));
      grid.back().push_back(*r.coefficient_of_restitution);
      CHECK(*r.coefficient_of_restitution > 0.0);
      CHECK(*r.coefficient_of_restitution < 1.0);
      // The unloading is slower than the loading: less energy to return.
      CHECK(*r.time_of_max_compression_s < 0.5 * *r.contact_duration_s);
    }
  }
  for (std::size_t i = 0; i < dampings.size(); ++i) {
    for (std::size_t j = 0; j < speeds.size(); ++j) {
      CAPTURE(dampings[i], speeds[j]);
      if (i > 0) CHECK(grid[i][j] < grid[i - 1][j]);
      if (j > 0) CHECK(grid[i][j] < grid[i][j - 1]);
    }
  }
}

TEST_CASE("Damping d -> 0 recovers the conservative path", "[exact][damping]") {
  const double thickness = GENERATE(0.0, 0.002, 0.015);
  const Scene conservative_scene = PaperScene(thickness, 27.6e6, 0.22);
  const ImpactModel conservative = ImpactModel::FromScene(conservative_scene);
  const ImpactResult reference = SolveExact(conservative);

  SECTION("d = 0 is the conservative path itself, to the bit") {
    const ImpactResult zero = SolveExact(ImpactModel::FromScene(Damped(conservative_scene, 0.0)));
    CHECK(zero.peaks.max_penetration_m == reference.peaks.max_penetration_m);
    CHECK(zero.peaks.peak_force_N == reference.peaks.peak_force_N);
    CHECK(zero.peaks.max_energy_density_J_per_m2 == reference.peaks.max_energy_density_J_per_m2);
    CHECK(*zero.contact_duration_s == *reference.contact_duration_s);
    CHECK(*zero.rebound_speed_m_per_s == 2.0);
    CHECK(*zero.coefficient_of_restitution == 1.0);
  }
  SECTION("the difference is O(d)") {
    auto differences = [&](double d) {
      const ImpactResult r = SolveExact(ImpactModel::FromScene(Damped(conservative_scene, d)));
      return std::vector<double>{
          RelativeError(r.peaks.max_penetration_m, reference.peaks.max_penetration_m),
          RelativeError(r.peaks.peak_force_N, reference.peaks.peak_force_N),
          RelativeError(r.peaks.max_compressive_stress_Pa, reference.peaks.max_compressive_stress_Pa),
          RelativeError(r.peaks.max_energy_density_J_per_m2, reference.peaks.max_energy_density_J_per_m2),
          RelativeError(*r.contact_duration_s, *reference.contact_duration_s),
          RelativeError(*r.rebound_speed_m_per_s, *reference.rebound_speed_m_per_s)};
    };
    const std::vector<double> at_1e3 = differences(1e-3), at_1e4 = differences(1e-4),
                              at_1e9 = differences(1e-9);
    for (std::size_t k = 0; k < at_1e3.size(); ++k) {
      CAPTURE(thickness, k, at_1e3[k], at_1e4[k], at_1e9[k]);
      CHECK(at_1e3[k] < 5 * 1e-3 * 2.0);  // |Δ| <~ d v0
      CHECK(at_1e3[k] / at_1e4[k] == Approx(10.0).epsilon(0.05));
      CHECK(at_1e9[k] < 1e-8);
    }
  }
}

TEST_CASE("With strong damping the peak force lies before delta_max", "[exact][damping]") {
  // F = F_el(δ)(1 + d v): dense scan of the loading branch, v from the energy relation by
  // bisection (the library's solver is not used).
  const ThresholdReading reading = GENERATE(ThresholdReading::kCumulative, ThresholdReading::kLiteral);
  const double thickness = GENERATE(0.0, 0.015);
  Scene scene = Damped(PaperScene(thickness, 27.6e6, 0.22), 2.0, 2.0);
  scene.model.thresholds = reading;
  const ImpactModel model = ImpactModel::FromScene(scene);
  const ImpactPeaks peaks = ExactPeaks(model);
  const double delta_max = peaks.max_penetration_m;
  const double stored = model.StateAt(delta_max).potential_energy_J;
  const int points = 20000;
  double scan_force = 0.0, scan_stress = 0.0, argmax = 0.0;
  auto visit = [&](std::size_t j, double delta) {
    const ContactState c = model.StateInSegment(j, delta);
    const double v = LoadingSpeedByBisection(stored - c.potential_energy_J, model.effective_mass_kg(), 2.0, 2.0);
    if (c.force_N * (1 + 2.0 * v) > scan_force) {
      scan_force = c.force_N * (1 + 2.0 * v);
      argmax = delta;
    }
    scan_stress = std::max(scan_stress, c.compressive_stress_Pa * (1 + 2.0 * v));
  };
  for (int i = 1; i < points; ++i) {
    // Denser towards δ_max, where v falls like sqrt(δ_max - δ).
    const double u = static_cast<double>(i) / points;
    const double delta = delta_max * (1.0 - (1.0 - u) * (1.0 - u));
    visit(model.SegmentIndexAt(delta), delta);
  }
  for (std::size_t j = 1; j < model.segment_count(); ++j) {  // both sides of each switch passed
    if (model.segment(j).start_m < delta_max) {
      visit(j - 1, model.segment(j).start_m);
      visit(j, model.segment(j).start_m);
    }
  }
  CAPTURE(reading == ThresholdReading::kLiteral, thickness, argmax / delta_max);
  CHECK(argmax < 0.97 * delta_max);
  CHECK(peaks.peak_force_N > 1.05 * model.StateAt(delta_max).force_N);
  CHECK(peaks.peak_force_N >= scan_force * (1 - 1e-12));
  CHECK(RelativeError(peaks.peak_force_N, scan_force) < 1e-6);
  CHECK(peaks.max_compressive_stress_Pa >= scan_stress * (1 - 1e-12));
  CHECK(RelativeError(peaks.max_compressive_stress_Pa, scan_stress) < 1e-6);
}

TEST_CASE("Damped scenes keep the compression flags and the validity warnings",
          "[exact][damping]") {
  // 2 mm of foam bottoms out at 2 m/s; strong damping keeps it off the bone.
  const ImpactModel soft_landing = ImpactModel::FromScene(Damped(PaperScene(0.002, 27.6e6, 0.22), 5.0));
  const ImpactResult damped = SolveExact(soft_landing);
  const ImpactResult undamped = SolveExact(ImpactModel::FromScene(PaperScene(0.002, 27.6e6, 0.22)));
  CHECK(undamped.peaks.fully_compressed);
  CHECK(damped.peaks.fully_compressed ==
        (damped.peaks.max_penetration_m > damped.peaks.full_compression_penetration_m));
  CHECK(damped.peaks.full_compression_penetration_m == undamped.peaks.full_compression_penetration_m);
  const auto has = [](const ImpactResult& r, ValidityCode code) {
    return std::any_of(r.warnings.begin(), r.warnings.end(),
                       [code](const ValidityWarning& w) { return w.code == code; });
  };
  CHECK(has(undamped, ValidityCode::kFullyCompressed));
  CHECK(has(damped, ValidityCode::kFullyCompressed) == damped.peaks.fully_compressed);
  // A stiff covering's comparison with a bare robot runs on the damped scene too.
  const ImpactResult stiff =
      SolveExact(ImpactModel::FromScene(Damped(PaperScene(0.015, 70e9, 0.3), 0.2)));
  CHECK(has(stiff, ValidityCode::kCoveringStifferThanScalp));
}

TEST_CASE("Negative or non-finite damping is refused naming model.damping", "[exact][damping]") {
  for (double bad : {-0.1, std::nan(""), 2e3}) {
    Scene scene = PaperScene(0.015);
    scene.model.damping_s_per_m = bad;
    CAPTURE(bad);
    try {
      (void)ImpactModel::FromScene(scene);
      FAIL("accepted");
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      CHECK(message.find("model.damping") != std::string::npos);
      CHECK(message.find("s/m") != std::string::npos);
    }
  }
}

TEST_CASE("The exact path refuses a braking robot and a neck, naming the time path",
          "[exact][damping]") {
  Scene braking = PaperScene(0.015);
  braking.robot.braking_m_per_s2 = 5.0;
  Scene neck = PaperScene(0.015);
  neck.head.torso_mass_kg = 30.0;
  neck.head.neck_stiffness_N_per_m = 1e4;
  for (const auto& [scene, field] : {std::pair{braking, "robot.braking"}, std::pair{neck, "head.torso_mass"}}) {
    const ImpactModel model = ImpactModel::FromScene(scene);
    try {
      (void)SolveExact(model);
      FAIL("accepted");
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      CAPTURE(message);
      CHECK(message.find(field) != std::string::npos);
      CHECK(message.find("energy integral") != std::string::npos);
      CHECK(message.find("needs the time path") != std::string::npos);
    }
  }
  // A reaction delay without braking changes nothing: the exact path answers.
  Scene delay_only = PaperScene(0.015);
  delay_only.robot.reaction_delay_s = 0.01;
  CHECK_NOTHROW(SolveExact(ImpactModel::FromScene(delay_only)));
}

TEST_CASE("The exact path's analytic design derivatives refuse a damped scene", "[exact][damping]") {
  // The optimiser differentiates the damped peaks by central differences instead.
  const ImpactModel model = ImpactModel::FromScene(Damped(PaperScene(0.015, 27.6e6, 0.22), 0.2));
  try {
    (void)ExactPeakSensitivities(model, ExactPeaks(model));
    FAIL("accepted");
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    CHECK(message.find("model.damping 0.2 s/m") != std::string::npos);
    CHECK(message.find("finite difference") != std::string::npos);
  }
}

TEST_CASE("Validity warnings on a braking scene compare on the exact path without the braking",
          "[exact][damping]") {
  // CheckValidity's comparisons (a bare robot, the cumulative reading) run the exact path,
  // which has no braking and no neck: they leave them out and say so.
  Scene scene = PaperScene(0.015, 70e9, 0.3);  // a covering stiffer than the scalp
  scene.robot.braking_m_per_s2 = 50.0;
  scene.model.thresholds = ThresholdReading::kLiteral;
  Scene two_body = scene;
  two_body.robot.braking_m_per_s2 = 0.0;
  const ImpactModel model = ImpactModel::FromScene(scene);
  const ImpactPeaks peaks = ExactPeaks(ImpactModel::FromScene(two_body));  // stands in for the time path's
  int noted = 0;
  for (const ValidityWarning& w : CheckValidity(model, peaks)) {
    if (w.message.find("without the braking and the neck") != std::string::npos) ++noted;
  }
  CHECK(noted == 2);
}

TEST_CASE("A damped delta_max landing exactly on a switch gives finite e_A and duration", "[exact][damping]") {
  // Found by the grazing scan of the extended path (docs/numerics.md): with damping, a δ_max
  // exactly on t1 or t2 (the top segment's start) made the quadratures' first piece empty, its
  // nodes 0/0, and e_A,max and the contact duration NaN in a result that said ok.
  for (const double thickness : {0.015, 0.0}) {
    Scene scene = PaperScene(thickness, 27.6e6, 0.22);
    scene.model.damping_s_per_m = 0.2;
    const ImpactModel base = ImpactModel::FromScene(scene);
    for (std::size_t segment = 1; segment < base.segment_count(); ++segment) {
      const double at_switch = base.segment(segment).start_m;
      const ImpactResult on = SolveExact(ImpactModel::FromScene(test::WithMaxPenetration(scene, at_switch)));
      const ImpactResult above =
          SolveExact(ImpactModel::FromScene(test::WithMaxPenetration(scene, at_switch * (1.0 + 1e-12))));
      INFO("covering " << thickness << " m, switch " << segment << ", δ_max " << on.peaks.max_penetration_m);
      REQUIRE(on.ok());
      CHECK(std::isfinite(on.peaks.max_energy_density_J_per_m2));
      REQUIRE(on.contact_duration_s.has_value());
      CHECK(std::isfinite(*on.contact_duration_s));
      CHECK(std::isfinite(*on.time_of_max_compression_s));
      // Continuous across the switch.
      CHECK(RelativeError(on.peaks.max_energy_density_J_per_m2, above.peaks.max_energy_density_J_per_m2) < 1e-9);
      CHECK(RelativeError(*on.contact_duration_s, *above.contact_duration_s) < 1e-9);
    }
  }
}
