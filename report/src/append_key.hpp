#pragma once
/// @file append_key.hpp
/// One key appended to a result's JSON text without re-printing it (its numbers keep the text
/// they were printed with): the provenance block (provenance.hpp), the input sources
/// (input_sources.hpp).

#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace covopt::report::internal {

/// `json_object` (the text of one JSON object, at any indent) with `key`: `value` appended as
/// its last key, at the same indent.
/// @throws std::invalid_argument "<caller>: the text is not a JSON object".
std::string AppendKey(const std::string& json_object, std::string_view key, const nlohmann::ordered_json& value,
                      std::string_view caller);

}  // namespace covopt::report::internal
