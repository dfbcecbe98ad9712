#include "optimize.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/chart/region_charts.hpp"
#include "covopt/core/quantity.hpp"
#include "covopt/core/verdict.hpp"
#include "covopt/optim/verdicts.hpp"
#include "covopt/report/verdict_text.hpp"
#include "covopt/report/body_contact_json.hpp"
#include "covopt/report/csv.hpp"
#include "body_region_output.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "report_option.hpp"

namespace covopt::cli {

using namespace body_text;

namespace {

/// optimize's flags that the body-region design does not take, refused with the reason.
/// @throws InputError.
void CheckRegionDesignFlags(const OptimizeOptions& options, const optim::DesignRequest& head,
                            const BodyRegionPlan& regions) {
  const auto refuse = [](bool given, std::string_view flag, std::string_view why) {
    if (given) throw InputError(fmt::format("{} with --body-region: {}; drop it", flag, why));
  };
  refuse(options.thickness.has_value(), "--thickness", "the body-region design finds the thinnest covering");
  refuse(options.csv.has_value(), "--csv", "the body-region design has no candidate CSV");
  refuse(options.oracle_flags.given(), "--oracle/--method/--rtol", "its verdicts are in closed form");
  refuse(options.uncertainty.samples.has_value() || options.max_injury_probability.has_value() ||
             !options.uncertainty.distributions.empty(),
         "--samples/--distribution/--max-injury-probability", "the head's robust design is not combined with it");
  refuse(options.global_algorithm.has_value() || options.min_modulus.has_value() || options.max_modulus.has_value(),
         "--global/--min-modulus/--max-modulus", "it designs over the catalog's materials, not a continuous modulus");
  refuse(options.laceration_limit.has_value() || options.contusion_limit.has_value(),
         "--laceration-limit/--contusion-limit", "the head is judged by Park et al.'s limits (1 MPa, 2.52 J/cm²) here");
  if (!regions.has_head()) {
    for (const auto& [field, typed] : options.scene_values) {
      if (field != "robot.mass" && field != "robot.speed" && field != "robot.radius") {
        throw InputError(fmt::format("--{} '{}' does not apply to the ISO/TS 15066 body regions: it is an input of "
                                     "the head's model; drop it, or add --body-region head",
                                     FindSceneField(field) ? std::string(FindSceneField(field)->name) : field, typed));
      }
    }
    if (options.choices.thresholds) throw InputError("--thresholds applies to the head's model; add --body-region head");
    if (options.choices.head_area) throw InputError("--head-area applies to the head's model; add --body-region head");
  }
  if (std::isinf(head.scene.robot.radius_m)) {
    throw InputError("--robot-radius flat: a covering on a body region needs a finite robot radius (its Hertz contact "
                     "is sphere-on-flat); give the radius, e.g. --robot-radius 15mm");
  }
}

}  // namespace

int RunBodyRegionOptimize(const OptimizeOptions& options, const optim::DesignRequest& head, const ResultInputs& inputs,
                          const std::vector<std::string>& scene_warnings, const BodyRegionPlan& regions,
                          std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "optimize");
  std::vector<std::string> input_warnings = scene_warnings;
  input_warnings.insert(input_warnings.end(), regions.notes.begin(), regions.notes.end());
  optim::BodyRegionDesignRequest request;
  try {
    CheckRegionDesignFlags(options, head, regions);
  } catch (const InputError& e) {
    return errors.BadInput(e.what());
  }
  request.scene = BodyContactSceneOf(head.scene, regions);
  request.regions = regions.IsoLimits();
  if (regions.has_head()) request.head = head.scene;
  request.materials = head.materials;
  request.covering_law = head.options.covering_law;
  request.rule = optim::DesignRule{head.options.safety_factor,
                                   head.options.allow_full_compression ? optim::DesignCriterion::kPaper
                                                                       : optim::DesignCriterion::kNoFullCompression,
                                   head.options.allow_crushing, head.options.allow_unknown_strength};
  request.max_thickness_m = head.options.space.max_thickness_m;
  request.thickness_step_m = head.options.thickness_step_m;
  optim::BodyRegionDesignResult result;
  try {
    result = optim::DesignForBodyRegions(request);
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(e.what());
  }
  if (options.json || options.report.file) {
    try {
      PrintAndReport(out, options.json,
                     report::BodyRegionDesignJson(request, result, BodyCriterion(request.rule, regions),
                                                  input_warnings),
                     options.run, options.report, inputs, report::ReportKind::kOptimize, [&] { return chart::BodyRegionDesignCharts(request, result); });
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (options.json) {
    out.flush();
    return out ? 0 : errors.Failed("cannot write the results to standard output");
  }
  std::string named;
  for (const BodyTarget& target : regions.targets) named += (named.empty() ? "" : ", ") + target.Name();
  fmt::print(out, "Design     the covering that lets the robot reach {:g} m/s for: {}\n", request.scene.speed_m_per_s,
             named);
  fmt::print(out, "Robot      {}, {}\n", Mass(request.scene.robot_mass_kg),
             std::isinf(request.scene.robot_radius_m) ? std::string("flat") : "radius " + Mm(request.scene.robot_radius_m));
  fmt::print(out, "Contact    {}\n{}Criterion  {}\n", ContactText(regions),
             regions.has_iso() ? "Limits     " + LimitTableText(regions) + "\n" : std::string(), BodyCriterion(request.rule, regions));
  fmt::print(out, "\n{}\n", result.message);
  // The head's verdict as every head verdict is built and printed (optim::HeadVerdict, report/verdict_text).
  const auto print_head = [&](const optim::DesignScore& score, double strength_Pa) {
    const Verdict v = optim::HeadVerdict(score, InjuryLimits{}, request.rule, strength_Pa,
                                         request.head ? request.head->head.area : HeadArea::kFrontal);
    fmt::print(out, "  head ({}): {}\n", HeadCriteriaName(), report::VerdictSummary(v));
    for (const Criterion& c : v.criteria) fmt::print(out, "      {}\n", report::CriterionText(c, v.safety_factor));
  };
  const auto print_regions = [&](const std::vector<BodyRegionJudgement>& judgements) {
    for (const BodyRegionJudgement& v : judgements) {
      fmt::print(out, "  {} {}: {}\n", v.limits.region->name, "(" + v.limits.area->name + ")", VerdictWord(v));
      PrintJudgement(out, v, "      ");
    }
  };
  if (result.recommendation) {
    const optim::BodyRegionDesignCandidate& c = result.candidates.at(*result.recommendation);
    fmt::print(out, "\nRecommended {} ({}, ν {:.2f}) at {}: every verdict at that thickness\n", c.material.name,
               FormatQuantity(c.material.youngs_modulus_Pa, QuantityKind::kModulus), c.material.poisson_ratio,
               Mm(*c.thickness_m));
    print_regions(c.regions);
    if (c.head) print_head(*c.head, c.material.compressive_strength_Pa);
  }
  fmt::print(out, "\nBare robot at {:g} m/s: {}\n", request.scene.speed_m_per_s,
             result.bare_robot_safe ? "safe for every region named" : "NOT safe for every region named");
  print_regions(result.bare_robot);
  if (result.bare_head) print_head(*result.bare_head, 0.0);
  // --top N (checked by optimize's Resolve), default 8.
  const std::size_t top = options.runners_up ? std::stoul(*options.runners_up) : 8;
  const std::size_t shown = std::min<std::size_t>(result.candidates.size(), top);
  if (shown > 0) {
    fmt::print(out, "\nCandidates (first {} of {})\n", shown, result.candidates.size());
    fmt::print(out, "  {:<3} {:<28} {:>10} {:>10} {:>9}  {}\n", "#", "material", "E", "thickness", "governing",
               "where");
    for (std::size_t i = 0; i < shown; ++i) {
      const optim::BodyRegionDesignCandidate& c = result.candidates[i];
      fmt::print(out, "  {:<3} {:<28} {:>10} {:>10} {:>9.3f}  {}\n", i + 1, c.material.name.substr(0, 28),
                 FormatQuantity(c.material.youngs_modulus_Pa, QuantityKind::kModulus),
                 c.thickness_m ? Mm(*c.thickness_m) : "> " + Mm(request.max_thickness_m), c.governing_ratio,
                 c.governing_where);
    }
  }
  fmt::print(out, "\nScope\n");
  for (const std::string& line : result.scope) fmt::print(out, "  {}\n", line);
  for (const std::string& w : input_warnings) fmt::print(out, "Warning: {}\n", w);
  for (const std::string& w : result.warnings) fmt::print(out, "Warning: {}\n", w);
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace covopt::cli
