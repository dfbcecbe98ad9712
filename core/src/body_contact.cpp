// The body-region contact of ISO/TS 15066 Annex A with the covering in series
// (docs/model.md §13): validation, the force law's closed forms, and the exact path.
#include "covopt/core/body_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "body_contact_time_path.hpp"
#include "covopt/core/physical_floors.hpp"
#include "numeric_format.hpp"
#include "range_check.hpp"
#include "robot_reaction.hpp"

namespace covopt {

namespace {

using internal::FormatNumber;

constexpr double kMinSpeed_m_per_s = 1e-6;
constexpr double kMaxSpeed_m_per_s = 100.0;
constexpr double kMaxMass_kg = 1e6;
constexpr double kMaxRadius_m = 100.0;
constexpr double kMaxStiffness_N_per_m = 1e9;
constexpr double kMaxModulus_Pa = 1e13;
constexpr double kMaxThickness_m = 1.0;
constexpr double kMaxContactArea_m2 = 1.0;
constexpr double kHertzPressureFactor = 3.0 / (2.0 * std::numbers::pi);  // p0 = 3F/(2πa²)

using internal::CheckInRange;
using internal::CheckPositive;
using internal::CheckZeroOrInRange;

[[noreturn]] void Reject(const std::string& field, const std::string& requirement, double value) {
  internal::RejectValue(field, requirement, value);
}

void CheckScene(const BodyContactScene& s) {
  CheckInRange("robot.mass", s.robot_mass_kg, kMinMass_kg, kMaxMass_kg, "kg", "fixed (infinite)");
  if (!(s.speed_m_per_s >= kMinSpeed_m_per_s && s.speed_m_per_s <= kMaxSpeed_m_per_s)) {
    Reject("robot.speed",
           "in [" + FormatNumber(kMinSpeed_m_per_s) + ", " + FormatNumber(kMaxSpeed_m_per_s) +
               "] m/s",
           s.speed_m_per_s);
  }
  CheckInRange("robot.radius", s.robot_radius_m, kMinRadius_m, kMaxRadius_m, "m", "flat (infinite)");
  const double b_c = s.covering.thickness_m;
  CheckZeroOrInRange("covering.thickness", b_c, kMinLayerThickness_m, kMaxThickness_m, "m", "no covering");
  const bool foam = b_c > 0.0 && internal::ResolveCoveringLaw(s.covering) == CoveringLaw::kFoam;
  if (foam && std::isinf(s.robot_radius_m) && !(s.contact_area_m2 > 0.0)) {
    throw std::invalid_argument(
        "contact_area: a foam covering on a flat robot face needs the face's contact area, in [1e-06, 1] m2 (got "
        "not given; or give the radius of a curved face)");
  }
  if (b_c > 0.0 && !foam) {
    CheckInRange("covering.modulus", s.covering.youngs_modulus_Pa, kMinModulus_Pa, kMaxModulus_Pa, "Pa");
    if (!(s.covering.poisson_ratio > -1.0 && s.covering.poisson_ratio <= 0.5)) {
      Reject("covering.poisson", "in (-1, 0.5]", s.covering.poisson_ratio);
    }
    if (std::isinf(s.robot_radius_m)) {
      throw std::invalid_argument(
          "robot.radius: a covering needs the radius of the robot surface under it (its Hertz "
          "contact is a sphere on a flat), in [0.0001, 100] m (got a flat robot)");
    }
  }
  CheckPositive("body.stiffness", s.body_stiffness_N_per_m, kMaxStiffness_N_per_m, "N/m");
  if (s.contact == ContactType::kTransient) {
    if (std::isinf(s.body_mass_kg) && s.body_mass_kg > 0.0) {
      throw std::invalid_argument(
          "body.mass: a transient contact needs a body region that moves, in [0.001, 1e+06] kg (got "
          "fixed; a region held against a fixed object is contact clamped)");
    }
    CheckInRange("body.mass", s.body_mass_kg, kMinMass_kg, kMaxMass_kg, "kg");
  } else if (std::isinf(s.robot_mass_kg)) {
    throw std::invalid_argument(
        "robot.mass: a clamped contact needs a robot that moves, in [0.001, 1e+06] kg (got fixed: the "
        "robot and the clamped body region would both be immovable)");
  }
  CheckZeroOrInRange("contact_area", s.contact_area_m2, kMinContactArea_m2, kMaxContactArea_m2, "m2", "not given");
  if (!(s.full_compression_fraction > 0.0 && s.full_compression_fraction <= 1.0)) {
    Reject("full_compression_fraction", "in (0, 1]", s.full_compression_fraction);
  }
  // The head scene's ranges and words (a fixed robot cannot brake).
  internal::CheckRobotReaction(s.reaction_delay_s, s.braking_m_per_s2, s.robot_mass_kg);
}

}  // namespace

std::string_view ToString(ContactType type) noexcept {
  switch (type) {
    case ContactType::kTransient: return "transient";
    case ContactType::kClamped: return "clamped";
  }
  return "?";
}

std::optional<ContactType> ParseContactType(std::string_view text) noexcept {
  if (text == "transient") return ContactType::kTransient;
  if (text == "clamped" || text == "quasi-static") return ContactType::kClamped;
  return std::nullopt;
}

BodyContactModel BodyContactModel::FromScene(const BodyContactScene& scene) {
  CheckScene(scene);
  BodyContactModel m;
  m.scene_ = scene;
  const double inverse_robot = std::isinf(scene.robot_mass_kg) ? 0.0 : 1.0 / scene.robot_mass_kg;
  const double inverse_body =
      scene.contact == ContactType::kClamped ? 0.0 : 1.0 / scene.body_mass_kg;
  m.reduced_mass_kg_ = 1.0 / (inverse_robot + inverse_body);
  m.impact_energy_J_ = 0.5 * m.reduced_mass_kg_ * scene.speed_m_per_s * scene.speed_m_per_s;
  if (scene.has_covering() && internal::ResolveCoveringLaw(scene.covering) == CoveringLaw::kFoam) {
    m.SetUpFoam();
  } else if (scene.has_covering()) {
    const CoveringSpec& c = scene.covering;
    m.outer_radius_m_ = scene.robot_radius_m + c.thickness_m;
    m.covering_stiffness_ = 4.0 / 3.0 * c.youngs_modulus_Pa / (1.0 - c.poisson_ratio * c.poisson_ratio) *
                            std::sqrt(m.outer_radius_m_);
    m.travel_m_ = scene.full_compression_fraction * c.thickness_m;
    m.bottom_out_force_N_ = m.covering_stiffness_ * m.travel_m_ * std::sqrt(m.travel_m_);
    const double stiffness_root = std::cbrt(m.covering_stiffness_);  // one cube root for both
    m.compliance_factor_ = 1.0 / (stiffness_root * stiffness_root);
    m.bottom_out_root_ = stiffness_root * std::sqrt(m.travel_m_);
    m.bottom_out_energy_J_ = m.EnergyAtForce(m.bottom_out_force_N_);
  } else {
    m.bottom_out_force_N_ = std::numeric_limits<double>::infinity();
    m.bottom_out_energy_J_ = std::numeric_limits<double>::infinity();
  }
  return m;
}

double BodyContactModel::EnergyAtForce(double force_N) const noexcept {
  const double spring = force_N * force_N / (2.0 * scene_.body_stiffness_N_per_m);
  if (!has_covering()) return spring;
  // A foam: U_c at the last compression with this force (d_end past the stop).
  if (foam()) return spring + FoamEnergyAtDeflection(FoamDeflectionAtForce(force_N));
  // W_c(F) = 2/5 K_c^(-2/3) F^(5/3) = 2/5 F δ_c(F); past F_b it stays 2/5 F_b (0.8 b_c).
  const double f = force_N < bottom_out_force_N_ ? force_N : bottom_out_force_N_;
  return spring + 0.4 * f * CoveringDeflectionAtForce(f);
}

double BodyContactModel::CoveringDeflectionAtForce(double force_N) const noexcept {
  if (!has_covering()) return 0.0;
  if (foam()) return FoamDeflectionAtForce(force_N);
  if (force_N >= bottom_out_force_N_) return travel_m_;
  const double s = std::cbrt(force_N);
  return s * s * compliance_factor_;
}

double BodyContactModel::ApproachAtForce(double force_N) const noexcept {
  return force_N / scene_.body_stiffness_N_per_m + CoveringDeflectionAtForce(force_N);
}

std::optional<double> BodyContactModel::PressureAtForce(double force_N) const noexcept {
  if (!has_covering()) {
    if (scene_.contact_area_m2 > 0.0) return force_N / scene_.contact_area_m2;
    return std::nullopt;
  }
  if (foam()) return FoamPressureAtForce(force_N);
  // a² = R_c δ_c(min(F, F_b)). At F = 0 the Hertz pressure is 0 (p ∝ F^(1/3)).
  const double contact_radius_sq = outer_radius_m_ * CoveringDeflectionAtForce(force_N);
  if (!(contact_radius_sq > 0.0)) return 0.0;
  return kHertzPressureFactor * force_N / contact_radius_sq;
}

double BodyContactModel::SpeedAtPeakForce(double force_N) const noexcept {
  return std::sqrt(2.0 * EnergyAtForce(force_N) / reduced_mass_kg_);
}

double BodyContactModel::ForceAtEnergy(double energy_J) const noexcept {
  const double k = scene_.body_stiffness_N_per_m;
  if (!(energy_J > 0.0)) return 0.0;
  if (!has_covering()) return std::sqrt(2.0 * k * energy_J);
  if (foam()) {
    if (energy_J >= bottom_out_energy_J_) {
      return std::sqrt(2.0 * k * (energy_J - bottom_out_energy_J_) + bottom_out_force_N_ * bottom_out_force_N_);
    }
    return FoamStateAtEnergy(energy_J).force_N;
  }
  // Past the bottoming out the covering stores W_b = 2/5 F_b (0.8 b_c) and the spring the rest.
  const double covering_bottom_energy = 0.4 * bottom_out_force_N_ * travel_m_;
  const double bottom_energy = bottom_out_force_N_ * bottom_out_force_N_ / (2.0 * k) + covering_bottom_energy;
  if (energy_J >= bottom_energy) return std::sqrt(2.0 * k * (energy_J - covering_bottom_energy));
  // Below it, in s = F^(1/3): g(s) = s⁶/(2k) + c s⁵ − E with c = 2/5 K_c^(-2/3), increasing and
  // convex on s > 0, so Newton from any point right of the root descends monotonically onto it.
  // Each of the three starting values bounds the root from above.
  const double c = 0.4 * compliance_factor_;
  double s = std::cbrt(std::sqrt(2.0 * k * energy_J));    // the spring alone
  const double s5 = s * s * s * s * s;
  if (c * s5 > energy_J) s = std::pow(energy_J / c, 0.2);  // the covering alone: the tighter bound
  s = std::min(s, bottom_out_root_);                      // the bottoming out
  const double inverse_2k = 0.5 / k;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double s2 = s * s;
    const double s4 = s2 * s2;
    const double g = s4 * s2 * inverse_2k + c * s4 * s - energy_J;
    if (!(g > 0.0)) break;
    const double slope = 6.0 * s4 * s * inverse_2k + 5.0 * c * s4;
    const double step = g / slope;
    s -= step;
    if (step <= 1e-16 * s) break;
  }
  return s * s * s;
}

namespace internal {

BodyContactResult PeaksAtForce(const BodyContactModel& model, double force_N) {
  BodyContactResult r;
  const BodyContactScene& scene = model.scene();
  r.reduced_mass_kg = model.reduced_mass_kg();
  r.energy_transferred_J = model.impact_energy_J();
  r.peak_force_N = force_N;
  r.body_deflection_m = force_N / scene.body_stiffness_N_per_m;
  r.body_energy_J = 0.5 * force_N * r.body_deflection_m;
  if (model.has_covering()) {
    // One deflection for every covering quantity (the accessors would each take a cube root).
    const double deflection = model.CoveringDeflectionAtForce(force_N);
    const double contact_radius_sq = model.covering_outer_radius_m() * deflection;
    r.covering_deflection_m = deflection;
    r.contact_radius_m = std::sqrt(contact_radius_sq);
    r.peak_pressure_Pa = contact_radius_sq > 0.0 ? kHertzPressureFactor * force_N / contact_radius_sq : 0.0;
    r.covering_energy_J = 0.4 * std::min(force_N, model.bottom_out_force_N()) * deflection;
    r.compression_ratio = deflection / model.covering_travel_m();
    r.fully_compressed = force_N > model.bottom_out_force_N();
  } else {
    r.peak_pressure_Pa = model.PressureAtForce(force_N);
  }
  r.max_approach_m = r.covering_deflection_m + r.body_deflection_m;
  FinishCoveringFields(model, r);
  return r;
}

void FinishCoveringFields(const BodyContactModel& model, BodyContactResult& r) noexcept {
  if (!model.has_covering()) return;
  r.covering_law = model.covering_law();
  r.covering_stress_Pa = r.peak_pressure_Pa.value_or(
      r.pressure_past_stop ? model.scene().covering.compressive_curve->last_stress_Pa() : 0.0);
  r.peak_strain = r.covering_deflection_m / model.scene().covering.thickness_m;
  if (r.fully_compressed) {
    r.energy_past_stop_J = std::max(r.body_energy_J + r.covering_energy_J - model.bottom_out_energy_J(), 0.0);
  }
  if (model.foam()) {
    r.validity = FoamValidity(model, r);
  } else {
    // Past its travel the layer is modelled as a rigid stop, but as for the head (Park's phase
    // 3) a fully compressed Hertz covering is beyond its law; a solid elastomer has its limits.
    r.validity.note = r.fully_compressed
                          ? "Hertz half-space law: fully compressed; past its travel the covering is a rigid stop"
                          : "Hertz half-space law (a small-strain solid thicker than its contact)";
    const CoveringSpec& covering = model.scene().covering;
    ApplyHertzCoveringLimits({.poisson_ratio = covering.poisson_ratio,
                                        .thickness_m = covering.thickness_m,
                                        .strain = r.peak_strain,
                                        .contact_radius_m = r.contact_radius_m,
                                        // past the travel: F_max/F_b > 1 (δ_c stays at the travel)
                                        .travel_ratio = r.fully_compressed ? r.peak_force_N / model.bottom_out_force_N()
                                                                           : r.compression_ratio,
                                        .fully_compressed = r.fully_compressed},
                                       r.validity);
  }
}

}  // namespace internal

namespace {

BodyContactResult SolveExactBodyContact(const BodyContactModel& model) {
  BodyContactResult r = model.foam() ? internal::FoamPeaksAtEnergy(model, model.impact_energy_J())
                                     : internal::PeaksAtForce(model, model.ForceAtEnergy(model.impact_energy_J()));
  r.method = "exact";  // short enough for the string's small buffer: no allocation
  r.rebound_speed_m_per_s = model.scene().speed_m_per_s;  // conservative: no energy is lost
  if (!model.has_covering()) {
    // The linear spring's half period.
    r.contact_duration_s =
        std::numbers::pi * std::sqrt(model.reduced_mass_kg() / model.scene().body_stiffness_N_per_m);
  }
  return r;
}

}  // namespace

BodyContactResult Solve(const BodyContactModel& model, const SolveOptions& options) {
  // A braking robot has no energy integral (as the head's, Scene::has_energy_integral).
  const bool brakes = model.scene().robot_brakes();
  const bool time_path = options.path == PathChoice::kTimePath || options.record_history || brakes;
  if (options.path == PathChoice::kExact && options.record_history) {
    throw std::invalid_argument(
        "path exact: a history needs the time path (give path time-path or auto, or no history)");
  }
  if (options.path == PathChoice::kExact && brakes) {
    throw std::invalid_argument(
        "path exact: the exact path needs the energy integral of a two-body contact, and robot.braking (" +
        FormatNumber(model.scene().braking_m_per_s2) +
        " m/s2) takes energy out over time: a braking robot has only the time path (give path time-path or auto)");
  }
  if (!time_path) return SolveExactBodyContact(model);
  ValidateTimeIntegrationOptions(options.time_path, "time_path.");
  if (!(options.history_samples_per_contact >= 0.0 &&
        std::isfinite(options.history_samples_per_contact))) {
    Reject("history_samples_per_contact", "finite and >= 0", options.history_samples_per_contact);
  }
  return internal::SolveBodyContactTimePath(model, options);
}

BodyContactResult Solve(const BodyContactScene& scene, const SolveOptions& options) {
  return Solve(BodyContactModel::FromScene(scene), options);
}

BodyContactResult SolveBodyContactPeaks(const BodyContactModel& model, const TimeIntegrationOptions& options) {
  ValidateTimeIntegrationOptions(options, "time_path.");
  SolveOptions solve;
  solve.time_path = options;
  return internal::SolveBodyContactTimePath(model, solve, /*to_peak=*/true);
}

}  // namespace covopt
