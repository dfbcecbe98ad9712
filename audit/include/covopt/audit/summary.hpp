#pragma once
/// @file summary.hpp
/// The result summary (covopt/core/result_summary.hpp) of an audit.

#include <string_view>

#include <covopt/core/result_summary.hpp>

#include <cstddef>
#include <string>
#include <vector>

#include "covopt/audit/audit.hpp"
#include "covopt/audit/retime.hpp"

namespace covopt::audit {

/// The criterion of a summary row no exposure zone lets the audit judge.
inline constexpr std::string_view kNotJudgedCriterion = "not judged";

/// `audit`: one row per moving link, its worst link × region cell (the largest ratio over the
/// regions and the motion): its speed v against the largest safe speed there, v_max (the derated
/// limit; the limit is SF × v_max), ratio the cell's governing ratio v / (SF v_max), criterion the
/// one that binds v_max. The binding row is the limiting cell's; the governing case names its
/// link, region, sample, time and point. The robot: the URDF's file name, its joints, the
/// payload, the governing cell's reflected mass and speed; the covering: the governing link's.
/// A moving link whose cells the exposure zones judge none of has a row of its own, criterion
/// kNotJudgedCriterion, not counted and not passed, its note saying why.
ResultSummary SummarizeAudit(const AuditSetup& setup, const AuditResult& result);

/// `retime`: the summary of the re-audit of the re-timed program (SummarizeAudit of
/// result.after), its command "retime": SAFE or MARGINAL only when the re-timed program is safe
/// (status safe or at rest; a row passes within the re-audit's `tolerance`, which the summary
/// notes); a time-optimal program touches its limit somewhere, so its margin is about
/// 1 - SF × 1/SF = 0 and its state MARGINAL unless the programmed speed caps it. Infeasible or
/// not safe: UNSAFE, the original program's rows, the message as the governing case; the audit
/// could not judge: NOT EVALUATED. The cycle times (re-timed, original, uniform slow-down) are
/// in the governing case and the robot's motion; the scope is the result's.
ResultSummary SummarizeRetime(const AuditSetup& setup, const RetimeResult& result, double tolerance);

/// One stretch of the original program where the re-timed one runs slower than programmed
/// (path speed ṡ < 1 - 1e-9): its samples and times (original program's time [s]), the
/// slowest path speed in it [-], and what holds the speed there: the bound at that sample
/// ("path-speed": the safety limit, named by its link and region; "joint-speed",
/// "joint-acceleration", "boundary").
struct RetimeSlowdown {
  std::size_t first_sample = 0;
  std::size_t last_sample = 0;
  double start_time_s = 0.0;
  double end_time_s = 0.0;
  double min_path_speed = 0.0;
  std::size_t slowest_sample = 0;
  std::string bound;   ///< optim::ToString(PathSpeedBound) at the slowest sample
  std::string link;    ///< the limiting link there ("" unless bound is path-speed)
  std::string region;  ///< the limiting region there ("" unless bound is path-speed)
};

/// The stretches where the re-timed program is slower than programmed, in time order. Empty
/// when it never slows, or without a profile.
std::vector<RetimeSlowdown> RetimeSlowdowns(const RetimeResult& result);

}  // namespace covopt::audit
