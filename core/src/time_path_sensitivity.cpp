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

#include "numeric_format.hpp"
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
  using internal::FormatNumber;
  const Scene& scene = model.scene();
  if (!model.has_covering()) {
    throw std::invalid_argument(
        "design sensitivities need a covering (covering.thickness > 0): b_c -> 0 is a discontinuity of the model");
  }
  if (scene.robot_brakes() || scene.head.has_neck()) {
    throw std::invalid_argument(
        "time-path forward sensitivities cover the two-mass contact (conservative or damped); a braking robot "
        "(robot.braking) or a neck (head.torso_mass) is outside that system");
  }
  if (!(o.relative_tolerance >= 1e-14 && o.relative_tolerance <= 1e-2)) {
    throw std::invalid_argument("rtol must be in [1e-14, 1e-2] (got " + FormatNumber(o.relative_tolerance) + ")");
  }
  if (!(o.absolute_tolerance == 0.0 || (o.absolute_tolerance > 0.0 && o.absolute_tolerance <= 1e-2))) {
    throw std::invalid_argument("atol must be in (0, 1e-2], or 0 for atol = rtol (got " +
                                FormatNumber(o.absolute_tolerance) + ")");
  }
  if (o.max_steps < 10) {
    throw std::invalid_argument("max_steps must be >= 10 (got " + std::to_string(o.max_steps) + ")");
  }
}

std::string FlagName(int flag) {
  char* name = CVodeGetReturnFlagName(flag);
  std::string text = name ? name : "unknown flag";
  std::free(name);
  return text + " (" + std::to_string(flag) + ")";
}

}  // namespace

TimePathSensitivities TimePathPeakSensitivities(const ImpactModel& model, const TimeIntegrationOptions& options) {
  Validate(model, options);
  const Scene& scene = model.scene();
  Run run;
  run.model = &model;
  run.inverse_mass = 1.0 / model.effective_mass_kg();
  run.damping_s_per_m = scene.model.damping_s_per_m;
  const std::array<double, kParameters> parameter = {scene.covering.youngs_modulus_Pa, scene.covering.thickness_m};
  const std::array<DesignParameter, kParameters> which = {DesignParameter::kCoveringModulus,
                                                          DesignParameter::kCoveringThickness};
  for (int i = 0; i < kParameters; ++i) {
    const auto all = internal::SegmentDerivativesOf(model, which[static_cast<std::size_t>(i)]);
    for (std::size_t j = 0; j < all.size(); ++j) {
      run.derivatives[static_cast<std::size_t>(i)][j] = Scaled(all[j], parameter[static_cast<std::size_t>(i)]);
    }
  }

  Workspace ws;
  std::string log;
  TimePathSensitivities out;
  auto fail = [&](SolveStatus status, int code, const std::string& what) {
    out.status = status;
    out.raw_code = code;
    out.message = what + (log.empty() ? "" : " (SUNDIALS: " + log + ")");
    return out;
  };

  // The time path's natural scales (time_integration.cpp): L from phase 1 alone, v0, and
  // the energy density phase 1 reaches at L; s = dy/d ln θ has the same scales.
  const ForceLawSegment& first = model.segment(0);
  const double v0 = model.impact_speed_m_per_s();
  const double p1 = first.exponent + 1.0;
  const double length_scale = std::pow(p1 * model.impact_energy_J() / first.stiffness, 1.0 / p1);
  const double density_scale = 3.0 / (2.0 * std::numbers::pi) * first.stiffness * first.curvature_per_m *
                               std::pow(length_scale, first.exponent) / first.exponent;
  const double rtol = options.relative_tolerance;
  const double atol = options.absolute_tolerance > 0.0 ? options.absolute_tolerance : rtol;
  sunrealtype* tolerance = NV_DATA_S(ws.tolerances);
  tolerance[0] = atol * length_scale;
  tolerance[1] = atol * v0;
  tolerance[2] = atol * density_scale;
  for (int i = 0; i < kParameters; ++i) N_VScale(1.0, ws.tolerances, ws.sensitivity_tolerances[i]);

  sunrealtype* y = NV_DATA_S(ws.state);
  y[0] = 0.0;
  y[1] = v0;
  y[2] = 0.0;
  for (int i = 0; i < kParameters; ++i) N_VConst(0.0, ws.sensitivities[i]);

  const bool damped = run.damping_s_per_m > 0.0;
  const int roots = damped ? 4 : 2;
  ws.cvode = CVodeCreate(CV_ADAMS, ws.context);
  if (!ws.cvode) throw std::runtime_error("CVodeCreate failed");
  CVodeSetErrHandlerFn(ws.cvode, CaptureMessage, &log);
  ws.solver = SUNNonlinSol_FixedPoint(ws.state, 0, ws.context);
  ws.sensitivity_solver = SUNNonlinSol_FixedPointSens(kParameters, ws.state, 0, ws.context);
  int flag = CVodeInit(ws.cvode, RightHandSide, 0.0, ws.state);
  if (flag == CV_SUCCESS) flag = CVodeSetUserData(ws.cvode, &run);
  if (flag == CV_SUCCESS) flag = CVodeSVtolerances(ws.cvode, rtol, ws.tolerances);
  if (flag == CV_SUCCESS) flag = CVodeSetNonlinearSolver(ws.cvode, ws.solver);
  if (flag == CV_SUCCESS) flag = CVodeSetMaxNumSteps(ws.cvode, options.max_steps);
  if (flag == CV_SUCCESS) flag = CVodeRootInit(ws.cvode, roots, RootFunctions);
  if (flag == CV_SUCCESS) {
    int directions[4] = {+1, -1, -1, -1};
    flag = CVodeSetRootDirection(ws.cvode, directions);
  }
  if (flag == CV_SUCCESS) flag = CVodeSetNoInactiveRootWarn(ws.cvode);
  if (flag == CV_SUCCESS) {
    flag = CVodeSensInit(ws.cvode, kParameters, CV_STAGGERED, SensitivityRightHandSide, ws.sensitivities);
  }
  if (flag == CV_SUCCESS) flag = CVodeSensSVtolerances(ws.cvode, rtol, ws.sensitivity_tolerances);
  if (flag == CV_SUCCESS) flag = CVodeSetSensErrCon(ws.cvode, SUNTRUE);
  if (flag == CV_SUCCESS) flag = CVodeSetNonlinearSolverSensStg(ws.cvode, ws.sensitivity_solver);
  if (flag != CV_SUCCESS) return fail(SolveStatus::kSolverFailure, flag, "CVODES setup returned " + FlagName(flag));

  auto add_statistics = [&] {
    long steps = 0, rhs = 0, sens_rhs = 0, g = 0, fails = 0, iterations = 0, conv = 0;
    CVodeGetNumSteps(ws.cvode, &steps);
    CVodeGetNumRhsEvals(ws.cvode, &rhs);
    CVodeGetSensNumRhsEvals(ws.cvode, &sens_rhs);
    CVodeGetNumGEvals(ws.cvode, &g);
    CVodeGetNumErrTestFails(ws.cvode, &fails);
    CVodeGetNumNonlinSolvIters(ws.cvode, &iterations);
    CVodeGetNumNonlinSolvConvFails(ws.cvode, &conv);
    out.statistics.steps += steps;
    out.statistics.rhs_evaluations += rhs + sens_rhs;
    out.statistics.root_evaluations += g;
    out.statistics.error_test_failures += fails;
    out.statistics.nonlinear_iterations += iterations;
    out.statistics.convergence_failures += conv;
  };

  const double d = run.damping_s_per_m;
  // s_e from w (the integrated third entry) at the current state: s_e = w + σ h s_δ.
  auto energy_sensitivity = [&](int i) {
    const sunrealtype* s = NV_DATA_S(ws.sensitivities[i]);
    return s[2] + LawAt(run, y[0]).stress_Pa * (1.0 + d * y[1]) * s[0];
  };
  // The value of F (σ) = P_el h at the current state, and its total derivative when the
  // event's time moves by dτ/dθ = `time_shift[i]`: (∂P/∂θ + P'(s_δ + δ' dτ)) h + P d (s_v + δ'' dτ).
  auto candidates = [&](const std::array<double, kParameters>& time_shift) {
    const Law law = LawAt(run, y[0]);
    const double h = 1.0 + d * y[1];
    const double acceleration = -law.force_N * h * run.inverse_mass;
    const double stress_slope = internal::StressSlope(model.segment(run.segment), y[0]);
    std::array<Candidate, 2> c;  // force, stress
    c[0].value = law.force_N * h;
    c[1].value = law.stress_Pa * h;
    for (int i = 0; i < kParameters; ++i) {
      const sunrealtype* s = NV_DATA_S(ws.sensitivities[i]);
      const Partials p = PartialsOf(run, i, y[0]);
      const double dt = time_shift[static_cast<std::size_t>(i)];
      const double penetration = s[0] + y[1] * dt, rate = s[1] + acceleration * dt;
      c[0].derivative[static_cast<std::size_t>(i)] =
          (p.force + law.stiffness_N_per_m * penetration) * h + law.force_N * d * rate;
      // σ' is unbounded at a phase start (x^(n-2)); there the penetration's motion is 0
      // (a switch: s_δ + δ' dτ = dt_j/dθ, multiplied by a slope only for a moving phase 3).
      const double slope_term = penetration == 0.0 || !std::isfinite(stress_slope) ? 0.0 : stress_slope * penetration;
      c[1].derivative[static_cast<std::size_t>(i)] = (p.stress + slope_term) * h + law.stress_Pa * d * rate;
    }
    return c;
  };

  Candidate force_max, stress_max;
  double t = 0.0;
  const double time_scale = length_scale / v0;
  const double horizon = 1e4 * time_scale;
  bool turned = false;
  while (!turned) {
    flag = CVode(ws.cvode, horizon, ws.state, &t, CV_NORMAL);
    if (flag < 0) {
      add_statistics();
      return fail(flag == CV_TOO_MUCH_WORK ? SolveStatus::kStepLimit : SolveStatus::kSolverFailure, flag,
                  "CVODES (forward sensitivities) returned " + FlagName(flag));
    }
    if (flag != CV_ROOT_RETURN) {
      add_statistics();
      return fail(SolveStatus::kEventMissed, flag, "the sensitivity integration ended without reaching maximum compression");
    }
    int found[4] = {0, 0, 0, 0};
    CVodeGetRootInfo(ws.cvode, found);
    if (CVodeGetSens(ws.cvode, &t, ws.sensitivities) != CV_SUCCESS) {
      add_statistics();
      return fail(SolveStatus::kSolverFailure, flag, "CVodeGetSens failed");
    }
    if (found[kRootTurn]) {
      // dτ/dθ = -s_v / δ'' at δ' = 0.
      const Law law = LawAt(run, y[0]);
      const double acceleration = -law.force_N * run.inverse_mass;
      std::array<double, kParameters> shift{};
      for (int i = 0; i < kParameters; ++i) {
        shift[static_cast<std::size_t>(i)] = -NV_DATA_S(ws.sensitivities[i])[1] / acceleration;
      }
      const auto c = candidates(shift);
      Keep(force_max, c[0]);
      Keep(stress_max, c[1]);
      turned = true;
      break;
    }
    if ((found[kRootForce] || found[kRootStress])) {
      const auto c = candidates({0.0, 0.0});  // envelope: dP/dt = 0
      if (found[kRootForce]) Keep(force_max, c[0]);
      if (found[kRootStress]) Keep(stress_max, c[1]);
      if (!found[kRootSwitch]) continue;  // a smooth point of the law: no restart
    }
    if (found[kRootSwitch]) {
      // dτ/dθ = -(s_δ - dt_j/dθ)/δ'; the left values are candidates, then the jump
      // s⁺ = s⁻ + (f⁻ - f⁺) dτ/dθ and w re-expressed with the next segment's σ.
      const std::size_t j = run.segment;
      std::array<double, kParameters> shift{};
      std::array<double, kParameters> energy{};
      for (int i = 0; i < kParameters; ++i) {
        const double moving_end = run.derivatives[static_cast<std::size_t>(i)][j + 1].start;
        shift[static_cast<std::size_t>(i)] = -(NV_DATA_S(ws.sensitivities[i])[0] - moving_end) / y[1];
        energy[static_cast<std::size_t>(i)] = energy_sensitivity(i);
      }
      const auto c = candidates(shift);
      Keep(force_max, c[0]);
      Keep(stress_max, c[1]);
      const double h = 1.0 + d * y[1];
      const Law before = LawAt(run, y[0]);
      ++run.segment;
      const Law after = LawAt(run, y[0]);
      const double force_jump = -(before.force_N - after.force_N) * h * run.inverse_mass;
      const double density_jump = (before.stress_Pa - after.stress_Pa) * h * y[1];
      for (int i = 0; i < kParameters; ++i) {
        sunrealtype* s = NV_DATA_S(ws.sensitivities[i]);
        const double dt = shift[static_cast<std::size_t>(i)];
        s[1] += force_jump * dt;
        const double s_e = energy[static_cast<std::size_t>(i)] + density_jump * dt;
        s[2] = s_e - after.stress_Pa * h * s[0];
      }
      add_statistics();
      ++out.statistics.restarts;
      flag = CVodeReInit(ws.cvode, t, ws.state);
      if (flag == CV_SUCCESS) flag = CVodeSensReInit(ws.cvode, CV_STAGGERED, ws.sensitivities);
      if (flag != CV_SUCCESS) return fail(SolveStatus::kSolverFailure, flag, "CVodeReInit returned " + FlagName(flag));
    }
  }
  add_statistics();

  const double delta_max = y[0];
  out.peaks = PeaksAtMaxPenetration(model, run.segment, delta_max);
  out.peaks.peak_force_N = force_max.value;
  out.peaks.max_compressive_stress_Pa = stress_max.value;
  out.peaks.max_tensile_stress_Pa = model.TensileFromCompressive(stress_max.value);
  out.peaks.max_energy_density_J_per_m2 = y[2];
  std::array<PeakDerivatives*, kParameters> per = {&out.sensitivities.per_covering_modulus,
                                                   &out.sensitivities.per_covering_thickness};
  for (int i = 0; i < kParameters; ++i) {
    const std::size_t k = static_cast<std::size_t>(i);
    const double to_parameter = 1.0 / parameter[k];  // d/dθ = (1/θ) d/d ln θ
    PeakDerivatives& p = *per[k];
    p.max_penetration = NV_DATA_S(ws.sensitivities[i])[0] * to_parameter;
    p.peak_force = force_max.derivative[k] * to_parameter;
    p.max_compressive_stress = stress_max.derivative[k] * to_parameter;
    p.max_tensile_stress = model.TensileFromCompressive(p.max_compressive_stress);
    p.max_energy_density = energy_sensitivity(i) * to_parameter;
  }
  return out;
}

}  // namespace covopt
