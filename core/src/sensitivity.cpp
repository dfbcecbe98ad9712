// Analytic design derivatives of the exact peaks (see sensitivity.hpp for the method).
#include "covopt/core/sensitivity.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "covopt/core/exact.hpp"
#include "numeric_format.hpp"
#include "sensitivity_internal.hpp"

namespace covopt {
namespace internal {
namespace {

constexpr double kHertzPressureFactor = 3.0 / (2.0 * std::numbers::pi);

/// x^p for x >= 0, with 0^p = 0 for p > 0 (and 1 for p == 0).
double Power(double x, double p) { return x > 0.0 ? std::pow(x, p) : (p == 0.0 ? 1.0 : 0.0); }

}  // namespace

Partials PartialsAt(const ForceLawSegment& seg, const SegmentDerivatives& d, double delta) {
  const double n = seg.exponent;
  const double k = seg.stiffness;
  const double kc = kHertzPressureFactor * k * seg.curvature_per_m;
  const double dkc = kHertzPressureFactor * (d.stiffness * seg.curvature_per_m + k * d.curvature);
  const double x = std::max(delta - seg.origin_m, 0.0);
  const double x0 = seg.start_m - seg.origin_m;
  const double dx = -d.origin;
  const double dx0 = d.start - d.origin;
  const double travel = delta - seg.start_m;
  // The σ term has x^(n-2): infinite at x = 0 unless the origin does not move.
  const double stress_slope_term =
      dx == 0.0 ? 0.0 : kc * (n - 1.0) * Power(x, n - 2.0) * dx;
  Partials p;
  p.force = d.force_offset + d.stiffness * Power(x, n) + k * n * Power(x, n - 1.0) * dx;
  p.stress = d.stress_offset + dkc * Power(x, n - 1.0) + stress_slope_term;
  p.energy = d.energy_start + d.force_offset * travel - seg.force_offset_N * d.start +
             d.stiffness * (Power(x, n + 1.0) - Power(x0, n + 1.0)) / (n + 1.0) +
             k * (Power(x, n) * dx - Power(x0, n) * dx0);
  p.density = d.density_start + d.stress_offset * travel - seg.stress_offset_Pa * d.start +
              dkc * (Power(x, n) - Power(x0, n)) / n +
              kc * (Power(x, n - 1.0) * dx - Power(x0, n - 1.0) * dx0);
  return p;
}

double StressSlope(const ForceLawSegment& seg, double delta) {
  const double x = delta - seg.origin_m;
  return kHertzPressureFactor * seg.stiffness * seg.curvature_per_m * (seg.exponent - 1.0) *
         std::pow(x, seg.exponent - 2.0);
}

namespace {

using Design = DesignParameter;

/// dK, dc, d start, d origin of segment j with respect to one design parameter.
SegmentDerivatives PrimitiveDerivatives(const ImpactModel& model, std::size_t j, Design design) {
  const Scene& scene = model.scene();
  const ForceLawSegment& seg = model.segment(j);
  SegmentDerivatives d;
  const bool covering_material = seg.phase == Phase::kCoveringOnScalp || seg.phase == Phase::kCoveringOnBone;
  if (covering_material) {
    if (design == Design::kCoveringModulus) {
      // K = 4/3 / (C sqrt(c)),  C ∋ (1 - ν_c²)/E_c  =>  dK/dE_c = (3/4) K² sqrt(c) (1 - ν_c²)/E_c².
      const double e_c = scene.covering.youngs_modulus_Pa;
      const double nu_c = scene.covering.poisson_ratio;
      d.stiffness = 0.75 * seg.stiffness * seg.stiffness * std::sqrt(seg.curvature_per_m) *
                    (1.0 - nu_c * nu_c) / (e_c * e_c);
    } else if (!std::isinf(scene.robot.radius_m)) {
      const double r_c = scene.robot.radius_m + scene.covering.thickness_m;
      d.curvature = -1.0 / (r_c * r_c);  // c = 1/R_c + ...,  R_c = R_r + b_c
      d.stiffness = -0.5 * seg.stiffness / seg.curvature_per_m * d.curvature;
    }
  }
  if (seg.phase == Phase::kRobotOnBone && design == Design::kCoveringThickness) {
    const double f = scene.model.full_compression_fraction;
    d.origin = f;  // t2 = t1 + f b_c (cumulative) or f b_c (literal)
    d.start = seg.start_m == seg.origin_m ? f : 0.0;  // ill-ordered literal: starts at t1
  }
  return d;
}

}  // namespace

std::array<SegmentDerivatives, 3> SegmentDerivativesOf(const ImpactModel& model, DesignParameter parameter) {
  std::array<SegmentDerivatives, 3> all{};
  all[0] = PrimitiveDerivatives(model, 0, parameter);
  for (std::size_t j = 0; j + 1 < model.segment_count(); ++j) {
    const ForceLawSegment& seg = model.segment(j);
    const ForceLawSegment& next = model.segment(j + 1);
    SegmentDerivatives following = PrimitiveDerivatives(model, j + 1, parameter);
    const Partials at_origin = PartialsAt(seg, all[j], next.origin_m);
    const Partials at_start = PartialsAt(seg, all[j], next.start_m);
    const ContactState state_origin = model.StateInSegment(j, next.origin_m);
    const ContactState state_start = model.StateInSegment(j, next.start_m);
    following.force_offset = at_origin.force + state_origin.stiffness_N_per_m * following.origin;
    following.stress_offset = at_origin.stress + StressSlope(seg, next.origin_m) * following.origin;
    following.energy_start = at_start.energy + state_start.force_N * following.start;
    following.density_start = at_start.density + state_start.compressive_stress_Pa * following.start;
    all[j + 1] = following;
  }
  return all;
}

namespace {

/// A candidate for F_max or σ_c,max: its value and its derivative.
struct Candidate {
  double value = 0.0, derivative = 0.0;
};

PeakDerivatives Differentiate(const ImpactModel& model, const ImpactPeaks& peaks, Design design) {
  const double delta_max = peaks.max_penetration_m;
  const std::size_t top = model.SegmentIndexAt(delta_max);
  const std::array<SegmentDerivatives, 3> d = SegmentDerivativesOf(model, design);
  // F and σ at the end of each segment passed (the literal law can drop after it), where
  // PeaksAtMaxPenetration may find the maximum; the end moves with the next segment's start.
  std::array<Candidate, 3> force_ends{}, stress_ends{};  // at most 3 segments, top <= 2
  for (std::size_t j = 0; j < top; ++j) {
    const ForceLawSegment& seg = model.segment(j);
    const Partials at_end = PartialsAt(seg, d[j], seg.end_m);
    const ContactState state_end = model.StateInSegment(j, seg.end_m);
    force_ends[j] = {state_end.force_N, at_end.force + state_end.stiffness_N_per_m * d[j + 1].start};
    stress_ends[j] = {state_end.compressive_stress_Pa,
                      at_end.stress + StressSlope(seg, seg.end_m) * d[j + 1].start};
  }
  const ForceLawSegment& seg = model.segment(top);
  const Partials p = PartialsAt(seg, d[top], delta_max);
  const ContactState state = model.StateInSegment(top, delta_max);
  PeakDerivatives out;
  out.max_penetration = -p.energy / state.force_N;
  // The same choice as PeaksAtMaxPenetration: δ_max's value unless an end is larger.
  auto largest = [top](Candidate at_max, const std::array<Candidate, 3>& ends) {
    for (std::size_t j = 0; j < top; ++j) {
      if (at_max.value < ends[j].value) at_max = ends[j];
    }
    return at_max.derivative;
  };
  out.peak_force = largest({state.force_N, p.force + state.stiffness_N_per_m * out.max_penetration},
                           force_ends);
  out.max_compressive_stress = largest(
      {state.compressive_stress_Pa, p.stress + StressSlope(seg, delta_max) * out.max_penetration},
      stress_ends);
  out.max_tensile_stress = model.TensileFromCompressive(out.max_compressive_stress);
  out.max_energy_density = p.density + state.compressive_stress_Pa * out.max_penetration;
  return out;
}

}  // namespace
}  // namespace internal

PeakSensitivities ExactPeakSensitivities(const ImpactModel& model, const ImpactPeaks& peaks) {
  if (!model.has_covering()) {
    throw std::invalid_argument(
        "design sensitivities need a covering (covering.thickness > 0): b_c -> 0 is a "
        "discontinuity of the model");
  }
  if (model.is_foam()) {
    throw std::invalid_argument(
        "design sensitivities (d/dE_c, d/db_c) are for the Hertz law: a covering under the foam law (covering.law "
        "foam or auto with a compressive_curve, docs/model.md §16) has a measured curve, not a modulus");
  }
  const Scene& scene = model.scene();
  if (!scene.is_conservative_two_mass()) {
    // The damped exact path maximises F and σ_c inside the loading branch and integrates e_A:
    // its derivatives are left to a finite difference or to the time path's sensitivities
    // (TimePathPeakSensitivities); braking and a neck have no exact path at all.
    const std::string what =
        scene.is_damped() ? "contact damping (model.damping " +
                                internal::FormatNumber(scene.model.damping_s_per_m) + " s/m)"
        : scene.robot_brakes() ? "a braking robot (robot.braking)"
                               : "a neck (head.torso_mass)";
    throw std::invalid_argument(
        "analytic design sensitivities of the exact path are for the conservative two-mass "
        "impact, not a scene with " + what +
        ": use a finite difference, or the time path's sensitivities (TimePathPeakSensitivities)");
  }
  using internal::DesignParameter;
  return {internal::Differentiate(model, peaks, DesignParameter::kCoveringModulus),
          internal::Differentiate(model, peaks, DesignParameter::kCoveringThickness)};
}

}  // namespace covopt
