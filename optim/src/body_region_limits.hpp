#pragma once
// Private: the closed-form speed limit of a body-region contact, per limit (docs/model.md §13.5,
// §15.6): the largest energy the springs may hold with each counted criterion met, and which
// binds; and the speed at which the covering is used up.
#include <optional>

#include <covopt/core/body_contact.hpp>
#include <covopt/materials/body_regions.hpp>

#include "covopt/optim/body_region_check.hpp"

namespace covopt::optim::internal {

/// The binding limit of a closed-form speed limit: the largest energy [J] at which every counted
/// criterion holds (each grows with the energy), and which criterion binds there.
struct LimitEnergy {
  double energy_J = 0.0;
  BodyLimitKind by = BodyLimitKind::kForce;
};

/// A foam covering's limits (model.foam()), each an energy on the balance U_c(d) + F(d)²/(2 k_H):
/// the force F_lim/SF (the last compression with that force, past the stop the body spring's
/// share); the pressure p_lim/SF (the last compression whose σ(d/h) is within it; past the stop
/// on a curved face σ_end + (F - F(d_end))/A, never binding there without an area); the crush
/// strength/SF as the pressure; the travel d_end/SF when options.keep_travel.
LimitEnergy FoamLimitEnergy(const BodyContactModel& model, const materials::BodyLimits& limits,
                            const BodyRegionOptions& options);

/// The speed [m/s] at which `model`'s covering is used up, sqrt(2 U_b / mu) with U_b its
/// bottom_out_energy_J(); empty bare or above `max_speed_m_per_s`.
std::optional<double> UsedUpSpeed(const BodyContactModel& model, double max_speed_m_per_s);

/// The largest speed up to `speed` [m/s] at which `region_scene`'s covering stays within its
/// law's validity (BodyContactResult::validity, lost once as the compression grows): `speed`
/// itself when within there, else by bisection from `lowest_m_per_s` (0 when not even there).
double WithinLawSpeed(const BodyContactScene& region_scene, double speed, double lowest_m_per_s);

}  // namespace covopt::optim::internal
