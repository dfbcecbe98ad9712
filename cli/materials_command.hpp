#pragma once
/// @file materials_command.hpp
/// `covopt materials list|show|find`: the covering-material catalog on the command line,
/// and the catalog options that `covopt simulate --material` shares.
///
///     covopt materials list [--json] [--catalog FILE]... [--no-builtin]
///     covopt materials show NAME [--json] [--catalog FILE]... [--no-builtin]
///     covopt materials find [--modulus LO..HI] [--poisson LO..HI] [--density LO..HI]
///                           [--strength LO..HI] [--crush C]... [--family F]...
///                           [--basis B]... [--name TEXT] [--include-unknown] [--json]
///                           [--catalog FILE]... [--no-builtin]
///
/// --strength keeps materials whose compressive strength is known and in range (materials
/// that do not crush, or whose strength is unknown, never pass it); --crush keeps materials
/// of the given crush behaviours (crushes, does-not-crush, unknown). A bare range end is SI
/// and must be plausible for its quantity, as elsewhere ("--modulus 10..100" is refused:
/// 10 Pa is no covering's modulus).
///
/// The catalog is the built-in one (covopt::materials::Catalog::BuiltIn()) plus every
/// --catalog file in order; a name defined twice is bad input naming both places.
/// --no-builtin drops the built-in catalog (then at least one --catalog is needed).
/// Exit codes: 0 done (also when `find` matches nothing), 2 bad input (a bad catalog file,
/// a bad range, an unknown family or basis, `show` of a name not in the catalog: one
/// message on stderr, nothing on stdout), 1 stdout could not be written.

#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "covopt/materials/catalog.hpp"
#include "quantity.hpp"
#include "run_context.hpp"

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

/// One catalog entry as JSON: name, family, youngs_modulus_Pa, poisson_ratio (null if
/// unknown), density_kg_per_m3 (null if unknown), modulus_basis, source, note (null if
/// none), crush_behaviour, compressive_strength_Pa (null unless known), strength_method,
/// strength_source, defined_at.
nlohmann::ordered_json MaterialToJson(const materials::Material& material);

/// `text` broken at spaces into lines of at most `width` characters (longer words, such as
/// URLs, stay whole): how `materials show` and `body-regions show` wrap long values.
std::vector<std::string> WrapWords(std::string_view text, std::size_t width);

/// Which `materials` subcommand ran.
enum class MaterialsAction { kNone, kList, kShow, kFind };

/// The options of `covopt materials ...`, as typed.
struct MaterialsOptions {
  MaterialsAction action = MaterialsAction::kNone;  ///< set by the parsed subcommand
  CatalogOptions catalog;                           ///< --catalog, --no-builtin
  bool json = false;                                ///< --json: JSON instead of a table
  std::string name;                                 ///< show NAME
  // find:
  std::optional<std::string> modulus;   ///< --modulus LO..HI (Pa, kPa, MPa, GPa)
  std::optional<std::string> poisson;   ///< --poisson LO..HI
  std::optional<std::string> density;   ///< --density LO..HI (kg/m3, g/cm3)
  std::optional<std::string> strength;  ///< --strength LO..HI (Pa, kPa, MPa, GPa)
  std::vector<std::string> crush;       ///< --crush C, repeatable: any of them
  std::vector<std::string> families;    ///< --family F, repeatable: any of them
  std::vector<std::string> bases;       ///< --basis B, repeatable: any of them
  std::optional<std::string> name_contains;  ///< --name TEXT: part of the name
  bool include_unknown = false;         ///< --include-unknown: unknown ν/density pass a range
  /// Not typed: the command line and input files for the JSON's provenance, set by RunCli.
  std::optional<RunContext> run;
};

/// Registers the `list`, `show`, `find` of the `materials` subcommand (made by RunCli with its
/// name and summary), storing what is typed into `options`, which must outlive the parse.
void SetupMaterials(CLI::App* materials, MaterialsOptions& options);

/// Runs the parsed subcommand; returns the exit code (0, 1 or 2).
int RunMaterials(const MaterialsOptions& options, std::ostream& out, std::ostream& err);

}  // namespace covopt::cli
