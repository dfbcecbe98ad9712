#pragma once
/// @file audit_json.hpp
/// The whole robot along its motion as JSON text and CSV: the object `covopt audit --json`
/// prints and `covopt.audit()` returns as a dict (both call AuditJson), and the rows of
/// `covopt audit --csv` (one per link × region) and of its per-sample stream.
/// SI values, units in the keys; an infinite scale (a link that never moves, a program at
/// rest) is null.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "covopt/audit/audit.hpp"

namespace covopt::report {

/// The per-cell keys in order, as the JSON cells' keys and the CSV header: link, region,
/// governing_ratio, binding, sample, time_s, point, point_in_link_x_m, point_in_link_y_m,
/// point_in_link_z_m, point_in_base_x_m, point_in_base_y_m, point_in_base_z_m,
/// speed_m_per_s, reflected_mass_kg, max_safe_speed_m_per_s, speed_scale, head_criterion.
/// sample (0-based) and everything after it is null (CSV: empty) for a link that never moves;
/// speed_scale = max safe speed / speed at the governing point-sample's minimum (null: +inf);
/// head_criterion: the head's row's own criterion ("laceration", "contusion", ...), else null.
std::span<const std::string_view> AuditCellColumns() noexcept;

/// One cell's fields as CSV text, in AuditCellColumns order: numbers in shortest round-trip
/// form, "" for null.
std::vector<std::string> AuditCellCsvCells(const audit::AuditResult& result, const audit::AuditCell& cell);

/// The header of the per-sample stream (`covopt audit --samples-csv`): sample, time_s, then
/// per link "<link>_ratio" and "<link>_region".
std::vector<std::string> AuditSampleColumns(std::span<const std::string> links);

/// One streamed sample's fields (AuditSampleColumns order); a link at rest has ratio 0 and an
/// empty region.
std::vector<std::string> AuditSampleCsvCells(const audit::AuditSampleRow& row, std::span<const std::string> regions);

/// The audit as one JSON object:
///   status ("safe", "unsafe", "at-rest"), message, safe_speed_scale (null: at rest
///   throughout), limiting (null, or {link, region, binding, time_s, governing_ratio}: the
///   cell that sets the scale), criterion (optim::BodyRegionCriterion of the rule),
///   safety_factor, contact_area_m2 (null: not given), reaction_delay_s, braking_m_per_s2,
///   robot {name, base_link, tip_link, joint_names, payload (null, or {mass_kg,
///   center_of_mass_m [3], inertia_kg_m2 [3][3]})}, surface {spacing_m, links [{name,
///   point_count}]}, sample_count, regions (names; the head last when judged), scope,
///   coverings [{link, material (catalog name or null), modulus_Pa, poisson_ratio,
///   thickness_m (0: bare), from ("all links" or "link file")}], cells (links × regions,
///   row-major, AuditCellColumns keys), ratio_over_time (null when not kept, else {time_s,
///   links, ratio: [sample][link]}), link_designs [{link, material, thickness_m,
///   governing_ratio, message}] (empty without a design), warnings: `input_warnings`, then the
///   audit's (the surface's among them).
/// `indent` as in nlohmann's dump: 2 (the CLI's), or -1 for one line.
std::string AuditJson(const audit::AuditSetup& setup, const audit::AuditResult& result,
                      std::span<const std::string> input_warnings = {}, int indent = 2);

}  // namespace covopt::report
