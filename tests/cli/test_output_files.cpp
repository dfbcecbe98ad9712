// The one file writer (OutputFile, cli/output.hpp) against what can be at an output path
// (issue 22, item 3): a character device is written straight to and stays a device
// (/dev/null written, /dev/full an exit-1 line naming ENOSPC), a FIFO is written to its
// reader, a symbolic link is followed and stays a link, a read-only file (even for root) is
// refused and left as it was, a missing directory and a directory at the path are one
// exit-1 line each, the temporary gets the final permissions and never outlives an error;
// and (item 8) SIGINT or SIGTERM in the middle of a sweep's streamed CSV, sent to the built
// covopt binary, leaves no temporary and the previous file untouched. Also the input side
// (item 7): a scene file is read with a 1 MiB limit (/dev/zero is refused at once), and the
// smaller cases of item 9 (a 100,000-character value is echoed short; progress lines on a
// non-terminal stderr).

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include "cli_test_support.hpp"
#include "errors.hpp"
#include "output.hpp"

// After the project headers: <csignal> defines macros (si_value) that clash with their
// parameter names.
#include <csignal>
#include <sys/wait.h>

using covopt::cli::OutputError;
using covopt::cli::OutputFile;
using covopt::cli::WriteFileAtomically;
using covopt::cli::testing::CliRun;
using covopt::cli::testing::ReadFile;
using covopt::cli::testing::Run;
using covopt::cli::testing::SplitLines;
using covopt::cli::testing::TempDir;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

namespace fs = std::filesystem;

/// The names in `dir` that look like the writer's temporaries.
std::vector<std::string> Temporaries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".tmp-") != std::string::npos) names.push_back(name);
  }
  return names;
}

bool IsCharacterDevice(const char* path) {
  struct stat st {};
  return ::lstat(path, &st) == 0 && S_ISCHR(st.st_mode);
}

mode_t ModeOf(const fs::path& path) {
  struct stat st {};
  REQUIRE(::stat(path.c_str(), &st) == 0);
  return st.st_mode & 07777;
}

/// An exit-1 output failure: one line on stderr naming `name`, nothing on stdout.
void CheckOutputFailure(const CliRun& run, const std::string& name, const std::string& reason) {
  CHECK(run.exit_code == 1);
  CHECK(run.out.empty());
  CHECK(SplitLines(run.err).size() == 1);
  CHECK_THAT(run.err, Contains(name));
  CHECK_THAT(run.err, Contains(reason));
}

}  // namespace

TEST_CASE("a character device is written straight to and stays a device", "[outputs][files]") {
  REQUIRE(IsCharacterDevice("/dev/null"));
  const CliRun run = Run({"simulate", "--history", "/dev/null"});
  CHECK(run.exit_code == 0);
  CHECK(IsCharacterDevice("/dev/null"));
  WriteFileAtomically("/dev/null", "anything\n");
  CHECK(IsCharacterDevice("/dev/null"));
}

TEST_CASE("/dev/full is an exit-1 line naming the device and ENOSPC, and stays a device",
          "[outputs][files]") {
  if (!IsCharacterDevice("/dev/full")) {
    WARN("no /dev/full here");
    return;
  }
  const CliRun run = Run({"simulate", "--history", "/dev/full"});
  CheckOutputFailure(run, "/dev/full", std::strerror(ENOSPC));
  CHECK(IsCharacterDevice("/dev/full"));
  CHECK_THROWS_AS(WriteFileAtomically("/dev/full", "x"), OutputError);
  CHECK(IsCharacterDevice("/dev/full"));
}

TEST_CASE("a FIFO is written to its reader and stays a FIFO", "[outputs][files]") {
  TempDir dir;
  const fs::path fifo = dir / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  std::string received;
  std::thread reader([&] {
    std::ifstream in(fifo, std::ios::binary);
    received.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  });
  const CliRun run = Run({"simulate", "--history", fifo.string()});
  reader.join();
  CHECK(run.exit_code == 0);
  CHECK_THAT(received, StartsWith("time_s,penetration_m,"));
  CHECK(SplitLines(received).size() > 10);
  struct stat st {};
  REQUIRE(::lstat(fifo.c_str(), &st) == 0);
  CHECK(S_ISFIFO(st.st_mode));
  CHECK(Temporaries(dir.path()).empty());
}

TEST_CASE("a symbolic link is followed: its target is replaced and the link stays a link",
          "[outputs][files]") {
  TempDir dir;
  fs::create_directories(dir / "data");
  const fs::path target = dir.Write("data/h.csv", "old\n");
  ::chmod(target.c_str(), 0640);
  const fs::path link = dir / "link.csv";
  fs::create_symlink("data/h.csv", link);  // relative to the link's directory

  const CliRun run = Run({"simulate", "--history", link.string()});
  CHECK(run.exit_code == 0);
  CHECK(fs::is_symlink(fs::symlink_status(link)));
  CHECK(fs::read_symlink(link) == fs::path("data/h.csv"));
  CHECK_THAT(ReadFile(target), StartsWith("time_s,"));
  CHECK(ModeOf(target) == 0640);  // an existing file keeps its permissions
  CHECK(Temporaries(dir.path()).empty());
  CHECK(Temporaries(dir / "data").empty());

  // A chain of links, and a dangling link, which makes its target.
  const fs::path chain = dir / "chain.csv";
  fs::create_symlink(link, chain);
  WriteFileAtomically(chain, "chained\n");
  CHECK(ReadFile(target) == "chained\n");
  CHECK(fs::is_symlink(fs::symlink_status(chain)));
  const fs::path dangling = dir / "dangling.csv";
  fs::create_symlink(dir / "data" / "new.csv", dangling);
  WriteFileAtomically(dangling, "made\n");
  CHECK(fs::is_symlink(fs::symlink_status(dangling)));
  CHECK(ReadFile(dir / "data" / "new.csv") == "made\n");

  // A loop of links is an error, not a hang.
  fs::create_symlink(dir / "loop-b", dir / "loop-a");
  fs::create_symlink(dir / "loop-a", dir / "loop-b");
  const CliRun loop = Run({"simulate", "--history", (dir / "loop-a").string()});
  CheckOutputFailure(loop, "loop-a", std::strerror(ELOOP));
}

TEST_CASE("a read-only file is refused and left as it was, even for root", "[outputs][files]") {
  TempDir dir;
  const fs::path file = dir.Write("h.csv", "keep me\n");
  REQUIRE(::chmod(file.c_str(), 0444) == 0);
  const CliRun run = Run({"simulate", "--history", file.string()});
  CheckOutputFailure(run, "h.csv", ::geteuid() == 0 ? "read-only" : std::strerror(EACCES));
  CHECK(ReadFile(file) == "keep me\n");
  CHECK(ModeOf(file) == 0444);
  CHECK(Temporaries(dir.path()).empty());
  // Through a link too: the link's target is named.
  const fs::path link = dir / "link.csv";
  fs::create_symlink(file, link);
  const CliRun linked = Run({"simulate", "--history", link.string()});
  CheckOutputFailure(linked, "link.csv", "h.csv");
  CHECK(ReadFile(file) == "keep me\n");
}

TEST_CASE("a missing directory and a directory at the path are one exit-1 line each",
          "[outputs][files]") {
  TempDir dir;
  const fs::path missing = dir / "no-such-dir" / "h.csv";
  const CliRun run = Run({"simulate", "--history", missing.string()});
  CheckOutputFailure(run, (dir / "no-such-dir").string(), "does not exist");
  CHECK_FALSE(fs::exists(dir / "no-such-dir"));

  fs::create_directories(dir / "out");
  const CliRun onto_directory = Run({"simulate", "--history", (dir / "out").string()});
  CheckOutputFailure(onto_directory, "out", "directory");
  CHECK(fs::is_directory(dir / "out"));
  CHECK(fs::is_empty(dir / "out"));
  CHECK(Temporaries(dir.path()).empty());
}

TEST_CASE("a new file gets 0666 & ~umask, and its temporary has them from the start",
          "[outputs][files]") {
  TempDir dir;
  const mode_t old_mask = ::umask(027);
  {
    OutputFile file(dir / "new.csv");
    REQUIRE(file.atomic());
    const std::vector<std::string> temporaries = Temporaries(dir.path());
    REQUIRE(temporaries.size() == 1);
    CHECK(ModeOf(dir / temporaries.front()) == 0640);
    file.Write("a,b\n");
    file.Commit();
  }
  ::umask(old_mask);
  CHECK(ModeOf(dir / "new.csv") == 0640);
  CHECK(ReadFile(dir / "new.csv") == "a,b\n");
  CHECK(Temporaries(dir.path()).empty());

  // Not committed (an error part-way): the temporary goes, the old file stays.
  {
    OutputFile file(dir / "new.csv");
    file.Write("partial");
  }
  CHECK(ReadFile(dir / "new.csv") == "a,b\n");
  CHECK(Temporaries(dir.path()).empty());
}

TEST_CASE("sweep's streamed CSV and optimize-style writes go through the same writer",
          "[outputs][files]") {
  TempDir dir;
  const fs::path file = dir.Write("s.csv", "keep me\n");
  REQUIRE(::chmod(file.c_str(), 0444) == 0);
  const CliRun run = Run({"sweep", "--x", "head-radius=0..100mm:11", "--csv", file.string()});
  CheckOutputFailure(run, "s.csv", ::geteuid() == 0 ? "read-only" : std::strerror(EACCES));
  CHECK(ReadFile(file) == "keep me\n");
  CHECK(Temporaries(dir.path()).empty());

  const CliRun devnull = Run({"sweep", "--x", "head-radius=0..100mm:11", "--csv", "/dev/null"});
  CHECK(devnull.exit_code == 0);
  CHECK(IsCharacterDevice("/dev/null"));
}

#ifdef COVOPT_CLI_BINARY
namespace {

/// Runs the built covopt with `args` (stdout and stderr to files in `dir`) and, once a
/// temporary appears in `dir`, sends `signal_number`; returns the wait status.
/// Starts the built covopt with `args` (args[0] the binary), stdout and stderr into `dir`'s
/// files "stdout" and "stderr", `environment` (NAME, VALUE pairs) set in the child.
pid_t Spawn(const TempDir& dir, const std::vector<std::string>& args,
            const std::vector<std::pair<std::string, std::string>>& environment = {}) {
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    const int out = ::open((dir / "stdout").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int err = ::open((dir / "stderr").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    ::dup2(out, 1);
    ::dup2(err, 2);
    for (const auto& [name, value] : environment) ::setenv(name.c_str(), value.c_str(), 1);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  return pid;
}

int InterruptLargeSweep(const TempDir& dir, const fs::path& target, int signal_number) {
  const std::vector<std::string> args = {COVOPT_CLI_BINARY, "sweep", "--x",
                                         "covering-thickness=1mm..50mm:1000", "--y",
                                         "speed=0.1..3:1000", "--csv", target.string()};
  const pid_t pid = Spawn(dir, args);
  // Wait (without a deadline: no timed test) for the temporary, or for the child's end.
  int status = 0;
  for (;;) {
    if (!Temporaries(dir.path()).empty()) break;
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) return status;  // it ended before writing: the checks below fail
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  // Let some rows reach the temporary, then interrupt.
  for (int i = 0; i < 1000; ++i) {
    const auto temporaries = Temporaries(dir.path());
    if (temporaries.empty()) break;
    std::error_code ec;
    if (fs::file_size(dir / temporaries.front(), ec) > 0 || ec) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  ::kill(pid, signal_number);
  REQUIRE(::waitpid(pid, &status, 0) == pid);
  return status;
}

}  // namespace

TEST_CASE("SIGINT or SIGTERM in the middle of a sweep's CSV leaves no temporary and the old file",
          "[outputs][files][signals]") {
  for (const int signal_number : {SIGINT, SIGTERM}) {
    CAPTURE(signal_number);
    TempDir dir;
    const fs::path target = dir.Write("big.csv", "previous content\n");
    const int status = InterruptLargeSweep(dir, target, signal_number);
    CHECK(WIFSIGNALED(status));
    if (WIFSIGNALED(status)) CHECK(WTERMSIG(status) == signal_number);
    CHECK(Temporaries(dir.path()).empty());
    CHECK(ReadFile(target) == "previous content\n");
  }
}

TEST_CASE("a sampling run on a non-terminal stderr prints progress lines", "[outputs][progress]") {
  TempDir dir;
  const pid_t pid = Spawn(dir, {COVOPT_CLI_BINARY, "simulate", "--head-mass", "3.7kg..5.8kg", "--samples", "20000"},
                          {{"COVOPT_PROGRESS", "lines"}});
  int status = 0;
  REQUIRE(::waitpid(pid, &status, 0) == pid);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  const std::string err = ReadFile(dir / "stderr");
  CHECK_THAT(err, Contains("covopt: sampling 100 % done"));
  CHECK_THAT(err, Contains("s left"));
}
#endif

TEST_CASE("a scene file is read up to 1 MiB: /dev/zero and a larger file are refused at once",
          "[bad-input][files]") {
  const CliRun zero = Run({"simulate", "--scene", "/dev/zero"});
  CHECK(zero.exit_code == 2);
  CHECK(zero.out.empty());
  CHECK(SplitLines(zero.err).size() == 1);
  CHECK_THAT(zero.err, Contains("/dev/zero"));
  CHECK_THAT(zero.err, Contains("1048576 bytes"));

  TempDir dir;
  const fs::path big = dir.Write("big.toml", "# " + std::string(std::size_t{1} << 20, 'x') + "\n");
  const CliRun large = Run({"simulate", "--scene", big.string()});
  CHECK(large.exit_code == 2);
  CHECK_THAT(large.err, Contains("big.toml"));
  CHECK_THAT(large.err, Contains("limit"));

  // Just under the limit is read (a comment and a valid scene).
  const fs::path fits =
      dir.Write("fits.toml", "# " + std::string((std::size_t{1} << 20) - 100, 'x') + "\n[robot]\nspeed = \"1 m/s\"\n");
  CHECK(Run({"simulate", "--scene", fits.string()}).exit_code == 0);
}

TEST_CASE("a 100,000-character value is echoed short in a one-line error", "[bad-input]") {
  const std::string digits(100000, '7');
  for (const std::string& value : {digits, "1" + std::string(99999, '0') + "kg", "5" + std::string(100000, 'q')}) {
    const CliRun run = Run({"simulate", "--robot-mass", value});
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK(SplitLines(run.err).size() == 1);
    CHECK(run.err.size() < 400);
    CHECK_THAT(run.err, Contains("characters)"));
    CHECK_THAT(run.err, Contains("--robot-mass"));
  }
  // A long value in a message of the CLI's own (a range flag's count).
  const CliRun sweep = Run({"sweep", "--x", "head-radius=0..100mm:" + digits});
  CHECK(sweep.exit_code == 2);
  CHECK(sweep.err.size() < 600);
  CHECK_THAT(sweep.err, Contains("characters)"));
}
