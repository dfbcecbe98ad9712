#include "covopt/scene_file/spelling.hpp"

#include <array>
#include <cctype>

namespace covopt::scene_file {
namespace {

bool FieldChar(char c) noexcept {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.' || c == '-';
}

bool ValueChar(char c) noexcept {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-' || c == '.';
}

constexpr std::array<std::string_view, 4> kTargetFields{"body.region", "body.area", "body.contact",
                                                        "body.contact_area"};

}  // namespace

std::span<const std::string_view> TargetFields() noexcept { return kTargetFields; }

std::string Respell(std::string_view message, std::span<const FieldSpelling> table, ValueStyle style) {
  std::string out;
  std::size_t i = 0;
  while (i < message.size()) {
    const bool word_start = i == 0 || !FieldChar(message[i - 1]);
    const FieldSpelling* hit = nullptr;
    if (word_start) {
      for (const FieldSpelling& entry : table) {
        const std::size_t end = i + entry.field.size();
        if (message.substr(i, entry.field.size()) != entry.field) continue;
        // A whole word: not the start of a longer field (body.contact in body.contact_area);
        // a sentence's full stop after it is no part of it.
        const bool whole = end == message.size() || !FieldChar(message[end]) ||
                           (message[end] == '.' && (end + 1 == message.size() || !FieldChar(message[end + 1])));
        if (whole && (hit == nullptr || entry.field.size() > hit->field.size())) hit = &entry;
      }
    }
    if (hit == nullptr) {
      out += message[i++];
      continue;
    }
    std::size_t end = i + hit->field.size();
    if (end < message.size() && message[end] == '=') {
      std::size_t value_end = end + 1;
      while (value_end < message.size() && ValueChar(message[value_end])) ++value_end;
      while (value_end > end + 1 && message[value_end - 1] == '.') --value_end;  // a full stop
      const std::string_view value = message.substr(end + 1, value_end - end - 1);
      out += hit->name;
      // Appended piece by piece: GCC 12 warns on "literal" + std::string (-Wrestrict).
      out += style == ValueStyle::kFlag ? " " : "='";
      out += value;
      if (style == ValueStyle::kKeyword) out += '\'';
      i = value_end;
      continue;
    }
    out += hit->name;
    i = end;
  }
  return out;
}

}  // namespace covopt::scene_file
