#pragma once
/// @file retime.hpp
/// `covopt retime`: the fastest program that is safe everywhere (docs/guide/retime.md). The
/// audit's inputs (audit.hpp's AddAuditInputOptions: the robot, the trajectory, the surface, the
/// coverings, the regions, braking, the rule) and the joints' limits; the program's path kept,
/// its timing the time-optimal one under the audit's per-sample safe speed and the joints'
/// limits (covopt::audit::Retime), re-audited; with --thickness, its cycle time against the
/// covering's thickness (covopt::audit::CycleTimeAgainstThickness).
///
///     covopt retime --urdf FILE --tip LINK --trajectory FILE.csv --joint-accel-limit 10[,...]
///                   [the audit's input flags] [--joint-speed-limit V[,...]] [--max-speed-scale X]
///                   [--output FILE.csv] [--thickness 0..40mm:9 [--material NAME ...] [--design]]
///                   [--json] [--plot FILE.svg] [--thickness-plot FILE.svg] [--report FILE.html|.pdf]
///
/// Exit codes: 0 an answer (safe, or no safe timing: reported with its status), 1 an output
/// could not be written, 2 bad input.

#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "audit_inputs.hpp"
#include "report_option.hpp"
#include "run_context.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The options of `covopt retime`, as typed.
struct RetimeCommandOptions : AuditInputOptions {
  std::optional<std::string> joint_accel_limit;  ///< --joint-accel-limit A[,A...] [rad/s² or m/s²]
  std::optional<std::string> joint_speed_limit;  ///< --joint-speed-limit V[,V...] [rad/s or m/s]
  std::optional<std::string> max_speed_scale;    ///< --max-speed-scale X (default 1)
  std::optional<std::string> output;             ///< --output FILE.csv: the re-timed trajectory
  std::optional<std::string> thickness;          ///< --thickness A..B:N: the cycle-time sweep
  std::vector<std::string> materials;            ///< --material NAME (repeatable with --thickness)
  bool json = false;                             ///< --json: report::RetimeJson
  std::optional<std::string> plot_file;          ///< --plot FILE.png|FILE.svg: speed scale over time
  std::optional<std::string> thickness_plot;     ///< --thickness-plot FILE.png|FILE.svg
  ReportFlags report;  ///< --report FILE.html|FILE.pdf and the sign-off flags (report_option.hpp)
  /// Not typed: the command line and input files for the JSON's provenance, set by RunCli.
  std::optional<RunContext> run;
};

/// Registers the options of the `retime` subcommand `sub`; `options` must outlive the parse.
void SetupRetime(CLI::App* sub, RetimeCommandOptions& options);

/// Re-times the program; returns the exit code (0, 1 or 2).
int RunRetime(const RetimeCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace covopt::cli
