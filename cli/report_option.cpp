#include "report_option.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <utility>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "errors.hpp"
#include "output.hpp"
#include "plot.hpp"
#include "report_pdf.hpp"

namespace covopt::cli {
namespace {

enum class ReportFormat { kHtml, kPdf };

/// The format for a file name's extension (.html, .htm or .pdf, any case).
std::optional<ReportFormat> ReportFormatFor(const std::string& file) {
  std::string extension = std::filesystem::path(file).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".html" || extension == ".htm") return ReportFormat::kHtml;
  if (extension == ".pdf") return ReportFormat::kPdf;
  return std::nullopt;
}

}  // namespace

void AddReportOption(CLI::App& command, std::optional<std::string>& file) {
  command
      .add_option("--report", file,
                  "also write the report for the risk-assessment file: self-contained HTML, or PDF "
                  "(printed by a headless Chromium)")
      ->type_name("FILE.html|FILE.pdf")
      ->check(CLI::Validator(
          [](std::string& value) -> std::string {
            if (ReportFormatFor(value) == ReportFormat::kPdf) {
              try {
                ChromiumTimeout();  // a bad $COVOPT_CHROMIUM_TIMEOUT is bad input, refused now
              } catch (const InputError& e) {
                return e.what();
              }
            }
            if (ReportFormatFor(value)) return {};
            return fmt::format("expected a file name ending in .html, .htm or .pdf (got '{}')", value);
          },
          "FILE.html|FILE.pdf", "report file"))
      ->group("Output");
}

void WriteReport(const std::string& file, report::ReportKind kind, const std::string& result_json,
                 std::span<const chart::GnuplotChart> charts) {
  std::string html;
  try {
    std::vector<report::SvgChart> drawn;
    if (!charts.empty()) drawn = chart::DrawSvgCharts(charts, SignalSafeScratch());
    html = report::HtmlReport({kind, result_json, std::move(drawn), {}});
  } catch (const std::exception& e) {  // gnuplot missing or failed; a result HtmlReport refuses
    throw OutputError(fmt::format("--report '{}': no report written: {}", file, e.what()));
  }
  if (ReportFormatFor(file) == ReportFormat::kPdf) {
    WriteReportPdf(file, html);
  } else {
    WriteFileAtomically(file, html);
  }
}

void PrintAndReport(std::ostream& out, bool print_json, const std::string& json_object,
                    const std::optional<RunContext>& run, const std::optional<std::string>& report_file,
                    report::ReportKind kind, const std::function<std::vector<chart::GnuplotChart>()>& charts) {
  const std::string stamped = WithRunProvenance(json_object, run);
  if (report_file) WriteReport(*report_file, kind, stamped, charts ? charts() : std::vector<chart::GnuplotChart>{});
  if (print_json) out << stamped << '\n';
}

}  // namespace covopt::cli
