#pragma once
/// @file run_context.hpp
/// The run a command's JSON came from, for its "provenance" block (covopt/report/provenance.hpp):
/// the command line and the input files. RunCli makes it once, after parsing, and hands it to
/// the subcommand that runs in its options (`run`); every JSON object a subcommand prints goes
/// through WithRunProvenance.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/report/provenance.hpp"

namespace CLI {
class App;
}

namespace covopt::cli {

/// The command line of the process and every input file its flags named.
struct RunContext {
  std::string command_line;                    ///< report::CommandLine(argv)
  std::vector<report::InputFile> input_files;  ///< with their roles, in the order of the flags
};

/// The role of an input-file flag ("--scene" -> "scene", "--catalog" -> "catalog", "--urdf",
/// "--trajectory", "--surface-file" -> "surface", "--link-coverings", "--limits"); empty for any other
/// flag (an output file such as --csv, --plot, --history, --report is no input).
std::string_view InputFileRole(std::string_view long_flag) noexcept;

/// Whether a flag names a file the run writes: --report, --csv, --samples-csv, --history,
/// --plot, --tolerance-plot (every output-file flag of every subcommand; '-' is stdout).
bool IsOutputFileFlag(std::string_view long_flag) noexcept;

/// Outputs never touch inputs or each other: the message of the first output file of the
/// parsed command line that is the same file (FileIdentity, cli/output.hpp: device and inode
/// after following links, or directory and name for a file not yet made) as one of its input
/// files (InputFileRole) or another of its output files (IsOutputFileFlag), naming both
/// flags and the path; nullopt when there is none. A character device (/dev/null) may be
/// named by any number of flags, and '-' (stdout) is no file. RunCli checks it right after
/// parsing, before anything runs or is written, and exits 2 on it.
std::optional<std::string> OutputPathClash(const CLI::App& app);

/// The context of a parsed command line: report::CommandLine(argv) and the values of the
/// input-file flags (InputFileRole) of the app and of every subcommand that was parsed.
RunContext MakeRunContext(const CLI::App& app, std::span<const char* const> argv);

/// `json_object` with the run's provenance block appended as its last key
/// (report::WithProvenance of report::MakeProvenance). Without a context (a command run
/// inside another, whose object is nested in the other's) the object is returned as it is.
/// @throws std::runtime_error when an input file can no longer be read.
std::string WithRunProvenance(const std::string& json_object, const std::optional<RunContext>& run);

}  // namespace covopt::cli
