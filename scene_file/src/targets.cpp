// The one resolver of target names (targets.hpp).
#include "covopt/scene_file/targets.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

#include "covopt/core/physical_floors.hpp"
#include "covopt/core/quantity.hpp"

namespace covopt::scene_file {
namespace {

using materials::ContactTarget;
using materials::ContactTargets;

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

/// The names of the request, each list split at its commas and trimmed; an empty one is refused.
std::vector<std::string> SplitNames(const std::vector<std::string>& typed_names) {
  std::vector<std::string> names;
  for (const std::string& typed : typed_names) {
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = typed.find(',', start);
      const std::string_view name = Trimmed(
          std::string_view(typed).substr(start, comma == std::string::npos ? std::string::npos : comma - start));
      if (name.empty()) {
        throw std::invalid_argument(fmt::format(
            "body.region: an empty name in '{}'; give region names separated by commas, e.g. chest,hands-fingers "
            "(the regions of ISO/TS 15066 Table A.2), head or all",
            typed));
      }
      names.emplace_back(name);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return names;
}

ContactType ReadContact(const std::optional<std::string>& contact) {
  if (!contact) return ContactType::kTransient;
  const std::optional<ContactType> type = ParseContactType(Lowered(Trimmed(*contact)));
  if (!type) {
    throw std::invalid_argument(fmt::format("body.contact: expected 'transient' or 'clamped' (got '{}')", *contact));
  }
  return *type;
}

double ReadContactArea(const TargetRequest& request) {
  if (!request.contact_area_m2) return 0.0;
  const double area = *request.contact_area_m2;
  if (!(area >= kMinContactArea_m2 && area <= 1.0)) {  // the floor (physical_floors.hpp): 1 mm²
    throw std::invalid_argument(fmt::format(
        "body.contact_area must be in [1 mm², 1 m²] (a bare number is m²: 1e-06 to 1; 1 cm² is 1e-4) (got '{}')",
        request.contact_area_shown.empty() ? fmt::format("{}", area) : request.contact_area_shown));
  }
  return area;
}

/// Adds `target` unless it is there already (then a note, once per target).
void Add(ContactTargets& targets, ContactTarget target, bool quiet) {
  const bool seen = std::any_of(targets.targets.begin(), targets.targets.end(),
                                [&](const ContactTarget& t) { return t.SameAs(target); });
  if (!seen) {
    targets.targets.push_back(std::move(target));
    return;
  }
  const std::string note = fmt::format("body.region: {} is named more than once; it is judged once", target.Name());
  if (!quiet && std::find(targets.notes.begin(), targets.notes.end(), note) == targets.notes.end()) {
    targets.notes.push_back(note);
  }
}

/// One ISO region named: its limits, the table's message naming the field otherwise.
ContactTarget IsoTarget(const materials::BodyRegionTable& table, const std::string& name,
                        const std::optional<std::string>& area, ContactType contact) {
  try {
    return ContactTarget{table.Limits(name, area.value_or(""), contact)};
  } catch (const materials::BodyRegionError& e) {
    const std::string message = e.what();
    const bool unknown_region = message.rfind("body region '", 0) == 0 && message.find("(regions:") != std::string::npos;
    const bool area_error = area && message.rfind("body area '", 0) == 0;
    throw std::invalid_argument(fmt::format("{}: {}{}", area_error ? "body.area" : "body.region", message,
                                            unknown_region ? "; or head (Park et al.'s skin model) or all" : ""));
  }
}

}  // namespace

const materials::BodyRegionTable& LimitTable(const std::optional<std::string>& path) {
  if (!path) return materials::BodyRegionTable::BuiltIn();
  if (path->find_first_not_of(" \t") == std::string::npos) {
    throw std::invalid_argument("body.limits: expected the path of a body-region table file (TOML), got ''");
  }
  try {
    return materials::BodyRegionTable::Load(*path);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(fmt::format("{} (body.limits)", e.what()));
  }
}

std::optional<ContactTargets> ResolveTargets(const TargetRequest& request) {
  if (request.names.empty()) {
    if (!request.any()) return std::nullopt;
    throw std::invalid_argument(fmt::format(
        "{} applies to an ISO/TS 15066 body region; give body.region (e.g. body.region=chest)",
        request.area      ? "body.area"
        : request.contact ? "body.contact"
        : request.limits  ? "body.limits"
                          : "body.contact_area"));
  }
  ContactTargets targets;
  targets.table = &LimitTable(request.limits);
  targets.contact = ReadContact(request.contact);
  targets.contact_area_m2 = ReadContactArea(request);
  const std::vector<std::string> names = SplitNames(request.names);
  const bool all = std::any_of(names.begin(), names.end(), [](const std::string& n) { return Lowered(n) == "all"; });
  const auto iso_count = std::count_if(names.begin(), names.end(), [](const std::string& n) {
    const std::string lowered = Lowered(n);
    return lowered != "all" && lowered != "head";
  });
  if (request.area && (all || iso_count != 1)) {
    throw std::invalid_argument(fmt::format(
        "body.area '{}' names an area of one region; give exactly one body.region with it (got {})", *request.area,
        all ? "all" : fmt::format("{} regions", iso_count)));
  }
  for (const std::string& name : names) {
    const std::string lowered = Lowered(name);
    if (lowered == "all") {
      // A region named besides "all" is in it: merged without a note.
      for (const materials::BodyLimits& limits : targets.table->AllLimits(targets.contact)) {
        Add(targets, ContactTarget{limits}, true);
      }
      if (targets.contact == ContactType::kTransient) Add(targets, ContactTarget{}, true);
    } else if (lowered == "head") {
      if (targets.contact == ContactType::kClamped) {
        throw std::invalid_argument(
            "body.region=head is judged by Park et al.'s skin model of a free head, which has no clamped contact; "
            "for a head held still give head.mass=fixed with a transient body.contact, or name skull-forehead or "
            "face, whose ISO/TS 15066 limits are quasi-static");
      }
      Add(targets, ContactTarget{}, all);
    } else {
      Add(targets, IsoTarget(*targets.table, name, request.area, targets.contact), all);
    }
  }
  // "all" named after a region: the region stays where it was named, "all" adds the rest.
  return targets;
}

void RequireBareRobotContactArea(const ContactTargets& targets, const BodyContactScene& scene) {
  if (!targets.has_iso() || scene.has_covering() || scene.contact_area_m2 > 0.0) return;
  throw std::invalid_argument(fmt::format(
      "body.contact_area is needed for the bare robot on {}: ISO/TS 15066 Table A.2 limits the pressure too, and the "
      "bare robot's pressure is its force over its contact area; give the area of the robot's contact surface, "
      "e.g. body.contact_area=1cm2 (a bare number is m², in [1e-06, 1]), or a covering",
      targets.IsoNames()));
}

std::optional<std::string> ContactAreaNote(const ContactTargets& targets, const BodyContactScene& scene,
                                           bool bare_robot_judged) {
  if (!(targets.contact_area_m2 > 0.0) || !scene.has_covering() || bare_robot_judged) return std::nullopt;
  return fmt::format("body.contact_area {} is the bare robot's; with the covering the pressure is its Hertz pressure "
                     "(the area is not used here)",
                     FormatQuantity(targets.contact_area_m2, QuantityKind::kArea));
}

bool BodyRegionReads(std::string_view field) noexcept {
  static constexpr std::string_view kRead[] = {
      "robot.mass",         "robot.speed",       "robot.radius",         "covering.modulus",      "covering.poisson",
      "covering.thickness", "covering.material", "covering.law",     "limits.safety_factor", "robot.reaction_delay",
      "robot.braking"};
  return std::find(std::begin(kRead), std::end(kRead), field) != std::end(kRead);
}

std::optional<std::string> BarePressureNote(const ContactTargets& targets) {
  if (!targets.has_iso() || targets.contact_area_m2 > 0.0) return std::nullopt;
  return "the bare robot's pressure is not evaluated (no body.contact_area): its limits are those of the force alone";
}

BodyContactScene BodyContactSceneOf(const Scene& scene, const materials::ContactTargets& targets) {
  BodyContactScene contact;
  contact.robot_mass_kg = scene.robot.mass_kg;
  contact.speed_m_per_s = scene.robot.speed_m_per_s;
  contact.robot_radius_m = scene.robot.radius_m;
  contact.covering = scene.covering;
  contact.contact = targets.contact;
  contact.contact_area_m2 = targets.contact_area_m2;
  contact.reaction_delay_s = scene.robot.reaction_delay_s;
  contact.braking_m_per_s2 = scene.robot.braking_m_per_s2;
  return contact;
}

bool NamesTheHead(std::string_view name) noexcept {
  constexpr std::string_view kHead = "head";
  return std::ranges::equal(name, kHead, [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) == b;
  });
}

}  // namespace covopt::scene_file
