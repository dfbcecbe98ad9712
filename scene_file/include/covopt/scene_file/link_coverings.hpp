#pragma once
/// @file link_coverings.hpp
/// Link-covering files (TOML): a covering per robot link, for `covopt audit --link-coverings`
/// and covopt.audit(link_coverings=...). One [[link]] table per link:
///
///     [[link]]
///     name = "fr3_link7"           # a link of the audited chain's surface
///     material = "PORON 4701-30"   # a catalog material (its modulus, Poisson ratio, crush data)
///     thickness = "10mm"           # a number in m, or a string with its unit; 0: bare
///
///     [[link]]
///     name = "fr3_link4"
///     modulus = "0.5MPa"           # instead of material: Young's modulus (Pa, or with a unit)
///     poisson = 0.45               # with modulus only (default 0.25)
///     thickness = 0.008
///
/// A link the file does not name keeps the covering given for all links. The catalog names
/// are resolved by the caller (the CLI's --catalog/--no-builtin, or Python's built-in
/// catalog); the links against the chain's surface.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace covopt::scene_file {

/// The largest link-covering file read [bytes]: 1 MiB.
inline constexpr std::size_t kMaxLinkCoveringsFileBytes = std::size_t{1} << 20;

/// One [[link]] table, as read (values in SI, checked for plausibility).
struct LinkCoveringEntry {
  std::string link;                     ///< name
  std::optional<std::string> material;  ///< material (catalog name, not yet looked up)
  std::optional<double> modulus_Pa;     ///< modulus [Pa]
  std::optional<double> poisson_ratio;  ///< poisson [-], with modulus only
  double thickness_m = 0.0;             ///< thickness [m]; 0: the bare link
  std::string where;                    ///< "file:line:column" of the table, for messages
};

/// Reads a link-covering file.
/// @throws std::invalid_argument "file:line:column: ..." naming the key and the value: not
///         TOML, a key other than [[link]] at the top or name, material, modulus, poisson,
///         thickness in a table (with the closest key), a link without a name or thickness, a
///         link named twice, both material and modulus, neither on a covered link, poisson
///         without modulus, a modulus, Poisson ratio or thickness out of its plausible range
///         (as the scene's covering fields), a file over kMaxLinkCoveringsFileBytes or none.
std::vector<LinkCoveringEntry> ReadLinkCoverings(const std::filesystem::path& path);
/// As ReadLinkCoverings, from the TOML text; messages call it `source_name`.
std::vector<LinkCoveringEntry> ParseLinkCoverings(const std::string& toml_text, const std::string& source_name);

}  // namespace covopt::scene_file
