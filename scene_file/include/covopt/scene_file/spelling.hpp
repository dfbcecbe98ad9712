#pragma once
/// @file spelling.hpp
/// The library's messages name inputs by field ("robot.mass must be in ...", "body.region:
/// ..."), and a value given to one as `field=value` ("use body.contact=clamped"). Each front
/// end spells them its own way from ONE table of field -> name: the command line as flags
/// ("--contact clamped"), Python as keywords ("contact='clamped'").

#include <span>
#include <string>
#include <string_view>

namespace covopt::scene_file {

/// One field and the front end's name for it: {"body.region", "--body-region"}.
struct FieldSpelling {
  std::string_view field;
  std::string_view name;
};

/// How `field=value` is written: "--contact clamped" or "contact='clamped'".
enum class ValueStyle { kFlag, kKeyword };

/// `message` with every field of `table` that stands as a whole word replaced by its name,
/// and `field=value` by the name and the value in `style`.
std::string Respell(std::string_view message, std::span<const FieldSpelling> table, ValueStyle style);

/// The fields of the body-region inputs: body.region, body.area, body.contact,
/// body.contact_area.
std::span<const std::string_view> TargetFields() noexcept;

}  // namespace covopt::scene_file
