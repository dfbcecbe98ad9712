#pragma once
// The text of materials/data/catalog.toml, compiled into the library: the definition is
// generated at build time (cmake/embed_text.cmake) into builtin_catalog.cpp in the build
// tree, and regenerated whenever the data file changes.

#include <string_view>

namespace covopt::materials::internal {

/// The whole catalog file, byte for byte.
extern const std::string_view kBuiltInCatalogToml;

/// How the built-in catalog names itself in origins and messages.
inline constexpr std::string_view kBuiltInCatalogName = "built-in catalog.toml";

}  // namespace covopt::materials::internal
