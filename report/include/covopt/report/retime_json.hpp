#pragma once
/// @file retime_json.hpp
/// The re-timed program as JSON text: the object `covopt retime --json` prints and
/// `covopt.retime()` returns as a dict (both call RetimeJson). SI values, units in the keys; an
/// infinite value (a safe path speed where nothing moves, a joint without a speed limit, a
/// sweep point without a safe timing) is null, and "notes" says so.

#include <span>
#include <string>
#include <vector>

#include "covopt/audit/retime.hpp"

namespace covopt::report {

/// The cycle-time sweep as asked and answered (audit::CycleTimeAgainstThickness).
struct RetimeSweep {
  std::vector<audit::CycleTimeDesign> designs;
  std::vector<double> thicknesses_m;
  std::vector<audit::CycleTimePoint> points;
};

/// The re-timed program as one JSON object:
///   status (audit::ToString(RetimeStatus)), message, summary (audit::SummarizeRetime),
///   cycle_time_s, original_cycle_time_s, uniform_cycle_time_s, uniform_speed_scale,
///   max_speed_scale, tolerance, joint_names, joint_speed_limits_rad_per_s (per joint [rad/s or m/s];
///   null: none), joint_acceleration_limits_rad_per_s2 (per joint [rad/s² or m/s²]), profile {status,
///   message}, slowdowns [{start_time_s, end_time_s, first_sample, last_sample, min_path_speed,
///   bound, link, region}] (where the program had to slow, audit::RetimeSlowdowns), samples
///   {original_time_s, time_s (the re-timed program's; null without one), safe_path_speed (null:
///   nothing moves), path_speed, bound, limiting_link, limiting_region (null where nothing
///   moves)}, before {status, message, safe_speed_scale, limiting} (the original program's
///   audit), after (the re-timed program's audit: report::AuditJson's object; null without one),
///   thickness_sweep (null when not asked, else {designs [names], thicknesses_m, points
///   [{design, thickness_m, status, cycle_time_s, uniform_cycle_time_s, safe_speed_scale,
///   message}]}), then the audit's inputs as AuditJson names them (criterion, safety_factor,
///   contact_area_m2, reaction_delay_s, braking_m_per_s2, robot, surface, sample_count,
///   regions, coverings), scope, notes, warnings (`input_warnings`, then the result's).
/// `indent` as in nlohmann's dump: 2 (the CLI's), or -1 for one line.
std::string RetimeJson(const audit::AuditSetup& setup, const audit::RetimeResult& result,
                       const audit::RetimeOptions& options, const RetimeSweep* sweep,
                       std::span<const std::string> input_warnings = {}, int indent = 2);

}  // namespace covopt::report
