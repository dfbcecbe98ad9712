// The one resolution of scene inputs (scene_inputs.hpp).
#include "covopt/scene_file/scene_inputs.hpp"

#include <algorithm>
#include <deque>
#include <stdexcept>

#include <fmt/format.h>

#include "covopt/core/quantity.hpp"
#include "covopt/core/scene_fields.hpp"
#include "covopt/scene_file/fields.hpp"

namespace covopt::scene_file {
namespace {

/// An input's value as SI, named by its field in messages.
double ReadValue(const SceneInput& input, const QuantitySpec& spec, std::string_view quote) {
  if (const auto* text = std::get_if<std::string>(&input.value)) return ParseQuantity(*text, spec, input.field);
  const double number = std::get<double>(input.value);
  CheckBareNumber(number, input.shown, spec, input.field, quote);
  return number;
}

std::string Shown(const SceneInput& input) {
  if (const auto* text = std::get_if<std::string>(&input.value)) return "'" + *text + "'";
  return input.shown.empty() ? fmt::format("{}", std::get<double>(input.value)) : input.shown;
}

void ApplyMaterial(std::span<const SceneInput> inputs, const materials::Catalog& catalog, ResolvedScene& resolved) {
  const auto material = std::find_if(inputs.begin(), inputs.end(),
                                     [](const SceneInput& i) { return i.field == "covering.material"; });
  if (material == inputs.end()) return;
  for (const char* field : {"covering.modulus", "covering.poisson"}) {
    if (std::any_of(inputs.begin(), inputs.end(), [&](const SceneInput& i) { return i.field == field; })) {
      throw std::invalid_argument(fmt::format("covering.material sets the covering's modulus and Poisson ratio; give "
                                              "either covering.material or {}, not both",
                                              field));
    }
  }
  const auto* name = std::get_if<std::string>(&material->value);
  if (name == nullptr) {
    throw std::invalid_argument(fmt::format("covering.material: expected a catalog name (got {})", Shown(*material)));
  }
  const materials::Material* m = catalog.Find(*name);
  if (m == nullptr) throw std::invalid_argument(catalog.MissingMaterialMessage(*name));
  const CoveringSpec covering = materials::CoveringOf(*m, resolved.scene.covering.thickness_m);
  resolved.scene.covering.youngs_modulus_Pa = covering.youngs_modulus_Pa;
  resolved.scene.covering.poisson_ratio = covering.poisson_ratio;
  resolved.scene.covering.compressive_curve = covering.compressive_curve;
  resolved.covering_material = m;
}

}  // namespace

void ApplySceneInputs(std::span<const SceneInput> inputs, const materials::Catalog& catalog, ResolvedScene& resolved,
                      std::string_view quote) {
  ApplyMaterial(inputs, catalog, resolved);
  for (const SceneInput& input : inputs) {
    if (input.field == "covering.material") continue;
    if (const SceneField* field = FindSceneField(input.field)) {
      field->field(resolved.scene) = ReadValue(input, field->spec, quote);
      continue;
    }
    if (input.field == "model.thresholds") {
      const auto* text = std::get_if<std::string>(&input.value);
      resolved.scene.model.thresholds = ParseThresholds(text ? *text : Shown(input), input.field);
      continue;
    }
    if (input.field == "covering.law") {
      const auto* text = std::get_if<std::string>(&input.value);
      resolved.scene.covering.law = ParseCoveringLawOrThrow(text ? *text : Shown(input), input.field);
      continue;
    }
    if (input.field == "head.area") {
      const auto* text = std::get_if<std::string>(&input.value);
      resolved.scene.head.area = ParseHeadAreaOrThrow(input.field, text ? *text : Shown(input));
      continue;
    }
    const std::span<const LimitField> limits = LimitFields();
    const auto limit = std::find_if(limits.begin(), limits.end(),
                                    [&](const LimitField& f) { return f.dotted_name() == input.field; });
    if (limit == limits.end()) throw std::logic_error("ApplySceneInputs: unknown field '" + input.field + "'");
    const double value = ReadValue(input, limit->spec, quote);
    CheckLimitValue(*limit, value, input.field, Shown(input));
    if (limit->key == "laceration") resolved.limits.laceration_tensile_stress_Pa = value;
    if (limit->key == "contusion") resolved.limits.contusion_energy_density_J_per_m2 = value;
    if (limit->key == "safety_factor") resolved.safety_factor = value;
  }
}

namespace {

/// The spellings of one style, built once: the names live as long as the program.
struct SpellingTable {
  std::deque<std::string> names;
  std::vector<FieldSpelling> table;

  explicit SpellingTable(ValueStyle style) {
    const std::string_view prefix = style == ValueStyle::kFlag ? "--" : "";
    const char dash = style == ValueStyle::kFlag ? '-' : '_';
    const auto add = [&](std::string field, std::string_view name) {
      std::string spelled(name);
      std::replace(spelled.begin(), spelled.end(), '-', dash);
      names.push_back(std::move(field));
      const std::string_view stored = names.back();
      names.push_back(std::string(prefix) + spelled);
      table.push_back(FieldSpelling{stored, names.back()});
    };
    for (const SceneField& field : SceneFields()) add(field.dotted_name(), field.name);
    for (const LimitField& field : LimitFields()) add(field.dotted_name(), field.name);
    add("covering.material", "material");
    add("model.thresholds", "thresholds");
    add("head.area", "head-area");
    add("covering.law", "covering-law");
  }
};

}  // namespace

std::span<const FieldSpelling> SceneInputSpellings(ValueStyle style) {
  static const SpellingTable flags(ValueStyle::kFlag);
  static const SpellingTable keywords(ValueStyle::kKeyword);
  return style == ValueStyle::kFlag ? std::span<const FieldSpelling>(flags.table)
                                    : std::span<const FieldSpelling>(keywords.table);
}

}  // namespace covopt::scene_file
