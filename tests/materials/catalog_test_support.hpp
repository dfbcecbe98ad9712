#pragma once
// Helpers of the catalog tests (test_catalog_errors.cpp, test_catalog_curves.cpp): the error a
// catalog text throws, and a sample with one line replaced.

#include <string>

#include <catch2/catch.hpp>

#include "covopt/materials/catalog.hpp"

namespace covopt::materials::testing {

/// The CatalogError that loading `text` as "mine.toml" throws; fails the test if none.
inline CatalogError ErrorFor(const std::string& text) {
  try {
    Catalog::FromTomlString(text, "mine.toml");
  } catch (const CatalogError& e) {
    return e;
  }
  FAIL("no CatalogError for:\n" << text);
  throw;  // unreachable
}

/// `sample` with the line starting with `key =` replaced by `line` (dropped if empty); when no
/// line has that key, `line` appended if `append_missing`, else the test fails.
inline std::string WithLine(const std::string& sample, const std::string& key, const std::string& line,
                            bool append_missing = false) {
  std::string text = sample;
  const auto at = text.find("\n" + key + " = ");
  if (at == std::string::npos && append_missing) return text + line + "\n";
  REQUIRE(at != std::string::npos);
  const auto end = text.find('\n', at + 1);
  text.replace(at + 1, end - at, line.empty() ? std::string() : line + "\n");
  return text;
}

}  // namespace covopt::materials::testing
