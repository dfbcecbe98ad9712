#include "run_context.hpp"

#include <algorithm>
#include <array>
#include <utility>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "output.hpp"

namespace covopt::cli {
namespace {

/// A file-naming flag's value: an input (InputFileRole) or an output (IsOutputFileFlag).
struct NamedFile {
  std::string flag;
  std::string path;
  bool output = false;
};

/// Appends the input and output files `command`'s flags name, then those of its parsed
/// subcommands.
void CollectNamedFiles(const CLI::App& command, std::vector<NamedFile>& files) {
  for (const CLI::Option* option : command.get_options()) {
    if (option->count() == 0) continue;
    for (const std::string& name : option->get_lnames()) {
      const std::string flag = "--" + name;
      const bool output = IsOutputFileFlag(flag);
      if (!output && InputFileRole(flag).empty()) continue;
      for (const std::string& value : option->results()) {
        if (!output || value != "-") files.push_back({flag, value, output});  // an output '-' is stdout
      }
      break;
    }
  }
  for (const CLI::App* sub : command.get_subcommands()) CollectNamedFiles(*sub, files);
}

}  // namespace

bool IsOutputFileFlag(std::string_view long_flag) noexcept {
  static constexpr std::array<std::string_view, 8> kOutputs{
      "--report", "--csv", "--samples-csv", "--history", "--plot", "--tolerance-plot", "--output", "--thickness-plot"};
  return std::find(kOutputs.begin(), kOutputs.end(), long_flag) != kOutputs.end();
}

std::optional<std::string> OutputPathClash(const CLI::App& app) {
  std::vector<NamedFile> files;
  CollectNamedFiles(app, files);
  std::vector<std::optional<FileIdentity>> identities;
  for (const NamedFile& file : files) identities.push_back(IdentifyFile(file.path));
  for (std::size_t o = 0; o < files.size(); ++o) {
    if (!files[o].output || !identities[o] || identities[o]->character_device) continue;
    // Every input, and the outputs before this one (each pair once).
    for (std::size_t other = 0; other < files.size(); ++other) {
      if (other == o || (files[other].output && other > o) || identities[other] != identities[o]) continue;
      const NamedFile& a = files[other];
      const NamedFile& b = files[o];
      const std::string same = a.path == b.path ? fmt::format("'{}'", a.path)
                                                : fmt::format("'{}' and '{}'", a.path, b.path);
      if (!a.output) {
        return fmt::format("{} and {} name the same file ({}): the output would overwrite the input; "
                           "write {} to another path", a.flag, b.flag, same, b.flag);
      }
      return fmt::format("{} and {} name the same file ({}): one output would replace the other; "
                         "give each output its own path", a.flag, b.flag, same);
    }
  }
  return std::nullopt;
}

std::string_view InputFileRole(std::string_view long_flag) noexcept {
  static constexpr std::array<std::pair<std::string_view, std::string_view>, 8> kRoles{{
      {"--limits", "limits"},
      {"--scene", "scene"},
      {"--catalog", "catalog"},
      {"--urdf", "urdf"},
      {"--trajectory", "trajectory"},
      {"--surface-file", "surface"},
      {"--link-coverings", "link-coverings"},
      {"--exposure", "exposure"},
  }};
  for (const auto& [flag, role] : kRoles) {
    if (flag == long_flag) return role;
  }
  return {};
}

RunContext MakeRunContext(const CLI::App& app, std::span<const char* const> argv) {
  RunContext run;
  run.command_line = report::CommandLine(argv);
  std::vector<NamedFile> files;
  CollectNamedFiles(app, files);
  for (const NamedFile& file : files) {
    if (!file.output) run.input_files.push_back({std::string(InputFileRole(file.flag)), file.path});
  }
  return run;
}

std::string WithRunProvenance(const std::string& json_object, const std::optional<RunContext>& run) {
  if (!run) return json_object;
  return report::WithProvenance(json_object, report::MakeProvenance(run->command_line, run->input_files));
}

}  // namespace covopt::cli
