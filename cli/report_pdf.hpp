#pragma once
/// @file report_pdf.hpp
/// `--report FILE.pdf`: the HTML report printed to PDF by a headless Chromium found at run
/// time. The HTML report never needs a browser; only the PDF does.

#include <chrono>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace covopt::cli {

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
/// @throws InputError (exit 2) naming the variable, its value and the range; the --report
///         option checks it when the file is a PDF, before anything runs.
std::chrono::milliseconds ChromiumTimeout();

/// The browser WriteReportPdf runs: $COVOPT_CHROMIUM when set and not empty (a path, or a
/// name looked up on $PATH), else the first of chromium, chromium-browser, google-chrome on
/// $PATH; empty when there is none.
std::optional<std::filesystem::path> FindChromium();

/// Prints `html` (a self-contained HTML document, report::HtmlReport's) to the PDF file `pdf`.
///
/// The HTML goes into a private temporary directory (mkdtemp, mode 0700), with Chromium's
/// profile (--user-data-dir) and its XDG_CONFIG_HOME and XDG_CACHE_HOME (its crash handler's
/// database) beside it, so that nothing is written into $HOME; Chromium runs without a shell as
/// `chromium --headless --disable-gpu --no-pdf-header-footer --print-to-pdf=TMP.pdf
/// file://TMP.html` (with --no-sandbox when running as root), in its own process group, with
/// stdin from /dev/null and stdout and stderr captured. A watchdog kills the whole group after
/// `timeout`; SIGINT, SIGTERM or SIGHUP while it runs kill it too, remove the temporary
/// directory, and then end the process as that signal would have. The PDF must be non-empty
/// and start with "%PDF"; it is then written to `pdf` by the CLI's one file writer
/// (OutputFile: atomically, nothing at the path when anything failed). The temporary
/// directory is removed on every path.
/// @throws OutputError (exit 1): kChromiumMissing when there is no browser (checked before
///         anything is written); the target's own errors; a browser that fails, crashes or
///         times out: one line with its status and what to do, and the last lines it printed
///         (up to kChromiumLogLines) as the error's details, shown under it as "  chromium: ...";
///         a file that is not a PDF.
void WriteReportPdf(const std::filesystem::path& pdf, const std::string& html);

/// WriteReportPdf with another watchdog time (the tests' fake browsers).
void WriteReportPdf(const std::filesystem::path& pdf, const std::string& html,
                    std::chrono::milliseconds timeout);

}  // namespace covopt::cli
