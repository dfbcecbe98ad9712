#pragma once
/// @file summary.hpp
/// The result summary (covopt/core/result_summary.hpp) of an audit.

#include <string_view>

#include <covopt/core/result_summary.hpp>

#include "covopt/audit/audit.hpp"

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

}  // namespace covopt::audit
