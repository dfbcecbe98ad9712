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

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace sf = covopt::scene_file;
  const std::string text(reinterpret_cast<const char*>(data), size);
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
