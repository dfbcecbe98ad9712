#pragma once
/// @file output_options.hpp
/// The output group every command shares ("Output" in its --help), registered here for all of
/// them: --json, and the output files (--csv, --plot, --history, ...); --report is
/// report_option.hpp's.

#include <optional>
#include <string>
#include <string_view>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace covopt::cli {

/// The JSON's description in --help when a command has no words of its own.
inline constexpr std::string_view kJsonObjectInsteadOfTable = "print one JSON object (SI units) instead of the table";

/// Adds --json to `command` in its "Output" group, storing into `json` (which must outlive the
/// parse); `description` says what is printed instead ("print one JSON object (SI units)
/// instead of the table").
CLI::Option* AddJsonFlag(CLI::App& command, bool& json, std::string_view description = kJsonObjectInsteadOfTable);

/// Adds the output file `flag` ("--csv", "--plot", ...) to `command`'s "Output" group, storing
/// into `file`; `type_name` says what it takes ("FILE.csv|-": a file, or '-' for stdout;
/// "FILE.png|FILE.svg": a chart). Where it is written, and how, is OutputFile's rules.
CLI::Option* AddOutputFileOption(CLI::App& command, std::string_view flag, std::optional<std::string>& file,
                                 std::string_view description, std::string_view type_name);

}  // namespace covopt::cli
