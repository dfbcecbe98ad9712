#pragma once
/// @file scene_inputs.hpp
/// The one resolution of a front end's scene inputs (the CLI's scene flags, Python's
/// covopt.Scene keywords) into a Scene, its injury limits and safety factor: the same
/// readers, checks, ranges and messages for both. Messages name fields ("robot.radius 40: a
/// bare number is in metres ...", "limits.safety_factor must be in [1, 100] (got '0.5')");
/// each front end spells them its way from one table (spelling.hpp: --robot-radius,
/// robot_radius), and SceneInputSpellings() builds that table.

#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "covopt/core/scene.hpp"
#include "covopt/materials/catalog.hpp"
#include "covopt/scene_file/spelling.hpp"

namespace covopt::scene_file {

/// One scene input as a front end was given it.
struct SceneInput {
  /// A Scene field's dotted name ("robot.mass"), "covering.material", "model.thresholds", "head.area", or
  /// a limit's ("limits.laceration", "limits.contusion", "limits.safety_factor").
  std::string field;
  /// A number in SI (finite, or +inf where the field allows "fixed"/"flat"), or a text: a
  /// quantity with its unit ("15mm", "fixed"), a threshold reading, a head area, or a material name.
  std::variant<double, std::string> value;
  /// The number as written, for messages ("40"); empty for a text.
  std::string shown;
};

/// What the inputs resolve to; start from the defaults (or what a scene file set).
struct ResolvedScene {
  Scene scene;
  InjuryLimits limits;
  double safety_factor = 1.0;
  /// The catalog entry of covering.material (its E and ν set the covering's); nullptr if none.
  const materials::Material* covering_material = nullptr;
};

/// Applies `inputs` to `resolved`: covering.material first (from `catalog`; with
/// covering.modulus or covering.poisson also given it is refused), then every other field in
/// order. A text is read with its unit (ParseQuantity), a bare number checked against the
/// field's plausible range (CheckBareNumber, `quote` around the suggested spellings), a
/// limit or the safety factor checked against its one range (CheckLimitValue), the
/// threshold reading parsed (ParseThresholds).
/// @throws std::invalid_argument one line naming the field and the value; an unknown field
///         is a programming error (std::logic_error).
void ApplySceneInputs(std::span<const SceneInput> inputs, const materials::Catalog& catalog, ResolvedScene& resolved,
                      std::string_view quote = "");

/// Every field ApplySceneInputs reads with its name in a front end, from the field's name
/// ("robot-mass", "laceration-limit", "material", "thresholds"): kFlag gives the CLI's flags
/// ("--robot-mass"), kKeyword Python's keywords ("robot_mass").
std::span<const FieldSpelling> SceneInputSpellings(ValueStyle style);

}  // namespace covopt::scene_file
