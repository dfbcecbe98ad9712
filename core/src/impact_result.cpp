// Verdicts, names and validity warnings shared by both computation paths.
#include "covopt/core/impact_result.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "covopt/core/exact.hpp"
#include "covopt/core/number_format.hpp"

namespace covopt {
namespace {

InjuryVerdict Judge(double value, double limit) noexcept {
  InjuryVerdict verdict;
  verdict.value = value;
  verdict.limit = limit;
  verdict.ratio = value / limit;
  verdict.safe = verdict.ratio <= 1.0;
  return verdict;
}

constexpr double kNearFullCompressionShare = 0.05;  // "within 5 % of full compression"

/// Three significant digits and a unit, e.g. "10.7 kN".
std::string Scaled(double value, double scale, const char* unit) {
  return FormatSignificant(value / scale, 3) + " " + unit;
}

std::string Millimetres(double metres) { return Scaled(metres, 1e-3, "mm"); }
std::string Force(double newtons) {
  return newtons >= 1e3 ? Scaled(newtons, 1e3, "kN") : Scaled(newtons, 1.0, "N");
}
std::string Stress(double pascals) { return Scaled(pascals, 1e6, "MPa"); }
std::string Modulus(double pascals) {
  return pascals >= 1e9 ? Scaled(pascals, 1e9, "GPa") : Scaled(pascals, 1e6, "MPa");
}
std::string Percent(double fraction) { return Scaled(fraction, 0.01, "%"); }

/// "peak force 10.7 kN, compressive stress 154 MPa (tensile 8.2 MPa), energy density 13.4 J/cm²".
std::string PeakSummary(const ImpactPeaks& peaks) {
  return "peak force " + Force(peaks.peak_force_N) + ", compressive stress " +
         Stress(peaks.max_compressive_stress_Pa) + " (tensile " +
         Stress(peaks.max_tensile_stress_Pa) +
         "), energy density " + Scaled(peaks.max_energy_density_J_per_m2, 1e4, "J/cm²");
}

/// The scene CheckValidity's comparisons run the exact path on: the scene itself, or for a
/// braking robot or a neck (which only the time path models, docs/model.md §10) its two-body
/// contact without them; `note` then says so in the message.
Scene ExactComparisonScene(const Scene& scene, std::string& note) {
  Scene comparison = scene;
  if (!scene.has_energy_integral()) {
    comparison.robot.reaction_delay_s = 0.0;
    comparison.robot.braking_m_per_s2 = 0.0;
    comparison.head.torso_mass_kg = 0.0;
    comparison.head.neck_stiffness_N_per_m = 0.0;
    comparison.head.neck_damping_N_s_per_m = 0.0;
    note = " (on the exact path, without the braking and the neck)";
  }
  return comparison;
}

}  // namespace

InjuryAssessment Assess(const ImpactPeaks& peaks, const InjuryLimits& limits, HeadArea area) noexcept {
  InjuryAssessment assessment;
  assessment.area = area;
  assessment.fracture = Judge(peaks.peak_force_N, FractureLimit(limits, area));
  assessment.laceration = Judge(peaks.max_tensile_stress_Pa, limits.laceration_tensile_stress_Pa);
  assessment.contusion =
      Judge(peaks.max_energy_density_J_per_m2, limits.contusion_energy_density_J_per_m2);
  return assessment;
}

std::string_view ToString(ComputationMethod method) noexcept {
  switch (method) {
    case ComputationMethod::kExact: return "exact";
    case ComputationMethod::kCvodeAdams: return "cvode-adams";
    case ComputationMethod::kCvodeBdf: return "cvode-bdf";
    case ComputationMethod::kArkodeErk32: return "arkode-erk32";
    case ComputationMethod::kArkodeErk54: return "arkode-erk54";
    case ComputationMethod::kArkodeErk65: return "arkode-erk65";
    case ComputationMethod::kArkodeErk87: return "arkode-erk87";
    case ComputationMethod::kArkodeSdirk43: return "arkode-sdirk43";
    case ComputationMethod::kArkodeEsdirk54: return "arkode-esdirk54";
  }
  return "unknown";
}

std::vector<ComputationMethod> TimeIntegrationMethods() {
  return {ComputationMethod::kCvodeAdams,    ComputationMethod::kCvodeBdf,
          ComputationMethod::kArkodeErk32,   ComputationMethod::kArkodeErk54,
          ComputationMethod::kArkodeErk65,   ComputationMethod::kArkodeErk87,
          ComputationMethod::kArkodeSdirk43, ComputationMethod::kArkodeEsdirk54};
}

std::optional<ComputationMethod> ParseComputationMethod(std::string_view name) noexcept {
  if (name == ToString(ComputationMethod::kExact)) return ComputationMethod::kExact;
  for (ComputationMethod method : TimeIntegrationMethods()) {
    if (name == ToString(method)) return method;
  }
  return std::nullopt;
}

std::string_view ToString(SolveStatus status) noexcept {
  switch (status) {
    case SolveStatus::kSuccess: return "success";
    case SolveStatus::kStepLimit: return "step-limit";
    case SolveStatus::kSolverFailure: return "solver-failure";
    case SolveStatus::kEventMissed: return "event-missed";
    case SolveStatus::kNoSeparation: return "no-separation";
  }
  return "unknown";
}

ImpactPeaks PeaksAtMaxPenetration(const ImpactModel& model, std::size_t segment,
                                  double max_penetration_m) noexcept {
  const ContactState state = model.StateInSegment(segment, max_penetration_m);
  double force = state.force_N;
  double stress = state.compressive_stress_Pa;
  // The ends of the segments passed: where the literal law can drop. With cumulative
  // thresholds each end equals the next segment's offset, which the value at δ_max adds a
  // non-negative term to, so std::max keeps the value at δ_max bit for bit.
  for (std::size_t j = 0; j < segment; ++j) {
    // Segment j ends where j + 1 starts; when j + 1's origin is there too, its offsets are
    // segment j's F and σ at that point, computed the same way (ImpactModel::FromScene).
    const ForceLawSegment& next = model.segment(j + 1);
    if (next.origin_m == next.start_m) {
      force = std::max(force, next.force_offset_N);
      stress = std::max(stress, next.stress_offset_Pa);
      continue;
    }
    const ContactState end = model.StateInSegment(j, model.segment(j).end_m);
    force = std::max(force, end.force_N);
    stress = std::max(stress, end.compressive_stress_Pa);
  }
  ImpactPeaks peaks;
  peaks.max_penetration_m = max_penetration_m;
  peaks.peak_force_N = force;
  peaks.max_compressive_stress_Pa = stress;
  peaks.max_tensile_stress_Pa = model.TensileFromCompressive(stress);
  if (model.is_foam()) {
    // The foam's σ_t is not proportional to its σ_c: the largest of its own at δ_max and at the
    // stop (where the load concentrates onto the bare robot's Hertz contact).
    peaks.max_tensile_stress_Pa = model.TensileStressInSegment(segment, max_penetration_m);
    if (segment > 0) {
      peaks.max_tensile_stress_Pa =
          std::max(peaks.max_tensile_stress_Pa, model.TensileStressInSegment(0, model.segment(0).end_m));
    }
  }
  peaks.max_energy_density_J_per_m2 = state.energy_density_J_per_m2;
  peaks.phase_at_max = model.segment(segment).phase;
  peaks.scalp_fully_compressed = segment > 0;
  peaks.fully_compressed = peaks.phase_at_max == Phase::kRobotOnBone;
  peaks.full_compression_penetration_m = model.segment(model.segment_count() - 1).start_m;
  peaks.covering_travel_start_m = model.has_covering() ? 0.0 : peaks.full_compression_penetration_m;
  for (std::size_t j = 0; j < model.segment_count(); ++j) {
    if (model.segment(j).phase == Phase::kCoveringOnBone) peaks.covering_travel_start_m = model.segment(j).start_m;
  }
  peaks.covering_law = model.covering_law();
  if (model.is_foam()) {
    // The layer's travel is its curve: from contact to the stop (docs/model.md §16).
    const double stop = model.foam_stop_penetration_m();
    peaks.scalp_fully_compressed = peaks.phase_at_max == Phase::kRobotOnBone;
    peaks.fully_compressed = segment > 0;
    peaks.full_compression_penetration_m = stop;
    peaks.covering_travel_start_m = 0.0;
    peaks.covering_strain_at_peak = std::min(max_penetration_m, stop) / model.scene().covering.thickness_m;
    if (segment > 0) peaks.energy_past_stop_J = state.potential_energy_J - model.segment(1).energy_at_start_J;
  } else if (model.has_covering()) {
    const double start = peaks.covering_travel_start_m, full = peaks.full_compression_penetration_m;
    peaks.covering_strain_at_peak =
        std::max(std::min(max_penetration_m, full) - start, 0.0) / model.scene().covering.thickness_m;
  }
  return peaks;
}

std::string_view ToString(ValidityCode code) noexcept {
  switch (code) {
    case ValidityCode::kHertzValidity: return "hertz-validity";
    case ValidityCode::kCoveringStifferThanScalp: return "covering-stiffer-than-scalp";
    case ValidityCode::kNearFullCompression: return "near-full-compression";
    case ValidityCode::kFullyCompressed: return "fully-compressed";
    case ValidityCode::kLiteralThresholds: return "literal-thresholds";
    case ValidityCode::kToleranceNotKept: return "tolerance-not-kept";
    case ValidityCode::kNoRestarts: return "no-restarts";
  }
  return "unknown";
}

void ImpactResult::AddWarning(ValidityCode code, std::string message) {
  warnings.push_back({code, std::move(message)});
}

std::vector<std::string> ImpactResult::WarningMessages() const {
  std::vector<std::string> messages;
  messages.reserve(warnings.size());
  for (const ValidityWarning& warning : warnings) messages.push_back(warning.message);
  return messages;
}

namespace {

using Warnings = std::vector<ValidityWarning>;

/// Per phase reached: its Hertz contact radius against the radii it presses on.
void WarnHertzValidity(const ImpactModel& model, const ImpactPeaks& peaks, Warnings& warnings) {
  const double delta_max = peaks.max_penetration_m;
  for (std::size_t i = 0; i < model.segment_count(); ++i) {
    const ForceLawSegment& seg = model.segment(i);
    if (!(delta_max > seg.start_m)) break;
    // Phase-local penetration reached in this contact, and its Hertz contact radius (the foam
    // law's a² = 2 R δ, R = 1/c the relative radius: docs/model.md §16).
    const double x = std::min(delta_max, seg.end_m) - seg.origin_m;
    const double contact_radius = std::sqrt((seg.curve ? 2.0 : 1.0) * x / seg.curvature_per_m);
    const double smallest_radius = std::min(seg.radius_a_m, seg.radius_b_m);
    if (contact_radius >= smallest_radius) {
      warnings.push_back(
          {ValidityCode::kHertzValidity,
           "outside Hertz validity: in phase " + std::to_string(PhaseNumber(seg.phase)) + " (" +
               std::string(ToString(seg.phase)) + ") the contact radius " +
               Millimetres(contact_radius) + " is not smaller than the radius " +
               Millimetres(smallest_radius) +
               " it presses on (paper footnote 7: eq. 4 needs non-sharp contact)"});
    }
  }
}

/// A covering stiffer than the scalp that gives a higher σ_c,max than a bare robot of radius
/// R_r + b_c (the same outer shape), compared on `comparison_scene`.
void WarnStifferCovering(const ImpactModel& model, const ImpactPeaks& peaks, const Scene& comparison_scene,
                         const std::string& comparison_note, Warnings& warnings) {
  const Scene& scene = model.scene();
  if (model.is_foam()) return;  // the foam law adds no Hertz pressures: its σ_c is the curve's
  if (!(model.has_covering() && scene.covering.youngs_modulus_Pa > scene.scalp.youngs_modulus_Pa)) return;
  // The same outer geometry without a covering: a bare robot of radius R_r + b_c.
  Scene bare_scene = comparison_scene;
  bare_scene.covering.thickness_m = 0.0;
  bare_scene.robot.radius_m = scene.robot.radius_m + scene.covering.thickness_m;  // ∞ stays ∞
  std::optional<ImpactPeaks> bare;
  try {
    bare = ExactPeaks(ImpactModel::FromScene(bare_scene));
  } catch (const std::invalid_argument&) {
    // R_r + b_c beyond the model's radius range: no comparison to make.
  }
  if (!(bare && peaks.max_compressive_stress_Pa > bare->max_compressive_stress_Pa)) return;
  const std::string radius = std::isinf(bare_scene.robot.radius_m)
                                 ? std::string("a flat bare robot")
                                 : "a bare robot of radius " + Millimetres(bare_scene.robot.radius_m) +
                                       " (R_r + b_c)";
  warnings.push_back(
      {ValidityCode::kCoveringStifferThanScalp,
       "covering stiffer than the scalp (E_c " + Modulus(scene.covering.youngs_modulus_Pa) + " > E_s " +
           Modulus(scene.scalp.youngs_modulus_Pa) + ") and worse than no covering: " +
           PeakSummary(peaks) + ", while " + radius +
           ", the same outer shape without the covering, gives " + PeakSummary(*bare) +
           comparison_note +
           "; the layered stress law adds phase-wise Hertz pressures and overstates the "
           "stress of a covering stiffer than the scalp (docs/model.md §5)"});
}

/// The foam law: a layer within 5 % of its curve's last strain, or used up (a rigid stop).
void WarnFoamCompression(const ImpactModel& model, const ImpactPeaks& peaks, Warnings& warnings) {
  const double last = model.scene().covering.compressive_curve->last_strain();
  const double strain = peaks.covering_strain_at_peak;
  if (!peaks.fully_compressed && strain >= (1.0 - kNearFullCompressionShare) * last) {
    warnings.push_back({ValidityCode::kNearFullCompression,
                        "the foam is within 5 % of its measured curve's end at the peak: strain " +
                            FormatSignificant(strain, 3) + " of its last " + FormatSignificant(last, 3) +
                            "; a little more impact energy uses the layer up (a rigid stop)"});
  }
  if (peaks.fully_compressed) {
    warnings.push_back({ValidityCode::kFullyCompressed, CoveringLawValidity(model, peaks).note});
  }
}

/// A covering within 5 % of full compression, or fully compressed.
void WarnCompression(const ImpactModel& model, const ImpactPeaks& peaks, Warnings& warnings) {
  if (!model.has_covering()) return;
  if (model.is_foam()) {
    WarnFoamCompression(model, peaks, warnings);
    return;
  }
  const double delta_max = peaks.max_penetration_m;
  if (peaks.phase_at_max == Phase::kCoveringOnBone) {
    const ForceLawSegment& seg = model.segment(model.SegmentIndexAt(delta_max));
    const double travel = seg.end_m - seg.start_m;  // t2 - t1
    if (delta_max >= seg.end_m - kNearFullCompressionShare * travel) {
      warnings.push_back(
          {ValidityCode::kNearFullCompression,
           "the covering is within 5 % of full compression at the peak: δ_max " + Millimetres(delta_max) +
               ", full compression at δ = " + Millimetres(seg.end_m) + " (the scalp's travel " +
               Millimetres(seg.start_m) + " plus the covering's " + Millimetres(travel) + "; " +
               Percent((delta_max - seg.start_m) / travel) +
               " of the covering's travel used); a little more impact energy bottoms it out and "
               "the robot reaches the bone"});
    }
  }
  if (peaks.fully_compressed) {
    warnings.push_back({ValidityCode::kFullyCompressed,
                        "the covering is fully compressed: the robot reaches the bone through it (phase 3); "
                        "the stresses then depend on the stiff robot-bone contact"});
  }
}

/// What the literal threshold reading changes against the default reading.
std::string LiteralThresholdsChange(const ImpactModel& model) {
  const Scene& scene = model.scene();
  const ModelConstants& constants = scene.model;
  const double t1 = constants.full_compression_fraction * scene.scalp.thickness_m;
  const double covering_travel = constants.full_compression_fraction * scene.covering.thickness_m;
  const ForceLawSegment& last = model.segment(model.segment_count() - 1);
  std::string what;
  if (!model.has_covering()) {
    what = "without a covering, phase 3 (robot on bone) takes over at 0.8 b_s = " + Millimetres(t1) +
           " with its law measured from δ = 0 (F = K_rb δ^n_rb)";
  } else if (last.origin_m == last.start_m) {
    what = "phase 3 (robot on bone) starts at 0.8 b_c = " + Millimetres(covering_travel) +
           " instead of 0.8 b_s + 0.8 b_c = " + Millimetres(t1 + covering_travel);
  } else {
    what = "0.8 b_c = " + Millimetres(covering_travel) + " is not beyond 0.8 b_s = " + Millimetres(t1) +
           ", so phase 2 vanishes and phase 3 (robot on bone) takes over at " + Millimetres(t1) +
           " with its law measured from " + Millimetres(covering_travel);
  }
  if (last.origin_m != last.start_m) {
    const ContactState below = model.StateInSegment(model.segment_count() - 2, last.start_m);
    const ContactState above = model.StateInSegment(model.segment_count() - 1, last.start_m);
    what += ": the force jumps there from " + Force(below.force_N) + " to " + Force(above.force_N);
  }
  return what;
}

/// The literal threshold reading: what it changes, the peaks against the default reading's
/// (on `comparison_scene`), and a drop of F or σ_c at a switch.
void WarnLiteralThresholds(const ImpactModel& model, const ImpactPeaks& peaks, const Scene& comparison_scene,
                           const std::string& comparison_note, Warnings& warnings) {
  if (model.scene().model.thresholds != ThresholdReading::kLiteral) return;
  Scene cumulative_scene = comparison_scene;
  cumulative_scene.model.thresholds = ThresholdReading::kCumulative;
  const ImpactPeaks cumulative = ExactPeaks(ImpactModel::FromScene(cumulative_scene));
  std::string message =
      "literal thresholds: the paper's eq. (2) read literally, not covopt's default "
      "cumulative reading (docs/model.md §4); " +
      LiteralThresholdsChange(model) + ". Peaks: " + PeakSummary(peaks) + "; the default reading gives " +
      PeakSummary(cumulative) + comparison_note;
  // A drop: the largest value over the contact lies at a switch before δ_max.
  const ContactState at_max = model.StateAt(peaks.max_penetration_m);
  if (peaks.peak_force_N > at_max.force_N) {
    message += ". The force dropped at a switch: F_max = " + Force(peaks.peak_force_N) +
               " is reached before δ_max, where F = " + Force(at_max.force_N);
  }
  if (peaks.max_compressive_stress_Pa > at_max.compressive_stress_Pa) {
    message += ". The stress dropped at a switch: σ_c,max = " + Stress(peaks.max_compressive_stress_Pa) +
               " is reached before δ_max, where σ_c = " + Stress(at_max.compressive_stress_Pa);
  }
  warnings.push_back({ValidityCode::kLiteralThresholds, std::move(message)});
}

}  // namespace

void ApplyHertzCoveringLimits(const HertzCoveringAtPeak& peak, CoveringValidity& validity) {
  validity.ratio_full_compression_allowed = 0.0;
  std::string limits;
  if (peak.poisson_ratio >= kSolidElastomerMinPoissonRatio) {
    const double strain_ratio = peak.strain / kSolidElastomerMaxStrain;
    const double max_radius_m = kSolidElastomerMaxContactRadiusPerThickness * peak.thickness_m;
    const double radius_ratio = peak.contact_radius_m / max_radius_m;
    validity.ratio_full_compression_allowed = std::max(strain_ratio, radius_ratio);
    const std::string strain = "peak strain " + FormatSignificant(peak.strain, 3);
    const std::string radius = "contact radius " + Millimetres(peak.contact_radius_m);
    const std::string thickness = "the layer's thickness " + Millimetres(peak.thickness_m);
    const std::string max_strain = FormatSignificant(kSolidElastomerMaxStrain, 3);
    limits = "; solid elastomer (ν " + FormatSignificant(peak.poisson_ratio, 3) + ") under the Hertz law: ";
    if (strain_ratio > 1.0) {
      limits += strain + " > " + max_strain +
                " (a bonded incompressible layer bulges; the half-space law does not describe it)";
    }
    if (radius_ratio > 1.0) {
      limits += std::string(strain_ratio > 1.0 ? ", and " : "") + radius + " > " + thickness +
                " (the half-space law needs a contact much smaller than the layer)";
    }
    if (!(strain_ratio > 1.0) && !(radius_ratio > 1.0)) {
      limits += "within its limits, " + strain + " <= " + max_strain + " and " + radius + " <= " + thickness;
    }
  }
  validity.ratio = std::max(peak.fully_compressed ? std::max(peak.travel_ratio, 1.0) : std::min(peak.travel_ratio, 1.0),
                            validity.ratio_full_compression_allowed);
  validity.within = !peak.fully_compressed && !(validity.ratio_full_compression_allowed > 1.0);
  validity.note += limits;
}

namespace {

/// The head's Hertz covering at `peaks`: its phase-2 (covering on bone) compression and
/// contact radius, √(x/c2) at the phase-local penetration x reached.
HertzCoveringAtPeak HeadHertzCovering(const ImpactModel& model, const ImpactPeaks& peaks) {
  HertzCoveringAtPeak peak;
  peak.poisson_ratio = model.scene().covering.poisson_ratio;
  peak.thickness_m = model.scene().covering.thickness_m;
  peak.strain = peaks.covering_strain_at_peak;
  peak.travel_ratio = peaks.covering_compression_ratio();
  peak.fully_compressed = peaks.fully_compressed;
  for (std::size_t i = 0; i < model.segment_count(); ++i) {
    const ForceLawSegment& seg = model.segment(i);
    if (seg.phase != Phase::kCoveringOnBone || !(peaks.max_penetration_m > seg.start_m)) continue;
    const double x = std::min(peaks.max_penetration_m, seg.end_m) - seg.origin_m;
    peak.contact_radius_m = std::sqrt(x / seg.curvature_per_m);
  }
  return peak;
}

}  // namespace

CoveringValidity CoveringLawValidity(const ImpactModel& model, const ImpactPeaks& peaks) {
  CoveringValidity validity;
  if (!model.has_covering()) {
    validity.note = "no covering";
    return validity;
  }
  // A used-up foam layer is modelled (a rigid stop, then the bare robot's chain): within the
  // law, as for a body region (§15.5); a fully compressed Hertz covering is beyond its law.
  const std::string strain = FormatSignificant(peaks.covering_strain_at_peak, 3);
  if (model.is_foam()) {
    const std::string last = FormatSignificant(model.scene().covering.compressive_curve->last_strain(), 3);
    if (!peaks.fully_compressed) {
      validity.note = "foam law: within the measured curve (strain " + strain + " of its last " + last + " at the peak)";
    } else {
      validity.note = "foam law: the layer is used up (strain " + last +
                      ", the curve's last point): a rigid stop; " +
                      FormatSignificant(peaks.energy_past_stop_J, 3) + " J of the " +
                      FormatSignificant(model.impact_energy_J(), 3) +
                      " J impact energy passed it into the scalp and skull";
    }
    return validity;
  }
  validity.note = !peaks.fully_compressed ? "hertz law: not fully compressed (" +
                                                Percent(peaks.covering_compression_ratio()) +
                                                " of the covering's travel used at the peak)"
                                          : "hertz law: fully compressed: the robot reaches the bone through the covering";
  ApplyHertzCoveringLimits(HeadHertzCovering(model, peaks), validity);
  return validity;
}

std::vector<ValidityWarning> CheckValidity(const ImpactModel& model, const ImpactPeaks& peaks) {
  Warnings warnings;
  std::string comparison_note;
  const Scene comparison_scene = ExactComparisonScene(model.scene(), comparison_note);
  WarnHertzValidity(model, peaks, warnings);
  WarnStifferCovering(model, peaks, comparison_scene, comparison_note, warnings);
  WarnCompression(model, peaks, warnings);
  WarnLiteralThresholds(model, peaks, comparison_scene, comparison_note, warnings);
  return warnings;
}

std::vector<std::string> ValidityWarnings(const ImpactModel& model, const ImpactPeaks& peaks) {
  std::vector<std::string> messages;
  for (ValidityWarning& warning : CheckValidity(model, peaks)) {
    messages.push_back(std::move(warning.message));
  }
  return messages;
}

double TensileStressOf(const ImpactModel& model, const HistorySample& sample) noexcept {
  if (!model.is_foam()) return model.TensileFromCompressive(sample.compressive_stress_Pa);
  return model.TensileStressInSegment(model.SegmentIndexAt(sample.penetration_m), sample.penetration_m);
}

}  // namespace covopt
