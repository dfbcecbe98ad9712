// CVODES forward sensitivities of the time path's loading branch (time_path_sensitivity.hpp).
#include "covopt/core/time_path_sensitivity.hpp"

#include <cvodes/cvodes.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "sensitivity_internal.hpp"

namespace covopt {
namespace {

using internal::DesignParameter;
using internal::Partials;
using internal::SegmentDerivatives;

constexpr int kParameters = 2;  // ln E_c, ln b_c
constexpr int kRootSwitch = 0;  // δ - end of the segment, upward
constexpr int kRootTurn = 1;    // δ' = 0, downward: maximum compression
constexpr int kRootForce = 2;   // dF/dt = 0, downward (damping only): an interior maximum of F
constexpr int kRootStress = 3;  // dσ/dt = 0, downward (damping only), scaled by x^(2-n)

/// What the callbacks see.
struct Run {
  const ImpactModel* model = nullptr;
  std::size_t segment = 0;
  double inverse_mass = 0.0;
  double damping_s_per_m = 0.0;
  /// Per parameter, per segment: the segment derivatives, already multiplied by θ (d/d ln θ).
  std::array<std::array<SegmentDerivatives, 3>, kParameters> derivatives{};
};

/// The segment's law at δ: F_el, dF_el/dδ, σ_el, and the partials per parameter.
struct Law {
  double force_N = 0.0, stiffness_N_per_m = 0.0, stress_Pa = 0.0;
};

Law LawAt(const Run& run, double delta) {
  const ContactState state = run.model->StateInSegment(run.segment, delta);
  return {state.force_N, state.stiffness_N_per_m, state.compressive_stress_Pa};
}

Partials PartialsOf(const Run& run, int parameter, double delta) {
  return internal::PartialsAt(run.model->segment(run.segment),
                              run.derivatives[static_cast<std::size_t>(parameter)][run.segment], delta);
}

SegmentDerivatives Scaled(SegmentDerivatives d, double scale) {
  d.stiffness *= scale;
  d.curvature *= scale;
  d.start *= scale;
  d.origin *= scale;
  d.force_offset *= scale;
  d.stress_offset *= scale;
  d.energy_start *= scale;
  d.density_start *= scale;
  return d;
}

int RightHandSide(sunrealtype /*t*/, N_Vector y, N_Vector ydot, void* user_data) {
  const Run& run = *static_cast<const Run*>(user_data);
  const sunrealtype* state = NV_DATA_S(y);
  sunrealtype* rate = NV_DATA_S(ydot);
  const Law law = LawAt(run, state[0]);
  const double h = 1.0 + run.damping_s_per_m * state[1];
  rate[0] = state[1];
  rate[1] = -law.force_N * h * run.inverse_mass;
  rate[2] = law.stress_Pa * h * state[1];
  return std::isfinite(rate[1]) && std::isfinite(rate[2]) ? 0 : 1;
}

/// s' = (∂f/∂y) s + ∂f/∂θ for (s_δ, s_v), and w' (see the header) for the third entry.
int SensitivityRightHandSide(int count, sunrealtype /*t*/, N_Vector y, N_Vector ydot, N_Vector* ys,
                             N_Vector* ysdot, void* user_data, N_Vector, N_Vector) {
  const Run& run = *static_cast<const Run*>(user_data);
  const sunrealtype* state = NV_DATA_S(y);
  const double delta = state[0], v = state[1];
  const double acceleration = NV_DATA_S(ydot)[1];
  const Law law = LawAt(run, delta);
  const double d = run.damping_s_per_m;
  const double h = 1.0 + d * v;
  for (int i = 0; i < count; ++i) {
    const sunrealtype* s = NV_DATA_S(ys[i]);
    sunrealtype* out = NV_DATA_S(ysdot[i]);
    const Partials p = PartialsOf(run, i, delta);
    out[0] = s[1];
    out[1] = -(law.stiffness_N_per_m * h * s[0] + law.force_N * d * s[1] + p.force * h) * run.inverse_mass;
    out[2] = law.stress_Pa * d * (v * s[1] - acceleration * s[0]) + p.stress * h * v;
    if (!std::isfinite(out[1]) || !std::isfinite(out[2])) return 1;
  }
  return 0;
}

int RootFunctions(sunrealtype /*t*/, N_Vector y, sunrealtype* g, void* user_data) {
  const Run& run = *static_cast<const Run*>(user_data);
  const sunrealtype* state = NV_DATA_S(y);
  const ForceLawSegment& seg = run.model->segment(run.segment);
  g[kRootSwitch] = std::isinf(seg.end_m) ? -1.0 : state[0] - seg.end_m;
  g[kRootTurn] = state[1];
  if (run.damping_s_per_m > 0.0) {
    const double d = run.damping_s_per_m, v = state[1];
    const Law law = LawAt(run, state[0]);
    const double h = 1.0 + d * v;
    const double acceleration = -law.force_N * h * run.inverse_mass;
    g[kRootForce] = law.stiffness_N_per_m * v * h + law.force_N * d * acceleration;
    // dσ/dt = σ'(δ) δ' h + σ d δ''; σ' ~ x^(n-2) is unbounded at a phase start for n < 2,
    // so the function is multiplied by x^(2-n) > 0 there (same sign, finite).
    const double n = seg.exponent;
    const double x = std::max(state[0] - seg.origin_m, 0.0);
    const double kc = 3.0 / (2.0 * std::numbers::pi) * seg.stiffness * seg.curvature_per_m;
    if (n < 2.0) {
      g[kRootStress] = kc * (n - 1.0) * v * h + law.stress_Pa * d * acceleration * std::pow(x, 2.0 - n);
    } else {
      g[kRootStress] = kc * (n - 1.0) * std::pow(x, n - 2.0) * v * h + law.stress_Pa * d * acceleration;
    }
  }
  return 0;
}

void CaptureMessage(int error_code, const char* module, const char* function, char* message, void* user_data) {
  auto* log = static_cast<std::string*>(user_data);
  if (!log) return;
  if (!log->empty()) log->append("; ");
  log->append(error_code > 0 ? "warning" : "error");
  log->append(" in ").append(module ? module : "?").append("::").append(function ? function : "?");
  log->append(": ").append(message ? message : "");
}

/// The SUNDIALS objects of one run, freed in the right order.
struct Workspace {
  SUNContext context = nullptr;
  N_Vector state = nullptr, tolerances = nullptr;
  N_Vector* sensitivities = nullptr;
  N_Vector* sensitivity_tolerances = nullptr;
  void* cvode = nullptr;
  SUNNonlinearSolver solver = nullptr, sensitivity_solver = nullptr;

  Workspace() {
    if (SUNContext_Create(nullptr, &context) != 0) throw std::runtime_error("SUNContext_Create failed");
    state = N_VNew_Serial(3, context);
    tolerances = N_VNew_Serial(3, context);
    if (!state || !tolerances) throw std::runtime_error("N_VNew_Serial failed");
    sensitivities = N_VCloneVectorArray(kParameters, state);
    sensitivity_tolerances = N_VCloneVectorArray(kParameters, state);
    if (!sensitivities || !sensitivity_tolerances) throw std::runtime_error("N_VCloneVectorArray failed");
  }
  ~Workspace() {
    if (cvode) CVodeFree(&cvode);
    if (sensitivity_solver) SUNNonlinSolFree(sensitivity_solver);
    if (solver) SUNNonlinSolFree(solver);
    if (sensitivity_tolerances) N_VDestroyVectorArray(sensitivity_tolerances, kParameters);
    if (sensitivities) N_VDestroyVectorArray(sensitivities, kParameters);
    if (tolerances) N_VDestroy(tolerances);
    if (state) N_VDestroy(state);
    if (context) SUNContext_Free(&context);
  }
  Workspace(const Workspace&) = delete;
  Workspace& operator=(const Workspace&) = delete;
};

/// A candidate for F_max or σ_c,max: its value and its derivative per parameter.
struct Candidate {
  double value = -std::numeric_limits<double>::infinity();
  std::array<double, kParameters> derivative{};
};

void Keep(Candidate& best, const Candidate& c) {
  if (c.value > best.value) best = c;
}

void Validate(const ImpactModel& model, const TimeIntegrationOptions& o) {
  const Scene& scene = model.scene();
  if (!model.has_covering()) {
    throw std::invalid_argument(
        "design sensitivities need a covering (covering.thickness > 0): b_c -> 0 is a discontinuity of the model");
  }
  if (model.is_foam()) {
    throw std::invalid_argument(
        "design sensitivities (d/dE_c, d/db_c) are for the Hertz law: a covering under the foam law (covering.law "
        "foam or auto with a compressive_curve, docs/model.md §16) has a measured curve, not a modulus");
  }
  if (!scene.has_energy_integral()) {
    throw std::invalid_argument(
        "time-path forward sensitivities cover the two-mass contact (conservative or damped); a braking robot "
        "(robot.braking) or a neck (head.torso_mass) is outside that system");
  }
  ValidateTimeIntegrationOptions(o);
}

std::string FlagName(int flag) {
  char* name = CVodeGetReturnFlagName(flag);
  std::string text = name ? name : "unknown flag";
  std::free(name);
  return text + " (" + std::to_string(flag) + ")";
}

/// One forward-sensitivity run along the loading branch: the CVODES setup, the events
/// (switches with the sensitivities' jump, with damping the interior maxima of F and σ_c, the
/// turn) and the peaks with their derivatives.
class SensitivityRun {
 public:
  SensitivityRun(const ImpactModel& model, const TimeIntegrationOptions& options)
      : model_(model), options_(options) {
    SetUpRun();
    SetUpState();
  }
  SensitivityRun(const SensitivityRun&) = delete;
  SensitivityRun& operator=(const SensitivityRun&) = delete;

  TimePathSensitivities Integrate();

 private:
  /// What the callbacks see, with the segment derivatives per ln θ.
  void SetUpRun() {
    const Scene& scene = model_.scene();
    run_.model = &model_;
    run_.inverse_mass = 1.0 / model_.effective_mass_kg();
    run_.damping_s_per_m = scene.model.damping_s_per_m;
    parameter_ = {scene.covering.youngs_modulus_Pa, scene.covering.thickness_m};
    const std::array<DesignParameter, kParameters> which = {DesignParameter::kCoveringModulus,
                                                            DesignParameter::kCoveringThickness};
    for (int i = 0; i < kParameters; ++i) {
      const auto all = internal::SegmentDerivativesOf(model_, which[static_cast<std::size_t>(i)]);
      for (std::size_t j = 0; j < all.size(); ++j) {
        run_.derivatives[static_cast<std::size_t>(i)][j] = Scaled(all[j], parameter_[static_cast<std::size_t>(i)]);
      }
    }
  }

  /// The time path's natural scales (time_integration.cpp): L from phase 1 alone, v0, and
  /// the energy density phase 1 reaches at L; s = dy/d ln θ has the same scales. The state
  /// at first contact, no sensitivity yet.
  void SetUpState() {
    const ForceLawSegment& first = model_.segment(0);
    const double v0 = model_.impact_speed_m_per_s();
    const double p1 = first.exponent + 1.0;
    const double length_scale = std::pow(p1 * model_.impact_energy_J() / first.stiffness, 1.0 / p1);
    const double density_scale = 3.0 / (2.0 * std::numbers::pi) * first.stiffness * first.curvature_per_m *
                                 std::pow(length_scale, first.exponent) / first.exponent;
    const double rtol = options_.relative_tolerance;
    const double atol = options_.absolute_tolerance > 0.0 ? options_.absolute_tolerance : rtol;
    sunrealtype* tolerance = NV_DATA_S(ws_.tolerances);
    tolerance[0] = atol * length_scale;
    tolerance[1] = atol * v0;
    tolerance[2] = atol * density_scale;
    for (int i = 0; i < kParameters; ++i) N_VScale(1.0, ws_.tolerances, ws_.sensitivity_tolerances[i]);
    y_ = NV_DATA_S(ws_.state);
    y_[0] = 0.0;
    y_[1] = v0;
    y_[2] = 0.0;
    for (int i = 0; i < kParameters; ++i) N_VConst(0.0, ws_.sensitivities[i]);
    time_scale_s_ = length_scale / v0;
  }

  /// CVODES Adams with fixed-point iteration, the sensitivities staggered and in the error
  /// test; returns the first failing flag (CV_SUCCESS when all went well).
  int SetUpCvodes() {
    const int roots = run_.damping_s_per_m > 0.0 ? 4 : 2;
    const double rtol = options_.relative_tolerance;
    ws_.cvode = CVodeCreate(CV_ADAMS, ws_.context);
    if (!ws_.cvode) throw std::runtime_error("CVodeCreate failed");
    CVodeSetErrHandlerFn(ws_.cvode, CaptureMessage, &log_);
    ws_.solver = SUNNonlinSol_FixedPoint(ws_.state, 0, ws_.context);
    ws_.sensitivity_solver = SUNNonlinSol_FixedPointSens(kParameters, ws_.state, 0, ws_.context);
    int flag = CVodeInit(ws_.cvode, RightHandSide, 0.0, ws_.state);
    if (flag == CV_SUCCESS) flag = CVodeSetUserData(ws_.cvode, &run_);
    if (flag == CV_SUCCESS) flag = CVodeSVtolerances(ws_.cvode, rtol, ws_.tolerances);
    if (flag == CV_SUCCESS) flag = CVodeSetNonlinearSolver(ws_.cvode, ws_.solver);
    if (flag == CV_SUCCESS) flag = CVodeSetMaxNumSteps(ws_.cvode, options_.max_steps);
    if (flag == CV_SUCCESS) flag = CVodeRootInit(ws_.cvode, roots, RootFunctions);
    if (flag == CV_SUCCESS) {
      int directions[4] = {+1, -1, -1, -1};
      flag = CVodeSetRootDirection(ws_.cvode, directions);
    }
    if (flag == CV_SUCCESS) flag = CVodeSetNoInactiveRootWarn(ws_.cvode);
    if (flag == CV_SUCCESS) {
      flag = CVodeSensInit(ws_.cvode, kParameters, CV_STAGGERED, SensitivityRightHandSide, ws_.sensitivities);
    }
    if (flag == CV_SUCCESS) flag = CVodeSensSVtolerances(ws_.cvode, rtol, ws_.sensitivity_tolerances);
    if (flag == CV_SUCCESS) flag = CVodeSetSensErrCon(ws_.cvode, SUNTRUE);
    if (flag == CV_SUCCESS) flag = CVodeSetNonlinearSolverSensStg(ws_.cvode, ws_.sensitivity_solver);
    return flag;
  }

  void AddStatistics() {
    long steps = 0, rhs = 0, sens_rhs = 0, g = 0, fails = 0, iterations = 0, conv = 0;
    CVodeGetNumSteps(ws_.cvode, &steps);
    CVodeGetNumRhsEvals(ws_.cvode, &rhs);
    CVodeGetSensNumRhsEvals(ws_.cvode, &sens_rhs);
    CVodeGetNumGEvals(ws_.cvode, &g);
    CVodeGetNumErrTestFails(ws_.cvode, &fails);
    CVodeGetNumNonlinSolvIters(ws_.cvode, &iterations);
    CVodeGetNumNonlinSolvConvFails(ws_.cvode, &conv);
    out_.statistics.steps += steps;
    out_.statistics.rhs_evaluations += rhs + sens_rhs;
    out_.statistics.root_evaluations += g;
    out_.statistics.error_test_failures += fails;
    out_.statistics.nonlinear_iterations += iterations;
    out_.statistics.convergence_failures += conv;
  }

  TimePathSensitivities Fail(SolveStatus status, int code, const std::string& what) {
    out_.status = status;
    out_.raw_code = code;
    out_.message = what + (log_.empty() ? "" : " (SUNDIALS: " + log_ + ")");
    return out_;
  }

  /// s_e from w (the integrated third entry) at the current state: s_e = w + σ h s_δ.
  double EnergySensitivity(int i) const {
    const sunrealtype* s = NV_DATA_S(ws_.sensitivities[i]);
    return s[2] + LawAt(run_, y_[0]).stress_Pa * (1.0 + run_.damping_s_per_m * y_[1]) * s[0];
  }

  /// The value of F (σ) = P_el h at the current state, and its total derivative when the
  /// event's time moves by dτ/dθ = `time_shift[i]`: (∂P/∂θ + P'(s_δ + δ' dτ)) h + P d (s_v + δ'' dτ).
  std::array<Candidate, 2> Candidates(const std::array<double, kParameters>& time_shift) const {
    const double d = run_.damping_s_per_m;
    const Law law = LawAt(run_, y_[0]);
    const double h = 1.0 + d * y_[1];
    const double acceleration = -law.force_N * h * run_.inverse_mass;
    const double stress_slope = internal::StressSlope(model_.segment(run_.segment), y_[0]);
    std::array<Candidate, 2> c;  // force, stress
    c[0].value = law.force_N * h;
    c[1].value = law.stress_Pa * h;
    for (int i = 0; i < kParameters; ++i) {
      const sunrealtype* s = NV_DATA_S(ws_.sensitivities[i]);
      const Partials p = PartialsOf(run_, i, y_[0]);
      const double dt = time_shift[static_cast<std::size_t>(i)];
      const double penetration = s[0] + y_[1] * dt, rate = s[1] + acceleration * dt;
      c[0].derivative[static_cast<std::size_t>(i)] =
          (p.force + law.stiffness_N_per_m * penetration) * h + law.force_N * d * rate;
      // σ' is unbounded at a phase start (x^(n-2)); there the penetration's motion is 0
      // (a switch: s_δ + δ' dτ = dt_j/dθ, multiplied by a slope only for a moving phase 3).
      const double slope_term = penetration == 0.0 || !std::isfinite(stress_slope) ? 0.0 : stress_slope * penetration;
      c[1].derivative[static_cast<std::size_t>(i)] = (p.stress + slope_term) * h + law.stress_Pa * d * rate;
    }
    return c;
  }

  /// Maximum compression: dτ/dθ = -s_v / δ'' at δ' = 0.
  void OnTurn() {
    const Law law = LawAt(run_, y_[0]);
    const double acceleration = -law.force_N * run_.inverse_mass;
    std::array<double, kParameters> shift{};
    for (int i = 0; i < kParameters; ++i) {
      shift[static_cast<std::size_t>(i)] = -NV_DATA_S(ws_.sensitivities[i])[1] / acceleration;
    }
    const auto c = Candidates(shift);
    Keep(force_max_, c[0]);
    Keep(stress_max_, c[1]);
  }

  /// A switch upward: dτ/dθ = -(s_δ - dt_j/dθ)/δ'; the left values are candidates, then the
  /// jump s⁺ = s⁻ + (f⁻ - f⁺) dτ/dθ and w re-expressed with the next segment's σ. Returns
  /// the restart's flag.
  int OnSwitch() {
    const double d = run_.damping_s_per_m;
    const std::size_t j = run_.segment;
    std::array<double, kParameters> shift{};
    std::array<double, kParameters> energy{};
    for (int i = 0; i < kParameters; ++i) {
      const double moving_end = run_.derivatives[static_cast<std::size_t>(i)][j + 1].start;
      shift[static_cast<std::size_t>(i)] = -(NV_DATA_S(ws_.sensitivities[i])[0] - moving_end) / y_[1];
      energy[static_cast<std::size_t>(i)] = EnergySensitivity(i);
    }
    const auto c = Candidates(shift);
    Keep(force_max_, c[0]);
    Keep(stress_max_, c[1]);
    const double h = 1.0 + d * y_[1];
    const Law before = LawAt(run_, y_[0]);
    ++run_.segment;
    const Law after = LawAt(run_, y_[0]);
    const double force_jump = -(before.force_N - after.force_N) * h * run_.inverse_mass;
    const double density_jump = (before.stress_Pa - after.stress_Pa) * h * y_[1];
    for (int i = 0; i < kParameters; ++i) {
      sunrealtype* s = NV_DATA_S(ws_.sensitivities[i]);
      const double dt = shift[static_cast<std::size_t>(i)];
      s[1] += force_jump * dt;
      const double s_e = energy[static_cast<std::size_t>(i)] + density_jump * dt;
      s[2] = s_e - after.stress_Pa * h * s[0];
    }
    AddStatistics();
    ++out_.statistics.restarts;
    int flag = CVodeReInit(ws_.cvode, t_, ws_.state);
    if (flag == CV_SUCCESS) flag = CVodeSensReInit(ws_.cvode, CV_STAGGERED, ws_.sensitivities);
    return flag;
  }

  /// The peaks at maximum compression and their derivatives per E_c and b_c.
  void SetPeaks() {
    out_.peaks = PeaksAtMaxPenetration(model_, run_.segment, y_[0]);
    out_.peaks.peak_force_N = force_max_.value;
    out_.peaks.max_compressive_stress_Pa = stress_max_.value;
    out_.peaks.max_tensile_stress_Pa = model_.TensileFromCompressive(stress_max_.value);
    out_.peaks.max_energy_density_J_per_m2 = y_[2];
    std::array<PeakDerivatives*, kParameters> per = {&out_.sensitivities.per_covering_modulus,
                                                     &out_.sensitivities.per_covering_thickness};
    for (int i = 0; i < kParameters; ++i) {
      const std::size_t k = static_cast<std::size_t>(i);
      const double to_parameter = 1.0 / parameter_[k];  // d/dθ = (1/θ) d/d ln θ
      PeakDerivatives& p = *per[k];
      p.max_penetration = NV_DATA_S(ws_.sensitivities[i])[0] * to_parameter;
      p.peak_force = force_max_.derivative[k] * to_parameter;
      p.max_compressive_stress = stress_max_.derivative[k] * to_parameter;
      p.max_tensile_stress = model_.TensileFromCompressive(p.max_compressive_stress);
      p.max_energy_density = EnergySensitivity(i) * to_parameter;
    }
  }

  const ImpactModel& model_;
  const TimeIntegrationOptions& options_;
  std::array<double, kParameters> parameter_{};
  Run run_;
  std::string log_;  // CVODES' messages; outlives the workspace
  Workspace ws_;
  TimePathSensitivities out_;
  sunrealtype* y_ = nullptr;
  double t_ = 0.0;
  double time_scale_s_ = 0.0;
  Candidate force_max_, stress_max_;
};

TimePathSensitivities SensitivityRun::Integrate() {
  int flag = SetUpCvodes();
  if (flag != CV_SUCCESS) return Fail(SolveStatus::kSolverFailure, flag, "CVODES setup returned " + FlagName(flag));
  const double horizon = 1e4 * time_scale_s_;
  while (true) {
    flag = CVode(ws_.cvode, horizon, ws_.state, &t_, CV_NORMAL);
    if (flag < 0) {
      AddStatistics();
      return Fail(flag == CV_TOO_MUCH_WORK ? SolveStatus::kStepLimit : SolveStatus::kSolverFailure, flag,
                  "CVODES (forward sensitivities) returned " + FlagName(flag));
    }
    if (flag != CV_ROOT_RETURN) {
      AddStatistics();
      return Fail(SolveStatus::kEventMissed, flag, "the sensitivity integration ended without reaching maximum compression");
    }
    int found[4] = {0, 0, 0, 0};
    CVodeGetRootInfo(ws_.cvode, found);
    if (CVodeGetSens(ws_.cvode, &t_, ws_.sensitivities) != CV_SUCCESS) {
      AddStatistics();
      return Fail(SolveStatus::kSolverFailure, flag, "CVodeGetSens failed");
    }
    if (found[kRootTurn]) {
      OnTurn();
      break;
    }
    if ((found[kRootForce] || found[kRootStress])) {
      const auto c = Candidates({0.0, 0.0});  // envelope: dP/dt = 0
      if (found[kRootForce]) Keep(force_max_, c[0]);
      if (found[kRootStress]) Keep(stress_max_, c[1]);
      if (!found[kRootSwitch]) continue;  // a smooth point of the law: no restart
    }
    if (found[kRootSwitch]) {
      flag = OnSwitch();
      if (flag != CV_SUCCESS) return Fail(SolveStatus::kSolverFailure, flag, "CVodeReInit returned " + FlagName(flag));
    }
  }
  AddStatistics();
  SetPeaks();
  return out_;
}

}  // namespace

TimePathSensitivities TimePathPeakSensitivities(const ImpactModel& model, const TimeIntegrationOptions& options) {
  Validate(model, options);
  SensitivityRun run(model, options);
  return run.Integrate();
}

}  // namespace covopt
