// The closed-form limits of a foam covering on a body region (body_region_limits.hpp).
#include "body_region_limits.hpp"

#include <cmath>
#include <limits>

namespace covopt::optim::internal {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The largest energy [J] at which a foam covering's peak pressure is within `pressure_Pa`
/// (BodyContactModel::PressureAtForce's rule); +inf where it never exceeds it.
double FoamEnergyAtPressure(const BodyContactModel& model, double pressure_Pa) {
  const BodyContactScene& scene = model.scene();
  if (model.foam_flat_face()) return model.EnergyAtForce(pressure_Pa * scene.contact_area_m2);  // p = F/A
  const double end_stress = scene.covering.compressive_curve->last_stress_Pa();
  if (pressure_Pa < end_stress) return model.EnergyAtDeflection(model.FoamDeflectionAtStress(pressure_Pa));
  // Past the stop: σ_end + (F - F(d_end))/A, not evaluated without an area.
  if (!(scene.contact_area_m2 > 0.0)) return kInfinity;
  return model.EnergyAtForce(model.bottom_out_force_N() + (pressure_Pa - end_stress) * scene.contact_area_m2);
}

}  // namespace

LimitEnergy FoamLimitEnergy(const BodyContactModel& model, const materials::BodyLimits& limits,
                            const BodyRegionOptions& options) {
  const double sf = options.rule.safety_factor;
  LimitEnergy out{model.EnergyAtForce(limits.force_N / sf), BodyLimitKind::kForce};
  auto consider = [&out](double energy_J, BodyLimitKind kind) {
    if (energy_J < out.energy_J) out = {energy_J, kind};
  };
  consider(FoamEnergyAtPressure(model, limits.pressure_Pa / sf), BodyLimitKind::kPressure);
  if (options.keep_travel) {
    consider(model.EnergyAtDeflection(model.covering_travel_m() / sf), BodyLimitKind::kFullCompression);
  }
  if (options.material && options.material->crush_behaviour == materials::CrushBehaviour::kCrushes &&
      !options.rule.crushing_allowed) {
    consider(FoamEnergyAtPressure(model, options.material->compressive_strength_Pa / sf), BodyLimitKind::kCrush);
  }
  return out;
}

std::optional<double> UsedUpSpeed(const BodyContactModel& model, double max_speed_m_per_s) {
  if (!model.has_covering()) return std::nullopt;
  const double speed = std::sqrt(2.0 * model.bottom_out_energy_J() / model.reduced_mass_kg());
  if (!(speed <= max_speed_m_per_s)) return std::nullopt;
  return speed;
}

double WithinLawSpeed(const BodyContactScene& region_scene, double speed, double lowest_m_per_s) {
  const auto within = [&](double v) {
    BodyContactScene at = region_scene;
    at.speed_m_per_s = v;
    return Solve(BodyContactModel::FromScene(at)).validity.within;
  };
  if (!(speed >= lowest_m_per_s) || within(speed)) return speed;
  double lo = lowest_m_per_s, hi = speed;
  if (!within(lo)) return 0.0;
  for (int iteration = 0; iteration < 200 && hi - lo > 1e-14 * hi; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    (within(mid) ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace covopt::optim::internal

namespace covopt::optim {

DesignRule JudgedRule(const BodyRegionOptions& options) noexcept {
  DesignRule rule = options.rule;
  rule.criterion = options.keep_travel ? DesignCriterion::kNoFullCompression : DesignCriterion::kPaper;
  return rule;
}

}  // namespace covopt::optim
