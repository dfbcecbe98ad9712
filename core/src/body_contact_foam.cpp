// The body-region contact with a foam covering (docs/model.md §15): the elastic-foundation law
// of a foam layer with its measured compressive curve, in series with the body spring, on a
// curved or a flat robot face, and the rigid stop past the curve's last point.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "body_contact_time_path.hpp"
#include "covopt/core/body_contact.hpp"

namespace covopt {

namespace internal {

CoveringLaw ResolveCoveringLaw(const CoveringSpec& covering) {
  switch (covering.law) {
    case CoveringLaw::kAuto: return covering.compressive_curve ? CoveringLaw::kFoam : CoveringLaw::kHertz;
    case CoveringLaw::kHertz: return CoveringLaw::kHertz;
    case CoveringLaw::kFoam:
      if (!covering.compressive_curve) {
        throw std::invalid_argument(
            "covering.law: foam needs the covering's measured compressive curve (covering.compressive_curve), got "
            "none; give a curve, or law auto or hertz");
      }
      return CoveringLaw::kFoam;
  }
  return CoveringLaw::kHertz;
}

}  // namespace internal

void BodyContactModel::SetUpFoam() {
  law_ = CoveringLaw::kFoam;
  curve_ = scene_.covering.compressive_curve.get();
  const double h = scene_.covering.thickness_m;
  foam_thickness_m_ = h;
  flat_foam_ = std::isinf(scene_.robot_radius_m);
  if (flat_foam_) {
    foam_force_factor_ = scene_.contact_area_m2;       // F = A σ
    foam_energy_factor_ = scene_.contact_area_m2 * h;  // U = A h W
  } else {
    outer_radius_m_ = scene_.robot_radius_m + h;
    foam_force_factor_ = 2.0 * std::numbers::pi * outer_radius_m_ * h;  // F = 2π R_c h W
    foam_energy_factor_ = foam_force_factor_ * h;                       // U = 2π R_c h² V
  }
  travel_m_ = curve_->last_strain() * h;
  bottom_out_force_N_ = FoamForceAtDeflection(travel_m_);
  bottom_out_energy_J_ = EnergyAtDeflection(travel_m_);
}

double BodyContactModel::FoamForceAtDeflection(double deflection_m) const noexcept {
  if (!foam()) return 0.0;
  const double strain = deflection_m / foam_thickness_m_;
  return foam_force_factor_ * (flat_foam_ ? curve_->StressAt(strain) : curve_->EnergyDensityAt(strain));
}

double BodyContactModel::FoamEnergyAtDeflection(double deflection_m) const noexcept {
  if (!foam()) return 0.0;
  const double strain = deflection_m / foam_thickness_m_;
  return foam_energy_factor_ * (flat_foam_ ? curve_->EnergyDensityAt(strain) : curve_->SecondIntegralAt(strain));
}

double BodyContactModel::EnergyAtDeflection(double deflection_m) const noexcept {
  const double force = FoamForceAtDeflection(deflection_m);
  return FoamEnergyAtDeflection(deflection_m) + force * force / (2.0 * scene_.body_stiffness_N_per_m);
}

double BodyContactModel::FoamStressAtDeflection(double deflection_m) const noexcept {
  return foam() ? curve_->StressAt(deflection_m / foam_thickness_m_) : 0.0;
}

double BodyContactModel::FoamDeflectionAtStress(double stress_Pa) const noexcept {
  if (!foam() || !(stress_Pa > 0.0)) return 0.0;
  if (stress_Pa >= curve_->last_stress_Pa()) return travel_m_;
  // The first point whose stress exceeds the given one ends the piece: σ_prev <= s < σ_k.
  const auto points = curve_->points();
  const auto it = std::upper_bound(points.begin(), points.end(), stress_Pa,
                                   [](double s, const StrainStressPoint& p) { return s < p.stress_Pa; });
  const auto k = static_cast<std::size_t>(it - points.begin());
  const double e0 = k == 0 ? 0.0 : points[k - 1].strain, s0 = k == 0 ? 0.0 : points[k - 1].stress_Pa;
  const double strain = e0 + (stress_Pa - s0) * (points[k].strain - e0) / (points[k].stress_Pa - s0);
  return std::clamp(strain, e0, points[k].strain) * foam_thickness_m_;
}

double BodyContactModel::FoamDeflectionAtForce(double force_N) const noexcept {
  if (!(force_N > 0.0)) return 0.0;
  if (force_N >= bottom_out_force_N_) return travel_m_;
  if (flat_foam_) return FoamDeflectionAtStress(force_N / foam_force_factor_);
  // Curved: W is strictly increasing (σ > 0 past the origin): one strain.
  return curve_->StrainAtEnergyDensity(force_N / foam_force_factor_).value_or(curve_->last_strain()) *
         foam_thickness_m_;
}

std::optional<double> BodyContactModel::FoamPressureAtForce(double force_N) const noexcept {
  if (flat_foam_) return force_N / foam_force_factor_;
  if (force_N <= bottom_out_force_N_) return curve_->StressAt(FoamDeflectionAtForce(force_N) / foam_thickness_m_);
  // Past the stop: σ_end for the foam's part, and the bare robot's rule for the rest.
  if (!(scene_.contact_area_m2 > 0.0)) return std::nullopt;
  return curve_->last_stress_Pa() + (force_N - bottom_out_force_N_) / scene_.contact_area_m2;
}

BodyContactModel::FoamState BodyContactModel::FoamStateAtEnergy(double energy_J) const noexcept {
  if (!foam() || !(energy_J > 0.0)) return {};
  const double h = foam_thickness_m_;
  const double ff = foam_force_factor_, fe = foam_energy_factor_;
  const double inverse_k = 1.0 / scene_.body_stiffness_N_per_m;
  if (energy_J >= bottom_out_energy_J_) {
    const double spring = 0.5 * bottom_out_force_N_ * bottom_out_force_N_ * inverse_k;
    return {travel_m_, bottom_out_force_N_, bottom_out_energy_J_ - spring, curve_->last_stress_Pa()};
  }
  const auto points = curve_->points();
  // The balance at point i's strain, from the curve's integrals there (no search).
  auto balance_at_point = [&](std::size_t i) {
    const double force = ff * (flat_foam_ ? points[i].stress_Pa : curve_->EnergyDensityAtPoint(i));
    const double energy = fe * (flat_foam_ ? curve_->EnergyDensityAtPoint(i) : curve_->SecondIntegralAtPoint(i));
    return energy + 0.5 * force * force * inverse_k;
  };
  // The piece: the first point whose balance reaches the target (the last one does).
  std::size_t lo = 0, hi = points.size() - 1;
  while (lo < hi) {
    const std::size_t mid = (lo + hi) / 2;
    if (balance_at_point(mid) >= energy_J) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  const double e0 = lo == 0 ? 0.0 : points[lo - 1].strain;
  const double s0 = lo == 0 ? 0.0 : points[lo - 1].stress_Pa;
  const double w0 = lo == 0 ? 0.0 : curve_->EnergyDensityAtPoint(lo - 1);
  const double v0 = lo == 0 ? 0.0 : curve_->SecondIntegralAtPoint(lo - 1);
  const double length = points[lo].strain - e0;
  const double slope = (points[lo].stress_Pa - s0) / length;
  // The state at x into the piece, from the piece's polynomials (W quadratic, V cubic).
  auto state_at = [&](double x) {
    const double sigma = s0 + slope * x;
    const double w = w0 + x * (s0 + 0.5 * slope * x);
    if (flat_foam_) return FoamState{(e0 + x) * h, ff * sigma, fe * w, sigma};
    return FoamState{(e0 + x) * h, ff * w, fe * (v0 + x * (w0 + x * (0.5 * s0 + slope * x / 6.0))), sigma};
  };
  // g(x) = U(e0 + x) + F(e0 + x)²/(2k) - E: a polynomial on the piece, increasing and convex, so
  // Newton from its right end (g >= 0 there) descends monotonically onto the root.
  double x = length;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const FoamState state = state_at(x);
    const double g = state.covering_energy_J + 0.5 * state.force_N * state.force_N * inverse_k - energy_J;
    // dg/dx = dU/dx + F F'/k: curved U' = fe W, F' = ff σ; flat U' = fe σ, F' = ff slope.
    const double derivative =
        flat_foam_ ? fe * state.stress_Pa + state.force_N * ff * slope * inverse_k
                   : state.force_N / ff * fe + state.force_N * ff * state.stress_Pa * inverse_k;
    if (!(g > 0.0) || !(derivative > 0.0)) break;
    const double step = std::min(g / derivative, x);
    x -= step;
    if (step <= 1e-16 * (e0 + x)) break;
  }
  return state_at(x);
}

namespace internal {

BodyContactResult FoamPeaksAt(const BodyContactModel& model, const BodyContactModel::FoamState& state, bool used_up) {
  BodyContactResult r;
  const BodyContactScene& scene = model.scene();
  const bool flat = model.foam_flat_face();
  const double d = state.deflection_m;
  const double force_N = state.force_N;
  r.reduced_mass_kg = model.reduced_mass_kg();
  r.energy_transferred_J = model.impact_energy_J();
  r.peak_force_N = force_N;
  r.body_deflection_m = force_N / scene.body_stiffness_N_per_m;
  r.body_energy_J = 0.5 * force_N * r.body_deflection_m;
  r.covering_deflection_m = d;
  r.covering_energy_J = state.covering_energy_J;
  r.contact_radius_m = flat ? std::sqrt(scene.contact_area_m2 / std::numbers::pi)
                            : std::sqrt(2.0 * model.covering_outer_radius_m() * d);
  if (used_up) {
    r.peak_pressure_Pa = model.PressureAtForce(force_N);
    r.pressure_past_stop = !flat;
  } else {
    r.peak_pressure_Pa = flat ? force_N / scene.contact_area_m2 : state.stress_Pa;
  }
  r.compression_ratio = used_up ? 1.0 : d / model.covering_travel_m();
  r.fully_compressed = used_up;
  r.max_approach_m = d + r.body_deflection_m;
  FinishCoveringFields(model, r);
  return r;
}

BodyContactModel::FoamState FoamStateAt(const BodyContactModel& model, double deflection_m, double force_N,
                                        bool used_up) {
  const double d = used_up ? model.covering_travel_m() : deflection_m;
  return {d, force_N, model.FoamEnergyAtDeflection(d), model.FoamStressAtDeflection(d)};
}

BodyContactResult FoamPeaksAtEnergy(const BodyContactModel& model, double energy_J) {
  if (energy_J > model.bottom_out_energy_J()) {
    return FoamPeaksAt(model, FoamStateAt(model, model.covering_travel_m(), model.ForceAtEnergy(energy_J), true),
                       true);
  }
  return FoamPeaksAt(model, model.FoamStateAtEnergy(energy_J), false);
}

CoveringValidity FoamValidity(const BodyContactModel& model, const BodyContactResult& r) noexcept {
  // On a curved face the gap under the flat body is read as d - r²/(2 R_c): a contact radius
  // beyond R_c (d > R_c/2) has left the face's cap, where that reading means nothing.
  const bool flat = std::isinf(model.scene().robot_radius_m);
  // How far along that limit (CoveringValidity::ratio): d/(R_c/2); a flat face has none.
  const double ratio = flat ? 0.0 : r.covering_deflection_m / (0.5 * model.covering_outer_radius_m());
  if (!flat && r.covering_deflection_m > 0.5 * model.covering_outer_radius_m()) {
    return {false,
            "foam law: the contact radius sqrt(2 R_c d) exceeds the face's radius R_c (d > R_c/2): the layer's gap "
            "reading does not hold there",
            ratio, ratio};
  }
  if (r.fully_compressed) {
    return {true,
            "foam law (elastic foundation on the measured curve); used up: past the curve's last point the layer is a "
            "rigid stop and the body spring takes the rest",
            ratio, ratio};
  }
  return {true, "foam law (elastic foundation on the measured curve), within the curve", ratio, ratio};
}

}  // namespace internal

}  // namespace covopt
