// The default answer: a material's verdict over its stated uncertainty (the scale of its
// curve), its thinnest admissible thickness over that range, and the nearest changes.
#include "covopt/optim/material_range.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/core/number_format.hpp>

#include "limit_bracket.hpp"
#include "robust_internal.hpp"

namespace covopt::optim {
namespace {

std::string Kilopascals(double pascals) { return FormatSignificant(pascals * 1e-3, 3); }
std::string Millimetres(double metres) { return FormatFixed(metres * 1e3, 2) + " mm"; }
std::string Factor(double f) { return FormatSignificant(f, 3); }

CrushInput CrushInputOf(materials::CrushBehaviour behaviour, double strength_Pa) {
  switch (behaviour) {
    case materials::CrushBehaviour::kCrushes: return {CrushCheck::kChecked, strength_Pa};
    case materials::CrushBehaviour::kDoesNotCrush: return {CrushCheck::kDoesNotCrush, 0.0};
    case materials::CrushBehaviour::kUnknown: break;
  }
  return {CrushCheck::kUnknownStrength, 0.0};
}

/// Admissible at every scale of `scales`.
bool AdmissibleAt(const Scene& scene, const RangedMaterial& m, double thickness_m, std::span<const double> scales,
                  const DesignOptions& options) {
  return std::all_of(scales.begin(), scales.end(), [&](double s) {
    return RangeVerdictAt(scene, m, thickness_m, s, options).safe();
  });
}

/// The worst governing ratio (SF applied) at the range's ends [-]; +inf when a counted criterion
/// without a ratio fails (an unknown strength refused: no change helps).
double WorstRatio(const MaterialRangeCheck& check, double safety_factor) {
  for (const Verdict& v : check.verdicts) {
    for (const Criterion& c : v.criteria) {
      if (c.counted && !c.passed && !std::isfinite(c.ratio)) return std::numeric_limits<double>::infinity();
    }
  }
  return safety_factor * check.worst().governing_ratio();
}

NearestChange NearestSpeed(const Scene& scene, const RangedMaterial& m, const DesignOptions& options,
                           double thickness) {
  const std::vector<double> ends = ScalesToJudge(m.range, options.rule());
  struct Probe {};
  const auto limit = internal::BracketLimit<Probe>(1e-6, scene.robot.speed_m_per_s, [&](double v) {
    Scene s = scene;
    s.robot.speed_m_per_s = v;
    internal::LimitProbe<Probe> p;
    p.admissible = AdmissibleAt(s, m, thickness, ends, options);
    return p;
  });
  NearestChange c;
  switch (limit.status) {
    case SpeedLimitStatus::kLimited:
    case SpeedLimitStatus::kSafeUpToSearchLimit:
      c.reachable = true;
      c.value = limit.value;
      c.note = "at " + Millimetres(thickness) + ", over its range";
      break;
    case SpeedLimitStatus::kNoSafeValue:
    case SpeedLimitStatus::kEvaluationFailed:
      c.note = "not reachable: not admissible at " + Millimetres(thickness) + " even at 1e-06 m/s";
      break;
  }
  return c;
}

NearestChange NearestThickness(const Scene& scene, const RangedMaterial& m, const DesignOptions& options) {
  NearestChange c;
  const std::optional<double> b = ThinnestOverRange(scene, m, options, kNearestChangeMaxThickness_m);
  if (b) {
    c.reachable = true;
    c.value = *b;
    c.note = "at the scene's speed, over its range";
  } else {
    c.note = "not reachable: no thickness up to " + Millimetres(kNearestChangeMaxThickness_m) + " is admissible";
  }
  return c;
}

NearestChange NearestRadius(const Scene& scene, const RangedMaterial& m, const DesignOptions& options,
                            double thickness) {
  NearestChange c;
  const double from = scene.robot.radius_m;
  if (!(from < kNearestChangeMaxRadius_m)) {
    c.note = "not reachable: the robot's radius is already " + Millimetres(from);
    return c;
  }
  const std::vector<double> ends = ScalesToJudge(m.range, options.rule());
  // The snap's scan then bisection, on the radius axis (admissibility need not be monotone in it).
  DesignSpace axis;
  axis.min_thickness_m = from;
  axis.max_thickness_m = kNearestChangeMaxRadius_m;
  const double resolution = kNearestChangeRelativeTolerance * kNearestChangeMaxRadius_m;
  const std::optional<double> r =
      internal::ThinnestAdmissibleThickness(axis, options.thickness_scan_points, resolution, [&](double radius) {
        Scene s = scene;
        s.robot.radius_m = radius;
        return AdmissibleAt(s, m, thickness, ends, options);
      });
  if (r) {
    c.reachable = true;
    c.value = *r;
    c.note = "at " + Millimetres(thickness) + ", over its range";
  } else {
    c.note = "not reachable: no robot radius up to " + Millimetres(kNearestChangeMaxRadius_m) + " is admissible";
  }
  return c;
}

}  // namespace

std::string CurveScaleRange::Describe() const {
  if (!curve) return "its modulus as given (Hertz law; uncertainty not stated)";
  if (!stated) return "its curve as given (uncertainty not stated)";
  std::string text;
  if (stress_at_25_band_Pa) {
    text = "σ(25 %) band " + Kilopascals(stress_at_25_band_Pa->low) + "–" + Kilopascals(stress_at_25_band_Pa->high) +
           " kPa";
  }
  if (rate_factor) {
    text += (text.empty() ? "" : " × ") + std::string("rate factor ") + Factor(rate_factor->low) + "–" +
            Factor(rate_factor->high);
  }
  return text + " (curve scale " + Factor(low) + "–" + Factor(high) + ")";
}

CurveScaleRange CurveScaleRangeOf(const CompressiveCurve* curve, const std::optional<materials::Bounds>& band_Pa,
                                  const std::optional<materials::Bounds>& rate_factor) {
  CurveScaleRange r;
  if (curve == nullptr) return r;
  r.curve = true;
  if (band_Pa && curve->last_strain() >= materials::kRatingStrain) {
    r.stress_at_25_Pa = curve->StressAt(materials::kRatingStrain);
    r.stress_at_25_band_Pa = band_Pa;
    r.low *= band_Pa->low / r.stress_at_25_Pa;
    r.high *= band_Pa->high / r.stress_at_25_Pa;
    r.stated = true;
  }
  if (rate_factor) {
    r.rate_factor = rate_factor;
    r.low *= rate_factor->low;
    r.high *= rate_factor->high;
    r.stated = true;
  }
  return r;
}

CurveScaleRange CurveScaleRangeOf(const materials::Material& m) {
  return CurveScaleRangeOf(m.compressive_curve.get(), m.stress_at_25_band_Pa, m.rate_factor);
}

RangedMaterial RangedMaterialOf(const materials::Material& material, CoveringLaw law) {
  RangedMaterial r{material.name, materials::CoveringOf(material, 0.0), {},
                   CrushInputOf(material.crush_behaviour, material.compressive_strength_Pa.value_or(0.0))};
  r.covering.law = law;
  if (r.foam()) r.range = CurveScaleRangeOf(material);
  return r;
}

RangedMaterial RangedMaterialOf(const CandidateMaterial& c, CoveringLaw law) {
  RangedMaterial r{c.name,
                   CoveringSpec{.youngs_modulus_Pa = c.youngs_modulus_Pa,
                                .poisson_ratio = c.poisson_ratio,
                                .thickness_m = 0.0,
                                .compressive_curve = c.compressive_curve,
                                .law = law},
                   {},
                   CrushInputOf(c.crush_behaviour, c.compressive_strength_Pa)};
  if (r.foam()) r.range = CurveScaleRangeOf(c.compressive_curve.get(), c.stress_at_25_band_Pa, c.rate_factor);
  return r;
}

namespace {

/// `scene` covered by `m` at `thickness_m`, its curve scaled by `scale` (foam law).
Scene RangeScene(const Scene& scene, const RangedMaterial& m, double thickness_m, double scale) {
  if (ChooseOracle(scene, OracleChoice::kAuto).kind != OracleKind::kExact) {
    throw std::invalid_argument(
        "the default answer's range check needs the exact path (a scene without braking or a neck)");
  }
  Scene s = scene;
  s.covering = m.covering;
  s.covering.thickness_m = thickness_m;
  if (m.foam()) {
    s.covering.law = CoveringLaw::kFoam;
    if (scale != 1.0) {
      s.covering.compressive_curve =
          std::make_shared<const CompressiveCurve>(m.covering.compressive_curve->Scaled(scale));
    }
  }
  return s;
}

}  // namespace

RangeImpact RangeImpactAt(const Scene& scene, const RangedMaterial& m, double thickness_m, double scale,
                          bool accept_full_compression) {
  const ImpactModel model = ImpactModel::FromScene(RangeScene(scene, m, thickness_m, scale));
  RangeImpact impact{.peaks = ExactPeaks(model), .validity = {}};
  impact.validity = JudgedValidity(model, impact.peaks, accept_full_compression);
  return impact;
}

Verdict RangeVerdictAt(const Scene& scene, const RangedMaterial& m, double thickness_m, double scale,
                       const DesignOptions& options) {
  const RangeImpact impact =
      RangeImpactAt(scene, m, thickness_m, scale, /*accept_full_compression=*/!options.rule().compression_counts());
  // The one head verdict, with the law's validity counted.
  return HeadVerdict(impact.peaks, thickness_m > 0.0, options.limits, options.rule(), m.crush, scene.head.area,
                     &impact.validity);
}

std::vector<double> ScalesToJudge(const CurveScaleRange& range, const DesignRule& rule) {
  if (range.low == range.high) return {range.low};
  std::vector<double> scales{range.low};
  if (!rule.compression_counts()) {
    for (int k = 1; k <= kInteriorRangeScales; ++k) {
      scales.push_back(range.low * std::pow(range.high / range.low, static_cast<double>(k) / (kInteriorRangeScales + 1)));
    }
  }
  scales.push_back(range.high);
  return scales;
}

bool MaterialRangeCheck::admissible() const noexcept {
  return std::all_of(verdicts.begin(), verdicts.end(), [](const Verdict& v) { return v.safe(); });
}

std::size_t MaterialRangeCheck::worst_index() const noexcept {
  std::size_t worst = 0;
  for (std::size_t i = 1; i < verdicts.size(); ++i) {
    const Verdict& v = verdicts[i];
    const Verdict& w = verdicts[worst];
    if ((w.safe() && !v.safe()) || (w.safe() == v.safe() && v.governing_ratio() > w.governing_ratio())) worst = i;
  }
  return worst;
}

MaterialRangeCheck CheckOverRange(const Scene& scene, const RangedMaterial& m, double thickness_m,
                                  const DesignOptions& options) {
  MaterialRangeCheck c;
  c.thickness_m = thickness_m;
  c.range = m.range;
  c.scales = ScalesToJudge(m.range, options.rule());
  for (double s : c.scales) c.verdicts.push_back(RangeVerdictAt(scene, m, thickness_m, s, options));
  return c;
}

std::optional<double> ThinnestAtScales(const Scene& scene, const RangedMaterial& m, const DesignOptions& options,
                                       double max_thickness_m, std::span<const double> scales) {
  DesignSpace space = options.space;
  space.max_thickness_m = max_thickness_m;
  const auto admissible = [&](double b) { return AdmissibleAt(scene, m, b, scales, options); };
  std::optional<double> b =
      internal::ThinnestAdmissibleThickness(space, options.thickness_scan_points, options.thickness_resolution_m,
                                            admissible);
  if (b && options.thickness_step_m > 0.0) {
    std::optional<double> beyond_max;
    const std::optional<double> stock = internal::FirstAdmissibleStock(
        *b, options.thickness_step_m, max_thickness_m, [](double t) { return t; }, admissible, beyond_max);
    if (stock) b = *stock;  // else the exact thinnest (no stock thickness within the range)
  }
  return b;
}

std::optional<double> ThinnestOverRange(const Scene& scene, const RangedMaterial& m, const DesignOptions& options,
                                        double max_thickness_m) {
  const std::vector<double> ends = ScalesToJudge(m.range, options.rule());
  return ThinnestAtScales(scene, m, options, max_thickness_m, ends);
}

std::string NearestChanges::Describe() const {
  std::vector<std::string> parts;
  if (speed.reachable) parts.push_back("a robot speed of at most " + FormatSignificant(speed.value, 4) + " m/s");
  if (thickness.reachable) parts.push_back(Millimetres(thickness.value) + " of it (at the scene's speed)");
  if (radius.reachable) parts.push_back("a robot radius of " + Millimetres(radius.value));
  std::string text = "nearest changes for " + material + ": ";
  if (parts.empty()) return text + "none reachable (speed, thickness up to 300 mm, radius up to 500 mm)";
  for (std::size_t i = 0; i < parts.size(); ++i) text += (i == 0 ? "" : i + 1 == parts.size() ? ", or " : ", ") + parts[i];
  return text;
}

std::optional<NearestChanges> FindNearestChanges(const Scene& scene, std::span<const RangedMaterial> materials,
                                                 const DesignOptions& options, std::optional<double> thickness_m) {
  const double at = thickness_m.value_or(options.space.max_thickness_m);
  const RangedMaterial* best = nullptr;
  double best_ratio = std::numeric_limits<double>::infinity();
  for (const RangedMaterial& m : materials) {
    const double ratio = WorstRatio(CheckOverRange(scene, m, at, options),
                                    options.safety_factor);
    if (ratio < best_ratio) {
      best_ratio = ratio;
      best = &m;
    }
  }
  if (best == nullptr) return std::nullopt;
  NearestChanges n;
  n.material = best->name;
  n.at_thickness_m = at;
  n.worst_ratio_at_thickness = best_ratio;
  n.range = best->range;
  n.speed = NearestSpeed(scene, *best, options, at);
  n.thickness = NearestThickness(scene, *best, options);
  n.radius = NearestRadius(scene, *best, options, at);
  return n;
}

}  // namespace covopt::optim
