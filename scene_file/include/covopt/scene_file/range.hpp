#pragma once
/// @file range.hpp
/// Quantities given as a range, LO..HI. A scene input written as a range (`mass =
/// "3.7kg..5.8kg"` under [head], or `--head-mass 3.7kg..5.8kg`) means "uncertain within
/// [LO, HI]" (docs/model.md §11); the materials filter takes open ranges ("1GPa..").

#include <string>
#include <string_view>

#include "covopt/core/quantity.hpp"
#include "covopt/core/scene_fields.hpp"
#include "covopt/materials/catalog.hpp"

namespace covopt::scene_file {

/// One scene field known only within [low, high].
struct SceneRange {
  std::string field;   ///< dotted name, "head.mass"
  std::string name;    ///< the field's name, "head-mass" (what --distribution NAME= takes)
  std::string text;    ///< as written, "3.7kg..5.8kg"
  std::string source;  ///< where: "--head-mass" or "scene.toml:4:8: head.mass"
  double low = 0.0;    ///< [SI]
  double high = 0.0;   ///< [SI], >= low
};

/// True when `text` is written as a range (holds "..").
bool IsRangeText(std::string_view text) noexcept;

/// Reads a closed range "LO..HI", "LO.." or "..HI" of quantities of one kind (units as
/// covopt::ParseQuantity reads them; a bare number is SI and must be plausible for `spec`).
/// A unit on one end and a bare nonzero number on the other is refused, since "10..100MPa"
/// would mean 10 Pa to 100 MPa.
/// @param example a good range for the messages; empty: one chosen by the spec's kind.
/// @throws std::invalid_argument naming `name`, e.g. "--modulus: expected a range LO..HI ...".
materials::Range ParseQuantityRange(std::string_view text, const QuantitySpec& spec,
                                    std::string_view name, std::string_view example = {});

/// Reads "LO..HI" for `field` (both ends needed, finite, LO <= HI).
/// @param source names the value in messages ("--head-mass" or "file:line:col: head.mass").
/// @throws std::invalid_argument "--head-mass: a range needs finite ends: a fixed body cannot
///   be uncertain ... (got 'fixed..5kg')", "... the lower end is above the upper end ...".
SceneRange ParseSceneRange(std::string_view text, const SceneField& field, std::string_view source);

}  // namespace covopt::scene_file
