#include "covopt/report/report_info.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <variant>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "covopt/internal/text.hpp"
#include "covopt/report/report_settings.hpp"
#include "covopt/scene_file/fields.hpp"

namespace covopt::report {
namespace {

/// The longest text of a sign-off field [characters].
constexpr std::size_t kMaxTextCharacters = 2000;

/// The first characters of `text`, escaped, for a message: "Line 3 of the pallet…".
std::string Excerpt(std::string_view text) {
  constexpr std::size_t kShown = 40;
  std::string shown = internal::EscapeControlCharacters(text.substr(0, kShown));
  return text.size() > kShown ? "'" + shown + "...'" : "'" + shown + "'";
}

/// What is wrong with a sign-off text, or nothing: more than kMaxTextCharacters characters
/// (UTF-8 code points), bytes that are not UTF-8, a control character (C0, DEL, C1) other than
/// a line break where `line_breaks` allows them.
std::optional<std::string> TextProblem(std::string_view text, bool line_breaks) {
  std::size_t characters = 0;
  for (std::size_t i = 0; i < text.size(); ++characters) {
    const auto byte = static_cast<unsigned char>(text[i]);
    const std::size_t length = byte < 0x80 ? 1 : (byte >> 5) == 0x6 ? 2 : (byte >> 4) == 0xE ? 3 : (byte >> 3) == 0x1E ? 4 : 0;
    bool valid = length != 0 && i + length <= text.size();
    for (std::size_t k = 1; valid && k < length; ++k) valid = (static_cast<unsigned char>(text[i + k]) >> 6) == 0x2;
    if (!valid) {
      return fmt::format("not UTF-8 text: byte {} is 0x{:02X} ({})", i + 1, byte, Excerpt(text));
    }
    const bool c1 = length == 2 && byte == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0;
    const bool control = byte < 0x20 || byte == 0x7F || c1;
    if (control && !(line_breaks && (byte == '\n' || byte == '\r'))) {
      return fmt::format("a control character at character {} ({}): {}", characters + 1, Excerpt(text),
                         line_breaks ? "only line breaks are allowed" : "none is allowed (the note may have line breaks)");
    }
    i += length;
  }
  if (characters > kMaxTextCharacters) {
    return fmt::format("{} characters ({}): at most {} are allowed", characters, Excerpt(text),
                       kMaxTextCharacters);
  }
  return std::nullopt;
}

/// What is wrong with a margin threshold, or nothing: `share` [-] outside [0, 1). `bare` when it
/// was written as a bare number (not a percentage), which between 1 and 100 is probably meant
/// as per cent; `shown` the value as written.
std::optional<std::string> ThresholdProblem(double share, bool bare, std::string_view shown) {
  if (std::isfinite(share) && share >= 0.0 && share < 1.0) return std::nullopt;
  if (bare && share >= 1.0 && share < 100.0) {
    return fmt::format("a bare number is a share in [0, 1); write {:g}% for {:g} per cent (got {})", share, share, shown);
  }
  return fmt::format("must be a share in [0, 1), 0 % to 100 % (got {})", shown);
}

/// The text field of `info` called `key`; nullptr for margin_threshold and appendix.
std::string* TextField(ReportInfo& info, std::string_view key) {
  if (key == "project") return &info.project;
  if (key == "cell") return &info.cell;
  if (key == "assessor") return &info.assessor;
  if (key == "note") return &info.note;
  return nullptr;
}

[[noreturn]] void Refuse(std::string_view name, std::string_view problem) {
  throw std::invalid_argument(name.empty() ? std::string(problem) : fmt::format("{}: {}", name, problem));
}

/// The setting's text; a number is refused naming what the key takes.
const std::string& TextOf(const ReportSetting& setting, std::string_view takes) {
  if (const auto* number = std::get_if<double>(&setting.value)) {
    Refuse(setting.name, fmt::format("expected {}, got the number {}", takes, *number));
  }
  return std::get<std::string>(setting.value);
}

void ApplyOne(const ReportSetting& setting, ReportInfo& info) {
  if (std::string* text = TextField(info, setting.key)) {
    const std::string& value = TextOf(setting, "a text");
    if (const auto problem = TextProblem(value, setting.key == "note")) Refuse(setting.name, *problem);
    *text = value;
  } else if (setting.key == "margin_threshold") {
    if (const auto* number = std::get_if<double>(&setting.value)) {
      if (const auto problem = ThresholdProblem(*number, true, fmt::format("{}", *number))) Refuse(setting.name, *problem);
      info.margin_threshold = *number;
    } else {
      info.margin_threshold = ParseMarginThreshold(std::get<std::string>(setting.value), setting.name);
    }
  } else if (setting.key == "appendix") {
    try {
      info.appendix = ParseReportAppendix(TextOf(setting, "none, summary or full"));
    } catch (const std::invalid_argument& e) {
      Refuse(setting.name, e.what());
    }
  } else {
    const auto keys = scene_file::ReportKeys();
    const auto suggestion = internal::Closest(setting.key, {keys.begin(), keys.end()});
    Refuse(setting.name, fmt::format("unknown key '{}'; {}", internal::EscapeControlCharacters(setting.key),
                                     suggestion ? fmt::format("did you mean '{}'?", *suggestion)
                                                : fmt::format("the keys are {}", fmt::join(keys, ", "))));
  }
}

}  // namespace

std::string_view ToString(ReportAppendix appendix) noexcept {
  switch (appendix) {
    case ReportAppendix::kNone: return "none";
    case ReportAppendix::kSummary: return "summary";
    case ReportAppendix::kFull: return "full";
  }
  return "summary";
}

ReportAppendix ParseReportAppendix(std::string_view name) {
  for (const ReportAppendix a : {ReportAppendix::kNone, ReportAppendix::kSummary, ReportAppendix::kFull}) {
    if (ToString(a) == name) return a;
  }
  throw std::invalid_argument(fmt::format("the appendix must be none, summary or full (got '{}')",
                                          internal::EscapeControlCharacters(name)));
}

void CheckReportInfo(const ReportInfo& info) {
  for (const auto& [name, text] : {std::pair{"project", &info.project}, std::pair{"cell", &info.cell},
                                   std::pair{"assessor", &info.assessor}, std::pair{"note", &info.note}}) {
    if (const auto problem = TextProblem(*text, std::string_view(name) == "note")) Refuse(name, *problem);
  }
  if (const auto problem = ThresholdProblem(info.margin_threshold, false, fmt::format("{}", info.margin_threshold))) {
    Refuse("margin_threshold", *problem);
  }
  (void)ParseReportAppendix(ToString(info.appendix));  // an enum value outside the three
}

double ParseMarginThreshold(std::string_view text, std::string_view name) {
  std::string_view number = internal::TrimBlanks(text);
  const bool percent = !number.empty() && number.back() == '%';
  if (percent) number = internal::TrimBlanks(number.substr(0, number.size() - 1));
  double value = 0.0;
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
  const std::string shown = internal::EscapeControlCharacters(text);
  if (number.empty() || error != std::errc{} || end != number.data() + number.size() || !std::isfinite(value)) {
    Refuse(name, fmt::format("expected a share, a number in [0, 1) or a percentage such as 10% (got '{}')", shown));
  }
  const double share = percent ? value / 100.0 : value;
  if (const auto problem = ThresholdProblem(share, !percent, "'" + shown + "'")) Refuse(name, *problem);
  return share + 0.0;  // -0 as 0
}

void ApplyReportSettings(std::span<const ReportSetting> settings, ReportInfo& info) {
  ReportInfo changed = info;
  for (const ReportSetting& setting : settings) ApplyOne(setting, changed);
  info = std::move(changed);
}

}  // namespace covopt::report
