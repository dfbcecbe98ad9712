#pragma once
// Private: one run of a time path, the part both paths share. The δ-only path
// (time_integration.cpp) and the extended path (extended_time_path.cpp) each derive their run
// from TimePathRun and supply the history sample, the first start and the events; the base
// holds the result, records the history (filling gaps with the integrator's dense output),
// drives the event loop (steps, the step limit, roots) and finishes with the status and the
// self-check (validity warnings, energy residual, tolerance and no-restart warnings).
#include <nvector/nvector_serial.h>

#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/time_integration.hpp"
#include "stepper.hpp"

namespace covopt::internal {

/// Calls at(τ) at the points that split [0, duration] [s] into equal gaps no wider than
/// `interval` [s], the ends left out: τ = duration k / gaps, k = 1 .. gaps - 1. Nothing for
/// interval <= 0 (no spacing asked for) or duration <= 0.
template <class At>
void ForEachFillPoint(double duration, double interval, At&& at) {
  if (!(interval > 0.0)) return;
  const int gaps = static_cast<int>(std::ceil(duration / interval));
  for (int k = 1; k < gaps; ++k) at(duration * k / gaps);
}

/// The time path's self-check against its tolerance, shared by every time path: the warning
/// ValidityCode::kToleranceNotKept, "the time path did not keep its tolerance: <residual_name>
/// <residual> exceeds max(100 rtol, 1e-9) = <allowed> (<method>[, no restart at the phase
/// switches])<tail>", when `residual` exceeds max(100 rtol, 1e-9) or is NaN; empty otherwise.
std::optional<ValidityWarning> ToleranceWarning(double residual, const TimeIntegrationOptions& options,
                                                bool restarted, std::string_view residual_name,
                                                std::string_view tail);

/// The most root functions a path has (the extended path's eight).
inline constexpr int kMaxRootCount = 8;

class TimePathRun {
 public:
  TimePathRun(const TimePathRun&) = delete;
  TimePathRun& operator=(const TimePathRun&) = delete;

  /// Records the start, starts the integrator (Begin), runs the event loop and finishes.
  ImpactResult Integrate();

 protected:
  TimePathRun(const ImpactModel& model, const TimeIntegrationOptions& options, Stepper& stepper,
              N_Vector state, N_Vector dense_output, const std::string& log);
  virtual ~TimePathRun() = default;

  /// The history sample of `state` at `time` [s].
  virtual HistorySample Sample(double time, const sunrealtype* state) const = 0;
  /// The first start of the integrator at (t_, y_); returns its flag.
  virtual int Begin() = 0;
  /// After each internal step (already recorded).
  virtual void AfterStep() {}
  /// After each step: the contact has run past the path's time bound (then timed_out_ is set).
  virtual bool PastTimeBound() { return false; }
  /// Why a run that timed out did not end (SolveStatus::kNoSeparation).
  virtual std::string TimeoutMessage() const { return {}; }
  /// The events at a root (already recorded); `found` holds one entry per root function.
  /// Returns the integrator's flag (a restart's, or kRootFound when it goes on as it is).
  virtual int OnRoot(const std::array<int, kMaxRootCount>& found) = 0;
  /// The peaks and the path's own checks after a run that ended well (FinishChecks).
  virtual void Finish() = 0;

  void PushSample(double time, const sunrealtype* state) {
    result_.history.push_back(Sample(time, state));
  }
  /// Records the state y_ at `time` (with record_history); after a step or a root
  /// (`interpolate`), first fills the gap since the last sample with the integrator's dense
  /// output, valid inside the step just taken.
  void Record(double time, bool interpolate);
  /// Adds the interval's counters before a restart and counts the restart.
  void CountRestart();
  void Fail(SolveStatus status, int code, const std::string& what);
  /// Separation: the contact duration and the rebound at the state y_ (δ' = y_[1] < 0).
  void Separate(double impact_speed_m_per_s);
  /// The validity warnings of the peaks, the energy residual and, where it exceeds
  /// max(100 rtol, 1e-9), the tolerance warning (its quantity named `residual_name`, followed
  /// by `tail`), and the warning of a run without restarts.
  void FinishChecks(double residual, std::string_view residual_name, std::string_view tail);

  const ImpactModel& model_;
  const TimeIntegrationOptions& options_;
  Stepper& stepper_;
  N_Vector state_;
  sunrealtype* y_;
  ImpactResult result_;
  double t_ = 0.0;
  /// Orients the integrator's first step only (one-step mode) [s].
  double horizon_s_ = 0.0;
  bool turned_ = false;     ///< maximum compression located
  bool separated_ = false;  ///< separation located: the loop ends
  bool timed_out_ = false;  ///< the contact ran past the path's time bound

 private:
  void SetStatus(int flag);

  N_Vector dense_output_;
  const std::string& log_;
  long steps_taken_ = 0;
};

/// A SUNDIALS context, created and freed with this object.
class SundialsContext {
 public:
  SundialsContext();
  ~SundialsContext();
  SundialsContext(const SundialsContext&) = delete;
  SundialsContext& operator=(const SundialsContext&) = delete;
  SUNContext get() const noexcept { return context_; }

 private:
  SUNContext context_ = nullptr;
};

/// What a time path keeps between runs, on a context owned elsewhere: the state, tolerance
/// and dense-output vectors (fixed-length serial vectors with fused operations: one call
/// instead of a chain of axpys for the Runge-Kutta stage sums and the Adams history; the
/// integrators' vectors are clones of `state`), the message log, and one integrator per
/// method, made on first use. Freed in the right order (integrators before vectors).
class StepperWorkspace {
 public:
  /// `size` state components; `callbacks` gives the right-hand side, roots, Jacobian and
  /// user data (its context, state and log are filled in here).
  StepperWorkspace(SUNContext context, int size, const StepperResources& callbacks);
  ~StepperWorkspace();
  StepperWorkspace(const StepperWorkspace&) = delete;
  StepperWorkspace& operator=(const StepperWorkspace&) = delete;

  /// The integrator of `method` (a time integrator), made on first use.
  Stepper& StepperFor(ComputationMethod method);

  N_Vector state = nullptr;
  N_Vector absolute_tolerances = nullptr;
  N_Vector dense_output = nullptr;
  std::string log;

 private:
  void Release() noexcept;
  StepperResources resources_;
  // One slot per ComputationMethod value (the enum's last value is the largest).
  static constexpr std::size_t kMethodSlots = static_cast<std::size_t>(ComputationMethod::kArkodeEsdirk54) + 1;
  std::array<std::unique_ptr<Stepper>, kMethodSlots> steppers_;
};

}  // namespace covopt::internal
