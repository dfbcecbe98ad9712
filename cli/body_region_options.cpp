#include "body_region_options.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "covopt/scene_file/spelling.hpp"
#include "covopt/scene_file/targets.hpp"
#include "errors.hpp"
#include "quantity.hpp"
#include "simulation_plan.hpp"

namespace covopt::cli {
namespace {


}  // namespace

void AddBodyRegionOptions(CLI::App& sub, BodyRegionFlags& flags) {
  constexpr std::string_view kGroup = "Body region (ISO/TS 15066)";
  sub.add_option("--body-region", flags.regions,
                 "judge an ISO/TS 15066 body region instead of the head: a region name (see 'covopt body-regions "
                 "list'), a comma-separated list, 'head' (Park et al.'s skin model) or 'all'; may be repeated")
      ->type_name("NAME[,NAME...]")
      ->group(std::string(kGroup));
  sub.add_option("--body-area", flags.area,
                 "the area of the one --body-region named (default: its lowest pressure limit)")
      ->type_name("NAME")
      ->group(std::string(kGroup));
  sub.add_option("--contact", flags.contact,
                 "transient (default: the region recoils) or clamped (quasi-static: held against a fixed object)")
      ->type_name("transient|clamped")
      ->group(std::string(kGroup));
  sub.add_option("--contact-area", flags.contact_area,
                 "the bare robot's contact area for its pressure F/A, e.g. 1cm2 (default: the bare robot's "
                 "pressure is not evaluated)")
      ->type_name("AREA")
      ->group(std::string(kGroup));
  AddLimitsOption(sub, flags.limits);
}

void AddLimitsOption(CLI::App& sub, std::optional<std::string>& path) {
  sub.add_option("--limits", path,
                 "a body-region limit table of your own (TOML, the built-in table's format: docs/guide/limits.md); "
                 "default: the built-in ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M")
      ->type_name("FILE")
      ->group("Body region (ISO/TS 15066)");
}

std::string AsFlags(std::string_view message) {
  static constexpr scene_file::FieldSpelling kFlags[] = {
      {"body.region", "--body-region"},
      {"body.area", "--body-area"},
      {"body.contact", "--contact"},
      {"body.contact_area", "--contact-area"},
      {"body.limits", "--limits"},
      {"head.mass", "--head-mass"},  // "give head.mass=fixed" for a head held still
  };
  return scene_file::Respell(message, kFlags, scene_file::ValueStyle::kFlag);
}

std::optional<BodyRegionPlan> ResolveBodyRegions(const BodyRegionFlags& flags) {
  scene_file::TargetRequest request;
  request.names = flags.regions;
  request.area = flags.area;
  request.contact = flags.contact;
  request.limits = flags.limits;
  if (flags.contact_area) {
    request.contact_area_m2 = ParseQuantity(*flags.contact_area, quantity_specs::kContactArea, "--contact-area");
    request.contact_area_shown = *flags.contact_area;
  }
  std::optional<BodyRegionPlan> plan;
  try {
    plan = scene_file::ResolveTargets(request);
  } catch (const std::invalid_argument& e) {
    throw InputError(AsFlags(e.what()));
  }
  if (plan) {
    for (std::string& note : plan->notes) note = AsFlags(note);
  }
  return plan;
}

int RunWithBodyRegions(const BodyRegionFlags& flags, const CommandErrors& errors,
                       const std::function<int(const BodyRegionPlan&)>& run) {
  std::optional<BodyRegionPlan> regions;
  try {
    regions = ResolveBodyRegions(flags);
  } catch (const InputError& e) {
    return errors.BadInput(e.what());
  }
  if (!regions) return errors.BadInput("--body-region: no region named");
  return run(*regions);
}

void CheckBodyRegionScene(const BodyRegionPlan& regions, const SimulationPlan& plan) {
  if (!regions.has_iso()) return;
  const std::string names = regions.IsoNames();
  if (!regions.has_head()) {
    for (const auto& [field, source] : plan.sources) {
      if (scene_file::BodyRegionReads(field)) continue;
      throw InputError(fmt::format("{} from {} does not apply to the ISO/TS 15066 body region ({}): it is an input "
                                   "of the head's model; drop it, or add --body-region head",
                                   field, source, names));
    }
    if (!plan.ranges.empty()) {
      throw InputError(fmt::format("{} '{}': scene ranges (uncertain inputs) are taken for the head's model only, "
                                   "not with --body-region {}",
                                   plan.ranges.front().source, plan.ranges.front().text, names));
    }
    if (plan.history_file || plan.plot_file) {
      throw InputError(fmt::format("{} draws the head's time history; the body region ({}) is answered by its "
                                   "energy balance; drop it",
                                   plan.history_file ? "--history" : "--plot", names));
    }
  }
  const Scene& scene = plan.scene;
  if (std::isinf(scene.robot.radius_m) && scene.covering.thickness_m > 0.0) {
    const auto source = plan.sources.find("robot.radius");
    const std::string given = source == plan.sources.end()               ? std::string("--robot-radius flat")
                              : source->second.rfind("--robot-radius", 0) == 0 ? source->second
                                                                                : "robot.radius flat (from " + source->second + ")";
    throw InputError(fmt::format(
        "{}: a covering on the body region ({}) needs a finite robot radius (its Hertz contact is sphere-on-flat); "
        "give the radius, e.g. --robot-radius 15mm, or --covering-thickness 0 for the bare robot",
        given, names));
  }
  // The bare robot's own verdict needs its pressure: the library's policy.
  try {
    scene_file::RequireBareRobotContactArea(regions, BodyContactSceneOf(scene, regions));
  } catch (const std::invalid_argument& e) {
    throw InputError(AsFlags(e.what()));
  }
}

optim::BodyRegionOptions BodyRegionOptionsOf(const SimulationPlan& plan, bool allow_full_compression,
                                             bool allow_crushing) {
  // Crushing is checked where the strength is known; a covering of unknown strength is judged
  // without it (the crush check's notes say so), as speed-limit does for the head.
  return optim::BodyRegionOptionsOf(plan.safety_factor, allow_full_compression, allow_crushing,
                                    !CrushCheckOf(plan).notes.empty(),
                                    plan.covering_material ? &*plan.covering_material : nullptr, plan.keep_travel);
}

std::optional<std::string> ContactAreaNote(const BodyRegionPlan& regions, const Scene& scene, bool bare_robot_judged) {
  const std::optional<std::string> note =
      scene_file::ContactAreaNote(regions, BodyContactSceneOf(scene, regions), bare_robot_judged);
  if (!note) return std::nullopt;
  return AsFlags(*note);
}

std::string HeadCriteriaName() { return std::string(optim::HeadCriteriaName()); }

std::string LimitTableText(const materials::LimitTableInfo& t) {
  return fmt::format("{} ({}); {}, sha256 {}", t.title, t.edition, t.source, t.sha256);
}

std::string LimitTableText(const BodyRegionPlan& regions) { return LimitTableText(regions.Table().info()); }

std::string BodyCriterion(const optim::DesignRule& rule, const BodyRegionPlan& regions) {
  return optim::BodyRegionCriterion(rule, regions.has_head(), regions.Citation());
}

}  // namespace covopt::cli
