#include "body_region_options.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string_view>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "covopt/core/physical_floors.hpp"
#include "errors.hpp"
#include "quantity.hpp"
#include "simulation_plan.hpp"

namespace covopt::cli {
namespace {

std::string Lowered(std::string_view text) {
  std::string lowered(text);
  for (char& c : lowered) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lowered;
}

std::string_view Trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

/// The names of a comma-separated --body-region value, each trimmed; an empty one is refused.
std::vector<std::string> SplitNames(const std::string& typed) {
  std::vector<std::string> names;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = typed.find(',', start);
    const std::string_view name =
        Trimmed(std::string_view(typed).substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (name.empty()) {
      throw InputError(fmt::format("--body-region: an empty name in '{}'; give region names separated by commas, "
                                   "e.g. chest,hands-fingers (see 'covopt body-regions list'), head or all",
                                   typed));
    }
    names.emplace_back(name);
    if (comma == std::string::npos) return names;
    start = comma + 1;
  }
}

/// The scene inputs an ISO region reads (the rest belong to the head's model).
constexpr std::array<std::string_view, 9> kBodyContactInputs{
    "robot.mass",         "robot.speed",         "robot.radius",         "covering.modulus",
    "covering.poisson",   "covering.thickness",  "limits.safety_factor", "robot.reaction_delay",
    "robot.braking"};

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
}

std::string BodyTarget::Name() const {
  if (!limits) return "head";
  return fmt::format("{} ({})", limits->region->name, limits->area->name);
}

bool BodyRegionPlan::has_head() const noexcept {
  return std::any_of(targets.begin(), targets.end(), [](const BodyTarget& t) { return t.is_head(); });
}

bool BodyRegionPlan::has_iso() const noexcept {
  return std::any_of(targets.begin(), targets.end(), [](const BodyTarget& t) { return !t.is_head(); });
}

std::vector<materials::BodyLimits> BodyRegionPlan::IsoLimits() const {
  std::vector<materials::BodyLimits> limits;
  for (const BodyTarget& target : targets) {
    if (target.limits) limits.push_back(*target.limits);
  }
  return limits;
}

std::optional<BodyRegionPlan> ResolveBodyRegions(const BodyRegionFlags& flags) {
  if (flags.regions.empty()) {
    if (flags.any()) {
      throw InputError(fmt::format("{} applies with --body-region NAME (see 'covopt body-regions list')",
                                   flags.area ? "--body-area" : flags.contact ? "--contact" : "--contact-area"));
    }
    return std::nullopt;
  }
  BodyRegionPlan plan;
  if (flags.contact) {
    const std::optional<ContactType> contact = ParseContactType(Lowered(Trimmed(*flags.contact)));
    if (!contact) {
      throw InputError(fmt::format("--contact: expected transient or clamped (got '{}')", *flags.contact));
    }
    plan.contact = *contact;
  }
  if (flags.contact_area) {
    plan.contact_area_m2 = ParseQuantity(*flags.contact_area, quantity_specs::kContactArea, "--contact-area");
    if (!(plan.contact_area_m2 >= kMinContactArea_m2) || plan.contact_area_m2 > 1.0) {  // the floor: 1 mm²
      throw InputError(fmt::format("--contact-area must be in [1 mm², 1 m²] (got '{}')", *flags.contact_area));
    }
  }

  std::vector<std::string> names;
  for (const std::string& typed : flags.regions) {
    for (std::string& name : SplitNames(typed)) names.push_back(std::move(name));
  }
  const bool all = std::any_of(names.begin(), names.end(), [](const std::string& n) { return Lowered(n) == "all"; });
  const auto iso_count = std::count_if(names.begin(), names.end(), [](const std::string& n) {
    const std::string lowered = Lowered(n);
    return lowered != "all" && lowered != "head";
  });
  if (flags.area && (all || iso_count != 1)) {
    throw InputError(fmt::format("--body-area '{}' names an area of one region; give exactly one --body-region "
                                 "with it (got {})",
                                 *flags.area, all ? "all" : fmt::format("{} regions", iso_count)));
  }

  const materials::BodyRegionTable& table = materials::BodyRegionTable::BuiltIn();
  const auto add = [&plan](BodyTarget target) {
    const bool seen = std::any_of(plan.targets.begin(), plan.targets.end(), [&](const BodyTarget& t) {
      return t.is_head() == target.is_head() &&
             (t.is_head() || (t.limits->region == target.limits->region && t.limits->area == target.limits->area));
    });
    if (!seen) plan.targets.push_back(std::move(target));
  };
  const auto add_head = [&] {
    if (plan.contact == ContactType::kClamped) {
      throw InputError("--body-region head is judged by Park et al.'s skin model of a free head, which has no clamped "
                       "contact; for a head held still give --head-mass fixed (and drop --contact clamped), or name "
                       "skull-forehead or face, whose ISO/TS 15066 limits are quasi-static");
    }
    add(BodyTarget{});
  };
  for (const std::string& name : names) {
    const std::string lowered = Lowered(name);
    if (lowered == "all") {
      for (const materials::BodyLimits& limits : table.AllLimits(plan.contact)) add(BodyTarget{limits});
      if (plan.contact == ContactType::kTransient) add(BodyTarget{});
    } else if (lowered == "head") {
      add_head();
    } else {
      try {
        add(BodyTarget{table.Limits(name, flags.area.value_or(""), plan.contact)});
      } catch (const materials::BodyRegionError& e) {
        const std::string message = e.what();
        // An unknown region: the table's choices, and the two names that are not regions.
        const bool unknown_region = message.rfind("body region '", 0) == 0 && message.find("(regions:") != std::string::npos;
        throw InputError(fmt::format("{}: {}{}", flags.area && message.find("area") != std::string::npos ? "--body-area" : "--body-region",
                                     message, unknown_region ? "; or head (Park et al.'s skin model) or all" : ""));
      }
    }
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
  const std::string names = [&] {
    std::string text;
    int shown = 0;
    for (const BodyTarget& target : regions.targets) {
      if (target.is_head()) continue;
      if (shown == 2) return text + ", ...";
      text += (shown++ > 0 ? ", " : "") + target.limits->region->name;
    }
    return text;
  }();
  if (!regions.has_head()) {
    for (const auto& [field, source] : plan.sources) {
      if (std::find(kBodyContactInputs.begin(), kBodyContactInputs.end(), field) != kBodyContactInputs.end()) continue;
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
  // The bare robot's own verdict needs its pressure: Table A.2 limits the pressure as well as
  // the force, and the pressure of a bare robot is its force over its contact area. Without
  // the area the verdict would be the force's alone. (With a covering the pressure is the
  // covering's Hertz pressure, and the bare robot is only the comparison.)
  if (optim::BareRobotLacksContactArea(BodyContactSceneOf(scene, regions))) {
    throw InputError(fmt::format(
        "--contact-area is needed for the bare robot on {}: ISO/TS 15066 Table A.2 limits the pressure too, and the "
        "bare robot's pressure is its force over its contact area; give the area of the robot's contact surface, "
        "e.g. --contact-area 1cm2 (a bare number is m², in [1e-06, 0.1]), or a covering",
        names));
  }
}

BodyContactScene BodyContactSceneOf(const Scene& scene, const BodyRegionPlan& regions) {
  BodyContactScene contact;
  contact.robot_mass_kg = scene.robot.mass_kg;
  contact.speed_m_per_s = scene.robot.speed_m_per_s;
  contact.robot_radius_m = scene.robot.radius_m;
  contact.covering = scene.covering;
  contact.contact = regions.contact;
  contact.contact_area_m2 = regions.contact_area_m2;
  contact.reaction_delay_s = scene.robot.reaction_delay_s;
  contact.braking_m_per_s2 = scene.robot.braking_m_per_s2;
  return contact;
}

optim::BodyRegionOptions BodyRegionOptionsOf(const SimulationPlan& plan, bool allow_full_compression,
                                             bool allow_crushing) {
  optim::BodyRegionOptions options;
  // Crushing is checked where the strength is known; a covering of unknown strength is judged
  // without it (the crush check's notes say so), as speed-limit does for the head.
  const bool unchecked = !CrushCheckOf(plan).notes.empty();
  options.rule = optim::DesignRule{plan.safety_factor,
                                   allow_full_compression ? optim::DesignCriterion::kPaper
                                                          : optim::DesignCriterion::kNoFullCompression,
                                   allow_crushing, unchecked};
  if (plan.covering_material) {
    const materials::Material& m = *plan.covering_material;
    optim::CandidateMaterial candidate;
    candidate.name = m.name;
    candidate.youngs_modulus_Pa = m.youngs_modulus_Pa;
    candidate.poisson_ratio = materials::PoissonRatioOrDefault(m);
    candidate.poisson_assumed = !m.poisson_ratio.has_value();
    candidate.family = m.family;
    candidate.crush_behaviour = m.crush_behaviour;
    candidate.compressive_strength_Pa = m.compressive_strength_Pa.value_or(0.0);
    options.material = std::move(candidate);
  }
  return options;
}

std::optional<std::string> ContactAreaNote(const BodyRegionPlan& regions, const Scene& scene, bool bare_robot_judged) {
  if (!(regions.contact_area_m2 > 0.0) || !(scene.covering.thickness_m > 0.0) || bare_robot_judged) return std::nullopt;
  return fmt::format("--contact-area {} is the bare robot's; with the covering the pressure is its Hertz pressure "
                     "(the area is not used here)",
                     FormatQuantity(regions.contact_area_m2, QuantityKind::kArea));
}

std::string HeadCriteriaName() { return std::string(optim::HeadCriteriaName()); }

std::string BodyCriterion(const optim::DesignRule& rule, bool head) { return optim::BodyRegionCriterion(rule, head); }

}  // namespace covopt::cli
