#pragma once
/// @file robust_sensitivity.hpp
/// Sensitivities of the injury ratios to every scene input at one scene (robust_design.hpp):
/// elasticities (x / r) dr/dx, analytic for the covering's modulus and thickness, checked
/// finite differences otherwise (ComputeElasticities).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <covopt/core/scene.hpp>
#include <covopt/core/time_integration.hpp>

namespace covopt::optim {


/// How a derivative was obtained.
enum class DerivativeMethod {
  kAnalytic,            ///< ExactPeakSensitivities (covering modulus and thickness)
  kCentralDifference,   ///< central differences in ln x at two steps
  kOneSidedDifference,  ///< second-order one-sided differences (at the edge of a field's range)
};
/// "analytic", "central-difference", "one-sided-difference".
std::string_view ToString(DerivativeMethod method) noexcept;

/// The elasticities d ln r / d ln x = (x / r) dr/dx of the ratios to one scene input.
struct InputElasticity {
  std::string field;  ///< the field's name ("head-mass")
  double value = 0.0; ///< x [SI]
  double laceration = 0.0;  ///< of r_L [-]
  double contusion = 0.0;   ///< of r_C [-]
  /// of r_δ = δ_max / t2 [-]; empty without a covering.
  std::optional<double> compression;
  DerivativeMethod method = DerivativeMethod::kCentralDifference;
  /// The two step sizes agreed to ElasticityOptions::tolerance (always true for kAnalytic).
  /// False near a phase switch (a kink of the law) or where a step leaves the field's range
  /// on both sides; the numbers are then the smaller step's.
  bool reliable = true;
  /// The largest disagreement of the two steps, |e1 − e2| / max(|e1|, |e2|, 1e-6) [-].
  double discrepancy = 0.0;
};

/// Options of ComputeElasticities.
struct ElasticityOptions {
  /// The laceration [Pa] and contusion [J/m²] limits (they scale the ratios only).
  InjuryLimits limits;
  /// The two steps in ln x: h and h/10, in [1e-6, 0.1]. Default: 1e-3.
  double log_step = 1e-3;
  /// Agreement required of the two steps, in (0, 1). Default: 1e-4.
  double tolerance = 1e-4;
  /// A braking robot's scene runs on the time path with these settings (checked then only):
  /// every elasticity, the covering's included, is then a difference at the steps 2h and h,
  /// h = max(log_step, cbrt(10 rtol)), and a failed neighbour counts as outside the range.
  /// Default: ARKODE ERK 5(4), rtol 1e-8.
  TimeIntegrationOptions time_path;
};

/// The elasticities at one scene (its covering is the design).
struct ElasticityTable {
  double laceration_ratio = 0.0;
  double contusion_ratio = 0.0;
  std::optional<double> compression_ratio;  ///< δ_max / t2; empty without a covering
  /// One row per scene field that is finite and non-zero in the scene (without a covering,
  /// the covering's fields are left out), sorted by the magnitude of the elasticity of the
  /// larger injury ratio at the scene (r_L or r_C), largest first, ties in SceneFields()
  /// order: a tornado chart's order.
  std::vector<InputElasticity> rows;
  long evaluations = 0;  ///< impacts computed (exact path; time path for a braking robot)
};

/// Elasticities of r_L, r_C and r_δ to every scene input at `scene`: the exact path, or the
/// time path for a braking robot (ElasticityOptions::time_path).
/// @throws std::invalid_argument for an invalid scene, a scene with contact damping or a neck,
///   or bad options; std::runtime_error when the time path fails at the scene itself.
ElasticityTable ComputeElasticities(const Scene& scene, const ElasticityOptions& options = {});

}  // namespace covopt::optim
