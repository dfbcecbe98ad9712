// Re-timing (audit/retime.hpp, docs/model.md "Re-timing"): the FR3 pick move re-timed and
// audited again, against the uniform slow-down and the joints' limits; a one-joint arm against
// its closed-form time-optimal profile; a safe program unchanged; braking; the cycle-time sweep;
// the trajectory writer; bad input.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include <covopt/audit/retime.hpp>
#include <covopt/materials/body_regions.hpp>
#include <covopt/materials/catalog.hpp>
#include <covopt/optim/body_region_check.hpp>
#include <covopt/optim/design.hpp>
#include <covopt/robot/link_kinematics.hpp>
#include <covopt/robot/surface.hpp>
#include <covopt/robot/trajectory.hpp>

#include "../../bench/fr3_pick.hpp"
#include "../robot/robot_test_support.hpp"

namespace {

using covopt::ContactType;
using covopt::materials::BodyLimits;
using covopt::materials::BodyRegionTable;
namespace ca = covopt::audit;
namespace co = covopt::optim;
namespace rb = covopt::robot;
using covopt::robot::testing::MessageOf;

constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<BodyLimits> SomeRegions() {
  const auto& t = BodyRegionTable::BuiltIn();
  return {t.Limits("chest", "", ContactType::kTransient),
          t.Limits("hands-fingers", "palm-dominant", ContactType::kTransient),
          t.Limits("abdomen", "", ContactType::kTransient)};
}

/// The foam of Fr3AuditSetup (PORON 4701-30 320).
const co::CandidateMaterial& Foam() {
  static const co::CandidateMaterial foam = *Fr3AuditSetup(rb::RobotSurface{}).covering.material;
  return foam;
}

/// The FR3's surface at a coarse spacing (0.1 m: quick).
const rb::RobotSurface& CoarseSurface() {
  static const rb::RobotSurface surface = [] {
    rb::SurfaceOptions options;
    options.spacing_m = 0.1;
    return rb::SurfaceFromUrdfFile(kFr3Urdf, Fr3(), options);
  }();
  return surface;
}

/// The FR3 with `thickness_m` of PORON 4701-30 320 on every link, every transient region of
/// ISO/TS 15066 and the head (Fr3AuditSetup's, at another thickness).
ca::AuditSetup Fr3Setup(double thickness_m) {
  ca::AuditSetup setup = Fr3AuditSetup(CoarseSurface());
  setup.covering.covering = co::CoveringOf(*setup.covering.material, thickness_m, covopt::CoveringLaw::kAuto);
  return setup;
}

ca::RetimeOptions Fr3Options() {
  ca::RetimeOptions options;
  options.joint_acceleration_limits = Eigen::VectorXd::Constant(7, 10.0);
  options.keep_ratio_over_time = true;
  return options;
}

/// Every sample's safe speed scale of an audit kept over time: 1/(SF × the largest ratio).
std::vector<double> SampleScales(const ca::AuditResult& a, double sf) {
  std::vector<double> out(a.sample_count, kInf);
  for (std::size_t i = 0; i < a.sample_count; ++i) {
    double worst = 0.0;
    for (std::size_t l = 0; l < a.links.size(); ++l) worst = std::max(worst, a.ratio_over_time[i * a.links.size() + l]);
    if (worst > 0.0) out[i] = 1.0 / (sf * worst);
  }
  return out;
}

/// The joints' limits kept at every sample: speeds, and accelerations by finite differences of
/// the re-timed velocities (the parameterisation's own q̈ bound per segment end).
void CheckJointLimits(const ca::RetimeResult& r) {
  const rb::JointTrajectory& t = r.trajectory;
  for (std::size_t i = 0; i < t.size(); ++i) {
    for (Eigen::Index j = 0; j < t.velocities[i].size(); ++j) {
      CHECK(std::abs(t.velocities[i][j]) <= r.joint_speed_limits[j] * (1.0 + 1e-9));
      if (i + 1 == t.size()) continue;
      const double dt = t.time_s[i + 1] - t.time_s[i];
      REQUIRE(dt > 0.0);
      const double accel = (t.velocities[i + 1][j] - t.velocities[i][j]) / dt;
      CHECK(std::abs(accel) <= r.joint_acceleration_limits[j] * (1.0 + 1e-6));
    }
  }
}

}  // namespace

TEST_CASE("the FR3 pick re-timed is safe at every sample, and the re-audit agrees with the safe path speed",
          "[retime][fr3]") {
  const ca::AuditSetup setup = Fr3Setup(0.006);
  const ca::RetimeResult r = ca::Retime(setup, Pick(), Fr3Options());
  INFO(r.message);
  REQUIRE(r.status == ca::RetimeStatus::kSafe);
  REQUIRE(r.before.safe_speed_scale < 1.0);  // the program as given is unsafe
  CHECK(r.after.safe_speed_scale >= 1.0);  // an audit of the re-timed program alone says "safe"
  const std::vector<double> before = SampleScales(r.before, setup.rule.safety_factor);
  const std::vector<double> after = SampleScales(r.after, setup.rule.safety_factor);
  REQUIRE(after.size() == r.path_speed.size());
  for (std::size_t i = 0; i < after.size(); ++i) {
    CHECK(after[i] >= 1.0 - 1e-6);
    CHECK(r.path_speed[i] <= r.safe_path_speed[i] * (1.0 + 1e-9));
    CHECK(before[i] == Approx(r.safe_path_speed[i]).epsilon(1e-12));
    // Velocities scale by ṡ, directions and masses stay: the re-audit's scale × ṡ is ṡ_max.
    if (std::isfinite(after[i])) CHECK(after[i] * r.path_speed[i] == Approx(r.safe_path_speed[i]).epsilon(1e-9));
  }
  // Same positions, times from the profile, velocities q'(s) ṡ.
  const rb::JointTrajectory& t = r.trajectory;
  REQUIRE(t.size() == Pick().size());
  CHECK(t.source_name.find("(re-timed)") != std::string::npos);
  CHECK(t.time_s.back() - t.time_s.front() == Approx(r.cycle_time_s).epsilon(1e-12));
  for (std::size_t i = 0; i < t.size(); ++i) {
    CHECK(t.positions[i] == Pick().positions[i]);
    CHECK((t.velocities[i] - Pick().velocities[i] * r.path_speed[i]).norm() <= 1e-12);
  }
  CheckJointLimits(r);
  CHECK(r.original_cycle_time_s == Approx(1.5).epsilon(1e-12));
  CHECK(r.cycle_time_s <= r.uniform_cycle_time_s * (1.0 + 1e-9));
  CHECK(r.uniform_cycle_time_s == Approx(r.original_cycle_time_s / r.uniform_speed_scale).epsilon(1e-12));
  CHECK(r.uniform_speed_scale <= r.before.safe_speed_scale);
}

TEST_CASE("a limit local to one instant: the re-timed FR3 pick is strictly faster than the uniform slow-down",
          "[retime][fr3]") {
  // 20 mm: unsafe (0.95×) only around the fastest stretch of the move.
  const ca::AuditSetup setup = Fr3Setup(0.02);
  const ca::RetimeResult r = ca::Retime(setup, Pick(), Fr3Options());
  INFO(r.message);
  REQUIRE(r.status == ca::RetimeStatus::kSafe);
  // Unsafe, but only at a few samples around one instant.
  const auto slow = std::count_if(r.safe_path_speed.begin(), r.safe_path_speed.end(), [](double s) { return s < 1.0; });
  REQUIRE(r.before.safe_speed_scale < 1.0);
  REQUIRE(slow > 0);
  REQUIRE(slow < static_cast<long>(r.safe_path_speed.size()) / 3);
  CHECK(r.cycle_time_s < 0.97 * r.uniform_cycle_time_s);
  CHECK(r.cycle_time_s > r.original_cycle_time_s);
  CHECK(r.after.safe_speed_scale >= 1.0 - 1e-6);
  CheckJointLimits(r);
  // Where the program had to slow: a path-speed bound from the audit.
  CHECK(std::count(r.bound.begin(), r.bound.end(), co::PathSpeedBound::kPathSpeed) > 0);
}

TEST_CASE("a safe program with max_speed_scale 1 comes back unchanged", "[retime][safe]") {
  const ca::AuditSetup setup = Fr3Setup(0.04);
  ca::RetimeOptions options = Fr3Options();
  options.joint_acceleration_limits = Eigen::VectorXd::Constant(7, 1e3);  // the program's own keep them
  const ca::RetimeResult r = ca::Retime(setup, Pick(), options);
  INFO(r.message);
  REQUIRE(r.before.safe_speed_scale >= 1.0);
  REQUIRE(r.status == ca::RetimeStatus::kSafe);
  CHECK(r.cycle_time_s == Approx(r.original_cycle_time_s).epsilon(1e-9));
  CHECK(r.uniform_cycle_time_s == Approx(r.original_cycle_time_s).epsilon(1e-12));
  for (std::size_t i = 0; i < r.path_speed.size(); ++i) {
    CHECK(r.path_speed[i] == Approx(1.0).epsilon(1e-9));
    CHECK(r.trajectory.time_s[i] == Approx(Pick().time_s[i]).epsilon(1e-9).margin(1e-12));
  }
}

TEST_CASE("a covering refused at any speed leaves no safe timing: infeasible, naming the instant, link and region",
          "[retime][infeasible]") {
  ca::AuditSetup setup = Fr3Setup(0.01);
  setup.covering.material->name = "mystery foam";
  setup.covering.material->crush_behaviour = covopt::materials::CrushBehaviour::kUnknown;  // refused by the rule
  const ca::RetimeResult r = ca::Retime(setup, Pick(), Fr3Options());
  CHECK(r.status == ca::RetimeStatus::kInfeasible);
  CHECK_THAT(r.message, Catch::Contains("infeasible: at t = ") && Catch::Contains("has no safe speed against") &&
                            Catch::Contains("no timing is safe"));
  CHECK(r.trajectory.size() == 0);
  CHECK(std::isinf(r.cycle_time_s));
  CHECK(std::isinf(r.uniform_cycle_time_s));
}

namespace {

/// A one-joint arm about z ('arm', 1 kg at x = 0.2 m, a sphere of 4 cm at x = 0.3 m), its
/// joint limited to 3 rad/s in the URDF.
const std::string kArmUrdf = R"(<robot name="t"><link name="base"/>
  <joint name="j1" type="revolute"><parent link="base"/><child link="arm"/><origin xyz="0 0 0.1"/>
    <axis xyz="0 0 1"/><limit lower="-3" upper="3" effort="1" velocity="3"/></joint>
  <link name="arm"><inertial><mass value="1"/><origin xyz="0.2 0 0"/>
    <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.01" iyz="0" izz="0.01"/></inertial>
    <collision><origin xyz="0.3 0 0"/><geometry><sphere radius="0.04"/></geometry></collision></link></robot>)";

/// A rest-to-rest trapezoid of joint speed: accelerate at `alpha` to `omega`, cruise, decelerate;
/// sampled every `dt` from 0 to `duration` (exact positions and velocities).
rb::JointTrajectory Trapezoid(double alpha, double omega, double duration, double dt, double q0) {
  const double ta = omega / alpha;
  rb::JointTrajectory t;
  const int n = static_cast<int>(std::lround(duration / dt));
  for (int k = 0; k <= n; ++k) {
    const double s = k * dt;
    double q = 0.0, qd = 0.0;
    if (s < ta) {
      qd = alpha * s;
      q = 0.5 * alpha * s * s;
    } else if (s <= duration - ta) {
      qd = omega;
      q = 0.5 * omega * ta + omega * (s - ta);
    } else {
      const double left = duration - s;
      qd = alpha * left;
      q = omega * (duration - ta) - 0.5 * alpha * left * left;
    }
    t.time_s.push_back(s);
    t.positions.push_back(Eigen::VectorXd::Constant(1, q0 + q));
    t.velocities.push_back(Eigen::VectorXd::Constant(1, qd));
  }
  return t;
}

}  // namespace

TEST_CASE("a one-joint arm's re-timing is the closed-form time-optimal trapezoid", "[retime][closed-form]") {
  const rb::KinematicChain chain = rb::KinematicChain::FromUrdfString(kArmUrdf, {"", "arm"});
  rb::SurfaceOptions surface_options;
  surface_options.spacing_m = 0.02;
  ca::AuditSetup setup{chain, rb::SurfaceFromUrdfString(kArmUrdf, chain, surface_options)};
  setup.regions = SomeRegions();
  setup.covering.covering = {5e6, 0.3, 0.002};
  setup.head = covopt::Scene{};
  // The program: 10 rad/s² to 2.5 rad/s, 1 s in all; the joint may accelerate at 4 rad/s² only.
  const double alpha = 10.0, omega = 2.5, duration = 1.0, a = 4.0;
  const rb::JointTrajectory program = Trapezoid(alpha, omega, duration, 1e-3, -0.9);
  ca::RetimeOptions options;
  options.joint_acceleration_limits = Eigen::VectorXd::Constant(1, a);
  const ca::RetimeResult r = ca::Retime(setup, program, options);
  INFO(r.message);
  REQUIRE(r.status == ca::RetimeStatus::kSafe);
  CHECK(r.joint_speed_limits[0] == 3.0);  // the URDF's
  // The safe joint speed is one number: every point's v = ω ρ and mass I/ρ² are fixed.
  const double omega_safe = std::min(omega * r.before.safe_speed_scale, 3.0);
  REQUIRE(omega_safe < omega);
  const double travel = omega * (duration - omega / alpha);
  REQUIRE(omega_safe * omega_safe / a < travel);
  // Time-optimal: accelerate at a to ω_safe, cruise, decelerate at a: T = Δq/ω_s + ω_s/a.
  const double closed_form = travel / omega_safe + omega_safe / a;
  CHECK(r.cycle_time_s == Approx(closed_form).epsilon(2e-3));
  CHECK(r.cycle_time_s >= closed_form * (1.0 - 1e-9));  // nothing beats the optimum
  // The profile in joint space: q̇ = min(sqrt(2 a q), ω_s, sqrt(2 a (Δq - q))).
  for (std::size_t i = 0; i < program.size(); ++i) {
    const double q = program.positions[i][0] + 0.9;
    const double expected = std::min({std::sqrt(2.0 * a * q), omega_safe, std::sqrt(2.0 * a * std::max(0.0, travel - q))});
    CHECK(r.trajectory.velocities[i][0] == Approx(expected).margin(0.02 * omega_safe));
  }
  // The uniform slow-down: the audit's scale and the acceleration sqrt(a/α).
  CHECK(r.uniform_speed_scale == Approx(std::min(r.before.safe_speed_scale, std::sqrt(a / alpha))).epsilon(1e-9));
  CHECK(r.cycle_time_s < r.uniform_cycle_time_s);
}

TEST_CASE("a braking robot: each sample's braked safe path speed is at least the unbraked one, and the result is safe",
          "[retime][braking]") {
  // A thinned FR3 surface and every fifth sample: the braked limits are the time path's.
  // The braked models take a Hertz covering (the foam law's time path is not modelled); three
  // regions, every tenth point.
  ca::AuditSetup setup = Fr3Setup(0.006);
  setup.covering.covering = co::CoveringOf(Foam(), 0.006, covopt::CoveringLaw::kHertz);
  setup.regions = SomeRegions();
  setup.head.reset();
  for (rb::LinkSurface& link : setup.surface.links) {
    std::vector<rb::SurfacePoint> some;
    for (std::size_t p = 0; p < link.points.size(); p += 10) some.push_back(link.points[p]);
    link.points = some;
  }
  rb::JointTrajectory some_samples;
  for (std::size_t i = 0; i < Pick().size(); i += 5) {
    some_samples.time_s.push_back(Pick().time_s[i]);
    some_samples.positions.push_back(Pick().positions[i]);
    some_samples.velocities.push_back(Pick().velocities[i]);
  }
  const ca::RetimeResult unbraked = ca::Retime(setup, some_samples, Fr3Options());
  setup.reaction_delay_s = 0.002;
  setup.braking_m_per_s2 = 200.0;
  const ca::RetimeResult braked = ca::Retime(setup, some_samples, Fr3Options());
  INFO(braked.message);
  REQUIRE(unbraked.status == ca::RetimeStatus::kSafe);
  REQUIRE(braked.status == ca::RetimeStatus::kSafe);
  REQUIRE(braked.safe_path_speed.size() == unbraked.safe_path_speed.size());
  std::size_t raised = 0;
  for (std::size_t i = 0; i < braked.safe_path_speed.size(); ++i) {
    CHECK(braked.safe_path_speed[i] >= unbraked.safe_path_speed[i] * (1.0 - 1e-12));
    if (braked.safe_path_speed[i] > unbraked.safe_path_speed[i] * (1.0 + 1e-6)) ++raised;
  }
  CHECK(raised > 0);  // the brake does raise them
  // Against brute force at three samples: every point-sample and region judged braked.
  rb::ChainSampleKinematics kin(setup.chain);
  for (std::size_t i : {std::size_t{4}, std::size_t{10}, std::size_t{16}}) {
    kin.Update(some_samples.positions[i], some_samples.velocities[i]);
    double brute = kInf;
    for (const rb::LinkSurface& link : setup.surface.links) {
      for (const rb::SurfacePoint& point : link.points) {
        const rb::PointMotion m = kin.Point(*kin.LinkIndex(link.link), point.position_m);
        if (!m.moving || m.speed_m_per_s < 1e-6) continue;
        for (const BodyLimits& region : setup.regions) {
          covopt::BodyContactScene scene;
          scene.robot_mass_kg = m.reflected_mass_kg;
          scene.robot_radius_m = point.radius_of_curvature_m;
          scene.covering = setup.covering.covering;
          scene.reaction_delay_s = setup.reaction_delay_s;
          scene.braking_m_per_s2 = setup.braking_m_per_s2;
          const co::BodyRegionSpeedLimit limit =
              co::MaxSafeSpeed(scene, region, co::BodyRegionOptions{setup.rule, setup.covering.material, false});
          REQUIRE(limit.status != co::SpeedLimitStatus::kEvaluationFailed);
          brute = std::min(brute, limit.max_safe_speed_m_per_s / m.speed_m_per_s);
        }
      }
    }
    INFO("sample " << i);
    CHECK(braked.safe_path_speed[i] == Approx(brute).epsilon(1e-9));
  }
  CHECK(braked.after.safe_speed_scale >= 1.0 - 1e-6);  // the braked re-audit
  CHECK(braked.cycle_time_s <= unbraked.cycle_time_s * (1.0 + 1e-9));
  CHECK(braked.before.safe_speed_scale >= unbraked.before.safe_speed_scale);
}

TEST_CASE("cycle time against thickness: a foam's cycle time does not rise with its thickness, the bare point included",
          "[retime][sweep]") {
  ca::AuditSetup setup = Fr3Setup(0.01);
  setup.contact_area_m2 = 1e-4;  // the bare point's pressure
  setup.link_coverings["fr3_link7"] = setup.covering;
  const std::vector<ca::CycleTimeDesign> designs{{"PORON 4701-30 320", setup.covering, std::nullopt}};
  const std::vector<double> thicknesses{0.0, 0.004, 0.008, 0.012, 0.016};
  const std::vector<ca::CycleTimePoint> points =
      ca::CycleTimeAgainstThickness(setup, Pick(), Fr3Options(), designs, thicknesses);
  REQUIRE(points.size() == thicknesses.size());
  double previous = kInf;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const ca::CycleTimePoint& p = points[k];
    INFO(p.message);
    CHECK(p.design == 0);
    CHECK(p.thickness_m == thicknesses[k]);
    CHECK(p.message.find("per-link covering(s) replaced") != std::string::npos);
    if (p.status != ca::RetimeStatus::kSafe) continue;  // the bare link may have no safe speed
    CHECK(p.cycle_time_s <= previous * (1.0 + 1e-9));
    CHECK(p.cycle_time_s <= p.uniform_cycle_time_s * (1.0 + 1e-9));
    previous = p.cycle_time_s;
    // The same as Retime with that covering on every link.
    if (k == 2) {
      ca::AuditSetup at = setup;
      at.link_coverings.clear();
      at.covering.covering = co::CoveringOf(Foam(), thicknesses[k], covopt::CoveringLaw::kAuto);
      CHECK(ca::Retime(at, Pick(), Fr3Options()).cycle_time_s == Approx(p.cycle_time_s).epsilon(1e-12));
    }
  }
  CHECK(std::isfinite(previous));
  CHECK(points.back().cycle_time_s < points[1].cycle_time_s);  // it does fall
}

TEST_CASE("the per-link design's point of the cycle-time sweep runs at full speed", "[retime][sweep]") {
  const ca::AuditSetup setup = Fr3Setup(0.004);
  ca::AuditDesignOptions design;
  design.materials = {Foam()};
  ca::RetimeOptions options = Fr3Options();
  options.joint_acceleration_limits = Eigen::VectorXd::Constant(7, 1e3);
  const std::vector<ca::CycleTimeDesign> designs{{"per-link design", setup.covering, design}};
  const std::vector<ca::CycleTimePoint> points = ca::CycleTimeAgainstThickness(setup, Pick(), options, designs, {});
  REQUIRE(points.size() == 1);
  INFO(points[0].message);
  REQUIRE(points[0].status == ca::RetimeStatus::kSafe);
  CHECK(points[0].thickness_m > 0.0);
  CHECK(points[0].safe_speed_scale >= 1.0);
  CHECK(points[0].cycle_time_s == Approx(1.5).epsilon(1e-9));
}

TEST_CASE("WriteJointTrajectory round-trips through ReadJointTrajectory exactly", "[retime][writer]") {
  rb::JointTrajectory t = Pick();
  t.time_s[3] = std::nextafter(t.time_s[3], 1.0);  // a number whose shortest form needs 17 digits
  t.velocities[5][2] = -1.0 / 3.0;
  t.positions[7][6] = 2.5e-7;
  std::ostringstream out;
  rb::WriteJointTrajectory(out, t, Fr3().joint_names());
  CHECK(out.str().rfind("time_s,fr3_joint1,", 0) == 0);
  CHECK(out.str().find(",fr3_joint7_velocity\n") != std::string::npos);
  std::istringstream in(out.str());
  const rb::JointTrajectory back = rb::ReadJointTrajectory(in, 7, "written");
  REQUIRE(back.size() == t.size());
  CHECK(back.warnings.empty());  // the header was read as one
  for (std::size_t i = 0; i < t.size(); ++i) {
    CHECK(back.time_s[i] == t.time_s[i]);
    CHECK(back.positions[i] == t.positions[i]);
    CHECK(back.velocities[i] == t.velocities[i]);
  }
  std::ostringstream sink;
  CHECK_THAT(MessageOf([&] { rb::WriteJointTrajectory(sink, t, {"a", "b"}); }),
             Catch::Contains("trajectory sample 1") && Catch::Contains("2 joints"));
  t.velocities[4][0] = std::nan("");
  CHECK_THAT(MessageOf([&] { rb::WriteJointTrajectory(sink, t, Fr3().joint_names()); }),
             Catch::Contains("trajectory sample 5") && Catch::Contains("not a finite number"));
}

TEST_CASE("Retime refuses bad input in one line naming the field and the value", "[retime][bad-input]") {
  const ca::AuditSetup setup = Fr3Setup(0.01);
  const rb::JointTrajectory& pick = Pick();
  const auto refuses = [&](const ca::RetimeOptions& o, const std::string& field, const std::string& value) {
    const std::string message = MessageOf([&] { ca::Retime(setup, pick, o); });
    CHECK_THAT(message, Catch::Contains(field) && Catch::Contains(value));
  };
  ca::RetimeOptions o = Fr3Options();
  o.joint_acceleration_limits.reset();
  refuses(o, "joint_acceleration_limits", "none given");
  o = Fr3Options();
  o.joint_acceleration_limits = Eigen::VectorXd::Constant(6, 10.0);
  refuses(o, "joint_acceleration_limits has 6 entries", "7 joints");
  o.joint_acceleration_limits = Eigen::VectorXd::Constant(7, 10.0);
  (*o.joint_acceleration_limits)[2] = kInf;
  refuses(o, "joint_acceleration_limits[2]", "inf");
  (*o.joint_acceleration_limits)[2] = -1.0;
  refuses(o, "joint_acceleration_limits[2]", "-1");
  o = Fr3Options();
  o.joint_speed_limits = Eigen::VectorXd::Constant(7, 2.0);
  (*o.joint_speed_limits)[4] = std::nan("");
  refuses(o, "joint_speed_limits[4]", "nan");
  o.joint_speed_limits = Eigen::VectorXd::Constant(3, 2.0);
  refuses(o, "joint_speed_limits has 3 entries", "7 joints");
  o = Fr3Options();
  o.max_speed_scale = 0.0;
  refuses(o, "max_speed_scale must be in (0, 100]", "got 0");
  o.max_speed_scale = 101.0;
  refuses(o, "max_speed_scale", "101");
  o = Fr3Options();
  o.tolerance = 0.1;
  refuses(o, "tolerance must be in [0, 1e-2]", "0.1");
  rb::JointTrajectory one = pick;
  one.time_s.resize(1);
  one.positions.resize(1);
  one.velocities.resize(1);
  CHECK_THAT(MessageOf([&] { ca::Retime(setup, one, Fr3Options()); }), Catch::Contains("at least 2"));
  rb::JointTrajectory same = pick;
  same.time_s[10] = same.time_s[9];
  CHECK_THAT(MessageOf([&] { ca::Retime(setup, same, Fr3Options()); }),
             Catch::Contains("franka_fr3_pick.csv:") && Catch::Contains("0.135 s") &&
                 Catch::Contains("strictly increasing"));
  // What Audit refuses, Retime refuses.
  ca::AuditSetup no_regions = setup;
  no_regions.regions.clear();
  no_regions.head.reset();
  CHECK_THAT(MessageOf([&] { ca::Retime(no_regions, pick, Fr3Options()); }), Catch::Contains("regions"));
  // The sweep's own fields.
  const std::vector<ca::CycleTimeDesign> designs{{"foam", setup.covering, std::nullopt}};
  CHECK_THAT(MessageOf([&] { ca::CycleTimeAgainstThickness(setup, pick, Fr3Options(), designs, {0.01, -0.002}); }),
             Catch::Contains("thicknesses_m[1]") && Catch::Contains("-0.002"));
  CHECK_THAT(MessageOf([&] { ca::CycleTimeAgainstThickness(setup, pick, Fr3Options(), {}, {0.01}); }),
             Catch::Contains("designs"));
}
