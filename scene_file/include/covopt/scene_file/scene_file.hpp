#pragma once
/// @file scene_file.hpp
/// Scene files: TOML with the tables and keys of the command line's scene flags, read the
/// same way by the library, the `covopt` command (--scene) and Python (covopt.load_scene).
///
///     [robot]    mass speed radius modulus poisson reaction_delay braking
///     [covering] modulus poisson thickness material  (thickness = 0: no covering)
///     [head]     mass radius torso_mass neck_stiffness neck_damping
///     [scalp]    modulus poisson thickness
///     [skull]    modulus poisson
///     [model]    thresholds = "cumulative" | "literal", damping
///     [limits]   laceration contusion safety_factor
///     [report]   project cell assessor note margin_threshold appendix
///
/// A value is a TOML number (SI) or a string with a unit ("15mm", "2 m/s", "fixed", "flat"),
/// read by covopt::ParseQuantity. A bare TOML number must be plausible for its quantity, as
/// on the command line (covopt/core/quantity.hpp): `radius = 40` is refused as 40 m,
/// `"40mm"` and `"40m"` are taken as written. `covering.material` is a catalog material's
/// name, which sets the covering's modulus and Poisson ratio (so it excludes
/// covering.modulus and covering.poisson); the caller looks it up. Every table and key is
/// optional; what a file leaves out keeps the value it had. Unknown tables and keys, wrong
/// types, bad values and TOML syntax errors are std::invalid_argument whose message starts
/// with "file:line:column:". A string value "LO..HI" is a range (SceneFileExtras::ranges),
/// refused where extras are not wanted.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "covopt/core/scene.hpp"
#include "covopt/scene_file/fields.hpp"
#include "covopt/scene_file/range.hpp"

namespace covopt::scene_file {

/// One sign-off setting of a report, as a front end was given it: a key of the scene file's
/// [report] table, a command-line flag (--project) or a key of Python's report_info. Read and
/// checked by covopt/report/report_settings.hpp.
struct ReportSetting {
  /// One of ReportKeys(): "project", "cell", "assessor", "note", "margin_threshold", "appendix".
  std::string key;
  /// A text as given, or a number (a margin threshold written as a TOML or Python number) [-].
  std::variant<double, std::string> value;
  /// How messages name it: "scene.toml:3:11: report.project", "--project", "report_info['project']".
  std::string name;
};

/// What a scene file sets besides the Scene: the [limits] table, covering.material, ranges,
/// the [report] table.
struct SceneFileExtras {
  /// limits.laceration: the laceration limit, tensile stress [Pa], > 0.
  std::optional<double> laceration_limit_Pa;
  /// limits.contusion: the contusion limit, energy density [J/m²], > 0.
  std::optional<double> contusion_limit_J_per_m2;
  /// limits.safety_factor: the limits are divided by it [-], in [1, 100].
  std::optional<double> safety_factor;
  /// covering.material: a catalog material's name, as written (not looked up here).
  std::optional<std::string> covering_material;
  /// Where covering.material is written, "file:line:column", for the caller's messages.
  std::string covering_material_where;
  /// Fields written as a range, "3.7kg..5.8kg" (an uncertain input, docs/model.md §11); the
  /// scene keeps its value there.
  std::vector<SceneRange> ranges;
  /// The [report] table, in the file's order: each key's value is checked only for its TOML
  /// type here (a string; margin_threshold also a number), its value when it is read.
  std::vector<ReportSetting> report;
};

/// The largest scene file read [bytes], 1 MiB (the examples are under 2 kB). A larger file,
/// or a device or FIFO that gives more (/dev/zero), is refused as soon as byte
/// kMaxSceneFileBytes + 1 is read.
inline constexpr std::size_t kMaxSceneFileBytes = std::size_t{1} << 20;

/// Reads the scene file at `path` into `scene` (and `extras`): the values it sets replace
/// theirs.
/// @param extras receives [limits], covering.material, ranges and [report]; when null, a file that
///        sets them is refused (the caller does not use them, and they must not be dropped
///        silently).
/// @return the fields the file set, by name ("robot.mass", "model.thresholds",
///         "limits.laceration", "covering.material", "report.project").
/// @throws std::invalid_argument if the file cannot be read or is not a valid scene file;
///         `scene` and `extras` are then unchanged.
std::vector<std::string> ApplySceneFile(const std::filesystem::path& path, Scene& scene,
                                        SceneFileExtras* extras = nullptr);

/// The same for TOML text; `source` names it in messages (usually the file name).
/// @throws std::invalid_argument as ApplySceneFile.
std::vector<std::string> ApplySceneToml(std::string_view toml_text, std::string_view source,
                                        Scene& scene, SceneFileExtras* extras = nullptr);

}  // namespace covopt::scene_file
