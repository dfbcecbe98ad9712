// TimeOptimalParameterization (optim/time_optimal_path.hpp): the closed-form bang-coast-bang
// profile of one joint, a dip in the path-speed bound entered at the acceleration limit, the
// joints' limits at every sample, a brute-force search that finds no faster profile, uniform
// scaling, the infeasible cases and every refused input.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/optim/time_optimal_path.hpp>

namespace {

namespace co = covopt::optim;
constexpr double kInf = std::numeric_limits<double>::infinity();

/// One joint, q(s) = s on [0, length] with `samples` evenly spaced samples.
co::PathSamples Line(double length, int samples) {
  co::PathSamples path;
  for (int i = 0; i < samples; ++i) {
    path.s.push_back(length * i / (samples - 1));
    path.dq_ds.push_back(Eigen::VectorXd::Constant(1, 1.0));
  }
  return path;
}

co::PathLimits OneJoint(std::size_t samples, double v, double a) {
  return {std::vector<double>(samples, kInf), Eigen::VectorXd::Constant(1, v), Eigen::VectorXd::Constant(1, a)};
}

co::TimeOptimalOptions RestToRest() {
  co::TimeOptimalOptions options;
  options.start_path_speed = 0.0;
  options.end_path_speed = 0.0;
  return options;
}

/// The time-optimal rest-to-rest duration of a distance L under |v| <= v_max, |a| <= a_max.
double BangCoastBang(double length, double v, double a) {
  return length >= v * v / a ? length / v + v / a : 2.0 * std::sqrt(length / a);
}

/// Three joints along q_j(s) = A_j sin(w_j s + p_j), s in [0, 2].
co::PathSamples Wave(int samples) {
  const double amplitude[] = {0.8, 0.5, 1.2}, rate[] = {2.0, 3.5, 1.3}, phase[] = {0.3, 1.1, -0.4};
  co::PathSamples path;
  for (int i = 0; i < samples; ++i) {
    const double s = 2.0 * i / (samples - 1);
    Eigen::VectorXd slope(3);
    for (int j = 0; j < 3; ++j) slope[j] = amplitude[j] * rate[j] * std::cos(rate[j] * s + phase[j]);
    path.s.push_back(s);
    path.dq_ds.push_back(slope);
  }
  return path;
}

/// The largest |q̈_j| at either end of segment i of a profile.
double SegmentAcceleration(const co::PathSamples& path, const co::TimeOptimalProfile& p, std::size_t i, Eigen::Index j) {
  const double ds = path.s[i + 1] - path.s[i];
  const double curvature = (path.dq_ds[i + 1][j] - path.dq_ds[i][j]) / ds;
  const double u = p.path_acceleration[i];
  const double x0 = p.path_speed[i] * p.path_speed[i];
  const double x1 = p.path_speed[i + 1] * p.path_speed[i + 1];
  return std::max(std::abs(path.dq_ds[i][j] * u + curvature * x0), std::abs(path.dq_ds[i + 1][j] * u + curvature * x1));
}

TEST_CASE("one joint from rest to rest takes the bang-coast-bang time, exactly when the switches fall on samples", "[topp]") {
  // L = 1, v = 0.5, a = 1: accelerate over 0.125, coast, brake over the last 0.125 (samples every 1/8).
  const co::PathSamples path = Line(1.0, 9);
  const co::TimeOptimalProfile p = co::TimeOptimalParameterization(path, OneJoint(9, 0.5, 1.0), RestToRest());
  REQUIRE(p.ok());
  CHECK(p.duration_s() == Approx(BangCoastBang(1.0, 0.5, 1.0)).epsilon(1e-12));
  CHECK(p.path_acceleration.front() == Approx(1.0).epsilon(1e-12));
  CHECK(p.path_acceleration.back() == Approx(-1.0).epsilon(1e-12));
  CHECK(p.bound.front() == co::PathSpeedBound::kBoundary);
  CHECK(p.bound[4] == co::PathSpeedBound::kJointSpeed);
  // Triangular: L = 1 < v²/a, peak at s = 0.5 (a sample).
  const co::TimeOptimalProfile t = co::TimeOptimalParameterization(path, OneJoint(9, 5.0, 2.0), RestToRest());
  REQUIRE(t.ok());
  CHECK(t.duration_s() == Approx(BangCoastBang(1.0, 5.0, 2.0)).epsilon(1e-12));
  CHECK(t.bound[4] == co::PathSpeedBound::kJointAcceleration);
}

TEST_CASE("one joint's duration converges to the closed form at second order in the sample spacing", "[topp]") {
  // Switches at s = v²/2a = 0.245 and 0.755, between samples for most spacings: the segment that
  // holds a switch is crossed a little slower (its u is below a), the time lost is O(Δs²). Where
  // a switch falls within its segment varies with the count, so take the worst of 8 counts.
  const double exact = BangCoastBang(1.0, 0.7, 1.0);
  std::vector<double> worst;
  for (const int base : {50, 100, 200, 400}) {
    double error = 0.0;
    for (int samples = base; samples < base + 8; ++samples) {
      const co::PathLimits limits = OneJoint(static_cast<std::size_t>(samples), 0.7, 1.0);
      const co::TimeOptimalProfile p = co::TimeOptimalParameterization(Line(1.0, samples), limits, RestToRest());
      REQUIRE(p.ok());
      CHECK(p.duration_s() >= exact * (1.0 - 1e-12));  // a discretised profile is never faster
      error = std::max(error, p.duration_s() - exact);
    }
    worst.push_back(error);
  }
  CHECK(worst.front() > 1e-4);  // the error is real at 50 samples
  for (std::size_t k = 1; k < worst.size(); ++k) {
    const double order = std::log2(worst[k - 1] / worst[k]);
    INFO("refinement " << k << ": worst error " << worst[k] << " s, observed order " << order);
    CHECK(order > 1.7);
    CHECK(order < 2.3);
  }
}

TEST_CASE("a dip in the path-speed bound is entered and left at exactly the acceleration limit", "[topp]") {
  const int samples = 201;
  const co::PathSamples path = Line(2.0, samples);
  co::PathLimits limits = OneJoint(samples, kInf, 0.5);
  for (int i = 0; i < samples; ++i) limits.max_path_speed[static_cast<std::size_t>(i)] = std::abs(path.s[static_cast<std::size_t>(i)] - 1.0) < 0.055 ? 0.3 : 1.0;
  const co::TimeOptimalProfile p = co::TimeOptimalParameterization(path, limits);
  REQUIRE(p.ok());
  int braking = 0, speeding = 0;
  for (std::size_t i = 0; i < p.path_speed.size(); ++i) {
    CHECK(p.path_speed[i] <= limits.max_path_speed[i] * (1.0 + 1e-12));
    if (i + 1 < p.path_speed.size()) {
      CHECK(std::abs(p.path_acceleration[i]) <= 0.5 * (1.0 + 1e-9));
      if (std::abs(p.path_acceleration[i] + 0.5) < 1e-9) ++braking;
      if (std::abs(p.path_acceleration[i] - 0.5) < 1e-9) ++speeding;
    }
  }
  // From 1 to 0.3 at 0.5: (1 - 0.09) / (2 * 0.5) = 0.91 of path, 91 segments of 0.01, each way.
  CHECK(braking == 91);
  CHECK(speeding == 91);
  CHECK(p.bound[100] == co::PathSpeedBound::kPathSpeed);
  CHECK(p.bound[60] == co::PathSpeedBound::kJointAcceleration);
  CHECK(p.path_speed.front() == Approx(1.0));
}

TEST_CASE("the joints' speed and acceleration limits hold at every sample and along every segment", "[topp]") {
  const co::PathSamples path = Wave(301);
  const co::PathLimits limits{std::vector<double>(301, 2.0), Eigen::Vector3d(1.0, 1.5, 0.8), Eigen::Vector3d(2.0, 4.0, 1.5)};
  const co::TimeOptimalProfile p = co::TimeOptimalParameterization(path, limits);
  REQUIRE(p.ok());
  bool joint_speed_binds = false, joint_accel_binds = false;
  for (std::size_t i = 0; i < 301; ++i) {
    for (Eigen::Index j = 0; j < 3; ++j) {
      CHECK(std::abs(path.dq_ds[i][j]) * p.path_speed[i] <= limits.max_joint_speed[j] * (1.0 + 1e-9));
      if (i + 1 == 301) continue;
      CHECK(SegmentAcceleration(path, p, i, j) <= limits.max_joint_acceleration[j] * (1.0 + 1e-9));
      // Independent: the mean acceleration over the segment's time from the joint speeds.
      const double dt = p.time_s[i + 1] - p.time_s[i];
      const double mean = (path.dq_ds[i + 1][j] * p.path_speed[i + 1] - path.dq_ds[i][j] * p.path_speed[i]) / dt;
      CHECK(std::abs(mean) <= limits.max_joint_acceleration[j] * (1.0 + 1e-9));
    }
    joint_speed_binds |= p.bound[i] == co::PathSpeedBound::kJointSpeed;
    joint_accel_binds |= p.bound[i] == co::PathSpeedBound::kJointAcceleration;
    CHECK(p.controllable_min[i] <= p.path_speed[i] * p.path_speed[i] * (1.0 + 1e-12));
    CHECK(p.path_speed[i] * p.path_speed[i] <= p.controllable_max[i] * (1.0 + 1e-12));
  }
  CHECK(joint_speed_binds);
  CHECK(joint_accel_binds);
  CHECK(std::is_sorted(p.time_s.begin(), p.time_s.end()));
}

TEST_CASE("a joint's turning point is passed at the speed its curvature allows, sqrt(a / q'')", "[topp]") {
  // q(s) = s² / 2 on [-1, 1]: q' = s, q'' = 1, the joint goes from 0.5 to 0 and back. At s = 0 it
  // stands still (no speed bound) but q̈ = q' s̈ + q'' ṡ² = ṡ² <= a caps ṡ at sqrt(a). Before it,
  // ṡ² > a would need s̈ >= (ṡ² - a) / |s| > 0 and could never come down: the joint's fastest
  // reversal is ṡ = sqrt(a) throughout (q̈ = a), 2 / sqrt(a) in all, exact on these samples.
  co::PathSamples path;
  for (int i = 0; i <= 20; ++i) {
    path.s.push_back(-1.0 + 0.1 * i);
    path.dq_ds.push_back(Eigen::VectorXd::Constant(1, path.s.back()));
  }
  path.s[10] = 0.0;
  path.dq_ds[10][0] = 0.0;
  for (const double a : {0.5, 2.0}) {
    const co::TimeOptimalProfile p = co::TimeOptimalParameterization(path, OneJoint(21, 3.0, a));
    REQUIRE(p.ok());
    CHECK(p.duration_s() == Approx(2.0 / std::sqrt(a)).epsilon(1e-12));
    for (std::size_t i = 0; i < 21; ++i) {
      CHECK(p.path_speed[i] == Approx(std::sqrt(a)).epsilon(1e-12));
      CHECK(p.bound[i] == co::PathSpeedBound::kJointAcceleration);  // the joint speed 3 is far
    }
  }
  CHECK(std::string(co::ToString(co::PathSpeedBound::kJointAcceleration)) == "joint-acceleration");
  CHECK(std::string(co::ToString(co::PathSpeedBound::kPathSpeed)) == "path-speed");
  CHECK(std::string(co::ToString(co::PathSpeedBound::kJointSpeed)) == "joint-speed");
  CHECK(std::string(co::ToString(co::PathSpeedBound::kBoundary)) == "boundary");
  CHECK(std::string(co::ToString(co::TimeOptimalStatus::kSuccess)) == "success");
}

/// Whether the profile x (ṡ² per sample) keeps every constraint; its duration if so.
double BruteDuration(const co::PathSamples& path, const co::PathLimits& limits, const std::vector<double>& x) {
  double time = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (std::sqrt(x[i]) > limits.max_path_speed[i]) return kInf;
    for (Eigen::Index j = 0; j < limits.max_joint_speed.size(); ++j) {
      if (std::abs(path.dq_ds[i][j]) * std::sqrt(x[i]) > limits.max_joint_speed[j]) return kInf;
    }
    if (i + 1 == x.size()) break;
    const double ds = path.s[i + 1] - path.s[i];
    const double u = (x[i + 1] - x[i]) / (2.0 * ds);
    for (Eigen::Index j = 0; j < limits.max_joint_speed.size(); ++j) {
      const double curvature = (path.dq_ds[i + 1][j] - path.dq_ds[i][j]) / ds;
      const double a = limits.max_joint_acceleration[j];
      if (std::abs(path.dq_ds[i][j] * u + curvature * x[i]) > a || std::abs(path.dq_ds[i + 1][j] * u + curvature * x[i + 1]) > a) {
        return kInf;
      }
    }
    const double sum = std::sqrt(x[i]) + std::sqrt(x[i + 1]);
    if (sum == 0.0) return kInf;
    time += 2.0 * ds / sum;
  }
  return time;
}

TEST_CASE("a dense grid search over a four-sample problem finds no faster profile", "[topp]") {
  co::PathSamples path;
  path.s = {0.0, 0.4, 0.7, 1.2};
  path.dq_ds = {Eigen::Vector2d(1.0, -0.5), Eigen::Vector2d(0.6, 0.8), Eigen::Vector2d(-0.3, 1.1), Eigen::Vector2d(-0.9, 0.4)};
  const co::PathLimits limits{{2.0, 1.5, 2.5, 2.0}, Eigen::Vector2d(1.2, 1.0), Eigen::Vector2d(1.5, 2.0)};
  co::TimeOptimalOptions options;
  options.start_path_speed = 0.0;
  const co::TimeOptimalProfile p = co::TimeOptimalParameterization(path, limits, options);
  REQUIRE(p.ok());
  std::vector<double> optimum(4);
  for (std::size_t i = 0; i < 4; ++i) optimum[i] = p.path_speed[i] * p.path_speed[i];
  CHECK(BruteDuration(path, limits, optimum) == Approx(p.duration_s()).epsilon(1e-6));  // the answer is feasible
  const int steps = 90;
  const double top = 4.0;  // ṡ <= 2 here
  double best = kInf;
  for (int a = 0; a <= steps; ++a) {
    for (int b = 0; b <= steps; ++b) {
      for (int c = 0; c <= steps; ++c) {
        const std::vector<double> x = {0.0, top * a / steps, top * b / steps, top * c / steps};
        best = std::min(best, BruteDuration(path, limits, x));
      }
    }
  }
  INFO("grid best " << best << " s, time-optimal " << p.duration_s() << " s");
  CHECK(best >= p.duration_s() * (1.0 - 1e-9));
  CHECK(best <= p.duration_s() * 1.05);  // and the grid comes close: the optimum is not conservative
}

TEST_CASE("when only a constant path-speed bound binds, the program is scaled uniformly", "[topp]") {
  const co::PathSamples path = Wave(101);
  for (const double c : {0.25, 0.6}) {
    const co::PathLimits limits{std::vector<double>(101, c), Eigen::Vector3d::Constant(100.0), Eigen::Vector3d::Constant(100.0)};
    const co::TimeOptimalProfile p = co::TimeOptimalParameterization(path, limits);
    REQUIRE(p.ok());
    CHECK(p.duration_s() == Approx(2.0 / c).epsilon(1e-12));
    for (const co::PathSpeedBound bound : p.bound) CHECK(bound == co::PathSpeedBound::kPathSpeed);
  }
}

TEST_CASE("random paths: limits kept, never slower than the fastest constant path speed", "[topp]") {
  // The fastest constant ṡ = c keeps every bound of the discretised problem (c <= the speed
  // bounds, and c² |q''| <= a on every segment), so the optimum's duration is at most L / c.
  std::mt19937 random(37);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const std::size_t samples = 30 + static_cast<std::size_t>(trial);
    co::PathSamples path;
    co::PathLimits limits{{}, Eigen::Vector3d(1.0, 2.0, 1.5), Eigen::Vector3d(3.0, 1.0, 5.0)};
    Eigen::Vector3d slope(unit(random), unit(random), unit(random));
    for (std::size_t i = 0; i < samples; ++i) {
      path.s.push_back(i == 0 ? 0.0 : path.s.back() + 0.02 + 0.05 * (1.0 + unit(random)));
      slope += 0.3 * Eigen::Vector3d(unit(random), unit(random), unit(random));
      if (i % 7 == 3) slope[trial % 3] = 1e-12;  // a joint almost at rest: a huge speed bound
      path.dq_ds.push_back(slope);
      limits.max_path_speed.push_back(i % 5 == 0 ? kInf : 1.0 + unit(random) * 0.8);
    }
    const co::TimeOptimalProfile p = co::TimeOptimalParameterization(path, limits);
    REQUIRE(p.ok());
    double c = kInf;
    for (std::size_t i = 0; i < samples; ++i) {
      c = std::min(c, limits.max_path_speed[i]);
      for (Eigen::Index j = 0; j < 3; ++j) {
        c = std::min(c, limits.max_joint_speed[j] / std::abs(path.dq_ds[i][j]));
        CHECK(std::abs(path.dq_ds[i][j]) * p.path_speed[i] <= limits.max_joint_speed[j] * (1.0 + 1e-9));
        if (i + 1 == samples) continue;
        CHECK(SegmentAcceleration(path, p, i, j) <= limits.max_joint_acceleration[j] * (1.0 + 1e-9));
        const double curvature = std::abs(path.dq_ds[i + 1][j] - path.dq_ds[i][j]) / (path.s[i + 1] - path.s[i]);
        c = std::min(c, std::sqrt(limits.max_joint_acceleration[j] / curvature));
      }
      CHECK(p.path_speed[i] <= limits.max_path_speed[i] * (1.0 + 1e-12));
      CHECK(std::isfinite(p.time_s[i]));
    }
    INFO("trial " << trial << ": " << p.duration_s() << " s against " << path.s.back() / c << " s at constant ṡ = " << c);
    CHECK(p.duration_s() <= path.s.back() / c * (1.0 + 1e-12));
    CHECK(p.duration_s() < path.s.back() / c * 0.99);  // and faster: the bounds vary along the path
  }
}

TEST_CASE("a path that cannot be kept is infeasible, and the message names where and why", "[topp]") {
  const co::PathSamples path = Line(1.0, 11);
  SECTION("too fast a start to stop by the end") {
    co::TimeOptimalOptions options = RestToRest();
    options.start_path_speed = 1.0;  // stopping needs 1 / (2 * 0.1) = 5 > 1
    const co::TimeOptimalProfile p = co::TimeOptimalParameterization(path, OneJoint(11, kInf, 0.1), options);
    CHECK_FALSE(p.ok());
    CHECK(std::string(co::ToString(p.status)) == "infeasible");
    CHECK_THAT(p.message, Catch::StartsWith("infeasible at sample 0 (s = 0)") && Catch::Contains("start_path_speed"));
    CHECK(p.path_speed.empty());
    CHECK(p.controllable_max[0] == Approx(0.2).epsilon(1e-9));  // ṡ² <= 2 a L
  }
  SECTION("an end speed that cannot be reached from a slow sample: an empty controllable set") {
    co::PathLimits limits = OneJoint(11, kInf, 0.1);
    limits.max_path_speed[9] = 0.1;
    co::TimeOptimalOptions options;
    options.end_path_speed = 1.0;  // from ṡ² <= 0.01 at sample 9, ṡ² gains at most 2 * 0.1 * 0.1
    const co::TimeOptimalProfile p = co::TimeOptimalParameterization(path, limits, options);
    CHECK_FALSE(p.ok());
    CHECK_THAT(p.message, Catch::StartsWith("infeasible at sample 9 (s = 0.9)") && Catch::Contains("controllable set is empty") &&
                              Catch::Contains("path-speed"));
  }
  SECTION("at rest at two neighbouring samples") {
    const co::TimeOptimalProfile p = co::TimeOptimalParameterization(Line(1.0, 2), OneJoint(2, 1.0, 1.0), RestToRest());
    CHECK_FALSE(p.ok());
    CHECK_THAT(p.message, Catch::StartsWith("infeasible at sample 0") && Catch::Contains("take forever"));
  }
  SECTION("no bound at all on a path where nothing moves") {
    co::PathSamples still = Line(1.0, 3);
    for (Eigen::VectorXd& slope : still.dq_ds) slope[0] = 0.0;
    const co::TimeOptimalProfile p = co::TimeOptimalParameterization(still, OneJoint(3, 1.0, 1.0));
    CHECK_FALSE(p.ok());
    CHECK_THAT(p.message, Catch::Contains("unbounded"));
  }
}

TEST_CASE("bad input is refused with the field and the value named", "[topp]") {
  const co::PathSamples good = Line(1.0, 3);
  const co::PathLimits limits = OneJoint(3, 1.0, 1.0);
  // Each case changes one input of a good problem; the message must name the field (and value).
  auto refuses = [&](const std::function<void(co::PathSamples&, co::PathLimits&, co::TimeOptimalOptions&)>& change,
                     const std::string& field) {
    co::PathSamples path = good;
    co::PathLimits lim = limits;
    co::TimeOptimalOptions options;
    change(path, lim, options);
    INFO("field " << field);
    CHECK_THROWS_WITH(co::TimeOptimalParameterization(path, lim, options), Catch::Contains(field));
  };
  using P = co::PathSamples;
  using L = co::PathLimits;
  using O = co::TimeOptimalOptions;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  refuses([](P& p, L& l, O&) { p = Line(1.0, 1); l = OneJoint(1, 1.0, 1.0); }, "path.s has 1 samples; it must have at least 2");
  refuses([](P& p, L&, O&) { p.dq_ds.pop_back(); }, "path.dq_ds has 2 entries");
  refuses([](P& p, L&, O&) { p.s[2] = 0.5; }, "path.s[2] = 0.5 must be > path.s[1]");
  refuses([&](P& p, L&, O&) { p.s[2] = nan; }, "path.s[2] = nan");
  refuses([](P& p, L&, O&) { p.dq_ds[1] = Eigen::Vector2d(1.0, 1.0); }, "path.dq_ds[1] has 2 entries");
  refuses([](P& p, L&, O&) { p.dq_ds[1][0] = kInf; }, "path.dq_ds[1][0] = inf");
  refuses([](P&, L& l, O&) { l.max_path_speed.pop_back(); }, "limits.max_path_speed has 2");
  refuses([](P&, L& l, O&) { l.max_joint_speed = Eigen::Vector2d(1.0, 1.0); }, "limits.max_joint_speed has 2");
  refuses([](P&, L& l, O&) { l.max_joint_acceleration = Eigen::Vector2d(1.0, 1.0); }, "limits.max_joint_acceleration has 2");
  for (const double bad : {0.0, -1.0, nan}) {
    const std::string value = " = " + std::string(std::isnan(bad) ? "nan" : bad == 0.0 ? "0" : "-1");
    refuses([&](P&, L& l, O&) { l.max_path_speed[1] = bad; }, "limits.max_path_speed[1]" + value);
    refuses([&](P&, L& l, O&) { l.max_joint_speed[0] = bad; }, "limits.max_joint_speed[0]" + value);
    refuses([&](P&, L& l, O&) { l.max_joint_acceleration[0] = bad; }, "limits.max_joint_acceleration[0]" + value);
    refuses([&](P&, L&, O& o) { o.tolerance = bad; }, "options.tolerance" + value);
  }
  refuses([](P&, L& l, O&) { l.max_joint_acceleration[0] = kInf; }, "limits.max_joint_acceleration[0] = inf");
  refuses([](P&, L&, O& o) { o.tolerance = 1e-2; }, "options.tolerance = 0.01 must be in (0, 1e-3]");
  refuses([](P&, L&, O& o) { o.start_path_speed = -0.1; }, "options.start_path_speed = -0.1");
  // above the joint's speed limit 1 at q' = 1
  refuses([](P&, L&, O& o) { o.end_path_speed = 1.5; }, "options.end_path_speed = 1.5 must be in [0, 1]");
}

}  // namespace
