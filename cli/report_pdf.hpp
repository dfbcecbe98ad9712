#pragma once
/// @file report_pdf.hpp
/// `--report FILE.pdf`: the HTML report printed to PDF by a headless browser (cli/report_pdf.cpp).

#include <filesystem>
#include <string>

namespace covopt::cli {

/// Renders `html` (a self-contained HTML document) to the PDF file `pdf` with a headless
/// browser found at run time. @throws OutputError when there is no browser or it fails, or
/// the file cannot be written.
void WriteReportPdf(const std::filesystem::path& pdf, const std::string& html);

}  // namespace covopt::cli
