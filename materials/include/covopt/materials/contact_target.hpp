#pragma once
/// @file contact_target.hpp
/// What a verdict is about: the head (Park et al.'s skin model) or one area of an ISO/TS
/// 15066 body region, under one contact type. The set of targets a command judges is what
/// covopt::scene_file::ResolveTargets makes of the names a user typed ("all", "head",
/// "chest,hands-fingers"); the CLI's --body-region and Python's covopt.Regions both go
/// through it, so they name the same targets in the same order.

#include <optional>
#include <string>
#include <vector>

#include <covopt/core/body_contact.hpp>
#include <covopt/materials/body_regions.hpp>

namespace covopt::materials {

/// One target: an area of an ISO region (its limits), or the head.
struct ContactTarget {
  /// The region's limits; empty for the head.
  std::optional<BodyLimits> limits;
  bool is_head() const noexcept { return !limits.has_value(); }
  /// "chest (sternum)" or "head".
  std::string Name() const;
  /// The same target: the head, or the same area of the same region under the same contact.
  bool SameAs(const ContactTarget& other) const noexcept;
};

/// The targets named, with the contact type and the bare robot's contact area they share.
struct ContactTargets {
  /// In the order named; "all" is the table's order with the head last.
  std::vector<ContactTarget> targets;
  ContactType contact = ContactType::kTransient;
  /// The bare robot's contact area [m²] (its pressure is force / area); 0: not given.
  double contact_area_m2 = 0.0;
  /// What the reader must know about the resolution (a target named twice and judged once).
  std::vector<std::string> notes;
  /// The limit table the ISO targets come from (BodyRegionTable::BuiltIn() or ::Load(path),
  /// both living for the program); nullptr: the built-in one.
  const BodyRegionTable* table = nullptr;

  /// The table judged on: *table, or the built-in one.
  const BodyRegionTable& Table() const;
  /// Its edition, the citation of every verdict on the ISO targets.
  const std::string& Citation() const { return Table().info().edition; }

  bool has_head() const noexcept;
  bool has_iso() const noexcept;
  /// The ISO targets' limits, in order (the head left out).
  std::vector<BodyLimits> IsoLimits() const;
  /// The ISO regions' names for messages: "chest, pelvis, ..." (at most `shown`, then "...").
  std::string IsoNames(std::size_t shown = 2) const;
};

}  // namespace covopt::materials
