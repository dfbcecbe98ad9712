#pragma once
/// @file scene_file.hpp
/// Scene files: TOML with the tables and keys of the command line's scene flags.
///
///     [robot]    mass speed radius modulus poisson
///     [covering] modulus poisson thickness          (thickness = 0: no covering)
///     [head]     mass radius
///     [scalp]    modulus poisson thickness
///     [skull]    modulus poisson
///     [model]    thresholds = "cumulative" | "literal"
///
/// A value is a TOML number (SI) or a string with a unit ("15mm", "2 m/s", "fixed", "flat"),
/// read by ParseQuantity. Every table and key is optional; what a file leaves out keeps the
/// value it had. Unknown tables and keys, wrong types and TOML syntax errors are InputErrors
/// that start with "file:line:column:".

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/scene.hpp"

namespace covopt::cli {

/// Reads the scene file at `path` into `scene`: the values it sets replace scene's.
/// @return the fields the file set, by name ("robot.mass", "model.thresholds").
/// @throws InputError if the file cannot be read or is not a valid scene file; `scene` is
///         then unchanged.
std::vector<std::string> ApplySceneFile(const std::filesystem::path& path, Scene& scene);

/// The same for TOML text; `source` names it in messages (usually the file name).
/// @throws InputError as ApplySceneFile.
std::vector<std::string> ApplySceneToml(std::string_view toml_text, std::string_view source,
                                        Scene& scene);

}  // namespace covopt::cli
