// The braking robot's per-sample safe path speed for Retime (docs/model.md, "Re-timing").
#include "retime_internal.hpp"

namespace covopt::audit::detail {

SafePathSpeed SafePathSpeedFor(const AuditSetup& setup, const robot::JointTrajectory& trajectory,
                               bool keep_ratio_over_time, AuditResult& audit) {
  SafePathSpeed safe = SafePathSpeedOf(setup, trajectory, keep_ratio_over_time, audit);
  if (setup.braking_m_per_s2 > 0.0) {
    safe.warnings.push_back(
        "braking: each sample's safe path speed is the unbraked robot's (conservative: braking only takes energy "
        "out), so the re-timed program may be slower than it needs to be; its re-audit is braked");
  }
  return safe;
}

}  // namespace covopt::audit::detail
