// ISO/TS 15066 body regions with the covering (docs/model.md §13): one contact's verdict,
// the closed-form speed limit per region, the all-regions table, and the covering design
// for every region named (and the head, by Park et al.'s skin model).
#include "covopt/optim/body_region_check.hpp"
#include "covopt/optim/design.hpp"
#include "covopt/optim/verdicts.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <covopt/core/number_format.hpp>
#include <covopt/core/time_integration.hpp>

#include "body_region_limits.hpp"
#include "limit_bracket.hpp"
#include "robust_internal.hpp"
#include "validation_internal.hpp"

namespace covopt::optim {
namespace {

using internal::Number;
using internal::Require;

/// The body-contact model's speed range [m/s] (core/src/body_contact.cpp).
constexpr double kMinSpeed_m_per_s = 1e-6;
constexpr double kMaxSpeed_m_per_s = 100.0;
/// Nudges of a speed limit whose own verdict rounds to inadmissible: relative steps of
/// 2^-52 × 2^i, at most this many (the last below 1e-12 relative).
constexpr int kMaxNudges = 12;

// The checks below run for every verdict and table row: each message is built only when
// its check fails.
void ValidateLimits(const materials::BodyLimits& limits) {
  if (limits.region == nullptr || limits.area == nullptr) {
    throw std::invalid_argument("limits: no body region and area given");
  }
  if (!(std::isfinite(limits.force_N) && limits.force_N > 0.0)) {
    throw std::invalid_argument("limits.force_N must be finite and > 0 N (got " + Number(limits.force_N) + ")");
  }
  if (!(std::isfinite(limits.pressure_Pa) && limits.pressure_Pa > 0.0)) {
    throw std::invalid_argument("limits.pressure_Pa must be finite and > 0 Pa (got " + Number(limits.pressure_Pa) +
                                ")");
  }
}

void ValidateRule(const DesignRule& rule) {
  if (!(std::isfinite(rule.safety_factor) && rule.safety_factor >= 1.0 && rule.safety_factor <= 100.0)) {
    throw std::invalid_argument("safety factor must be in [1, 100] (got " + Number(rule.safety_factor) + ")");
  }
}

void ValidateMaterial(const CandidateMaterial& m) {
  if (m.crush_behaviour != materials::CrushBehaviour::kCrushes) return;
  internal::CheckCompressiveStrength(m.compressive_strength_Pa, "material '" + m.name + "': ");
}

void ValidateOptions(const BodyRegionOptions& options) {
  ValidateRule(options.rule);
  if (options.material) ValidateMaterial(*options.material);
}

/// `options` as the body-region code reads them: the travel criterion counts exactly when
/// keep_travel is set (BodyRegionOptions::keep_travel decides, not the rule's criterion).
BodyRegionOptions Effective(BodyRegionOptions options) {
  options.rule = JudgedRule(options);
  return options;
}

/// What a judgement's scope is built from: the limits' Describe() and the safety factor as
/// text, made once per region (the speed limits and the table judge each region several times).
struct ScopeText {
  std::string description;
  std::string safety_factor;
};

ScopeText ScopeTextOf(const materials::BodyLimits& limits, const DesignRule& rule) {
  return {limits.Describe(), FormatSignificant(rule.safety_factor)};
}

/// The scope of one contact: the limits, then the criteria of `rule` that count, in words,
/// and the safety factor: "...: 280 N, 240 N/cm²; criteria: force, pressure, the covering not
/// fully compressed, the covering not crushed; safety factor 2 on each".
std::string ScopeOf(const ScopeText& text, const DesignRule& rule, bool covered, bool pressure_evaluated,
                    CrushCheck crush) {
  std::string scope;
  scope.reserve(text.description.size() + 192);
  scope += text.description;
  scope += "; criteria: force";
  if (pressure_evaluated) scope += ", pressure";
  if (covered) scope += ", the covering within its law's validity";
  if (covered && rule.compression_counts()) scope += ", the covering not fully compressed";
  if (covered) {
    switch (crush) {
      case CrushCheck::kChecked:
        scope += rule.crushing_allowed ? ", crushing allowed (a sacrificial liner)" : ", the covering not crushed";
        break;
      case CrushCheck::kUnknownStrength:
        scope += rule.refuses_unknown_strength() ? "; the covering's strength is unknown: refused"
                                                 : "; the covering's strength is unknown: unverified for crushing";
        break;
      case CrushCheck::kDoesNotCrush: scope += " (the covering does not crush)"; break;
      case CrushCheck::kNoMaterial: scope += " (no material given: crushing not checked)"; break;
    }
  }
  scope += "; safety factor ";
  scope += text.safety_factor;
  scope += " on each";
  if (!pressure_evaluated) scope += "; pressure not evaluated: no contact area given";
  return scope;
}

/// The crush check of `material` at a covering stress, by CheckCrush's rule.
void ApplyCrushCheck(const CandidateMaterial& material, double stress_Pa, BodyRegionJudgement& j) {
  DesignScore score;
  score.peaks.max_compressive_stress_Pa = stress_Pa;
  CheckCrush(material, score);
  j.crush_check = score.crush_check;
  j.crush_ratio = score.crush_ratio;
}

/// JudgeBodyContact on a validated model (the region's fields already in it); the scope is
/// written only when `text` is given.
BodyRegionJudgement Judge(const BodyContactModel& model, const materials::BodyLimits& limits,
                          const BodyRegionOptions& options, const ScopeText* text,
                          const TimeIntegrationOptions& time_path = {}, bool peaks_only = false) {
  BodyRegionJudgement j;
  j.limits = limits;
  if (model.scene().robot_brakes() && peaks_only) {
    j.contact = SolveBodyContactPeaks(model, time_path);  // the time path up to the peak
  } else if (model.scene().robot_brakes()) {
    SolveOptions solve;  // auto: the time path, the only one for a braking robot
    solve.time_path = time_path;
    j.contact = Solve(model, solve);
  } else {
    j.contact = Solve(model);
  }
  const DesignRule& rule = options.rule;
  const bool covered = model.has_covering();
  const BodyContactResult& c = j.contact;
  if (!c.ok()) {  // not an answer (BodyRegionJudgement)
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    j.force_ratio = kInfinity;
    if (covered || model.scene().contact_area_m2 > 0.0) j.pressure_ratio = kInfinity;
    j.governing = BodyLimitKind::kNone;
    j.governing_ratio = kInfinity;
    j.margin = -kInfinity;
    j.admissible = false;
    j.verdict = BodyRegionVerdict(c, limits, covered, rule, {});
    if (text) {
      j.scope = ScopeOf(*text, rule, covered, j.pressure_ratio.has_value(), j.crush_check) +
                "; no verdict: the time path failed (" + std::string(ToString(c.status)) + ": " + c.message + ")";
      j.verdict.scope = {j.scope};
    }
    return j;
  }
  j.force_ratio = c.peak_force_N / limits.force_N;
  if (c.peak_pressure_Pa) j.pressure_ratio = *c.peak_pressure_Pa / limits.pressure_Pa;
  j.compression_ratio = c.compression_ratio;
  if (covered && options.material) ApplyCrushCheck(*options.material, c.covering_stress_Pa, j);

  j.governing = BodyLimitKind::kForce;
  j.governing_ratio = j.force_ratio;
  auto consider = [&j](double ratio, BodyLimitKind kind) {
    if (ratio > j.governing_ratio) {
      j.governing_ratio = ratio;
      j.governing = kind;
    }
  };
  if (j.pressure_ratio) consider(*j.pressure_ratio, BodyLimitKind::kPressure);
  const bool compression_counts = covered && rule.compression_counts();
  if (compression_counts) consider(j.compression_ratio, BodyLimitKind::kFullCompression);
  if (j.crush_check == CrushCheck::kChecked && !rule.crushing_allowed) consider(j.crush_ratio, BodyLimitKind::kCrush);
  // The law's validity (the verdict's "law-validity"): how far along its limits, not derated.
  if (covered) consider(c.validity.ratio / rule.safety_factor, BodyLimitKind::kLawValidity);

  const double strength = options.material ? options.material->compressive_strength_Pa : 0.0;
  j.verdict = BodyRegionVerdict(c, limits, covered, rule, {j.crush_check, strength});
  j.margin = j.verdict.margin();
  j.admissible = j.verdict.safe();
  if (text) {
    j.scope = ScopeOf(*text, rule, covered, j.pressure_ratio.has_value(), j.crush_check);
    j.verdict.scope = {j.scope};
  }
  return j;
}

/// The peak force [N] at which the peak pressure reaches `pressure_Pa`: the inverse of
/// BodyContactModel::PressureAtForce (bare with an area: p A; covered: Hertz below the
/// bottoming out, p ∝ F^(1/3), and p ∝ F on the fixed contact area past it).
double ForceAtPressure(const BodyContactModel& model, double pressure_Pa) {
  constexpr double kHertz = 2.0 * std::numbers::pi / 3.0;  // F = p · 2π a² / 3
  if (!model.has_covering()) return pressure_Pa * model.scene().contact_area_m2;
  const double radius = model.covering_outer_radius_m();
  const double travel = model.covering_travel_m();
  const double stiffness = model.covering_stiffness();
  const double bottom_force = model.bottom_out_force_N();
  const double bottom_pressure = bottom_force / (kHertz * radius * travel);
  if (pressure_Pa > bottom_pressure) return pressure_Pa * kHertz * radius * travel;
  const double x = kHertz * radius * pressure_Pa;  // F^(1/3) K_c^(2/3)
  return x * x * x / (stiffness * stiffness);
}

std::string RegionName(const materials::BodyLimits& limits) {
  return limits.region->name + " (" + limits.area->name + ")";
}

BodyContactScene AtSpeed(BodyContactScene scene, double speed_m_per_s) {
  scene.speed_m_per_s = speed_m_per_s;
  return scene;
}

/// "chest (sternum), transient: <what> (<the limits>)", in one allocation.
std::string RegionMessage(const materials::BodyLimits& limits, const ScopeText& text, std::string_view what) {
  std::string m;
  m.reserve(limits.region->name.size() + limits.area->name.size() + what.size() + text.description.size() + 24);
  m.append(limits.region->name).append(" (").append(limits.area->name).append("), ");
  m.append(ToString(limits.contact)).append(": ").append(what);
  m.append(" (").append(text.description).append(")");
  return m;
}

/// `what` of a speed limit, with "; covering used up at v = ... m/s" where the covering is used
/// up below the limit (not an injury: BodyRegionSpeedLimit::covering_used_up_m_per_s).
std::string UsedUpText(const BodyRegionSpeedLimit& limit, std::string what) {
  const std::optional<double>& used_up = limit.covering_used_up_m_per_s;
  if (used_up && *used_up < limit.max_safe_speed_m_per_s) {
    what += "; covering used up at v = " + FormatSignificant(*used_up, 6) + " m/s";
  }
  return what;
}

/// A covering of unknown compressive strength that the rule refuses: no speed is safe.
bool RefusedForUnknownStrength(const BodyContactScene& scene, const BodyRegionOptions& options) {
  return scene.has_covering() && options.material &&
         options.material->crush_behaviour == materials::CrushBehaviour::kUnknown &&
         options.rule.refuses_unknown_strength();
}

BodyRegionSpeedLimit RegionSpeedLimit(const BodyContactScene& region_scene, const materials::BodyLimits& limits,
                                      const BodyRegionOptions& options, const ScopeText& text,
                                      const TimeIntegrationOptions& time_path = {});
BodyRegionSpeedLimit BrakedSpeedLimit(const BodyContactScene& region_scene, const materials::BodyLimits& limits,
                                      const BodyRegionOptions& options, const ScopeText& text,
                                      const TimeIntegrationOptions& time_path);

/// MaxSafeSpeed with the scene already carrying the region, and the scope's text given.
BodyRegionSpeedLimit RegionSpeedLimit(const BodyContactScene& region_scene, const materials::BodyLimits& limits,
                                      const BodyRegionOptions& options, const ScopeText& text,
                                      const TimeIntegrationOptions& time_path) {
  if (region_scene.robot_brakes()) return BrakedSpeedLimit(region_scene, limits, options, text, time_path);
  const BodyContactModel model = BodyContactModel::FromScene(AtSpeed(region_scene, 1.0));
  const DesignRule& rule = options.rule;
  const double sf = rule.safety_factor;
  const bool covered = model.has_covering();

  double force = model.foam() ? 0.0 : limits.force_N / sf;  // a foam's limits are energies (below)
  BodyLimitKind by = BodyLimitKind::kForce;
  auto consider = [&](double candidate, BodyLimitKind kind) {
    if (candidate < force) {
      force = candidate;
      by = kind;
    }
  };
  if (!model.foam() && (covered || model.scene().contact_area_m2 > 0.0)) {
    consider(ForceAtPressure(model, limits.pressure_Pa / sf), BodyLimitKind::kPressure);
  }
  if (covered && !model.foam() && rule.compression_counts()) {
    const double travel = model.covering_travel_m() / sf;  // at SF 1: F_b itself (inclusive)
    consider(model.covering_stiffness() * travel * std::sqrt(travel), BodyLimitKind::kFullCompression);
  }
  const bool refused = RefusedForUnknownStrength(model.scene(), options);
  if (covered && !model.foam() && options.material) {
    const CandidateMaterial& m = *options.material;
    if (m.crush_behaviour == materials::CrushBehaviour::kCrushes && !rule.crushing_allowed) {
      consider(ForceAtPressure(model, m.compressive_strength_Pa / sf), BodyLimitKind::kCrush);
    }
  }

  BodyRegionSpeedLimit out;
  const auto message = [&](std::string_view what) { return RegionMessage(limits, text, what); };
  double speed = force > 0.0 ? model.SpeedAtPeakForce(force) : 0.0;
  if (model.foam()) {
    const internal::LimitEnergy limit = internal::FoamLimitEnergy(model, limits, options);
    by = limit.by;
    speed = std::sqrt(2.0 * limit.energy_J / model.reduced_mass_kg());
  }
  if (covered) {  // the law's validity counts always ("law-validity")
    const double within = internal::WithinLawSpeed(region_scene, std::min(speed, kMaxSpeed_m_per_s), kMinSpeed_m_per_s);
    // Below the other limits; tied with one (the travel at SF 1), that one stays the limit.
    if (within < std::min(speed, kMaxSpeed_m_per_s) * (1.0 - 1e-12)) {
      speed = within;
      by = BodyLimitKind::kLawValidity;
    }
  }
  out.covering_used_up_m_per_s = internal::UsedUpSpeed(model, kMaxSpeed_m_per_s);
  if (!refused && speed > kMaxSpeed_m_per_s) {
    out.status = SpeedLimitStatus::kSafeUpToSearchLimit;
    out.limited_by = BodyLimitKind::kNone;
    out.max_safe_speed_m_per_s = kMaxSpeed_m_per_s;
    out.at_limit = Judge(BodyContactModel::FromScene(AtSpeed(region_scene, kMaxSpeed_m_per_s)), limits, options,
                         &text);
    out.message = message(UsedUpText(out, "safe up to the model's 100 m/s"));
    return out;
  }
  if (!refused && speed >= kMinSpeed_m_per_s) {
    // The limit's own verdict can round past 1/SF (or past the bottoming out at SF 1): step
    // the speed down by a few ulps until it holds.
    for (int i = 0; i <= kMaxNudges; ++i) {
      out.at_limit = Judge(BodyContactModel::FromScene(AtSpeed(region_scene, speed)), limits, options, nullptr);
      if (out.at_limit.admissible) break;
      speed *= 1.0 - std::ldexp(1.0, -52 + i);
    }
    // The scope once, for the verdict kept.
    out.at_limit.scope = ScopeOf(text, rule, covered, out.at_limit.pressure_ratio.has_value(), out.at_limit.crush_check);
    if (out.at_limit.admissible) {
      out.status = SpeedLimitStatus::kLimited;
      out.max_safe_speed_m_per_s = speed;
      out.limited_by = by;
      // The speed to 6 significant digits, as FormatSignificant writes it, without its buffer.
      char digits[32];
      const auto end = std::to_chars(digits, digits + sizeof digits, speed, std::chars_format::general, 6).ptr;
      std::string what(digits, end);
      what.append(" m/s, limited by ").append(ToString(by));
      out.message = message(UsedUpText(out, what));
      return out;
    }
  }
  out.status = SpeedLimitStatus::kNoSafeValue;
  out.max_safe_speed_m_per_s = 0.0;
  out.limited_by = refused ? BodyLimitKind::kCrush : by;
  out.at_limit =
      Judge(BodyContactModel::FromScene(AtSpeed(region_scene, kMinSpeed_m_per_s)), limits, options, &text);
  out.message = message(refused ? "no safe speed: the compressive strength of '" + options.material->name +
                                        "' is unknown (allow unknown strengths, or crushing, to accept it)"
                                  : "no safe speed, unsafe even at 1e-06 m/s (" +
                                        std::string(ToString(out.limited_by)) + ")");
  return out;
}

/// Whether j's limit is the covering's bottoming out: the travel rule at SF 1 (where its ratio stays
/// 1 past it), a Hertz covering fully compressed or its law-validity by the travel (steep past it).
bool BindsAtBottom(const BodyRegionJudgement& j, bool travel_at_bottom, bool hertz) noexcept {
  const CoveringValidity& v = j.contact.validity;
  if (travel_at_bottom && (j.governing == BodyLimitKind::kFullCompression || j.contact.fully_compressed)) return true;
  return hertz && (j.contact.fully_compressed ||
                   (j.governing == BodyLimitKind::kLawValidity && v.ratio_full_compression_allowed < v.ratio));
}

/// A braking robot's limit (body_region_check.hpp): bracketed on the time path (limit_bracket.hpp)
/// from just below the unbraked closed-form limit, which bounds it from below, and narrowed by
/// regula falsi on log(SF × governing ratio).
BodyRegionSpeedLimit BrakedSpeedLimit(const BodyContactScene& region_scene, const materials::BodyLimits& limits,
                                      const BodyRegionOptions& options, const ScopeText& text,
                                      const TimeIntegrationOptions& time_path) {
  BodyContactScene unbraked_scene = region_scene;
  unbraked_scene.braking_m_per_s2 = 0.0;
  const BodyRegionSpeedLimit unbraked = RegionSpeedLimit(unbraked_scene, limits, options, text);
  // Refused at any speed whatever the brake does: the unbraked answer is the answer.
  if (RefusedForUnknownStrength(region_scene, options)) return unbraked;

  const DesignRule& rule = options.rule;
  const bool covered = region_scene.has_covering();
  int runs = 0;
  const auto judge = [&](double speed) {
    ++runs;
    // The peaks decide: the time path stops at maximum compression.
    return Judge(BodyContactModel::FromScene(AtSpeed(region_scene, speed)), limits, options, nullptr, time_path,
                 /*peaks_only=*/true);
  };
  // Where the covering's bottoming out binds (BindsAtBottom) the narrowing is steered by the
  // approach against the approach there, log(δ_max/δ_b), smooth across it.
  const BodyContactModel unit_model = BodyContactModel::FromScene(AtSpeed(region_scene, 1.0));
  const bool hertz = covered && !unit_model.foam();
  const bool travel_at_bottom = covered && JudgedRule(options).compression_counts() && rule.safety_factor == 1.0;
  const double bottom_approach_m =
      travel_at_bottom || hertz ? unit_model.ApproachAtForce(unit_model.bottom_out_force_N()) : 0.0;
  const auto evaluate = [&](double speed) {
    internal::LimitProbe<BodyRegionJudgement> e;
    e.judgement = judge(speed);
    e.failed = !e.judgement.contact.ok();
    e.admissible = e.judgement.admissible;
    if (e.failed) return e;
    const BodyRegionJudgement& j = e.judgement;
    const double scaled = rule.safety_factor * j.governing_ratio;
    if (BindsAtBottom(j, travel_at_bottom, hertz)) {
      e.excess = std::log(j.contact.max_approach_m / bottom_approach_m);
    } else if (scaled > 0.0 && (e.admissible || scaled > 1.0)) {
      e.excess = std::log(scaled);
    }
    return e;
  };
  // Every speed up to the unbraked limit is safe (braking only lowers the peaks): the scan
  // starts just below it, where the time path's own error cannot tip the verdict; if even
  // that is not safe (or there is no unbraked limit), it starts at the model's lowest speed.
  internal::LimitBracket<BodyRegionJudgement> found;
  bool searched = false;
  if (unbraked.status == SpeedLimitStatus::kSafeUpToSearchLimit) {
    internal::LimitProbe<BodyRegionJudgement> top = evaluate(kMaxSpeed_m_per_s);
    if (top.failed || top.admissible) {
      found.status = top.failed ? SpeedLimitStatus::kEvaluationFailed : SpeedLimitStatus::kSafeUpToSearchLimit;
      found.value = top.failed ? 0.0 : kMaxSpeed_m_per_s;
      found.failed_at = top.failed ? kMaxSpeed_m_per_s : 0.0;
      found.at = std::move(top.judgement);
      searched = true;
    }
  } else if (unbraked.status == SpeedLimitStatus::kLimited) {
    const double lowest = unbraked.max_safe_speed_m_per_s * (1.0 - 1e-6);
    if (lowest > kMinSpeed_m_per_s) {
      found = internal::BracketLimit<BodyRegionJudgement>(lowest, kMaxSpeed_m_per_s, evaluate);
      searched = found.status != SpeedLimitStatus::kNoSafeValue;
    }
  }
  if (!searched) found = internal::BracketLimit<BodyRegionJudgement>(kMinSpeed_m_per_s, kMaxSpeed_m_per_s, evaluate);

  BodyRegionSpeedLimit out;
  out.time_path_runs = runs;
  out.status = found.status;
  const std::string braking = "braking " + FormatSignificant(region_scene.braking_m_per_s2, 4) + " m/s² after " +
                              FormatSignificant(region_scene.reaction_delay_s * 1e3, 4) + " ms (time path)";
  switch (found.status) {
    case SpeedLimitStatus::kLimited:
      out.max_safe_speed_m_per_s = found.value;
      out.limited_by = found.unsafe_at.governing;
      out.message = RegionMessage(limits, text,
                                  FormatSignificant(found.value, 6) + " m/s, limited by " +
                                      std::string(ToString(out.limited_by)) + ", " + braking);
      break;
    case SpeedLimitStatus::kSafeUpToSearchLimit:
      out.max_safe_speed_m_per_s = kMaxSpeed_m_per_s;
      out.limited_by = BodyLimitKind::kNone;
      out.message = RegionMessage(limits, text, "safe up to the model's 100 m/s, " + braking);
      break;
    case SpeedLimitStatus::kNoSafeValue:
      out.limited_by = found.at.governing;
      out.message = RegionMessage(limits, text,
                                  "no safe speed, unsafe even at 1e-06 m/s (" + std::string(ToString(out.limited_by)) +
                                      "), " + braking);
      break;
    case SpeedLimitStatus::kEvaluationFailed:
      out.limited_by = BodyLimitKind::kNone;
      out.message = RegionMessage(limits, text,
                                  "no answer: the time path failed at " + FormatSignificant(found.failed_at, 6) +
                                      " m/s (" + std::string(ToString(found.at.contact.status)) + ": " +
                                      found.at.contact.message + "), " + braking);
      break;
  }
  out.at_limit = std::move(found.at);
  out.at_limit.scope = ScopeOf(text, rule, covered, out.at_limit.pressure_ratio.has_value(), out.at_limit.crush_check);
  return out;
}

}  // namespace

std::string_view ToString(BodyLimitKind kind) noexcept {
  switch (kind) {
    case BodyLimitKind::kNone: return "none";
    case BodyLimitKind::kForce: return "force";
    case BodyLimitKind::kPressure: return "pressure";
    case BodyLimitKind::kFullCompression: return "full-compression";
    case BodyLimitKind::kCrush: return "crush";
    case BodyLimitKind::kLawValidity: return "law-validity";
  }
  return "unknown";
}

bool BareRobotLacksContactArea(const BodyContactScene& scene) noexcept {
  return !scene.has_covering() && !(scene.contact_area_m2 > 0.0);
}

BodyContactScene WithRegion(BodyContactScene scene, const materials::BodyLimits& limits) {
  ValidateLimits(limits);
  scene.body_stiffness_N_per_m = limits.stiffness_N_per_m();
  scene.body_mass_kg = limits.effective_mass_kg();
  scene.contact = limits.contact;
  return scene;
}

BodyRegionJudgement JudgeBodyContact(const BodyContactScene& scene, const materials::BodyLimits& limits,
                                     const BodyRegionOptions& options) {
  return JudgeBodyContact(scene, limits, options, TimeIntegrationOptions{});
}

BodyRegionJudgement JudgeBodyContact(const BodyContactScene& scene, const materials::BodyLimits& limits,
                                     const BodyRegionOptions& given, const TimeIntegrationOptions& time_path) {
  ValidateOptions(given);
  const BodyRegionOptions options = Effective(given);
  const BodyContactModel model = BodyContactModel::FromScene(WithRegion(scene, limits));
  const ScopeText text = ScopeTextOf(limits, options.rule);
  return Judge(model, limits, options, &text, time_path);
}

BodyRegionSpeedLimit MaxSafeSpeed(const BodyContactScene& scene, const materials::BodyLimits& limits,
                                  const BodyRegionOptions& options) {
  return MaxSafeSpeed(scene, limits, options, TimeIntegrationOptions{});
}

BodyRegionSpeedLimit MaxSafeSpeed(const BodyContactScene& scene, const materials::BodyLimits& limits,
                                  const BodyRegionOptions& given, const TimeIntegrationOptions& time_path) {
  ValidateOptions(given);
  const BodyRegionOptions options = Effective(given);
  if (scene.robot_brakes()) ValidateTimeIntegrationOptions(time_path, "time_path.");
  return RegionSpeedLimit(WithRegion(scene, limits), limits, options, ScopeTextOf(limits, options.rule), time_path);
}

std::optional<double> BodyRegionSpeedLimitRow::gain() const noexcept {
  if (!covered || !(bare.max_safe_speed_m_per_s > 0.0)) return std::nullopt;
  return covered->max_safe_speed_m_per_s / bare.max_safe_speed_m_per_s;
}

std::vector<BodyRegionSpeedLimitRow> BodyRegionSpeedLimitTable(const BodyContactScene& scene,
                                                               std::span<const materials::BodyLimits> regions,
                                                               const BodyRegionOptions& options) {
  return BodyRegionSpeedLimitTable(scene, regions, options, TimeIntegrationOptions{});
}

std::vector<BodyRegionSpeedLimitRow> BodyRegionSpeedLimitTable(const BodyContactScene& scene,
                                                               std::span<const materials::BodyLimits> regions,
                                                               const BodyRegionOptions& given,
                                                               const TimeIntegrationOptions& time_path) {
  ValidateOptions(given);
  const BodyRegionOptions options = Effective(given);
  if (scene.robot_brakes()) ValidateTimeIntegrationOptions(time_path, "time_path.");
  BodyContactScene bare_scene = scene;
  bare_scene.covering.thickness_m = 0.0;
  std::vector<BodyRegionSpeedLimitRow> rows;
  rows.reserve(regions.size());
  for (const materials::BodyLimits& limits : regions) {
    const ScopeText text = ScopeTextOf(limits, options.rule);
    BodyRegionSpeedLimitRow row;
    row.limits = limits;
    row.bare = RegionSpeedLimit(WithRegion(bare_scene, limits), limits, options, text, time_path);
    if (scene.has_covering()) row.covered = RegionSpeedLimit(WithRegion(scene, limits), limits, options, text, time_path);
    rows.push_back(std::move(row));
  }
  return rows;
}

namespace {

void ValidateRequest(const BodyRegionDesignRequest& r) {
  Require(!r.regions.empty() || r.head.has_value(), "regions: no body region named and no head to judge");
  Require(std::isfinite(r.scene.robot_radius_m) && r.scene.robot_radius_m > 0.0,
          "robot.radius: a covering needs the radius of the robot surface under it, in (0, 100] m (got " +
              Number(r.scene.robot_radius_m) + ")");
  ValidateRule(r.rule);
  internal::ValidateThicknessScan(r.min_thickness_m, r.max_thickness_m, r.thickness_scan_points,
                                  r.thickness_resolution_m, r.thickness_step_m);
  for (const CandidateMaterial& m : r.materials) internal::ValidateCandidateMaterial(m);
}

/// The request's regions with their scenes and scope texts, judged together.
class RegionSet {
 public:
  explicit RegionSet(const BodyRegionDesignRequest& request) : request_(request) {
    for (const materials::BodyLimits& limits : request.regions) {
      scenes_.push_back(WithRegion(request.scene, limits));
      texts_.push_back(ScopeTextOf(limits, request.rule));
    }
    if (request.head) {
      Scene head = *request.head;
      head.robot.mass_kg = request.scene.robot_mass_kg;
      head.robot.radius_m = request.scene.robot_radius_m;
      head.robot.speed_m_per_s = request.scene.speed_m_per_s;
      // Park et al.'s skin model on the exact path, as the catalog snap scores a material.
      head_oracle_.emplace(head, 0.25);
    }
  }

  /// Every region (and the head) at covering `covering` (thickness 0: bare); with
  /// `scopes` the judgements carry their scope.
  struct Verdicts {
    std::vector<BodyRegionJudgement> regions;
    std::optional<DesignScore> head;
    bool admissible = true;
  };
  Verdicts At(const CoveringSpec& covering, const BodyRegionOptions& options, bool scopes) const {
    Verdicts v;
    v.regions.reserve(scenes_.size());
    for (std::size_t i = 0; i < scenes_.size(); ++i) {
      BodyContactScene scene = scenes_[i];
      scene.covering = covering;
      v.regions.push_back(Judge(BodyContactModel::FromScene(scene), request_.regions[i], options,
                                scopes ? &texts_[i] : nullptr));
      v.admissible = v.admissible && v.regions.back().admissible;
    }
    if (head_oracle_) {
      if (covering.thickness_m > 0.0) {
        v.head = head_oracle_->ScoreCovering(covering);
        if (options.material) CheckCrush(*options.material, *v.head);
      } else {
        v.head = head_oracle_->ScoreBare();
      }
      v.admissible = v.admissible && v.head->admissible(options.rule);
    }
    return v;
  }

  /// Admissible for every region and the head, without building any judgement's text.
  bool Admissible(const CoveringSpec& covering, const BodyRegionOptions& options) const {
    for (std::size_t i = 0; i < scenes_.size(); ++i) {
      BodyContactScene scene = scenes_[i];
      scene.covering = covering;
      if (!Judge(BodyContactModel::FromScene(scene), request_.regions[i], options, nullptr).admissible) return false;
    }
    if (!head_oracle_) return true;
    DesignScore head = head_oracle_->ScoreCovering(covering);
    if (options.material) CheckCrush(*options.material, head);
    return head.admissible(options.rule);
  }

 private:
  const BodyRegionDesignRequest& request_;
  std::vector<BodyContactScene> scenes_;
  std::vector<ScopeText> texts_;
  std::optional<ExactPathOracle> head_oracle_;
};

/// The governing ratio over the regions and the head, and where it is.
void FillGoverning(const DesignRule& rule, BodyRegionDesignCandidate& c) {
  c.governing_ratio = -1.0;
  for (const BodyRegionJudgement& j : c.regions) {
    if (j.governing_ratio > c.governing_ratio) {
      c.governing_ratio = j.governing_ratio;
      c.governing_where = RegionName(j.limits) + ", " + std::string(ToString(j.limits.contact)) + ": " +
                          std::string(ToString(j.governing));
    }
  }
  if (c.head) {
    const GoverningRatio g = c.head->governing(rule);
    if (g.ratio > c.governing_ratio) {
      c.governing_ratio = g.ratio;
      c.governing_where = "head (Park et al. 2011): " + std::string(ToString(g.criterion));
    }
  }
}

BodyRegionDesignCandidate DesignCandidate(const RegionSet& set, const BodyRegionDesignRequest& r,
                                          const CandidateMaterial& material) {
  // The travel counts as the request's rule says (optimize's design rule).
  BodyRegionOptions options{r.rule, material, r.rule.compression_counts()};
  auto covering = [&](double b) { return CoveringOf(material, b, r.covering_law); };
  BodyRegionDesignCandidate c;
  c.material = material;
  std::optional<double> thickness;
  const bool refused =
      material.crush_behaviour == materials::CrushBehaviour::kUnknown && r.rule.refuses_unknown_strength();
  if (!refused) {
    DesignSpace space;  // only its thickness range is read
    space.min_thickness_m = r.min_thickness_m;
    space.max_thickness_m = r.max_thickness_m;
    thickness = internal::ThinnestAdmissibleThickness(space, r.thickness_scan_points, r.thickness_resolution_m,
                                                      [&](double b) { return set.Admissible(covering(b), options); });
  }
  if (thickness && r.thickness_step_m > 0.0) {
    std::optional<double> beyond_max;
    const std::optional<double> stock = internal::FirstAdmissibleStock(
        *thickness, r.thickness_step_m, r.max_thickness_m, [](double b) { return b; },
        [&](double b) { return set.Admissible(covering(b), options); }, beyond_max);
    if (stock) thickness = *stock;  // else the exact thinnest (no stock thickness within the range)
  }
  RegionSet::Verdicts at = set.At(covering(thickness.value_or(r.max_thickness_m)), options, /*scopes=*/true);
  c.regions = std::move(at.regions);
  c.head = at.head;
  if (thickness && at.admissible) c.thickness_m = thickness;
  FillGoverning(r.rule, c);
  return c;
}

std::string Millimetres(double m) { return FormatSignificant(m * 1e3, 4) + " mm"; }

}  // namespace

BodyRegionDesignResult DesignForBodyRegions(const BodyRegionDesignRequest& request) {
  ValidateRequest(request);
  const RegionSet set(request);
  const double speed = request.scene.speed_m_per_s;
  BodyRegionDesignResult out;

  // The bare robot.
  {
    const BodyRegionOptions bare_options{request.rule, std::nullopt, request.rule.compression_counts()};
    RegionSet::Verdicts bare = set.At(CoveringSpec{1.0, 0.25, 0.0}, bare_options, /*scopes=*/true);
    out.bare_robot = std::move(bare.regions);
    out.bare_head = bare.head;
    // Safe only when every limit was checked: a bare robot's pressure needs its contact area,
    // and a verdict on the force alone must not say that no covering is needed.
    const bool pressure_checked = std::all_of(out.bare_robot.begin(), out.bare_robot.end(),
                                              [](const BodyRegionJudgement& j) { return j.pressure_ratio.has_value(); });
    out.bare_robot_safe = bare.admissible && pressure_checked;
  }

  for (const CandidateMaterial& material : request.materials) {
    out.candidates.push_back(DesignCandidate(set, request, material));
  }
  const double sf = request.rule.safety_factor;
  std::stable_sort(out.candidates.begin(), out.candidates.end(),
                   [sf](const BodyRegionDesignCandidate& a, const BodyRegionDesignCandidate& b) {
                     if (a.admissible() != b.admissible()) return a.admissible();
                     if (a.admissible() && *a.thickness_m != *b.thickness_m) return *a.thickness_m < *b.thickness_m;
                     const double ma = 1.0 - sf * a.governing_ratio, mb = 1.0 - sf * b.governing_ratio;
                     if (ma != mb) return ma > mb;
                     return a.material.name < b.material.name;
                   });
  if (!out.candidates.empty() && out.candidates.front().admissible()) out.recommendation = 0;

  // What the verdicts cover.
  const std::vector<BodyRegionJudgement>& judged =
      out.recommendation ? out.candidates.front().regions : out.bare_robot;
  for (const BodyRegionJudgement& j : judged) out.scope.push_back(j.scope);
  if (!request.regions.empty()) {
    out.scope.push_back(
        "The covering: a Hertz layer on the robot's surface in series with the region's spring (" + materials::BuiltInEdition() +
        "'s model; the covering is covopt's extension, the standard has none); its peak pressure is also its "
        "compressive stress for the crush check.");
  }
  if (request.head) {
    for (std::string& line : HeadVerdictScope(request.rule)) out.scope.push_back("Head (Park et al. 2011): " + line);
  }

  const std::string speed_text = FormatSignificant(speed, 4) + " m/s";
  if (out.recommendation) {
    const BodyRegionDesignCandidate& best = out.candidates.front();
    out.message = "Recommended: " + best.material.name + " at " + Millimetres(*best.thickness_m) +
                  " (every region" + (request.head ? " and the head" : "") + " safe at " + speed_text +
                  "; governing " + best.governing_where + ", margin " +
                  FormatPercent(1.0 - sf * best.governing_ratio) + ")";
    if (best.material.poisson_assumed) {
      out.warnings.push_back("the Poisson ratio of '" + best.material.name + "' is not known: " +
                             FormatSignificant(best.material.poisson_ratio, 3) + " is assumed");
    }
    if (best.material.crush_behaviour == materials::CrushBehaviour::kUnknown) {
      out.warnings.push_back("the compressive strength of '" + best.material.name +
                             "' is unknown: the design is unverified for crushing (unknown strengths allowed)");
    }
    if (request.rule.crushing_allowed && best.material.crush_behaviour == materials::CrushBehaviour::kCrushes) {
      out.warnings.push_back("crushing allowed: '" + best.material.name +
                             "' may crush at the first impact (a sacrificial liner); replace it after any contact");
    }
  } else if (out.candidates.empty()) {
    out.message = "No candidate material given";
  } else {
    const BodyRegionDesignCandidate& closest = out.candidates.front();
    out.message = "No candidate material in " + Millimetres(request.min_thickness_m) + " .. " +
                  Millimetres(request.max_thickness_m) + " makes every region" + (request.head ? " and the head" : "") +
                  " safe at " + speed_text + "; the closest is " + closest.material.name + " (at " +
                  Millimetres(request.max_thickness_m) + ": " + closest.governing_where + ", ratio " +
                  FormatSignificant(closest.governing_ratio, 3) + ")";
  }
  if (out.bare_robot_safe) {
    out.message += out.recommendation || out.candidates.empty() ? "; the bare robot is safe too: no covering is needed"
                                                                : "; the bare robot is safe: no covering is needed";
  }
  for (const BodyRegionJudgement& j : out.bare_robot) {
    if (!j.pressure_ratio) {
      out.warnings.push_back(
          "the bare robot's pressure is not evaluated (no contact area given): it is never called safe, and its "
          "verdicts are the force's alone");
      break;
    }
  }
  return out;
}

std::string_view HeadCriteriaName() noexcept { return "skin injury, Park et al. 2011"; }

std::string BodyRegionCriterion(const DesignRule& rule, bool head, std::string_view citation) {
  char sf[32];
  std::snprintf(sf, sizeof sf, "%g", rule.safety_factor);  // as fmt's {:g}
  std::string text = "each region's force and pressure (" +
                     (citation.empty() ? materials::BuiltInEdition() : std::string(citation)) + ")";
  if (head) text += ", the head's laceration and contusion (Park et al. 2011) and bone fracture (docs/model.md §7.1)";
  text += ", the covering within its law's validity";
  if (rule.compression_counts()) text += ", the covering not fully compressed";
  if (!rule.crushing_allowed) text += ", the covering not crushed where its strength is known";
  return text + "; safety factor " + sf + " on each";
}

BodyRegionOptions BodyRegionOptionsOf(double safety_factor, bool allow_full_compression, bool allow_crushing,
                                      bool unknown_strength_allowed, const materials::Material* material,
                                      bool keep_travel) {
  BodyRegionOptions options;
  options.rule = DesignRule{safety_factor,
                            allow_full_compression ? DesignCriterion::kPaper : DesignCriterion::kNoFullCompression,
                            allow_crushing, unknown_strength_allowed};
  if (material) options.material = CandidateOf(*material);
  options.keep_travel = keep_travel && !allow_full_compression;
  return options;
}

}  // namespace covopt::optim
