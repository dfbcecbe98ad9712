#pragma once
/// @file region_charts.hpp
/// The charts of the body-region modes: bars per region (or per criterion of one region), the
/// bare robot beside the covered one, and the audit's link × region map. Each chart takes the
/// result its command already has.

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "covopt/audit/audit.hpp"
#include "covopt/chart/charts.hpp"
#include "covopt/core/body_contact.hpp"
#include "covopt/optim/body_region_check.hpp"
#include "covopt/optim/body_region_trajectory.hpp"
#include "covopt/report/body_contact_json.hpp"

namespace covopt::chart {

/// One group of bars: the bare robot's value beside the covered robot's.
struct BareCoveredBar {
  std::string label;               ///< "chest (sternum)", or "force" for one region's criteria
  std::optional<double> bare;      ///< empty: not evaluated (no bar drawn)
  std::optional<double> covered;   ///< empty: no covering, or not evaluated
};

/// What a bar chart draws: horizontal bars, one group per label, top to bottom.
struct BareCoveredBars {
  std::string title;        ///< the chart's own title (drawn above it)
  std::string value_label;  ///< the value axis with its unit: "governing ratio [-]"
  std::vector<BareCoveredBar> bars;
  std::optional<double> limit;  ///< a dashed line at this value, e.g. the ratio 1/SF
  std::string limit_label;      ///< its key entry: "limit 1/SF = 0.5"
};

/// The gnuplot script of `bars` (its title and caption as given): the covered bar in blue, the
/// bare bar in grey below it, each value written at the bar's end; a value that is not finite
/// is left out. 1000 wide, 24 px per bar. Reports lay it out as any chart.
/// @throws std::invalid_argument without bars.
GnuplotChart BareCoveredBarChart(const BareCoveredBars& bars, std::string title, std::string caption);

/// The charts of `simulate --body-region`'s report: BodyRegionRatioChart, then the working points
/// on a foam covering's curve (FoamWorkingPointChartOf; `material` names it). None without
/// judgements (the head alone).
std::vector<GnuplotChart> BodyRegionSimulationCharts(const BodyContactScene& scene,
                                                     std::span<const optim::BodyRegionJudgement> judged,
                                                     const optim::BodyRegionOptions& options,
                                                     const std::optional<std::string>& material);

/// The body-region ratio chart from its judgements: the governing ratio [-] per region (several
/// regions), or the force and pressure ratios [-] of the one region, `covered` (empty: no
/// covering, the bare robot alone) beside `bare` (one per region, in the same order; an empty
/// one is not drawn), the limit 1/`safety_factor` dashed; `note` ends the caption.
/// @throws std::invalid_argument without regions, or with `bare` and `covered` of other sizes.
GnuplotChart BodyRegionRatioChart(std::span<const optim::BodyRegionJudgement> covered,
                                  std::span<const std::optional<optim::BodyRegionJudgement>> bare, double safety_factor,
                                  const std::string& note);

/// `simulate --body-region`: the governing ratio [-] per region judged (several regions), or
/// the force and pressure ratios [-] of the one region, for the covered robot and the bare
/// robot (the same contact judged again with covering thickness 0, by optim::JudgeBodyContact
/// under `options`), with the limit 1/SF. A bare judgement the model refuses (or a bare robot
/// without a contact area, whose pressure is not evaluated) is left out and the caption says so.
/// @throws std::invalid_argument without judgements.
GnuplotChart BodyRegionRatioChart(const BodyContactScene& scene, std::span<const optim::BodyRegionJudgement> judged,
                                  const optim::BodyRegionOptions& options);

/// `optimize --body-region`'s report chart: BodyRegionRatioChart of every region for the bare
/// robot (result.bare_robot) and with the recommended covering (or, none admissible, the best
/// candidate at the thickest scanned), the caption naming the covering. None for the head alone.
std::vector<GnuplotChart> BodyRegionDesignCharts(const optim::BodyRegionDesignRequest& request,
                                                 const optim::BodyRegionDesignResult& result);

/// `robot --trajectory --body-region`'s report chart: the largest governing ratio over
/// `regions` [-] at each sample over time [s] (0 at rest), the limit 1/`safety_factor` dashed,
/// the sample that sets the safe speed scale marked. None without samples (the head alone).
std::vector<GnuplotChart> BodyRegionTrajectoryCharts(const optim::BodyRegionTrajectoryCheck& check,
                                                     std::span<const materials::BodyLimits> regions,
                                                     double safety_factor);

/// `speed-limit --body-region`: the largest safe speed [m/s] per row of the table (region and
/// area, and the mass where the table has several), bare robot against covered.
/// @throws std::invalid_argument without rows.
GnuplotChart BodyRegionSpeedChart(std::span<const report::BodyRegionTableRow> rows);

/// `audit`: the governing ratio of every link × region (the worst over the motion's samples and
/// the link's points), its value written in the cell, green below the limit 1/SF and red above.
/// 1100 wide.
GnuplotChart AuditRegionMap(const audit::AuditResult& result, double safety_factor);

}  // namespace covopt::chart
