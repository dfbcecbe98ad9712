#include "scene_fields.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include "errors.hpp"

namespace covopt::cli {
namespace {

/// The flags are stored once, for the life of the program, so the string_views stay valid.
template <class CliField, class LibraryField>
struct FlagTable {
  std::vector<std::string> flags;
  std::vector<CliField> fields;

  explicit FlagTable(std::span<const LibraryField> library) {
    flags.reserve(library.size());
    for (const LibraryField& field : library) flags.push_back("--" + std::string(field.name));
    fields.reserve(library.size());
    for (std::size_t i = 0; i < library.size(); ++i) fields.push_back(CliField{library[i], flags[i]});
  }
};

}  // namespace

std::span<const SceneField> SceneFields() noexcept {
  static const FlagTable<SceneField, covopt::SceneField> table(covopt::SceneFields());
  return table.fields;
}

std::span<const LimitField> LimitFields() noexcept {
  static const FlagTable<LimitField, scene_file::LimitField> table(scene_file::LimitFields());
  return table.fields;
}

void CheckLimitValue(const LimitField& field, double value, std::string_view name,
                     std::string_view shown) {
  AsInputError([&] { scene_file::CheckLimitValue(field, value, name, shown); });
}

void ApplySceneFlagInputs(std::span<const scene_file::SceneInput> inputs, scene_file::ResolvedScene& resolved) {
  try {
    scene_file::ApplySceneInputs(inputs, materials::Catalog{}, resolved);
  } catch (const std::invalid_argument& e) {
    throw InputError(scene_file::Respell(e.what(), scene_file::SceneInputSpellings(scene_file::ValueStyle::kFlag),
                                         scene_file::ValueStyle::kFlag));
  }
}

ThresholdReading ParseThresholds(std::string_view text, std::string_view name) {
  return AsInputError([&] { return scene_file::ParseThresholds(text, name); });
}

HeadArea ParseHeadArea(std::string_view text, std::string_view name) {
  return AsInputError([&] { return ParseHeadAreaOrThrow(name, text); });
}

}  // namespace covopt::cli
