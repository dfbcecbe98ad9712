#pragma once
/// @file link_coverings.hpp
/// Link-covering files (TOML): a covering per robot link, for `covopt audit --link-coverings`
/// and covopt.audit(link_coverings=...). One [[link]] table per link:
///
///     [[link]]
///     name = "fr3_link7"           # a link of the audited chain's surface
///     material = "PU foam PORON 4701-30 320"   # a catalog material (modulus, Poisson, crush data)
///     thickness = "10mm"           # a number in m, or a string with its unit; 0: bare
///
///     [[link]]
///     name = "fr3_link4"
///     modulus = "0.5MPa"           # instead of material: Young's modulus (Pa, or with a unit)
///     poisson = 0.45               # with modulus only (default 0.25), in (-1, 0.5]
///     thickness = 0.008            # 0, or 0.1 mm (kMinLayerThickness_m) to 1 m
///
/// A link the file does not name keeps the covering given for all links. The catalog names
/// are resolved by the caller (the CLI's --catalog/--no-builtin, or Python's built-in
/// catalog); the links against the chain's surface.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
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
///         without modulus, a bare number out of its plausible range (as the scene's covering
///         fields), a value out of its range (CheckLinkCovering), a link name with a control
///         character, a file over kMaxLinkCoveringsFileBytes or none. A value is echoed as
///         written, with control characters escaped: every message is one line.
std::vector<LinkCoveringEntry> ReadLinkCoverings(const std::filesystem::path& path);
/// As ReadLinkCoverings, from the TOML text; messages call it `source_name`.
std::vector<LinkCoveringEntry> ParseLinkCoverings(const std::string& toml_text, const std::string& source_name);

/// The largest covering thickness of a link [m]: 1 m, as covering.thickness's.
inline constexpr double kMaxLinkCoveringThickness_m = 1.0;
/// The largest covering modulus of a link [Pa]: 1e13 Pa, as covering.modulus's.
inline constexpr double kMaxLinkCoveringModulus_Pa = 1e13;

/// One of an entry's values out of its range, found by CheckLinkCovering.
struct LinkCoveringProblem {
  std::string key;      ///< "thickness", "modulus" or "poisson"
  std::string message;  ///< "thickness must be 0 (bare) or in [0.1 mm, 1000 mm] (got -5 mm)"
};

/// The range checks of one link's covering, shared by the file's reader and Python's dict of
/// coverings: thickness 0 (bare) or in [kMinLayerThickness_m, kMaxLinkCoveringThickness_m],
/// modulus in [kMinModulus_Pa, kMaxLinkCoveringModulus_Pa], poisson in covering.poisson's
/// range (covopt::IsPoissonRatio); each finite.
/// @return the first value out of its range, or nullopt.
std::optional<LinkCoveringProblem> CheckLinkCovering(const LinkCoveringEntry& entry);

/// Why `name` cannot be a link's or a material's name (`what`: "link name", "material name"):
/// empty, or a control character in it (a newline would break every message that echoes it);
/// nullopt for a good name. The message shows the name with its control characters escaped:
/// "a link name has no control characters (got 'fr3\\nlink7')" (a backslash and n).
std::optional<std::string> NameProblem(std::string_view what, const std::string& name);

}  // namespace covopt::scene_file
