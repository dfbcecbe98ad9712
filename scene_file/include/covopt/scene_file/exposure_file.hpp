#pragma once
/// @file exposure_file.hpp
/// Exposure-zone files (TOML), for `covopt audit --exposure` and covopt.audit(exposure=...): the
/// boxes of the cell (the robot's base frame) and the body regions a person can present in each,
/// as a risk assessment decides them. An audit judges a point-sample against a region only where
/// a zone exposes that region (covopt/audit/audit.hpp, ExposureZone).
///
///     title = "Table cell"                  # optional: what the file describes
///     source = "risk assessment RA-12"      # optional: where its answer comes from
///
///     [[zone]]
///     name = "above the table"
///     min_m = [-1.5, -1.5, 0.75]           # the box's lower corner [m], base frame
///     max_m = [1.5, 1.5, 1.4]              # its upper corner [m], >= min_m on every axis
///     regions = ["hands-fingers", "lower-arms-wrists", "chest (sternum)", "head"]
///
/// A region is named as the ISO/TS 15066 table names it: a region ("lower-legs": all its
/// areas), or a region and one area ("chest (sternum)"), or "head" (Park et al.'s head model),
/// or "all". A point on a box's face counts as inside.

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace covopt::scene_file {

/// The largest exposure file read [bytes]: 1 MiB.
inline constexpr std::size_t kMaxExposureFileBytes = std::size_t{1} << 20;
/// The largest coordinate of a zone's corner [m] (|x|, |y|, |z|): 1000 m.
inline constexpr double kMaxExposureCoordinate_m = 1000.0;

/// One [[zone]] table, as read.
struct ExposureZoneEntry {
  std::string name;
  std::array<double, 3> min_m{};  ///< lower corner [m], base frame
  std::array<double, 3> max_m{};  ///< upper corner [m]
  std::vector<std::string> regions;
  std::string where;              ///< "file:line:column" of the table
};

/// An exposure file: its optional title and source, and its zones in order.
struct ExposureFile {
  std::string title;
  std::string source;
  std::vector<ExposureZoneEntry> zones;
};

/// Reads an exposure file.
/// @throws std::invalid_argument "file:line:column: ..." naming the key and the value: not TOML,
///         an unknown key (with the closest one), a zone without name, min_m, max_m or regions, a
///         corner that is not three finite numbers within ±kMaxExposureCoordinate_m, min_m above
///         max_m on an axis, empty regions, a region that is no ISO/TS 15066 region (nor "head",
///         "all"), a zone name given twice, no zone at all, a file over kMaxExposureFileBytes.
ExposureFile ReadExposureFile(const std::filesystem::path& path);
/// As ReadExposureFile, from the TOML text; messages call it `source_name`.
ExposureFile ParseExposureFile(const std::string& toml_text, const std::string& source_name);

/// Why `name` is no region an exposure zone can name (nullopt: it is one): a region or
/// "region (area)" of the built-in ISO/TS 15066 table, "head", or "all".
std::optional<std::string> ExposureRegionProblem(const std::string& name);

}  // namespace covopt::scene_file
