// Elasticities of the injury and compression ratios to every scene input at one design
// (optim/robust_design.hpp, ComputeElasticities): analytic for the covering's modulus and
// thickness, central differences in ln x at two steps otherwise, checked against each other.
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/core/sensitivity.hpp>
#include <covopt/core/time_integration.hpp>

#include "covopt/optim/robust_sensitivity.hpp"
#include "robust_internal.hpp"

namespace covopt::optim {
namespace {

using internal::Require;

/// ln r_L, ln r_C, ln r_δ of one scene; empty when the scene is not valid.
struct LogRatios {
  double laceration = 0.0, contusion = 0.0, compression = 0.0;
};

/// The peaks of a valid scene: the exact path, or the time path for a braking robot (empty
/// when it fails; `failure` gets the first message).
std::optional<ImpactPeaks> PeaksOf(const ImpactModel& model, const TimeIntegrationOptions& time_path,
                                   std::string* failure) {
  if (!model.scene().robot_brakes()) return ExactPeaks(model);
  TimeIntegrationOptions options = time_path;
  options.record_history = false;
  const ImpactResult result = SimulateImpact(model, options);
  if (!result.ok()) {
    if (failure && failure->empty()) {
      *failure = "time path: " + std::string(covopt::ToString(result.status)) + ": " + result.message;
    }
    return std::nullopt;
  }
  return result.peaks;
}

std::optional<LogRatios> LogRatiosAt(const Scene& scene, const InjuryLimits& limits, const TimeIntegrationOptions& time_path,
                                     long& evaluations) {
  ++evaluations;
  std::optional<ImpactModel> model;
  try {
    model.emplace(ImpactModel::FromScene(scene));
  } catch (const std::invalid_argument&) {
    return std::nullopt;
  }
  const std::optional<ImpactPeaks> found = PeaksOf(*model, time_path, nullptr);
  if (!found) return std::nullopt;  // a failed neighbour: treated as outside the range
  const ImpactPeaks& peaks = *found;
  LogRatios r;
  r.laceration = std::log(peaks.max_tensile_stress_Pa / limits.laceration_tensile_stress_Pa);
  r.contusion = std::log(peaks.max_energy_density_J_per_m2 / limits.contusion_energy_density_J_per_m2);
  // ln of the covering's travel ratio; -inf while δ_max stays within the scalp's travel, which
  // the caller treats as no compression elasticity.
  if (model->has_covering()) r.compression = std::log(peaks.covering_compression_ratio());
  return r;
}

/// d ln r / d ln x by finite differences with step h in ln x: central when both sides are valid
/// scenes, else second-order one-sided on the valid side.
struct Difference {
  bool ok = false;
  bool one_sided = false;
  LogRatios elasticity;
};

Difference Differentiate(const Scene& scene, const SceneField& field, const LogRatios& at_x, double h,
                         const InjuryLimits& limits, const TimeIntegrationOptions& time_path, long& evaluations) {
  const double x = field.value(scene);
  auto at = [&](double s) {
    Scene shifted = scene;
    field.field(shifted) = x * std::exp(s);
    return LogRatiosAt(shifted, limits, time_path, evaluations);
  };
  Difference d;
  const std::optional<LogRatios> plus = at(h), minus = at(-h);
  if (plus && minus) {
    d.ok = true;
    d.elasticity = {(plus->laceration - minus->laceration) / (2 * h), (plus->contusion - minus->contusion) / (2 * h),
                    (plus->compression - minus->compression) / (2 * h)};
    return d;
  }
  const double side = plus ? 1.0 : -1.0;
  const std::optional<LogRatios>& near = plus ? plus : minus;
  if (!near) return d;
  const std::optional<LogRatios> far = at(2 * side * h);
  if (!far) return d;
  auto one_sided = [&](double f0, double f1, double f2) { return (-3 * f0 + 4 * f1 - f2) / (2 * side * h); };
  d.ok = true;
  d.one_sided = true;
  d.elasticity = {one_sided(at_x.laceration, near->laceration, far->laceration),
                  one_sided(at_x.contusion, near->contusion, far->contusion),
                  one_sided(at_x.compression, near->compression, far->compression)};
  return d;
}

double Disagreement(double a, double b) { return std::abs(a - b) / std::max({std::abs(a), std::abs(b), 1e-6}); }

}  // namespace

std::string_view ToString(DerivativeMethod method) noexcept {
  switch (method) {
    case DerivativeMethod::kAnalytic: return "analytic";
    case DerivativeMethod::kCentralDifference: return "central-difference";
    case DerivativeMethod::kOneSidedDifference: return "one-sided-difference";
  }
  return "unknown";
}

namespace {

/// The options' and the scene's checks of ComputeElasticities.
/// @throws std::invalid_argument naming the field.
void RequireElasticityInputs(const Scene& scene, const ElasticityOptions& options) {
  Require(std::isfinite(options.log_step) && options.log_step >= 1e-6 && options.log_step <= 0.1,
          "log step must be in [1e-6, 0.1] (got " + internal::Number(options.log_step) + ")");
  Require(options.tolerance > 0.0 && options.tolerance < 1.0,
          "tolerance must be in (0, 1) (got " + internal::Number(options.tolerance) + ")");
  internal::ValidateCriterion({DesignCriterion::kNoFullCompression, 1.0, options.limits});
  if (scene.is_damped() || scene.head.has_neck()) {
    throw std::invalid_argument(
        "elasticities cover the two-mass impact, conservative (the exact path) or with a braking robot (the time "
        "path): the scene has contact damping or a neck (docs/model.md §10)");
  }
  if (scene.robot_brakes()) ValidateTimeIntegrationOptions(options.time_path, "time_path.");
}

}  // namespace

ElasticityTable ComputeElasticities(const Scene& scene, const ElasticityOptions& options) {
  RequireElasticityInputs(scene, options);
  const ImpactModel model = ImpactModel::FromScene(scene);
  const bool brakes = scene.robot_brakes();
  std::string failure;
  const std::optional<ImpactPeaks> found = PeaksOf(model, options.time_path, &failure);
  if (!found) throw std::runtime_error("elasticities at the scene: " + failure);
  const ImpactPeaks peaks = *found;
  // The steps in ln x: h and h/10 on the exact path; on the time path (a braking robot) 2h and
  // h with h = max(log_step, cbrt(10 rtol)), which balances the truncation error (h²) against
  // the values' own error (10 rtol / h), as the time-path oracle's differences do.
  const double time_step = std::max(options.log_step, std::cbrt(10.0 * options.time_path.relative_tolerance));
  const double coarse_step = brakes ? 2.0 * time_step : options.log_step;
  const double fine_step = brakes ? time_step : options.log_step / 10;
  const bool covered = model.has_covering();
  ElasticityTable table;
  long evaluations = 1;
  table.laceration_ratio = peaks.max_tensile_stress_Pa / options.limits.laceration_tensile_stress_Pa;
  table.contusion_ratio = peaks.max_energy_density_J_per_m2 / options.limits.contusion_energy_density_J_per_m2;
  // The covering's travel ratio is 0 while δ_max stays within the scalp's travel: no elasticity then.
  const bool compressed = covered && peaks.covering_compression_ratio() > 0.0;
  if (compressed) table.compression_ratio = peaks.covering_compression_ratio();
  const LogRatios at_x{std::log(table.laceration_ratio), std::log(table.contusion_ratio),
                       compressed ? std::log(*table.compression_ratio) : 0.0};

  std::optional<PeakSensitivities> analytic;
  if (covered && !brakes && !model.is_foam()) analytic = ExactPeakSensitivities(model, peaks);  // Hertz only

  for (const SceneField& field : SceneFields()) {
    const double x = field.value(scene);
    if (!std::isfinite(x) || x == 0.0) continue;
    const bool covering_field = field.table == "covering";
    if (covering_field && !covered) continue;
    InputElasticity row;
    row.field = std::string(field.name);
    row.value = x;
    if (analytic && (field.name == "covering-modulus" || field.name == "covering-thickness")) {
      const bool modulus = field.name == "covering-modulus";
      const PeakDerivatives& d = modulus ? analytic->per_covering_modulus : analytic->per_covering_thickness;
      row.method = DerivativeMethod::kAnalytic;
      row.laceration = x * d.max_tensile_stress / peaks.max_tensile_stress_Pa;
      row.contusion = x * d.max_energy_density / peaks.max_energy_density_J_per_m2;
      // r_δ = (δ_max − s) / (t2 − s), s = covering_travel_start_m: t2 moves with b_c by the
      // full-compression fraction f (cumulative; literal only once f b_c > t1), s and E_c do not.
      double dt2 = 0.0;
      if (!modulus) {
        const ModelConstants& c = scene.model;
        const double t1 = c.full_compression_fraction * scene.scalp.thickness_m;
        const bool moves = c.thresholds == ThresholdReading::kCumulative || c.full_compression_fraction * x > t1;
        dt2 = moves ? c.full_compression_fraction : 0.0;
      }
      const double used = peaks.max_penetration_m - peaks.covering_travel_start_m;
      const double travel = peaks.full_compression_penetration_m - peaks.covering_travel_start_m;
      row.compression = x * (d.max_penetration / used - dt2 / travel);
    } else {
      const Difference coarse =
          Differentiate(scene, field, at_x, coarse_step, options.limits, options.time_path, evaluations);
      const Difference fine = Differentiate(scene, field, at_x, fine_step, options.limits, options.time_path, evaluations);
      if (!coarse.ok || !fine.ok) {
        row.reliable = false;  // both sides leave the field's range: nothing to difference
        row.discrepancy = 1.0;
      } else {
        row.method = fine.one_sided ? DerivativeMethod::kOneSidedDifference : DerivativeMethod::kCentralDifference;
        row.laceration = fine.elasticity.laceration;
        row.contusion = fine.elasticity.contusion;
        // A neighbour whose δ_max stays within the scalp's travel has no finite ln r_δ.
        const bool compression_differs = compressed && std::isfinite(fine.elasticity.compression) &&
                                         std::isfinite(coarse.elasticity.compression);
        if (compression_differs) row.compression = fine.elasticity.compression;
        row.discrepancy = std::max(Disagreement(coarse.elasticity.laceration, fine.elasticity.laceration),
                                   Disagreement(coarse.elasticity.contusion, fine.elasticity.contusion));
        if (compression_differs) {
          row.discrepancy =
              std::max(row.discrepancy, Disagreement(coarse.elasticity.compression, fine.elasticity.compression));
        }
        row.reliable = row.discrepancy <= options.tolerance;
      }
    }
    if (!compressed || (row.compression && !std::isfinite(*row.compression))) row.compression.reset();
    table.rows.push_back(row);
  }
  const bool laceration_worse = table.laceration_ratio >= table.contusion_ratio;
  std::stable_sort(table.rows.begin(), table.rows.end(), [&](const InputElasticity& a, const InputElasticity& b) {
    const double ka = std::abs(laceration_worse ? a.laceration : a.contusion);
    const double kb = std::abs(laceration_worse ? b.laceration : b.contusion);
    return ka > kb;
  });
  table.evaluations = evaluations;
  return table;
}

}  // namespace covopt::optim
