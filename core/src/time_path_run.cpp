// The run both time paths share (time_path_run.hpp): history, event loop, status, self-check.
#include "time_path_run.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "fixed_length_vector.hpp"
#include "numeric_format.hpp"

namespace covopt::internal {

TimePathRun::TimePathRun(const ImpactModel& model, const TimeIntegrationOptions& options,
                         Stepper& stepper, N_Vector state, N_Vector dense_output,
                         const std::string& log)
    : model_(model),
      options_(options),
      stepper_(stepper),
      state_(state),
      y_(N_VGetArrayPointer(state)),
      dense_output_(dense_output),
      log_(log) {
  result_.method = options.method;
}

void TimePathRun::Record(double time, bool interpolate) {
  if (!options_.record_history) return;
  if (interpolate && !result_.history.empty()) {
    const double last = result_.history.back().time_s;
    ForEachFillPoint(time - last, options_.history_max_interval_s, [&](double since_last) {
      const double tk = last + since_last;
      if (stepper_.Interpolate(tk, dense_output_) == kStepTaken) {
        PushSample(tk, N_VGetArrayPointer(dense_output_));
      }
    });
  }
  PushSample(time, y_);
}

void TimePathRun::CountRestart() {
  stepper_.AddStatistics(result_.statistics);
  ++result_.statistics.restarts;
}

void TimePathRun::Fail(SolveStatus status, int code, const std::string& what) {
  result_.status = status;
  result_.raw_code = code;
  result_.message = what;
  if (!log_.empty()) result_.message += " (SUNDIALS: " + log_ + ")";
}

void TimePathRun::Separate(double impact_speed_m_per_s) {
  separated_ = true;
  result_.contact_duration_s = t_;
  result_.rebound_speed_m_per_s = -y_[1];
  result_.coefficient_of_restitution = -y_[1] / impact_speed_m_per_s;
}

ImpactResult TimePathRun::Integrate() {
  Record(0.0, false);
  int flag = Begin();
  while (flag >= 0 && !separated_) {
    flag = stepper_.Step(t_ + horizon_s_, state_, &t_);
    if (flag == kStepTaken) {
      Record(t_, true);
      AfterStep();
      if (++steps_taken_ >= options_.max_steps) break;
      if (PastTimeBound()) break;
      continue;
    }
    if (flag != kRootFound) break;
    std::array<int, kMaxRootCount> found{};
    stepper_.RootInfo(found.data());
    Record(t_, true);
    flag = OnRoot(found);
  }
  stepper_.AddStatistics(result_.statistics);
  SetStatus(flag);
  if (result_.ok()) Finish();
  return std::move(result_);
}

void TimePathRun::SetStatus(int flag) {
  if (flag < 0) {
    Fail(flag == kTooMuchWork ? SolveStatus::kStepLimit : SolveStatus::kSolverFailure, flag,
         std::string(ToString(options_.method)) + " returned " + stepper_.FlagName(flag));
  } else if (timed_out_) {
    Fail(SolveStatus::kNoSeparation, 0, TimeoutMessage());
  } else if (!separated_ && steps_taken_ >= options_.max_steps) {
    Fail(SolveStatus::kStepLimit, kTooMuchWork,
         "step limit of " + std::to_string(options_.max_steps) + " steps reached before separation");
  } else if (!separated_ || !turned_) {
    Fail(SolveStatus::kEventMissed, flag,
         "the integration ended without locating maximum compression and separation");
  }
}

void TimePathRun::FinishChecks(double residual, std::string_view residual_name,
                               std::string_view tail) {
  for (ValidityWarning& warning : CheckValidity(model_, result_.peaks)) {
    result_.AddWarning(warning.code, std::move(warning.message));
  }
  result_.validity = CoveringLawValidity(model_, result_.peaks);
  // The self-check: the energy balance of the model, which an exact solution keeps.
  result_.energy_residual = residual;
  if (auto warning = ToleranceWarning(residual, options_, options_.restart_at_phase_switches, residual_name, tail)) {
    result_.AddWarning(warning->code, std::move(warning->message));
  }
  if (!options_.restart_at_phase_switches) {
    result_.AddWarning(
        ValidityCode::kNoRestarts,
        "integrated straight through the force law's C0 kinks (restart_at_phase_switches "
        "off): the local error test does not see them, so the error may exceed the "
        "tolerance (a numerics-study setting)");
  }
}

std::optional<ValidityWarning> ToleranceWarning(double residual, const TimeIntegrationOptions& options,
                                                bool restarted, std::string_view residual_name,
                                                std::string_view tail) {
  const double allowed = std::max(100.0 * options.relative_tolerance, 1e-9);
  if (residual <= allowed) return std::nullopt;
  return ValidityWarning{
      ValidityCode::kToleranceNotKept,
      "the time path did not keep its tolerance: " + std::string(residual_name) + " " +
          FormatNumber(residual) + " exceeds max(100 rtol, 1e-9) = " + FormatNumber(allowed) + " (" +
          std::string(ToString(options.method)) + (restarted ? "" : ", no restart at the phase switches") +
          ")" + std::string(tail)};
}

SundialsContext::SundialsContext() {
  if (SUNContext_Create(nullptr, &context_) != 0) throw std::runtime_error("SUNContext_Create failed");
}
SundialsContext::~SundialsContext() {
  if (context_) SUNContext_Free(&context_);
}

StepperWorkspace::StepperWorkspace(SUNContext context, int size, const StepperResources& callbacks)
    : resources_(callbacks) {
  state = MakeFixedLengthVector(size, context);
  absolute_tolerances = MakeFixedLengthVector(size, context);
  dense_output = MakeFixedLengthVector(size, context);
  if (!state || !absolute_tolerances || !dense_output) {
    Release();
    throw std::runtime_error("N_VNew_Serial failed");
  }
  resources_.context = context;
  resources_.state = state;
  resources_.log = &log;
}

StepperWorkspace::~StepperWorkspace() { Release(); }

void StepperWorkspace::Release() noexcept {
  for (auto& stepper : steppers_) stepper.reset();  // before the vectors they were built on
  for (N_Vector* v : {&state, &absolute_tolerances, &dense_output}) {
    if (*v) N_VDestroy(*v);
    *v = nullptr;
  }
}

Stepper& StepperWorkspace::StepperFor(ComputationMethod method) {
  auto& slot = steppers_[static_cast<std::size_t>(method)];
  if (!slot) {
    const bool cvode = method == ComputationMethod::kCvodeAdams || method == ComputationMethod::kCvodeBdf;
    slot = cvode ? MakeCvodeStepper(method, resources_) : MakeArkodeStepper(method, resources_);
  }
  return *slot;
}

}  // namespace covopt::internal
