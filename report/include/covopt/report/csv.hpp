#pragma once
/// @file csv.hpp
/// CSV, one rule for every CSV covopt writes (sweep, speed-limit, robot --trajectory, optimize
/// --csv): RFC 4180 fields separated by ',' and records ended by '\n'. A field holding a
/// comma, a double quote or a line break is enclosed in double quotes, with each inner double
/// quote doubled; every other field is written as it is (numbers, words, empty). Line breaks
/// inside a field are written as spaces, so that every record is one line. Free-text columns
/// (messages: sweep's warnings and error) may ask to be quoted always (CsvQuote::kAlways),
/// which RFC 4180 allows, so that a reader sees them as text; an empty one stays empty.

#include <string>
#include <string_view>

namespace covopt::report {

/// When a field is enclosed in double quotes.
enum class CsvQuote {
  kWhenNeeded,  ///< only when it holds ',', '"', CR or LF (the default)
  kAlways,      ///< always, unless empty (free-text columns)
};

/// True when `text` must be quoted: it holds a comma, a double quote, CR or LF.
inline bool CsvNeedsQuotes(std::string_view text) noexcept {
  return text.find_first_of(",\"\n\r") != std::string_view::npos;
}

/// Appends `text` as one CSV field to `out` (a std::string or an fmt::memory_buffer: anything
/// with push_back(char) and append(const char*, const char*)).
template <class Buffer>
void AppendCsvField(Buffer& out, std::string_view text, CsvQuote quote = CsvQuote::kWhenNeeded) {
  if (text.empty()) return;
  const bool quoted = quote == CsvQuote::kAlways || CsvNeedsQuotes(text);
  if (!quoted) {
    out.append(text.data(), text.data() + text.size());
    return;
  }
  out.push_back('"');
  const char* run = text.data();
  const char* const end = text.data() + text.size();
  for (const char* p = run; p != end; ++p) {
    if (*p != '"' && *p != '\n' && *p != '\r') continue;
    out.append(run, p);
    if (*p == '"') {
      out.push_back('"');
      out.push_back('"');
    } else {
      out.push_back(' ');
    }
    run = p + 1;
  }
  out.append(run, end);
  out.push_back('"');
}

/// `text` as one CSV field.
inline std::string CsvField(std::string_view text, CsvQuote quote = CsvQuote::kWhenNeeded) {
  std::string field;
  AppendCsvField(field, text, quote);
  return field;
}

/// Appends one CSV record to `out`: the cells (strings or string_views) as fields, separated
/// by ',', and '\n'.
template <class Buffer, class Cells>
void AppendCsvRecord(Buffer& out, const Cells& cells) {
  bool first = true;
  for (const auto& cell : cells) {
    if (!first) out.push_back(',');
    AppendCsvField(out, std::string_view(cell));
    first = false;
  }
  out.push_back('\n');
}

}  // namespace covopt::report
