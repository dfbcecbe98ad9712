// libFuzzer target: the link-coverings file parser (covopt::scene_file::ParseLinkCoverings,
// covopt audit --link-coverings, covopt.audit(link_coverings=...)). Bad input must end in
// std::invalid_argument with a one-line message; every entry it accepts must be usable as it
// stands: a link name and material name without control characters, a thickness of 0 or in
// [kMinLayerThickness_m, 1 m], a modulus in [kMinModulus_Pa, 1e13 Pa], a Poisson ratio in
// (-1, 0.5] and only with a modulus, a covered link with a material or a modulus, each finite,
// no link twice. Anything else (a crash, a sanitizer report, another exception, a message of
// several lines, an accepted value out of range) is a finding.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <set>
#include <stdexcept>
#include <string>

#include "covopt/core/physical_floors.hpp"
#include "covopt/core/poisson_ratio.hpp"
#include "covopt/scene_file/link_coverings.hpp"

namespace {

bool Printable(const std::string& name) {
  return !name.empty() && std::none_of(name.begin(), name.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return byte < 0x20 || byte == 0x7f;
  });
}

/// Whether toml++ 3.3.0 (Debian bookworm's) reaches __builtin_unreachable() when it asks whether
/// the code point `c` is whitespace: toml::impl::is_non_ascii_horizontal_whitespace looks c up
/// in blocks of 0x3FA code points from U+00A0, and its switch lacks blocks 0, 11 and 63 (U+00A1..
/// U+0499, U+2C5E..U+3057 but U+3000, U+FB26..U+FEFE). Upstream issues marzer/tomlplusplus #190
/// and #295, fixed by PR #305 after 3.3.0: undefined behaviour in every TOML reader of covopt,
/// which this target found at once (fuzz/README.md).
bool TomlUnreachable(char32_t c) {
  if (c <= 0xA0 || c >= 0xFEFF || c == 0x3000) return false;
  const auto block = (c - 0xA0) / 0x3FA;
  return block == 0 || block == 11 || block == 63;
}

/// Whether `text` holds the UTF-8 sequence (two or three bytes) of such a code point. Those
/// inputs are skipped, so that the fuzzer keeps exploring covopt's own code; remove this with a
/// fixed toml++.
bool HasTomlUnreachableCodePoint(const std::string& text) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const auto continuation = [&](std::size_t i) { return i < text.size() && (byte(i) & 0xC0) == 0x80; };
  for (std::size_t i = 0; i < text.size(); ++i) {
    if ((byte(i) & 0xE0) == 0xC0 && continuation(i + 1)) {
      if (TomlUnreachable(static_cast<char32_t>(((byte(i) & 0x1F) << 6) | (byte(i + 1) & 0x3F)))) return true;
    } else if ((byte(i) & 0xF0) == 0xE0 && continuation(i + 1) && continuation(i + 2)) {
      const auto c = static_cast<char32_t>(((byte(i) & 0x0F) << 12) | ((byte(i + 1) & 0x3F) << 6) | (byte(i + 2) & 0x3F));
      if (TomlUnreachable(c)) return true;
    }
  }
  return false;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace sf = covopt::scene_file;
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (HasTomlUnreachableCodePoint(text)) return 0;
  std::vector<sf::LinkCoveringEntry> entries;
  try {
    entries = sf::ParseLinkCoverings(text, "fuzz.toml");
  } catch (const std::invalid_argument& e) {
    const char* message = e.what();
    if (std::strchr(message, '\n') != nullptr || std::strchr(message, '\r') != nullptr) std::abort();
    return 0;
  }
  std::set<std::string> links;
  for (const sf::LinkCoveringEntry& entry : entries) {
    if (!Printable(entry.link) || !links.insert(entry.link).second) std::abort();
    if (entry.material && !Printable(*entry.material)) std::abort();
    const double t = entry.thickness_m;
    if (!(t == 0.0 || (t >= covopt::kMinLayerThickness_m && t <= sf::kMaxLinkCoveringThickness_m))) std::abort();
    if (entry.material && entry.modulus_Pa) std::abort();
    if (t > 0.0 && !entry.material && !entry.modulus_Pa) std::abort();
    if (entry.modulus_Pa && !(*entry.modulus_Pa >= covopt::kMinModulus_Pa &&
                              *entry.modulus_Pa <= sf::kMaxLinkCoveringModulus_Pa)) {
      std::abort();
    }
    if (entry.poisson_ratio && (!entry.modulus_Pa || !covopt::IsPoissonRatio(*entry.poisson_ratio))) std::abort();
    if (entry.where.empty() || entry.where.find('\n') != std::string::npos) std::abort();
    if (sf::CheckLinkCovering(entry)) std::abort();  // the shared check agrees with the reader
  }
  return 0;
}
