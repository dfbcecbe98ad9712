#pragma once
/// @file sensitivity.hpp
/// Analytic derivatives of the exact peaks with respect to the covering design (E_c, b_c).
///
/// δ_max is an implicit function of the design through U(δ_max; θ) = ½ m v0², so
///
///     dδ_max/dθ = -(∂U/∂θ)|δ / F(δ_max)
///     dP/dθ     = (∂P/∂θ)|δ + P'(δ_max) dδ_max/dθ      for P = F, σ_c, e
///
/// except where the literal reading's F_max or σ_c,max lies at a switch before δ_max: then
/// it is the derivative of the law's value at that switch (which moves with the design only
/// if the switch does).
///
/// The partials at fixed δ are propagated segment by segment: each segment's offsets
/// (F_off, σ_off, U(start), e(start)) are the previous segment's values at its origin/start,
/// and K, the curvature sum c and the thresholds depend on θ through E_c (K1, K2) and b_c
/// (R_c = R_r + b_c in c1, c2; t2 = t1 + 0.8 b_c). Exact to rounding; tested against finite
/// differences. Defined only for a scene with a covering (b_c > 0): b_c → 0⁺ is a
/// discontinuity of the model (docs/model.md §5).

#include "covopt/core/impact_model.hpp"
#include "covopt/core/impact_result.hpp"

namespace covopt {

/// Derivatives of the peak quantities with respect to one design parameter.
struct PeakDerivatives {
  double max_penetration = 0.0;         ///< dδ_max/dθ
  double peak_force = 0.0;              ///< dF_max/dθ
  double max_compressive_stress = 0.0;  ///< dσ_c,max/dθ
  double max_tensile_stress = 0.0;      ///< dσ_t,max/dθ
  double max_energy_density = 0.0;      ///< de_A,max/dθ
};

/// Derivatives with respect to the covering's modulus [per Pa] and thickness [per m].
struct PeakSensitivities {
  PeakDerivatives per_covering_modulus;    ///< d/dE_c, units of the quantity per Pa
  PeakDerivatives per_covering_thickness;  ///< d/db_c, units of the quantity per m
};

/// Analytic derivatives of ExactPeaks(model), for the conservative two-mass impact.
/// @throws std::invalid_argument if the model has no covering, or has contact damping (the
///         damped peaks are a maximisation and a quadrature, docs/model.md §10.1: use a finite
///         difference or TimePathPeakSensitivities), braking or a neck.
PeakSensitivities ExactPeakSensitivities(const ImpactModel& model, const ImpactPeaks& peaks);

}  // namespace covopt
