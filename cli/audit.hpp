#pragma once
/// @file audit.hpp
/// `covopt audit`: the whole robot along its motion (docs/guide/audit.md). Every surface
/// point of every link, at every sample of the trajectory, against every exposed body region
/// (audit::Audit).
///
///     covopt audit --urdf FILE [--base LINK] --tip LINK --trajectory FILE.csv
///                  [--surface-file FILE.toml] [--surface-spacing 50mm] [--box-edge-radius 5mm]
///                  [--flat-face-radius 20mm] [--payload-mass M ...]
///                  [--covering-thickness 10mm --material NAME | --covering-modulus E]
///                  [--link-coverings FILE.toml] [--body-region all|NAME,...|head]
///                  [--contact-area 1cm2] [--safety-factor X] [--reaction-delay T --braking A]
///                  [--design [--family F] [--design-material NAME]]
///                  [--json] [--csv FILE|-] [--samples-csv FILE|-] [--plot FILE.png|FILE.svg]
///
/// The flags are the other commands' groups: the robot model (robot_model_options.hpp), the
/// scene's covering, head and braking flags with --material and the catalog (simulate.hpp),
/// the body regions (body_region_options.hpp; default: every transient region and the head).
/// Exit codes: 0 an answer (safe, unsafe or at rest), 1 an output could not be written,
/// 2 bad input.

#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "audit_inputs.hpp"
#include "report_option.hpp"
#include "run_context.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The options of `covopt audit`, as typed: the audit's inputs and its outputs.
struct AuditCommandOptions : AuditInputOptions {
  bool json = false;                           ///< --json: report::AuditJson
  std::optional<std::string> csv_file;         ///< --csv FILE|-: one row per link × region
  std::optional<std::string> samples_csv;      ///< --samples-csv FILE|-: one row per sample, streamed
  std::optional<std::string> plot_file;        ///< --plot FILE.png|FILE.svg: the heat map
  ReportFlags report;  ///< --report FILE.html|FILE.pdf and the sign-off flags (report_option.hpp)
  /// Not typed: the command line and input files for the JSON's provenance, set by RunCli.
  std::optional<RunContext> run;
};

/// Registers the options of the `audit` subcommand `sub` (made by RunCli with its name and
/// summary); `options` must outlive the parse.
void SetupAudit(CLI::App* sub, AuditCommandOptions& options);

/// Runs the audit; returns the exit code (0, 1 or 2).
int RunAudit(const AuditCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace covopt::cli
