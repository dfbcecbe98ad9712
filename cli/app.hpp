#pragma once
/// @file app.hpp
/// The `covopt` command line: the top-level app and its subcommands.
///
/// RunCli is main() without the process: tests call it in-process with string streams.
/// Exit codes (all subcommands):
///
///     0  done (also --help and --version)
///     1  the computation failed, or an output could not be written
///     2  bad input: unknown flag, bad value, bad scene file, no subcommand
///
/// `covopt` without a subcommand prints the help to stderr and exits 2: it is a usage
/// error, and stdout stays empty on every usage error.

#include <ostream>

namespace covopt::cli {

/// Parses argv and runs the chosen subcommand, printing to `out` and `err`.
/// @return the process exit code.
int RunCli(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace covopt::cli
