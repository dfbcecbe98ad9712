#pragma once
// Private: the time path of the body-region contact (docs/model.md §13), and the peaks of a
// contact at a given peak force, shared by both paths.
#include "covopt/core/body_contact.hpp"
#include "covopt/core/solve.hpp"

namespace covopt::internal {

/// Every peak quantity of `model`'s contact when its peak force is `force_N` [N] (status,
/// method, duration and rebound speed are left for the caller).
BodyContactResult PeaksAtForce(const BodyContactModel& model, double force_N);

/// Integrates mu δ'' = -F(δ) with SUNDIALS (options.time_path), restarting where the covering
/// bottoms out; reads the peaks at δ' = 0 and the duration and rebound speed at separation.
BodyContactResult SolveBodyContactTimePath(const BodyContactModel& model, const SolveOptions& options);

}  // namespace covopt::internal
