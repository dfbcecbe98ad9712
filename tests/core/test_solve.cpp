// Solve chooses the path by one rule (Scene::has_energy_integral()): the exact path for the
// conservative and the damped two-mass contact, the time path for a braking robot, a neck or a
// history; each answer is the chosen path's own, bit for bit. A history is sampled at least
// history_samples_per_contact times over the contact. A refused path and bad options are
// std::invalid_argument naming the option.
#include <catch2/catch.hpp>

#include <string>

#include "covopt/core/solve.hpp"
#include "test_helpers.hpp"

using namespace covopt;
using Catch::Matchers::Contains;

namespace {

Scene Braking() {
  Scene scene;
  scene.robot.braking_m_per_s2 = 50.0;
  scene.robot.reaction_delay_s = 1e-3;
  return scene;
}

Scene Neck() {
  Scene scene;
  scene.head.torso_mass_kg = 30.0;
  scene.head.neck_stiffness_N_per_m = 1e4;
  return scene;
}

Scene Damped() {
  Scene scene;
  scene.model.damping_s_per_m = 0.5;
  return scene;
}

void CheckSame(const ImpactResult& a, const ImpactResult& b) {
  CHECK(a.method == b.method);
  CHECK(a.status == b.status);
  CHECK(a.peaks.max_penetration_m == b.peaks.max_penetration_m);
  CHECK(a.peaks.peak_force_N == b.peaks.peak_force_N);
  CHECK(a.peaks.max_energy_density_J_per_m2 == b.peaks.max_energy_density_J_per_m2);
  CHECK(a.contact_duration_s == b.contact_duration_s);
  CHECK(a.rebound_speed_m_per_s == b.rebound_speed_m_per_s);
  CHECK(a.statistics.steps == b.statistics.steps);
  CHECK(a.history.size() == b.history.size());
  CHECK(a.WarningMessages() == b.WarningMessages());
}

}  // namespace

TEST_CASE("the rule: an energy integral without braking or a neck", "[solve]") {
  CHECK(Scene{}.has_energy_integral());
  CHECK(Damped().has_energy_integral());
  CHECK_FALSE(Braking().has_energy_integral());
  CHECK_FALSE(Neck().has_energy_integral());
  CHECK(Scene{}.is_conservative_two_mass());
  CHECK_FALSE(Damped().is_conservative_two_mass());
}

TEST_CASE("Solve takes the exact path where the scene has an energy integral", "[solve]") {
  for (const Scene& scene : {Scene{}, Damped()}) {
    const ImpactModel model = ImpactModel::FromScene(scene);
    CHECK(ChoosePath(scene, {}) == PathChoice::kExact);
    const ImpactResult solved = Solve(scene);
    CHECK(solved.method == ComputationMethod::kExact);
    CheckSame(solved, SolveExact(model));
    SolveOptions no_duration;
    no_duration.exact.compute_duration = false;
    CHECK_FALSE(Solve(model, no_duration).contact_duration_s.has_value());
  }
}

TEST_CASE("Solve takes the time path for braking, a neck, a history or when asked", "[solve]") {
  for (const Scene& scene : {Braking(), Neck()}) {
    CHECK(ChoosePath(scene, {}) == PathChoice::kTimePath);
    SolveOptions options;
    options.time_path.method = ComputationMethod::kCvodeAdams;
    const ImpactResult solved = Solve(scene, options);
    REQUIRE(solved.ok());
    CheckSame(solved, SimulateImpact(ImpactModel::FromScene(scene), options.time_path));
  }
  SolveOptions asked;
  asked.path = PathChoice::kTimePath;
  CHECK(ChoosePath(Scene{}, asked) == PathChoice::kTimePath);
  CheckSame(Solve(Scene{}, asked), SimulateImpact(ImpactModel::FromScene(Scene{})));
  SolveOptions history;
  history.record_history = true;
  CHECK(ChoosePath(Scene{}, history) == PathChoice::kTimePath);
}

TEST_CASE("a history is sampled history_samples_per_contact times over the contact", "[solve]") {
  for (const Scene& scene : {Scene{}, Damped(), Braking()}) {
    const ImpactModel model = ImpactModel::FromScene(scene);
    SolveOptions options;
    options.record_history = true;
    const ImpactResult solved = Solve(model, options);
    REQUIRE(solved.ok());
    REQUIRE(solved.history.size() >= 400u);
    const double spacing = *solved.contact_duration_s / 400.0;
    for (std::size_t i = 1; i < solved.history.size(); ++i) {
      CHECK(solved.history[i].time_s - solved.history[i - 1].time_s <= spacing * (1 + 1e-6));
    }
    // The same as the time path with that spacing: the exact duration of a conservative
    // scene, else a first run's.
    TimeIntegrationOptions time;
    time.record_history = true;
    time.history_max_interval_s = (scene.is_conservative_two_mass()
                                       ? ExactContactDuration(model, ExactPeaks(model))
                                       : *SimulateImpact(model).contact_duration_s) /
                                  400.0;
    CheckSame(solved, SimulateImpact(model, time));
    // 0: the internal steps and events only.
    options.history_samples_per_contact = 0.0;
    time.history_max_interval_s = 0.0;
    CheckSame(Solve(model, options), SimulateImpact(model, time));
  }
}

TEST_CASE("Solve refuses the exact path where it cannot answer, and bad options", "[solve]") {
  SolveOptions exact;
  exact.path = PathChoice::kExact;
  CHECK_THROWS_WITH(Solve(Braking(), exact), Contains("energy integral") && Contains("robot.braking"));
  CHECK_THROWS_WITH(ChoosePath(Neck(), exact), Contains("energy integral") && Contains("head.torso_mass"));
  exact.record_history = true;
  CHECK_THROWS_WITH(Solve(Scene{}, exact), Contains("computes no time history") && Contains("record_history"));
  SolveOptions bad;
  bad.history_samples_per_contact = -1.0;
  CHECK_THROWS_WITH(Solve(Scene{}, bad), "history_samples_per_contact must be a finite number >= 0 (got -1)");
  bad = {};
  bad.path = PathChoice::kTimePath;
  bad.time_path.relative_tolerance = 1.0;
  CHECK_THROWS_WITH(Solve(Scene{}, bad), "time_path.relative_tolerance must be in [1e-14, 1e-2] (got 1)");
  Scene invalid;
  invalid.head.radius_m = 0.001;
  CHECK_THROWS_WITH(Solve(invalid), Contains("head.radius"));
  CHECK(ToString(PathChoice::kTimePath) == "time-path");
}
