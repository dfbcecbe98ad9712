#pragma once
/// @file scene_file.hpp
/// Scene files for the command line (--scene): the library's reader
/// (covopt/scene_file/scene_file.hpp, which documents the format), with its bad-input
/// std::invalid_argument turned into the CLI's InputError (exit 2), same message.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/core/scene.hpp"
#include "covopt/scene_file/scene_file.hpp"
#include "covopt/scene_file/range.hpp"

namespace covopt::cli {

using scene_file::IsRangeText;  // a scene input given as a range, LO..HI (docs/model.md §11)
using scene_file::kMaxSceneFileBytes;
using scene_file::SceneRange;
using scene_file::SceneFileExtras;

/// covopt::scene_file::ApplySceneFile, throwing InputError. A function object, like
/// cli::ParseQuantity, so that argument-dependent lookup does not also find the library's.
struct ApplySceneFileToInputError {
  /// @throws InputError with the library's message ("scene.toml:3:8: unknown key ...").
  std::vector<std::string> operator()(const std::filesystem::path& path, Scene& scene,
                                      SceneFileExtras* extras = nullptr) const;
};
inline constexpr ApplySceneFileToInputError ApplySceneFile{};

/// covopt::scene_file::ApplySceneToml, throwing InputError.
struct ApplySceneTomlToInputError {
  /// @throws InputError with the library's message.
  std::vector<std::string> operator()(std::string_view toml_text, std::string_view source,
                                      Scene& scene, SceneFileExtras* extras = nullptr) const;
};
inline constexpr ApplySceneTomlToInputError ApplySceneToml{};

}  // namespace covopt::cli
