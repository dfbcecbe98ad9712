#pragma once
// Private: the pieces of the exact path's design derivatives (sensitivity.cpp) that the time
// path's forward sensitivities (time_path_sensitivity.cpp) share: the derivatives of each
// force-law segment's parameters and offsets with respect to one design parameter, and the
// partials of F, σ, U, e at a fixed penetration δ inside a segment.
#include <array>

#include "covopt/core/impact_model.hpp"

namespace covopt::internal {

/// The design parameter a derivative is taken with respect to.
enum class DesignParameter {
  kCoveringModulus,    ///< E_c [Pa]
  kCoveringThickness,  ///< b_c [m]
};

/// Derivatives of one segment's parameters and offsets with respect to one design parameter θ.
struct SegmentDerivatives {
  double stiffness = 0.0;       // dK
  double curvature = 0.0;       // dc
  double start = 0.0;           // d start
  double origin = 0.0;          // d origin
  double force_offset = 0.0;    // dF_off
  double stress_offset = 0.0;   // dσ_off
  double energy_start = 0.0;    // dU(start)
  double density_start = 0.0;   // de(start)
};

/// ∂F [N/θ], ∂σ [Pa/θ], ∂U [J/θ], ∂e [J/m²/θ] with respect to θ at fixed δ.
struct Partials {
  double force = 0.0, stress = 0.0, energy = 0.0, density = 0.0;
};

/// The partials at penetration δ [m] inside `seg` (its formula continued past its ends, the
/// phase-local penetration clamped at 0), given the segment's derivatives `d`.
Partials PartialsAt(const ForceLawSegment& seg, const SegmentDerivatives& d, double delta);

/// dσ/dδ [Pa/m] inside a segment at δ (infinite at the origin for n < 2).
double StressSlope(const ForceLawSegment& seg, double delta);

/// The derivatives of every segment of `model` (entries past segment_count() are zero): each
/// segment's offsets are the previous segment's values at its origin/start, differentiated
/// along with the switch's own motion.
std::array<SegmentDerivatives, 3> SegmentDerivativesOf(const ImpactModel& model, DesignParameter parameter);

}  // namespace covopt::internal
