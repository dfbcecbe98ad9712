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
#include <fmt/ranges.h>

#include "covopt/core/impact_model.hpp"

#include "errors.hpp"
#include "output.hpp"

extern char** environ;  // NOLINT: POSIX, for posix_spawnp

namespace covopt::cli {
namespace {

/// A temporary file made by mkstemp, removed when this goes out of scope, or by the
/// SIGINT/SIGTERM/SIGHUP handlers (RegisterTemporaryFile) should the process be ended.
class TempFile {
 public:
  /// Creates "<directory>/<prefix>XXXXXX". @throws OutputError.
  TempFile(const std::filesystem::path& directory, std::string_view prefix)
      : path_((directory / fmt::format("{}XXXXXX", prefix)).string()) {
    const int fd = ::mkstemp(path_.data());
    if (fd >= 0) slot_ = RegisterTemporaryFile(path_);
    if (fd < 0) {
      throw OutputError(fmt::format("cannot create a temporary file in '{}': {}",
                                    directory.string(), std::strerror(errno)));
    }
    ::close(fd);
  }
  ~TempFile() {
    if (!path_.empty()) ::unlink(path_.c_str());
    UnregisterTemporaryFile(slot_);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;

  const std::string& path() const noexcept { return path_; }

 private:
  std::string path_;
  int slot_ = -1;
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
  const ImpactModel model = ImpactModel::FromScene(report.scene);
  // σ_t = σ_c (1 - 2ν_t)/3: the chart shows the stress the laceration limit judges; the
  // axis label gives the factor back to the compressive stress.
  const double tensile_per_compressive = model.TensileFromCompressive(1.0);
  const InjuryVerdict& lac = report.assessment.laceration;
  const InjuryVerdict& con = report.assessment.contusion;
  const std::string blue = "#1f5fa8";
  const std::string red = "#c0392b";
  const std::string green = "#2e8b57";
  std::string s;
  s += "set encoding utf8\n";
  s += GnuplotTerminal(format, 1100, 900);
  s += fmt::format("set output {}\n", SingleQuoted(output_path));
  std::string title = fmt::format("covopt simulate: {}", SceneHeadline(report.scene));
  if (const auto details = SceneDetailsBeyondHeadline(report.scene); !details.empty()) {
    title += fmt::format("; {}", fmt::join(details, ", "));
  }
  title += fmt::format(
      "\npeak force {:.4g} N; max tensile stress {:.4g} MPa (laceration ratio {:.3g}); max "
      "energy density {:.4g} J/cm² (contusion ratio {:.3g})\n{}, {} history samples",
      r.peaks.peak_force_N, r.peaks.max_tensile_stress_Pa / 1e6, lac.ratio,
      r.peaks.max_energy_density_J_per_m2 / 1e4, con.ratio, ToString(r.method),
      r.history.size());
  s += "$history << EOD\n";
  for (const HistorySample& h : r.history) {
    const double t_ms = h.time_s * 1e3;
    const double tensile_MPa = model.TensileFromCompressive(h.compressive_stress_Pa) / 1e6;
    const double energy_density_J_per_cm2 = h.energy_density_J_per_m2 / 1e4;
    if (!std::isfinite(t_ms) || !std::isfinite(h.force_N) || !std::isfinite(tensile_MPa) ||
        !std::isfinite(energy_density_J_per_cm2)) {
      continue;
    }
    s += fmt::format("{} {} {} {}\n", t_ms, h.force_N, tensile_MPa, energy_density_J_per_cm2);
  }
  s += "EOD\n";

  // Two panels sharing the time axis: force and tensile stress with the laceration limit,
  // then energy density with the contusion limit. Fixed margins keep the time axes aligned
  // and leave room for the two title lines.
  s += fmt::format("set multiplot title {}\n", DoubleQuoted(title));
  s += "set lmargin 12\nset rmargin 14\n";
  s += "set xrange [0:*]\nset autoscale xfix\nset xtics nomirror\n";
  s += "set grid xtics ytics linecolor rgb '#dddddd'\n";
  // The key in two rows across the top of each panel; every axis reaches about a third past
  // its highest curve or line, so the key sits above them. The force axis has more room
  // than the stress axis so that its peak does not sit on the laceration limit's line.
  constexpr double kHeadroom = 1.3;
  constexpr double kForceHeadroom = 1.5;
  s += "set key inside top center horizontal maxcols 2 width 1 opaque box linecolor rgb "
       "'#cccccc'\n";
  if (r.time_of_max_compression_s && std::isfinite(*r.time_of_max_compression_s)) {
    const double t_ms = *r.time_of_max_compression_s * 1e3;
    s += fmt::format(
        "set arrow 1 from {0}, graph 0 to {0}, graph 1 nohead dashtype 3 linecolor rgb '#777777'\n"
        "set label 1 'max compression' at {0}, graph 0.04 offset 0.5, 0 textcolor rgb '#555555'\n",
        t_ms);
  }

  // Top panel.
  s += "set size 1, 0.55\nset origin 0, 0.38\nset tmargin 1\nset bmargin 1\n";
  s += "set format x ''\nunset xlabel\n";
  s += fmt::format("set ylabel 'force [N]' textcolor rgb '{}'\n", blue);
  s += fmt::format(
      "set y2label 'tensile stress σ_t [MPa]  (compressive σ_c = {:.4g} σ_t)' textcolor rgb '{}'\n",
      1.0 / tensile_per_compressive, red);
  s += fmt::format("set ytics nomirror textcolor rgb '{}'\n", blue);
  s += fmt::format("set y2tics nomirror textcolor rgb '{}'\n", red);
  s += fmt::format("set yrange [0:{}]\nset y2range [0:{}]\nset border 11\n",
                   kForceHeadroom * r.peaks.peak_force_N,
                   kHeadroom * std::max(r.peaks.max_tensile_stress_Pa, lac.limit) / 1e6);
  // With a safety factor, the derated limit (the one the verdict uses) beside the limit.
  const double sf = report.safety_factor;
  const auto derated = [&](double limit, std::string_view unit, std::string_view colour,
                           std::string_view axes) {
    if (sf == 1.0) return std::string();
    return fmt::format(
        ", \\\n     {} {} with lines linewidth 1.5 dashtype 3 linecolor rgb '{}' "
        "title 'derated limit {:.4g} {} (limit / safety factor {:g})'",
        limit / sf, axes, colour, limit / sf, unit, sf);
  };
  s += fmt::format(
      "plot $history using 1:2 axes x1y1 with lines linewidth 2 linecolor rgb '{0}' "
      "title 'force [N] (left axis)', \\\n"
      "     $history using 1:3 axes x1y2 with lines linewidth 2 dashtype 2 linecolor rgb '{1}' "
      "title 'tensile stress [MPa] (right axis)', \\\n"
      "     {2} axes x1y2 with lines linewidth 1.5 dashtype 4 linecolor rgb '{1}' "
      "title 'laceration limit {3:g} MPa (tensile)'{4}\n",
      blue, red, lac.limit / 1e6, lac.limit / 1e6, derated(lac.limit / 1e6, "MPa", red, "axes x1y2"));

  // Bottom panel.
  s += "set size 1, 0.38\nset origin 0, 0\nset tmargin 0.5\nset bmargin 3.5\n";
  s += "set format x '% h'\nset xlabel 'time [ms]'\n";
  s += fmt::format("set ylabel 'energy density [J/cm²]' textcolor rgb '{}'\n", green);
  s += fmt::format("set ytics mirror textcolor rgb '{}'\n", green);
  s += fmt::format("unset y2label\nunset y2tics\nset border 15\nset yrange [0:{}]\n",
                   kHeadroom * std::max(r.peaks.max_energy_density_J_per_m2, con.limit) / 1e4);
  s += fmt::format(
      "plot $history using 1:4 with lines linewidth 2 linecolor rgb '{0}' "
      "title 'energy density [J/cm²]', \\\n"
      "     {1} with lines linewidth 1.5 dashtype 4 linecolor rgb '#000000' "
      "title 'contusion limit {2:g} J/cm²'{3}\n",
      green, con.limit / 1e4, con.limit / 1e4, derated(con.limit / 1e4, "J/cm²", "#000000", ""));
  s += "unset multiplot\nunset output\n";
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

  // The target is checked (and its temporary made) before gnuplot runs, by the one file
  // writer's rules (OutputFile, cli/output.hpp); gnuplot draws into a scratch file that is
  // then copied into it.
  OutputFile file(path);
  std::error_code ec;
  const std::filesystem::path temp_directory = std::filesystem::temp_directory_path(ec);
  if (ec) throw OutputError(fmt::format("no temporary directory: {}", ec.message()));
  TempFile output(temp_directory, "covopt-plot-output-");
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

  std::ifstream drawn(output.path(), std::ios::binary);
  std::ostringstream bytes;
  bytes << drawn.rdbuf();
  if (!drawn) {
    throw OutputError(fmt::format("gnuplot failed to draw '{}': cannot read its output", target));
  }
  file.Write(bytes.str());
  file.Commit();
}

}  // namespace covopt::cli
