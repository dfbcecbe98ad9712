#pragma once
/// @file body_regions_command.hpp
/// `covopt body-regions list|show`: the body-region table of ISO/TS 15066:2016 Annex A = ISO
/// 10218-2:2025 Annex M (Tables A.2 and A.3, covopt::materials::BodyRegionTable::BuiltIn()), or
/// the user's own with --limits FILE, on the command line.
///
///     covopt body-regions list [--json] [--limits FILE]
///     covopt body-regions show NAME [--json] [--limits FILE]
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
  std::optional<std::string> limits;                    ///< --limits FILE: a table of one's own
  /// Not typed: the command line and input files for the JSON's provenance, set by RunCli.
  std::optional<RunContext> run;
};

/// Registers the `list` and `show` of the `body-regions` subcommand (made by RunCli with its
/// name and summary), storing what is typed into `options`, which must outlive the parse.
void SetupBodyRegions(CLI::App* command, BodyRegionsOptions& options);

/// Runs the parsed subcommand; returns the exit code (0, 1 or 2).
int RunBodyRegions(const BodyRegionsOptions& options, std::ostream& out, std::ostream& err);

}  // namespace covopt::cli
