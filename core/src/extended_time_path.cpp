// The extended time path of docs/model.md §10.2 and §10.3: robot, head and torso along the
// impact axis, Hunt-Crossley contact damping, a robot that brakes after a reaction delay and a
// head on a neck, integrated by any method of the Stepper abstraction (stepper.hpp, given this
// file's callbacks and a 7-entry vector) with events and a restart at every kink or jump of
// the right-hand side.
#include "extended_time_path.hpp"

#include <nvector/nvector_serial.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "fixed_length_vector.hpp"
#include "numeric_format.hpp"
#include "stepper.hpp"
#include "time_path_run.hpp"

namespace covopt::internal {
namespace {

/// Entries of the state vector.
enum StateEntry : int {
  kPenetration = 0,   // δ = x_r - x_b [m]
  kPenetrationRate,   // δ' [m/s]
  kHeadSpeed,         // v_b [m/s], in the frame where the head starts at rest
  kNeckStretch,       // q = x_b - x_t [m]; stays 0 without a neck
  kNeckStretchRate,   // q' = v_b - v_t [m/s]; stays 0 without a neck
  kEnergyDensity,     // e = ∫σ_c dδ [J/m²]
  kWork,              // W [J]: dampers, brake, a fixed robot's support
  kStateSize,
};

/// Root functions (the events of docs/model.md §10.2).
enum EventEntry : int {
  kUpperSwitch = 0,  // δ - end of the current segment, rising: restart in the next segment
  kLowerSwitch,      // δ - start of the current segment, falling: restart below, or separation
  kTurn,             // δ', falling: a maximum of δ
  kBrakeStart,       // t - t_d, rising, until the brake has started: restart braking
  kRobotStops,       // v_r, falling, while braking: restart without the brake
  kDampingClamp,     // 1 + d δ', either way: the Hunt-Crossley force reaches or leaves 0
  kForcePeak,        // dF/dt, falling (damping only): a maximum of F in time
  kStressPeak,       // dσ_c/dt, falling (damping only): a maximum of σ_c in time
  kEventCount,
};
constexpr std::array<int, kEventCount> kEventDirections{+1, -1, -1, +1, -1, 0, -1, -1};

constexpr double kHertzPressureFactor = 3.0 / (2.0 * std::numbers::pi);  // k = 3/(2π)

/// The bodies along the impact axis: robot, head, torso (in that order).
struct Bodies {
  Eigen::Vector3d inverse_mass = Eigen::Vector3d::Zero();   // [1/kg]; 0 fixed, or no torso
  Eigen::Vector3d moving_mass = Eigen::Vector3d::Zero();    // [kg]; 0 fixed, or no torso
  Eigen::Vector3d held = Eigen::Vector3d::Zero();           // 1 for a fixed body, else 0
  Eigen::Vector3d initial_speed = Eigen::Vector3d::Zero();  // [m/s]: (v0, 0, 0)
};

/// What the C callbacks see: the model, the bodies and where the integration is.
struct Run {
  const ImpactModel* model = nullptr;
  long segment = 0;  // index into the law, or kWholeLaw without restarts at the switches
  Bodies bodies;
  double damping_s_per_m = 0.0;
  double braking_m_per_s2 = 0.0;
  double reaction_delay_s = 0.0;
  bool has_neck = false;
  double neck_stiffness_N_per_m = 0.0;
  double neck_damping_N_s_per_m = 0.0;
  bool brake_pending = false;  // the robot brakes, but t_d has not come yet
  bool brake_on = false;       // braking now: t >= t_d and the robot still moving forward
  /// Floor on the phase-local penetration in dσ_el/dδ ~ x^(n-2), unbounded at a phase's start
  /// for n < 2, so the stress-peak root function stays finite [m].
  double slope_floor_m = 0.0;
};

/// The elastic law F_el, σ_el of the current segment at δ (continued past its ends, the
/// phase-local penetration clamped at 0), and with `slopes` its δ-derivatives.
struct ElasticLaw {
  double force_N = 0.0;
  double stress_Pa = 0.0;
  double stiffness_N_per_m = 0.0;
  double stress_slope_Pa_per_m = 0.0;
};

ElasticLaw ElasticLawAt(const Run& run, double delta, bool slopes) noexcept {
  const bool first = run.segment == 0 || run.segment == kWholeLaw;
  if (first && !(delta > 0.0)) return {};  // free flight
  const std::size_t i = run.segment == kWholeLaw ? run.model->SegmentIndexAt(delta)
                                                 : static_cast<std::size_t>(run.segment);
  const ForceLawSegment& seg = run.model->segment(i);
  const double n = seg.exponent;
  const double x = std::max(delta - seg.origin_m, 0.0);
  const double x_pow_nm1 = std::pow(x, n - 1.0);
  const double kc = kHertzPressureFactor * seg.stiffness * seg.curvature_per_m;
  ElasticLaw law;
  law.force_N = seg.force_offset_N + seg.stiffness * (x_pow_nm1 * x);
  law.stress_Pa = seg.stress_offset_Pa + kc * x_pow_nm1;
  if (slopes) {
    law.stiffness_N_per_m = n * seg.stiffness * x_pow_nm1;
    law.stress_slope_Pa_per_m = kc * (n - 1.0) * std::pow(std::max(x, run.slope_floor_m), n - 2.0);
  }
  return law;
}

/// Forces and motion at one state.
struct Dynamics {
  ElasticLaw law;
  double damping_factor = 1.0;  // 1 + d δ', before the clamp at 0
  double force_N = 0.0;         // F = F_el max(0, 1 + d δ')
  double stress_Pa = 0.0;       // σ_c = σ_el max(0, 1 + d δ')
  double brake_force_N = 0.0;   // B = m_r a on the robot, against its motion
  double neck_force_N = 0.0;    // on the torso, k_n q + c_n q' (the head gets minus this)
  Eigen::Vector3d velocity;     // robot, head, torso [m/s]
  Eigen::Vector3d force;        // on robot, head, torso [N]
  Eigen::Vector3d acceleration;  // [m/s²]; 0 for a fixed body
};

Dynamics Evaluate(const Run& run, const sunrealtype* y, bool slopes = false) noexcept {
  Dynamics d;
  d.law = ElasticLawAt(run, y[kPenetration], slopes);
  d.damping_factor = 1.0 + run.damping_s_per_m * y[kPenetrationRate];
  // Hunt-Crossley never pulls: at separation speeds above 1/d the force is 0, not negative.
  const double factor = std::max(d.damping_factor, 0.0);
  d.force_N = d.law.force_N * factor;
  d.stress_Pa = d.law.stress_Pa * factor;
  const double head = y[kHeadSpeed];
  d.velocity = Eigen::Vector3d(head + y[kPenetrationRate], head, head - y[kNeckStretchRate]);
  if (run.brake_on) d.brake_force_N = run.braking_m_per_s2 * run.bodies.moving_mass(0);
  if (run.has_neck) {
    d.neck_force_N = run.neck_stiffness_N_per_m * y[kNeckStretch] +
                     run.neck_damping_N_s_per_m * y[kNeckStretchRate];
  }
  d.force = Eigen::Vector3d(-d.force_N - d.brake_force_N, d.force_N - d.neck_force_N, d.neck_force_N);
  d.acceleration = run.bodies.inverse_mass.cwiseProduct(d.force);
  return d;
}

int ExtendedRightHandSide(sunrealtype /*t*/, N_Vector y, N_Vector ydot, void* user_data) {
  const auto& run = *static_cast<const Run*>(user_data);
  const sunrealtype* s = NV_DATA_S(y);
  sunrealtype* rate = NV_DATA_S(ydot);
  const Dynamics d = Evaluate(run, s);
  rate[kPenetration] = s[kPenetrationRate];
  rate[kPenetrationRate] = d.acceleration(0) - d.acceleration(1);
  rate[kHeadSpeed] = d.acceleration(1);
  rate[kNeckStretch] = run.has_neck ? s[kNeckStretchRate] : 0.0;
  rate[kNeckStretchRate] = run.has_neck ? d.acceleration(1) - d.acceleration(2) : 0.0;
  rate[kEnergyDensity] = d.stress_Pa * s[kPenetrationRate];
  // The power leaving the moving bodies other than into U and the neck spring: the contact
  // damper (F - F_el) δ', the neck damper c_n q'², the brake B v_r, and the force on a fixed
  // body times its (constant) speed, which is the work its support does.
  rate[kWork] = (d.force_N - d.law.force_N) * s[kPenetrationRate] +
                run.neck_damping_N_s_per_m * s[kNeckStretchRate] * s[kNeckStretchRate] +
                d.brake_force_N * d.velocity(0) +
                run.bodies.held.dot(d.force.cwiseProduct(d.velocity));
  for (int i = 0; i < kStateSize; ++i) {
    if (!std::isfinite(rate[i])) return 1;  // recoverable: the integrator retries smaller
  }
  return 0;
}

int ExtendedRootFunctions(sunrealtype t, N_Vector y, sunrealtype* g, void* user_data) {
  const auto& run = *static_cast<const Run*>(user_data);
  const sunrealtype* s = NV_DATA_S(y);
  const bool damped = run.damping_s_per_m > 0.0;
  const Dynamics d = Evaluate(run, s, damped);
  double lower = 0.0;
  double upper = std::numeric_limits<double>::infinity();
  if (run.segment != kWholeLaw) {
    const ForceLawSegment& seg = run.model->segment(static_cast<std::size_t>(run.segment));
    lower = seg.start_m;
    upper = seg.end_m;
  }
  g[kUpperSwitch] = std::isinf(upper) ? -1.0 : s[kPenetration] - upper;
  g[kLowerSwitch] = s[kPenetration] - lower;
  g[kTurn] = s[kPenetrationRate];
  g[kBrakeStart] = run.brake_pending ? t - run.reaction_delay_s : -1.0;
  g[kRobotStops] = run.brake_on ? d.velocity(0) : 1.0;
  g[kDampingClamp] = damped ? d.damping_factor : 1.0;
  if (damped && d.damping_factor > 0.0) {
    // d/dt [F_el(δ)(1 + d δ')] = F_el' δ' (1 + d δ') + F_el d δ'', and the same for σ.
    const double rate = s[kPenetrationRate];
    const double acceleration = d.acceleration(0) - d.acceleration(1);
    g[kForcePeak] = d.law.stiffness_N_per_m * rate * d.damping_factor +
                    d.law.force_N * run.damping_s_per_m * acceleration;
    g[kStressPeak] = d.law.stress_slope_Pa_per_m * rate * d.damping_factor +
                     d.law.stress_Pa * run.damping_s_per_m * acceleration;
  } else {
    g[kForcePeak] = -1.0;  // undamped: the peaks are the law's values at δ_max
    g[kStressPeak] = -1.0;
  }
  return 0;
}

/// (ΔK + U(δ) + ½ k_n q² + W) / (½ m v0²): zero for an exact solution (ImpactResult::
/// energy_residual).
double EnergyImbalance(const Run& run, const sunrealtype* y) noexcept {
  const Dynamics d = Evaluate(run, y);
  const Bodies& b = run.bodies;
  // ½ m (v - v0)(v + v0) per body, which keeps its accuracy for a heavy robot.
  const double kinetic_change =
      0.5 * b.moving_mass.dot((d.velocity - b.initial_speed).cwiseProduct(d.velocity + b.initial_speed));
  const double elastic = run.model->StateAt(y[kPenetration]).potential_energy_J;
  const double neck = 0.5 * run.neck_stiffness_N_per_m * y[kNeckStretch] * y[kNeckStretch];
  return (kinetic_change + elastic + neck + y[kWork]) / run.model->impact_energy_J();
}

/// The bodies and forces of `scene` for the callbacks (Run), at first contact.
void SetUpRun(const ImpactModel& model, bool restart_at_phase_switches, Run& run) {
  const Scene& scene = model.scene();
  run = Run{};
  run.model = &model;
  run.segment = restart_at_phase_switches ? 0 : kWholeLaw;
  const double v0 = model.impact_speed_m_per_s();
  const std::array<double, 3> masses{scene.robot.mass_kg, scene.head.mass_kg,
                                     scene.head.has_neck() ? scene.head.torso_mass_kg : 0.0};
  for (int i = 0; i < 3; ++i) {
    if (std::isinf(masses[static_cast<std::size_t>(i)])) {
      run.bodies.held(i) = 1.0;
    } else if (masses[static_cast<std::size_t>(i)] > 0.0) {
      run.bodies.moving_mass(i) = masses[static_cast<std::size_t>(i)];
      run.bodies.inverse_mass(i) = 1.0 / masses[static_cast<std::size_t>(i)];
    }
  }
  run.bodies.initial_speed = Eigen::Vector3d(v0, 0.0, 0.0);
  run.damping_s_per_m = scene.model.damping_s_per_m;
  const bool brakes = scene.robot_brakes();
  run.braking_m_per_s2 = scene.robot.braking_m_per_s2;
  run.reaction_delay_s = scene.robot.reaction_delay_s;
  run.brake_pending = brakes && run.reaction_delay_s > 0.0;
  run.brake_on = brakes && !run.brake_pending;  // the robot moves forward at first contact
  run.has_neck = scene.head.has_neck();
  run.neck_stiffness_N_per_m = scene.head.neck_stiffness_N_per_m;
  run.neck_damping_N_s_per_m = scene.head.neck_damping_N_s_per_m;
}

/// One run of the extended path: robot, head and torso, the events of docs/model.md §10.2
/// (a restart at every kink or jump of the right-hand side), the peaks over every maximum of
/// δ and, with damping, of F and σ_c in time, and the time bound on the contact.
class ExtendedRun final : public TimePathRun {
 public:
  ExtendedRun(const ImpactModel& model, const TimeIntegrationOptions& options, Stepper& stepper,
              Run& run, N_Vector state, N_Vector absolute_tolerances, N_Vector dense_output,
              const std::string& log)
      : TimePathRun(model, options, stepper, state, dense_output, log),
        run_(run),
        absolute_tolerances_(absolute_tolerances),
        v0_(model.impact_speed_m_per_s()),
        brakes_(model.scene().robot_brakes()) {
    SetUpRun(model, options.restart_at_phase_switches, run_);
    damped_ = run_.damping_s_per_m > 0.0;
    SetScales();
    SetTimeBound();
    for (int i = 0; i < kStateSize; ++i) y_[i] = 0.0;
    y_[kPenetrationRate] = v0_;
  }
  ~ExtendedRun() override { run_.model = nullptr; }

 private:
  /// Natural scales, as on the δ-only path: L from phase 1 alone, v0, the matching energy
  /// density, and the impact energy for the work.
  void SetScales() {
    const ForceLawSegment& first = model_.segment(0);
    const double p1 = first.exponent + 1.0;
    const double conservative_length_m =
        std::pow(p1 * model_.impact_energy_J() / first.stiffness, 1.0 / p1);
    // A braking robot travels at most v0 t_d + v0²/(2a), which bounds δ: far below L when the
    // brake stops it early (low speed, strong brake), and δ must stay above its tolerance.
    const double length_scale =
        brakes_ ? std::min(conservative_length_m,
                           v0_ * run_.reaction_delay_s + v0_ * v0_ / (2.0 * run_.braking_m_per_s2))
                : conservative_length_m;
    const double energy_density_scale = kHertzPressureFactor * first.stiffness *
                                        first.curvature_per_m *
                                        std::pow(length_scale, first.exponent) / first.exponent;
    time_scale_s_ = conservative_length_m / v0_;
    horizon_s_ = 1e3 * time_scale_s_;  // only orients the first step (one-step mode)
    run_.slope_floor_m = 1e-12 * length_scale;
    const double atol =
        options_.absolute_tolerance > 0.0 ? options_.absolute_tolerance : options_.relative_tolerance;
    sunrealtype* tolerance = N_VGetArrayPointer(absolute_tolerances_);
    tolerance[kPenetration] = atol * length_scale;
    tolerance[kPenetrationRate] = atol * v0_;
    tolerance[kHeadSpeed] = atol * v0_;
    tolerance[kNeckStretch] = atol * length_scale;
    tolerance[kNeckStretchRate] = atol * v0_;
    tolerance[kEnergyDensity] = atol * energy_density_scale;
    tolerance[kWork] = atol * model_.impact_energy_J();
  }

  /// The bound on the contact's length: 100 times the slower of the contact's own time
  /// (3 L/v0 ~ the conservative duration) and the neck's (a period of all moving masses on
  /// the neck spring, their time constant on its damper), after the reaction delay.
  void SetTimeBound() {
    double slowest_s = 3.0 * time_scale_s_;
    if (run_.has_neck) {
      const double total_mass_kg = run_.bodies.moving_mass.sum();
      if (run_.neck_stiffness_N_per_m > 0.0) {
        slowest_s = std::max(slowest_s, 2.0 * std::numbers::pi *
                                            std::sqrt(total_mass_kg / run_.neck_stiffness_N_per_m));
      }
      if (run_.neck_damping_N_s_per_m > 0.0) {
        slowest_s = std::max(slowest_s, total_mass_kg / run_.neck_damping_N_s_per_m);
      }
    }
    time_bound_s_ = (brakes_ ? run_.reaction_delay_s : 0.0) + 100.0 * slowest_s;
    neck_time_s_ = slowest_s > 3.0 * time_scale_s_ ? slowest_s : 0.0;
    inverse_reduced_mass_ = run_.bodies.inverse_mass(0) + run_.bodies.inverse_mass(1);
  }

  HistorySample Sample(double time, const sunrealtype* s) const override {
    const Dynamics d = Evaluate(run_, s);
    return {time, s[kPenetration], s[kPenetrationRate], d.force_N, d.stress_Pa, s[kEnergyDensity],
            d.velocity(0), d.velocity(1), d.neck_force_N, s[kWork]};
  }

  int Begin() override {
    int flag = stepper_.BeginRun(0.0, state_);  // a new run: nothing carried over
    if (flag == kStepTaken) flag = stepper_.SetInitStep(0.0);
    if (flag == kStepTaken) flag = stepper_.SetTolerances(options_.relative_tolerance, absolute_tolerances_);
    return flag;
  }

  int Restart() {
    CountRestart();
    int flag = stepper_.ReInit(t_, state_);
    if (flag == kStepTaken) flag = stepper_.SetInitStep(0.0);
    return flag;
  }

  /// With damping F and σ_c are tracked over the contact: at every step, every event (with
  /// the formulas on both sides of a switch) and at their own maxima in time.
  void TrackDampedPeaks() {
    if (!damped_) return;
    const Dynamics d = Evaluate(run_, y_);
    largest_force_N_ = std::max(largest_force_N_, d.force_N);
    largest_stress_Pa_ = std::max(largest_stress_Pa_, d.stress_Pa);
  }
  void CheckEnergy() { residual_ = std::max(residual_, std::abs(EnergyImbalance(run_, y_))); }

  /// From a maximum of δ or the robot's stop on, what is left of the contact depends on the
  /// state there, not on v0: a robot braked to rest early leaves a tiny δ that the elastic
  /// force alone unloads, slowly (from rest at δ, for F ~ δ^n, in a time ~ δ^((1-n)/2)). So
  /// the bound grows to 100 times the slower of the neck's time and 3 δ/v, v the relative
  /// speed that δ' and U(δ) give.
  void ExtendTimeBound() {
    const double potential_J = model_.StateAt(y_[kPenetration]).potential_energy_J;
    const double speed = std::sqrt(y_[kPenetrationRate] * y_[kPenetrationRate] +
                                   2.0 * potential_J * inverse_reduced_mass_);
    if (speed > 0.0) {
      time_bound_s_ =
          std::max(time_bound_s_, t_ + 100.0 * std::max(neck_time_s_, 3.0 * y_[kPenetration] / speed));
    }
  }

  void AfterStep() override { TrackDampedPeaks(); }

  bool PastTimeBound() override {
    timed_out_ = t_ > time_bound_s_;
    return timed_out_;
  }

  std::string TimeoutMessage() const override {
    return "the contact had not ended after " + FormatNumber(time_bound_s_) +
           " s (100 times the slower of 3 L/v0 and the neck's period or time constant" +
           std::string(brakes_ ? ", after the reaction delay" : "") +
           ", or from the last maximum compression" +
           std::string(brakes_ ? " or the robot's stop" : "") +
           " of that and 3 delta/v, v the relative speed from delta' and U(delta)): the "
           "bodies keep pressing";
  }

  /// A maximum of δ (δ_max is the largest); smooth here: no restart.
  void OnTurn() {
    CheckEnergy();
    largest_energy_density_ = std::max(largest_energy_density_, y_[kEnergyDensity]);
    if (!turned_ || y_[kPenetration] > max_penetration_m_) {
      turned_ = true;
      max_penetration_m_ = y_[kPenetration];
      segment_at_max_ = run_.segment == kWholeLaw ? model_.SegmentIndexAt(max_penetration_m_)
                                                  : static_cast<std::size_t>(run_.segment);
      time_at_max_s_ = t_;
    }
    ExtendTimeBound();
  }

  int OnRoot(const std::array<int, kMaxRootCount>& found) override {
    TrackDampedPeaks();  // also the maxima of F and σ_c in time (kForcePeak, kStressPeak)
    if (found[kTurn]) OnTurn();
    bool kink = false;
    if (found[kLowerSwitch]) {
      if (run_.segment == 0 || run_.segment == kWholeLaw) {
        Separate(v0_);
        CheckEnergy();
        return kRootFound;
      }
      --run_.segment;
      kink = true;
    } else if (found[kUpperSwitch]) {
      ++run_.segment;
      kink = true;
    }
    if (found[kBrakeStart]) {
      run_.brake_pending = false;
      run_.brake_on = Evaluate(run_, y_).velocity(0) > 0.0;
      kink = true;
    }
    if (found[kRobotStops]) {
      run_.brake_on = false;
      ExtendTimeBound();
      kink = true;
    }
    if (found[kDampingClamp]) kink = true;
    if (!kink) return kRootFound;
    TrackDampedPeaks();  // the new segment's formula at a switch (the literal law jumps)
    return Restart();
  }

  void Finish() override {
    result_.peaks = PeaksAtMaxPenetration(model_, segment_at_max_, max_penetration_m_);
    if (damped_) {  // the largest over the contact, which the loading branch holds
      result_.peaks.peak_force_N = largest_force_N_;
      result_.peaks.max_compressive_stress_Pa = largest_stress_Pa_;
      result_.peaks.max_tensile_stress_Pa = model_.TensileFromCompressive(largest_stress_Pa_);
      result_.peaks.max_energy_density_J_per_m2 = largest_energy_density_;
    }
    // Without damping e is a function of δ, and e_A,max is the law's value at δ_max (set by
    // PeaksAtMaxPenetration), as accurate as δ_max: the integrated e picks up the integrator's
    // error at every phase start (σ ~ x^(n-1)), up to 324 rtol for CVODE BDF at rtol 1e-6 on a
    // neck scene whose δ_max grazes t1 (docs/numerics.md), where δ_max was within 4 rtol.
    result_.time_of_max_compression_s = time_at_max_s_;
    FinishChecks(residual_, "energy residual (work accounted for)", "");
  }

  Run& run_;
  N_Vector absolute_tolerances_;
  const double v0_;
  const bool brakes_;
  bool damped_ = false;
  double time_scale_s_ = 0.0;
  double time_bound_s_ = 0.0;
  double neck_time_s_ = 0.0;
  double inverse_reduced_mass_ = 0.0;
  // The peaks so far.
  double max_penetration_m_ = 0.0;
  std::size_t segment_at_max_ = 0;
  double time_at_max_s_ = 0.0;
  double largest_energy_density_ = 0.0;  // e over every maximum of δ
  double largest_force_N_ = 0.0;
  double largest_stress_Pa_ = 0.0;
  double residual_ = 0.0;
};

}  // namespace

struct ExtendedTimePath::Workspace {
  Run run;
  StepperWorkspace steppers;
  explicit Workspace(SUNContext context) : steppers(context, kStateSize, Callbacks(run)) {}
  static StepperResources Callbacks(Run& run) {
    StepperResources resources;
    resources.user_data = &run;
    resources.rhs = ExtendedRightHandSide;
    resources.roots = ExtendedRootFunctions;
    resources.root_directions = kEventDirections;
    resources.jacobian = nullptr;  // the implicit methods use difference quotients
    return resources;
  }
};

ExtendedTimePath::ExtendedTimePath(SUNContext context)
    : workspace_(std::make_unique<Workspace>(context)) {}
ExtendedTimePath::~ExtendedTimePath() = default;

ImpactResult ExtendedTimePath::Simulate(const ImpactModel& model,
                                        const TimeIntegrationOptions& options) {
  Workspace& ws = *workspace_;
  StepperWorkspace& s = ws.steppers;
  s.log.clear();
  ExtendedRun run(model, options, s.StepperFor(options.method), ws.run, s.state, s.absolute_tolerances,
                  s.dense_output, s.log);
  return run.Integrate();
}

}  // namespace covopt::internal
