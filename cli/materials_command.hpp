#pragma once
/// @file materials_command.hpp
/// `covopt materials list|show|find`: the covering-material catalog on the command line,
/// and the catalog options that `covopt simulate --material` shares.
///
///     covopt materials list [--json] [--catalog FILE]... [--no-builtin]
///     covopt materials show NAME [--json] [--plot FILE.png|FILE.svg] [--catalog FILE]...
///                           [--no-builtin]
///     covopt materials find [--modulus LO..HI] [--poisson LO..HI] [--density LO..HI]
///                           [--strength LO..HI] [--stress-at-25 LO..HI] [--has-curve]
///                           [--crush C]... [--family F]...
///                           [--basis B]... [--name TEXT] [--include-unknown] [--json]
///                           [--catalog FILE]... [--no-builtin]
///
/// --strength keeps materials whose compressive strength is known and in range (materials
/// that do not crush, or whose strength is unknown, never pass it); --crush keeps materials
/// of the given crush behaviours (crushes, does-not-crush, unknown). --stress-at-25 keeps
/// materials whose compressive curve's stress at 25 % strain is in range, --has-curve those with
/// a curve; the closing line says how many were left out for want of a curve. `show` prints the
/// curve (its points, W at the last point, σ(25 %), source, rate, recovers, rate factor) and
/// --plot draws it with gnuplot (chart::CompressiveCurveChart). A bare range end is SI
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
#include "catalog_options.hpp"
#include "run_context.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// One catalog entry as JSON: name, family, youngs_modulus_Pa, poisson_ratio (null if
/// unknown), density_kg_per_m3 (null if unknown), modulus_basis, source, note (null if
/// none), crush_behaviour, compressive_strength_Pa (null unless known), strength_method,
/// strength_source, defined_at, then the curve's keys (report::MaterialJson).
nlohmann::ordered_json MaterialToJson(const materials::Material& material);

/// Which `materials` subcommand ran.
enum class MaterialsAction { kNone, kList, kShow, kFind };

/// The options of `covopt materials ...`, as typed.
struct MaterialsOptions {
  MaterialsAction action = MaterialsAction::kNone;  ///< set by the parsed subcommand
  CatalogOptions catalog;                           ///< --catalog, --no-builtin
  bool json = false;                                ///< --json: JSON instead of a table
  std::string name;                                 ///< show NAME
  std::optional<std::string> plot_file;             ///< show --plot FILE.png|FILE.svg
  // find:
  std::optional<std::string> modulus;   ///< --modulus LO..HI (Pa, kPa, MPa, GPa)
  std::optional<std::string> poisson;   ///< --poisson LO..HI
  std::optional<std::string> density;   ///< --density LO..HI (kg/m3, g/cm3)
  std::optional<std::string> strength;  ///< --strength LO..HI (Pa, kPa, MPa, GPa)
  std::optional<std::string> stress_at_25;  ///< --stress-at-25 LO..HI (Pa, kPa, MPa, GPa)
  bool has_curve = false;               ///< --has-curve: only materials with a compressive curve
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
