#include "report_option.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <utility>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "covopt/report/report_settings.hpp"
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

/// The sign-off flags: each one's key (scene_file::ReportKeys()), member and help.
struct SignOffFlag {
  std::string_view key;
  std::string_view flag;
  std::optional<std::string> ReportFlags::*member;
  std::string_view type_name;
  std::string_view help;
};

constexpr SignOffFlag kSignOffFlags[] = {
    {"project", "--project", &ReportFlags::project, "TEXT", "the project the report is for, printed on its first page"},
    {"cell", "--cell", &ReportFlags::cell, "TEXT", "the robot cell (or station) the report is for"},
    {"assessor", "--assessor", &ReportFlags::assessor, "TEXT", "who made the assessment"},
    {"note", "--note", &ReportFlags::note, "TEXT", "a note printed with the sign-off fields"},
    {"margin_threshold", "--margin-threshold", &ReportFlags::margin_threshold, "SHARE",
     "a SAFE verdict whose margin is below this reads MARGINAL: a share, 10% or 0.1 (default 10%)"},
    {"appendix", "--report-appendix", &ReportFlags::appendix, "{none,summary,full}",
     "what the report's appendix holds: none, summary (every summary row and input; the default) or full "
     "(every value of the JSON)"},
};

}  // namespace

std::vector<scene_file::ReportSetting> ReportFlags::Settings() const {
  std::vector<scene_file::ReportSetting> settings;
  for (const SignOffFlag& f : kSignOffFlags) {
    if (const std::optional<std::string>& typed = this->*f.member) {
      settings.push_back({std::string(f.key), *typed, std::string(f.flag)});
    }
  }
  return settings;
}

report::ReportInfo ReportInfoOf(const ReportFlags& flags, const ResultInputs& inputs) {
  report::ReportInfo info;
  AsInputError([&] {
    report::ApplyReportSettings(inputs.file_report, info);
    report::ApplyReportSettings(flags.Settings(), info);
  });
  return info;
}

void AddReportOption(CLI::App& command, ReportFlags& flags) {
  std::optional<std::string>& file = flags.file;
  CLI::Option* report = command
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
  for (const SignOffFlag& f : kSignOffFlags) {
    command.add_option(std::string(f.flag), flags.*f.member, std::string(f.help))
        ->type_name(std::string(f.type_name))
        ->check(CLI::Validator(
            [key = f.key](std::string& value) -> std::string {
              report::ReportInfo scratch;
              const scene_file::ReportSetting setting{std::string(key), value, ""};
              try {  // the report's own reading: the same message as the scene file's value gets
                report::ApplyReportSettings({&setting, 1}, scratch);
              } catch (const std::invalid_argument& e) {
                return e.what();
              }
              return {};
            },
            "", std::string(f.key)))
        ->needs(report)
        ->group("Report");
  }
}

void WriteReport(const std::string& file, report::ReportKind kind, const std::string& result_json,
                 std::span<const chart::GnuplotChart> charts, const report::ReportInfo& info) {
  std::string html;
  try {
    std::vector<report::SvgChart> drawn;
    if (!charts.empty()) drawn = chart::DrawSvgCharts(charts, SignalSafeScratch());
    html = report::HtmlReport({kind, result_json, std::move(drawn), info});
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
                    const std::optional<RunContext>& run, const ReportFlags& report, const ResultInputs& inputs,
                    report::ReportKind kind, const std::function<std::vector<chart::GnuplotChart>()>& charts) {
  std::string object = json_object;
  if (run) {  // a top-level result (a nested one, inside another's object, has neither)
    object = report::WithInputSources(object, inputs.origins);
    if (inputs.robot_model) object = report::WithRobotModel(object, *inputs.robot_model);
  }
  const std::string stamped = WithRunProvenance(object, run);
  if (report.file) {
    WriteReport(*report.file, kind, stamped, charts ? charts() : std::vector<chart::GnuplotChart>{},
                ReportInfoOf(report, inputs));
  }
  if (print_json) out << stamped << '\n';
}

}  // namespace covopt::cli
