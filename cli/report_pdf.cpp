#include "report_pdf.hpp"

#include "errors.hpp"

namespace covopt::cli {

std::chrono::milliseconds ChromiumTimeout() {
  return AsInputError([] { return report::ChromiumTimeout(); });
}

void WriteReportPdf(const std::filesystem::path& pdf, const std::string& html) {
  report::WriteReportPdf(pdf, html, ChromiumTimeout());
}

}  // namespace covopt::cli
