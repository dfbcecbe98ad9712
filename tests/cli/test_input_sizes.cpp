// Every command on bad input answers within 10 s of CPU and 1 GiB of address space: the built
// covopt runs in a child process under setrlimit (RLIMIT_AS 1 GiB, RLIMIT_CPU 10 s) and must
// exit 2 with one line naming what to change. A surface too large for its cap was once built
// before it was counted (a 100 m sphere at 1 mm: past 60 s and 11 GB; a surface file's 999 m
// segment of radius 999 m: a hang; a 1000 m sphere: "internal error: std::bad_alloc").
// No timing is asserted beyond the limits: the kernel enforces them.
#include <algorithm>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include <catch2/catch.hpp>
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli_test_support.hpp"

#ifdef COVOPT_CLI_BINARY
namespace {

using covopt::cli::testing::ReadFile;
using covopt::cli::testing::TempDir;

// AddressSanitizer reserves terabytes of address space: under it only the CPU limit applies.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressLimit = false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressLimit = false;
#else
constexpr bool kAddressLimit = true;
#endif
#else
constexpr bool kAddressLimit = true;
#endif

constexpr rlim_t kAddressBytes = rlim_t{1} << 30;  // 1 GiB
constexpr rlim_t kCpuSeconds = 10;

struct LimitedRun {
  bool exited = false;   ///< ended by exit(), not by a signal (SIGXCPU, SIGKILL, SIGSEGV, ...)
  int exit_code = -1;
  int signal = 0;
  std::string out, err;
};

/// Runs the built covopt with `args` under the limits; a child still running after 120 s of
/// wall time (a loaded machine; the CPU limit is the test) is killed.
LimitedRun RunLimited(const std::vector<std::string>& args) {
  TempDir dir;
  std::vector<std::string> argv_strings{COVOPT_CLI_BINARY};
  argv_strings.insert(argv_strings.end(), args.begin(), args.end());
  const pid_t pid = ::fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    const int out = ::open((dir / "stdout").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    const int err = ::open((dir / "stderr").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    ::dup2(out, 1);
    ::dup2(err, 2);
    const rlimit cpu{kCpuSeconds, kCpuSeconds};
    ::setrlimit(RLIMIT_CPU, &cpu);
    if (kAddressLimit) {
      const rlimit address{kAddressBytes, kAddressBytes};
      ::setrlimit(RLIMIT_AS, &address);
    }
    ::setenv("COVOPT_PROGRESS", "none", 1);
    std::vector<char*> argv;
    for (const std::string& a : argv_strings) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  LimitedRun run;
  run.exited = WIFEXITED(status);
  run.exit_code = run.exited ? WEXITSTATUS(status) : -1;
  run.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  run.out = ReadFile(dir / "stdout");
  run.err = ReadFile(dir / "stderr");
  return run;
}

void RequireRefusal(const LimitedRun& run, const std::vector<std::string>& needles) {
  INFO("signal " << run.signal << ", stderr: " << run.err);
  REQUIRE(run.exited);
  CHECK(run.exit_code == 2);
  CHECK(run.out.empty());
  CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  for (const std::string& needle : needles) CHECK_THAT(run.err, Catch::Contains(needle));
}

/// A one-joint arm whose moving link carries `collision` (XML inside <geometry>).
std::string ArmUrdf(const std::string& geometry) {
  return R"(<robot name="big"><link name="base"/>
  <link name="arm"><inertial><mass value="2"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry>)" +
         geometry + R"(</geometry></collision></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-3" upper="3" effort="10" velocity="2"/></joint>
</robot>)";
}

/// `covopt audit` of the arm in `urdf` on a two-sample move.
std::vector<std::string> Audit(const TempDir& dir, const std::string& urdf, std::vector<std::string> more = {}) {
  std::vector<std::string> args = {"audit",
                                   "--urdf",
                                   dir.Write("arm.urdf", urdf).string(),
                                   "--tip",
                                   "arm",
                                   "--trajectory",
                                   dir.Write("move.csv", "time_s,q,qd\n0,0,0.5\n0.1,0.05,0.5\n").string(),
                                   "--covering-thickness",
                                   "0",
                                   "--contact-area",
                                   "1cm2"};
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

}  // namespace

TEST_CASE("a URDF sphere too large to sample is refused within 10 s and 1 GiB, naming a spacing that does",
          "[cli][sizes][audit]") {
  TempDir dir;
  const std::string sphere100 = ArmUrdf("<sphere radius=\"100\"/>");
  // At 1 mm: past 60 s and 11 GB before; at the default 5 cm: 9.6 s and 4.2 GB.
  RequireRefusal(RunLimited(Audit(dir, sphere100, {"--surface-spacing", "1mm"})),
                 {"--urdf: ", "would have about 1.25", "more than the 1000000 allowed",
                  "URDF <collision> 1 of link 'arm', a sphere of radius 100 m", "--surface-spacing"});
  RequireRefusal(RunLimited(Audit(dir, sphere100)), {"would have about 5.02", "more than the 1000000 allowed"});
  // The documented maximum radius: "internal error: std::bad_alloc" before.
  RequireRefusal(RunLimited(Audit(dir, ArmUrdf("<sphere radius=\"1000\"/>"))),
                 {"more than the 1000000 allowed", "even the largest spacing, 1 m"});
}

TEST_CASE("a surface file's 999 m segment of radius 999 m is refused within 10 s and 1 GiB", "[cli][sizes][audit]") {
  TempDir dir;
  const std::string surface = dir.Write("huge.toml", "[[link]]\nname = \"arm\"\n"
                                                     "segments = [ { from_m = [0, 0, 0], to_m = [999, 0, 0], radius_m = 999 } ]\n")
                                  .string();
  RequireRefusal(RunLimited(Audit(dir, ArmUrdf("<mesh filename=\"arm.stl\"/>"), {"--surface-file", surface})),
                 {"--surface-file: ", "huge.toml:3:", "a capsule of radius 999 m and length 999 m",
                  "more than the 1000000 allowed"});
}

TEST_CASE("a radius of curvature below 0.1 mm is exit 2, not a verdict", "[cli][sizes][audit]") {
  TempDir dir;
  // "safe up to 3.946x" at 4.9e-324 m, "unsafe 0x" at 2.3e-308 m before.
  for (const std::string radius : {"4.9e-324", "2.3e-308"}) {
    RequireRefusal(RunLimited(Audit(dir, ArmUrdf("<sphere radius=\"" + radius + "\"/>"))),
                   {"--urdf: ", "link 'arm' <collision> 1: <sphere radius> = ", "[0.0001, 1000] m"});
  }
  // A surface-file point of 1e-310 m: the bare head cell's ratio fell from 0.93 to 0.0185.
  const std::string surface =
      dir.Write("tiny.toml", "[[link]]\nname = \"arm\"\npoints = [ { at_m = [0.1, 0, 0], radius_m = 1e-310 } ]\n").string();
  RequireRefusal(RunLimited(Audit(dir, ArmUrdf("<mesh filename=\"arm.stl\"/>"), {"--surface-file", surface})),
                 {"--surface-file: ", "tiny.toml:3:", "radius_m = 1e-310 m is not allowed"});
}

TEST_CASE("a sweep grid over its cap is refused within 10 s and 1 GiB", "[cli][sizes][sweep]") {
  RequireRefusal(RunLimited({"sweep", "--x", "speed=1m/s..2m/s:100000", "--y", "head-mass=1kg..5kg:100000"}),
                 {"10000000000 points; at most 1000000"});
  RequireRefusal(RunLimited({"sweep", "--x", "speed=1m/s..2m/s:100001"}), {"--x", "100000"});
  // The body-region sweep had no cap on the grid: 4e8 points were reserved at once.
  RequireRefusal(RunLimited({"sweep", "--body-region", "chest", "--contact-area", "1cm2", "--x",
                             "robot-mass=1kg..2kg:20000", "--y", "speed=0.1m/s..1m/s:20000"}),
                 {"the grid has 20000 x 20000 = 400000000 points; at most 1000000 are allowed"});
}
#endif
