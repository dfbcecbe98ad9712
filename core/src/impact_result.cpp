// Verdicts, names and validity warnings shared by both computation paths.
#include "covopt/core/impact_result.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace covopt {
namespace {

InjuryVerdict Judge(double value, double limit) noexcept {
  InjuryVerdict verdict;
  verdict.value = value;
  verdict.limit = limit;
  verdict.ratio = value / limit;
  verdict.safe = verdict.ratio <= 1.0;
  return verdict;
}

std::string Millimetres(double metres) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.3g mm", metres * 1e3);
  return buffer;
}

}  // namespace

InjuryAssessment Assess(const ImpactPeaks& peaks, const InjuryLimits& limits) noexcept {
  InjuryAssessment assessment;
  assessment.laceration = Judge(peaks.max_tensile_stress_Pa, limits.laceration_tensile_stress_Pa);
  assessment.contusion =
      Judge(peaks.max_energy_density_J_per_m2, limits.contusion_energy_density_J_per_m2);
  return assessment;
}

std::string_view ToString(ComputationMethod method) noexcept {
  switch (method) {
    case ComputationMethod::kExact: return "exact";
    case ComputationMethod::kCvodeAdams: return "cvode-adams";
    case ComputationMethod::kCvodeBdf: return "cvode-bdf";
    case ComputationMethod::kArkodeErk32: return "arkode-erk32";
    case ComputationMethod::kArkodeErk54: return "arkode-erk54";
    case ComputationMethod::kArkodeErk65: return "arkode-erk65";
    case ComputationMethod::kArkodeErk87: return "arkode-erk87";
    case ComputationMethod::kArkodeSdirk43: return "arkode-sdirk43";
    case ComputationMethod::kArkodeEsdirk54: return "arkode-esdirk54";
  }
  return "unknown";
}

std::vector<ComputationMethod> TimeIntegrationMethods() {
  return {ComputationMethod::kCvodeAdams,    ComputationMethod::kCvodeBdf,
          ComputationMethod::kArkodeErk32,   ComputationMethod::kArkodeErk54,
          ComputationMethod::kArkodeErk65,   ComputationMethod::kArkodeErk87,
          ComputationMethod::kArkodeSdirk43, ComputationMethod::kArkodeEsdirk54};
}

std::optional<ComputationMethod> ParseComputationMethod(std::string_view name) noexcept {
  if (name == ToString(ComputationMethod::kExact)) return ComputationMethod::kExact;
  for (ComputationMethod method : TimeIntegrationMethods()) {
    if (name == ToString(method)) return method;
  }
  return std::nullopt;
}

std::string_view ToString(SolveStatus status) noexcept {
  switch (status) {
    case SolveStatus::kSuccess: return "success";
    case SolveStatus::kStepLimit: return "step-limit";
    case SolveStatus::kSolverFailure: return "solver-failure";
    case SolveStatus::kEventMissed: return "event-missed";
  }
  return "unknown";
}

std::vector<std::string> ValidityWarnings(const ImpactModel& model, const ImpactPeaks& peaks) {
  std::vector<std::string> warnings;
  const double delta_max = peaks.max_penetration_m;
  for (std::size_t i = 0; i < model.segment_count(); ++i) {
    const ForceLawSegment& seg = model.segment(i);
    if (!(delta_max > seg.start_m)) break;
    // Phase-local penetration reached in this contact, and its Hertz contact radius.
    const double x = std::min(delta_max, seg.end_m) - seg.origin_m;
    const double contact_radius = std::sqrt(x / seg.curvature_per_m);
    const double smallest_radius = std::min(seg.radius_a_m, seg.radius_b_m);
    if (contact_radius >= smallest_radius) {
      warnings.push_back("outside Hertz validity: in phase " +
                         std::to_string(PhaseNumber(seg.phase)) + " (" +
                         std::string(ToString(seg.phase)) + ") the contact radius " +
                         Millimetres(contact_radius) + " is not smaller than the radius " +
                         Millimetres(smallest_radius) +
                         " it presses on (paper footnote 7: eq. 4 needs non-sharp contact)");
    }
  }
  if (model.has_covering() && peaks.fully_compressed) {
    warnings.push_back(
        "the covering is fully compressed: the robot reaches the bone through it (phase 3); "
        "the stresses then depend on the stiff robot-bone contact");
  }
  return warnings;
}

}  // namespace covopt
