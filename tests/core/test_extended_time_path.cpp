// The extended time path (docs/model.md §10.2, §10.3): robot, head and torso as bodies with
// Hunt-Crossley contact damping, a robot braking after a reaction delay and a neck. It must
// reproduce the δ-only path when the new inputs are zero; agree with an independent fixed-step
// RK4 written here on damped contacts; close its energy balance with the dissipated and braking
// work accounted for; converge to a closed-form solution (a linear law with braking) as the
// tolerance falls; show the physical trends of braking and of a neck (a stiff neck makes head
// and torso one mass, a vanishing one a free head); report a contact that never ends as a
// status; run on every SUNDIALS method; and record a history with the bodies' speeds.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "test_helpers.hpp"

using namespace covopt;
using covopt::test::AddVariant;
using covopt::test::NamedScene;
using covopt::test::PaperScene;
using covopt::test::RelativeError;

namespace {

ImpactResult Simulate(const Scene& scene, double rtol,
                      ComputationMethod method = ComputationMethod::kArkodeErk54,
                      bool force_extended = false, bool history = false) {
  TimeIntegrationOptions options;
  options.relative_tolerance = rtol;
  options.method = method;
  options.force_extended_dynamics = force_extended;
  options.record_history = history;
  return SimulateImpact(ImpactModel::FromScene(scene), options);
}

/// The largest relative difference of the peaks, the duration and the rebound speed.
double WorstDifference(const ImpactResult& a, const ImpactResult& b) {
  return std::max({RelativeError(a.peaks.max_penetration_m, b.peaks.max_penetration_m),
                   RelativeError(a.peaks.peak_force_N, b.peaks.peak_force_N),
                   RelativeError(a.peaks.max_compressive_stress_Pa, b.peaks.max_compressive_stress_Pa),
                   RelativeError(a.peaks.max_energy_density_J_per_m2, b.peaks.max_energy_density_J_per_m2),
                   RelativeError(*a.contact_duration_s, *b.contact_duration_s),
                   RelativeError(*a.rebound_speed_m_per_s, *b.rebound_speed_m_per_s)});
}

Scene BrakingScene(double braking_m_per_s2, double delay_s) {
  Scene scene = PaperScene(0.015, 27.6e6, 0.22);
  scene.robot.braking_m_per_s2 = braking_m_per_s2;
  scene.robot.reaction_delay_s = delay_s;
  return scene;
}

Scene NeckScene(double torso_kg, double stiffness_N_per_m, double damping_N_s_per_m) {
  Scene scene = PaperScene(0.015, 27.6e6, 0.22);
  scene.head.torso_mass_kg = torso_kg;
  scene.head.neck_stiffness_N_per_m = stiffness_N_per_m;
  scene.head.neck_damping_N_s_per_m = damping_N_s_per_m;
  return scene;
}

/// An independent check of a damped two-body contact: classical RK4 with a fixed step on
///     δ'' = -F_el(δ) max(0, 1 + d δ') / m,   e' = σ_el(δ) max(0, 1 + d δ') δ',
/// the whole piecewise law (ImpactModel::StateAt), from (0, v0, 0) to separation. Maxima and
/// crossings are refined between steps with the local quadratic; F and σ_c may peak at a phase
/// switch (the next phase's law starts with zero slope), so they are also taken there.
struct ReferenceContact {
  double max_penetration_m = 0.0;
  double peak_force_N = 0.0;
  double max_stress_Pa = 0.0;
  double max_energy_density = 0.0;
  double duration_s = 0.0;
  double rebound_speed_m_per_s = 0.0;
};

ReferenceContact DampedRk4(const ImpactModel& model, int steps_per_conservative_duration) {
  const double d = model.scene().model.damping_s_per_m;
  const double inverse_mass = 1.0 / model.effective_mass_kg();
  struct State {
    double delta, rate, e;
  };
  struct Rate {
    double delta, rate, e, force, stress;
  };
  const auto f = [&](const State& s) {
    const ContactState law = model.StateAt(s.delta);
    const double factor = std::max(0.0, 1.0 + d * s.rate);
    const double force = law.force_N * factor;
    const double stress = law.compressive_stress_Pa * factor;
    return Rate{s.rate, -force * inverse_mass, stress * s.rate, force, stress};
  };
  Scene conservative = model.scene();
  conservative.model.damping_s_per_m = 0.0;
  const ImpactModel undamped = ImpactModel::FromScene(conservative);
  const double h = ExactContactDuration(undamped, ExactPeaks(undamped)) / steps_per_conservative_duration;
  ReferenceContact out;
  State s{0.0, model.impact_speed_m_per_s(), 0.0};
  std::array<double, 3> forces{0.0, 0.0, 0.0}, stresses{0.0, 0.0, 0.0};  // last three samples
  std::array<std::size_t, 3> segments{0, 0, 0};                           // and their segments
  double t = 0.0;
  for (long k = 0; k < 100L * steps_per_conservative_duration; ++k) {
    const Rate k1 = f(s);
    const Rate k2 = f({s.delta + 0.5 * h * k1.delta, s.rate + 0.5 * h * k1.rate, s.e + 0.5 * h * k1.e});
    const Rate k3 = f({s.delta + 0.5 * h * k2.delta, s.rate + 0.5 * h * k2.rate, s.e + 0.5 * h * k2.e});
    const Rate k4 = f({s.delta + h * k3.delta, s.rate + h * k3.rate, s.e + h * k3.e});
    const State next{s.delta + h / 6 * (k1.delta + 2 * k2.delta + 2 * k3.delta + k4.delta),
                     s.rate + h / 6 * (k1.rate + 2 * k2.rate + 2 * k3.rate + k4.rate),
                     s.e + h / 6 * (k1.e + 2 * k2.e + 2 * k3.e + k4.e)};
    if (s.rate > 0.0 && next.rate <= 0.0) {  // maximum of δ and of e: δ' ~ linear over the step
      const double acceleration = (next.rate - s.rate) / h;
      const double tau = -s.rate / acceleration;
      out.max_penetration_m = s.delta + s.rate * tau + 0.5 * acceleration * tau * tau;
      out.max_energy_density = s.e + 0.5 * k1.e * tau;
    }
    if (next.delta <= 0.0 && s.rate < 0.0) {  // separation
      const double acceleration = (next.rate - s.rate) / h;
      const double tau = -s.delta / s.rate;
      out.duration_s = t + tau;
      out.rebound_speed_m_per_s = -(s.rate + acceleration * tau);
      break;
    }
    // F and σ_c sampled at every step; a maximum is refined by the parabola through three
    // samples of one phase.
    const Rate at_next = f(next);
    forces = {forces[1], forces[2], at_next.force};
    stresses = {stresses[1], stresses[2], at_next.stress};
    segments = {segments[1], segments[2], model.SegmentIndexAt(next.delta)};
    const bool one_phase = segments[0] == segments[1] && segments[1] == segments[2];
    const auto refine = [&](const std::array<double, 3>& v) {
      const double curvature = v[0] - 2.0 * v[1] + v[2];
      return one_phase && curvature < 0.0
                 ? v[1] - 0.125 * (v[2] - v[0]) * (v[2] - v[0]) / curvature
                 : v[1];
    };
    if (forces[1] >= forces[0] && forces[1] > forces[2]) {
      out.peak_force_N = std::max(out.peak_force_N, refine(forces));
    }
    if (stresses[1] >= stresses[0] && stresses[1] > stresses[2]) {
      out.max_stress_Pa = std::max(out.max_stress_Pa, refine(stresses));
    }
    // A switch crossed upward inside the step: F and σ_c there, with δ' from the quadratic.
    for (std::size_t i = 1; i < model.segment_count(); ++i) {
      const double edge = model.segment(i).start_m;
      if (!(s.delta < edge && next.delta >= edge && s.rate > 0.0)) continue;
      const double acceleration = (next.rate - s.rate) / h;
      double tau = (edge - s.delta) / s.rate;
      for (int iteration = 0; iteration < 5; ++iteration) {  // Newton on the quadratic
        const double rate = s.rate + acceleration * tau;
        tau -= (s.delta + s.rate * tau + 0.5 * acceleration * tau * tau - edge) / rate;
      }
      const double factor = std::max(0.0, 1.0 + d * (s.rate + acceleration * tau));
      const ContactState law = model.StateAt(edge);
      out.peak_force_N = std::max(out.peak_force_N, law.force_N * factor);
      out.max_stress_Pa = std::max(out.max_stress_Pa, law.compressive_stress_Pa * factor);
    }
    s = next;
    t += h;
  }
  return out;
}

/// A braking robot on a linear law (all contact in phase 1, n = 1, F = K δ), solved in closed
/// form: δ = (v0/ω) sin ωt until t_d, then δ'' = -ω² δ - a, a sinusoid about -a/ω².
struct LinearBrakingCase {
  Scene scene;
  double max_penetration_m = 0.0;
  double time_of_max_s = 0.0;
  double duration_s = 0.0;
  double rebound_speed_m_per_s = 0.0;
};

LinearBrakingCase MakeLinearBrakingCase() {
  LinearBrakingCase c;
  c.scene = PaperScene(0.0);
  c.scene.model.exponent_covering_scalp = 1.0;
  const ImpactModel probe = ImpactModel::FromScene(c.scene);
  const double omega = std::sqrt(probe.segment(0).stiffness / probe.effective_mass_kg());
  const double t1 = probe.segment(0).end_m;
  const double v0 = 0.5 * t1 * omega;  // unbraked δ_max = t1 / 2: phase 1 only
  const double a = 100.0;              // m/s²
  const double t_d = 0.3 * (std::numbers::pi / 2.0) / omega;
  c.scene.robot.speed_m_per_s = v0;
  c.scene.robot.braking_m_per_s2 = a;
  c.scene.robot.reaction_delay_s = t_d;
  const double delta_d = v0 / omega * std::sin(omega * t_d);
  const double rate_d = v0 * std::cos(omega * t_d);
  const double offset = a / (omega * omega);
  const double amplitude = std::hypot(delta_d + offset, rate_d / omega);
  const double phase = std::atan2(rate_d / omega, delta_d + offset);
  c.max_penetration_m = amplitude - offset;
  c.time_of_max_s = t_d + phase / omega;
  c.duration_s = t_d + (phase + std::acos(offset / amplitude)) / omega;
  c.rebound_speed_m_per_s = omega * std::sqrt(amplitude * amplitude - offset * offset);
  return c;
}

double LinearCaseError(const LinearBrakingCase& c, const ImpactResult& r) {
  return std::max({RelativeError(r.peaks.max_penetration_m, c.max_penetration_m),
                   RelativeError(*r.time_of_max_compression_s, c.time_of_max_s),
                   RelativeError(*r.contact_duration_s, c.duration_s),
                   RelativeError(*r.rebound_speed_m_per_s, c.rebound_speed_m_per_s)});
}

}  // namespace

TEST_CASE("With the new inputs zero the extended path reproduces the δ-only path", "[extended]") {
  std::vector<NamedScene> scenes;
  const Scene base = PaperScene(0.015, 27.6e6, 0.22);
  auto add = [&](std::string name, auto&& edit) { AddVariant(scenes, base, std::move(name), edit); };
  add("paper scene", [](Scene&) {});
  add("no covering", [](Scene& s) { s.covering.thickness_m = 0; });
  add("thin, fully compressed covering", [](Scene& s) { s.covering.thickness_m = 0.002; });
  add("fixed head", [](Scene& s) { s.head.mass_kg = kFixed; });
  add("fixed robot (head drop)", [](Scene& s) { s.robot.mass_kg = kFixed; });
  add("fast impact", [](Scene& s) { s.robot.speed_m_per_s = 8.0; });
  add("literal thresholds, the force drops at t1", [](Scene& s) {
    s.model.thresholds = ThresholdReading::kLiteral;
    s.scalp.thickness_m = 0.010;
    s.covering = {100e6, 0.25, 0.0065};
    s.robot.speed_m_per_s = 1.5;
  });
  for (const NamedScene& named : scenes) {
    for (const ComputationMethod method : {ComputationMethod::kArkodeErk54, ComputationMethod::kCvodeBdf}) {
      const ImpactResult reference = Simulate(named.scene, 1e-10, method);
      const ImpactResult extended = Simulate(named.scene, 1e-10, method, true);
      INFO(named.name << ", " << ToString(method) << ": " << extended.message);
      REQUIRE(reference.ok());
      REQUIRE(extended.ok());
      CHECK(extended.peaks.phase_at_max == reference.peaks.phase_at_max);
      CHECK(WorstDifference(extended, reference) < 1e-7);
      CHECK(RelativeError(*extended.time_of_max_compression_s, *reference.time_of_max_compression_s) < 1e-7);
    }
  }
}

TEST_CASE("A damped contact agrees with an independent fixed-step RK4", "[extended][damping]") {
  std::vector<NamedScene> scenes;
  const Scene base = PaperScene(0.015, 27.6e6, 0.22);
  auto add = [&](std::string name, auto&& edit) { AddVariant(scenes, base, std::move(name), edit); };
  add("paper scene, d 0.2 s/m", [](Scene& s) { s.model.damping_s_per_m = 0.2; });
  add("no covering, d 0.5 s/m (reaches bone)", [](Scene& s) {
    s.covering.thickness_m = 0;
    s.model.damping_s_per_m = 0.5;
  });
  add("thin covering fully compressed, d 1 s/m, fast", [](Scene& s) {
    s.covering.thickness_m = 0.002;
    s.robot.speed_m_per_s = 4.0;
    s.model.damping_s_per_m = 1.0;
  });
  add("fixed head, d 0.3 s/m", [](Scene& s) {
    s.head.mass_kg = kFixed;
    s.model.damping_s_per_m = 0.3;
  });
  for (const NamedScene& named : scenes) {
    const ImpactModel model = ImpactModel::FromScene(named.scene);
    const ReferenceContact reference = DampedRk4(model, 200000);
    const ImpactResult simulated = Simulate(named.scene, 1e-10);
    INFO(named.name << ": " << simulated.message);
    REQUIRE(simulated.ok());
    CHECK(RelativeError(simulated.peaks.max_penetration_m, reference.max_penetration_m) < 1e-6);
    CHECK(RelativeError(simulated.peaks.peak_force_N, reference.peak_force_N) < 1e-6);
    CHECK(RelativeError(simulated.peaks.max_compressive_stress_Pa, reference.max_stress_Pa) < 1e-6);
    CHECK(RelativeError(simulated.peaks.max_energy_density_J_per_m2, reference.max_energy_density) < 1e-6);
    CHECK(RelativeError(*simulated.contact_duration_s, reference.duration_s) < 1e-6);
    CHECK(RelativeError(*simulated.rebound_speed_m_per_s, reference.rebound_speed_m_per_s) < 1e-6);
    CHECK(*simulated.coefficient_of_restitution ==
          *simulated.rebound_speed_m_per_s / named.scene.robot.speed_m_per_s);
    // Damping dissipates: the rebound is slower, and the force peaks before δ_max, above the
    // elastic force there.
    CHECK(*simulated.coefficient_of_restitution < 1.0);
    CHECK(simulated.peaks.peak_force_N > model.StateAt(simulated.peaks.max_penetration_m).force_N);
  }
}

TEST_CASE("A damped contact agrees with the exact damped path", "[extended][damping]") {
  std::vector<NamedScene> scenes;
  const Scene base = PaperScene(0.015, 27.6e6, 0.22);
  auto add = [&](std::string name, auto&& edit) { AddVariant(scenes, base, std::move(name), edit); };
  add("paper scene, d 0.2 s/m", [](Scene& s) { s.model.damping_s_per_m = 0.2; });
  add("light damping, slow", [](Scene& s) {
    s.model.damping_s_per_m = 0.05;
    s.robot.speed_m_per_s = 1.0;
  });
  add("no covering, d 0.5 s/m", [](Scene& s) {
    s.covering.thickness_m = 0;
    s.model.damping_s_per_m = 0.5;
  });
  add("thin covering, d 1 s/m, 4 m/s (the force peaks at a switch)", [](Scene& s) {
    s.covering.thickness_m = 0.002;
    s.robot.speed_m_per_s = 4.0;
    s.model.damping_s_per_m = 1.0;
  });
  add("fixed head, d 0.3 s/m", [](Scene& s) {
    s.head.mass_kg = kFixed;
    s.model.damping_s_per_m = 0.3;
  });
  add("fixed robot, d 0.3 s/m", [](Scene& s) {
    s.robot.mass_kg = kFixed;
    s.model.damping_s_per_m = 0.3;
  });
  add("heavy damping, d v0 = 10 (restitution 0.1)", [](Scene& s) {
    s.model.damping_s_per_m = 2.0;
    s.robot.speed_m_per_s = 5.0;
  });
  for (const NamedScene& named : scenes) {
    const ImpactModel model = ImpactModel::FromScene(named.scene);
    const ImpactResult exact = SolveExact(model);
    for (const ComputationMethod method : {ComputationMethod::kArkodeErk54, ComputationMethod::kCvodeBdf,
                                           ComputationMethod::kCvodeAdams}) {
      TimeIntegrationOptions options;  // the default tolerance, rtol 1e-8
      options.method = method;
      const ImpactResult simulated = SimulateImpact(model, options);
      INFO(named.name << ", " << ToString(method) << ": " << simulated.message);
      REQUIRE(exact.ok());
      REQUIRE(simulated.ok());
      CHECK(simulated.peaks.phase_at_max == exact.peaks.phase_at_max);
      CHECK(WorstDifference(simulated, exact) <= 1e-5);
    }
  }
}

TEST_CASE("The energy balance closes with the dissipated and braking work accounted for",
          "[extended][energy]") {
  std::vector<NamedScene> scenes;
  const Scene base = PaperScene(0.015, 27.6e6, 0.22);
  auto add = [&](std::string name, auto&& edit) { AddVariant(scenes, base, std::move(name), edit); };
  add("damping 0.2 s/m", [](Scene& s) { s.model.damping_s_per_m = 0.2; });
  add("damping 0.5 s/m, no covering", [](Scene& s) {
    s.model.damping_s_per_m = 0.5;
    s.covering.thickness_m = 0;
  });
  add("braking 100 m/s2 after 2 ms", [](Scene& s) {
    s.robot.braking_m_per_s2 = 100;
    s.robot.reaction_delay_s = 0.002;
  });
  add("braking 300 m/s2 at once (the robot stops in contact)", [](Scene& s) {
    s.robot.braking_m_per_s2 = 300;
  });
  add("undamped neck, 30 kg torso", [](Scene& s) {
    s.head.torso_mass_kg = 30;
    s.head.neck_stiffness_N_per_m = 3e4;
  });
  add("damped neck on a fixed torso", [](Scene& s) {
    s.head.torso_mass_kg = kFixed;
    s.head.neck_stiffness_N_per_m = 1e5;
    s.head.neck_damping_N_s_per_m = 200;
  });
  add("fixed robot, damping and a neck (the support's work counts)", [](Scene& s) {
    s.robot.mass_kg = kFixed;
    s.model.damping_s_per_m = 0.2;
    s.head.torso_mass_kg = 40;
    s.head.neck_stiffness_N_per_m = 5e4;
  });
  add("everything at once", [](Scene& s) {
    s.model.damping_s_per_m = 0.2;
    s.robot.braking_m_per_s2 = 100;
    s.robot.reaction_delay_s = 0.002;
    s.head.torso_mass_kg = 30;
    s.head.neck_stiffness_N_per_m = 3e4;
    s.head.neck_damping_N_s_per_m = 50;
  });
  for (const NamedScene& named : scenes) {
    const ImpactModel model = ImpactModel::FromScene(named.scene);
    for (const double rtol : {1e-6, 1e-8, 1e-10}) {
      const ImpactResult result = Simulate(named.scene, rtol, ComputationMethod::kArkodeErk54, false, true);
      INFO(named.name << ", rtol " << rtol << ": " << result.message);
      REQUIRE(result.ok());
      REQUIRE(result.energy_residual.has_value());
      CHECK(*result.energy_residual <= 100 * rtol);
      for (const ValidityWarning& warning : result.warnings) CHECK(warning.message.find("tolerance") == std::string::npos);
    }
    // Where energy leaves the bodies, the balance needs the work: it is far from 0.
    const Scene& s = named.scene;
    if (s.is_damped() || s.robot_brakes() || s.head.neck_damping_N_s_per_m > 0.0 ||
        std::isinf(s.robot.mass_kg)) {
      const ImpactResult result = Simulate(s, 1e-8, ComputationMethod::kArkodeErk54, false, true);
      CHECK(std::abs(result.history.back().dissipated_work_J) > 1e-3 * model.impact_energy_J());
    }
  }
}

TEST_CASE("A braking robot on a linear law converges to the closed form as rtol falls",
          "[extended][braking][convergence]") {
  const LinearBrakingCase linear = MakeLinearBrakingCase();
  const ImpactModel model = ImpactModel::FromScene(linear.scene);
  REQUIRE(linear.max_penetration_m < model.segment(0).end_m);  // phase 1 throughout
  std::vector<double> errors;
  for (const double rtol : {1e-4, 1e-6, 1e-8, 1e-10}) {
    const ImpactResult result = Simulate(linear.scene, rtol, ComputationMethod::kArkodeErk54, false, true);
    INFO("rtol " << rtol << ": " << result.message);
    REQUIRE(result.ok());
    // The closed form assumes the robot keeps moving forward (the brake never releases).
    for (const HistorySample& sample : result.history) REQUIRE(sample.robot_speed_m_per_s > 0.0);
    CHECK(result.statistics.restarts == 1);  // the brake's start
    const double error = LinearCaseError(linear, result);
    CAPTURE(error);
    CHECK(error < 100 * rtol);
    // F = K δ and σ_c = k K c (n = 1) at δ_max.
    CHECK(result.peaks.peak_force_N == Approx(model.StateAt(result.peaks.max_penetration_m).force_N).epsilon(1e-12));
    errors.push_back(error);
  }
  // The error falls with the tolerance: over six decades of rtol, at least four of error.
  CHECK(errors.back() < 1e-4 * errors.front());
  for (std::size_t i = 1; i < errors.size(); ++i) CHECK(errors[i] < errors[i - 1]);
}

TEST_CASE("Braking trends: a later or weaker brake hits harder", "[extended][braking]") {
  const double rtol = 1e-9;
  SECTION("a longer reaction delay gives larger peaks") {
    double previous = 0.0, previous_force = 0.0, previous_energy = 0.0;
    for (const double delay : {0.0, 0.001, 0.003, 0.006}) {
      const ImpactResult r = Simulate(BrakingScene(200, delay), rtol);
      REQUIRE(r.ok());
      CHECK(r.peaks.max_penetration_m > previous);
      CHECK(r.peaks.peak_force_N > previous_force);
      CHECK(r.peaks.max_energy_density_J_per_m2 > previous_energy);
      previous = r.peaks.max_penetration_m;
      previous_force = r.peaks.peak_force_N;
      previous_energy = r.peaks.max_energy_density_J_per_m2;
    }
  }
  SECTION("stronger braking gives smaller peaks") {
    double previous = 1.0, previous_force = 1e300;
    for (const double braking : {25.0, 50.0, 100.0, 200.0, 400.0}) {
      const ImpactResult r = Simulate(BrakingScene(braking, 0.001), rtol);
      REQUIRE(r.ok());
      CHECK(r.peaks.max_penetration_m < previous);
      CHECK(r.peaks.peak_force_N < previous_force);
      previous = r.peaks.max_penetration_m;
      previous_force = r.peaks.peak_force_N;
    }
  }
  SECTION("a brake that starts after maximum compression changes nothing before it") {
    const ImpactResult unbraked = Simulate(BrakingScene(0, 0), rtol, ComputationMethod::kArkodeErk54, true);
    REQUIRE(unbraked.ok());
    const ImpactResult late = Simulate(BrakingScene(300, 1.2 * *unbraked.time_of_max_compression_s), rtol);
    REQUIRE(late.ok());
    CHECK(RelativeError(late.peaks.max_penetration_m, unbraked.peaks.max_penetration_m) < 1e-12);
    CHECK(RelativeError(late.peaks.peak_force_N, unbraked.peaks.peak_force_N) < 1e-12);
    CHECK(RelativeError(late.peaks.max_energy_density_J_per_m2, unbraked.peaks.max_energy_density_J_per_m2) < 1e-12);
    CHECK(*late.time_of_max_compression_s == Approx(*unbraked.time_of_max_compression_s).epsilon(1e-12));
    // ... but after it: the robot falls back faster, and the contact ends sooner.
    CHECK(*late.rebound_speed_m_per_s > *unbraked.rebound_speed_m_per_s);
    CHECK(*late.contact_duration_s < *unbraked.contact_duration_s);
  }
}

TEST_CASE("A robot braked to a stop is released: only the contact pushes it back", "[extended][braking]") {
  const Scene scene = BrakingScene(300, 0.0);
  const ImpactResult r = Simulate(scene, 1e-9, ComputationMethod::kArkodeErk54, false, true);
  REQUIRE(r.ok());
  const auto stop = std::find_if(r.history.begin(), r.history.end(),
                                 [](const HistorySample& s) { return s.robot_speed_m_per_s <= 0.0; });
  REQUIRE(stop != r.history.end());  // it stops during the contact
  for (auto s = stop; s != r.history.end(); ++s) CHECK(s->robot_speed_m_per_s <= 1e-9);
  // Near separation the force is ~0, so the released robot hardly accelerates (a brake still
  // on would decelerate it at 300 m/s²).
  const HistorySample& last = r.history.back();
  const HistorySample& before = r.history[r.history.size() - 2];
  const double acceleration =
      (last.robot_speed_m_per_s - before.robot_speed_m_per_s) / (last.time_s - before.time_s);
  CHECK(std::abs(acceleration) < 30.0);
  // The stop is an event: the phase switches up and down, and the stop.
  CHECK(r.statistics.restarts == 3);
}

TEST_CASE("Every braking run separates, from 1e-6 to 10 m/s and 0 to 1000 m/s²", "[extended][braking]") {
  // A strong brake at a low speed stops the robot after δ ~ v0²/(2a), far below the unbraked
  // penetration; only the elastic force then unloads that tiny δ, over a time that grows as
  // δ_max falls (~δ^(-1/4) for Hertz) and far exceeds 3 L/v0. The contact must still end
  // (a free head, no neck), with the energy balance kept.
  for (const double delay_s : {0.0, 1e-3}) {
    for (const double braking : {0.0, 1.0, 10.0, 100.0, 150.0, 200.0, 1000.0}) {
      for (double speed = 1e-6; speed <= 10.0 * (1.0 + 1e-9); speed *= 10.0) {
        Scene scene = BrakingScene(braking, delay_s);
        scene.robot.speed_m_per_s = speed;
        CAPTURE(delay_s, braking, speed);
        const ImpactResult r = Simulate(scene, 1e-8, ComputationMethod::kArkodeErk54, true);
        REQUIRE(r.ok());
        REQUIRE(r.contact_duration_s.has_value());
        CHECK(*r.contact_duration_s > 0.0);
        CHECK(*r.rebound_speed_m_per_s >= 0.0);
        CHECK(r.energy_residual <= 1e-6);  // max(100 rtol, 1e-9)
        for (const ValidityWarning& warning : r.warnings) {
          CHECK(warning.message.find("did not keep its tolerance") == std::string::npos);
        }
        if (braking > 0.0) {  // δ_max is at most the robot's travel, v0 t_d + v0²/(2a)
          const double travel_m = speed * delay_s + speed * speed / (2.0 * braking);
          CHECK(r.peaks.max_penetration_m <= travel_m * (1.0 + 1e-6));
          // Far below the unbraked penetration, the brake (m_r a ~ 1e3 N) dwarfs the contact
          // force and the robot stops after exactly v0²/(2a).
          if (delay_s == 0.0 && braking >= 100.0 && speed <= 1e-4) {
            CHECK(RelativeError(r.peaks.max_penetration_m, travel_m) < 1e-6);
          }
        }
      }
    }
  }
}

TEST_CASE("A very stiff neck makes head and torso one mass", "[extended][neck]") {
  const double torso = 40.0;
  Scene one_mass = PaperScene(0.015, 27.6e6, 0.22);
  one_mass.head.mass_kg += torso;
  const ImpactResult reference = Simulate(one_mass, 1e-10);
  REQUIRE(reference.ok());
  std::vector<double> differences;
  for (const double stiffness : {1e7, 1e8, 1e9}) {
    const ImpactResult neck = Simulate(NeckScene(torso, stiffness, 0.0), 1e-10);
    INFO("k_n " << stiffness << ": " << neck.message);
    REQUIRE(neck.ok());
    differences.push_back(std::max({RelativeError(neck.peaks.max_penetration_m, reference.peaks.max_penetration_m),
                                    RelativeError(neck.peaks.peak_force_N, reference.peaks.peak_force_N),
                                    RelativeError(neck.peaks.max_energy_density_J_per_m2,
                                                  reference.peaks.max_energy_density_J_per_m2),
                                    RelativeError(*neck.contact_duration_s, *reference.contact_duration_s)}));
  }
  CAPTURE(differences);
  CHECK(differences.back() < 1e-3);
  CHECK(differences[1] < 0.3 * differences[0]);
  CHECK(differences[2] < 0.3 * differences[1]);
}

TEST_CASE("A vanishing neck leaves a free head", "[extended][neck]") {
  const Scene free_head = PaperScene(0.015, 27.6e6, 0.22);
  const ImpactResult reference = Simulate(free_head, 1e-10);
  const ImpactResult neck = Simulate(NeckScene(30.0, 1e-6, 1e-6), 1e-10);
  REQUIRE(reference.ok());
  REQUIRE(neck.ok());
  CHECK(WorstDifference(neck, reference) < 1e-7);
  // A real neck on a fixed torso holds the head back: the robot penetrates deeper.
  const ImpactResult held = Simulate(NeckScene(kFixed, 1e5, 0.0), 1e-10);
  REQUIRE(held.ok());
  CHECK(held.peaks.max_penetration_m > reference.peaks.max_penetration_m);
}

TEST_CASE("A neck can make δ rise again: δ_max is the largest of its maxima", "[extended][neck]") {
  // A heavy robot presses the head into a neck on a fixed torso; the neck sends the head back.
  Scene scene = NeckScene(kFixed, 1e5, 0.0);
  scene.robot.mass_kg = 100.0;
  const ImpactModel model = ImpactModel::FromScene(scene);
  const ImpactResult r = Simulate(scene, 1e-9, ComputationMethod::kArkodeErk54, false, true);
  REQUIRE(r.ok());
  int maxima = 0;
  double largest = 0.0;
  for (std::size_t i = 1; i < r.history.size(); ++i) {
    if (r.history[i - 1].penetration_rate_m_per_s > 0.0 && r.history[i].penetration_rate_m_per_s <= 0.0) ++maxima;
    largest = std::max(largest, r.history[i].penetration_m);
  }
  CHECK(maxima >= 3);
  CHECK(r.peaks.max_penetration_m == largest);  // every maximum is an event sample
  const HistorySample& at_max = *std::find_if(r.history.begin(), r.history.end(), [&](const HistorySample& s) {
    return s.penetration_m == largest;
  });
  CHECK(*r.time_of_max_compression_s == at_max.time_s);
  CHECK(r.peaks.peak_force_N == model.StateAt(largest).force_N);  // undamped: the law at δ_max
  // e too; the history's integrated e agrees to the tolerance.
  CHECK(r.peaks.max_energy_density_J_per_m2 == model.StateAt(largest).energy_density_J_per_m2);
  CHECK(RelativeError(at_max.energy_density_J_per_m2, r.peaks.max_energy_density_J_per_m2) < 100 * 1e-9);
  CHECK(*r.energy_residual < 100 * 1e-9);
}

TEST_CASE("A contact that cannot end is refused before it runs", "[extended][failure]") {
  // A fixed robot would keep driving the head into a fixed torso: bad input, not a run. The
  // extended path keeps its time bound (SolveStatus::kNoSeparation) as a guard.
  Scene scene = NeckScene(kFixed, 1e6, 0.0);
  scene.robot.mass_kg = kFixed;
  CHECK_THROWS_WITH(ImpactModel::FromScene(scene), Catch::Matchers::Contains("never end"));
  CHECK(ToString(SolveStatus::kNoSeparation) == "no-separation");
}

TEST_CASE("A Hunt-Crossley force never pulls: it is 0 while 1 + d δ' < 0", "[extended][damping]") {
  // Braking pushes the separation speed past 1/d = 0.5 m/s, where the damped force would pull.
  Scene scene = PaperScene(0.015, 27.6e6, 0.22);
  scene.model.damping_s_per_m = 2.0;
  scene.robot.speed_m_per_s = 3.0;
  scene.robot.braking_m_per_s2 = 300.0;
  const ImpactResult r = Simulate(scene, 1e-9, ComputationMethod::kArkodeErk54, false, true);
  REQUIRE(r.ok());
  bool clamped = false;
  for (const HistorySample& s : r.history) {
    CHECK(s.force_N >= 0.0);
    if (1.0 + 2.0 * s.penetration_rate_m_per_s < 0.0) {
      clamped = true;
      CHECK(s.force_N == 0.0);
    }
  }
  CHECK(clamped);
  CHECK(*r.rebound_speed_m_per_s > 0.5);
  CHECK(*r.energy_residual < 100 * 1e-9);
}

TEST_CASE("Every SUNDIALS method runs the extended scenes", "[extended][methods]") {
  Scene scene = PaperScene(0.015, 27.6e6, 0.22);
  scene.model.damping_s_per_m = 0.2;
  scene.robot.braking_m_per_s2 = 100;
  scene.robot.reaction_delay_s = 0.002;
  scene.head.torso_mass_kg = 30;
  scene.head.neck_stiffness_N_per_m = 3e4;
  scene.head.neck_damping_N_s_per_m = 50;
  const ImpactResult reference = Simulate(scene, 1e-12);
  REQUIRE(reference.ok());
  for (const ComputationMethod method : TimeIntegrationMethods()) {
    const ImpactResult r = Simulate(scene, 1e-8, method);
    INFO(ToString(method) << ": " << r.message);
    REQUIRE(r.ok());
    CHECK(r.method == method);
    CHECK(WorstDifference(r, reference) < 1e-4);
  }
}

TEST_CASE("The extended history carries the bodies' speeds and the work", "[extended][history]") {
  Scene scene = NeckScene(30.0, 3e4, 50.0);
  scene.model.damping_s_per_m = 0.2;
  TimeIntegrationOptions options;
  options.record_history = true;
  options.history_max_interval_s = 5e-5;
  const ImpactModel model = ImpactModel::FromScene(scene);
  const ImpactResult r = SimulateImpact(model, options);
  REQUIRE(r.ok());
  REQUIRE(r.history.size() > 300);
  CHECK(r.history.front().time_s == 0.0);
  CHECK(r.history.back().time_s == *r.contact_duration_s);
  double previous_time = -1.0, previous_work = -1.0, largest_force = 0.0;
  for (const HistorySample& s : r.history) {
    CHECK(s.time_s > previous_time);
    CHECK(s.time_s - previous_time <= 5e-5 * (1 + 1e-9) + (previous_time < 0 ? 1.0 : 0.0));
    CHECK(s.robot_speed_m_per_s - s.head_speed_m_per_s ==
          Approx(s.penetration_rate_m_per_s).margin(1e-12));
    CHECK(s.dissipated_work_J >= previous_work - 1e-12);  // dampers only take energy out
    previous_time = s.time_s;
    previous_work = s.dissipated_work_J;
    largest_force = std::max(largest_force, s.force_N);
  }
  CHECK(largest_force <= r.peaks.peak_force_N * (1 + 1e-12));
  CHECK(largest_force > 0.99 * r.peaks.peak_force_N);
  CHECK(r.history.back().neck_force_N > 0.0);  // the head has moved ahead of the torso
}

TEST_CASE("The δ-only path's history carries the bodies' speeds from momentum", "[time][history]") {
  const Scene scene = PaperScene(0.015, 27.6e6, 0.22);
  const ImpactResult r = Simulate(scene, 1e-8, ComputationMethod::kArkodeErk54, false, true);
  REQUIRE(r.ok());
  for (const HistorySample& s : r.history) {
    CHECK(scene.robot.mass_kg * s.robot_speed_m_per_s + scene.head.mass_kg * s.head_speed_m_per_s ==
          Approx(scene.robot.mass_kg * scene.robot.speed_m_per_s).epsilon(1e-12));
    CHECK(s.dissipated_work_J == 0.0);
  }
  CHECK(*r.coefficient_of_restitution == *r.rebound_speed_m_per_s / scene.robot.speed_m_per_s);
}

namespace {

/// The grazing checks of one result against its reference: status, the peaks but σ_c, T and
/// the rebound within `bound` rtol, σ_c within max(bound rtol, its change over 100 rtol of
/// δ_max), which is far larger just above t1 (docs/numerics.md, "σ_c grazing t1").
void CheckGrazingRun(const ImpactModel& model, const ImpactResult& result, const ImpactResult& reference,
                     double rtol, double bound) {
  CHECK(result.ok());  // every failing combination listed, not only the first
  if (!result.ok()) return;
  CHECK(RelativeError(result.peaks.max_penetration_m, reference.peaks.max_penetration_m) <= bound * rtol);
  CHECK(RelativeError(result.peaks.peak_force_N, reference.peaks.peak_force_N) <= bound * rtol);
  CHECK(RelativeError(result.peaks.max_energy_density_J_per_m2, reference.peaks.max_energy_density_J_per_m2) <=
        bound * rtol);
  CHECK(RelativeError(*result.contact_duration_s, *reference.contact_duration_s) <= bound * rtol);
  CHECK(RelativeError(*result.rebound_speed_m_per_s, *reference.rebound_speed_m_per_s) <= bound * rtol);
  const double stress_bound =
      std::max(bound * rtol, test::StressChangeOver(model, reference.peaks, 100.0 * rtol));
  CHECK(RelativeError(result.peaks.max_compressive_stress_Pa, reference.peaks.max_compressive_stress_Pa) <=
        stress_bound);
}

/// ERK 6(5) and ERK 8(7) keep only their own measured limits (docs/numerics.md); here a bound
/// against gross errors (a turn or a return lost), as in test_time_path.cpp's grazing test.
double GrazingBound(ComputationMethod method) {
  return method == ComputationMethod::kArkodeErk65 || method == ComputationMethod::kArkodeErk87 ? 1e4 : 100.0;
}

}  // namespace

TEST_CASE("Grazing a switch on the extended path: conservative and damped", "[extended][grazing]") {
  // The δ-only path failed where δ_max grazes a switch (CV_ILL_INPUT, a runaway, a step limit:
  // test_time_path.cpp, "Grazing the full-compression switch"). The extended path has no series
  // opening or closing, and its lower switch root is the segment's start itself; a scan of it
  // found no failure (docs/numerics.md, "Every event loop scanned for the grazing case":
  // 12 scenes, conservative forced onto it and damped, x t1 and t2 x 63 offsets x 8 methods x
  // rtol 1e-4 .. 1e-10, 44 352 runs). This holds a sample of that scan.
  std::vector<NamedScene> scenes;
  const Scene paper = PaperScene(0.015, 27.6e6, 0.22);
  auto add = [&](std::string name, auto&& edit) { AddVariant(scenes, paper, std::move(name), edit); };
  add("paper scene", [](Scene&) {});
  add("4 mm of 1 GPa", [](Scene& s) { s.covering = {999109940.49841368, 0.25, 0.0039910199699451044}; });
  add("no covering", [](Scene& s) { s.covering.thickness_m = 0.0; });
  add("paper scene, d 0.2 s/m", [](Scene& s) { s.model.damping_s_per_m = 0.2; });
  add("4 mm of 1 GPa, d 0.2 s/m", [](Scene& s) {
    s.covering = {999109940.49841368, 0.25, 0.0039910199699451044};
    s.model.damping_s_per_m = 0.2;
  });
  TimeIntegrator integrator;
  for (const NamedScene& named : scenes) {
    const ImpactModel base = ImpactModel::FromScene(named.scene);
    for (std::size_t segment = 1; segment < base.segment_count(); ++segment) {
      for (const double relative : {-1e-6, -1e-10, -1e-14, 0.0, 1e-16, 1e-14, 1e-12, 1e-10, 1e-8, 1e-6}) {
        const ImpactModel model = ImpactModel::FromScene(
            test::WithMaxPenetration(named.scene, base.segment(segment).start_m * (1.0 + relative)));
        const ImpactResult exact = SolveExact(model);
        REQUIRE(exact.ok());
        for (const double rtol : {1e-6, 1e-8}) {
          for (const ComputationMethod method : TimeIntegrationMethods()) {
            TimeIntegrationOptions options;
            options.method = method;
            options.relative_tolerance = rtol;
            options.force_extended_dynamics = true;
            const ImpactResult result = integrator.Simulate(model, options);
            INFO(named.name << ", δ_max at switch " << segment << " x (1 + " << relative << "), "
                            << ToString(method) << ", rtol " << rtol << ": " << result.message);
            CheckGrazingRun(model, result, exact, rtol, GrazingBound(method));
          }
        }
      }
    }
  }
}

TEST_CASE("Grazing a switch on the extended path: a braking robot and a neck", "[extended][grazing]") {
  // No exact path: the speed putting δ_max on the switch was found by bisection on the time
  // path at rtol 1e-12 (CVODE Adams), which is also the reference here.
  struct Case {
    std::string name;
    Scene scene;
    std::size_t segment;
    double speed_m_per_s;  // δ_max on the switch
  };
  Scene braking = PaperScene(0.015, 27.6e6, 0.22);
  braking.robot.braking_m_per_s2 = 50.0;
  braking.robot.reaction_delay_s = 0.002;
  Scene neck = PaperScene(0.015, 27.6e6, 0.22);
  neck.head.torso_mass_kg = 40.0;
  neck.head.neck_stiffness_N_per_m = 2e4;
  neck.head.neck_damping_N_s_per_m = 50.0;
  const Case cases[] = {{"braking 50 m/s² after 2 ms", braking, 1, 0.461751291027},
                        {"braking 50 m/s² after 2 ms", braking, 2, 2.69900615746},
                        {"neck", neck, 1, 0.24885881447},
                        {"neck", neck, 2, 2.49794572059}};
  TimeIntegrator integrator;
  for (const Case& c : cases) {
    for (const double relative : {-1e-7, -1e-11, 0.0, 1e-11, 1e-9, 1e-7}) {
      Scene scene = c.scene;
      scene.robot.speed_m_per_s = c.speed_m_per_s * (1.0 + relative);
      const ImpactModel model = ImpactModel::FromScene(scene);
      TimeIntegrationOptions reference_options;
      reference_options.method = ComputationMethod::kCvodeAdams;
      reference_options.relative_tolerance = 1e-12;
      const ImpactResult reference = integrator.Simulate(model, reference_options);
      REQUIRE(reference.ok());
      // The scene grazes the switch: δ_max within 1e-6 of it.
      CHECK(RelativeError(reference.peaks.max_penetration_m, model.segment(c.segment).start_m) < 1e-6);
      for (const double rtol : {1e-6, 1e-8}) {
        for (const ComputationMethod method : TimeIntegrationMethods()) {
          TimeIntegrationOptions options;
          options.method = method;
          options.relative_tolerance = rtol;
          const ImpactResult result = integrator.Simulate(model, options);
          INFO(c.name << ", switch " << c.segment << ", speed x (1 + " << relative << "), " << ToString(method)
                      << ", rtol " << rtol << ": " << result.message);
          CheckGrazingRun(model, result, reference, rtol, GrazingBound(method));
        }
      }
    }
  }
}
