#pragma once
/// @file catalog.hpp
/// The covering-material catalog: the built-in one (materials/data/catalog.toml, compiled
/// into the library, so no file is needed at run time), user catalog files in the same
/// TOML format, lookup by name, "did you mean" suggestions and range filters.
///
/// A catalog file is a list of [[material]] tables with these keys (SI units, in the
/// key names):
///
///     name               string, required, unique ignoring case
///     family             string, required ("foam", "elastomer", ...)
///     youngs_modulus_Pa  number (Pa) or a string with a unit ("27.6MPa"), required, > 0
///                        and <= 1e12
///     poisson_ratio      number in (-1, 0.5], or "unknown"; optional (absent = unknown)
///     density_kg_per_m3  number (kg/m³) or a string with a unit ("0.05g/cm3"), > 0 and
///                        <= 1e5; optional (absent = unknown)
///     modulus_basis      "compressive" | "tensile" | "bending" | "fitted" | "as-printed"
///                        | "hardness", required
///     source             string, required: a URL or a citation
///     note               string, optional: how E was derived
///     compressive_strength_Pa
///                        the stress at which the material stops being elastic: a number
///                        (Pa) or a string with a unit ("172 kPa"), > 0 and <= 1e12 (the
///                        material crushes); or "does not crush" (elastomers, gels, flexible
///                        foams: they densify); or "unknown". Optional in a user file
///                        (absent = unknown); the built-in catalog states it for every entry
///     strength_method    string: with a strength, its test method and definition ("ASTM
///                        D1621, at yield or 10 % strain"); with "does not crush", why.
///                        Required with either, not allowed with "unknown"
///     strength_source    string: a URL or a citation for the strength or for "does not
///                        crush". Required with either, not allowed with "unknown"
///     compressive_curve  optional: the loading curve as measured points, piecewise linear,
///                        the origin implied: [[strain, "stress with unit"], ...]; a strain is
///                        a fraction in (0, 1) or a percentage ("25%"); a stress needs its unit
///                        ("57.3kPa"; a bare number is refused). Strains increase, stresses
///                        never decrease, 1 Pa to 10 GPa (CompressiveCurve::FromPoints)
///     curve_source       string: a URL, DOI or citation for the points, and how they were
///                        read. Required with a curve
///     curve_rate         "quasi-static", "unknown" or a strain rate with its unit ("20 1/s",
///                        in (0, 1e6] 1/s). Required with a curve
///     recovers           true (a flexible foam that recovers) or false (a crushable liner).
///                        Required with a curve
///     rate_factor        optional, [low, high]: the factor the curve's stresses may take at
///                        impact rates, 0.1 <= low <= high <= 10. Only with a curve
///     stress_at_25_band  optional, ["low unit", "high unit"]: a grade band (e.g. ASTM D1056)
///                        standing in for a measured curve: the range of σ(25 %), carried as an
///                        uncertainty. Needs curve_shape, and the curve's σ(25 %) in the band
///     curve_shape        string: with a band, the assumed shape its curve follows (which
///                        measured curve, scaled how). Needs stress_at_25_band
///
/// Values with units are read as in scene files (covopt/core/quantity.hpp): a bare number is
/// SI and must be plausible for its quantity (youngs_modulus_Pa = 27.6 would be 27.6 Pa and
/// is refused; write "27.6MPa"; a bare compressive_strength_Pa must lie in
/// [kPlausibleStrengthMin_Pa, kPlausibleStrengthMax_Pa], 1 kPa to 10 GPa). Any other key, or a top-level key other than `material`, is
/// an error.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/materials/material.hpp"

namespace covopt::materials {

/// A catalog that cannot be read or is not valid. what() is one line that starts with
/// "file:line:column: " where the file says where (and only the file name for a file
/// that cannot be read), names the offending key, and says what is allowed, e.g.
///
///     mine.toml:7:17: material 'soft foam': poisson_ratio must be in (-1, 0.5], or
///     "unknown" (got 0.7)
class CatalogError : public std::runtime_error {
 public:
  CatalogError(const std::string& message, std::string location, std::string key);
  /// "file:line:column" (or "file" alone), empty for entries added in code.
  const std::string& location() const noexcept { return location_; }
  /// The offending key ("poisson_ratio", "name", ...), empty for syntax and file errors.
  const std::string& key() const noexcept { return key_; }

 private:
  std::string location_;
  std::string key_;
};

/// The largest catalog file FromTomlFile reads [bytes]: 1 MiB, about 500 times the built-in one.
inline constexpr std::size_t kMaxCatalogFileBytes = std::size_t{1} << 20;

/// A closed interval [min, max]; an empty bound is unbounded on that side.
struct Range {
  std::optional<double> min;
  std::optional<double> max;
  /// True when neither bound is set.
  bool unbounded() const noexcept { return !min && !max; }
  /// min <= value <= max for the bounds that are set.
  bool Contains(double value) const noexcept;
};

/// What Catalog::Filter keeps: every condition that is set must hold.
struct MaterialFilter {
  Range youngs_modulus_Pa;   ///< E [Pa]
  Range poisson_ratio;       ///< ν [-]
  Range density_kg_per_m3;   ///< density [kg/m³]
  /// Families to keep, compared ignoring case; empty keeps every family.
  std::vector<std::string> families;
  /// Bases of E to keep; empty keeps every basis.
  std::vector<ModulusBasis> bases;
  /// Keep names that contain this text, ignoring case; empty keeps every name.
  std::string name_contains;
  /// Compressive strength [Pa]: a bounded range keeps only materials whose strength is
  /// known (they crush) and in range; materials that do not crush, or whose strength is
  /// unknown, never pass it (include_unknown does not apply). Select those by
  /// crush_behaviours.
  Range compressive_strength_Pa;
  /// Crush behaviours to keep; empty keeps every behaviour.
  std::vector<CrushBehaviour> crush_behaviours;
  /// Whether an entry whose ν (or density) is unknown passes a bounded ν (or density)
  /// range. Default false: a value that is not known is not known to be in range.
  bool include_unknown = false;
  /// σ(25 %) of the compressive curve [Pa] (StressAt25Pa): a bounded range keeps only
  /// materials with a curve through 25 % whose σ(25 %) is in range; materials without one
  /// never pass it (include_unknown does not apply).
  Range stress_at_25_Pa;
  /// true: keep only materials with a compressive curve.
  bool has_curve = false;
  /// Whether the filter asks for a curve (has_curve, or a bounded stress_at_25_Pa).
  bool needs_curve() const noexcept { return has_curve || !stress_at_25_Pa.unbounded(); }
};

/// An ordered list of materials with unique names (ignoring case). Value type.
class Catalog {
 public:
  /// An empty catalog.
  Catalog() = default;

  /// The catalog shipped with covopt (materials/data/catalog.toml, embedded at build
  /// time), parsed on the first call (thread-safe) and kept for the process's lifetime.
  /// Copy it to extend it: `Catalog mine = Catalog::BuiltIn(); mine.Add(...)`.
  /// @throws CatalogError only if the shipped file is invalid (a build defect).
  static const Catalog& BuiltIn();

  /// Reads a catalog file of at most kMaxCatalogFileBytes (reading stops one byte past it, so
  /// a device or a FIFO is refused at once).
  /// @throws CatalogError if the file cannot be read, is larger, or is not a valid catalog.
  static Catalog FromTomlFile(const std::filesystem::path& path);

  /// Reads catalog text; `source_name` names it in messages and origins (usually the
  /// file name).
  /// @throws CatalogError naming source_name:line:column, the key and what is allowed.
  static Catalog FromTomlString(std::string_view toml_text, std::string_view source_name);

  /// Appends every entry of `other`, in order. All or nothing.
  /// @throws CatalogError if a name is already present (ignoring case); the message
  ///         names both places.
  void Add(const Catalog& other);

  /// Appends one entry after validating it as a file entry would be.
  /// @throws CatalogError naming the key and what is allowed, or a duplicate name.
  void Add(Material material);

  /// The entry with this name, compared ignoring ASCII case; nullptr if none. The pointer
  /// is valid until the catalog is changed or destroyed.
  const Material* Find(std::string_view name) const noexcept;

  /// Names that `name` was probably meant to be, best first, at most `max_count`:
  /// names within a small edit distance (ignoring case), and names that contain every
  /// word of `name` ("polystyrene" -> both polystyrene foams). Empty if nothing is close.
  std::vector<std::string> Suggest(std::string_view name, std::size_t max_count = 3) const;

  /// What to tell a user who asked for `name` and it is not here: "no material 'X' in the
  /// catalog; did you mean 'Y' or 'Z'?", or "...; run 'covopt materials list' for the names"
  /// when nothing is close.
  std::string MissingMaterialMessage(std::string_view name) const;

  /// The entries that pass `filter`, in catalog order.
  std::vector<const Material*> Filter(const MaterialFilter& filter) const;

  /// How many entries `filter` leaves out only because they have no curve through 25 %
  /// (for --stress-at-25) or no curve (for --has-curve): they pass every other condition.
  /// 0 when the filter asks for no curve.
  std::size_t ExcludedForWantOfCurve(const MaterialFilter& filter) const;

  /// The distinct families, in order of first appearance.
  std::vector<std::string> families() const;

  /// Every entry, in the order they were loaded or added.
  const std::vector<Material>& materials() const noexcept { return materials_; }
  std::size_t size() const noexcept { return materials_.size(); }
  bool empty() const noexcept { return materials_.empty(); }

 private:
  std::vector<Material> materials_;
};

}  // namespace covopt::materials
