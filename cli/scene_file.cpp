#include "scene_file.hpp"

#include <stdexcept>

#include "errors.hpp"

namespace covopt::cli {

std::vector<std::string> ApplySceneFileToInputError::operator()(const std::filesystem::path& path,
                                                                Scene& scene,
                                                                SceneFileExtras* extras) const {
  return AsInputError([&] { return scene_file::ApplySceneFile(path, scene, extras); });
}

std::vector<std::string> ApplySceneTomlToInputError::operator()(std::string_view toml_text,
                                                                std::string_view source, Scene& scene,
                                                                SceneFileExtras* extras) const {
  return AsInputError([&] { return scene_file::ApplySceneToml(toml_text, source, scene, extras); });
}

}  // namespace covopt::cli
