#pragma once
// The text of materials/data/iso_ts_15066.toml, compiled into the library: the definition is
// generated at build time (cmake/embed_text.cmake) into builtin_body_regions.cpp in the build
// tree, and regenerated whenever the data file changes.

#include <string_view>

namespace covopt::materials::internal {

/// The whole table file, byte for byte.
extern const std::string_view kBuiltInBodyRegionsToml;

/// How the built-in table names itself in origins and messages.
inline constexpr std::string_view kBuiltInBodyRegionsName = "built-in iso_ts_15066.toml";

}  // namespace covopt::materials::internal
