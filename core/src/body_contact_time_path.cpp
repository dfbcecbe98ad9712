// The time path of the body-contact model (body_contact_time_path.hpp): the covering and the
// body spring in series, integrated in the covering's (or the body's) deflection so that F(δ)
// is never inverted, by any integrator of the Stepper abstraction (stepper.hpp) on a 2-entry
// state, with a restart where the covering bottoms out and where it comes back. A braking
// robot (docs/model.md §13.10) adds the robot's own speed and the brake's work to the state
// (4 entries, a workspace of its own) and restarts where the brake starts and where the robot
// stops.
#include "body_contact_time_path.hpp"

#include <nvector/nvector_serial.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <utility>

#include "numeric_format.hpp"
#include "stepper.hpp"
#include "time_path_run.hpp"

namespace covopt::internal {
namespace {

/// Entries of the state vector; the last two only for a braking robot.
enum StateEntry : int {
  kDeflection = 0,  // q: δ_c in phase 1, δ_b in phase 2 [m]
  kApproachRate,    // δ' [m/s]
  kStateSize,       // without braking
  kRobotSpeed = kStateSize,  // v_R, the robot's own speed (the body region starts at rest) [m/s]
  kBrakeWork,                // W = ∫ m_R a v_R dt while braking [J]
  kBrakingStateSize,
};

/// Root functions, in the order (and with the directions) of stepper.hpp's kRootDirections.
enum EventEntry : int {
  kBottomsOut = 0,  // phase 1: q - travel, rising: restart in phase 2
  kLowerEnd,        // phase 1: q falling through 0 (separation); phase 2: q - F_b/k_H falling
                    // (back to phase 1), or q falling through 0 bare (separation)
  kTurn,            // δ' falling through 0: maximum compression
  kEventCount,      // without braking
  kBrakeStart = kEventCount,  // t - t_d, rising, until the brake has started: restart braking
  kRobotStops,                // v_R, falling, while braking: restart without the brake
  kBrakingEventCount,
};
constexpr std::array<int, kEventCount> kEventDirections{+1, -1, -1};
constexpr std::array<int, kBrakingEventCount> kBrakingEventDirections{+1, -1, -1, +1, -1};

/// The phases of the contact.
enum class Phase { kCovering, kBody };

/// What the C callbacks see: the constants of the model and the phase.
struct Run {
  Phase phase = Phase::kBody;
  bool covered = false;
  // A foam covering (docs/model.md §15). The piece of its curve the state is on: its ends [m]
  // are the phase's events, and on it the force is the piece's polynomial, continued past its
  // ends (so that the integrator and its dense output see a smooth right-hand side up to the
  // event; the force's derivative jumps at a point of the curve: the integrator restarts there).
  const BodyContactModel* foam = nullptr;
  bool flat_foam = false;
  std::size_t piece = 0;
  double piece_low_m = 0.0;
  double piece_high_m = 0.0;
  double inverse_thickness = 0.0;  // 1/h [1/m]
  double force_factor = 0.0;       // F = this W (curved) or this σ (flat) [m²]
  double energy_factor = 0.0;      // U_c = this V (curved) or this W (flat) [m³]
  double piece_strain = 0.0;       // ε at the piece's start, and there σ [Pa], W, V [J/m³]
  double piece_stress = 0.0;
  double piece_energy = 0.0;
  double piece_second = 0.0;
  double piece_slope = 0.0;        // dσ/dε on the piece [Pa]
  double covering_stiffness = 0.0;  // K_c [N/m^1.5]
  double body_stiffness = 0.0;      // k_H [N/m]
  double inverse_mass = 0.0;        // 1/mu [1/kg]
  double series_factor = 0.0;       // 1.5 K_c/k_H [1/m^0.5]: dδ/dδ_c = 1 + this sqrt(δ_c)
  double travel_m = 0.0;            // the covering's travel 0.8 b_c [m]
  double body_at_bottom_m = 0.0;    // F_b/k_H: δ_b where the covering bottoms out [m]
  double root_floor_m = 0.0;        // floor on δ_c in the Jacobian (sqrt(δ_c) in a denominator)
  // A braking robot (the state's last two entries and the last two events exist).
  bool braking = false;
  double braking_m_per_s2 = 0.0;    // a
  double robot_mass_kg = 0.0;       // m_R (finite: a fixed robot cannot brake)
  double inverse_robot_mass = 0.0;  // 1/m_R
  double reaction_delay_s = 0.0;    // t_d
  bool brake_pending = false;       // the robot brakes, but t_d has not come yet
  bool brake_on = false;            // braking now: t >= t_d and the robot still moving forward
};

/// A foam's force F(q) [N] and its slope dF/dq [N/m] on the run's piece of the curve (continued
/// past the piece's ends as its polynomial).
struct FoamForce {
  double force_N = 0.0;
  double slope_N_per_m = 0.0;
};
FoamForce FoamForceOnPiece(const Run& run, double q) noexcept {
  const double x = q * run.inverse_thickness - run.piece_strain;
  const double stress = run.piece_stress + run.piece_slope * x;
  if (run.flat_foam) return {run.force_factor * stress, run.force_factor * run.inverse_thickness * run.piece_slope};
  const double energy = run.piece_energy + x * (run.piece_stress + 0.5 * run.piece_slope * x);
  return {run.force_factor * energy, run.force_factor * run.inverse_thickness * stress};
}
/// The foam's energy U_c(q) [J] on the run's piece.
double FoamEnergyOnPiece(const Run& run, double q) noexcept {
  const double x = q * run.inverse_thickness - run.piece_strain;
  const double energy = run.piece_energy + x * (run.piece_stress + 0.5 * run.piece_slope * x);
  if (run.flat_foam) return run.energy_factor * energy;
  return run.energy_factor *
         (run.piece_second + x * (run.piece_energy + x * (0.5 * run.piece_stress + run.piece_slope * x / 6.0)));
}

/// The contact at one state: its force, the two deflections and the approach.
struct Contact {
  double force_N = 0.0;
  double covering_m = 0.0;  // δ_c
  double body_m = 0.0;      // δ_b
  double approach_m = 0.0;  // δ = δ_c + δ_b
};

/// Phase 1 takes δ_c clamped at 0 (an overshooting step past separation never takes the pow of
/// a negative base); phase 2 is linear and continued past its lower end as it is.
Contact ContactAt(const Run& run, const sunrealtype* y) noexcept {
  Contact c;
  if (run.phase == Phase::kCovering) {
    c.covering_m = std::max(y[kDeflection], 0.0);
    c.force_N = run.foam ? FoamForceOnPiece(run, c.covering_m).force_N
                         : run.covering_stiffness * c.covering_m * std::sqrt(c.covering_m);
    c.body_m = c.force_N / run.body_stiffness;
  } else {
    c.covering_m = run.travel_m;  // 0 bare
    c.body_m = y[kDeflection];
    c.force_N = run.body_stiffness * c.body_m;
  }
  c.approach_m = c.covering_m + c.body_m;
  return c;
}

/// The covering's energy W_c at `c` [J]: 2/5 K_c δ_c^2.5 (= 2/5 K_c^(-2/3) F^(5/3) below the
/// bottoming out).
double CoveringEnergy(const Run& run, const Contact& c) noexcept {
  if (run.foam) return FoamEnergyOnPiece(run, c.covering_m);
  return 0.4 * run.covering_stiffness * c.covering_m * c.covering_m * std::sqrt(c.covering_m);
}
/// The energy both springs store at `c` [J]: F²/(2 k_H) + W_c.
double StoredEnergy(const Run& run, const Contact& c) noexcept { return 0.5 * c.force_N * c.body_m + CoveringEnergy(run, c); }

int BodyRightHandSide(sunrealtype /*t*/, N_Vector y, N_Vector ydot, void* user_data) {
  const auto& run = *static_cast<const Run*>(user_data);
  const sunrealtype* s = NV_DATA_S(y);
  sunrealtype* rate = NV_DATA_S(ydot);
  double force = 0.0;
  if (run.phase == Phase::kCovering && run.foam) {
    // dδ/dq = 1 + F'(q)/k_H: the foam and the body spring in series.
    const FoamForce f = FoamForceOnPiece(run, s[kDeflection]);
    force = f.force_N;
    rate[kDeflection] = s[kApproachRate] / (1.0 + f.slope_N_per_m / run.body_stiffness);
  } else if (run.phase == Phase::kCovering) {
    const double q = std::max(s[kDeflection], 0.0);
    const double root = std::sqrt(q);
    force = run.covering_stiffness * q * root;
    rate[kDeflection] = s[kApproachRate] / (1.0 + run.series_factor * root);
  } else {
    force = run.body_stiffness * s[kDeflection];
    rate[kDeflection] = s[kApproachRate];
  }
  rate[kApproachRate] = -force * run.inverse_mass;
  if (!run.braking) {
    return std::isfinite(rate[kDeflection]) && std::isfinite(rate[kApproachRate]) ? 0 : 1;  // 1: recoverable
  }
  // m_R v_R' = -F - B, m_H v_H' = F (0 clamped): δ'' = -F/mu - a while braking; W' = B v_R.
  const double deceleration = run.brake_on ? run.braking_m_per_s2 : 0.0;
  rate[kApproachRate] -= deceleration;
  rate[kRobotSpeed] = -force * run.inverse_robot_mass - deceleration;
  rate[kBrakeWork] = run.robot_mass_kg * deceleration * s[kRobotSpeed];
  for (int i = 0; i < kBrakingStateSize; ++i) {
    if (!std::isfinite(rate[i])) return 1;
  }
  return 0;
}

int BodyRootFunctions(sunrealtype t, N_Vector y, sunrealtype* g, void* user_data) {
  const auto& run = *static_cast<const Run*>(user_data);
  const sunrealtype* s = NV_DATA_S(y);
  const bool covering = run.phase == Phase::kCovering;
  g[kBottomsOut] = covering ? s[kDeflection] - (run.foam ? run.piece_high_m : run.travel_m) : -1.0;
  g[kLowerEnd] = s[kDeflection] - (covering ? run.piece_low_m : run.body_at_bottom_m);
  g[kTurn] = s[kApproachRate];
  if (run.braking) {
    g[kBrakeStart] = run.brake_pending ? t - run.reaction_delay_s : -1.0;
    g[kRobotStops] = run.brake_on ? s[kRobotSpeed] : 1.0;
  }
  return 0;
}

/// The analytic Jacobian for the implicit methods; in phase 1 d/dq of δ'/(1 + c sqrt(q)) is
/// unbounded at q = 0, so q is floored there (Newton's matrix need only be approximate).
int BodyJacobian(sunrealtype /*t*/, N_Vector y, N_Vector /*fy*/, SUNMatrix jac, void* user_data,
                 N_Vector, N_Vector, N_Vector) {
  const auto& run = *static_cast<const Run*>(user_data);
  const sunrealtype* s = NV_DATA_S(y);
  double force_slope = 0.0;  // dF/dq [N/m]
  if (run.phase == Phase::kCovering && run.foam) {
    // Newton's matrix need only be approximate: the foam's dq'/dq (through F''(q)) is left out.
    force_slope = FoamForceOnPiece(run, s[kDeflection]).slope_N_per_m;
    SM_ELEMENT_D(jac, 0, 0) = 0.0;
    SM_ELEMENT_D(jac, 0, 1) = 1.0 / (1.0 + force_slope / run.body_stiffness);
  } else if (run.phase == Phase::kCovering) {
    const double root = std::sqrt(std::max(s[kDeflection], run.root_floor_m));
    const double divisor = 1.0 + run.series_factor * root;
    SM_ELEMENT_D(jac, 0, 0) = -s[kApproachRate] * run.series_factor / (2.0 * root * divisor * divisor);
    SM_ELEMENT_D(jac, 0, 1) = 1.0 / divisor;
    force_slope = 1.5 * run.covering_stiffness * root;
  } else {
    SM_ELEMENT_D(jac, 0, 0) = 0.0;
    SM_ELEMENT_D(jac, 0, 1) = 1.0;
    force_slope = run.body_stiffness;
  }
  SM_ELEMENT_D(jac, 1, 0) = -force_slope * run.inverse_mass;
  SM_ELEMENT_D(jac, 1, 1) = 0.0;
  if (run.braking) {
    for (int row = 0; row < kBrakingStateSize; ++row) {
      for (int column = 0; column < kBrakingStateSize; ++column) {
        if (row >= kStateSize || column >= kStateSize) SM_ELEMENT_D(jac, row, column) = 0.0;
      }
    }
    SM_ELEMENT_D(jac, kRobotSpeed, kDeflection) = -force_slope * run.inverse_robot_mass;
    SM_ELEMENT_D(jac, kBrakeWork, kRobotSpeed) = run.brake_on ? run.robot_mass_kg * run.braking_m_per_s2 : 0.0;
  }
  return 0;
}

/// "time path (arkode-erk54, rtol 1e-08)", with the absolute tolerance when it differs.
std::string MethodText(const TimeIntegrationOptions& o) {
  std::string text = "time path (" + std::string(ToString(o.method)) + ", rtol " +
                     FormatNumber(o.relative_tolerance);
  if (o.absolute_tolerance > 0.0 && o.absolute_tolerance != o.relative_tolerance) {
    text += ", atol " + FormatNumber(o.absolute_tolerance);
  }
  return text + ")";
}

/// One run: the event loop over the integrator's steps, the history and the peaks.
class BodyContactRun {
 public:
  BodyContactRun(const BodyContactModel& model, const SolveOptions& options, Stepper& stepper,
                 Run& run, StepperWorkspace& workspace, bool to_peak)
      : record_(options.record_history),
        to_peak_(to_peak),
        model_(model),
        options_(options.time_path),
        stepper_(stepper),
        run_(run),
        state_(workspace.state),
        tolerances_(workspace.absolute_tolerances),
        dense_output_(workspace.dense_output),
        log_(workspace.log),
        y_(N_VGetArrayPointer(workspace.state)),
        v0_(model.scene().speed_m_per_s),
        // v_R = v0 - (mu/m_R)(v0 - δ') without braking (momentum; 0 for a fixed robot's 1/m_R).
        speed_share_(std::isinf(model.scene().robot_mass_kg) ? 0.0
                                                             : model.reduced_mass_kg() / model.scene().robot_mass_kg) {
    SetUpRun();
    SetScales(record_ ? options.history_samples_per_contact : 0.0);
    result_.method = MethodText(options_);
    result_.reduced_mass_kg = model.reduced_mass_kg();
    result_.energy_transferred_J = model.impact_energy_J();
  }

  BodyContactResult Integrate() {
    y_[kDeflection] = 0.0;
    y_[kApproachRate] = v0_;
    if (run_.braking) {
      y_[kRobotSpeed] = v0_;
      y_[kBrakeWork] = 0.0;
    }
    Record(false);
    int flag = stepper_.BeginRun(0.0, state_);
    if (flag == kStepTaken) flag = StartInterval();
    long steps = 0;
    while (flag >= 0 && !Done()) {
      flag = stepper_.Step(t_ + horizon_s_, state_, &t_);
      if (flag == kStepTaken) {
        Record(true);
        if (++steps >= options_.max_steps) break;
        continue;
      }
      if (flag != kRootFound) break;
      std::array<int, kBrakingEventCount> found{};  // the braking events stay 0 without braking
      stepper_.RootInfo(found.data());
      Record(true);
      flag = OnRoot(found);
    }
    if (flag < 0) {
      Fail(flag == kTooMuchWork ? SolveStatus::kStepLimit : SolveStatus::kSolverFailure,
           std::string(ToString(options_.method)) + " returned " + stepper_.FlagName(flag));
    } else if (!Done() && steps >= options_.max_steps) {
      Fail(SolveStatus::kStepLimit, "step limit of " + std::to_string(options_.max_steps) +
                                        (to_peak_ ? " steps reached before maximum compression"
                                                  : " steps reached before separation"));
    } else if (!Done() || !turned_) {
      Fail(SolveStatus::kEventMissed,
           to_peak_ ? "the integration ended without locating maximum compression"
                    : "the integration ended without locating maximum compression and separation");
    } else {
      FinishChecks();
    }
    return std::move(result_);
  }

 private:
  /// Separated, or (to the peak only) past maximum compression.
  bool Done() const noexcept { return separated_ || (to_peak_ && turned_); }

  void SetUpRun() {
    run_ = Run{};
    run_.covered = model_.has_covering();
    run_.foam = model_.foam() ? &model_ : nullptr;
    if (run_.foam) {
      run_.flat_foam = model_.foam_flat_face();
      run_.inverse_thickness = 1.0 / model_.scene().covering.thickness_m;
      run_.force_factor = model_.foam_force_factor();
      run_.energy_factor = model_.foam_energy_factor();
    }
    run_.phase = run_.covered ? Phase::kCovering : Phase::kBody;
    run_.covering_stiffness = model_.covering_stiffness();
    run_.body_stiffness = model_.scene().body_stiffness_N_per_m;
    run_.inverse_mass = 1.0 / model_.reduced_mass_kg();
    run_.series_factor = 1.5 * run_.covering_stiffness / run_.body_stiffness;
    run_.travel_m = model_.covering_travel_m();
    run_.body_at_bottom_m = run_.covered ? model_.bottom_out_force_N() / run_.body_stiffness : 0.0;
    if (run_.foam) SetPiece(0);
    const BodyContactScene& scene = model_.scene();
    if (scene.robot_brakes()) {  // a finite robot mass (BodyContactModel::FromScene)
      run_.braking = true;
      run_.braking_m_per_s2 = scene.braking_m_per_s2;
      run_.robot_mass_kg = scene.robot_mass_kg;
      run_.inverse_robot_mass = 1.0 / scene.robot_mass_kg;
      run_.reaction_delay_s = scene.reaction_delay_s;
      run_.brake_pending = scene.reaction_delay_s > 0.0;
      run_.brake_on = !run_.brake_pending;  // the robot moves forward at first contact
    }
  }

  /// The natural scales of q in each phase and of δ' (v0), from the exact peak force: they
  /// set the absolute tolerances, the first step's orientation and the history's spacing.
  void SetScales(double history_samples) {
    const double force_N = model_.ForceAtEnergy(model_.impact_energy_J());
    const double approach_m = model_.ApproachAtForce(force_N);
    const double atol =
        options_.absolute_tolerance > 0.0 ? options_.absolute_tolerance : options_.relative_tolerance;
    // A braking robot travels at most v0 t_d + v0²/(2a), which bounds δ and each deflection:
    // far below the unbraked scales when a strong brake stops it early.
    const double travel_m = run_.braking ? v0_ * run_.reaction_delay_s + v0_ * v0_ / (2.0 * run_.braking_m_per_s2)
                                         : std::numeric_limits<double>::infinity();
    covering_tolerance_m_ = atol * std::min(model_.CoveringDeflectionAtForce(force_N), travel_m);
    body_tolerance_m_ = atol * std::min(force_N / run_.body_stiffness, travel_m);
    rate_tolerance_ = atol * v0_;
    work_tolerance_J_ = atol * 0.5 * run_.robot_mass_kg * v0_ * v0_;  // the brake takes at most ½ m_R v0²
    run_.root_floor_m = 1e-12 * run_.travel_m;
    horizon_s_ = 1e3 * approach_m / v0_;  // only orients the first step (one-step mode)
    if (history_samples > 0.0) {
      // The contact lasts pi sqrt(mu/k_H) bare; with a covering at least 2 δ_max/v0 (|δ'| <= v0
      // throughout), so spacing by that gives at least the samples asked for (about 1.5 times).
      const double duration_s = run_.covered
                                    ? 2.0 * approach_m / v0_
                                    : std::numbers::pi / std::sqrt(run_.body_stiffness * run_.inverse_mass);
      history_interval_s_ = duration_s / history_samples;
    }
  }

  /// The tolerances of the current phase and a first step the integrator estimates.
  int StartInterval() {
    sunrealtype* tolerance = N_VGetArrayPointer(tolerances_);
    tolerance[kDeflection] = run_.phase == Phase::kCovering ? covering_tolerance_m_ : body_tolerance_m_;
    tolerance[kApproachRate] = rate_tolerance_;
    if (run_.braking) {
      tolerance[kRobotSpeed] = rate_tolerance_;
      tolerance[kBrakeWork] = work_tolerance_J_;
    }
    int flag = stepper_.SetTolerances(options_.relative_tolerance, tolerances_);
    if (flag == kStepTaken) flag = stepper_.SetInitStep(0.0);
    return flag;
  }

  /// Continues in `phase` from deflection q at the current δ': the integrator restarts.
  int Switch(Phase phase, double q) {
    run_.phase = phase;
    y_[kDeflection] = q;
    int flag = stepper_.ReInit(t_, state_);
    if (flag == kStepTaken) flag = StartInterval();
    return flag;
  }

  int OnRoot(const std::array<int, kBrakingEventCount>& found) {
    if (found[kTurn] && !turned_) Peaks();
    // The brake's changes: the right-hand side jumps, so the integrator restarts (below, or
    // with a phase switch found at the same time).
    bool brake_changed = false;
    if (found[kBrakeStart]) {
      run_.brake_pending = false;
      run_.brake_on = y_[kRobotSpeed] > 0.0;
      brake_changed = true;
    }
    if (found[kRobotStops]) {
      run_.brake_on = false;  // not held: the contact force may push the robot back
      brake_changed = true;
    }
    if (found[kBottomsOut]) {
      if (run_.foam && run_.piece_high_m < run_.travel_m) return ToPiece(run_.piece + 1, run_.piece_high_m);
      return Switch(Phase::kBody, run_.body_at_bottom_m);
    }
    if (found[kLowerEnd]) {
      if (run_.phase == Phase::kBody && run_.covered) {
        if (run_.foam) SetPiece(CurvePoints().size() - 1);
        return Switch(Phase::kCovering, run_.travel_m);
      }
      if (run_.foam && run_.piece_low_m > 0.0) return ToPiece(run_.piece - 1, run_.piece_low_m);
      separated_ = true;
      result_.contact_duration_s = t_;
      result_.rebound_speed_m_per_s = -y_[kApproachRate];
      if (run_.braking) {
        CheckEnergy(StoredEnergy(run_, ContactAt(run_, y_)));
      } else {
        // Conservative: the rebound is the impact speed (momentum and energy), never faster.
        Worsen(std::abs(result_.rebound_speed_m_per_s / v0_ - 1.0));
      }
      return kRootFound;
    }
    if (brake_changed) return Switch(run_.phase, y_[kDeflection]);
    return kRootFound;
  }

  /// A foam's curve points, and the piece of it the run is on (its ends in d [m]).
  std::span<const StrainStressPoint> CurvePoints() const {
    return model_.scene().covering.compressive_curve->points();
  }
  void SetPiece(std::size_t piece) {
    const auto points = CurvePoints();
    const double h = model_.scene().covering.thickness_m;
    run_.piece = piece;
    run_.piece_low_m = piece == 0 ? 0.0 : points[piece - 1].strain * h;
    run_.piece_high_m = piece + 1 == points.size() ? run_.travel_m : points[piece].strain * h;
    const CompressiveCurve& curve = *model_.scene().covering.compressive_curve;
    run_.piece_strain = piece == 0 ? 0.0 : points[piece - 1].strain;
    run_.piece_stress = piece == 0 ? 0.0 : points[piece - 1].stress_Pa;
    run_.piece_slope = (points[piece].stress_Pa - run_.piece_stress) / (points[piece].strain - run_.piece_strain);
    run_.piece_energy = curve.EnergyDensityAt(run_.piece_strain);
    run_.piece_second = curve.SecondIntegralAt(run_.piece_strain);
  }
  /// Continues on another piece of the foam's curve from its end `at_m` [m]: a restart.
  int ToPiece(std::size_t piece, double at_m) {
    SetPiece(piece);
    return Switch(Phase::kCovering, at_m);
  }

  /// Maximum compression: the peaks from the state (δ' = 0 here).
  void Peaks() {
    turned_ = true;
    const Contact c = ContactAt(run_, y_);
    const bool bottomed = run_.covered && run_.phase == Phase::kBody;
    if (run_.foam) {
      FoamPeaks(c, bottomed);
      return;
    }
    result_.peak_force_N = c.force_N;
    result_.peak_pressure_Pa = model_.PressureAtForce(c.force_N);
    result_.covering_deflection_m = run_.covered ? c.covering_m : 0.0;
    result_.body_deflection_m = c.body_m;
    result_.max_approach_m = c.approach_m;
    result_.contact_radius_m =
        run_.covered ? std::sqrt(model_.covering_outer_radius_m() * c.covering_m) : 0.0;
    result_.body_energy_J = 0.5 * c.force_N * c.body_m;
    result_.covering_energy_J = CoveringEnergy(run_, c);
    result_.compression_ratio = run_.covered ? (bottomed ? 1.0 : c.covering_m / run_.travel_m) : 0.0;
    result_.fully_compressed = bottomed;
    // Less than ½ mu v0² with braking: the springs hold what reached them.
    if (run_.braking) result_.energy_transferred_J = result_.body_energy_J + result_.covering_energy_J;
    FinishCoveringFields(model_, result_);
    CheckEnergy(StoredEnergy(run_, c));
  }

  /// Peaks() for a foam covering: the exact path's reading of the state (FoamPeaksAt).
  void FoamPeaks(const Contact& c, bool bottomed) {
    BodyContactResult peaks = FoamPeaksAt(model_, FoamStateAt(model_, c.covering_m, c.force_N, bottomed), bottomed);
    peaks.method = std::move(result_.method);
    peaks.history = std::move(result_.history);
    peaks.energy_transferred_J =
        run_.braking ? peaks.body_energy_J + peaks.covering_energy_J : result_.energy_transferred_J;
    result_ = std::move(peaks);
    CheckEnergy(StoredEnergy(run_, c));
  }

  /// The self-check's energy balance at the state y_ (maximum compression or separation),
  /// `stored` the springs' energy there [J]: its error relative to ½ mu v0² joins the residual.
  /// Without braking the balance at the turn is U(δ_max) = ½ mu v0²; a braking robot's counts the
  /// kinetic energies of both bodies and the brake's work (BodyContactResult::energy_residual).
  void CheckEnergy(double stored) {
    const double impact_energy_J = model_.impact_energy_J();
    double balance_J = stored - impact_energy_J;  // δ' = 0 at the turn
    if (run_.braking) {
      const BodyContactScene& scene = model_.scene();
      const double robot_speed = y_[kRobotSpeed];
      const double body_speed = robot_speed - y_[kApproachRate];
      const double body_kinetic_J =
          scene.contact == ContactType::kClamped ? 0.0 : 0.5 * scene.body_mass_kg * body_speed * body_speed;
      balance_J = 0.5 * run_.robot_mass_kg * (robot_speed * robot_speed - v0_ * v0_) + body_kinetic_J + stored +
                  y_[kBrakeWork];
    }
    Worsen(std::abs(balance_J) / impact_energy_J);
  }

  /// The residual becomes `error` where that is larger, or NaN (which the warning then reports).
  void Worsen(double error) noexcept {
    if (!(error <= residual_)) residual_ = error;
  }

  /// The self-check after a run that ended well: the energy residual and, above
  /// max(100 rtol, 1e-9), the head's time path's tolerance warning.
  void FinishChecks() {
    result_.energy_residual = residual_;
    const bool exact_reference = !run_.braking;
    if (auto warning = ToleranceWarning(residual_, options_, /*restarted=*/true,
                                        run_.braking ? "energy residual (brake work accounted for)" : "energy residual",
                                        exact_reference ? "; the exact path is the reference for peaks" : "")) {
      result_.warnings.push_back(std::move(*warning));
    }
  }

  /// Records the state y_ at t_ (with a history); after a step or at a root (`interpolate`),
  /// first fills the gap since the last sample with the integrator's dense output.
  void Record(bool interpolate) {
    if (!record_) return;
    if (interpolate && !result_.history.empty()) {
      const double last = result_.history.back().time_s;
      ForEachFillPoint(t_ - last, history_interval_s_, [&](double since_last) {
        const double tk = last + since_last;
        if (stepper_.Interpolate(tk, dense_output_) == kStepTaken) {
          Push(tk, N_VGetArrayPointer(dense_output_));
        }
      });
    }
    Push(t_, y_);
  }
  void Push(double time, const sunrealtype* s) {
    const Contact c = ContactAt(run_, s);
    const double robot_speed =
        run_.braking ? s[kRobotSpeed] : v0_ - speed_share_ * (v0_ - s[kApproachRate]);
    result_.history.push_back(
        {time, c.approach_m, s[kApproachRate], c.force_N, robot_speed, run_.braking ? s[kBrakeWork] : 0.0});
  }

  void Fail(SolveStatus status, std::string what) {
    // No peaks from a failed run: only the status, the message and the history so far.
    BodyContactResult failed;
    failed.status = status;
    failed.message = std::move(what);
    if (!log_.empty()) failed.message += " (SUNDIALS: " + log_ + ")";
    failed.method = std::move(result_.method);
    failed.reduced_mass_kg = result_.reduced_mass_kg;
    failed.energy_transferred_J = result_.energy_transferred_J;
    failed.history = std::move(result_.history);
    result_ = std::move(failed);
  }

  const bool record_;
  const bool to_peak_;
  const BodyContactModel& model_;
  const TimeIntegrationOptions& options_;
  Stepper& stepper_;
  Run& run_;
  N_Vector state_;
  N_Vector tolerances_;
  N_Vector dense_output_;
  const std::string& log_;
  sunrealtype* y_;
  const double v0_;
  const double speed_share_;  // mu/m_R [-]
  BodyContactResult result_;
  double t_ = 0.0;
  double horizon_s_ = 0.0;
  double history_interval_s_ = 0.0;
  double covering_tolerance_m_ = 0.0;
  double body_tolerance_m_ = 0.0;
  double rate_tolerance_ = 0.0;
  double work_tolerance_J_ = 0.0;
  bool turned_ = false;
  bool separated_ = false;
  double residual_ = 0.0;  // the self-check's worst relative energy error so far [-]
};

/// The SUNDIALS context, the state's vectors (2 entries, or 4 for a braking robot) and one
/// integrator per method, made on first use per thread and reused for every run; members are
/// freed in reverse order (the context last).
struct Workspace {
  SundialsContext context;
  Run run;
  StepperWorkspace steppers;
  Workspace(int size, std::span<const int> directions) : steppers(context.get(), size, Callbacks(run, directions)) {}
  static StepperResources Callbacks(Run& run, std::span<const int> directions) {
    StepperResources resources;
    resources.user_data = &run;
    resources.rhs = BodyRightHandSide;
    resources.roots = BodyRootFunctions;
    resources.root_directions = directions;
    resources.jacobian = BodyJacobian;
    // BodyJacobian at first contact (δ_c = 0, its floor) is far off a moment later: re-evaluate
    // it at every Newton setup (a 2×2 or 4×4 matrix: cheap).
    resources.jacobian_at_every_setup = true;
    return resources;
  }
};

/// The workspace of a run with or without braking: the unbraked contact keeps its 2 entries.
Workspace& WorkspaceFor(bool braking) {
  if (braking) {
    thread_local Workspace workspace(kBrakingStateSize, kBrakingEventDirections);
    return workspace;
  }
  thread_local Workspace workspace(kStateSize, kEventDirections);
  return workspace;
}

}  // namespace

BodyContactResult SolveBodyContactTimePath(const BodyContactModel& model, const SolveOptions& options, bool to_peak) {
  Workspace& workspace = WorkspaceFor(model.scene().robot_brakes());
  StepperWorkspace& s = workspace.steppers;
  s.log.clear();
  BodyContactRun run(model, options, s.StepperFor(options.time_path.method), workspace.run, s, to_peak);
  return run.Integrate();
}

}  // namespace covopt::internal
