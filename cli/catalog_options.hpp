#pragma once
/// @file catalog_options.hpp
/// The covering-material catalog on the command line, shared by the commands that take
/// --material (`materials`, `simulate`, `optimize`, ...): --catalog FILE and --no-builtin,
/// the catalog they describe, and the reading of a range LO..HI of quantities.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/materials/catalog.hpp"
#include "covopt/report/wrap_words.hpp"
#include "quantity.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// Where a catalog comes from (`materials` subcommands and `simulate --material`).
struct CatalogOptions {
  /// --catalog FILE, repeatable: catalog files added, in order, to the built-in catalog.
  std::vector<std::string> files;
  /// --no-builtin: use only the --catalog files.
  bool no_builtin = false;

  bool given() const { return !files.empty() || no_builtin; }
};

/// Adds --catalog and --no-builtin to `command`, storing into `options`.
void AddCatalogOptions(CLI::App& command, CatalogOptions& options);

/// The catalog the options describe.
/// @throws InputError with the loader's message (file:line:column, key, what is allowed),
///         or for --no-builtin without --catalog.
materials::Catalog LoadCatalog(const CatalogOptions& options);

/// "no material 'X' in the catalog; did you mean 'Y' or 'Z'?" (or "...; run 'covopt
/// materials list' for the names" when nothing is close).
std::string NoSuchMaterial(const materials::Catalog& catalog, std::string_view name);

/// Reads a closed range "LO..HI", "LO.." or "..HI" of quantities of one kind (units as
/// ParseQuantity reads them; a bare number is SI). A unit on one end and a bare nonzero
/// number on the other is refused, since "10..100MPa" would mean 10 Pa to 100 MPa.
/// @throws InputError naming `name`, e.g. "--modulus: expected a range LO..HI ...".
materials::Range ParseRange(std::string_view text, const QuantitySpec& spec,
                            std::string_view name);

/// Long values broken at spaces (covopt/report/wrap_words.hpp).
using report::WrapWords;

}  // namespace covopt::cli
