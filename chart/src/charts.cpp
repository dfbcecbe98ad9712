// gnuplot as a child process: every chart of a call in one run, in a private temporary
// directory that is removed on every path out.
#include "covopt/chart/charts.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include "chart_script.hpp"

extern char** environ;  // NOLINT: POSIX, for posix_spawnp

namespace covopt::chart {

using report::SvgChart;
namespace {

/// A private directory (mkdtemp, 0700) and the files made in it, all removed (files first)
/// when this goes out of scope; the observer hears of each.
class ScratchDirectory {
 public:
  explicit ScratchDirectory(const ScratchObserver& observer) : observer_(observer) {
    std::error_code ec;
    const std::filesystem::path base = std::filesystem::temp_directory_path(ec);
    if (ec) throw std::runtime_error(fmt::format("no temporary directory for the charts: {}", ec.message()));
    std::string name = (base / "covopt-charts-XXXXXX").string();
    if (::mkdtemp(name.data()) == nullptr) {
      throw std::runtime_error(
          fmt::format("cannot create a temporary directory in '{}': {}", base.string(), std::strerror(errno)));
    }
    directory_ = {name, Made(name)};
  }
  ~ScratchDirectory() {
    for (auto it = files_.rbegin(); it != files_.rend(); ++it) {
      ::unlink(it->first.c_str());
      Removed(it->second);
    }
    ::rmdir(directory_.first.c_str());
    Removed(directory_.second);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;

  /// Creates the empty file `name` in the directory and returns its path.
  const std::string& MakeFile(const std::string& name) {
    std::string path = directory_.first + "/" + name;
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0) throw std::runtime_error(fmt::format("cannot create '{}': {}", path, std::strerror(errno)));
    ::close(fd);
    const int token = Made(path);
    files_.emplace_back(std::move(path), token);
    return files_.back().first;
  }

 private:
  int Made(const std::string& path) const { return observer_.made ? observer_.made(path) : -1; }
  void Removed(int token) const noexcept {
    if (observer_.removed) observer_.removed(token);
  }

  const ScratchObserver& observer_;
  std::pair<std::string, int> directory_;
  std::vector<std::pair<std::string, int>> files_;
};

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

/// The last `max_lines` non-empty lines of a file.
std::string ReadTail(const std::string& path, std::size_t max_lines) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) lines.push_back(line);
  }
  const std::size_t first = lines.size() > max_lines ? lines.size() - max_lines : 0;
  std::string tail;
  for (std::size_t i = first; i < lines.size(); ++i) {
    if (!tail.empty()) tail += '\n';
    tail += lines[i];
  }
  return tail;
}

/// Runs `gnuplot SCRIPT` (no shell), stdin from /dev/null, stdout and stderr into `log`;
/// returns its wait status.
int RunGnuplot(const std::string& script, const std::string& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_TRUNC, 0);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::string program = "gnuplot";
  std::string script_path = script;
  char* argv[] = {program.data(), script_path.data(), nullptr};
  pid_t pid = 0;
  const int spawn_error = ::posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawn_error == ENOENT) throw std::runtime_error(std::string(kGnuplotMissing));
  if (spawn_error != 0) throw std::runtime_error(fmt::format("cannot run gnuplot: {}", std::strerror(spawn_error)));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error(fmt::format("waiting for gnuplot: {}", std::strerror(errno)));
  }
  return status;
}

}  // namespace

std::string GnuplotQuoted(std::string_view text) {
  std::string quoted = "'";
  for (const char c : text) {
    quoted += c;
    if (c == '\'') quoted += '\'';
  }
  return quoted + "'";
}

std::string GnuplotTerminal(ChartFormat format, int width_px, int height_px) {
  if (format == ChartFormat::kPng) {
    return fmt::format("set terminal pngcairo size {},{} font 'sans,11' noenhanced\n", width_px, height_px);
  }
  return fmt::format("set terminal svg size {},{} dynamic font 'sans,11' noenhanced background rgb 'white'\n",
                     width_px, height_px);
}

std::vector<std::string> DrawCharts(std::span<const GnuplotChart> charts, ChartFormat format,
                                    const ScratchObserver& observer) {
  if (charts.empty()) return {};
  if (!report::FindOnPath("gnuplot")) throw std::runtime_error(std::string(kGnuplotMissing));
  const std::string_view extension = format == ChartFormat::kPng ? "png" : "svg";
  ScratchDirectory scratch(observer);
  std::vector<std::string> outputs;
  for (std::size_t i = 0; i < charts.size(); ++i) {
    outputs.push_back(scratch.MakeFile(fmt::format("chart-{}.{}", i + 1, extension)));
  }
  const std::string script_path = scratch.MakeFile("charts.gp");
  const std::string log_path = scratch.MakeFile("gnuplot.log");
  {
    std::string script;
    for (std::size_t i = 0; i < charts.size(); ++i) {
      // Each chart starts from gnuplot's defaults: nothing of the one before leaks into it.
      if (i > 0) script += "reset session\n";
      script += charts[i].script(format, outputs[i]);
      script += "\nunset output\n";
    }
    std::ofstream out(script_path, std::ios::binary);
    out << script;
    if (!out.flush()) throw std::runtime_error(fmt::format("cannot write the gnuplot script '{}'", script_path));
  }

  const int status = RunGnuplot(script_path, log_path);
  const bool exited_ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  std::vector<std::string> drawn;
  for (std::size_t i = 0; i < charts.size(); ++i) {
    drawn.push_back(ReadFile(outputs[i]));
    if (exited_ok && !drawn.back().empty()) continue;
    // The first chart not drawn is where gnuplot stopped.
    if (!exited_ok && !drawn.back().empty() && i + 1 < charts.size()) continue;
    const std::string how = WIFEXITED(status)     ? fmt::format("exit code {}", WEXITSTATUS(status))
                            : WIFSIGNALED(status) ? fmt::format("signal {}", WTERMSIG(status))
                                                  : std::string("unknown status");
    const std::string messages = ReadTail(log_path, 8);
    throw std::runtime_error(fmt::format("gnuplot failed to draw '{}' ({}{}){}{}", charts[i].title, how,
                                         exited_ok ? ", empty output" : "", messages.empty() ? "" : ":\n",
                                         messages));
  }
  return drawn;
}

std::vector<SvgChart> DrawSvgCharts(std::span<const GnuplotChart> charts, const ScratchObserver& observer) {
  std::vector<std::string> svg = DrawCharts(charts, ChartFormat::kSvg, observer);
  std::vector<SvgChart> out;
  for (std::size_t i = 0; i < charts.size(); ++i) out.push_back({charts[i].title, charts[i].caption, std::move(svg[i])});
  return out;
}

namespace internal {

GnuplotChart MakeChart(std::string title, std::string caption, int width_px, int height_px, std::string body) {
  GnuplotChart chart;
  chart.title = std::move(title);
  chart.caption = std::move(caption);
  chart.script = [width_px, height_px, body = std::move(body)](ChartFormat format, const std::string& output_path) {
    return "set encoding utf8\n" + GnuplotTerminal(format, width_px, height_px) +
           fmt::format("set output {}\n", GnuplotQuoted(output_path)) + body;
  };
  return chart;
}

std::string GnuplotDoubleQuoted(std::string_view text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '\n') {
      quoted += "\\n";
      continue;
    }
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

}  // namespace internal
}  // namespace covopt::chart
