// The time path of docs/model.md §3: a SUNDIALS integrator (CVODE or ARKODE) with rootfinding and
// a restart at every phase switch.
#include "covopt/core/time_integration.hpp"

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "exact_internal.hpp"
#include "extended_time_path.hpp"
#include "numeric_format.hpp"
#include "stepper.hpp"
#include "time_path_run.hpp"
#include "fixed_length_vector.hpp"

namespace covopt {
namespace internal {
namespace {

/// F and σ_c at δ, with the current segment's formula (continued beyond its ends).
ContactState Law(const RunState& run, double delta) noexcept {
  if (run.segment == kWholeLaw) return run.model->StateAt(delta);
  if (run.segment == 0 && !(delta > 0.0)) return ContactState{};  // free flight
  return run.model->StateInSegment(static_cast<std::size_t>(run.segment), delta);
}

/// F [N] and σ_c [Pa] at δ with the current segment's formula: Law's force and stress, with
/// ImpactModel::StateInSegment's expressions (so the same to the bit) but without the
/// energies and the stiffness the right-hand side does not use.
struct ForceAndStress {
  double force_N = 0.0;
  double compressive_stress_Pa = 0.0;
};

ForceAndStress LawForceAndStress(const RunState& run, double delta) noexcept {
  if (run.segment == kWholeLaw) {
    const ContactState contact = run.model->StateAt(delta);
    return {contact.force_N, contact.compressive_stress_Pa};
  }
  if (run.segment == 0 && !(delta > 0.0)) return {};  // free flight
  const ForceLawSegment& seg = run.model->segment(static_cast<std::size_t>(run.segment));
  if (seg.curve) [[unlikely]] {  // the foam law (docs/model.md §16)
    const ContactState contact = run.model->StateInSegment(static_cast<std::size_t>(run.segment), delta);
    return {contact.force_N, contact.compressive_stress_Pa};
  }
  constexpr double kHertzPressureFactor = 3.0 / (2.0 * std::numbers::pi);  // k = 3/(2π)
  const double x = std::max(delta - seg.origin_m, 0.0);
  const double x_pow_nm1 = std::pow(x, seg.exponent - 1.0);
  const double kc = kHertzPressureFactor * seg.stiffness * seg.curvature_per_m;
  return {seg.force_offset_N + seg.stiffness * (x_pow_nm1 * x), seg.stress_offset_Pa + kc * x_pow_nm1};
}

}  // namespace

int RightHandSide(sunrealtype /*t*/, N_Vector y, N_Vector ydot, void* user_data) {
  const auto& run = *static_cast<const RunState*>(user_data);
  // Every vector here is a clone of MakeFixedLengthVector's: serial layout, read directly.
  const sunrealtype* state = NV_DATA_S(y);
  sunrealtype* rate = NV_DATA_S(ydot);
  const ForceAndStress law = LawForceAndStress(run, state[0]);
  rate[0] = state[1];
  rate[1] = -law.force_N * run.inverse_mass;
  rate[2] = law.compressive_stress_Pa * state[1];
  return std::isfinite(rate[1]) && std::isfinite(rate[2]) ? 0 : 1;  // 1: recoverable
}

int RootFunctions(sunrealtype /*t*/, N_Vector y, sunrealtype* g, void* user_data) {
  const auto& run = *static_cast<const RunState*>(user_data);
  const sunrealtype* state = NV_DATA_S(y);
  double lower = 0.0;
  double upper = std::numeric_limits<double>::infinity();
  if (run.segment != kWholeLaw) {
    const ForceLawSegment& seg = run.model->segment(static_cast<std::size_t>(run.segment));
    lower = seg.start_m + run.closing_m[static_cast<std::size_t>(run.segment)];
    upper = seg.end_m;
  }
  g[kRootUpperSwitch] = std::isinf(upper) ? -1.0 : state[0] - upper;
  g[kRootLowerSwitch] = state[0] - lower;
  g[kRootTurn] = state[1];
  return 0;
}

/// Analytic Jacobian of (δ', -F/m, σ δ') for the BDF/Newton variant. dσ/dδ is unbounded
/// at a phase start (x^(n-2)); the phase-local penetration is floored so Newton's matrix
/// stays finite (it only needs to be approximate).
int Jacobian(sunrealtype /*t*/, N_Vector y, N_Vector /*fy*/, SUNMatrix jac, void* user_data,
             N_Vector, N_Vector, N_Vector) {
  const auto& run = *static_cast<const RunState*>(user_data);
  const sunrealtype* state = N_VGetArrayPointer(y);
  const double delta = state[0];
  const ContactState contact = Law(run, delta);
  double stress_slope = 0.0;
  if (delta > 0.0) {
    const std::size_t i = run.segment == kWholeLaw ? run.model->SegmentIndexAt(delta)
                                                   : static_cast<std::size_t>(run.segment);
    const ForceLawSegment& seg = run.model->segment(i);
    const double x = std::max(delta - seg.origin_m, 1e-9 * std::max(seg.start_m, 1e-6));
    stress_slope = seg.curve ? seg.curve->SlopeAt(delta / seg.foam_thickness_m) / seg.foam_thickness_m
                             : 3.0 / (2.0 * std::numbers::pi) * seg.stiffness * seg.curvature_per_m *
                                   (seg.exponent - 1.0) * std::pow(x, seg.exponent - 2.0);
  }
  SM_ELEMENT_D(jac, 0, 0) = 0.0;
  SM_ELEMENT_D(jac, 0, 1) = 1.0;
  SM_ELEMENT_D(jac, 0, 2) = 0.0;
  SM_ELEMENT_D(jac, 1, 0) = -contact.stiffness_N_per_m * run.inverse_mass;
  SM_ELEMENT_D(jac, 1, 1) = 0.0;
  SM_ELEMENT_D(jac, 1, 2) = 0.0;
  SM_ELEMENT_D(jac, 2, 0) = stress_slope * state[1];
  SM_ELEMENT_D(jac, 2, 1) = contact.compressive_stress_Pa;
  SM_ELEMENT_D(jac, 2, 2) = 0.0;
  return 0;
}

void CaptureMessage(int error_code, const char* module, const char* function, char* message,
                    void* user_data) {
  auto* log = static_cast<std::string*>(user_data);
  if (!log) return;
  if (!log->empty()) log->append("; ");
  log->append(error_code > 0 ? "warning" : "error");  // CV_WARNING = ARK_WARNING = 99
  log->append(" in ").append(module ? module : "?").append("::").append(function ? function : "?");
  log->append(": ").append(message ? message : "");
}

std::string TakeFlagName(char* malloced_name, int flag) {
  std::string text = malloced_name ? malloced_name : "unknown flag";
  std::free(malloced_name);
  return text + " (" + std::to_string(flag) + ")";
}

}  // namespace internal

namespace {

/// The opening of a phase entered upward at x = 0 with speed v > 0. The solution is
/// singular there (x^n with non-integer n: an order-q method needs steps ~ 0.1 t for many
/// decades of t), so the first stretch τ* is taken from the phase's series solution
///     x(τ) = v τ - a τ² - b τ^(n+2),   a = F_off/(2m),   b = K v^n / (m (n+1)(n+2)),
/// whose first neglected terms are c1 τ^(n+3) and c2 τ^(2n+3) with
///     c1 = (K/m) n v^(n-1) a / ((n+2)(n+3)),   c2 = (K/m) n v^(n-1) b / ((2n+2)(2n+3)).
/// τ* keeps both (and their τ-derivatives in v) below a twentieth of the local tolerance,
/// and the opening short of the segment's end. CVODE integrates everything after τ*.
struct PhaseOpening {
  double duration_s = 0.0;  ///< τ*; 0 when no opening could be taken
  double v = 0.0, a = 0.0, b = 0.0, n = 1.0;
  /// Phase-local penetration x [m] and its rate [m/s] at τ in [0, τ*].
  std::pair<double, double> At(double tau) const {
    const double tau_pow = std::pow(tau, n + 1.0);
    return {v * tau - a * tau * tau - b * tau_pow * tau,
            v - 2.0 * a * tau - (n + 2.0) * b * tau_pow};
  }
};

PhaseOpening OpenPhase(const ForceLawSegment& seg, double v, double inverse_mass, double tol_x,
                       double tol_v) {
  PhaseOpening opening;
  const double n = seg.exponent;
  opening.v = v;
  opening.n = n;
  opening.a = 0.5 * seg.force_offset_N * inverse_mass;
  opening.b = seg.stiffness * std::pow(v, n) * inverse_mass / ((n + 1.0) * (n + 2.0));
  const double common = seg.stiffness * inverse_mass * n * std::pow(v, n - 1.0);
  const double c1 = common * opening.a / ((n + 2.0) * (n + 3.0));
  const double c2 = common * opening.b / ((2.0 * n + 2.0) * (2.0 * n + 3.0));
  constexpr double kShare = 0.05;
  double tau = std::pow(kShare * tol_x / c2, 1.0 / (2.0 * n + 3.0));
  tau = std::min(tau, std::pow(kShare * tol_v / ((2.0 * n + 3.0) * c2), 1.0 / (2.0 * n + 2.0)));
  if (c1 > 0.0) {
    tau = std::min(tau, std::pow(kShare * tol_x / c1, 1.0 / (n + 3.0)));
    tau = std::min(tau, std::pow(kShare * tol_v / ((n + 3.0) * c1), 1.0 / (n + 2.0)));
  }
  const double room = 0.25 * (seg.end_m - seg.start_m);  // +inf for the last segment
  for (int halving = 0; halving < 60; ++halving, tau *= 0.5) {
    const auto [x, rate] = opening.At(tau);
    if (x > 0.0 && x <= room && rate >= 0.5 * v) {
      opening.duration_s = tau;
      break;
    }
  }
  return opening;
}

/// The end of a phase left downward at x = 0: the phase's opening run backwards (the law is
/// conservative, so the motion is time-reversible). From the state at phase-local
/// penetration x_c > 0 with rate v_c < 0, the exit speed w follows from the energy of the
/// segment's law between x_c and 0,  w² = v_c² + (2/m) (F_off x_c + K x_c^(n+1)/(n+1)),  and
/// the time s left to x = 0 from the series  x(s) = w s - a s² - b s^(n+2)  (PhaseOpening
/// with v = w, s counted back from the exit) by Newton. The closing point is where the
/// opening ended, so the series keeps the same tolerance. duration_s = 0: no closing found.
struct PhaseClosing {
  double duration_s = 0.0;  ///< s, the time from the closing point to x = 0 [s]
  PhaseOpening series;      ///< x and -rate at time s' before the exit
};

PhaseClosing ClosePhase(const ForceLawSegment& seg, double x_c, double v_c, double inverse_mass) {
  PhaseClosing closing;
  const double n = seg.exponent;
  const double drop = 2.0 * inverse_mass *
                      (seg.force_offset_N * x_c + seg.stiffness * std::pow(x_c, n + 1.0) / (n + 1.0));
  const double w = std::sqrt(v_c * v_c + drop);
  if (!(x_c > 0.0 && w > 0.0 && std::isfinite(w))) return closing;
  PhaseOpening& series = closing.series;
  series.v = w;
  series.n = n;
  series.a = 0.5 * seg.force_offset_N * inverse_mass;
  series.b = seg.stiffness * std::pow(w, n) * inverse_mass / ((n + 1.0) * (n + 2.0));
  double s = x_c / w;
  for (int iteration = 0; iteration < 20; ++iteration) {
    const auto [x, rate] = series.At(s);
    if (!(rate > 0.0)) return closing;
    const double step = (x - x_c) / rate;
    s -= step;
    if (std::abs(step) <= 1e-15 * s) {
      if (s > 0.0 && std::isfinite(s)) closing.duration_s = s;
      return closing;
    }
  }
  return closing;
}

/// The largest excursion past a switch, in units of the integrator's δ tolerance there
/// (tol_x = atol L + rtol δ, the local tolerance of OpenPhase), that GrazingTurnAtSwitch takes
/// from its series instead of integrating it. The integrator controls δ only to tol_x per step:
/// an excursion below that is inside its own error, and the root functions that must see it
/// (the turn, then the return through the next phase's closing point, which its opening puts
/// at no more than 3/4 of the excursion) compare values within that error. Measured before
/// the series existed, over 6 scenes x 522 offsets of δ_max from the full-compression switch
/// (±1e-17 .. ±1e-4 relative) x 8 methods x rtol 1e-4 .. 1e-12 (200 448 runs): each of the
/// 2300 failures had a rise below 0.55 tol_x at the switch root, and all 32 000 runs with a
/// rise between 1 and 100 tol_x integrated correctly. 10 is 18 times the largest rise that
/// failed. In floating point, rtol >= 1e-14 makes 10 tol_x at least 1e-13 δ, some 450 units in
/// the last place of δ: an excursion that is integrated never rounds back onto the switch.
constexpr double kGrazingExcursionTolerances = 10.0;

/// The share of tol_x the series of a grazing excursion may be off by (as in OpenPhase).
constexpr double kGrazingSeriesShare = 0.05;

/// Maximum compression taken from the local series where δ_max grazes a switch.
///
/// At the root of an upward switch (δ_s = δ at the end of segment `below`, speed v) the
/// integrator would restart in segment below + 1 and integrate the rest of the loading, the
/// turn and the return. The excursion beyond the switch is, to second order,
///     δ(t_s + τ) = δ_s + v τ - A τ² / 2,   A = F(δ_s) / m   (the law beyond the switch):
/// a rise of v² / (2A) to the turn at τ = v / A, back at δ_s at τ = 2 v / A with speed -v
/// (the motion is conservative and time-reversible). When that rise is below
/// kGrazingExcursionTolerances tol_x the whole excursion is taken from this series. Its error
/// comes from the force's growth ΔF over the rise, which moves δ_max by at most rise ΔF / F;
/// the series is used only while that is below kGrazingSeriesShare tol_x (for the cumulative
/// law ΔF = K rise^n, far below it). Integrating such an excursion failed instead: after the
/// restart δ_s + x rounded to δ_s, so the lower switch's root function was exactly 0 from the
/// restart on and its crossing was never seen (CVODE: "Root found at and very near t", ERK 5(4)
/// ran away on the continued law, ERK 8(7) hit its step limit).
///
/// A root found with v <= 0 is the turn itself (the crossing and the turn within the root
/// finder's tolerance): maximum compression is there, at δ_s + v² / (2A) with the current
/// law's A, and the run goes on downward in the same segment.
struct GrazingTurn {
  double time_to_turn_s = 0.0;  ///< from the switch root to δ' = 0 [s]; <= 0 for v <= 0
  double deceleration_m_per_s2 = 0.0;  ///< A
  double max_penetration_m = 0.0;
  double max_energy_density_J_per_m2 = 0.0;  ///< e(δ_s) integrated, plus σ (δ_max - δ_s)
  double compressive_stress_Pa = 0.0;  ///< σ_c of the law used over the excursion
  std::size_t segment = 0;             ///< the segment δ_max lies in (for the peaks)
};

std::optional<GrazingTurn> GrazingTurnAtSwitch(const ImpactModel& model, std::size_t below,
                                               const sunrealtype* y, double inverse_mass,
                                               double tolerance_m) {
  const double v = y[1];
  const bool beyond = v > 0.0;  // still loading: the excursion runs on the next segment's law
  const std::size_t law = beyond ? below + 1 : below;
  const ContactState at = model.StateInSegment(law, y[0]);
  const double deceleration = at.force_N * inverse_mass;
  if (!(deceleration > 0.0)) return std::nullopt;
  const double rise = 0.5 * v * v / deceleration;
  if (beyond) {
    if (!(rise <= kGrazingExcursionTolerances * tolerance_m)) return std::nullopt;  // integrate
    const double growth = model.StateInSegment(law, y[0] + rise).force_N / at.force_N - 1.0;
    if (!(std::abs(growth) * rise <= kGrazingSeriesShare * tolerance_m)) return std::nullopt;
  }
  GrazingTurn turn;
  turn.time_to_turn_s = v / deceleration;
  turn.deceleration_m_per_s2 = deceleration;
  // Loading reached the switch: δ_max is beyond it, as on the exact path (its energy exceeds
  // U at the switch) even where δ_s + rise rounds to the switch or δ_s lies a rounding below it.
  turn.max_penetration_m =
      beyond ? std::max(y[0] + rise, model.segment(below).end_m) : y[0] + rise;
  turn.compressive_stress_Pa = at.compressive_stress_Pa;
  turn.max_energy_density_J_per_m2 = y[2] + at.compressive_stress_Pa * rise;
  turn.segment = beyond ? law : model.SegmentIndexAt(turn.max_penetration_m);
  return turn;
}


/// One run of the δ-only path: the state (δ, δ', e), the series openings and closings of the
/// phases, the grazing turns, and the events (switches both ways, the turn, separation).
class ConservativeRun final : public internal::TimePathRun {
 public:
  ConservativeRun(const ImpactModel& model, const TimeIntegrationOptions& options,
                  internal::Stepper& stepper, internal::RunState& run, N_Vector state,
                  N_Vector absolute_tolerances, N_Vector dense_output, const std::string& log)
      : TimePathRun(model, options, stepper, state, dense_output, log),
        run_(run),
        absolute_tolerances_(absolute_tolerances),
        v0_(model.impact_speed_m_per_s()),
        // The bodies' speeds from momentum: m_r v_r + m_b v_b = m_r v0 with v_r - v_b = δ'
        // gives v_b = (m / m_b)(v0 - δ') (0 for a fixed head; v0 - δ' for a fixed robot).
        head_speed_per_closing_(model.effective_mass_kg() / model.scene().head.mass_kg) {
    run_.model = &model;
    run_.segment = options.restart_at_phase_switches ? 0 : internal::kWholeLaw;
    run_.inverse_mass = 1.0 / model.effective_mass_kg();
    run_.closing_m = {};
    SetScales();
    y_[0] = 0.0;
    y_[1] = v0_;
    y_[2] = 0.0;
  }
  ~ConservativeRun() override { run_.model = nullptr; }

 private:
  /// Natural scales: L from phase 1 alone (an upper estimate of δ_max), v0, and the energy
  /// density phase 1 would reach at L. The absolute tolerances are relative to them.
  void SetScales() {
    const ForceLawSegment& first = model_.segment(0);
    const double p1 = first.exponent + 1.0;
    double length_scale = 0.0, energy_density_scale = 0.0;
    if (first.curve) {
      // The foam law: δ where the layer alone stores the energy (at most its stop), and e there.
      length_scale = internal::SolveEnergyBalance(first, model_.impact_energy_J());
      energy_density_scale = model_.StateInSegment(0, length_scale).energy_density_J_per_m2;
    } else {
      length_scale = std::pow(p1 * model_.impact_energy_J() / first.stiffness, 1.0 / p1);
      energy_density_scale = 3.0 / (2.0 * std::numbers::pi) * first.stiffness * first.curvature_per_m *
                             std::pow(length_scale, first.exponent) / first.exponent;
    }
    const double time_scale = length_scale / v0_;
    const double atol =
        options_.absolute_tolerance > 0.0 ? options_.absolute_tolerance : options_.relative_tolerance;
    tolerance_ = N_VGetArrayPointer(absolute_tolerances_);
    tolerance_[0] = atol * length_scale;
    tolerance_[1] = atol * v0_;
    tolerance_[2] = atol * energy_density_scale;
    horizon_s_ = 1e3 * time_scale;  // only orients CVODE's first step (one-step mode)
  }

  HistorySample Sample(double time, const sunrealtype* state) const override {
    const ContactState contact = model_.StateAt(state[0]);
    const double head_speed = head_speed_per_closing_ * (v0_ - state[1]);
    return {time, state[0], state[1], contact.force_N, contact.compressive_stress_Pa, state[2],
            head_speed + state[1], head_speed};
  }

  /// The local δ tolerance of the integrator at the current state [m].
  double PenetrationTolerance() const { return tolerance_[0] + options_.relative_tolerance * std::abs(y_[0]); }

  int Begin() override {
    int flag = Restart(true);
    if (flag == internal::kStepTaken) {
      flag = stepper_.SetTolerances(options_.relative_tolerance, absolute_tolerances_);
    }
    return flag;
  }

  /// An upward entry at x = 0 of the current phase's law: takes the phase's series opening
  /// (sampled for the history), moves (t, y) to its end and returns the integrator's first
  /// step after it, a tenth of it; 0 where no opening is taken.
  double TakeOpening() {
    const std::size_t j = static_cast<std::size_t>(run_.segment);
    const ForceLawSegment& seg = model_.segment(j);
    // The foam law is a polynomial in δ on its curve's first piece: smooth, no opening needed.
    if (seg.origin_m != seg.start_m || seg.curve) return 0.0;
    const double tol_v = tolerance_[1] + options_.relative_tolerance * std::abs(y_[1]);
    const PhaseOpening opening = OpenPhase(seg, y_[1], run_.inverse_mass, PenetrationTolerance(), tol_v);
    if (!(opening.duration_s > 0.0)) return 0.0;
    const double t_start = t_;
    auto set_state = [&](double tau) {
      const auto [x, rate] = opening.At(tau);
      y_[0] = seg.start_m + x;
      y_[1] = rate;
      y_[2] = model_.StateInSegment(j, y_[0]).energy_density_J_per_m2;
    };
    if (options_.record_history) {  // the opening, sampled
      internal::ForEachFillPoint(opening.duration_s, options_.history_max_interval_s, [&](double tau) {
        set_state(tau);
        PushSample(t_start + tau, y_);
      });
    }
    set_state(opening.duration_s);
    // Unloading, the phase ends where its opening did (ClosePhase).
    run_.closing_m[j] = y_[0] - seg.start_m;
    t_ = t_start + opening.duration_s;
    Record(t_, false);
    return 0.1 * opening.duration_s;
  }

  /// Re-initialise at a phase switch. An upward entry (x = 0 of the new phase's law) first
  /// takes the phase's series opening; the integrator starts after it with a step a tenth of
  /// it. A downward entry at the end of a segment meets the same smooth law as the loading
  /// did there (the motion is time-reversible), so it starts with the step that crossed that
  /// end rather than the integrator's cautious estimate (about 1000 times smaller).
  int Restart(bool upward, bool reentry_at_end = true) {
    double first_step = 0.0;  // 0: the integrator estimates
    if (!upward && reentry_at_end && run_.segment != internal::kWholeLaw) {
      first_step = stepper_.ReentryStep(loading_step_at_end_[static_cast<std::size_t>(run_.segment)]);
    }
    if (upward && run_.segment != internal::kWholeLaw && y_[1] > 0.0) {
      const double opening_step = TakeOpening();
      if (opening_step > 0.0) first_step = opening_step;
    }
    int flag = run_started_ ? stepper_.ReInit(t_, state_) : stepper_.BeginRun(t_, state_);
    run_started_ = true;
    if (flag == internal::kStepTaken) flag = stepper_.SetInitStep(first_step);
    return flag;
  }

  /// Records a sample of the grazing turn's series in time order: one that would not come
  /// after the last sample (the excursion shorter than the rounding of t) replaces it if it is
  /// the turn (`replaces`), and is left out otherwise.
  void PushInOrder(double time, const sunrealtype* state, bool replaces) {
    if (result_.history.empty() || time > result_.history.back().time_s) {
      PushSample(time, state);
    } else if (replaces) {
      const double kept = result_.history.back().time_s;
      result_.history.pop_back();
      PushSample(kept, state);
    }
  }

  /// A grazing turn (GrazingTurnAtSwitch) at (t, y): the history gets the excursion from its
  /// series (sampled to the requested spacing) and the turn; y and t move to the return to
  /// the switch.
  void TakeGrazingTurn(const GrazingTurn& turn) {
    const double t_switch = t_;
    const double duration = 2.0 * turn.time_to_turn_s;  // <= 0: the turn was at the root
    const double v = y_[1];
    if (options_.record_history) {
      const double delta_switch = y_[0];
      const double e_switch = y_[2];
      std::array<sunrealtype, 3> state{};
      auto at = [&](double tau) {
        const double rise = (v - 0.5 * turn.deceleration_m_per_s2 * tau) * tau;
        state = {delta_switch + rise, v - turn.deceleration_m_per_s2 * tau,
                 e_switch + turn.compressive_stress_Pa * rise};
        return state.data();
      };
      bool turn_recorded = false;
      auto record_turn = [&] {
        state = {turn.max_penetration_m, 0.0, turn.max_energy_density_J_per_m2};
        PushInOrder(t_switch + std::max(turn.time_to_turn_s, 0.0), state.data(), true);
        turn_recorded = true;
      };
      internal::ForEachFillPoint(duration, options_.history_max_interval_s, [&](double tau) {
        if (!turn_recorded && tau >= turn.time_to_turn_s) record_turn();
        if (tau != turn.time_to_turn_s) PushInOrder(t_switch + tau, at(tau), false);
      });
      if (!turn_recorded) record_turn();
    }
    if (duration > 0.0) {
      y_[1] = -v;  // y[0] and y[2] are back at their values at the switch
      t_ = t_switch + duration;
      if (options_.record_history) PushInOrder(t_, y_, false);
    }
  }

  /// Loading reaches the end of the current segment: a grazing turn, or the next segment.
  int OnUpperSwitch() {
    const std::size_t j = static_cast<std::size_t>(run_.segment);
    loading_step_at_end_[j] = stepper_.LastStep();
    const double tol_x = PenetrationTolerance();
    CountRestart();  // either way the run restarts here
    if (const std::optional<GrazingTurn> turn = GrazingTurnAtSwitch(model_, j, y_, run_.inverse_mass, tol_x)) {
      turned_ = true;
      result_.peaks = PeaksAtMaxPenetration(model_, turn->segment, turn->max_penetration_m);
      result_.peaks.max_energy_density_J_per_m2 = turn->max_energy_density_J_per_m2;
      result_.time_of_max_compression_s = t_ + turn->time_to_turn_s;
      TakeGrazingTurn(*turn);
      // Back at the switch (v > 0: after the excursion, with speed -v; v <= 0: already
      // there): unloading goes on in this segment, as it would after a turn below the switch.
      return Restart(false);
    }
    ++run_.segment;
    return Restart(true);
  }

  /// Maximum compression. F and σ: the largest over the loading branch (the law at δ_max and
  /// at the switches passed), as on the exact path; e as integrated. The law is smooth here:
  /// no restart.
  void OnTurn() {
    turned_ = true;
    result_.peaks = PeaksAtMaxPenetration(model_, model_.SegmentIndexAt(y_[0]), y_[0]);
    result_.peaks.max_energy_density_J_per_m2 = y_[2];
    result_.time_of_max_compression_s = t_;
  }

  /// The phase's series closing from its closing point down to x = 0 (sampled for the
  /// history); false where none was found (then integrate down to the start).
  bool TakeClosing() {
    const std::size_t j = static_cast<std::size_t>(run_.segment);
    const ForceLawSegment& seg = model_.segment(j);
    const PhaseClosing closing = ClosePhase(seg, y_[0] - seg.start_m, y_[1], run_.inverse_mass);
    run_.closing_m[j] = 0.0;  // the phase's own start from here on
    if (!(closing.duration_s > 0.0)) return false;
    const double t_close = t_;
    auto set_state = [&](double before_exit) {
      const auto [x, rate] = closing.series.At(before_exit);
      y_[0] = seg.start_m + x;
      y_[1] = -rate;
      y_[2] = model_.StateInSegment(j, y_[0]).energy_density_J_per_m2;
    };
    if (options_.record_history) {  // the closing, sampled
      internal::ForEachFillPoint(closing.duration_s, options_.history_max_interval_s, [&](double tau) {
        set_state(closing.duration_s - tau);
        PushSample(t_close + tau, y_);
      });
    }
    set_state(0.0);
    t_ = t_close + closing.duration_s;
    Record(t_, false);
    return true;
  }

  /// Unloading reaches the start of the current segment (or its closing point): the segment
  /// below, or separation.
  int OnLowerSwitch() {
    if (run_.segment != internal::kWholeLaw && run_.closing_m[static_cast<std::size_t>(run_.segment)] > 0.0 &&
        !TakeClosing()) {
      CountRestart();
      return Restart(false, false);
    }
    if (run_.segment == 0 || run_.segment == internal::kWholeLaw) {
      Separate(v0_);
      return internal::kRootFound;
    }
    --run_.segment;
    CountRestart();
    return Restart(false);
  }

  int OnRoot(const std::array<int, internal::kMaxRootCount>& found) override {
    // The upper switch first, so that a turn found together with the switch (both within the
    // root finder's tolerance) is the grazing turn.
    if (found[internal::kRootUpperSwitch] && !turned_) return OnUpperSwitch();
    if (found[internal::kRootTurn] && !turned_) {
      OnTurn();
      return internal::kRootFound;
    }
    if (found[internal::kRootLowerSwitch] && turned_) return OnLowerSwitch();
    return internal::kRootFound;
  }

  void Finish() override {
    // Energy is conserved by the model, so its loss measures the error.
    const double energy = model_.StateAt(result_.peaks.max_penetration_m).potential_energy_J;
    const double residual = std::max(std::abs(energy / model_.impact_energy_J() - 1.0),
                                     std::abs(*result_.rebound_speed_m_per_s / v0_ - 1.0));
    FinishChecks(residual, "energy residual", "; the exact path is the reference for peaks");
  }

  internal::RunState& run_;
  N_Vector absolute_tolerances_;
  sunrealtype* tolerance_ = nullptr;
  const double v0_;
  const double head_speed_per_closing_;
  /// Per segment, the step that crossed its end on the way up (Restart).
  std::array<double, 3> loading_step_at_end_{};
  bool run_started_ = false;  // the first start is a new run (Stepper::BeginRun), then restarts
};

}  // namespace

/// The SUNDIALS context, vectors and one integrator per method, created on first use and
/// reused for every run; members are freed in reverse order (the context last).
struct TimeIntegrator::Workspace {
  internal::SundialsContext context;
  internal::RunState run;
  internal::StepperWorkspace steppers{context.get(), 3, internal::StepperResources{.user_data = &run}};
  /// Scenes beyond the conservative two-mass model (extended_time_path.cpp), on first use.
  std::unique_ptr<internal::ExtendedTimePath> extended;
};

void ValidateTimeIntegrationOptions(const TimeIntegrationOptions& o, std::string_view prefix) {
  using internal::FormatNumber;
  const std::string field(prefix);
  if (o.method == ComputationMethod::kExact || ToString(o.method) == "unknown") {
    std::string names;
    for (const ComputationMethod method : TimeIntegrationMethods()) {
      names += (names.empty() ? "" : ", ") + std::string(ToString(method));
    }
    throw std::invalid_argument(field + "method must be a time integrator (" + names + ") (got " +
                                std::string(ToString(o.method)) + ")");
  }
  if (!(o.relative_tolerance >= 1e-14 && o.relative_tolerance <= 1e-2)) {
    throw std::invalid_argument(field + "relative_tolerance must be in [1e-14, 1e-2] (got " +
                                FormatNumber(o.relative_tolerance) + ")");
  }
  if (!(o.absolute_tolerance == 0.0 ||
        (o.absolute_tolerance > 0.0 && o.absolute_tolerance <= 1e-2))) {
    throw std::invalid_argument(field +
                                "absolute_tolerance must be in (0, 1e-2], or 0 for the relative "
                                "tolerance (got " +
                                FormatNumber(o.absolute_tolerance) + ")");
  }
  if (!(o.history_max_interval_s >= 0.0 && std::isfinite(o.history_max_interval_s))) {
    throw std::invalid_argument(field + "history_max_interval_s must be finite and >= 0 s (got " +
                                FormatNumber(o.history_max_interval_s) + ")");
  }
  if (o.max_steps < 10) {
    throw std::invalid_argument(field + "max_steps must be >= 10 (got " +
                                std::to_string(o.max_steps) + ")");
  }
}

TimeIntegrator::TimeIntegrator() : workspace_(std::make_unique<Workspace>()) {}
TimeIntegrator::~TimeIntegrator() = default;
TimeIntegrator::TimeIntegrator(TimeIntegrator&&) noexcept = default;
TimeIntegrator& TimeIntegrator::operator=(TimeIntegrator&&) noexcept = default;

ImpactResult TimeIntegrator::Simulate(const ImpactModel& model,
                                      const TimeIntegrationOptions& options) {
  ValidateTimeIntegrationOptions(options);
  Workspace& ws = *workspace_;
  if (options.force_extended_dynamics && model.is_foam()) {
    throw std::invalid_argument(
        "force_extended_dynamics: the extended time path does not model the foam law of a covering with a "
        "measured curve (docs/model.md §16); leave it off, or give covering.law hertz");
  }
  if (options.force_extended_dynamics || !model.scene().is_conservative_two_mass()) {
    if (!ws.extended) ws.extended = std::make_unique<internal::ExtendedTimePath>(ws.context.get());
    return ws.extended->Simulate(model, options);
  }
  internal::StepperWorkspace& s = ws.steppers;
  s.log.clear();
  ConservativeRun run(model, options, s.StepperFor(options.method), ws.run, s.state, s.absolute_tolerances,
                      s.dense_output, s.log);
  return run.Integrate();
}

ImpactResult SimulateImpact(const ImpactModel& model, const TimeIntegrationOptions& options) {
  thread_local TimeIntegrator integrator;
  return integrator.Simulate(model, options);
}

}  // namespace covopt
