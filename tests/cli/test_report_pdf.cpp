// --report FILE.pdf (issue 26, item 2): WriteReportPdf prints the HTML report with a headless
// Chromium found at run time. Without a browser it is one exit-1 error and nothing is written;
// a browser that fails, hangs or writes something else is one error with its status and its
// last lines, and is killed with its whole process group; the private temporary directory is
// gone on every path, also when SIGTERM ends the process mid-print; and the real Chromium
// (installed by scripts/install-deps.sh) prints a one-page PDF whose text is the page's.

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <catch2/catch.hpp>

#include "cli_test_support.hpp"
#include "errors.hpp"
#include "report_pdf.hpp"

// After the project headers: <csignal> defines macros (si_value) that clash with their
// parameter names.
#include <csignal>
#include <sys/wait.h>

using covopt::cli::ChromiumTimeout;
using covopt::cli::FindChromium;
using covopt::cli::testing::CliRun;
using covopt::cli::testing::Run;
using covopt::cli::kChromiumMissing;
using covopt::cli::OutputError;
using covopt::cli::WriteReportPdf;
using covopt::cli::testing::ReadFile;
using covopt::cli::testing::ScopedEnv;
using covopt::cli::testing::SplitLines;
using covopt::cli::testing::TempDir;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

namespace fs = std::filesystem;

const std::string kTinyHtml =
    "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>tiny</title></head>"
    "<body><h1>Covering verdict UNSAFE</h1><p>governing ratio 1.234</p></body></html>";

/// The entries of a directory (the private temporary directories WriteReportPdf makes in
/// $TMPDIR must all be gone).
std::vector<std::string> Entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) {
    names.push_back(entry.path().filename().string());
  }
  return names;
}

/// An executable shell script standing in for the browser.
fs::path FakeBrowser(const TempDir& dir, const std::string& name, const std::string& body) {
  const fs::path script = dir.Write(name, "#!/bin/sh\n" + body);
  fs::permissions(script, fs::perms::owner_all);
  return script;
}

/// The error WriteReportPdf throws as the CLI shows it (its one-line message, then each of its
/// details as "TOOL: LINE" on a line of its own), or "" when it throws nothing. The message
/// itself must be one line.
std::string Rendered(const OutputError& e) {
  std::string text = e.what();
  CHECK(text.find('\n') == std::string::npos);
  for (const std::string& line : e.details()) text += "\n" + e.tool() + ": " + line;
  return text;
}

std::string ErrorOf(const fs::path& pdf, const std::string& html,
                    std::chrono::milliseconds timeout = std::chrono::seconds(60)) {
  try {
    WriteReportPdf(pdf, html, timeout);
  } catch (const OutputError& e) {
    return Rendered(e);
  }
  return "";
}

/// The standard output of a command run by the shell (test code only).
std::string Capture(const std::string& command) {
  std::string text;
  FILE* pipe = ::popen(command.c_str(), "r");
  REQUIRE(pipe != nullptr);
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) text.append(buffer, n);
  ::pclose(pipe);
  return text;
}

/// Whether a process is alive: it exists and is not a zombie (an orphan reparented to a
/// container's init may stay one for long).
bool ProcessAlive(pid_t pid) {
  const std::string stat = ReadFile("/proc/" + std::to_string(pid) + "/stat");
  const std::size_t close = stat.rfind(')');
  if (close == std::string::npos || close + 2 >= stat.size()) return false;
  const char state = stat[close + 2];
  return state != 'Z' && state != 'X';
}

/// The pid a fake browser wrote into `file`, waiting up to 10 s for it.
pid_t WaitForPid(const fs::path& file) {
  for (int i = 0; i < 1000; ++i) {
    const std::string text = ReadFile(file);
    if (!text.empty() && text.back() == '\n') return static_cast<pid_t>(std::stol(text));
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  FAIL("the fake browser never wrote its pid into " << file);
  return -1;
}

}  // namespace

TEST_CASE("report pdf: no browser on PATH is the one error, and nothing is written") {
  TempDir dir, tmp;
  const ScopedEnv tmpdir("TMPDIR", tmp.path().string());
  const ScopedEnv path("PATH", (dir / "empty").string());
  ::unsetenv("COVOPT_CHROMIUM");
  fs::create_directory(dir / "empty");
  CHECK_FALSE(FindChromium().has_value());
  CHECK(ErrorOf(dir / "report.pdf", kTinyHtml) == std::string(kChromiumMissing));
  CHECK(ErrorOf(dir / "report.pdf", kTinyHtml) ==
        "chromium not found on PATH: install chromium (Debian) to write a PDF report, or write "
        "--report FILE.html");
  CHECK(Entries(dir.path()) == std::vector<std::string>{"empty"});
  CHECK(Entries(tmp.path()).empty());
  // An existing file at the target is left as it was.
  dir.Write("old.pdf", "the previous report");
  CHECK_FALSE(ErrorOf(dir / "old.pdf", kTinyHtml).empty());
  CHECK(ReadFile(dir / "old.pdf") == "the previous report");
}

TEST_CASE("report pdf: COVOPT_CHROMIUM naming no executable is one error naming it") {
  TempDir dir, tmp;
  const ScopedEnv tmpdir("TMPDIR", tmp.path().string());
  const fs::path not_executable = tmp.Write("chromium", "not a program");
  fs::permissions(not_executable, fs::perms::owner_read | fs::perms::owner_write);
  for (const std::string& chosen :
       {std::string("/nonexistent"), std::string("no-such-browser-covopt"),
        not_executable.string()}) {
    const ScopedEnv browser("COVOPT_CHROMIUM", chosen);
    CHECK_FALSE(FindChromium().has_value());
    const std::string error = ErrorOf(dir / "report.pdf", kTinyHtml);
    CHECK_THAT(error, StartsWith("chromium not found: COVOPT_CHROMIUM='" + chosen + "'"));
    CHECK_THAT(error, Contains("install chromium (Debian) to write a PDF report, or write "
                               "--report FILE.html"));
    CHECK(error.find('\n') == std::string::npos);
  }
  CHECK(Entries(dir.path()).empty());
  CHECK(Entries(tmp.path()) == std::vector<std::string>{"chromium"});
}

TEST_CASE("report pdf: the browser runs headless, without a shell, on a private copy of the page") {
  TempDir dir, tmp;
  const ScopedEnv tmpdir("TMPDIR", tmp.path().string());
  // The fake browser records its arguments, its stdin and the page, then prints a small PDF.
  const fs::path record = dir / "argv.txt";
  const fs::path browser = FakeBrowser(
      dir, "fake chromium",
      "for a in \"$@\"; do printf '%s\\n' \"$a\" >> '" + record.string() + "'; done\n"
      "readlink /proc/self/fd/0 > '" + (dir / "stdin.txt").string() + "'\n"
      "echo \"$XDG_CONFIG_HOME $XDG_CACHE_HOME\" > '" + (dir / "xdg.txt").string() + "'\n"
      "for a in \"$@\"; do case \"$a\" in\n"
      "  --print-to-pdf=*) out=\"${a#--print-to-pdf=}\" ;;\n"
      "  file://*) page=\"${a#file://}\" ;;\n"
      "esac; done\n"
      "cp \"$page\" '" + (dir / "page.html").string() + "'\n"
      "ls -ld \"$(dirname \"$page\")\" > '" + (dir / "mode.txt").string() + "'\n"
      "printf '%%PDF-1.4\\n%%fake\\n' > \"$out\"\n"
      "echo 'some noise on stderr' >&2\n");
  const ScopedEnv chosen("COVOPT_CHROMIUM", browser.string());
  REQUIRE(FindChromium() == fs::absolute(browser));
  const std::string html = kTinyHtml + "<!-- ü ' \" $(x) -->";
  REQUIRE(ErrorOf(dir / "out.pdf", html).empty());
  CHECK(ReadFile(dir / "out.pdf") == "%PDF-1.4\n%fake\n");
  CHECK(ReadFile(dir / "page.html") == html);
  CHECK(ReadFile(dir / "stdin.txt") == "/dev/null\n");
  CHECK_THAT(ReadFile(dir / "mode.txt"), StartsWith("drwx------"));
  const std::vector<std::string> argv = SplitLines(ReadFile(record));
  REQUIRE(argv.size() >= 6);
  CHECK(argv[0] == "--headless");
  CHECK(argv[1] == "--disable-gpu");
  CHECK(argv[2] == "--no-pdf-header-footer");
  const bool root = ::geteuid() == 0;
  CHECK((argv[3] == "--no-sandbox") == root);
  const std::size_t next = root ? 4 : 3;
  REQUIRE(argv.size() == next + 3);
  // The profile, the page and the PDF are in one private directory under $TMPDIR.
  const std::string private_dir = argv[next + 1].substr(std::string("--print-to-pdf=").size());
  const fs::path directory = fs::path(private_dir).parent_path();
  CHECK(directory.parent_path() == tmp.path());
  CHECK(argv[next] == "--user-data-dir=" + (directory / "profile").string());
  CHECK(argv[next + 2] == "file://" + (directory / "report.html").string());
  // Chromium's crash handler keeps its database under $XDG_CONFIG_HOME, not in the profile.
  CHECK(ReadFile(dir / "xdg.txt") ==
        (directory / "config").string() + " " + (directory / "cache").string() + "\n");
  // ... and gone.
  CHECK(Entries(tmp.path()).empty());
}

TEST_CASE("report pdf: a failing browser is one error with its status and last lines") {
  TempDir dir, tmp;
  const ScopedEnv tmpdir("TMPDIR", tmp.path().string());
  dir.Write("report.pdf", "the previous report");

  SECTION("exit code") {
    const ScopedEnv chosen(
        "COVOPT_CHROMIUM",
        FakeBrowser(dir, "crash", "echo 'first line' >&2\necho 'Aborting: no display' >&2\nexit 3\n")
            .string());
    const std::string error = ErrorOf(dir / "report.pdf", kTinyHtml);
    CHECK(error == "chromium ('" + (dir / "crash").string() + "') failed to print '" +
                       (dir / "report.pdf").string() +
                       "': exit code 3; its last lines follow; write --report FILE.html for the same report "
                       "without a browser\nchromium: first line\nchromium: Aborting: no display");
  }
  SECTION("killed by a signal") {
    const ScopedEnv chosen("COVOPT_CHROMIUM",
                           FakeBrowser(dir, "segv", "kill -SEGV $$\n").string());
    CHECK_THAT(ErrorOf(dir / "report.pdf", kTinyHtml), Contains(": killed by signal 11"));
  }
  SECTION("no PDF, or not a PDF") {
    const ScopedEnv chosen("COVOPT_CHROMIUM", FakeBrowser(dir, "nothing", "exit 0\n").string());
    CHECK_THAT(ErrorOf(dir / "report.pdf", kTinyHtml), Contains(": it wrote no PDF"));
    const ScopedEnv html_instead(
        "COVOPT_CHROMIUM",
        FakeBrowser(dir, "html",
                    "for a in \"$@\"; do case \"$a\" in --print-to-pdf=*) "
                    "echo '<html>' > \"${a#--print-to-pdf=}\";; esac; done\n")
            .string());
    CHECK_THAT(ErrorOf(dir / "report.pdf", kTinyHtml), Contains(": what it wrote is not a PDF"));
  }
  CHECK(ReadFile(dir / "report.pdf") == "the previous report");
  CHECK(Entries(tmp.path()).empty());
}

TEST_CASE("report pdf: a hanging browser is killed with its whole process group") {
  TempDir dir, tmp;
  const ScopedEnv tmpdir("TMPDIR", tmp.path().string());
  // The browser's helper (a grandchild, as Chromium's renderers are) hangs too.
  const fs::path pid_file = dir / "helper.pid";
  const ScopedEnv chosen(
      "COVOPT_CHROMIUM",
      FakeBrowser(dir, "hang",
                  "echo 'waiting for the renderer' >&2\nsleep 60 &\necho $! > '" +
                      pid_file.string() + "'\nwait\n")
          .string());
  // The watchdog of the CLI's call (WriteReportPdf without a time), set to 1 s (default 30 s).
  const ScopedEnv limit("COVOPT_CHROMIUM_TIMEOUT", "1");
  const auto start = std::chrono::steady_clock::now();
  std::string error;
  try {
    WriteReportPdf(dir / "report.pdf", kTinyHtml);
  } catch (const OutputError& e) {
    error = Rendered(e);
  }
  const auto took = std::chrono::steady_clock::now() - start;
  CHECK_THAT(error, Contains(": did not finish within 1 s and was killed (COVOPT_CHROMIUM_TIMEOUT sets the "
                             "limit); its last lines follow; write --report FILE.html for the same report "
                             "without a browser\nchromium: waiting for the renderer"));
  CHECK(took < std::chrono::seconds(20));  // the 1 s watchdog, not the 30 s default nor sleep's 60 s
  const pid_t helper = WaitForPid(pid_file);
  CHECK_FALSE(ProcessAlive(helper));
  CHECK_FALSE(fs::exists(dir / "report.pdf"));
  CHECK(Entries(tmp.path()).empty());
}

TEST_CASE("report pdf: the watchdog is 30 s, or COVOPT_CHROMIUM_TIMEOUT's seconds in [0.1, 3600]") {
  {
    const ScopedEnv unset("COVOPT_CHROMIUM_TIMEOUT", "");
    CHECK(ChromiumTimeout() == std::chrono::seconds(30));
  }
  {
    const ScopedEnv limit("COVOPT_CHROMIUM_TIMEOUT", "2.5");
    CHECK(ChromiumTimeout() == std::chrono::milliseconds(2500));
  }
  for (const char* bad : {"0", "-1", "abc", "1e9", "nan", "30s", "inf"}) {
    INFO(bad);
    const ScopedEnv limit("COVOPT_CHROMIUM_TIMEOUT", bad);
    CHECK_THROWS_WITH(ChromiumTimeout(), Contains("COVOPT_CHROMIUM_TIMEOUT='" + std::string(bad) +
                                                  "': expected the PDF browser's time limit in seconds, 0.1 to 3600"));
    // On the command line: bad input (exit 2) before the run, for a PDF report only.
    const TempDir dir;
    const CliRun run = Run({"simulate", "--report", (dir / "r.pdf").string()});
    CHECK(run.exit_code == 2);
    CHECK(run.out.empty());
    CHECK_THAT(run.err, Contains("COVOPT_CHROMIUM_TIMEOUT='" + std::string(bad) + "'"));
    CHECK(SplitLines(run.err).size() == 1);
    CHECK(Run({"simulate", "--report", (dir / "r.html").string()}).exit_code == 0);
  }
}

TEST_CASE("report pdf: on the command line a failing browser is one error line, its lines indented below") {
  TempDir dir, tmp;
  const ScopedEnv tmpdir("TMPDIR", tmp.path().string());
  const ScopedEnv chosen(
      "COVOPT_CHROMIUM",
      FakeBrowser(dir, "crash",
                  "for i in 1 2 3 4 5 6 7 8 9; do echo \"noise $i\" >&2; done\n"
                  "printf 'Aborting:\\tno display\\033[0m\\n' >&2\nexit 3\n")
          .string());
  const CliRun run = Run({"simulate", "--report", (dir / "r.pdf").string()});
  CHECK(run.exit_code == 1);
  const std::vector<std::string> lines = SplitLines(run.err);
  REQUIRE(lines.size() == 7);  // the error and the browser's last 6 lines
  CHECK_THAT(lines[0], StartsWith("covopt simulate: error: chromium ('" + (dir / "crash").string() +
                                  "') failed to print '" + (dir / "r.pdf").string() + "': exit code 3; "));
  CHECK(lines[1] == "  chromium: noise 5");
  CHECK(lines[5] == "  chromium: noise 9");
  CHECK(lines[6] == "  chromium: Aborting:\\tno display\\x1b[0m");  // control characters escaped
  CHECK_FALSE(fs::exists(dir / "r.pdf"));
}

TEST_CASE("report pdf: SIGTERM while the browser prints ends the process, leaving nothing") {
  TempDir dir, tmp;
  dir.Write("report.pdf", "the previous report");
  const fs::path pid_file = dir / "helper.pid";
  const fs::path browser = FakeBrowser(
      dir, "slow", "sleep 60 &\necho $! > '" + pid_file.string() + "'\nwait\n");
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    // Catch's own handlers out of the way: the signals' default actions, as in the CLI.
    for (const int signal_number : {SIGINT, SIGTERM, SIGHUP}) ::signal(signal_number, SIG_DFL);
    ::setenv("TMPDIR", tmp.path().c_str(), 1);
    ::setenv("COVOPT_CHROMIUM", browser.c_str(), 1);
    try {
      WriteReportPdf(dir / "report.pdf", kTinyHtml);
    } catch (...) {
      ::_exit(10);
    }
    ::_exit(11);
  }
  const pid_t helper = WaitForPid(pid_file);
  CHECK(::kill(child, SIGTERM) == 0);
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  CHECK(WIFSIGNALED(status));
  if (WIFSIGNALED(status)) CHECK(WTERMSIG(status) == SIGTERM);
  CHECK_FALSE(ProcessAlive(helper));
  CHECK(Entries(tmp.path()).empty());
  // No new file: the previous report as it was. (The OutputFile's temporary beside it is
  // removed by the file writer's signal handlers (report/src/output_file.cpp), installed on its first use in a process, which
  // an earlier test case in this process may have left out in favour of Catch's handlers;
  // test_output_files.cpp proves that removal on the built program.)
  std::vector<std::string> left;
  for (const std::string& name : Entries(dir.path())) {
    if (name.rfind(".report.pdf.tmp-", 0) != 0) left.push_back(name);
  }
  std::sort(left.begin(), left.end());
  CHECK(left == std::vector<std::string>{"helper.pid", "report.pdf", "slow"});
  CHECK(ReadFile(dir / "report.pdf") == "the previous report");
}

TEST_CASE("report pdf: Chromium prints a tiny page to a one-page PDF with its text") {
  TempDir dir, tmp;
  const ScopedEnv tmpdir("TMPDIR", tmp.path().string());
  ::unsetenv("COVOPT_CHROMIUM");
  // scripts/install-deps.sh installs chromium and poppler-utils for the tests: missing, this
  // fails rather than skips.
  REQUIRE(FindChromium().has_value());
  const fs::path pdf = dir / "tiny report.pdf";
  REQUIRE(ErrorOf(pdf, kTinyHtml).empty());
  CHECK_THAT(ReadFile(pdf), StartsWith("%PDF-"));
  const std::string quoted = "'" + pdf.string() + "'";
  CHECK_THAT(Capture("pdfinfo " + quoted + " 2>&1"), Contains("Pages:           1\n"));
  const std::string text = Capture("pdftotext -layout " + quoted + " - 2>&1");
  CHECK_THAT(text, Contains("Covering verdict UNSAFE"));
  CHECK_THAT(text, Contains("governing ratio 1.234"));
  // No header or footer (the temporary file's name or URL, a date, a page number).
  CHECK(text.find("report.html") == std::string::npos);
  CHECK(text.find("file:") == std::string::npos);
  CHECK(Entries(tmp.path()).empty());
  CHECK(Entries(dir.path()) == std::vector<std::string>{"tiny report.pdf"});
}
