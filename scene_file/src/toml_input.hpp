#pragma once
/// @file toml_input.hpp
/// What the scene-file library's TOML readers share (private): a bounded file read, and a
/// number read as SI or as a string with a unit (scene files, link-covering files).

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

#include "covopt/internal/toml.hpp"

#include "covopt/core/quantity.hpp"

namespace covopt::scene_file::internal {

/// The text of the file at `path`, at most `max_bytes` (a larger file, a directory or an
/// unreadable one is refused: "cannot read <what> 'PATH': REASON").
/// @throws std::invalid_argument.
std::string ReadBoundedFile(const std::filesystem::path& path, std::string_view what, std::size_t max_bytes);

/// A TOML number as the user wrote it, near enough: "40", "0.015", "2.76e+07".
std::string NumberText(const toml::node& node);

/// What the user wrote, for messages: a string in quotes, a number as a number.
std::string Shown(const toml::node& node);

/// Reads one numeric value: a TOML number (SI, which must be plausible for `spec`) or a
/// string with a unit. `example` shows a good value in the wrong-type message.
/// @throws std::invalid_argument "source:line:column: name: ...".
double ReadQuantity(const toml::node& node, const QuantitySpec& spec, const std::string& name,
                    std::string_view example, std::string_view source);

}  // namespace covopt::scene_file::internal
