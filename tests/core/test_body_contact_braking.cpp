// A braking robot in the body-region contact (docs/model.md §13.10): the robot brakes with a
// after its reaction delay t_d while it still moves forward. Checked: the inputs are the head
// scene's (same ranges, same words); only the time path answers (auto takes it, exact is
// refused); braking 0, or a brake that starts after the maximum, leaves the unbraked peaks; a
// bare robot's peak against the closed form of a spring with a constant force added at t_d;
// the energy closes along the history (kinetic energies, springs and the brake's work); every
// integrator agrees; the peaks fall with the brake and grow with the delay (dense scans).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <covopt/core/body_contact.hpp>
#include <covopt/core/impact_model.hpp>

namespace {

using covopt::BodyContactModel;
using covopt::BodyContactResult;
using covopt::BodyContactScene;
using covopt::ContactType;

/// A robot of `robot_mass` at `speed` on a region (k_H, m_H, contact), braking `a` after `t_d`.
BodyContactScene Braking(double robot_mass, double speed, double stiffness, double body_mass, ContactType contact,
                         double delay_s, double braking) {
  return {.robot_mass_kg = robot_mass,
          .speed_m_per_s = speed,
          .body_stiffness_N_per_m = stiffness,
          .body_mass_kg = body_mass,
          .contact = contact,
          .reaction_delay_s = delay_s,
          .braking_m_per_s2 = braking};
}

BodyContactScene WithCovering(BodyContactScene s, double modulus, double thickness, double radius) {
  s.covering = {modulus, 0.3, thickness};
  s.robot_radius_m = radius;
  return s;
}

/// Braking scenes: bare and covered, transient and clamped, the brake at contact or later,
/// coverings that bottom out. Table A.3: chest 25 kN/m, 40 kg; hand 75 kN/m, 0.6 kg.
std::vector<BodyContactScene> BrakingScenes() {
  using enum ContactType;
  const BodyContactScene chest = Braking(10.0, 1.0, 25e3, 40.0, kTransient, 5e-3, 100.0);
  const BodyContactScene hand_clamped = Braking(20.0, 0.5, 75e3, 0.6, kClamped, 2e-3, 40.0);
  return {
      chest,
      hand_clamped,
      Braking(3.0, 0.3, 150e3, 4.4, kTransient, 0.0, 500.0),
      WithCovering(chest, 0.5e6, 20e-3, 0.04),
      // Bottoms out: a very soft foam lets the robot travel 25 ms at 1 m/s before it brakes.
      WithCovering(Braking(10.0, 1.0, 25e3, 40.0, kTransient, 25e-3, 50.0), 1e3, 20e-3, 0.04),
      WithCovering(hand_clamped, 2e6, 10e-3, 0.03),
      WithCovering(hand_clamped, 0.2e6, 2e-3, 0.02),  // bottoms out
  };
}

covopt::SolveOptions TimePath(double rtol) {
  covopt::SolveOptions options;
  options.path = covopt::PathChoice::kTimePath;
  options.time_path.relative_tolerance = rtol;
  return options;
}

double Relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

std::string MessageOf(auto&& call) {
  try {
    call();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("the body contact's braking inputs are refused with the head scene's words", "[body_contact][braking]") {
  const double delay = GENERATE(-1e-3, 11.0, std::nan(""), 0.0);
  const double braking = GENERATE(-1.0, 2e4, std::nan(""), 100.0);
  const double robot_mass = GENERATE(10.0, covopt::kFixed);
  CAPTURE(delay, braking, robot_mass);
  BodyContactScene body = Braking(robot_mass, 0.5, 25e3, 40.0, ContactType::kTransient, delay, braking);
  covopt::Scene head;
  head.robot.mass_kg = robot_mass;
  head.robot.reaction_delay_s = delay;
  head.robot.braking_m_per_s2 = braking;
  const std::string body_message = MessageOf([&] { (void)BodyContactModel::FromScene(body); });
  const std::string head_message = MessageOf([&] { (void)covopt::ImpactModel::FromScene(head); });
  CHECK(body_message == head_message);
  const bool valid = delay == 0.0 && braking == 100.0 && std::isfinite(robot_mass);
  CHECK(body_message.empty() == valid);
  if (delay == 11.0 && braking == 100.0) {
    CHECK(body_message == "robot.reaction_delay must be 0 (brake at contact) or in [1e-06, 10] s (got 11)");
  }
  if (delay == 0.0 && braking == 100.0 && !std::isfinite(robot_mass)) {
    CHECK(body_message.starts_with("robot.braking needs a robot that moves: robot.mass is fixed"));
  }
}

TEST_CASE("a braking robot takes the time path under auto and is refused by the exact path", "[body_contact][braking]") {
  const BodyContactScene scene = BrakingScenes()[0];
  const BodyContactResult r = covopt::Solve(scene);
  REQUIRE(r.ok());
  CHECK(r.method == "time path (arkode-erk54, rtol 1e-08)");
  covopt::SolveOptions exact;
  exact.path = covopt::PathChoice::kExact;
  CHECK_THROWS_WITH(covopt::Solve(scene, exact),
                    Catch::Contains("path exact") && Catch::Contains("robot.braking (100 m/s2)") &&
                        Catch::Contains("only the time path"));
  // A reaction delay without braking is no brake: the exact path answers.
  BodyContactScene delay_only = scene;
  delay_only.braking_m_per_s2 = 0.0;
  CHECK(covopt::Solve(delay_only, exact).method == "exact");
  CHECK(covopt::Solve(delay_only).method == "exact");
}

TEST_CASE("braking 0, or a brake that starts after the maximum, leaves the unbraked peaks", "[body_contact][braking]") {
  const std::vector<BodyContactScene> scenes = BrakingScenes();
  const BodyContactScene& braked = scenes[static_cast<std::size_t>(GENERATE(range(0, 7)))];
  CAPTURE(braked.speed_m_per_s, braked.has_covering(), covopt::ToString(braked.contact));
  BodyContactScene unbraked = braked;
  unbraked.braking_m_per_s2 = 0.0;
  const covopt::SolveOptions options = TimePath(1e-10);
  const BodyContactResult exact = covopt::Solve(unbraked);
  const BodyContactResult plain = covopt::Solve(unbraked, options);
  REQUIRE(plain.ok());
  REQUIRE(plain.contact_duration_s.has_value());

  // Braking 0 with any delay: the unbraked time path itself.
  CHECK(plain.peak_force_N == covopt::Solve(unbraked, options).peak_force_N);

  // The brake starting after separation, and after the maximum but before separation.
  const double after_peak = GENERATE(0.55, 2.0);
  BodyContactScene late = braked;
  late.reaction_delay_s = after_peak * *plain.contact_duration_s;
  CAPTURE(late.reaction_delay_s);
  const BodyContactResult r = covopt::Solve(late, options);
  REQUIRE(r.ok());
  CHECK(Relative(r.peak_force_N, exact.peak_force_N) <= 1e-7);
  CHECK(Relative(r.max_approach_m, exact.max_approach_m) <= 1e-7);
  CHECK(Relative(r.peak_force_N, plain.peak_force_N) <= 1e-8);
  CHECK(r.fully_compressed == exact.fully_compressed);
  CHECK(Relative(r.energy_transferred_J, exact.energy_transferred_J) <= 1e-7);
  if (exact.peak_pressure_Pa) CHECK(Relative(*r.peak_pressure_Pa, *exact.peak_pressure_Pa) <= 1e-7);
  if (after_peak > 1.0) {
    // Never braked: the contact ends as the unbraked one does.
    REQUIRE(r.contact_duration_s.has_value());
    CHECK(Relative(*r.contact_duration_s, *plain.contact_duration_s) <= 1e-8);
    CHECK(Relative(r.rebound_speed_m_per_s, braked.speed_m_per_s) <= 1e-7);
  }
}

TEST_CASE("a bare robot's braked peak is the closed form of a spring with a constant force from t_d", "[body_contact][braking]") {
  // Until t_d: δ = (v0/ω) sin ωt. From t_d on, while the robot moves forward (up to the maximum
  // it does: v_R = v_H + δ' > 0), δ'' = -ω² δ - a, so δ + a/ω² oscillates about 0 and
  // δ_max = sqrt((δ_d + a/ω²)² + (δ'_d/ω)²) - a/ω²,  ω² = k_H/mu, F_max = k_H δ_max.
  const ContactType contact = GENERATE(ContactType::kTransient, ContactType::kClamped);
  const double braking = GENERATE(20.0, 300.0, 5000.0);
  const double delay_fraction = GENERATE(0.0, 0.3, 0.9);  // of the unbraked quarter period
  const double robot_mass = 8.0, speed = 0.7, stiffness = 75e3, body_mass = 0.6;
  const double mu = contact == ContactType::kClamped ? robot_mass : 1.0 / (1.0 / robot_mass + 1.0 / body_mass);
  const double omega = std::sqrt(stiffness / mu);
  const double delay = delay_fraction * std::numbers::pi / (2.0 * omega);
  CAPTURE(covopt::ToString(contact), braking, delay);
  const double offset = braking / (omega * omega);
  const double at_delay = speed / omega * std::sin(omega * delay);
  const double rate_at_delay = speed * std::cos(omega * delay);
  const double expected = std::hypot(at_delay + offset, rate_at_delay / omega) - offset;
  const BodyContactResult r =
      covopt::Solve(Braking(robot_mass, speed, stiffness, body_mass, contact, delay, braking), TimePath(1e-11));
  REQUIRE(r.ok());
  CHECK(Relative(r.max_approach_m, expected) <= 1e-8);
  CHECK(Relative(r.peak_force_N, stiffness * expected) <= 1e-8);
  CHECK(r.energy_transferred_J == Approx(0.5 * r.peak_force_N * r.max_approach_m).epsilon(1e-12));
  CHECK(r.peak_force_N < speed * std::sqrt(mu * stiffness));  // below Annex A's unbraked force
}

TEST_CASE("the energy closes along a braking robot's history: kinetic, springs and the brake's work", "[body_contact][braking]") {
  const std::vector<BodyContactScene> scenes = BrakingScenes();
  const BodyContactScene& scene = scenes[static_cast<std::size_t>(GENERATE(range(0, 7)))];
  const double rtol = GENERATE(1e-8, 1e-10);
  CAPTURE(scene.speed_m_per_s, scene.has_covering(), covopt::ToString(scene.contact), rtol);
  const BodyContactModel model = BodyContactModel::FromScene(scene);
  covopt::SolveOptions options = TimePath(rtol);
  options.record_history = true;
  options.history_samples_per_contact = 200.0;
  const BodyContactResult r = covopt::Solve(model, options);
  REQUIRE(r.ok());
  REQUIRE(r.history.size() >= 100);
  const bool clamped = scene.contact == ContactType::kClamped;
  const double m_r = scene.robot_mass_kg, m_h = scene.body_mass_kg, v0 = scene.speed_m_per_s;
  const double initial = 0.5 * m_r * v0 * v0;  // in the frame where the region starts at rest
  double imbalance = 0.0, largest_work = 0.0, largest_force = 0.0;
  for (const covopt::BodyContactSample& s : r.history) {
    const double body_speed = clamped ? 0.0 : s.robot_speed_m_per_s - s.approach_rate_m_per_s;
    if (clamped) CHECK(s.robot_speed_m_per_s == s.approach_rate_m_per_s);  // the region cannot move
    const double kinetic = 0.5 * m_r * s.robot_speed_m_per_s * s.robot_speed_m_per_s + 0.5 * m_h * body_speed * body_speed;
    imbalance = std::max(imbalance, std::abs(kinetic + model.EnergyAtForce(s.force_N) + s.braking_work_J - initial));
    CHECK(s.braking_work_J >= 0.0);
    largest_work = std::max(largest_work, s.braking_work_J);
    largest_force = std::max(largest_force, s.force_N);
  }
  CHECK(imbalance <= 100.0 * rtol * initial);
  CHECK(largest_work > 0.0);  // the brake did act
  CHECK(largest_work <= initial);
  CHECK(Relative(largest_force, r.peak_force_N) <= 1e-12);
  // The springs hold less than ½ mu v0² at the peak: the brake took the rest.
  CHECK(r.energy_transferred_J < model.impact_energy_J());
  CHECK(r.energy_transferred_J == Approx(r.body_energy_J + r.covering_energy_J).epsilon(1e-14));
  // The brake lets go where the robot stops: it never drives the robot backwards.
  for (std::size_t i = 1; i < r.history.size(); ++i) {
    if (r.history[i - 1].robot_speed_m_per_s <= 0.0) {
      CHECK(r.history[i].braking_work_J == Approx(r.history[i - 1].braking_work_J).margin(1e-12 * initial));
    }
  }
}

TEST_CASE("the braking scenes include coverings that bottom out, and the restart keeps the brake", "[body_contact][braking]") {
  int bottomed = 0;
  for (const BodyContactScene& scene : BrakingScenes()) {
    const BodyContactResult r = covopt::Solve(scene, TimePath(1e-8));
    REQUIRE(r.ok());
    bottomed += r.fully_compressed ? 1 : 0;
    BodyContactScene unbraked = scene;
    unbraked.braking_m_per_s2 = 0.0;
    CHECK(r.peak_force_N < covopt::Solve(unbraked).peak_force_N);
  }
  CHECK(bottomed == 2);
}

TEST_CASE("every integrator agrees on a braking robot's peaks", "[body_contact][braking]") {
  using covopt::ComputationMethod;
  const ComputationMethod method =
      GENERATE(ComputationMethod::kCvodeAdams, ComputationMethod::kCvodeBdf, ComputationMethod::kArkodeErk32,
               ComputationMethod::kArkodeErk87, ComputationMethod::kArkodeSdirk43, ComputationMethod::kArkodeEsdirk54);
  const std::vector<BodyContactScene> scenes = BrakingScenes();
  const BodyContactScene& scene = scenes[static_cast<std::size_t>(GENERATE(0, 3, 4, 6))];
  CAPTURE(covopt::ToString(method), scene.speed_m_per_s, scene.has_covering());
  covopt::SolveOptions options = TimePath(1e-10);
  const BodyContactResult reference = covopt::Solve(scene, TimePath(1e-12));
  options.time_path.method = method;
  const BodyContactResult r = covopt::Solve(scene, options);
  REQUIRE(reference.ok());
  REQUIRE(r.ok());
  CHECK(Relative(r.peak_force_N, reference.peak_force_N) <= 1e-6);
  CHECK(Relative(r.max_approach_m, reference.max_approach_m) <= 1e-6);
  CHECK(Relative(r.rebound_speed_m_per_s, reference.rebound_speed_m_per_s) <= 1e-5);
}

TEST_CASE("a braking robot's peaks fall with the brake and grow with the delay (dense scans)", "[body_contact][braking]") {
  const std::vector<BodyContactScene> scenes = BrakingScenes();
  const BodyContactScene& scene = scenes[static_cast<std::size_t>(GENERATE(range(0, 7)))];
  CAPTURE(scene.speed_m_per_s, scene.has_covering(), covopt::ToString(scene.contact));
  const covopt::SolveOptions options = TimePath(1e-10);
  constexpr double kJitter = 1e-8;  // relative: the integrator's, far below the trends
  const auto peaks = [&](const BodyContactScene& s) {
    const BodyContactResult r = covopt::Solve(s, options);
    REQUIRE(r.ok());
    return r;
  };
  // The brake from 0.1 to 1e4 m/s², 120 points.
  BodyContactScene s = scene;
  BodyContactResult previous = peaks([&] { BodyContactScene z = scene; z.braking_m_per_s2 = 0.0; return z; }());
  for (int i = 0; i <= 120; ++i) {
    s.braking_m_per_s2 = 0.1 * std::pow(1e5, i / 120.0);
    const BodyContactResult r = peaks(s);
    CAPTURE(s.braking_m_per_s2);
    CHECK(r.peak_force_N <= previous.peak_force_N * (1.0 + kJitter));
    CHECK(r.max_approach_m <= previous.max_approach_m * (1.0 + kJitter));
    if (r.peak_pressure_Pa) CHECK(*r.peak_pressure_Pa <= *previous.peak_pressure_Pa * (1.0 + kJitter));
    previous = r;
  }
  // The delay from 0 to past the contact, 120 points: up to the unbraked peaks.
  BodyContactScene unbraked = scene;
  unbraked.braking_m_per_s2 = 0.0;
  const BodyContactResult free_contact = peaks(unbraked);
  s = scene;
  s.reaction_delay_s = 0.0;
  previous = peaks(s);
  for (int i = 1; i <= 120; ++i) {
    s.reaction_delay_s = 1.2 * *free_contact.contact_duration_s * i / 120.0;
    const BodyContactResult r = peaks(s);
    CAPTURE(s.reaction_delay_s);
    CHECK(r.peak_force_N >= previous.peak_force_N * (1.0 - kJitter));
    CHECK(r.max_approach_m >= previous.max_approach_m * (1.0 - kJitter));
    CHECK(r.peak_force_N <= free_contact.peak_force_N * (1.0 + kJitter));
    previous = r;
  }
  CHECK(Relative(previous.peak_force_N, free_contact.peak_force_N) <= 1e-8);
}

TEST_CASE("a braking robot's failed run is a status, not peaks", "[body_contact][braking]") {
  covopt::SolveOptions options = TimePath(1e-10);
  options.time_path.max_steps = 10;
  const BodyContactResult r = covopt::Solve(BrakingScenes()[3], options);
  CHECK(r.status == covopt::SolveStatus::kStepLimit);
  CHECK(r.peak_force_N == 0.0);
  CHECK_FALSE(r.peak_pressure_Pa.has_value());
}

TEST_CASE("the time path to the peak gives the full run's peaks to the bit, without duration or rebound",
          "[body_contact][braking]") {
  std::vector<BodyContactScene> scenes = BrakingScenes();
  for (const BodyContactScene& braked : BrakingScenes()) {
    BodyContactScene unbraked = braked;
    unbraked.braking_m_per_s2 = 0.0;
    scenes.push_back(unbraked);
  }
  for (const BodyContactScene& scene : scenes) {
    CAPTURE(scene.speed_m_per_s, scene.has_covering(), scene.braking_m_per_s2);
    const BodyContactModel model = BodyContactModel::FromScene(scene);
    const BodyContactResult full = covopt::Solve(model, TimePath(1e-8));
    const BodyContactResult peak = covopt::SolveBodyContactPeaks(model);
    REQUIRE(full.ok());
    REQUIRE(peak.ok());
    CHECK(peak.method == full.method);
    CHECK(peak.peak_force_N == full.peak_force_N);
    CHECK(peak.max_approach_m == full.max_approach_m);
    CHECK(peak.peak_pressure_Pa == full.peak_pressure_Pa);
    CHECK(peak.compression_ratio == full.compression_ratio);
    CHECK(peak.fully_compressed == full.fully_compressed);
    CHECK(peak.energy_transferred_J == full.energy_transferred_J);
    CHECK_FALSE(peak.contact_duration_s.has_value());
    CHECK(peak.rebound_speed_m_per_s == 0.0);
  }
  covopt::TimeIntegrationOptions few;
  few.max_steps = 10;
  const BodyContactResult failed = covopt::SolveBodyContactPeaks(BodyContactModel::FromScene(scenes[3]), few);
  CHECK(failed.status == covopt::SolveStatus::kStepLimit);
  CHECK(failed.message == "step limit of 10 steps reached before maximum compression");
  few.relative_tolerance = 1.0;
  CHECK_THROWS_WITH(covopt::SolveBodyContactPeaks(BodyContactModel::FromScene(scenes[3]), few),
                    Catch::StartsWith("time_path.relative_tolerance"));
}
