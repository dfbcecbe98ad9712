#include "run_context.hpp"

#include <array>
#include <utility>

#include <CLI/CLI.hpp>

namespace covopt::cli {
namespace {

/// Appends the input files `command`'s flags name, then those of its parsed subcommands.
void CollectInputFiles(const CLI::App& command, std::vector<report::InputFile>& files) {
  for (const CLI::Option* option : command.get_options()) {
    if (option->count() == 0) continue;
    for (const std::string& name : option->get_lnames()) {
      const std::string_view role = InputFileRole("--" + name);
      if (role.empty()) continue;
      for (const std::string& value : option->results()) files.push_back({std::string(role), value});
      break;
    }
  }
  for (const CLI::App* sub : command.get_subcommands()) CollectInputFiles(*sub, files);
}

}  // namespace

std::string_view InputFileRole(std::string_view long_flag) noexcept {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 6> kRoles{{
      {"--scene", "scene"},
      {"--catalog", "catalog"},
      {"--urdf", "urdf"},
      {"--trajectory", "trajectory"},
      {"--surface-file", "surface"},
      {"--link-coverings", "link-coverings"},
  }};
  for (const auto& [flag, role] : kRoles) {
    if (flag == long_flag) return role;
  }
  return {};
}

RunContext MakeRunContext(const CLI::App& app, std::span<const char* const> argv) {
  RunContext run;
  run.command_line = report::CommandLine(argv);
  CollectInputFiles(app, run.input_files);
  return run;
}

std::string WithRunProvenance(const std::string& json_object, const std::optional<RunContext>& run) {
  if (!run) return json_object;
  return report::WithProvenance(json_object, report::MakeProvenance(run->command_line, run->input_files));
}

}  // namespace covopt::cli
