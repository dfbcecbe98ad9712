#pragma once
/// @file report_pdf.hpp
/// `--report FILE.pdf`: the HTML report printed to PDF by a headless Chromium found at run
/// time (report::PrintPdf, covopt/report/pdf_print.hpp), written by the CLI's one file writer.

#include <chrono>
#include <filesystem>
#include <string>

#include "covopt/report/pdf_print.hpp"

namespace covopt::cli {

using report::FindChromium;
using report::kChromiumLogLines;
using report::kChromiumMissing;
using report::kChromiumTimeout;

/// report::ChromiumTimeout, throwing InputError (exit 2) for a bad $COVOPT_CHROMIUM_TIMEOUT.
std::chrono::milliseconds ChromiumTimeout();

/// report::WriteReportPdf with the watchdog time of $COVOPT_CHROMIUM_TIMEOUT (ChromiumTimeout).
/// @throws InputError for a bad $COVOPT_CHROMIUM_TIMEOUT; OutputError (exit 1) as
///         report::WriteReportPdf: no browser, the target's errors, a browser that fails (its
///         last lines as the error's details, shown under it as "  chromium: ...").
void WriteReportPdf(const std::filesystem::path& pdf, const std::string& html);

/// With another watchdog time (the tests' fake browsers).
using report::WriteReportPdf;

}  // namespace covopt::cli
