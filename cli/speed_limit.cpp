#include "speed_limit.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string_view>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ostream.h>

#include "errors.hpp"
#include "output.hpp"
#include "limit_search_output.hpp"
#include "report_option.hpp"
#include "sweep_axis_option.hpp"
#include "uncertainty_options.hpp"
#include "covopt/optim/design.hpp"
#include "covopt/optim/robust_design.hpp"
#include "covopt/optim/speed_limit_table.hpp"
#include "covopt/report/csv.hpp"
#include "covopt/report/robust_json.hpp"
#include "covopt/optim/summaries.hpp"
#include "covopt/report/speed_limit_json.hpp"
#include "covopt/report/summary_json.hpp"
#include "covopt/report/speed_limit_text.hpp"
#include "output_options.hpp"
#include "rule_options.hpp"

namespace covopt::cli {
namespace {

using optim::SpeedLimitQuantity;
using optim::SpeedLimitRow;

constexpr std::string_view kFooter = R"(Values take a unit as in 'covopt simulate' (10kg, 2m/s, 15mm, 27.6MPa).
The max safe speed is the largest v0 such that every speed up to it is safe:
both injury ratios <= 1/--safety-factor and (default criterion) the covering
not fully compressed at the peak. The search stops at the model's 100 m/s and
says so. --robot-mass (or --speed with --solve-for mass) takes one value or a
list/range as in 'covopt sweep': 0.5kg..50kg:log:20,fixed gives one row each.
--material may be repeated: one block of rows and one chart curve each.
--plot draws the speed limit over the reflected mass (log axes), one curve per
covering and one for the bare robot, over the range of --robot-mass (without a
list, 0.5 kg .. 200 kg).

The oracle (--oracle): auto takes the exact path's solve along the
penetration where the scene allows it (the conservative two-mass impact),
the exact path with damping, the time path with braking or a neck; time-path
runs the SUNDIALS integrator --method at --rtol on every impact of a
bracketed bisection.

Exit codes: 0 an answer (also "no speed is safe"); 1 an output could not be
written; 2 bad input.)";

/// Reads a value or list/range typed after `flag` for the sweep axis `axis_name`.
std::vector<double> ParseValues(const std::string& text, std::string_view axis_name, std::string_view flag) {
  try {
    return ParseSweepAxis(fmt::format("{}={}", axis_name, text), flag).values;
  } catch (const InputError& e) {
    // The axis parser quotes "NAME=SPEC"; the user typed SPEC after the flag.
    std::string message = e.what();
    const std::string quoted = fmt::format("'{}=", axis_name);
    for (std::size_t at = message.find(quoted); at != std::string::npos; at = message.find(quoted, at + 1)) {
      message.replace(at, quoted.size(), "'");
    }
    // "... (got 'SPEC') in 'SPEC'": once is enough.
    const std::string suffix = fmt::format(" in '{}'", text);
    if (message.size() > suffix.size() && message.ends_with(suffix) &&
        message.find(fmt::format("'{}'", text)) < message.size() - suffix.size()) {
      message.resize(message.size() - suffix.size());
    }
    throw InputError(message);
  }
}

/// The rows of every covering: one library call.
std::vector<SpeedLimitRow> ComputeRows(const SpeedLimitPlan& plan, std::string* bad_input) {
  std::vector<optim::SpeedLimitCovering> coverings;
  for (const SimulationPlan& covering : plan.coverings) {
    optim::SpeedLimitOptions options = plan.options;
    options.covering_compressive_strength_Pa = CrushCheckOf(covering).compressive_strength_Pa;
    coverings.push_back({covering.scene,
                         covering.covering_material ? std::optional(covering.covering_material->name) : std::nullopt,
                         options});
  }
  try {
    return optim::SpeedLimitTable(plan.quantity, coverings, plan.values);
  } catch (const optim::SpeedLimitTableError& e) {
    *bad_input = AttributeError(e.what(), plan.coverings[e.covering_index()]);
    return {};
  }
}

std::string CsvText(const SpeedLimitPlan& plan, const std::vector<SpeedLimitRow>& rows) {
  std::string text;
  report::AppendCsvRecord(text, report::SpeedLimitColumns(plan.quantity));
  for (const SpeedLimitRow& row : rows) {
    report::AppendCsvRecord(text, report::SpeedLimitCsvCells(plan.quantity, row));
  }
  return text;
}

}  // namespace

report::GnuplotChart SpeedLimitChartOf(const SpeedLimitPlan& plan) {
  report::SpeedLimitChartInput input{{}, plan.values, plan.options};
  for (const SimulationPlan& covering : plan.coverings) {
    input.coverings.push_back(
        {covering.scene, covering.covering_material ? std::optional(covering.covering_material->name) : std::nullopt});
  }
  return report::SpeedLimitChart(input);
}

void SetupSpeedLimit(CLI::App* sub, SpeedLimitCommandOptions& options) {
  sub->footer(std::string(kFooter));
  AddSceneOptions(*sub, options.scene);
  AddRobotModelOptions(*sub, options.scene.robot_model, true, "Robot model (instead of --robot-mass)");
  AddBodyRegionOptions(*sub, options.scene.body);
  // --material is repeatable here (one block of rows and one chart curve each).
  sub->remove_option(sub->get_option("--material"));
  sub->add_option("--material", options.materials,
                  "covering modulus and Poisson ratio from the material catalog; repeat it for one block of "
                  "rows and one chart curve per material")
      ->type_name("NAME")
      ->group("Scene");
  AddRuleOptions(*sub, {.safety_factor = &options.scene.safety_factor,
                        .allow_full_compression = &options.allow_full_compression,
                        .allow_crushing = &options.allow_crushing,
                        .keep_travel = &options.scene.keep_travel});
  sub->add_option("--solve-for", options.solve_for,
                  "speed (default): the max safe speed per --robot-mass; mass: the max safe reflected mass per "
                  "--speed")
      ->type_name("speed|mass")
      ->group("Limits");
  AddOracleOptions(*sub, options.oracle, "the impacts of the search", "Oracle");
  AddJsonFlag(*sub, options.json);
  AddOutputFileOption(*sub, "--csv", options.csv_file, "write the rows as CSV ('-': to stdout instead of the table)", "FILE.csv|-");
  AddOutputFileOption(*sub, "--plot", options.plot_file, "chart with gnuplot: max safe speed over reflected mass, one curve per --material and the "
                  "bare robot", "FILE.png|FILE.svg");
  AddReportOption(*sub, options.report);
}

SpeedLimitPlan ResolveSpeedLimit(const SpeedLimitCommandOptions& options) {
  SpeedLimitPlan plan;
  if (options.solve_for) {
    if (*options.solve_for == "speed") {
      plan.quantity = SpeedLimitQuantity::kSpeed;
    } else if (*options.solve_for == "mass") {
      plan.quantity = SpeedLimitQuantity::kMass;
    } else {
      throw InputError(fmt::format("--solve-for: expected speed or mass (got '{}')", *options.solve_for));
    }
  }
  const bool by_speed = plan.quantity == SpeedLimitQuantity::kSpeed;
  // The quantity solved for is not an input; the one the rows vary may be a list.
  const std::string solved_key = by_speed ? "robot.speed" : "robot.mass";
  const std::string varied_key = by_speed ? "robot.mass" : "robot.speed";
  const std::string_view solved_flag = by_speed ? "--speed" : "--robot-mass";
  const std::string_view varied_flag = by_speed ? "--robot-mass" : "--speed";
  if (const auto typed = options.scene.scene_values.find(solved_key); typed != options.scene.scene_values.end()) {
    throw InputError(fmt::format("{} '{}': speed-limit --solve-for {} computes it; drop {}{}", solved_flag,
                                 typed->second, by_speed ? "speed" : "mass", solved_flag,
                                 by_speed ? " (or add --solve-for mass for the max safe mass at that speed)" : ""));
  }
  SimulateOptions scene_options = options.scene;
  scene_options.json = false;
  scene_options.accept_ranges = true;  // other inputs as LO..HI: the limit over the box (RunSpeedLimit)
  std::optional<std::string> varied_text;
  if (const auto typed = scene_options.scene_values.find(varied_key); typed != scene_options.scene_values.end()) {
    varied_text = typed->second;
    scene_options.scene_values.erase(typed);
  }
  if (options.scene.robot_model.given() && (!by_speed || varied_text)) {  // --urdf: one robot mass
    // The ISO fallback (--robot-moving-mass) is refused alike.
    const std::string source = options.scene.robot_model.iso_fallback() ? "--robot-moving-mass" : "--urdf";
    throw InputError(by_speed ? fmt::format("--robot-mass and {} both give the robot mass; give one ({})", source,
                                            source == "--urdf" ? "--urdf computes the reflected mass from the robot model"
                                                               : "--robot-moving-mass M is ISO/TS 15066's M/2 + m_L")
                              : fmt::format("{} gives the robot mass, which --solve-for mass computes; drop one of them",
                                            source));
  }
  if (!options.materials.empty() && (scene_options.scene_values.count("covering.modulus") != 0 ||
                                     scene_options.scene_values.count("covering.poisson") != 0)) {
    throw InputError(fmt::format("--material '{}' sets the covering's modulus and Poisson ratio; give either "
                                 "--material or --covering-modulus/--covering-poisson, not both",
                                 options.materials.front()));
  }
  // One resolved scene per covering: the one place the scene is read (ResolveSimulation).
  if (options.materials.empty()) {
    plan.coverings.push_back(ResolveSimulation(scene_options));
  } else {
    for (const std::string& name : options.materials) {
      scene_options.material = name;
      plan.coverings.push_back(ResolveSimulation(scene_options));
    }
  }
  if (varied_text) {
    plan.values = ParseValues(*varied_text, by_speed ? "robot-mass" : "speed", varied_flag);
    plan.values_source = fmt::format("{} '{}'", varied_flag, *varied_text);
    for (SimulationPlan& covering : plan.coverings) covering.sources[varied_key] = plan.values_source;
  } else {
    const Scene& scene = plan.coverings.front().scene;
    plan.values = {by_speed ? scene.robot.mass_kg : scene.robot.speed_m_per_s};
  }

  const SimulationPlan& first = plan.coverings.front();
  plan.options.limits = first.limits;
  plan.options.safety_factor = first.safety_factor;
  plan.options.allow_full_compression = options.allow_full_compression;
  plan.options.keep_travel = first.keep_travel;
  plan.options.allow_crushing = options.allow_crushing;
  // The coverings differ only in their covering: the first scene decides what the oracle may be.
  plan.options.oracle = ResolveOracleFlags(options.oracle, first.scene, "search", plan.warnings);
  plan.json = options.json;
  if (options.csv_file) {
    if (options.csv_file->empty()) throw InputError("--csv: empty file name");
    plan.csv_file = options.csv_file;
  }
  if (options.plot_file) {
    if (!by_speed) {
      throw InputError("--plot draws the max safe speed over the reflected mass; it applies with --solve-for "
                       "speed (the default)");
    }
    const auto format = PlotFormatFor(*options.plot_file);
    if (!format) {
      throw InputError(fmt::format("--plot: cannot tell the format of '{}'; name the file *.png or *.svg",
                                   *options.plot_file));
    }
    plan.plot_file = options.plot_file;
    plan.plot_format = *format;
  }
  if (plan.json && plan.csv_file && *plan.csv_file == "-") {
    throw InputError("--json and --csv - both print to stdout; give --csv a file name");
  }
  return plan;
}

namespace {

/// speed-limit with scene ranges (docs/model.md §11): per covering and row, the limit safe for
/// every value in the box (MaxSafeSpeedOverBox / MaxSafeMassOverBox) and where it is set.
int RunRobustSpeedLimit(const SpeedLimitPlan& plan, const SpeedLimitCommandOptions& options, std::ostream& out,
                        std::ostream& err) {
  const CommandErrors errors(err, "speed-limit");
  const bool by_speed = plan.quantity == SpeedLimitQuantity::kSpeed;
  if (plan.csv_file || plan.plot_file || options.oracle.given()) {
    return errors.BadInput(fmt::format("{} with scene ranges: the limit over the box is one number per row, found on "
                                       "the exact path; drop it",
                                       plan.csv_file ? "--csv" : plan.plot_file ? "--plot" : "--oracle/--method/--rtol"));
  }
  std::vector<optim::RobustSpeedLimitRow> rows;
  std::optional<optim::UncertaintyBox> first_box;
  std::string text;
  try {
    for (const SimulationPlan& covering : plan.coverings) {
      const auto uncertain = ResolveUncertainInputs(covering.ranges, {});
      for (const double value : plan.values) {
        Scene nominal = covering.scene;
        (by_speed ? nominal.robot.mass_kg : nominal.robot.speed_m_per_s) = value;
        const optim::UncertaintyBox box = MakeUncertaintyBox(nominal, uncertain, covering.ranges);
        if (!first_box) first_box = box;
        optim::RobustSpeedLimitRow row;
        if (covering.covering_material) row.material = covering.covering_material->name;
        if (by_speed) {
          row.robot_mass_kg = value;
          row.speed_limit = optim::MaxSafeSpeedOverBox(box, plan.options);
        } else {
          row.speed_m_per_s = value;
          row.mass_limit = optim::MaxSafeMassOverBox(box, plan.options);
        }
        text += report::RobustSpeedLimitRowText(box, plan.quantity, row);
        rows.push_back(std::move(row));
      }
    }
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(e.what());
  }
  if (plan.json || options.report.file) {
    try {
      PrintAndReport(out, plan.json, report::RobustSpeedLimitTableJson(plan.quantity, *first_box, rows), options.run,
                     options.report, plan.coverings.front().inputs, report::ReportKind::kSpeedLimit, nullptr);
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (!plan.json) {
    out << "Limits over the box of " << plan.coverings.front().ranges.size() << " uncertain inputs:\n";
    for (const SceneRange& range : plan.coverings.front().ranges) {
      out << fmt::format("  {:<20} {}  (from {})\n", range.name, range.text, range.source);
    }
    out << '\n' << text;
  }
  return 0;
}

}  // namespace

int RunSpeedLimit(const SpeedLimitCommandOptions& options, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "speed-limit");
  if (options.scene.body.any()) {  // ISO/TS 15066 body regions (speed_limit_body_region.cpp)
    return RunWithBodyRegions(options.scene.body, errors, [&](const BodyRegionPlan& regions) {
      return RunBodyRegionSpeedLimit(options, regions, out, err);
    });
  }
  SpeedLimitPlan plan;
  try {
    plan = ResolveSpeedLimit(options);
  } catch (const std::invalid_argument& e) {  // InputError and the library's own checks
    return errors.BadInput(e.what());
  }
  if (!plan.coverings.front().ranges.empty()) return RunRobustSpeedLimit(plan, options, out, err);
  std::string bad_input;
  const std::vector<SpeedLimitRow> rows = ComputeRows(plan, &bad_input);
  if (!bad_input.empty()) return errors.BadInput(bad_input);
  // A row the oracle could not answer is no answer at all: exit 1 with its message.
  if (const SpeedLimitRow* failed = optim::FirstFailedRow(plan.quantity, rows)) {
    return errors.Failed(optim::RowMessage(plan.quantity, *failed) +
                         (failed->material ? " (" + *failed->material + ")" : std::string()));
  }

  std::vector<std::string> input_warnings;
  for (const SimulationPlan& covering : plan.coverings) {
    std::vector<std::string> warnings = InputWarnings(covering);
    for (std::string& note : CrushCheckOf(covering).notes) warnings.push_back(std::move(note));
    for (std::string& w : warnings) {
      if (std::find(input_warnings.begin(), input_warnings.end(), w) == input_warnings.end()) {
        input_warnings.push_back(std::move(w));
      }
    }
  }
  for (const std::string& w : plan.warnings) input_warnings.push_back(w);
  const Scene& scene = plan.coverings.front().scene;
  try {
    if ((plan.plot_file || options.report.file) && !FindOnPath("gnuplot")) return errors.Failed(kGnuplotMissing);
    if (plan.csv_file && *plan.csv_file != "-") WriteFileAtomically(*plan.csv_file, CsvText(plan, rows));
    if (plan.plot_file) {
      RunGnuplot(*plan.plot_file, SpeedLimitChartOf(plan));
    }
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }

  if (plan.json || options.report.file) {
    try {
      PrintAndReport(out, plan.json, report::SpeedLimitJson(plan.quantity, scene, plan.options, rows, input_warnings),
                     options.run, options.report, plan.coverings.front().inputs, report::ReportKind::kSpeedLimit,
                     [&] { return std::vector{SpeedLimitChartOf(plan)}; });
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (!plan.json && plan.csv_file && *plan.csv_file == "-") {
    out << CsvText(plan, rows);
  } else if (!plan.json) {
    const bool by_speed = plan.quantity == SpeedLimitQuantity::kSpeed;
    std::vector<std::string_view> omitted{"robot.mass", "robot.speed"};
    if (plan.coverings.size() > 1) omitted.push_back("covering.modulus");
    std::string headline = SceneHeadline(scene, omitted);
    if (!by_speed && plan.values.size() == 1) headline += fmt::format("; at {:g} m/s", plan.values.front());
    fmt::print(out, "Scene      {}\n", headline);
    if (plan.coverings.size() == 1 && plan.coverings.front().covering_material && scene.covering.thickness_m > 0.0) {
      fmt::print(out, "Material   {}\n", plan.coverings.front().covering_material->name);
    }
    PrintLimitsAndCriterion(out, plan.options, plan.coverings.front());
    fmt::print(out, "Search     {}; the ratios are those of the impact at the limit\n\n",
               by_speed ? fmt::format("speeds up to {:g} m/s (the model's ceiling)", plan.options.max_speed_m_per_s)
                        : fmt::format("reflected masses up to {:g} kg (the model's ceiling){}", plan.options.max_mass_kg,
                                      std::isinf(scene.head.mass_kg) ? "" : ", and a fixed robot"));
    if (!rows.empty()) {
      // The δ-axis solve of the exact path goes without saying; a bisection on an oracle is said.
      const optim::OracleReport oracle = optim::SpeedLimitOracle(plan.quantity, rows);
      const bool bracketed = by_speed ? rows.front().speed_limit.bracketed : rows.front().mass_limit.bracketed;
      if (bracketed) {
        fmt::print(out, "Oracle     {}, a bracketed bisection ({} runs{}): {}\n\n", oracle.Name(), oracle.evaluations,
                   oracle.failed_evaluations > 0 ? fmt::format(", {} failed", oracle.failed_evaluations) : "",
                   oracle.reason);
      }
    }
    fmt::print(out, "Verdict    {}\n\n",
               report::SummaryHeadline(optim::SummarizeSpeedLimits(plan.quantity, scene, plan.options, rows)));
    report::PrintSpeedLimitRows(out, plan.quantity, plan.coverings.size() > 1, rows);
    PrintHeadScope(out, plan.options, plan.coverings.front());
    for (const std::string& w : input_warnings) fmt::print(out, "Warning: {}\n", w);
    for (const std::string& w : report::SpeedLimitRowWarnings(plan.quantity, rows)) {
      fmt::print(out, "Warning: {}\n", w);
    }
    if (plan.csv_file || plan.plot_file) {
      fmt::print(out, "Wrote      {}{}{}\n", plan.csv_file.value_or(""), plan.csv_file && plan.plot_file ? ", " : "",
                 plan.plot_file.value_or(""));
    }
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace covopt::cli
