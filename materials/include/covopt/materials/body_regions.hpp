#pragma once
/// @file body_regions.hpp
/// The body regions of ISO/TS 15066:2016 Annex A (= ISO 10218-2:2025 Annex M, which took it
/// over unchanged) as data: Table A.2 (quasi-static force per region, quasi-static pressure per
/// area, the transient multiplier or "not permitted") and Table A.3 (effective spring constant
/// k_H and effective mass m_H per region), 12 regions and their 29 areas, each with its sources.
/// The table is materials/data/iso_ts_15066.toml, compiled into the library like the materials
/// catalog, so no file is needed at run time. A user's own table in the same format (its own
/// title, edition, regions, areas, limits and transient factors) is read by Load(path).
///
///     const auto& table = covopt::materials::BodyRegionTable::BuiltIn();
///     const covopt::materials::BodyRegion& chest = table.Region("chest");
///     const covopt::materials::BodyLimits limits =
///         table.Limits("chest", "", covopt::ContactType::kTransient);  // sternum: 280 N, 2.4 MPa
///
/// Units: SI inside (N, Pa, N/m, kg). The standard's N/cm² and N/mm are converted when the
/// data file is read (1 N/cm² = 1e4 Pa, 1 N/mm = 1e3 N/m).

#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <covopt/core/body_contact.hpp>

namespace covopt::materials {

/// What a body-region table is: its title and edition (the top-level keys `title` and
/// `edition` of its file), where it came from, and its bytes (for their digest). Every limit
/// of the table cites it: BodyLimits::Citation() is its edition.
struct LimitTableInfo {
  /// e.g. "Biomechanical limits of the body model (ISO/TS 15066:2016 Annex A)".
  std::string title;
  /// The standard and edition the values are from, e.g. "ISO/TS 15066:2016 Annex A =
  /// ISO 10218-2:2025 Annex M": the citation of every verdict judged on the table.
  std::string edition;
  /// "built-in", or the path of the file as the user gave it.
  std::string source;
  /// The file's bytes as read.
  std::string text;
  /// The SHA-256 of `text`, lower-case hex (covopt/core/sha256.hpp): the digest every verdict
  /// judged on the table names.
  std::string sha256;
  bool built_in() const noexcept { return source == "built-in"; }
  /// Who forbids a transient contact where the transient factor is "not permitted": "ISO/TS
  /// 15066:2016 A.3.2 (= ISO 10218-2:2025 Annex M)" for the built-in table, else the edition.
  std::string NoTransientClause() const;
};

/// One area of a region (Table A.2's rows of pressure).
struct BodyArea {
  /// Lower-case, hyphenated, unique over the table: "sternum", "forefinger-pad-dominant".
  std::string name;
  /// As the standard names it, e.g. "Sternum", "Forefinger pad (dominant hand)".
  std::string title;
  /// The standard's area number in Table A.1/A.2 (1..29).
  int number = 0;
  /// Maximum permissible quasi-static pressure p_qs [Pa] (Table A.2, 75th percentile of the
  /// pain-onset pressures).
  double quasi_static_pressure_Pa = 0.0;
};

/// One body region (Tables A.2 and A.3).
struct BodyRegion {
  /// Lower-case, hyphenated, unique: "skull-forehead", "chest", "hands-fingers".
  std::string name;
  /// As the standard names it: "Skull and forehead", "Chest".
  std::string title;
  /// Maximum permissible quasi-static force F_qs [N] (Table A.2).
  double quasi_static_force_N = 0.0;
  /// The transient limits are this multiple of the quasi-static ones (force and pressure);
  /// 0: transient contact is not permitted (skull/forehead and face, A.3.2).
  double transient_factor = 2.0;
  /// Effective spring constant k_H [N/m] (Table A.3).
  double stiffness_N_per_m = 0.0;
  /// Effective mass m_H [kg] (Table A.3).
  double effective_mass_kg = 0.0;
  /// The areas, in the standard's order.
  std::vector<BodyArea> areas;
  /// The sources each value was found in (one citation or URL each).
  std::vector<std::string> sources;
  /// The table the region belongs to (its title, edition and source).
  std::shared_ptr<const LimitTableInfo> table;
  bool transient_permitted() const noexcept { return transient_factor > 0.0; }
  /// The area with the lowest quasi-static pressure (the default area).
  const BodyArea& LowestPressureArea() const;
};

/// The limits that apply to one contact with one area of one region. It points into its
/// table: keep the table alive (BuiltIn() lives for the program).
struct BodyLimits {
  const BodyRegion* region = nullptr;
  const BodyArea* area = nullptr;
  ContactType contact = ContactType::kTransient;
  double force_N = 0.0;       ///< F_lim [N]: quasi-static, ×transient_factor when transient
  double pressure_Pa = 0.0;   ///< p_lim [Pa]: likewise
  /// Who sets them, e.g. "ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M, transient
  /// (2× quasi-static), chest (sternum): 280 N, 240 N/cm²".
  std::string Describe() const;
  /// The edition of the table the limits come from (LimitTableInfo::edition): the source a
  /// verdict names for its force and pressure criteria.
  std::string Citation() const;
  /// The scene parts the region contributes: k_H, and m_H (kFixed when clamped).
  double stiffness_N_per_m() const noexcept { return region->stiffness_N_per_m; }
  double effective_mass_kg() const noexcept;
};

/// A lookup that failed: an unknown region or area, or a contact the standard forbids.
/// what() is one line naming the value and the choices, e.g. "body region 'chset' is not in
/// ISO/TS 15066 Table A.2; did you mean 'chest'? (regions: skull-forehead, face, ...)".
class BodyRegionError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// The built-in table (and the loader of a table file in the same TOML format, for tests).
class BodyRegionTable {
 public:
  /// The table compiled into the library (materials/data/iso_ts_15066.toml).
  static const BodyRegionTable& BuiltIn();
  /// Reads a table from TOML text; `origin` names it in messages and is its info().source.
  /// @throws std::runtime_error "origin:line:column: ..." naming the key for invalid data.
  static BodyRegionTable FromTomlText(std::string_view text, std::string_view origin);
  /// A user's table file (the format of materials/data/iso_ts_15066.toml), read once and kept
  /// for the program's life like BuiltIn() (the BodyLimits of its regions point into it; a file
  /// read again with the same bytes is the same table).
  /// @throws std::runtime_error "path:line:column: ..." for invalid data, or naming the file
  ///         when it cannot be read.
  static const BodyRegionTable& Load(const std::filesystem::path& path);

  /// The table's title, edition, source and bytes.
  const LimitTableInfo& info() const noexcept { return *info_; }

  const std::vector<BodyRegion>& regions() const noexcept { return regions_; }
  /// The number of areas over all regions (29 for the standard).
  std::size_t area_count() const noexcept;
  /// The region named `name` (ignoring case; "_", "/" and " " read as "-"). "head" is not a
  /// region here: the head keeps Park et al.'s skin model (optim, the CLI's --body-region head).
  /// @throws BodyRegionError naming the choices and the closest name.
  const BodyRegion& Region(std::string_view name) const;
  /// The limits for `area_name` of region `region_name` (empty area: the region's lowest
  /// pressure) under `contact`.
  /// @throws BodyRegionError for an unknown region or area (naming the region's areas), or
  ///         for transient contact where the standard forbids it: "ISO/TS 15066:2016 A.3.2
  ///         does not permit transient contact with the face; use body.contact=clamped, or judge
  ///         the head with Park et al.'s skin model (body.region=head)". The messages name the
  ///         inputs by field (body.region, body.contact): each front end spells them its way
  ///         (covopt/scene_file/spelling.hpp).
  BodyLimits Limits(std::string_view region_name, std::string_view area_name,
                    ContactType contact) const;
  /// Every (region, area) pair the standard permits under `contact`, in table order; the
  /// regions forbidden under it are left out.
  std::vector<BodyLimits> AllLimits(ContactType contact) const;

 private:
  std::vector<BodyRegion> regions_;
  std::shared_ptr<const LimitTableInfo> info_;
};

/// The edition of the built-in table ("ISO/TS 15066:2016 Annex A = ISO 10218-2:2025 Annex M"):
/// what a citation of the standard names when no table is at hand.
const std::string& BuiltInEdition();

}  // namespace covopt::materials
