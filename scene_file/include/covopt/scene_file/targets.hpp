#pragma once
/// @file targets.hpp
/// The one resolver of the names a user gives for what to judge (the CLI's --body-region,
/// --body-area, --contact, --contact-area; Python's covopt.Regions(names, area, contact,
/// contact_area)) into materials::ContactTargets, and the bare-robot contact-area policy.
///
/// Behaviour (the same in every front end, docs/guide/inputs-and-errors.md):
/// - names are comma-separated lists, trimmed, case-insensitive; "all" is every region/area
///   the standard permits under the contact in table order, then the head when transient;
///   "head" is the head (Park et al.'s skin model, transient only);
/// - the targets keep the order named; a target named twice (or a region also in "all") is
///   judged once, and a note says so;
/// - an area applies to the one ISO region named (not with "all"; the head may be named too);
/// - the contact is "transient" (default), "clamped" or "quasi-static", case-insensitive;
/// - the contact area is in [1 mm², 1 m²];
/// - body.limits names a table file in the built-in table's format (docs/guide/limits.md); its
///   errors are "file:line:column: ..." naming the key.
/// Messages name the fields body.region, body.area, body.contact and body.contact_area
/// (covopt/scene_file/spelling.hpp spells them for each front end).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/body_contact.hpp"
#include "covopt/core/scene.hpp"
#include "covopt/materials/contact_target.hpp"

namespace covopt::scene_file {

/// The inputs as given.
struct TargetRequest {
  /// body.region: names, each a name or a comma-separated list ("chest,face", "head", "all").
  std::vector<std::string> names;
  std::optional<std::string> area;     ///< body.area
  std::optional<std::string> contact;  ///< body.contact
  /// body.contact_area [m²], read from its text or number by the front end.
  std::optional<double> contact_area_m2;
  /// body.contact_area as given, for messages ("1cm2", "5.0").
  std::string contact_area_shown;
  /// body.limits: the path of a body-region table file (materials::BodyRegionTable::Load)
  /// whose limits replace the built-in ones; none: the built-in table.
  std::optional<std::string> limits;
  /// Any input was given.
  bool any() const noexcept { return !names.empty() || area || contact || contact_area_m2 || limits; }
};

/// The table body.limits names: the built-in one without a path, else the file's
/// (materials::BodyRegionTable::Load, kept for the program's life).
/// @throws std::invalid_argument "file:line:column: ... (body.limits)" for a bad table, or naming
///         the file when it cannot be read.
const materials::BodyRegionTable& LimitTable(const std::optional<std::string>& path);

/// The targets `request` names; nullopt when no name is given and nothing else is (with an
/// area, contact or contact area but no name: refused).
/// @throws std::invalid_argument one line naming the field, the value and the choices.
std::optional<materials::ContactTargets> ResolveTargets(const TargetRequest& request);

/// The body contact of `scene`'s robot (mass, speed, radius, reaction delay and braking) and
/// covering, with the targets' contact type and the bare robot's contact area; k_H and m_H
/// are set per region by optim::WithRegion. Both shells build it here.
BodyContactScene BodyContactSceneOf(const Scene& scene, const materials::ContactTargets& targets);

/// Whether one name given for a target is the head alone ("head", any case): a front end then
/// judges it by the head's own model.
bool NamesTheHead(std::string_view name) noexcept;

/// The bare-robot contact-area policy: the bare robot's own verdict needs its pressure
/// (ISO/TS 15066 Table A.2 limits the pressure as well as the force, and a bare robot's
/// pressure is its force over its contact area), so ISO targets with a bare robot and no
/// contact area are refused rather than judged on the force alone. With a covering the
/// pressure is the covering's Hertz pressure.
/// @throws std::invalid_argument naming body.contact_area.
void RequireBareRobotContactArea(const materials::ContactTargets& targets, const BodyContactScene& scene);

/// The warning when a contact area was given but a covering takes the contact (its Hertz
/// pressure is used, not the area); nullopt otherwise or when `bare_robot_judged`.
std::optional<std::string> ContactAreaNote(const materials::ContactTargets& targets, const BodyContactScene& scene,
                                           bool bare_robot_judged = false);

/// Whether an ISO region's model reads the scene input `field` ("robot.mass", "robot.speed",
/// "robot.radius", the covering's, "limits.safety_factor", "robot.reaction_delay",
/// "robot.braking"); the rest belong to the head's model, and with only ISO regions named a
/// front end refuses them rather than ignore them.
bool BodyRegionReads(std::string_view field) noexcept;

/// The warning of a speed-limit table whose bare column is the force's alone: ISO targets
/// and no contact area; nullopt otherwise.
std::optional<std::string> BarePressureNote(const materials::ContactTargets& targets);

}  // namespace covopt::scene_file
