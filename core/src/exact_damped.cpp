// The damped exact path of docs/model.md §10.1: Hunt-Crossley contact damping,
// F = F_el(δ)(1 + d δ'), σ_c = σ_el(δ)(1 + d δ'), answered without integrating in time.
//
// With v = δ' and w = d v, m v dv/dδ = -F_el(δ)(1 + d v) integrates on both branches to
//
//     m φ(d v) / d² = U(δ_max) - U(δ),      φ(w) = w - ln(1 + w),
//
// with v >= 0 on the loading and v <= 0 on the unloading (1 + d v > 0 throughout). At δ = 0
// on the loading v = v0, so U(δ_max) = m φ(d v0) / d²; at δ = 0 on the unloading v is the
// rebound speed. With q = sqrt(2 (U(δ_max) - U(δ)) / m), the conservative speed at the same
// energy gap, d v = Ω(±d q), where Ω(p) solves φ(Ω) = p²/2 with the sign of p.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "exact_internal.hpp"

namespace covopt::internal {
namespace {

constexpr double kHertzPressureFactor = 3.0 / (2.0 * std::numbers::pi);  // k = 3/(2π)
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// ---------------------------------------------------------------------------------------------
// φ(w) = w - ln(1 + w) and its inverse.

/// 2 φ(w) / w² for w > -1 (1 at w = 0), without cancellation near w = 0.
double TwoPhiOverSquare(double w) noexcept {
  if (std::abs(w) < 0.1) {
    // 2 Σ_{k>=2} (-1)^k w^(k-2) / k: the first term left out is below 1e-19 of the sum.
    double sum = 0.0;
    for (int k = 20; k >= 2; --k) sum = sum * w + (k % 2 == 0 ? 2.0 : -2.0) / k;
    return sum;
  }
  return 2.0 * (w - std::log1p(w)) / (w * w);
}

double Phi(double w) noexcept { return 0.5 * w * w * TwoPhiOverSquare(w); }

/// Ω(p) = p + Σ_{m>=2} a_m p^m, the inversion of φ(w) = p²/2 about w = 0: from
/// Ω' Ω = p (1 + Ω), (m + 1) a_m = a_(m-1) - Σ_{j=2}^{m-1} (m - j + 1) a_(m-j+1) a_j.
/// Its radius of convergence is 2 sqrt(π) (the other roots of φ = 0 are at φ = 2πik).
/// a_2 ... a_30; the rest of the series is below 2e-19 for |p| <= 1.
constexpr std::array<double, 29> kOmegaSeries = {
    0.3333333333333333,     0.027777777777777776,   -0.003703703703703704,
    0.0002314814814814815,  5.878894767783657e-05,  -2.553644914756026e-05,
    4.899078973153047e-06,  -2.428276122977769e-07, -1.85406221071516e-07,
    7.542464855411896e-08,  -1.47216272806884e-08,  5.159887341078076e-10,
    7.32986413160022e-10,   -2.921357345635569e-10, 5.717312238897994e-11,
    -1.5008349408791911e-12, -3.239317851416903e-12, 1.2822077905614429e-12,
    -2.513834640057088e-13, 5.2401866818838735e-15, 1.5326196647277207e-14,
    -6.053864010513748e-15, 1.1889539086269768e-15, -2.055644733697029e-17,
    -7.59703395936517e-17,  2.999822650631319e-17,  -5.900904005856487e-18,
    8.726010378440995e-20,  3.895646579519859e-19};

/// Ω(p)/p and Ω(-p)/(-p) by the series (|p| <= 1), evaluated as four interleaved Horner
/// chains in p⁴ (Σ c_k p^k = A0 + p A1 + p² A2 + p³ A3, A_r = Σ_j c_(4j+r) p^(4j)): the same
/// chains give both signs, at a quarter of one chain's latency.
struct SpeedRatioPair {
  double plus = 1.0;   ///< Ω(p)/p
  double minus = 1.0;  ///< Ω(-p)/(-p)
};

SpeedRatioPair SeriesSpeedRatios(double p) noexcept {
  constexpr std::size_t kCount = kOmegaSeries.size();  // c_0 ... c_28
  const double p2 = p * p;
  const double p4 = p2 * p2;
  std::array<double, 4> chain{};
  for (std::size_t r = 0; r < 4; ++r) {
    std::size_t k = r + 4 * ((kCount - 1 - r) / 4);  // the highest c_(4j+r)
    chain[r] = kOmegaSeries[k];
    while (k >= 4 + r) {
      k -= 4;
      chain[r] = chain[r] * p4 + kOmegaSeries[k];
    }
  }
  const double even = chain[0] + p2 * chain[2];
  const double odd = p * (chain[1] + p2 * chain[3]);
  return {1.0 + p * (even + odd), 1.0 - p * (even - odd)};
}

/// Ω(p)/p by the series (|p| <= 1).
double SeriesSpeedRatio(double p) noexcept { return SeriesSpeedRatios(p).plus; }

/// Ω(p)/p by Halley's method on φ(w) = p²/2 (|p| > 1).
double IteratedSpeedRatio(double p) noexcept {
  const double tau = 0.5 * p * p;  // φ(w) = τ
  const double root_term = std::sqrt(tau * (tau + 2.0));
  double lower = 0.0, upper = 0.0, w = 0.0;
  if (p > 0.0) {
    // w²/(2 (1 + w)) <= φ(w) <= w²/2 for w >= 0 bracket the root.
    lower = p;
    upper = tau + root_term;
    if (p <= 2.0) {
      w = p * SeriesSpeedRatio(p);  // within 1e-9 for 1 < p <= 2
    } else {
      w = tau + std::log1p(tau);  // w = τ + ln(1 + w), twice
      w = tau + std::log1p(w);
    }
  } else {
    // 1 + w = y solves y - ln y = 1 + τ; beyond τ = 40, y < 1e-17 and w rounds to -1.
    if (tau > 40.0) return -1.0 / p;
    // w²/2 <= φ(w) <= w²/(2 (1 + w)) for -1 < w <= 0.
    lower = std::max(p, -1.0);
    upper = -2.0 * tau / (tau + root_term);
    if (p >= -2.0) {
      w = p * SeriesSpeedRatio(p);
    } else {
      double y = std::exp(-1.0 - tau);  // y = exp(y - 1 - τ), twice
      y = std::exp(y - 1.0 - tau);
      w = y - 1.0;
    }
  }
  if (!(w > lower && w < upper)) w = 0.5 * (lower + upper);
  // Halley on f(w) = φ(w) - τ (f' = w/(1 + w), f'' = 1/(1 + w)²), kept inside the bracket.
  // The scale of w is |w|, or 1 + w near w = -1 (the unloading of a strongly damped contact);
  // a step below 1e-7 of it leaves an error of order 1e-21 of it.
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double one_plus_w = 1.0 + w;
    const double scale = std::min(std::abs(w), one_plus_w);
    const double f = Phi(w) - tau;
    if (f == 0.0) break;
    const double slope = w / one_plus_w;
    const double newton = f / slope;
    const double correction = 0.5 * newton / (one_plus_w * w);  // f f'' / (2 f'²)
    const double step = std::abs(correction) < 0.5 ? newton / (1.0 - correction) : newton;
    if (std::abs(step) <= 1e-7 * scale) return (w - step) / p;
    if ((f > 0.0) == (p > 0.0)) {
      upper = w;
    } else {
      lower = w;
    }
    const double next = w - step;
    w = next > lower && next < upper ? next : 0.5 * (lower + upper);
    if (!(upper - lower > 4.0 * kEpsilon * scale)) break;
  }
  return w / p;
}

/// Ω(p)/p > 0: the damped speed over the conservative one at the same energy gap, on the
/// loading (p = d q > 0) or the unloading (p = -d q < 0) branch; 1 at p = 0. The series for
/// |p| <= 1, Halley's method beyond (relative error about 2e-16 in both).
double SpeedRatio(double p) noexcept {
  if (std::abs(p) <= 1.0) return SeriesSpeedRatio(p);
  return IteratedSpeedRatio(p);
}

/// Ω(a)/a and Ω(-a)/(-a) for a >= 0: the loading and unloading speed ratios at one point.
SpeedRatioPair SpeedRatios(double a) noexcept {
  if (a <= 1.0) return SeriesSpeedRatios(a);
  return {IteratedSpeedRatio(a), IteratedSpeedRatio(-a)};
}

// ---------------------------------------------------------------------------------------------
// A bracketed root finder.

/// A root of f in [a, b], given f(a) and f(b) of opposite signs, within `tolerance` (Brent's
/// zeroin: inverse quadratic interpolation and secant steps, bisection when they stall).
/// Returns early, at the point just evaluated, once `stop` is true (f may set it).
template <class Function>
double FindRoot(Function&& f, double a, double b, double fa, double fb, double tolerance,
                const bool& stop) noexcept {
  double c = a, fc = fa, d = b - a, e = d;
  for (int iteration = 0; iteration < 200; ++iteration) {
    if ((fb > 0.0) == (fc > 0.0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const double tol = 2.0 * kEpsilon * std::abs(b) + 0.5 * tolerance;
    const double half = 0.5 * (c - b);
    if (std::abs(half) <= tol || fb == 0.0) return b;
    if (std::abs(e) >= tol && std::abs(fa) > std::abs(fb)) {
      const double s = fb / fa;
      double p = 0.0, q = 0.0;
      if (a == c) {
        p = 2.0 * half * s;
        q = 1.0 - s;
      } else {
        const double qa = fa / fc, r = fb / fc;
        p = s * (2.0 * half * qa * (qa - r) - (b - a) * (r - 1.0));
        q = (qa - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0) {
        q = -q;
      } else {
        p = -p;
      }
      if (2.0 * p < std::min(3.0 * half * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = e = half;
      }
    } else {
      d = e = half;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol ? d : (half > 0.0 ? tol : -tol);
    fb = f(b);
    if (stop) return b;
  }
  return b;
}

// ---------------------------------------------------------------------------------------------
// The loading branch, one force-law segment at a time.

/// The elastic force and stress of a segment at one point of the loading branch, with the
/// loading speed there.
struct BranchPoint {
  double x = 0.0;          ///< phase-local penetration [m]
  double speed = 0.0;      ///< v [m/s]
  double x_pow_nm1 = 0.0;  ///< x^(n-1)
  double x_pow_n = 0.0;    ///< x^n
};

/// Segment j's part of the loading branch: local penetrations [x_a, x_b] (x_b = δ_max's in
/// the segment holding it) and the loading speed v(x) from U(δ_max) - U(origin + x).
class LoadingPiece {
 public:
  LoadingPiece(const ImpactModel& model, std::size_t j, double upper_m, double energy_above_J,
               double damping_s_per_m) noexcept
      : segment_(&model.segment(j)),
        gap_below_upper_(model, j, upper_m),
        lower_local_m_(segment_->start_m - segment_->origin_m),
        upper_local_m_(upper_m - segment_->origin_m),
        energy_above_J_(energy_above_J),
        two_over_mass_(2.0 / model.effective_mass_kg()),
        damping_s_per_m_(damping_s_per_m) {}

  const ForceLawSegment& segment() const noexcept { return *segment_; }
  double lower_local_m() const noexcept { return lower_local_m_; }
  double upper_local_m() const noexcept { return upper_local_m_; }
  /// U(δ_max) - U(start of the segment) [J].
  double EnergyAboveStart() const noexcept {
    return energy_above_J_ + gap_below_upper_(upper_local_m_ - lower_local_m_);
  }
  /// The branch at x = x_b - gap [m].
  BranchPoint At(double gap_m) const noexcept {
    BranchPoint point;
    point.x = std::max(upper_local_m_ - gap_m, 0.0);  // s² may round past x_a = 0
    const double q = std::sqrt(two_over_mass_ * (energy_above_J_ + gap_below_upper_(gap_m)));
    point.speed = q * SpeedRatio(damping_s_per_m_ * q);
    point.x_pow_nm1 = std::pow(point.x, segment_->exponent - 1.0);
    point.x_pow_n = point.x_pow_nm1 * point.x;
    return point;
  }

 private:
  const ForceLawSegment* segment_;
  ImpactModel::EnergyGapBelow gap_below_upper_;
  double lower_local_m_, upper_local_m_;
  double energy_above_J_;
  double two_over_mass_;
  double damping_s_per_m_;
};

/// Which elastic quantity P_el = P_off + T(x), T = C x^k, a search maximises P_el (1 + d v) of.
enum class Quantity {
  kForce,   ///< F_el: P_off = F_off, T = K x^n
  kStress,  ///< σ_el: P_off = σ_off, T = k K c x^(n-1)
};

/// What the peak search reads at one point: P = P_el (1 + d v), the sign of dP/dδ and of the
/// slope of ln Q (see MaxOverPiece).
struct PeakProbe {
  double value = 0.0;    ///< P_el (1 + d v)
  double rise = 0.0;     ///< m v - d F_el P_el / P_el': the sign of dP/dδ
  double q_slope = 0.0;  ///< v² d ln Q / d ln x: decreasing in x
};

PeakProbe Probe(const ForceLawSegment& seg, Quantity quantity, const BranchPoint& point,
                double mass_kg, double damping_s_per_m) noexcept {
  const double n = seg.exponent;
  const double force_term = seg.stiffness * point.x_pow_n;
  const double force = seg.force_offset_N + force_term;
  const bool is_force = quantity == Quantity::kForce;
  const double power = is_force ? n : n - 1.0;  // k
  const double offset = is_force ? seg.force_offset_N : seg.stress_offset_Pa;
  const double coefficient =  // C
      is_force ? seg.stiffness : kHertzPressureFactor * seg.stiffness * seg.curvature_per_m;
  const double term = is_force ? force_term : coefficient * point.x_pow_nm1;
  const double law = offset + term;
  const double x = point.x;
  // P_el / P_el' = x P_el / (k T) and the log-slopes x P'/P = k T/P, x F'/F = n K x^n/F,
  // read at x = 0 as their limits.
  double law_over_derivative = 0.0, law_log_slope = power, force_log_slope = n;
  if (x > 0.0) {
    law_over_derivative = x * law / (power * term);
    if (offset != 0.0) law_log_slope = power * term / law;
    if (seg.force_offset_N != 0.0) force_log_slope = n * force_term / force;
  } else {
    if (offset != 0.0) {
      law_log_slope = 0.0;
      // x/T = x^(1-k)/C -> 0, 1/C or +inf
      law_over_derivative = power < 1.0    ? 0.0
                            : power == 1.0 ? offset / coefficient
                                           : std::numeric_limits<double>::infinity();
    }
    if (seg.force_offset_N != 0.0) force_log_slope = 0.0;
  }
  const double v = point.speed;
  const double d = damping_s_per_m;
  PeakProbe probe;
  probe.value = law * (1.0 + d * v);
  probe.rise = mass_kg * v - d * force * law_over_derivative;
  probe.q_slope = v * v * (power - 1.0 - law_log_slope - force_log_slope) -
                  x * force * (1.0 + d * v) / mass_kg;
  return probe;
}

/// Largest P = P_el (1 + d v) over one loading piece.
///
/// dP/dδ = (1 + d v) (P_el' - d P_el F_el / (m v)) has the sign of Q - d with
/// Q = m v P_el' / (P_el F_el), and ln Q is concave in ln x: ln v is (v is concave and
/// decreasing in δ), and so are ln(P_el'/P_el) and -ln F_el (a linear term in ln x minus the
/// log of a sum of exponentials of it). So {Q > d} is an interval: P falls, rises, falls
/// (any part possibly empty), and its largest value is at x_a, at x_b, or where it stops
/// rising: the root of `rise` right of a point inside the interval. The searches run in
/// s = sqrt(x_b - x), in which v is smooth at δ_max.
double MaxOverPiece(const LoadingPiece& piece, Quantity quantity, const BranchPoint& lower,
                    const BranchPoint& upper, double mass_kg, double damping_s_per_m) noexcept {
  const ForceLawSegment& seg = piece.segment();
  auto probe = [&](const BranchPoint& point) {
    return Probe(seg, quantity, point, mass_kg, damping_s_per_m);
  };
  const PeakProbe at_a = probe(lower), at_b = probe(upper);
  double best = std::max(at_a.value, at_b.value);
  if (quantity == Quantity::kStress && seg.exponent == 1.0) return best;  // σ_el constant
  if (at_b.rise >= 0.0) return best;  // P rises up to x_b (after falling, perhaps)
  const double s_range = std::sqrt(piece.upper_local_m() - piece.lower_local_m());
  const double tolerance = 1e-9 * s_range;
  auto at_s = [&](double s) { return piece.At(s * s); };
  double s_rising = s_range;  // a point where P rises
  double rise_rising = at_a.rise;
  if (!(at_a.rise > 0.0)) {
    // Look for the interval {Q > d} at Q's largest value, where q_slope changes sign;
    // stop at the first point inside it.
    if (!(at_a.q_slope > 0.0) || at_b.q_slope >= 0.0) return best;  // Q <= Q(x_a) or Q(x_b)
    bool inside = false;
    auto q_slope_at = [&](double s) {
      const PeakProbe p = probe(at_s(s));
      if (p.rise > 0.0) {
        inside = true;
        rise_rising = p.rise;
      }
      return p.q_slope;
    };
    // q_slope falls with x, so it rises with s: negative at s = 0 (x_b).
    s_rising = FindRoot(q_slope_at, 0.0, s_range, at_b.q_slope, at_a.q_slope, 1e-6 * s_range, inside);
    if (!inside) return best;  // Q <= d throughout: P never rises
  }
  bool never = false;
  auto rise_at = [&](double s) { return probe(at_s(s)).rise; };
  const double s_top = FindRoot(rise_at, 0.0, s_rising, at_b.rise, rise_rising, tolerance, never);
  return std::max(best, probe(at_s(s_top)).value);
}

/// U(δ_max) = m φ(d v0) / d² [J], the energy stored at the maximum compression.
double EnergyAtMaxCompression(const ImpactModel& model) noexcept {
  const double w0 = model.scene().model.damping_s_per_m * model.impact_speed_m_per_s();
  return model.impact_energy_J() * TwoPhiOverSquare(w0);
}

// ---------------------------------------------------------------------------------------------
// Quadratures over δ in s = sqrt(δ_max - δ), as the conservative duration (exact.cpp): pieces
// end at the switches, each is mapped by s = a + (b - a) u²(3 - 2u) and integrated with
// N-point Gauss-Legendre.

template <int N>
struct MappedNodes {
  std::array<double, N> phi{};
  std::array<double, N> weight_dphi{};
  MappedNodes() {
    const GaussLegendre<N> rule;
    for (int i = 0; i < N; ++i) {
      const double u = rule.node[i];
      phi[i] = u * u * (3.0 - 2.0 * u);
      weight_dphi[i] = rule.weight[i] * 6.0 * u * (1.0 - u);
    }
  }
};

template <int N>
const MappedNodes<N>& Nodes() {
  static const MappedNodes<N> nodes;
  return nodes;
}

/// The δ [m], in descending order, where the damping parameter a = d q passes 1, 4, 16, ...
/// on the way in (q = sqrt(2 (U(δ_max) - U(δ)) / m) grows from 0 at δ_max to q0 at δ = 0).
/// Around a = 1 the unloading speed turns from q towards its bound 1/d; splitting the
/// quadratures there keeps their integrands smooth on each piece however strong the damping.
struct DampingSplits {
  std::array<double, 8> penetration_m{};
  std::size_t count = 0;
};

DampingSplits SplitsOf(const ImpactModel& model, double energy_at_max_J, double damping_s_per_m) {
  DampingSplits splits;
  const double half_mass = 0.5 * model.effective_mass_kg();
  for (double a = 1.0; splits.count < splits.penetration_m.size(); a *= 4.0) {
    // U(δ) = U(δ_max) - ½ m (a/d)²
    const double speed = a / damping_s_per_m;
    const double energy = energy_at_max_J - half_mass * speed * speed;
    if (!(energy > 0.0)) break;
    const std::size_t j = PeakSegment(model, energy);
    const ForceLawSegment& seg = model.segment(j);
    splits.penetration_m[splits.count++] = SolveEnergyBalance(seg, energy - seg.energy_at_start_J);
  }
  return splits;
}

/// Calls visit(j, x, s, q, weight) at every node: segment j, its local penetration x [m],
/// s = sqrt(δ_max - δ) [m^½], the conservative speed q [m/s] and the node's weight in s.
/// The pieces end at the switches and at `splits`.
template <int N, class Visit>
void ForEachNode(const ImpactModel& model, std::size_t top, double delta_max,
                 const DampingSplits& splits, Visit&& visit) {
  const MappedNodes<N>& nodes = Nodes<N>();
  const double two_over_mass = 2.0 / model.effective_mass_kg();
  double s_lower = 0.0;
  double energy_above = 0.0;  // U(δ_max) - U(top of the piece)
  std::size_t next_split = 0;
  for (std::size_t j = top + 1; j-- > 0;) {
    const ForceLawSegment& seg = model.segment(j);
    double upper = (j == top) ? delta_max : seg.end_m;
    for (;;) {
      while (next_split < splits.count && !(splits.penetration_m[next_split] < upper)) ++next_split;
      const bool split = next_split < splits.count && splits.penetration_m[next_split] > seg.start_m;
      const double lower = split ? splits.penetration_m[next_split] : seg.start_m;
      const double s_upper = std::sqrt(delta_max - lower);
      const double width = s_upper - s_lower;
      const ImpactModel::EnergyGapBelow gap_below_upper(model, j, upper);
      const double upper_local = upper - seg.origin_m;
      // An empty piece (δ_max exactly on the top segment's start) adds nothing; its nodes
      // would be 0/0 (s = q = 0), as the conservative duration's first piece was.
      for (int i = 0; i < N && width > 0.0; ++i) {
        const double s = s_lower + width * nodes.phi[i];
        const double gap = (s - s_lower) * (s + s_lower);  // δ = upper - gap
        const double q = std::sqrt(two_over_mass * (energy_above + gap_below_upper(gap)));
        visit(j, upper_local - gap, s, q, width * nodes.weight_dphi[i]);
      }
      energy_above += gap_below_upper(upper - lower);
      s_lower = s_upper;
      if (!split) break;
      upper = lower;
    }
  }
}

/// Gauss-Legendre nodes per piece of the quadratures. Measured against 200 nodes per piece
/// (splits at a = 1, 2, 4, ...) on 168 scenes (bare and 15 mm covered, v0 0.3 to 8 m/s,
/// d 0.01 to 170 s/m): e_A within 8e-13, the loading time within 3e-13 and the unloading time
/// within 4e-12. Without the splits the unloading time was off by up to 3e-7 at d q0 = 26.
constexpr int kNodes = 20;

}  // namespace

ImpactPeaks DampedExactPeaks(const ImpactModel& model) noexcept {
  const double d = model.scene().model.damping_s_per_m;
  const double mass = model.effective_mass_kg();
  const double energy = EnergyAtMaxCompression(model);
  const std::size_t top = PeakSegment(model, energy);
  const ForceLawSegment& top_segment = model.segment(top);
  const double delta_max =
      SolveEnergyBalance(top_segment, energy - top_segment.energy_at_start_J);
  // δ_max's phase, the compression flags and e_el(δ_max); F and σ are replaced below.
  ImpactPeaks peaks = PeaksAtMaxPenetration(model, top, delta_max);

  double force = 0.0, stress = 0.0;
  double energy_above = 0.0;  // U(δ_max) - U(top of segment j)
  for (std::size_t j = top + 1; j-- > 0;) {
    const ForceLawSegment& seg = model.segment(j);
    const LoadingPiece piece(model, j, j == top ? delta_max : seg.end_m, energy_above, d);
    const BranchPoint lower = piece.At(piece.upper_local_m() - piece.lower_local_m());
    const BranchPoint upper = piece.At(0.0);
    force = std::max(force, MaxOverPiece(piece, Quantity::kForce, lower, upper, mass, d));
    stress = std::max(stress, MaxOverPiece(piece, Quantity::kStress, lower, upper, mass, d));
    energy_above = piece.EnergyAboveStart();
  }
  peaks.peak_force_N = force;
  peaks.max_compressive_stress_Pa = stress;
  peaks.max_tensile_stress_Pa = model.TensileFromCompressive(stress);

  // e_A = ∫σ_el (1 + d v) dδ = e_el(δ_max) + d ∫σ_el v dδ, and by parts (e_el(0) = 0,
  // v(δ_max) = 0, m v v' = -F_el (1 + d v)):  ∫σ_el v dδ = (1/m) ∫ e_el F_el (1 + d v)/v dδ,
  // whose integrand is smoother at the phase starts (x^n against σ_el's x^(n-1)); dδ/v is
  // 2s ds/v, finite at δ_max.
  double integral = 0.0;
  ForEachNode<kNodes>(model, top, delta_max, SplitsOf(model, energy, d),
                      [&](std::size_t j, double x, double s, double q, double weight) {
    const ForceLawSegment& seg = model.segment(j);
    const double n = seg.exponent;
    const double x0 = seg.start_m - seg.origin_m;  // > 0 only in the literal ill-ordered case
    const double x_pow_n = std::pow(x, n);
    const double kc = kHertzPressureFactor * seg.stiffness * seg.curvature_per_m;
    const double force_el = seg.force_offset_N + seg.stiffness * x_pow_n;
    // x^n - x0^n as x0^n expm1(n log1p((x - x0)/x0)) where x0 > 0: no cancellation just
    // past the start (x - x0 is exact there).
    const double power_difference =
        x0 > 0.0 ? std::pow(x0, n) * std::expm1(n * std::log1p((x - x0) / x0)) : x_pow_n;
    const double density_el = seg.energy_density_at_start_J_per_m2 +
                              seg.stress_offset_Pa * (x - x0) + kc * power_difference / n;
    const double a = d * q;
    const double ratio = SpeedRatio(a);
    // (1 + d v) 2s/v with v = q ρ: (1 + a ρ) 2s/(q ρ)
    integral += weight * density_el * force_el * (1.0 + a * ratio) * (2.0 * s / (q * ratio));
  });
  peaks.max_energy_density_J_per_m2 += d / mass * integral;
  return peaks;
}

DampedContactTimes DampedContactDurations(const ImpactModel& model,
                                          const ImpactPeaks& peaks) noexcept {
  const double d = model.scene().model.damping_s_per_m;
  const double energy = EnergyAtMaxCompression(model);
  const std::size_t top = PeakSegment(model, energy);
  DampedContactTimes times;
  auto visit = [&](std::size_t, double, double s, double q, double weight) {
    const double conservative = weight * 2.0 * s / q;  // 2s ds / q
    const SpeedRatioPair ratio = SpeedRatios(d * q);
    times.loading_s += conservative / ratio.plus;
    times.unloading_s += conservative / ratio.minus;
  };
  ForEachNode<kNodes>(model, top, peaks.max_penetration_m, SplitsOf(model, energy, d), visit);
  return times;
}

double DampedReboundSpeed(const ImpactModel& model) noexcept {
  // At δ = 0 on the unloading, m φ(d v) / d² = U(δ_max): the conservative speed there is
  // q0 = sqrt(2 U(δ_max) / m) = v0 sqrt(2 φ(w0)/w0²).
  const double d = model.scene().model.damping_s_per_m;
  const double w0 = d * model.impact_speed_m_per_s();
  const double q0 = model.impact_speed_m_per_s() * std::sqrt(TwoPhiOverSquare(w0));
  return q0 * SpeedRatio(-d * q0);
}

}  // namespace covopt::internal
