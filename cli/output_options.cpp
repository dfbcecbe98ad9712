#include "output_options.hpp"

#include <string>

#include <CLI/CLI.hpp>

namespace covopt::cli {

CLI::Option* AddJsonFlag(CLI::App& command, bool& json, std::string_view description) {
  return command.add_flag("--json", json, std::string(description))->group("Output");
}

CLI::Option* AddOutputFileOption(CLI::App& command, std::string_view flag, std::optional<std::string>& file,
                                 std::string_view description, std::string_view type_name) {
  return command.add_option(std::string(flag), file, std::string(description))
      ->type_name(std::string(type_name))
      ->group("Output");
}

}  // namespace covopt::cli
