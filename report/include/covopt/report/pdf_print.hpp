#pragma once
/// @file pdf_print.hpp
/// The HTML report printed to PDF (`--report FILE.pdf`) by a headless Chromium found at run
/// time. The HTML report never needs a browser; only the PDF does.

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "covopt/report/output_file.hpp"

namespace covopt::report {

/// The message when no browser is found (exit 1).
inline constexpr std::string_view kChromiumMissing =
    "chromium not found on PATH: install chromium (Debian) to write a PDF report, or write "
    "--report FILE.html";

/// How long a Chromium may take to print a report before it is killed, unless
/// $COVOPT_CHROMIUM_TIMEOUT says otherwise: a report prints in 1.2-1.4 s, 2.7-3.8 s for the whole
/// command on a loaded 2-core machine (docs/guide/report.md), so 30 s is ten times the worst of
/// these, and a browser stuck on a missing display or a dead profile lock is not waited for
/// two minutes.
inline constexpr std::chrono::seconds kChromiumTimeout{30};

/// The most lines of a failing browser's output shown under the error (OutputError::details).
inline constexpr std::size_t kChromiumLogLines = 6;

/// The watchdog time of WriteReportPdf(pdf, html): $COVOPT_CHROMIUM_TIMEOUT in seconds (a
/// decimal number, 0.1 to 3600) when set and not empty, else kChromiumTimeout.
/// @throws std::invalid_argument naming the variable, its value and the range (the CLI's exit
///         2; its --report option checks it when the file is a PDF, before anything runs).
std::chrono::milliseconds ChromiumTimeout();

/// The browser PrintPdf runs: $COVOPT_CHROMIUM when set and not empty (a path, or a
/// name looked up on $PATH), else the first of chromium, chromium-browser, google-chrome on
/// $PATH; empty when there is none.
std::optional<std::filesystem::path> FindChromium();

/// FindChromium's browser. @throws OutputError when there is none: kChromiumMissing, or naming
/// $COVOPT_CHROMIUM when it is set to no executable.
std::filesystem::path RequireChromium();

/// What a browser printed: the PDF's bytes, or the signal that interrupted it.
struct PrintedPdf {
  std::string bytes;            ///< the PDF, starting with "%PDF-" (empty when interrupted)
  /// SIGINT, SIGTERM or SIGHUP that arrived while the browser ran (it was killed and the
  /// temporary directory removed); the caller ends the process as that signal would have.
  int interrupting_signal = 0;
};

/// Prints `html` (a self-contained HTML document, report::HtmlReport's) to PDF; `target` names
/// the file it is for in messages.
///
/// The HTML goes into a private temporary directory (mkdtemp, mode 0700), with Chromium's
/// profile (--user-data-dir) and its XDG_CONFIG_HOME and XDG_CACHE_HOME (its crash handler's
/// database) beside it, so that nothing is written into $HOME; Chromium runs without a shell as
/// `chromium --headless --disable-gpu --no-pdf-header-footer --print-to-pdf=TMP.pdf
/// file://TMP.html` (with --no-sandbox when running as root), in its own process group, with
/// stdin from /dev/null and stdout and stderr captured. A watchdog kills the whole group after
/// `timeout`; SIGINT, SIGTERM or SIGHUP while it runs (blocked meanwhile) kill it too and are
/// returned (PrintedPdf::interrupting_signal). The PDF must be non-empty and start with "%PDF".
/// The temporary directory is removed on every path.
/// @throws OutputError: kChromiumMissing when there is no browser; a browser that fails, crashes
///         or times out: one line with its status and what to do, and the last lines it printed
///         (up to kChromiumLogLines) as the error's details; a file that is not a PDF.
PrintedPdf PrintPdf(const std::string& html, const std::string& target, std::chrono::milliseconds timeout);

/// Prints `html` to the PDF file `pdf` (PrintPdf), written by the one file writer (OutputFile:
/// atomically, nothing at the path when anything failed; the target is checked before the
/// browser runs). A signal that interrupted the browser ends the process as it would have
/// (the CLI's handlers first remove the temporary).
/// @throws OutputError: kChromiumMissing when there is no browser (checked before anything is
///         written); the target's own errors; PrintPdf's.
void WriteReportPdf(const std::filesystem::path& pdf, const std::string& html, std::chrono::milliseconds timeout);

}  // namespace covopt::report
