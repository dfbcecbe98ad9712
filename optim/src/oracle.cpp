// The design oracles (oracle.hpp): the exact path and the time path behind one interface,
// and the rule choosing between them.
#include "covopt/optim/oracle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include <covopt/core/exact.hpp>
#include <covopt/core/impact_model.hpp>
#include <covopt/core/number_format.hpp>
#include <covopt/core/physical_floors.hpp>
#include <covopt/core/sensitivity.hpp>
#include <covopt/core/time_path_sensitivity.hpp>

namespace covopt::optim {
namespace {

constexpr double kLn10 = std::numbers::ln10;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// A design value as typed back to reproduce a failure (17 digits: reads back exactly).
std::string Exactly(double value) { return FormatSignificant(value, 17); }

/// Why a scene has only the time path ("" when it has an energy integral,
/// Scene::has_energy_integral(): the conservative two-mass impact, or a damped two-mass
/// contact, which keeps an energy relation, docs/model.md §10.1).
std::string WhyNoEnergyIntegral(const Scene& scene) {
  if (scene.has_energy_integral()) return "";
  const bool brakes = scene.robot_brakes(), neck = scene.head.has_neck();
  if (brakes && neck) return "the robot brakes (an external force) and the head hangs on a neck (three bodies)";
  if (brakes) return "the robot brakes (an external force)";
  return "the head hangs on a neck (three bodies)";
}

/// The gradient a kind of oracle gives on a scene.
GradientSource GradientFor(OracleKind kind, const Scene& scene) {
  if (kind == OracleKind::kExact) {
    return scene.is_damped() ? GradientSource::kCentralDifference : GradientSource::kAnalytic;
  }
  return scene.has_energy_integral() ? GradientSource::kForwardSensitivities : GradientSource::kCentralDifference;
}

/// The ratio gradient from peak derivatives (per E_c [1/Pa], per b_c [1/m]).
void FillGradient(const DesignScore& score, const PeakSensitivities& s, const InjuryLimits& limits,
                  double fracture_force_N, double compression_per_thickness, RatioGradient& gradient) {
  const double per_log10 = score.design.youngs_modulus_Pa * kLn10;  // dE/du, u = log10 E
  const double laceration = limits.laceration_tensile_stress_Pa;
  const double contusion = limits.contusion_energy_density_J_per_m2;
  gradient.laceration[0] = s.per_covering_modulus.max_tensile_stress * per_log10 / laceration;
  gradient.laceration[1] = s.per_covering_thickness.max_tensile_stress / laceration;
  gradient.contusion[0] = s.per_covering_modulus.max_energy_density * per_log10 / contusion;
  gradient.contusion[1] = s.per_covering_thickness.max_energy_density / contusion;
  gradient.fracture[0] = s.per_covering_modulus.peak_force * per_log10 / fracture_force_N;
  gradient.fracture[1] = s.per_covering_thickness.peak_force / fracture_force_N;
  // r = (δ_max − s) / (t2 − s): E_c moves neither t2 nor s; 0 (flat) while δ_max <= s.
  const double travel = score.peaks.full_compression_penetration_m - score.peaks.covering_travel_start_m;
  gradient.compression[0] =
      score.compression_ratio > 0.0 ? s.per_covering_modulus.max_penetration * per_log10 / travel : 0.0;
  gradient.compression[1] = compression_per_thickness;
}

/// Differences of the three ratios in ln E_c and ln b_c from the points at ±h and ±2h
/// (relative steps), converted to a gradient in log10 E_c and b_c. Where every point has
/// δ_max in the same phase as the centre: the central difference with step h, and the largest
/// relative disagreement with step 2h's as its error check. Where one side crosses a phase
/// switch (the ratios have a kink there: σ_c's slope, e's curvature change at t1, t2), the
/// second-order one-sided difference from the other side, (∓3 f0 ± 4 f(±h) ∓ f(±2h)) / 2h,
/// which is the derivative of the centre's own phase, as the analytic gradient is. False
/// when an evaluation failed.
template <class ScoreAt>
bool CentralDifference(const ScoreAt& score_at, const DesignScore& centre, double h, RatioGradient& gradient,
                       double& disagreement) {
  const CoveringDesign& d = centre.design;
  const std::array<double, 4> f0 = {centre.laceration_ratio, centre.contusion_ratio, centre.compression_ratio,
                                    centre.fracture_ratio};
  disagreement = 0.0;
  for (int p = 0; p < 2; ++p) {
    // The points stay within the scene's range: at the floor (physical_floors.hpp: 1 kPa, 0.1 mm,
    // where the design spaces begin) the forward difference alone, at the top the backward one.
    const double value = p == 0 ? d.youngs_modulus_Pa : d.thickness_m;
    const bool down_ok = value * std::exp(-2 * h) >= (p == 0 ? kMinModulus_Pa : kMinLayerThickness_m);
    const bool up_ok = value * std::exp(2 * h) <= (p == 0 ? 1e13 : 1.0);
    std::array<DesignScore, 4> at;  // +h, -h, +2h, -2h
    const std::array<double, 4> steps = {h, -h, 2 * h, -2 * h};
    for (std::size_t k = 0; k < 4; ++k) {
      if ((steps[k] < 0 && !down_ok) || (steps[k] > 0 && !up_ok)) continue;
      CoveringDesign shifted = d;
      (p == 0 ? shifted.youngs_modulus_Pa : shifted.thickness_m) *= std::exp(steps[k]);
      at[k] = score_at(shifted);
      if (at[k].failed) return false;
    }
    auto ratios = [](const DesignScore& s) {
      return std::array<double, 4>{s.laceration_ratio, s.contusion_ratio, s.compression_ratio, s.fracture_ratio};
    };
    const auto same_phase = [&](std::size_t k) { return at[k].peaks.phase_at_max == centre.peaks.phase_at_max; };
    const std::array<double, 4> up = ratios(at[0]), down = ratios(at[1]), up2 = ratios(at[2]), down2 = ratios(at[3]);
    std::array<double, 4> slope{};  // d ratio / d ln θ
    const bool forward = up_ok && (!down_ok || (same_phase(0) && same_phase(2)));
    const bool backward = down_ok && (!up_ok || (same_phase(1) && same_phase(3)));
    for (std::size_t r = 0; r < slope.size(); ++r) {
      if (forward == backward) {  // smooth on both sides (or kinked on both: central regardless)
        slope[r] = (up[r] - down[r]) / (2 * h);
        const double wide = (up2[r] - down2[r]) / (4 * h);
        const double scale = std::max(std::abs(slope[r]), 1e-2 * std::abs(f0[r]));
        if (scale > 0.0) disagreement = std::max(disagreement, std::abs(slope[r] - wide) / scale);
      } else if (forward) {
        slope[r] = (-3 * f0[r] + 4 * up[r] - up2[r]) / (2 * h);
      } else {
        slope[r] = (3 * f0[r] - 4 * down[r] + down2[r]) / (2 * h);
      }
    }
    // d/d log10 E = ln 10 d/d ln E;  d/db = (1/b) d/d ln b.
    const double to_parameter = p == 0 ? kLn10 : 1.0 / d.thickness_m;
    gradient.laceration[p] = slope[0] * to_parameter;
    gradient.contusion[p] = slope[1] * to_parameter;
    gradient.compression[p] = slope[2] * to_parameter;
    gradient.fracture[p] = slope[3] * to_parameter;
  }
  return true;
}

/// The central difference's step [-] for values accurate to about `accuracy` (relative): the
/// cube root balances truncation (h²) against the values' error (accuracy / h).
double DifferenceStepFor(double accuracy) { return std::clamp(std::cbrt(accuracy), 1e-5, 0.05); }

/// The relative accuracy of the time path's peaks at rtol (their global error stays within
/// a few times rtol on the measured scenes, docs/numerics.md).
double TimePathAccuracy(double rtol) { return 10.0 * rtol; }

/// The accuracy of the exact path's damped peaks (a quadrature for e_A).
constexpr double kExactDampedAccuracy = 1e-12;

}  // namespace

std::string_view ToString(DesignCriterion criterion) noexcept {
  switch (criterion) {
    case DesignCriterion::kNoFullCompression: return "no-full-compression";
    case DesignCriterion::kPaper: return "paper";
  }
  return "unknown";
}

std::string_view ToString(LimitingCriterion criterion) noexcept {
  switch (criterion) {
    case LimitingCriterion::kNone: return "none";
    case LimitingCriterion::kLaceration: return "laceration";
    case LimitingCriterion::kContusion: return "contusion";
    case LimitingCriterion::kFullCompression: return "full-compression";
    case LimitingCriterion::kCrush: return "crush";
    case LimitingCriterion::kFracture: return "fracture";
    case LimitingCriterion::kLawValidity: return "law-validity";
  }
  return "unknown";
}

std::string_view ToString(LimitingCriterion criterion, CoveringLaw law) noexcept {
  if (criterion == LimitingCriterion::kFullCompression && law == CoveringLaw::kFoam) return "within-curve";
  return ToString(criterion);
}

std::string_view ToString(CrushCheck check) noexcept {
  switch (check) {
    case CrushCheck::kNoMaterial: return "no-material";
    case CrushCheck::kChecked: return "checked";
    case CrushCheck::kDoesNotCrush: return "does-not-crush";
    case CrushCheck::kUnknownStrength: return "unknown-strength";
  }
  return "unknown";
}

std::vector<std::string> DesignRule::Parts() const {
  std::vector<std::string> parts = {std::string(ToString(LimitingCriterion::kLaceration)),
                                    std::string(ToString(LimitingCriterion::kContusion)),
                                    std::string(ToString(LimitingCriterion::kFracture))};
  if (compression_counts()) parts.emplace_back(ToString(LimitingCriterion::kFullCompression));
  if (!crushing_allowed) parts.emplace_back(ToString(LimitingCriterion::kCrush));
  parts.emplace_back(ToString(LimitingCriterion::kLawValidity));  // counted always
  return parts;
}

std::string DesignRule::Describe() const {
  std::string text =
      "no laceration and no contusion (Park et al. 2011's skin limits), no fracture (the peak force within the "
      "struck area's lowest published fracture force)";
  if (compression_counts()) text += ", the covering not fully compressed";
  text += crushing_allowed ? "; crushing allowed (a sacrificial liner)" : ", the covering not crushed";
  if (!crushing_allowed && unknown_strength_allowed) text += " where its strength is known";
  text += ", the covering within its law's validity (\"law-validity\", without the safety factor)";
  text += "; safety factor " + FormatSignificant(safety_factor) + " on each";
  if (compression_counts()) {
    text += " (design rule \"full-compression\" under the Hertz law; \"within-curve\" under the foam law: the layer "
            "within its measured curve, SF as a strain reserve)";
  }
  return text;
}

std::vector<std::string> HeadVerdictScope(const DesignRule& rule) {
  return {"Criteria: " + rule.Describe() + ".",
          "ISO/TS 15066:2016 (Annex A, A.3.2) does not permit transient contact with the skull, forehead or face; "
          "its quasi-static limits there (Table A.2) are 130 N and 130 N/cm² on the forehead (110 N/cm² on the "
          "temple) and 65 N and 110 N/cm² on the face. A safe verdict here means no skin injury in Park et al.'s "
          "model and a peak force below the struck bone's lowest published fracture force, not compliance with the "
          "standard."};
}

GoverningRatio DesignScore::governing(const DesignRule& rule) const noexcept {
  GoverningRatio g{LimitingCriterion::kLaceration, laceration_ratio};
  auto consider = [&g](double ratio, LimitingCriterion criterion) {
    if (ratio > g.ratio) g = {criterion, ratio};
  };
  consider(contusion_ratio, LimitingCriterion::kContusion);
  consider(fracture_ratio, LimitingCriterion::kFracture);
  if (rule.compression_counts() && !bare()) consider(compression_ratio, LimitingCriterion::kFullCompression);
  if (!rule.crushing_allowed && crush_check == CrushCheck::kChecked) consider(crush_ratio, LimitingCriterion::kCrush);
  if (!bare()) consider(validity_ratio(rule) / rule.safety_factor, LimitingCriterion::kLawValidity);
  return g;
}

CoveringValidity DesignScore::judged_validity(const DesignRule& rule) const {
  CoveringValidity judged = validity;
  if (bare() || !full_compression_accepted(rule)) return judged;
  judged.ratio = validity.ratio_full_compression_allowed;
  judged.within = !validity_fails(rule);
  if (peaks.fully_compressed && judged.within) {
    judged.note = std::string(kFullCompressionAcceptedNote) + judged.note;
  }
  return judged;
}

bool DesignScore::admissible(const DesignRule& rule) const noexcept {
  if (failed) return false;
  if (rule.compression_counts() && compression_exceeded(rule.safety_factor)) return false;
  if (validity_fails(rule)) return false;
  if (crush_check == CrushCheck::kUnknownStrength && rule.refuses_unknown_strength()) {
    return false;
  }
  return rule.safety_factor * governing(rule).ratio <= 1.0;
}

std::optional<OracleChoice> ParseOracleChoice(std::string_view name) noexcept {
  for (const OracleChoice c : {OracleChoice::kAuto, OracleChoice::kExact, OracleChoice::kTimePath}) {
    if (name == ToString(c)) return c;
  }
  return std::nullopt;
}

std::string_view ToString(OracleKind kind) noexcept {
  switch (kind) {
    case OracleKind::kExact: return "exact";
    case OracleKind::kTimePath: return "time-path";
  }
  return "unknown";
}

std::string_view ToString(GradientSource source) noexcept {
  switch (source) {
    case GradientSource::kAnalytic: return "analytic";
    case GradientSource::kForwardSensitivities: return "cvodes-forward-sensitivities";
    case GradientSource::kCentralDifference: return "central-difference";
  }
  return "unknown";
}

OracleSelection ChooseOracle(const Scene& scene, OracleChoice choice) {
  const std::string why_not = WhyNoEnergyIntegral(scene);
  OracleSelection s;
  switch (choice) {
    case OracleChoice::kAuto:
      if (scene.has_energy_integral()) {
        s.kind = OracleKind::kExact;
        s.reason = scene.is_damped()
                       ? "auto: the damped two-mass contact keeps an energy relation, the exact path answers every peak"
                       : "auto: the conservative two-mass impact has an energy integral, the exact path answers "
                         "every peak";
      } else {
        s.kind = OracleKind::kTimePath;
        s.reason = "auto: " + why_not + ", no energy integral: only the time path answers";
      }
      break;
    case OracleChoice::kExact:
      if (!scene.has_energy_integral()) {
        throw std::invalid_argument("oracle exact: the exact path needs an energy integral; " + why_not +
                                    ", so this scene has only the time path; choose auto or time-path");
      }
      s.kind = OracleKind::kExact;
      s.reason = "exact: as asked";
      break;
    case OracleChoice::kTimePath:
      s.kind = OracleKind::kTimePath;
      s.reason = "time-path: as asked";
      break;
  }
  s.gradient = GradientFor(s.kind, scene);
  return s;
}

std::string OracleReport::Name() const {
  if (kind == OracleKind::kExact) return "exact path";
  return "time path (" + std::string(covopt::ToString(method)) + ", rtol " + FormatScientific(relative_tolerance, 0) +
         ")";
}

// --- DesignOracle ----------------------------------------------------------------------

DesignOracle::DesignOracle(const Scene& scene, double covering_poisson_ratio, const InjuryLimits& limits,
                           OracleSelection selection, const TimeIntegrationOptions* time_path)
    : scene_(scene), limits_(limits), selection_(std::move(selection)) {
  scene_.covering.poisson_ratio = covering_poisson_ratio;
  // The scene's own covering is what is designed: its curve and law are not the designs'
  // (a material brings its own through ScoreCovering; a design (E_c, b_c) is a Hertz layer).
  scene_.covering.compressive_curve = nullptr;
  scene_.covering.law = CoveringLaw::kAuto;
  Scene bare = scene_;
  bare.covering.thickness_m = 0.0;
  (void)ImpactModel::FromScene(bare);  // validates everything but the design
  CheckInjuryLimits(limits);
  if (time_path) {
    method_ = time_path->method;
    relative_tolerance_ = time_path->relative_tolerance;
  }
}

OracleReport DesignOracle::Report() const {
  OracleReport r;
  r.kind = selection_.kind;
  r.reason = selection_.reason;
  r.method = method_;
  r.relative_tolerance = relative_tolerance_;
  r.gradient = selection_.gradient;
  r.evaluations = evaluations_.load();
  r.gradient_evaluations = gradient_evaluations_.load();
  r.failed_evaluations = failed_evaluations_.load();
  const std::lock_guard<std::mutex> lock(failure_mutex_);
  r.first_failure = first_failure_;
  r.gradient_step_disagreement = gradient_step_disagreement_;
  return r;
}

void DesignOracle::Judge(DesignScore& score) const {
  const InjuryAssessment a = Assess(score.peaks, limits_, scene_.head.area);
  score.laceration_ratio = a.laceration.ratio;
  score.contusion_ratio = a.contusion.ratio;
  score.fracture_ratio = a.fracture.ratio;
  score.compression_ratio = score.bare() ? 0.0 : score.peaks.covering_compression_ratio();
}

void DesignOracle::Fail(DesignScore& score, const std::string& message) const {
  ++failed_evaluations_;
  score.failed = true;
  score.laceration_ratio = score.contusion_ratio = score.compression_ratio = score.fracture_ratio = kInfinity;
  score.peaks.fully_compressed = true;  // inadmissible under either criterion, on every side of a bisection
  const std::lock_guard<std::mutex> lock(failure_mutex_);
  if (first_failure_.empty()) first_failure_ = message;
}

void DesignOracle::NoteDisagreement(double relative) const {
  const std::lock_guard<std::mutex> lock(failure_mutex_);
  gradient_step_disagreement_ = std::max(gradient_step_disagreement_, relative);
}

DesignScore DesignOracle::ScoreMaterial(const CoveringDesign& design, double poisson_ratio) const {
  return ScoreCovering(CoveringSpec{.youngs_modulus_Pa = design.youngs_modulus_Pa,
                                    .poisson_ratio = poisson_ratio,
                                    .thickness_m = design.thickness_m});
}

Scene DesignOracle::WithCovering(const CoveringDesign& design, double poisson_ratio) const {
  Scene scene = scene_;
  scene.covering = {design.youngs_modulus_Pa, poisson_ratio, design.thickness_m};
  return scene;
}

double DesignOracle::CompressionThicknessDerivative(const DesignScore& score, double max_penetration_per_m) const {
  // compression ratio (δ_max − s) / (t2 − s): t2 moves with b_c by the full-compression
  // fraction f (cumulative: t2 = t1 + f b_c; literal: t2 = max(f b_c, t1)); s = t1 (or 0)
  // does not move. 0 (flat) while δ_max <= s.
  const ModelConstants& constants = scene_.model;
  const double t1 = constants.full_compression_fraction * scene_.scalp.thickness_m;
  const double covering_travel = constants.full_compression_fraction * score.design.thickness_m;
  const double dt2_db = (constants.thresholds == ThresholdReading::kCumulative || covering_travel > t1)
                            ? constants.full_compression_fraction
                            : 0.0;
  if (!(score.compression_ratio > 0.0)) return 0.0;
  const double travel = score.peaks.full_compression_penetration_m - score.peaks.covering_travel_start_m;
  return (max_penetration_per_m - score.compression_ratio * dt2_db) / travel;
}

// --- ExactPathOracle -------------------------------------------------------------------

ExactPathOracle::ExactPathOracle(const Scene& scene, double covering_poisson_ratio, const InjuryLimits& limits,
                                 std::string reason)
    : DesignOracle(scene, covering_poisson_ratio, limits, ChooseOracle(scene, OracleChoice::kExact), nullptr) {
  selection_.reason = std::move(reason);
}

DesignScore ExactPathOracle::ScoreCovering(const CoveringSpec& covering) const {
  ++evaluations_;
  DesignScore score;
  score.design = {covering.youngs_modulus_Pa, covering.thickness_m};
  score.poisson_ratio = covering.poisson_ratio;
  Scene scene = scene_;
  scene.covering = covering;
  const ImpactModel model = ImpactModel::FromScene(scene);
  score.peaks = ExactPeaks(model);
  Judge(score);
  score.validity = CoveringLawValidity(model, score.peaks);
  return score;
}

DesignScore ExactPathOracle::Score(const CoveringDesign& design) const {
  return ScoreMaterial(design, scene_.covering.poisson_ratio);
}

DesignScore ExactPathOracle::Score(const CoveringDesign& design, RatioGradient& gradient) const {
  ++gradient_evaluations_;
  if (selection_.gradient == GradientSource::kCentralDifference) {
    const DesignScore score = Score(design);
    double disagreement = 0.0;
    CentralDifference([this](const CoveringDesign& d) { return Score(d); }, score,
                      DifferenceStepFor(kExactDampedAccuracy), gradient, disagreement);
    NoteDisagreement(disagreement);
    return score;
  }
  ++evaluations_;
  const Scene scene = WithCovering(design, scene_.covering.poisson_ratio);
  const ImpactModel model = ImpactModel::FromScene(scene);
  DesignScore score;
  score.design = design;
  score.poisson_ratio = scene.covering.poisson_ratio;
  score.peaks = ExactPeaks(model);
  Judge(score);
  score.validity = CoveringLawValidity(model, score.peaks);
  const PeakSensitivities s = ExactPeakSensitivities(model, score.peaks);
  FillGradient(score, s, limits_, FractureLimit(limits_, scene_.head.area),
               CompressionThicknessDerivative(score, s.per_covering_thickness.max_penetration), gradient);
  return score;
}

DesignScore ExactPathOracle::ScoreBare() const {
  ++evaluations_;
  Scene scene = scene_;
  scene.covering.thickness_m = 0.0;
  DesignScore score;
  score.design.thickness_m = 0.0;
  score.peaks = ExactPeaks(ImpactModel::FromScene(scene));
  Judge(score);
  return score;
}

// --- TimePathOracle --------------------------------------------------------------------

TimePathOracle::TimePathOracle(const Scene& scene, double covering_poisson_ratio, const InjuryLimits& limits,
                               const TimeIntegrationOptions& time_path, std::string reason)
    : DesignOracle(scene, covering_poisson_ratio, limits,
                   OracleSelection{OracleKind::kTimePath, std::move(reason), GradientFor(OracleKind::kTimePath, scene)},
                   &time_path),
      time_path_(time_path) {
  ValidateTimeIntegrationOptions(time_path, "oracle.time_path.");
  time_path_.record_history = false;
}

double TimePathOracle::DifferenceStep() const noexcept {
  const double step = DifferenceStepFor(TimePathAccuracy(time_path_.relative_tolerance));
  // Differences of differences: a wider step where the gradient is a difference itself.
  return selection_.gradient == GradientSource::kCentralDifference ? std::min(0.05, 4.0 * step) : step;
}

DesignScore TimePathOracle::Simulate(const CoveringSpec& covering) const {
  ++evaluations_;
  DesignScore score;
  score.design = {covering.youngs_modulus_Pa, covering.thickness_m};
  score.poisson_ratio = covering.poisson_ratio;
  Scene scene = scene_;
  if (covering.thickness_m > 0.0) {
    scene.covering = covering;
  } else {
    scene.covering.thickness_m = 0.0;  // the bare robot
  }
  const ImpactModel model = ImpactModel::FromScene(scene);
  const ImpactResult result = SimulateImpact(model, time_path_);
  if (!result.ok()) {
    Fail(score, "time path at E_c " + Exactly(covering.youngs_modulus_Pa) + " Pa, b_c " +
                    Exactly(covering.thickness_m) + " m: " + std::string(covopt::ToString(result.status)) + ": " +
                    result.message);
    return score;
  }
  score.peaks = result.peaks;
  Judge(score);
  score.validity = CoveringLawValidity(model, score.peaks);
  return score;
}

DesignScore TimePathOracle::ScoreCovering(const CoveringSpec& covering) const { return Simulate(covering); }

DesignScore TimePathOracle::Score(const CoveringDesign& design) const {
  return ScoreMaterial(design, scene_.covering.poisson_ratio);
}

DesignScore TimePathOracle::Score(const CoveringDesign& design, RatioGradient& gradient) const {
  DesignScore score = ScoreMaterial(design, scene_.covering.poisson_ratio);
  if (score.failed) return score;
  ++gradient_evaluations_;
  if (selection_.gradient == GradientSource::kCentralDifference) {
    double disagreement = 0.0;
    const bool ok = CentralDifference([this](const CoveringDesign& d) { return Score(d); }, score,
                                      DifferenceStepFor(TimePathAccuracy(time_path_.relative_tolerance)), gradient,
                                      disagreement);
    if (!ok) {
      Fail(score, "time path: a central-difference neighbour failed");
      return score;
    }
    NoteDisagreement(disagreement);
    return score;
  }
  const ImpactModel model = ImpactModel::FromScene(WithCovering(design, scene_.covering.poisson_ratio));
  const TimePathSensitivities s = TimePathPeakSensitivities(model, time_path_);
  if (!s.ok()) {
    Fail(score, "forward sensitivities at E_c " + Exactly(design.youngs_modulus_Pa) + " Pa, b_c " +
                    Exactly(design.thickness_m) + " m: " + std::string(covopt::ToString(s.status)) + ": " + s.message);
    return score;
  }
  FillGradient(score, s.sensitivities, limits_, FractureLimit(limits_, scene_.head.area),
               CompressionThicknessDerivative(score, s.sensitivities.per_covering_thickness.max_penetration),
               gradient);
  return score;
}

DesignScore TimePathOracle::ScoreBare() const {
  return Simulate(CoveringSpec{.youngs_modulus_Pa = 0.0, .poisson_ratio = scene_.covering.poisson_ratio,
                               .thickness_m = 0.0});
}

std::unique_ptr<DesignOracle> MakeOracle(const Scene& scene, double covering_poisson_ratio,
                                         const InjuryLimits& limits, const OracleOptions& options) {
  const OracleSelection selection = ChooseOracle(scene, options.choice);
  if (selection.kind == OracleKind::kExact) {
    return std::make_unique<ExactPathOracle>(scene, covering_poisson_ratio, limits, selection.reason);
  }
  return std::make_unique<TimePathOracle>(scene, covering_poisson_ratio, limits, options.time_path,
                                          selection.reason);
}

}  // namespace covopt::optim
