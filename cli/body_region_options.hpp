#pragma once
/// @file body_region_options.hpp
/// The option group "Body region (ISO/TS 15066)" of `simulate`, `speed-limit`, `optimize`,
/// `robot --trajectory` and `sweep`: --body-region, --body-area, --contact and --contact-area,
/// resolved into the targets a command judges (docs/model.md §13).
///
///     --body-region chest,hands-fingers --body-region head   (a list; may be repeated)
///     --body-region all        every region/area ISO/TS 15066 permits under --contact, and
///                              (transient) the head under Park et al.'s skin model
///     --body-area palm-dominant   one area of the one region named (default: the region's
///                                 lowest pressure limit)
///     --contact transient|clamped (default transient; clamped = quasi-static)
///     --contact-area 1cm2         the bare robot's contact area (its pressure F/A)
///     --limits FILE               a body-region table of one's own (default: the built-in
///                                 ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M)
///
/// A target is an area of an ISO region (its materials::BodyLimits), or the head judged by
/// the head model and Park et al.'s criteria, unchanged. The body contact's scene is built from
/// the command's robot (mass, speed, radius) and covering; the head model's other inputs do not
/// apply to an ISO region and are refused when only ISO regions are named.

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/body_contact.hpp"
#include "covopt/materials/contact_target.hpp"
#include "covopt/materials/body_regions.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/optim/body_region_check.hpp"
#include "covopt/scene_file/targets.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

struct SimulationPlan;  // simulate.hpp
class CommandErrors;    // errors.hpp

/// The four options as typed.
struct BodyRegionFlags {
  /// --body-region (repeatable; each a comma-separated list): region names, "head", "all".
  std::vector<std::string> regions;
  std::optional<std::string> area;          ///< --body-area NAME
  std::optional<std::string> contact;       ///< --contact transient|clamped
  std::optional<std::string> contact_area;  ///< --contact-area AREA (e.g. 1cm2)
  std::optional<std::string> limits;        ///< --limits FILE: a body-region table of one's own
  /// Any of the five was given.
  bool any() const noexcept { return !regions.empty() || area || contact || contact_area || limits; }
};

/// Adds the group "Body region (ISO/TS 15066)" to `sub`, filling `flags`.
void AddBodyRegionOptions(CLI::App& sub, BodyRegionFlags& flags);

/// Adds --limits FILE (a body-region table in the built-in one's format, docs/guide/limits.md)
/// to `sub`, filling `path`.
void AddLimitsOption(CLI::App& sub, std::optional<std::string>& path);

/// One thing a command judges: an area of an ISO region, or the head (Park et al.): the
/// library's target (covopt/materials/contact_target.hpp).
using BodyTarget = materials::ContactTarget;

/// What the flags resolve to: the library's targets (scene_file::ResolveTargets).
using BodyRegionPlan = materials::ContactTargets;

/// Reads the flags with the library's resolver (scene_file::ResolveTargets, which documents
/// the behaviour: case, "all", "head", duplicates), its messages spelled as flags; empty when
/// --body-region is not given (then --body-area, --contact and --contact-area are bad input).
/// @throws InputError one line naming the flag, the value and the choices.
std::optional<BodyRegionPlan> ResolveBodyRegions(const BodyRegionFlags& flags);

/// A library message naming the body-region fields (body.region, body.contact=clamped) with
/// the flags (--body-region, --contact clamped): the CLI's one table of their spellings.
std::string AsFlags(std::string_view message);

/// ResolveBodyRegions(flags) handed to `run`, a refusal being exit 2 through `errors`: how each
/// command enters its --body-region form.
int RunWithBodyRegions(const BodyRegionFlags& flags, const CommandErrors& errors,
                       const std::function<int(const BodyRegionPlan&)>& run);

/// Refuses, with only ISO regions named, a scene input they do not read (the head, scalp,
/// skull, the robot's modulus and Poisson ratio, damping, a neck, the phase
/// thresholds, the laceration and contusion limits, scene ranges, a history or plot of the
/// head's time path) wherever it was set (a flag or the scene file); and a covering on a flat
/// robot (naming --robot-radius).
/// @throws InputError.
void CheckBodyRegionScene(const BodyRegionPlan& regions, const SimulationPlan& plan);

/// The body contact of a scene with the targets' contact: the library's (scene_file).
using scene_file::BodyContactSceneOf;

/// The rule and the covering's material (its crush behaviour and strength) a body-region
/// verdict applies: the command's safety factor, criterion and crushing flag.
optim::BodyRegionOptions BodyRegionOptionsOf(const SimulationPlan& plan, bool allow_full_compression,
                                             bool allow_crushing);

/// A warning when --contact-area was given and the contact has a covering (its pressure is
/// the Hertz pressure; the area is the bare robot's); empty otherwise.
std::optional<std::string> ContactAreaNote(const BodyRegionPlan& regions, const Scene& scene,
                                           bool bare_robot_judged);

/// Whose criteria judge the head: "skin injury, Park et al. 2011".
std::string HeadCriteriaName();

/// A limit table for the text outputs: "TITLE (EDITION); SOURCE, sha256 DIGEST" (SOURCE
/// "built-in" or the --limits path).
std::string LimitTableText(const materials::LimitTableInfo& table);
/// The limit table `regions` are judged on, as above.
std::string LimitTableText(const BodyRegionPlan& regions);

/// The criteria a body-region verdict on `regions` applies under `rule`, in words ("each
/// region's force and pressure (EDITION), ..., safety factor 1 on each"), citing their table's
/// edition; the head too when they name it.
std::string BodyCriterion(const optim::DesignRule& rule, const BodyRegionPlan& regions);

}  // namespace covopt::cli
