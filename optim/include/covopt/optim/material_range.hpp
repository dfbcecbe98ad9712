#pragma once
/// @file material_range.hpp
/// The default answer of `covopt optimize` (docs/guide/optimize.md, "The default answer"): a
/// recommended material must stay admissible over its stated uncertainty, and when no material
/// can, the answer names the nearest change that would make one work, computed.
///
/// The uncertainty of a material with a compressive curve is a factor on the curve's stresses:
///
///     s in [band_lo / σ25, band_hi / σ25] × [rate_lo, rate_hi]
///
/// (σ25 the curve's stress at 25 %, the band its grade's σ(25 %) band, the rate factor the range
/// its stresses may take at impact rates). A material that states neither is judged at s = 1
/// only, and the range says that its uncertainty is not stated. A material without a curve
/// (Hertz, or the request's law is hertz) is judged at s = 1, its own E.
///
/// The verdict over the range is the head's verdict (optim::HeadVerdict on the exact path,
/// under the design request's rule: injury, the covering's travel rule, crush, and whatever
/// else the one verdict counts) at the scales ScalesToJudge gives. Under the default rule (the
/// travel counts) these are the two ends: the share of the curve used falls with s, so a layer
/// within its curve at the low end is within it over the whole range, and there every injury
/// rises with s (a stiffer layer stops the head over less travel). Where the layer is used up
/// (s below the scale s* that just uses it), the stop passes the rest to the head and an injury
/// may peak inside the range; the travel rule fails there anyway, but under the paper's
/// criterion (travel not counted) the check also scans interior scales. tests/optim/
/// test_material_range.cpp checks the claims by brute force over 21 interior scales.
/// The worst of the verdicts is the range's.
///
/// Everything is a value; no printing, no shared state.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include <covopt/core/scene.hpp>
#include <covopt/core/verdict.hpp>
#include <covopt/materials/material.hpp>

#include "covopt/optim/covering_design.hpp"
#include "covopt/optim/oracle.hpp"
#include "covopt/optim/verdicts.hpp"

namespace covopt::optim {

/// The factor range on a curve's stresses [-].
struct CurveScaleRange {
  double low = 1.0;   ///< the lowest factor [-]
  double high = 1.0;  ///< the highest factor [-]
  /// The material is judged with its curve (the foam law); false: by its modulus (Hertz).
  bool curve = false;
  /// The material states a band or a rate factor (else the range is {1, 1}).
  bool stated = false;
  /// The grade's σ(25 %) band [Pa] and the curve's own σ(25 %) [Pa], when a band is given.
  std::optional<materials::Bounds> stress_at_25_band_Pa;
  double stress_at_25_Pa = 0.0;
  /// The rate factor range [-], when given.
  std::optional<materials::Bounds> rate_factor;
  /// "σ(25 %) band 34.5–62.1 kPa × rate factor 1–3 (curve scale 0.6–3.24)", "rate factor 1–4
  /// (curve scale 1–4)", "its curve as given (uncertainty not stated)", "its modulus as given
  /// (Hertz law; uncertainty not stated)".
  std::string Describe() const;
};

/// A material as the default answer judges it: its covering (E, ν, curve) at any thickness, the
/// range of its curve's scale, and its crush input.
struct RangedMaterial {
  std::string name;
  /// The covering without its thickness (materials::CoveringOf(material, 0)).
  CoveringSpec covering;
  CurveScaleRange range;
  CrushInput crush;
  /// The law the verdict takes: foam with a curve (unless the request says hertz), else Hertz.
  bool foam() const noexcept { return covering.compressive_curve != nullptr && covering.law != CoveringLaw::kHertz; }
};

/// CurveScaleRange of a material: from its band (over its curve's σ(25 %)) and rate factor.
CurveScaleRange CurveScaleRangeOf(const materials::Material& material);
/// The same from the parts (a curve, optional band [Pa] and rate factor [-]).
CurveScaleRange CurveScaleRangeOf(const CompressiveCurve* curve, const std::optional<materials::Bounds>& band_Pa,
                                  const std::optional<materials::Bounds>& rate_factor);

/// A catalog material as a RangedMaterial, judged under `law` (the request's covering law).
RangedMaterial RangedMaterialOf(const materials::Material& material, CoveringLaw law = CoveringLaw::kAuto);

/// A design candidate as a RangedMaterial (its curve, band and rate factor), under `law`.
RangedMaterial RangedMaterialOf(const CandidateMaterial& material, CoveringLaw law = CoveringLaw::kAuto);

/// One impact of `scene` covered by `material` at `thickness_m` with its curve scaled by
/// `scale` (foam law; the Hertz law without a curve), on the exact path: its peaks and the
/// covering's validity as a verdict counts it (JudgedValidity; Hertz full compression accepted
/// with `accept_full_compression`, the paper's criterion).
struct RangeImpact {
  ImpactPeaks peaks;
  CoveringValidity validity;
};
/// @throws std::invalid_argument for a scene the exact path cannot answer (braking, a neck).
RangeImpact RangeImpactAt(const Scene& scene, const RangedMaterial& material, double thickness_m, double scale,
                          bool accept_full_compression);

/// The verdict of one impact of `scene` covered by `material` at `thickness_m` with its curve
/// scaled by `scale`, under `options`' rule and limits (HeadVerdict on the exact path).
/// @throws std::invalid_argument for a scene the exact path cannot answer (braking, a neck).
Verdict RangeVerdictAt(const Scene& scene, const RangedMaterial& material, double thickness_m, double scale,
                       const DesignOptions& options);

/// How many interior scales the range check scans when the covering's travel does not count.
inline constexpr int kInteriorRangeScales = 21;

/// The scales a range is judged at, ascending: its two ends (one when they coincide). Under a
/// rule where the covering's travel does not count (the paper's criterion), also
/// kInteriorRangeScales interior scales, geometric: a layer used up at some scales passes the
/// rest of the energy to the head through the stop, and an injury can then peak inside the
/// range (at the scale where the layer is just used up), so the ends alone do not govern.
/// Under the default rule such scales fail the travel rule anyway, and within the curve every
/// injury rises with the scale: the ends govern.
std::vector<double> ScalesToJudge(const CurveScaleRange& range, const DesignRule& rule);

/// The verdict of a material at a thickness over its range.
struct MaterialRangeCheck {
  double thickness_m = 0.0;
  CurveScaleRange range;
  std::vector<double> scales;     ///< ScalesToJudge(range, rule), ascending
  std::vector<Verdict> verdicts;  ///< one per scale
  bool admissible() const noexcept;
  const Verdict& at_low() const noexcept { return verdicts.front(); }
  const Verdict& at_high() const noexcept { return verdicts.back(); }
  /// The verdict with the largest governing ratio (an unsafe one before a safe one; the lowest
  /// scale on a tie).
  std::size_t worst_index() const noexcept;
  const Verdict& worst() const noexcept { return verdicts[worst_index()]; }
  double worst_scale() const noexcept { return scales[worst_index()]; }
  /// The worst verdict's margin (1 − SF × its governing ratio) [-].
  double worst_margin() const noexcept { return worst().margin(); }
};
MaterialRangeCheck CheckOverRange(const Scene& scene, const RangedMaterial& material, double thickness_m,
                                  const DesignOptions& options);

/// The thinnest thickness [m] in [options.space.min_thickness_m, max_thickness_m] admissible at
/// both ends of the range (`scales`, default the material's), by the catalog snap's scan and
/// bisection to options.thickness_resolution_m, rounded up to options.thickness_step_m where a
/// rounded thickness is admissible within the maximum. Empty when none is.
std::optional<double> ThinnestOverRange(const Scene& scene, const RangedMaterial& material,
                                        const DesignOptions& options, double max_thickness_m);
std::optional<double> ThinnestAtScales(const Scene& scene, const RangedMaterial& material,
                                       const DesignOptions& options, double max_thickness_m,
                                       std::span<const double> scales);

/// The largest thickness the nearest-change search considers [m], and radius [m].
inline constexpr double kNearestChangeMaxThickness_m = 0.3;
inline constexpr double kNearestChangeMaxRadius_m = 0.5;
/// The relative resolution of the nearest speed and radius, and the thickness's [m].
inline constexpr double kNearestChangeRelativeTolerance = 1e-10;

/// One nearest change: the value that would make the best candidate admissible, or not reachable.
struct NearestChange {
  bool reachable = false;
  double value = 0.0;  ///< [m/s] or [m]; 0 when not reachable
  /// Why not, or what it is ("at 50.00 mm, over its range"), one sentence.
  std::string note;
};

/// What would make a material work when none does.
struct NearestChanges {
  /// The best candidate: the one whose worst governing ratio over its range at the thickness
  /// (`at_thickness_m`) is least (a material refused for an unknown strength is not a candidate).
  std::string material;
  /// The thickness the speed and radius changes keep [m]: the design's maximum (problem a) or
  /// its given thickness (problem b).
  double at_thickness_m = 0.0;
  /// The worst governing ratio (SF applied) at that thickness over its range [-].
  double worst_ratio_at_thickness = 0.0;
  CurveScaleRange range;
  /// The highest robot speed [m/s] at which it is admissible at that thickness over its range
  /// (every lower speed too), to 1e-10 relative.
  NearestChange speed;
  /// The thinnest thickness [m] up to kNearestChangeMaxThickness_m admissible at the scene's
  /// speed over its range, to options.thickness_resolution_m (rounded up to the stock step
  /// where that holds).
  NearestChange thickness;
  /// The smallest robot radius [m], from the scene's up to kNearestChangeMaxRadius_m, at which
  /// it is admissible at that thickness over its range, to 1e-10 × 0.5 m.
  NearestChange radius;
  /// "nearest changes for X: a robot speed of at most 0.61 m/s, or 62.50 mm of it (at the
  /// scene's speed), or a robot radius of 48.00 mm".
  std::string Describe() const;
};

/// The nearest changes for the best of `materials` in `scene` under `options`, the speed and
/// radius at `thickness_m` (default: options.space.max_thickness_m). Empty when `materials`
/// has no candidate (every one refused for an unknown strength, or none given).
std::optional<NearestChanges> FindNearestChanges(const Scene& scene, std::span<const RangedMaterial> materials,
                                                 const DesignOptions& options,
                                                 std::optional<double> thickness_m = std::nullopt);

}  // namespace covopt::optim
