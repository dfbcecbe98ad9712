#pragma once
// Helpers for the CLI tests: run `covopt ...` in-process and capture what it prints, and a
// temporary directory that removes itself.

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "app.hpp"

namespace covopt::cli::testing {

/// What one run of the program produced.
struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

/// Runs `covopt <args...>` through RunCli (argv[0] is added).
inline CliRun Run(std::vector<std::string> args) {
  args.insert(args.begin(), "covopt");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  CliRun run;
  run.exit_code = RunCli(static_cast<int>(argv.size()), argv.data(), out, err);
  run.out = out.str();
  run.err = err.str();
  return run;
}

/// A JSON object the CLI printed without its "provenance" block (the run's command line and
/// date: test_provenance_cli.cpp checks it) and its "input_sources" (the flags of the run:
/// test_report_option.cpp checks them), to compare with the library's *Json or another run.
template <class JsonType>
JsonType WithoutProvenance(JsonType j) {
  j.erase("provenance");
  j.erase("input_sources");
  return j;
}

/// The same for the printed text: a JSON object is dumped again (indent 2) without the block;
/// any other text is returned as it is.
inline std::string WithoutProvenance(const std::string& out) {
  const nlohmann::ordered_json j = nlohmann::ordered_json::parse(out, nullptr, false);
  if (j.is_discarded() || !j.is_object()) return out;
  return WithoutProvenance(j).dump(2) + "\n";
}

/// A fresh directory under the system's temporary directory, removed with its contents.
class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    std::random_device random;
    path_ = std::filesystem::temp_directory_path() /
            ("covopt-cli-test-" + std::to_string(::getpid()) + "-" +
             std::to_string(counter++) + "-" + std::to_string(random()));
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

  /// Writes a file in the directory and returns its path.
  std::filesystem::path Write(const std::string& name, const std::string& content) const {
    const auto file = path_ / name;
    std::ofstream(file, std::ios::binary) << content;
    return file;
  }

 private:
  std::filesystem::path path_;
};

/// Sets an environment variable for the scope, restoring the old value after.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (old_) {
      ::setenv(name_, old_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

/// The lines of a text (without their line ends).
inline std::vector<std::string> SplitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

inline std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace covopt::cli::testing
