#include "app.hpp"

#include <exception>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ostream.h>

#include "audit.hpp"
#include "body_regions_command.hpp"
#include "errors.hpp"
#include "materials_command.hpp"
#include "optimize.hpp"
#include "parse_errors.hpp"
#include "simulate.hpp"
#include "robot.hpp"
#include "run_context.hpp"
#include "speed_limit.hpp"
#include "sweep.hpp"
#include "workprecision.hpp"

#ifndef COVOPT_VERSION
#define COVOPT_VERSION "unknown"
#endif

namespace covopt::cli {

int RunCli(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{"covopt: design the soft covering of a collaborative robot so that a blunt "
               "hit on a human head causes no laceration or contusion (Park et al. 2011).",
               "covopt"};
  app.set_version_flag("--version", std::string("covopt ") + COVOPT_VERSION);
  app.require_subcommand(0, 1);
  app.get_formatter()->column_width(34);
  app.footer("Run 'covopt SUBCOMMAND --help' for a subcommand's options.\n"
             "Exit codes: 0 done; 1 computation or output failed; 2 bad input.");

  SimulateOptions simulate_options;
  CLI::App* simulate = SetupSimulate(app, simulate_options);
  MaterialsOptions materials_options;
  CLI::App* materials = SetupMaterials(app, materials_options);
  OptimizeOptions optimize_options;
  CLI::App* optimize = SetupOptimize(app, optimize_options);
  SweepCommandOptions sweep_options;
  CLI::App* sweep = SetupSweep(app, sweep_options);
  WorkPrecisionOptions workprecision_options;
  CLI::App* workprecision = SetupWorkPrecision(app, workprecision_options);
  SpeedLimitCommandOptions speed_limit_options;
  CLI::App* speed_limit = SetupSpeedLimit(app, speed_limit_options);
  RobotOptions robot_options;
  CLI::App* robot = SetupRobot(app, robot_options);
  BodyRegionsOptions body_regions_options;
  CLI::App* body_regions = SetupBodyRegions(app, body_regions_options);
  AuditCommandOptions audit_options;
  CLI::App* audit = SetupAudit(app, audit_options);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) {
      app.exit(e, out, err);  // --help, --help-all, --version
      out.flush();
      return 0;
    }
    // One line naming the subcommand, the flag, the value and what is allowed.
    const std::string command = ActiveCommandPath(app);
    fmt::print(err, "covopt{}{}: error: {}\n", command.empty() ? "" : " ", command,
               ShortenLongWords(DescribeParseError(app, e)));
    return 2;
  }

  // Outputs never touch inputs or each other: checked before anything runs or is written.
  if (const std::optional<std::string> clash = OutputPathClash(app)) {
    fmt::print(err, "covopt {}: error: {}\n", ActiveCommandPath(app), ShortenLongWords(*clash));
    return 2;
  }

  // The command line and input files every JSON's provenance names (run_context.hpp).
  const RunContext run = MakeRunContext(app, {argv, static_cast<std::size_t>(argc)});
  simulate_options.run = materials_options.run = optimize_options.run = workprecision_options.run =
      speed_limit_options.run = robot_options.run = body_regions_options.run = audit_options.run = run;
  try {
    if (simulate->parsed()) return RunSimulate(simulate_options, out, err);
    if (materials->parsed()) return RunMaterials(materials_options, out, err);
    if (optimize->parsed()) return RunOptimize(optimize_options, out, err);
    if (sweep->parsed()) return RunSweep(sweep_options, out, err);
    if (workprecision->parsed()) return RunWorkPrecision(workprecision_options, out, err);
    if (speed_limit->parsed()) return RunSpeedLimit(speed_limit_options, out, err);
    if (robot->parsed()) return RunRobot(robot_options, out, err);
    if (body_regions->parsed()) return RunBodyRegions(body_regions_options, out, err);
    if (audit->parsed()) return RunAudit(audit_options, out, err);
  } catch (const std::exception& e) {
    fmt::print(err, "covopt: internal error: {}\n", ShortenLongWords(e.what()));
    return 1;
  }

  err << app.help();
  fmt::print(err, "covopt: error: no subcommand given\n");
  return 2;
}

}  // namespace covopt::cli
