#include "covopt/report/pdf_print.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include <fcntl.h>
#include <spawn.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "covopt/internal/text.hpp"
#include "covopt/report/find_on_path.hpp"

// After the project headers: <csignal> (and <sys/wait.h>, which includes it) defines macros
// (si_value) that clash with their parameter names.
#include <csignal>
#include <sys/wait.h>

extern char** environ;  // NOLINT: POSIX, for posix_spawn

namespace covopt::report {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// The signals that end the process (the CLI's handlers remove its temporaries on them).
constexpr int kEndingSignals[] = {SIGINT, SIGTERM, SIGHUP};

/// Blocks SIGINT, SIGTERM, SIGHUP and SIGCHLD for its lifetime, so that the wait for the
/// browser receives them with sigtimedwait instead of dying with a temporary directory (a
/// tree of files the unlink-only signal handlers cannot remove) and a browser left behind.
/// A signal still pending when the mask is restored is delivered then.
class SignalBlock {
 public:
  SignalBlock() {
    sigemptyset(&blocked_);
    sigemptyset(&awaited_);
    for (const int signal_number : kEndingSignals) {
      sigaddset(&blocked_, signal_number);
      // An ignored signal (nohup's SIGHUP) stays ignored: Linux queues even an ignored signal
      // while it is blocked, so it is not waited for, and is discarded on unblocking.
      struct sigaction current {};
      if (::sigaction(signal_number, nullptr, &current) == 0 &&
          ((current.sa_flags & SA_SIGINFO) != 0 || current.sa_handler != SIG_IGN)) {
        sigaddset(&awaited_, signal_number);
      }
    }
    sigaddset(&blocked_, SIGCHLD);
    sigaddset(&awaited_, SIGCHLD);
    ::pthread_sigmask(SIG_BLOCK, &blocked_, &previous_);
  }
  ~SignalBlock() { ::pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }
  SignalBlock(const SignalBlock&) = delete;
  SignalBlock& operator=(const SignalBlock&) = delete;

  /// The signals a wait returns on: the ending ones not ignored, and SIGCHLD.
  const sigset_t& awaited() const noexcept { return awaited_; }

 private:
  sigset_t blocked_{};
  sigset_t awaited_{};
  sigset_t previous_{};
};

/// A private directory made by mkdtemp (mode 0700), removed with its contents when this goes
/// out of scope.
class PrivateDirectory {
 public:
  PrivateDirectory() {
    std::error_code ec;
    const fs::path base = fs::temp_directory_path(ec);
    if (ec) throw OutputError(fmt::format("no temporary directory: {}", ec.message()));
    std::string pattern = (base / "covopt-report-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) {
      throw OutputError(fmt::format("cannot create a temporary directory in '{}': {}",
                                    base.string(), std::strerror(errno)));
    }
    path_ = pattern;
  }
  ~PrivateDirectory() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  PrivateDirectory(const PrivateDirectory&) = delete;
  PrivateDirectory& operator=(const PrivateDirectory&) = delete;

  fs::path operator/(std::string_view name) const { return path_ / name; }
  const fs::path& path() const noexcept { return path_; }

 private:
  fs::path path_;
};

/// How a browser run ended.
struct BrowserRun {
  int status = 0;          // waitpid's status (when neither timed out nor interrupted)
  bool timed_out = false;  // killed by the watchdog
  int interrupting_signal = 0;  // SIGINT, SIGTERM or SIGHUP received meanwhile (it was killed)
};

/// Whether a process of process group `group` is still alive (not a zombie), by /proc: an
/// orphaned zombie may wait long for a container's init to reap it, and holds no file.
bool GroupHasLiveProcess(pid_t group) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator("/proc", ec)) {
    const std::string name = entry.path().filename().string();
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name.front())) == 0) continue;
    std::ifstream in(entry.path() / "stat");
    std::string stat;
    std::getline(in, stat);
    // "pid (comm) state ppid pgrp ...": comm may hold spaces and parentheses.
    const std::size_t close = stat.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream fields(stat.substr(close + 1));
    char state = 0;
    long parent = 0, process_group = 0;
    if (!(fields >> state >> parent >> process_group)) continue;
    if (process_group == group && state != 'Z' && state != 'X') return true;
  }
  return false;
}

/// Kills the browser's whole process group (its renderer, zygote and crash handler
/// processes with it) and reaps the browser; waits (up to 2 s) for the group's other processes
/// to be gone, so that none still writes into the temporary directory as it is removed.
void KillAndReap(pid_t pid, int* status) {
  ::kill(-pid, SIGKILL);
  while (::waitpid(pid, status, 0) < 0 && errno == EINTR) {
  }
  const auto give_up = Clock::now() + std::chrono::seconds(2);
  while (GroupHasLiveProcess(pid) && Clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

/// The environment of the browser: ours, with XDG_CONFIG_HOME and XDG_CACHE_HOME in the
/// private directory, where Chromium's crash handler keeps its database ("chromium/Crash
/// Reports", which --user-data-dir does not move), so that nothing is written into $HOME.
std::vector<std::string> BrowserEnvironment(const fs::path& directory) {
  std::vector<std::string> environment;
  for (char** variable = environ; *variable != nullptr; ++variable) {
    const std::string_view entry = *variable;
    if (entry.rfind("XDG_CONFIG_HOME=", 0) == 0 || entry.rfind("XDG_CACHE_HOME=", 0) == 0) {
      continue;
    }
    environment.emplace_back(entry);
  }
  environment.push_back("XDG_CONFIG_HOME=" + (directory / "config").string());
  environment.push_back("XDG_CACHE_HOME=" + (directory / "cache").string());
  return environment;
}

/// Runs `argv` (argv[0] an absolute path; no shell) with `environment` in a process group of
/// its own, stdin from /dev/null, stdout and stderr into `log`, until it exits, `timeout`
/// passes or an ending signal arrives. The caller holds a SignalBlock.
BrowserRun RunBrowser(std::vector<std::string> argv, std::vector<std::string> environment,
                      const fs::path& log, std::chrono::milliseconds timeout,
                      const SignalBlock& signals) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  // The child starts with no signal blocked and the ending signals at their default action.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  for (const int signal_number : kEndingSignals) sigaddset(&defaults, signal_number);
  sigaddset(&defaults, SIGCHLD);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setpgroup(&attributes, 0);
  posix_spawnattr_setflags(&attributes,
                           POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETPGROUP);
  std::vector<char*> args;
  for (std::string& arg : argv) args.push_back(arg.data());
  args.push_back(nullptr);
  std::vector<char*> variables;
  for (std::string& variable : environment) variables.push_back(variable.data());
  variables.push_back(nullptr);
  pid_t pid = 0;
  const int spawn_error = ::posix_spawn(&pid, argv.front().c_str(), &actions, &attributes,
                                        args.data(), variables.data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (spawn_error != 0) {
    throw OutputError(
        fmt::format("cannot run '{}': {}", argv.front(), std::strerror(spawn_error)));
  }

  BrowserRun run;
  const auto deadline = Clock::now() + timeout;
  while (true) {
    // Has it exited? (WNOWAIT: not reaped yet, so its process group id stays its own until
    // the group has been killed.)
    siginfo_t info{};
    if (::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
        info.si_pid == pid) {
      break;
    }
    const auto left = deadline - Clock::now();
    if (left <= Clock::duration::zero()) {
      run.timed_out = true;
      break;
    }
    const auto wait = std::min<Clock::duration>(left, std::chrono::milliseconds(100));
    const auto wait_ns = std::chrono::duration_cast<std::chrono::nanoseconds>(wait).count();
    struct timespec slice {};
    slice.tv_sec = static_cast<time_t>(wait_ns / 1'000'000'000);
    slice.tv_nsec = static_cast<long>(wait_ns % 1'000'000'000);
    const int received = ::sigtimedwait(&signals.awaited(), nullptr, &slice);
    if (received > 0 && received != SIGCHLD) {
      run.interrupting_signal = received;
      break;
    }
  }
  KillAndReap(pid, &run.status);
  return run;
}

/// The last `max_lines` non-empty lines of a browser's log, without Chromium's complaints
/// about a missing D-Bus (printed on every run in a container, never the reason it failed).
std::vector<std::string> LogTail(const fs::path& log, std::size_t max_lines) {
  std::ifstream in(log);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line.find(":ERROR:dbus/") != std::string::npos) continue;
    lines.push_back(line);
  }
  if (lines.size() > max_lines) lines.erase(lines.begin(), lines.end() - static_cast<std::ptrdiff_t>(max_lines));
  return lines;
}

/// The browser failed: one line with its status and what to do, its last lines as details.
[[noreturn]] void BrowserFailed(const fs::path& browser, const std::string& target, const std::string& status,
                                const fs::path& log) {
  std::vector<std::string> tail = LogTail(log, kChromiumLogLines);
  const std::string message = fmt::format(
      "chromium ('{}') failed to print '{}': {}; {}write --report FILE.html for the same report without a browser",
      browser.string(), target, status, tail.empty() ? "" : "its last lines follow; ");
  throw OutputError(message, "chromium", std::move(tail));
}

/// A file: URL for an absolute path, every byte but unreserved ones and '/' percent-encoded.
std::string FileUrl(const fs::path& path) {
  std::string url = "file://";
  for (const char c : path.string()) {
    const auto byte = static_cast<unsigned char>(c);
    if (std::isalnum(byte) != 0 || c == '/' || c == '-' || c == '.' || c == '_' || c == '~') {
      url += c;
    } else {
      url += fmt::format("%{:02X}", byte);
    }
  }
  return url;
}

bool IsExecutableFile(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec) && ::access(path.c_str(), X_OK) == 0;
}

std::string Describe(const BrowserRun& run, std::chrono::milliseconds timeout) {
  if (run.timed_out) {
    const auto ms = timeout.count();
    return fmt::format("did not finish within {} and was killed (COVOPT_CHROMIUM_TIMEOUT sets the limit)",
                       ms % 1000 == 0 ? fmt::format("{} s", ms / 1000) : fmt::format("{} ms", ms));
  }
  if (WIFEXITED(run.status)) return fmt::format("exit code {}", WEXITSTATUS(run.status));
  if (WIFSIGNALED(run.status)) {
    return fmt::format("killed by signal {} ({})", WTERMSIG(run.status),
                       ::strsignal(WTERMSIG(run.status)));
  }
  return "unknown status";
}

}  // namespace

std::optional<fs::path> FindChromium() {
  if (const char* chosen = std::getenv("COVOPT_CHROMIUM"); chosen != nullptr && *chosen != '\0') {
    const std::string name = chosen;
    if (name.find('/') == std::string::npos) return FindOnPath(name);
    if (!IsExecutableFile(name)) return std::nullopt;
    std::error_code ec;
    const fs::path absolute = fs::absolute(name, ec);
    return ec ? fs::path(name) : absolute;
  }
  for (const std::string_view name : {"chromium", "chromium-browser", "google-chrome"}) {
    if (auto found = FindOnPath(name)) return found;
  }
  return std::nullopt;
}

std::chrono::milliseconds ChromiumTimeout() {
  const char* typed = std::getenv("COVOPT_CHROMIUM_TIMEOUT");
  if (typed == nullptr || *typed == '\0') return kChromiumTimeout;
  const std::string text = typed;
  char* end = nullptr;
  errno = 0;
  const double seconds = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || errno != 0 || !(seconds >= 0.1 && seconds <= 3600.0)) {
    throw std::invalid_argument(fmt::format("COVOPT_CHROMIUM_TIMEOUT='{}': expected the PDF browser's time limit in seconds, "
                                 "0.1 to 3600 (default {} s); unset it, or give e.g. 60",
                                 covopt::internal::EscapeControlCharacters(text), kChromiumTimeout.count()));
  }
  return std::chrono::milliseconds(static_cast<long long>(std::llround(seconds * 1000.0)));
}

fs::path RequireChromium() {
  std::optional<fs::path> browser = FindChromium();
  if (!browser) {
    const char* chosen = std::getenv("COVOPT_CHROMIUM");
    if (chosen != nullptr && *chosen != '\0') {
      throw OutputError(fmt::format(
          "chromium not found: COVOPT_CHROMIUM='{}' is not an executable on PATH or a path to "
          "one: unset it, or install chromium (Debian) to write a PDF report, or write "
          "--report FILE.html",
          chosen));
    }
    throw OutputError(std::string(kChromiumMissing));
  }
  return *browser;
}

PrintedPdf PrintPdf(const std::string& html, const std::string& target, std::chrono::milliseconds timeout) {
  const std::optional<fs::path> browser = RequireChromium();
  PrintedPdf printed_pdf;
  std::string& bytes = printed_pdf.bytes;
  int& interrupting_signal = printed_pdf.interrupting_signal;
  {
    const SignalBlock signals;
    {
      const PrivateDirectory directory;
      const fs::path page = directory / "report.html";
      const fs::path printed = directory / "report.pdf";
      const fs::path log = directory / "chromium.log";
      {
        std::ofstream out(page, std::ios::binary);
        out << html;
        if (!out.flush()) {
          throw OutputError(fmt::format("cannot write the report's HTML into '{}'", page.string()));
        }
      }
      std::vector<std::string> argv = {browser->string(), "--headless", "--disable-gpu",
                                       "--no-pdf-header-footer"};
      if (::geteuid() == 0) argv.emplace_back("--no-sandbox");  // Chromium refuses root otherwise
      argv.push_back("--user-data-dir=" + (directory / "profile").string());
      argv.push_back("--print-to-pdf=" + printed.string());
      argv.push_back(FileUrl(page));
      const BrowserRun run =
          RunBrowser(argv, BrowserEnvironment(directory.path()), log, timeout, signals);
      interrupting_signal = run.interrupting_signal;
      if (interrupting_signal == 0) {
        const bool exited_ok =
            !run.timed_out && WIFEXITED(run.status) && WEXITSTATUS(run.status) == 0;
        if (!exited_ok) BrowserFailed(*browser, target, Describe(run, timeout), log);
        std::ifstream in(printed, std::ios::binary);
        std::ostringstream content;
        content << in.rdbuf();
        bytes = content.str();
        if (bytes.size() < 5 || bytes.compare(0, 5, "%PDF-") != 0) {
          BrowserFailed(*browser, target, bytes.empty() ? "it wrote no PDF" : "what it wrote is not a PDF", log);
        }
      }
    }  // the temporary directory is removed here, the signals still blocked
  }  // the signal mask is restored here
  return printed_pdf;
}

void WriteReportPdf(const std::filesystem::path& pdf, const std::string& html, std::chrono::milliseconds timeout) {
  const std::string target = pdf.string();
  RequireChromium();  // no browser: said before the target is touched
  // The target is checked (and its temporary made) before the browser runs, by the one file
  // writer's rules (OutputFile, output_file.hpp).
  OutputFile file(pdf);
  const PrintedPdf printed = PrintPdf(html, target, timeout);
  if (printed.interrupting_signal != 0) {
    // Ends the process as the signal would have (the CLI's handlers first remove the
    // OutputFile's temporary); should a handler of someone else's return, report it.
    ::raise(printed.interrupting_signal);
    throw OutputError(fmt::format("writing '{}' was interrupted by signal {}", target, printed.interrupting_signal));
  }
  file.Write(printed.bytes);
  file.Commit();
}

}  // namespace covopt::report
