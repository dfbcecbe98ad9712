#include "speed_limit.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/chart/region_charts.hpp"
#include "covopt/core/quantity.hpp"
#include "covopt/optim/target_speed_limits.hpp"
#include "covopt/report/body_contact_json.hpp"
#include "covopt/report/csv.hpp"
#include "covopt/report/speed_limit_text.hpp"
#include "covopt/scene_file/targets.hpp"
#include "body_region_output.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "report_option.hpp"

namespace covopt::cli {

using namespace body_text;

namespace {

/// speed-limit's plan, checked for the body-region table. @throws std::invalid_argument (InputError).
SpeedLimitPlan ResolveRegionSpeedLimit(const SpeedLimitCommandOptions& options, const BodyRegionPlan& regions) {
  if (options.solve_for && *options.solve_for == "mass") {
    throw InputError("--solve-for mass with --body-region: the body-region table solves for the speed; drop one");
  }
  if (options.plot_file) throw InputError("--plot with --body-region: the table has no chart; drop --plot");
  SpeedLimitPlan plan = ResolveSpeedLimit(options);
  // A braking robot's limits are bracketed on the time path, which --method/--rtol/--max-steps set.
  if (options.oracle.given() && !plan.coverings.front().scene.robot_brakes()) {
    throw InputError("--oracle/--method/--rtol with --body-region: the body-region limits are in closed form on the "
                     "energy balance; drop them");
  }
  for (const SimulationPlan& covering : plan.coverings) {
    if (!covering.ranges.empty()) {
      throw InputError(fmt::format("{} '{}': scene ranges (uncertain inputs) are not taken with --body-region",
                                   covering.ranges.front().source, covering.ranges.front().text));
    }
    CheckBodyRegionScene(regions, covering);
  }
  return plan;
}

/// The input warnings of every covering (each once) and the bare robot's missing contact area.
std::vector<std::string> RegionSpeedLimitWarnings(const SpeedLimitPlan& plan, const BodyRegionPlan& regions) {
  std::vector<std::string> warnings;
  for (const SimulationPlan& covering : plan.coverings) {
    for (std::string& w : InputWarnings(covering)) {
      if (std::find(warnings.begin(), warnings.end(), w) == warnings.end()) warnings.push_back(std::move(w));
    }
  }
  warnings.insert(warnings.end(), regions.notes.begin(), regions.notes.end());
  if (const auto note = scene_file::BarePressureNote(regions)) warnings.push_back(AsFlags(*note));
  return warnings;
}

/// The text table: the robot, the contact, the criterion, one block of rows per material and
/// robot mass, the scope and the warnings.
void PrintRegionSpeedLimitTable(std::ostream& out, const SpeedLimitPlan& plan, const BodyRegionPlan& regions,
                                const std::vector<report::BodyRegionTableRow>& rows, const optim::DesignRule& rule,
                                const std::vector<std::string>& warnings) {
  const SimulationPlan& first = plan.coverings.front();
  const BodyContactScene first_scene = BodyContactSceneOf(first.scene, regions);
  const std::vector<materials::BodyLimits> iso = regions.IsoLimits();
  fmt::print(out, "Robot      {}\n",
             plan.coverings.size() == 1 ? RobotSurface(first_scene, MaterialName(first))
                                        : fmt::format("{}; covering {} of {} materials, one block each",
                                                      std::isinf(first_scene.robot_radius_m)
                                                          ? std::string("flat robot")
                                                          : "robot radius " + Mm(first_scene.robot_radius_m),
                                                      Mm(first_scene.covering.thickness_m), plan.coverings.size()));
  fmt::print(out, "Contact    {}\n", ContactText(regions));
  if (regions.has_iso()) fmt::print(out, "Limits     {}\n", LimitTableText(regions));
  if (first_scene.robot_brakes()) {
    fmt::print(out, "Braking    {}: each ISO limit bracketed on it from the unbraked one\n", BrakingText(first_scene));
  }
  fmt::print(out, "Criterion  {}\n", BodyCriterion(rule, regions));
  fmt::print(out, "Speeds     the largest safe impact speed, bare and with the covering; 'binds' is the limit reached\n");
  report::PrintBodyRegionSpeedLimitRows(out, rows);
  fmt::print(out, "\nScope      (p_lim in N/cm²)\n");
  if (iso.size() <= 3) {
    for (const materials::BodyLimits& limits : iso) fmt::print(out, "  {}\n", limits.Describe());
  } else if (!iso.empty()) {
    fmt::print(out, "  {}, {} contact{}: each row's F_lim and p_lim, k_H and m_H\n", regions.Citation(),
               ToString(regions.contact),
               regions.contact == ContactType::kTransient ? " (each region's transient factor × quasi-static)"
                                                          : " (quasi-static)");
  }
  if (regions.has_head()) {
    fmt::print(out, "  head: {}\n", HeadCriteriaName());
    for (const std::string& line :
         optim::HeadVerdictScope(LimitRule(plan.options, first))) {
      fmt::print(out, "    {}\n", line);
    }
  }
  for (const std::string& w : warnings) fmt::print(out, "Warning: {}\n", w);
  if (plan.csv_file) fmt::print(out, "Wrote      {}\n", *plan.csv_file);
}

}  // namespace

int RunBodyRegionSpeedLimit(const SpeedLimitCommandOptions& options, const BodyRegionPlan& regions,
                            std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "speed-limit");
  SpeedLimitPlan plan;
  try {
    plan = ResolveRegionSpeedLimit(options, regions);
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(e.what());
  }

  std::vector<report::BodyRegionTableRow> rows;
  optim::DesignRule rule;
  try {
    for (const SimulationPlan& covering : plan.coverings) {
      optim::TargetSpeedLimitRequest request{covering.scene, BodyContactSceneOf(covering.scene, regions), plan.values,
                                             BodyRegionOptionsOf(covering, options.allow_full_compression,
                                                                 options.allow_crushing),
                                             plan.options, plan.options.oracle.time_path};
      request.head_options.covering_compressive_strength_Pa = CrushCheckOf(covering).compressive_strength_Pa;
      rule = optim::JudgedRule(request.region_options);
      // A limit the time path could not answer (a braking robot) is no answer at all: exit 1.
      const optim::TargetSpeedLimits table = optim::TargetSpeedLimitTable(request, regions);
      if (!table.failure.empty()) return errors.Failed(table.failure);
      for (const optim::TargetSpeedLimit& row : table.rows) {
        rows.push_back(report::TableRow(row, MaterialName(covering).value_or("")));
      }
    }
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(AttributeError(e.what(), plan.coverings.front()));
  }

  const std::vector<std::string> warnings = RegionSpeedLimitWarnings(plan, regions);
  const auto csv_text = [&] {
    std::string text;
    report::AppendCsvRecord(text, report::BodyRegionTableColumns());
    for (const report::BodyRegionTableRow& row : rows) report::AppendCsvRecord(text, report::BodyRegionTableCsvCells(row));
    return text;
  };
  try {
    if (plan.csv_file && *plan.csv_file != "-") WriteFileAtomically(*plan.csv_file, csv_text());
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }
  const SimulationPlan& first = plan.coverings.front();
  const BodyContactScene first_scene = BodyContactSceneOf(first.scene, regions);
  if (plan.json || options.report.file) {
    try {
      PrintAndReport(out, plan.json,
                     report::BodyRegionSpeedLimitJson(first_scene,
                                                      plan.coverings.size() == 1 ? MaterialName(first) : std::nullopt,
                                                      BodyCriterion(rule, regions), rule.safety_factor,
                                                      rows, warnings),
                     options.run, options.report, first.inputs, report::ReportKind::kSpeedLimit,
                     [&] { return std::vector{chart::BodyRegionSpeedChart(rows)}; });
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (!plan.json && plan.csv_file && *plan.csv_file == "-") {
    out << csv_text();
  } else if (!plan.json) {
    PrintRegionSpeedLimitTable(out, plan, regions, rows, rule, warnings);
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace covopt::cli
