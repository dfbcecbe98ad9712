#pragma once
/// @file body_regions_command.hpp
/// `covopt body-regions list|show`: ISO/TS 15066:2016's body-region table (Tables A.2 and
/// A.3, covopt::materials::BodyRegionTable::BuiltIn()) on the command line.
///
///     covopt body-regions list [--json]
///     covopt body-regions show NAME [--json]
///
/// list prints one row per area (29): region, area, its number, the quasi-static and
/// transient force [N] and pressure [N/cm²], k [N/mm] and m_H [kg]; show prints one region
/// with every value, its areas and its sources. --json gives the same in SI units, named in
/// the keys (report::BodyRegionsJson, report::BodyRegionJson). NAME ignores case and reads
/// "_", "/" and " " as "-".
/// Exit codes: 0 done, 2 bad input (a name not in the table: one line naming the closest
/// name and the choices, nothing on stdout), 1 stdout could not be written.

#include <optional>
#include <ostream>
#include <string>

#include "run_context.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// Which `body-regions` subcommand ran.
enum class BodyRegionsAction { kNone, kList, kShow };

/// The options of `covopt body-regions ...`, as typed.
struct BodyRegionsOptions {
  BodyRegionsAction action = BodyRegionsAction::kNone;  ///< set by the parsed subcommand
  bool json = false;                                    ///< --json: JSON instead of text
  std::string name;                                     ///< show NAME
  /// Not typed: the command line and input files for the JSON's provenance, set by RunCli.
  std::optional<RunContext> run;
};

/// Registers the `list` and `show` of the `body-regions` subcommand (made by RunCli with its
/// name and summary), storing what is typed into `options`, which must outlive the parse.
void SetupBodyRegions(CLI::App* command, BodyRegionsOptions& options);

/// Runs the parsed subcommand; returns the exit code (0, 1 or 2).
int RunBodyRegions(const BodyRegionsOptions& options, std::ostream& out, std::ostream& err);

}  // namespace covopt::cli
