#include "plot.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include "errors.hpp"

extern char** environ;  // NOLINT: POSIX, for posix_spawnp

namespace covopt::cli {
namespace {

/// A temporary file made by mkstemp, removed when this goes out of scope.
class TempFile {
 public:
  /// Creates "<directory>/<prefix>XXXXXX". @throws OutputError.
  TempFile(const std::filesystem::path& directory, std::string_view prefix)
      : path_((directory / fmt::format("{}XXXXXX", prefix)).string()) {
    const int fd = ::mkstemp(path_.data());
    if (fd < 0) {
      throw OutputError(fmt::format("cannot create a temporary file in '{}': {}",
                                    directory.string(), std::strerror(errno)));
    }
    ::close(fd);
  }
  ~TempFile() {
    if (!path_.empty()) ::unlink(path_.c_str());
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  const std::string& path() const noexcept { return path_; }
  /// Keeps the file (after it has been renamed away).
  void Release() noexcept { path_.clear(); }

 private:
  std::string path_;
};

/// A gnuplot single-quoted string: no escapes except '' for a quote.
std::string SingleQuoted(std::string_view text) {
  std::string quoted = "'";
  for (const char c : text) {
    quoted += c;
    if (c == '\'') quoted += '\'';
  }
  return quoted + "'";
}

/// A gnuplot double-quoted string, in which \n is a line break.
std::string DoubleQuoted(std::string_view text) {
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

}  // namespace

std::optional<PlotFormat> PlotFormatFor(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".png") return PlotFormat::kPng;
  if (extension == ".svg") return PlotFormat::kSvg;
  return std::nullopt;
}

std::optional<std::filesystem::path> FindOnPath(std::string_view name) {
  const char* const path_variable = std::getenv("PATH");
  if (path_variable == nullptr) return std::nullopt;
  std::string_view directories = path_variable;
  while (true) {
    const std::size_t colon = directories.find(':');
    const std::string_view directory = directories.substr(0, colon);
    // An empty entry means the current directory (POSIX).
    const std::filesystem::path candidate =
        std::filesystem::path(directory.empty() ? "." : std::string(directory)) / name;
    std::error_code ec;
    if (std::filesystem::is_regular_file(candidate, ec) &&
        ::access(candidate.c_str(), X_OK) == 0) {
      return candidate;
    }
    if (colon == std::string_view::npos) break;
    directories.remove_prefix(colon + 1);
  }
  return std::nullopt;
}

std::string GnuplotScript(const SimulationReport& report, PlotFormat format,
                          const std::string& output_path) {
  const ImpactResult& r = report.result;
  const std::string blue = "#1f5fa8";
  const std::string red = "#c0392b";
  std::string s;
  s += "set encoding utf8\n";
  s += GnuplotTerminal(format, 1100, 650);
  s += fmt::format("set output {}\n", SingleQuoted(output_path));
  s += fmt::format(
      "set title {}\n",
      DoubleQuoted(fmt::format(
          "covopt simulate: {}\npeak force {:.4g} N, max compressive stress {:.4g} MPa "
          "({}, {} history samples)",
          SceneHeadline(report.scene), r.peaks.peak_force_N,
          r.peaks.max_compressive_stress_Pa / 1e6, ToString(r.method), r.history.size())));
  s += "set xlabel 'time [ms]'\n";
  s += fmt::format("set ylabel 'force [N]' textcolor rgb '{}'\n", blue);
  s += fmt::format("set y2label 'compressive stress [MPa]' textcolor rgb '{}'\n", red);
  s += fmt::format("set ytics nomirror textcolor rgb '{}'\n", blue);
  s += fmt::format("set y2tics nomirror textcolor rgb '{}'\n", red);
  s += "set xtics nomirror\n";
  s += "set yrange [0:*]\nset y2range [0:*]\nset xrange [0:*]\n";
  s += "set grid xtics ytics linecolor rgb '#dddddd'\n";
  s += "set key outside below center horizontal\n";
  s += "set border 11\n";
  if (r.time_of_max_compression_s && std::isfinite(*r.time_of_max_compression_s)) {
    const double t_ms = *r.time_of_max_compression_s * 1e3;
    s += fmt::format(
        "set arrow from {0}, graph 0 to {0}, graph 1 nohead dashtype 3 linecolor rgb '#777777'\n"
        "set label 'max compression' at {0}, graph 0.04 offset 0.5, 0 textcolor rgb '#555555'\n",
        t_ms);
  }
  s += "$history << EOD\n";
  for (const HistorySample& h : r.history) {
    const double t_ms = h.time_s * 1e3;
    const double stress_MPa = h.compressive_stress_Pa / 1e6;
    if (!std::isfinite(t_ms) || !std::isfinite(h.force_N) || !std::isfinite(stress_MPa)) continue;
    s += fmt::format("{} {} {}\n", t_ms, h.force_N, stress_MPa);
  }
  s += "EOD\n";
  s += fmt::format(
      "plot $history using 1:2 axes x1y1 with lines linewidth 2 linecolor rgb '{}' "
      "title 'force [N] (left axis)', \\\n"
      "     $history using 1:3 axes x1y2 with lines linewidth 2 dashtype 2 linecolor rgb '{}' "
      "title 'compressive stress [MPa] (right axis)'\n",
      blue, red);
  s += "unset output\n";
  return s;
}

std::string GnuplotQuoted(std::string_view text) { return SingleQuoted(text); }

std::string GnuplotTerminal(PlotFormat format, int width, int height) {
  if (format == PlotFormat::kPng) {
    return fmt::format("set terminal pngcairo size {},{} font 'sans,11' noenhanced\n", width,
                       height);
  }
  return fmt::format(
      "set terminal svg size {},{} dynamic font 'sans,11' noenhanced background rgb 'white'\n",
      width, height);
}

void PlotHistory(const std::filesystem::path& path, const SimulationReport& report,
                 PlotFormat format) {
  if (report.result.history.empty()) {
    throw OutputError(
        fmt::format("cannot plot '{}': the result has no history", path.string()));
  }
  RunGnuplot(path, [&](const std::string& output_path) {
    return GnuplotScript(report, format, output_path);
  });
}

void RunGnuplot(const std::filesystem::path& path,
                const std::function<std::string(const std::string& output_path)>& make_script) {
  const std::string target = path.string();
  if (!FindOnPath("gnuplot")) throw OutputError(std::string(kGnuplotMissing));

  const std::filesystem::path directory =
      path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  TempFile output(directory, fmt::format(".{}.tmp-", path.filename().string()));
  std::error_code ec;
  const std::filesystem::path temp_directory = std::filesystem::temp_directory_path(ec);
  if (ec) throw OutputError(fmt::format("no temporary directory: {}", ec.message()));
  TempFile script(temp_directory, "covopt-plot-");
  TempFile log(temp_directory, "covopt-gnuplot-log-");
  {
    std::ofstream out(script.path(), std::ios::binary);
    out << make_script(output.path());
    if (!out.flush()) {
      throw OutputError(fmt::format("cannot write the gnuplot script '{}'", script.path()));
    }
  }

  // gnuplot SCRIPT, stdin from /dev/null, stdout and stderr into the log. No shell.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.path().c_str(), O_WRONLY | O_TRUNC, 0);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  std::string program = "gnuplot";
  std::string script_path = script.path();
  char* argv[] = {program.data(), script_path.data(), nullptr};
  pid_t pid = 0;
  const int spawn_error = ::posix_spawnp(&pid, "gnuplot", &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawn_error == ENOENT) throw OutputError(std::string(kGnuplotMissing));
  if (spawn_error != 0) {
    throw OutputError(fmt::format("cannot run gnuplot: {}", std::strerror(spawn_error)));
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      throw OutputError(fmt::format("waiting for gnuplot: {}", std::strerror(errno)));
    }
  }
  const bool exited_ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  std::error_code size_ec;
  const auto size = std::filesystem::file_size(output.path(), size_ec);
  if (!exited_ok || size_ec || size == 0) {
    const std::string how = WIFEXITED(status)   ? fmt::format("exit code {}", WEXITSTATUS(status))
                            : WIFSIGNALED(status) ? fmt::format("signal {}", WTERMSIG(status))
                                                  : std::string("unknown status");
    const std::string messages = ReadTail(log.path(), 8);
    throw OutputError(fmt::format("gnuplot failed to draw '{}' ({}{}){}{}", target, how,
                                  exited_ok ? ", empty output" : "",
                                  messages.empty() ? "" : ":\n", messages));
  }

  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::chmod(output.path().c_str(), 0666 & ~mask);
  if (::rename(output.path().c_str(), target.c_str()) != 0) {
    throw OutputError(fmt::format("cannot write '{}': {}", target, std::strerror(errno)));
  }
  output.Release();
}

}  // namespace covopt::cli
