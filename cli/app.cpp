#include "app.hpp"

#include <array>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ostream.h>

#include "audit.hpp"
#include "body_regions_command.hpp"
#include "errors.hpp"
#include "materials_command.hpp"
#include "measure.hpp"
#include "optimize.hpp"
#include "parse_errors.hpp"
#include "simulate.hpp"
#include "retime.hpp"
#include "robot.hpp"
#include "run_context.hpp"
#include "speed_limit.hpp"
#include "sweep.hpp"
#include "workprecision.hpp"

#ifndef COVOPT_VERSION
#define COVOPT_VERSION "unknown"
#endif

namespace covopt::cli {
namespace {

/// How a registered subcommand runs once parsed, given the run's context.
using Runner = std::function<int(const RunContext& run, std::ostream& out, std::ostream& err)>;

/// Registers the options of the subcommand `sub` into an Options of its own and returns how to run it.
template <class Options, void (*Setup)(CLI::App*, Options&),
          int (*Run)(const Options&, std::ostream&, std::ostream&)>
Runner Register(CLI::App* sub) {
  auto options = std::make_shared<Options>();
  Setup(sub, *options);
  return [options](const RunContext& run, std::ostream& out, std::ostream& err) {
    if constexpr (requires { options->run; }) options->run = run;
    return Run(*options, out, err);
  };
}

/// One subcommand: what `covopt --help` lists of it (its name and summary), and the one call that
/// registers its options. Only the subcommand the command line names is registered (the others
/// are their name and summary): building every subcommand's options cost more than a hello-world
/// process (docs/performance.md, start-up).
struct Command {
  const char* name;
  const char* summary;
  Runner (*setup)(CLI::App* sub);
};

// In the order `covopt --help` lists them.
constexpr std::array kCommands{
    Command{"simulate",
            "Compute one impact: peak force, stresses, energy density and the laceration/contusion verdicts",
            Register<SimulateOptions, SetupSimulate, RunSimulate>},
    Command{"materials", "The covering-material catalog: list, show or find materials",
            Register<MaterialsOptions, SetupMaterials, RunMaterials>},
    Command{"optimize",
            "Find the covering (real material and thickness) that prevents laceration and contusion, with "
            "its margin",
            Register<OptimizeOptions, SetupOptimize, RunOptimize>},
    Command{"sweep",
            "Sweep one or two scene quantities over a grid (exact path, or the time path where the scene "
            "needs it; all cores): CSV of every point, and a map or line chart of the injury ratios",
            Register<SweepCommandOptions, SetupSweep, RunSweep>},
    Command{"workprecision",
            "Speed against accuracy: every time-integration method over a ladder of tolerances, measured "
            "against the exact path (table, CSV, charts)",
            Register<WorkPrecisionOptions, SetupWorkPrecision, RunWorkPrecision>},
    Command{"speed-limit",
            "The largest safe impact speed of the robot with its covering (or, --solve-for mass, the "
            "largest safe reflected mass), per reflected mass",
            Register<SpeedLimitCommandOptions, SetupSpeedLimit, RunSpeedLimit>},
    Command{"robot",
            "Reflected mass of a robot (URDF) at a contact point, along a direction and its extremes; "
            "with --trajectory, the safety check of a motion",
            Register<RobotOptions, SetupRobot, RunRobot>},
    Command{"body-regions", "ISO/TS 15066:2016's body regions: list or show their limits, k and m_H",
            Register<BodyRegionsOptions, SetupBodyRegions, RunBodyRegions>},
    Command{"measure",
            "What a force-measuring device (spring + Shore A pad) would read, beside the body model's prediction "
            "for the same region",
            Register<MeasureOptions, SetupMeasure, RunMeasure>},
    Command{"audit",
            "The whole robot along its motion: every link's surface against every body region; the safe "
            "speed scale, which link and region set it, and per link the covering that makes the "
            "program safe",
            Register<AuditCommandOptions, SetupAudit, RunAudit>},
    Command{"retime",
            "The fastest program that is safe everywhere: the program's path re-timed under the audit's "
            "per-sample safe speed and the joints' limits, re-audited; its cycle time against the uniform "
            "slow-down, and against the covering's thickness",
            Register<RetimeCommandOptions, SetupRetime, RunRetime>},
};

/// The word of the command line that can name a subcommand: the first that is no flag (the top
/// level's only options, --help and --version, take no value). Empty when there is none.
std::string_view FirstWord(int argc, const char* const* argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (!word.starts_with('-')) return word;
  }
  return {};
}

}  // namespace

int RunCli(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{"covopt: design the soft covering of a collaborative robot so that a blunt "
               "hit on a human head causes no laceration or contusion (Park et al. 2011).",
               "covopt"};
  app.set_version_flag("--version", std::string("covopt ") + COVOPT_VERSION);
  app.require_subcommand(0, 1);
  app.get_formatter()->column_width(34);
  app.footer("Run 'covopt SUBCOMMAND --help' for a subcommand's options.\n"
             "Exit codes: 0 done; 1 computation or output failed; 2 bad input.");

  // Every subcommand is listed; only the one argv names gets its options (and a runner).
  const std::string_view named = FirstWord(argc, argv);
  const CLI::App* registered = nullptr;
  Runner run_registered;
  for (const Command& command : kCommands) {
    CLI::App* sub = app.add_subcommand(command.name, command.summary);
    if (named == command.name) {
      registered = sub;
      run_registered = command.setup(sub);
    }
  }

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

  if (!app.get_subcommands().empty()) {
    // The command line and input files every JSON's provenance names (run_context.hpp).
    const RunContext run = MakeRunContext(app, {argv, static_cast<std::size_t>(argc)});
    try {
      // CLI11 enters a subcommand only by its exact name: the first word that is no flag.
      if (app.get_subcommands().front() != registered) throw std::logic_error("a subcommand was parsed unregistered");
      return run_registered(run, out, err);
    } catch (const std::exception& e) {
      fmt::print(err, "covopt: internal error: {}\n", ShortenLongWords(e.what()));
      return 1;
    }
  }

  err << app.help();
  fmt::print(err, "covopt: error: no subcommand given\n");
  return 2;
}

}  // namespace covopt::cli
