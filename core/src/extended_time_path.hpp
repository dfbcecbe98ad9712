#pragma once
// Private: the extended time path (docs/model.md §10.2, §10.3), which answers every scene the
// δ-only path of time_integration.cpp cannot: contact damping, a braking robot, a head on a
// neck, and any combination. TimeIntegrator owns one and dispatches to it.
#include <sundials/sundials_context.h>

#include <memory>

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"
#include "covopt/core/time_integration.hpp"

namespace covopt::internal {

/// Its own state vectors (seven entries) and one integrator per method, created on first use
/// on the caller's SUNDIALS context and reused for every run. Not thread-safe.
class ExtendedTimePath {
 public:
  /// `context` must outlive this object.
  explicit ExtendedTimePath(SUNContext context);
  ~ExtendedTimePath();
  ExtendedTimePath(const ExtendedTimePath&) = delete;
  ExtendedTimePath& operator=(const ExtendedTimePath&) = delete;

  /// Integrates one impact; `options` are already validated (TimeIntegrator::Simulate).
  ImpactResult Simulate(const ImpactModel& model, const TimeIntegrationOptions& options);

 private:
  struct Workspace;
  std::unique_ptr<Workspace> workspace_;
};

}  // namespace covopt::internal
