#pragma once
/// @file scene_fields.hpp
/// The numeric fields of covopt::Scene a user can set, by name, listed once for every front
/// end: the command line's flags ("--" + name: `--robot-mass`), scene files (`[robot] mass`),
/// sweep axes (covopt::Sweep takes "robot-mass" or "robot.mass") and the Python keywords
/// (the name with '_' for '-': `robot_mass`). Values are SI; each field carries the
/// QuantitySpec its text is read with (covopt::quantity_specs), so a unit slip is refused
/// the same way everywhere. The threshold reading (ThresholdReading) is a word, not a
/// quantity, and the injury limits are not Scene fields: neither is listed here.

#include <span>
#include <string>
#include <string_view>

#include "covopt/core/quantity.hpp"
#include "covopt/core/scene.hpp"

namespace covopt {

/// One settable numeric field of a Scene.
struct SceneField {
  std::string_view table;  ///< scene-file table, e.g. "robot"
  std::string_view key;    ///< key in that table, e.g. "mass"
  /// The field's name: "robot-mass". The command-line flag is "--" + name.
  std::string_view name;
  /// Kind, unit, plausible bare numbers, and whether "fixed"/"flat" (+inf) are allowed.
  QuantitySpec spec;
  /// The Scene member, in its SI unit (kg, m, m/s, Pa or -).
  double& (*field)(Scene&);
  /// One line saying what it is, for help texts: "robot reflected mass, e.g. 10kg, or 'fixed'".
  std::string_view help;

  /// "robot.mass": how scene files and the library's messages name the field.
  std::string dotted_name() const;
  /// The field's value in `scene` [SI].
  double value(const Scene& scene) const;
};

/// Every settable numeric field, in the order of `covopt simulate --help`: robot-mass,
/// speed, robot-radius, robot-modulus, robot-poisson, covering-modulus, covering-poisson,
/// covering-thickness, head-mass, head-radius, scalp-modulus, scalp-poisson,
/// scalp-thickness, skull-modulus, skull-poisson, then the inputs of the scenes beyond the
/// conservative two-mass model: damping, reaction-delay, braking, torso-mass, neck-stiffness,
/// neck-damping.
std::span<const SceneField> SceneFields() noexcept;

/// The field called `name` ("robot-mass") or `dotted_name` ("robot.mass"); nullptr if none.
const SceneField* FindSceneField(std::string_view name) noexcept;

/// The fields' names joined by ", ": "robot-mass, speed, robot-radius, ...", for messages.
std::string SceneFieldNames();

}  // namespace covopt
