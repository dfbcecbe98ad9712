#include "retime.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ostream.h>

#include "covopt/audit/retime.hpp"
#include "covopt/audit/retime_inputs.hpp"
#include "covopt/audit/summary.hpp"
#include "covopt/chart/retime_charts.hpp"
#include "covopt/report/retime_json.hpp"
#include "covopt/report/summary_json.hpp"
#include "covopt/robot/trajectory.hpp"
#include "catalog_options.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "output_options.hpp"
#include "plot.hpp"
#include "quantity.hpp"
#include "report_option.hpp"
#include "simulation_plan.hpp"

namespace covopt::cli {
namespace {

constexpr std::string_view kFooter = R"(The program's path (its joint positions, sample by sample) is kept; its timing
becomes the fastest that is safe at every sample and keeps the joints' speed and
acceleration limits: the audit gives each sample's largest safe path speed (its
safe speed scale alone), the time-optimal parameterisation (TOPP-RA, Pham and
Pham 2018) the timing under it, and the re-timed program is audited again. The
cycle time is compared with the original's and with the uniform slow-down's
(the whole program slowed by the audit's one safe speed scale).

--thickness A..B:N: the cycle time against the covering's thickness, per
--material (repeatable), and with --design the per-link design's point.

Joint limits are SI: rad/s and rad/s² (m/s, m/s² for a prismatic joint); the
URDF gives no acceleration limit, so --joint-accel-limit is required.

Exit codes: 0 an answer (a safe timing, or none: its status says why); 1 an
output could not be written; 2 bad input.)";

/// "10" or "10,10,8": the joints' limits as typed (SI numbers; "inf": none).
std::vector<double> ParseLimits(const std::string& typed, const char* flag) {
  std::vector<double> values;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = typed.find(',', start);
    std::string item = typed.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    const auto first = item.find_first_not_of(' ');
    item = first == std::string::npos ? std::string() : item.substr(first, item.find_last_not_of(' ') - first + 1);
    double value = 0.0;
    const auto [stop, ec] = std::from_chars(item.data(), item.data() + item.size(), value);
    if (item.empty() || ec != std::errc() || stop != item.data() + item.size()) {
      throw InputError(fmt::format("{}: expected numbers in SI units (rad/s, rad/s²), one for every joint or one per "
                                   "joint, comma-separated (got '{}' in '{}')",
                                   flag, item, typed));
    }
    values.push_back(value);
    if (comma == std::string::npos) return values;
    start = comma + 1;
  }
}

/// Everything the outputs need.
struct RetimeRun {
  explicit RetimeRun(ResolvedAuditInputs r) : resolved(std::move(r)) {}
  ResolvedAuditInputs resolved;
  audit::RetimeOptions options;
  std::optional<report::RetimeSweep> sweep;
  std::vector<std::string> materials;
};

std::optional<PlotFormat> CheckPlot(const std::optional<std::string>& file, const char* flag) {
  if (!file) return std::nullopt;
  std::optional<PlotFormat> format = PlotFormatFor(*file);
  if (!format) throw InputError(fmt::format("{}: cannot tell the format of '{}'; name the file *.png or *.svg", flag, *file));
  return format;
}

void CheckOutputFlags(const RetimeCommandOptions& o) {
  if (o.output) {
    if (o.output->empty() || *o.output == "-") throw InputError("--output: give a file name (FILE.csv)");
    const std::filesystem::path parent = std::filesystem::path(*o.output).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent)) {
      throw InputError(fmt::format("--output '{}': the directory '{}' does not exist", *o.output, parent.string()));
    }
  }
  CheckPlot(o.plot_file, "--plot");
  CheckPlot(o.thickness_plot, "--thickness-plot");
  if (o.thickness_plot && !o.thickness) throw InputError("--thickness-plot needs --thickness (the sweep it draws)");
  if (o.materials.size() > 1 && !o.thickness) {
    throw InputError(fmt::format("--material is given {} times; more than one needs --thickness (one sweep line per "
                                 "material)",
                                 o.materials.size()));
  }
}

/// The flags resolved: the audit's inputs, the joints' limits, the sweep's grid and designs.
RetimeRun Resolve(const RetimeCommandOptions& o) {
  CheckOutputFlags(o);
  AuditInputOptions inputs = o;
  if (!o.materials.empty()) inputs.scene.material = o.materials.front();
  RetimeRun run(ResolveAuditInputs(inputs));
  const std::size_t joints = run.resolved.assembled.setup.chain.joint_count();
  if (!o.joint_accel_limit) {
    throw InputError("--joint-accel-limit is required (the URDF gives no acceleration limit): one value in rad/s² for "
                     "every joint, or one per joint, comma-separated");
  }
  run.options.joint_acceleration_limits = audit::JointLimitVector(
      ParseLimits(*o.joint_accel_limit, "--joint-accel-limit"), joints, "--joint-accel-limit",
      audit::kMaxJointAccelerationLimit, false);
  if (o.joint_speed_limit) {
    run.options.joint_speed_limits =
        audit::JointLimitVector(ParseLimits(*o.joint_speed_limit, "--joint-speed-limit"), joints,
                                "--joint-speed-limit", audit::kMaxJointSpeedLimit, true);
  }
  if (o.max_speed_scale) {
    const std::vector<double> scale = ParseLimits(*o.max_speed_scale, "--max-speed-scale");
    if (scale.size() != 1 || !(scale.front() > 0.0 && scale.front() <= 100.0)) {
      throw InputError(fmt::format("--max-speed-scale: expected one number in (0, 100] (got '{}')", *o.max_speed_scale));
    }
    run.options.max_speed_scale = scale.front();
  }
  run.options.keep_ratio_over_time = false;
  if (o.thickness) {
    report::RetimeSweep sweep;
    sweep.thicknesses_m = audit::ThicknessGrid(*o.thickness, "--thickness");
    const materials::Catalog catalog = LoadCatalog(o.scene.catalog);
    sweep.designs = audit::CycleTimeDesigns(run.resolved.assembled, catalog, o.materials, o.design, "--material");
    run.sweep = std::move(sweep);
  }
  return run;
}

std::string Number(double value) { return std::isfinite(value) ? fmt::format("{:.4g}", value) : std::string("-"); }

void PrintSweep(std::ostream& out, const report::RetimeSweep& sweep) {
  fmt::print(out, "\nCycle time against covering thickness (re-timed; uniform slow-down)\n");
  fmt::print(out, "  {:<36} {:>10} {:>11} {:>11} {:>8}  {}\n", "covering", "thickness", "cycle [s]", "uniform [s]",
             "scale", "status");
  for (const audit::CycleTimePoint& p : sweep.points) {
    fmt::print(out, "  {:<36} {:>10} {:>11} {:>11} {:>8}  {}\n",
               p.design < sweep.designs.size() ? sweep.designs[p.design].name : std::string("?"),
               FormatQuantity(p.thickness_m, QuantityKind::kLength), Number(p.cycle_time_s),
               Number(p.uniform_cycle_time_s), Number(p.safe_speed_scale), audit::ToString(p.status));
  }
}

void PrintText(std::ostream& out, const RetimeCommandOptions& o, const RetimeRun& run, const audit::RetimeResult& r) {
  const audit::AuditSetup& setup = run.resolved.assembled.setup;
  PrintAuditInputs(out, o, run.resolved.assembled, r.original_time_s.size());
  const auto limits = [](const Eigen::VectorXd& v) {
    std::vector<std::string> items;
    for (const double x : v) items.push_back(std::isfinite(x) ? fmt::format("{:g}", x) : std::string("none"));
    return fmt::format("{}", fmt::join(items, ", "));
  };
  fmt::print(out, "Joints     speed limits [rad/s] {}; acceleration limits [rad/s²] {}\n", limits(r.joint_speed_limits),
             limits(r.joint_acceleration_limits));
  fmt::print(out, "Verdict    {}\n{}", r.message,
             report::SummaryText(audit::SummarizeRetime(setup, r, run.options.tolerance), 11));
  const bool answer = r.status == audit::RetimeStatus::kSafe || r.status == audit::RetimeStatus::kAtRest;
  fmt::print(out, "Cycle time re-timed {} s; original {} s; uniform slow-down {} s (scale {})\n",
             answer ? Number(r.cycle_time_s) : std::string("-"), Number(r.original_cycle_time_s),
             Number(r.uniform_cycle_time_s), Number(r.uniform_speed_scale));
  const std::vector<audit::RetimeSlowdown> slowdowns = audit::RetimeSlowdowns(r);
  if (answer && slowdowns.empty()) fmt::print(out, "\nThe program never had to slow.\n");
  if (!slowdowns.empty()) {
    fmt::print(out, "\nWhere the program had to slow (original program's time)\n");
    fmt::print(out, "  {:>8} {:>8}  {:>9}  {}\n", "from [s]", "to [s]", "slowest", "what binds there");
    for (const audit::RetimeSlowdown& d : slowdowns) {
      const std::string what = !d.link.empty() ? fmt::format("{} against {}", d.link, d.region)
                               : d.bound == "path-speed" ? std::string("the largest speed scale (--max-speed-scale)")
                                                         : d.bound;
      fmt::print(out, "  {:>8.4g} {:>8.4g}  {:>9.4g}  {}\n", d.start_time_s, d.end_time_s, d.min_path_speed, what);
    }
  }
  if (run.sweep) PrintSweep(out, *run.sweep);
  fmt::print(out, "\nScope\n");
  for (const std::string& s : r.scope) fmt::print(out, "  {}\n", s);
  std::vector<std::string> warnings = run.resolved.assembled.input_warnings;
  warnings.insert(warnings.end(), r.warnings.begin(), r.warnings.end());
  if (warnings.empty()) fmt::print(out, "\nWarnings: none\n");
  for (const std::string& w : warnings) fmt::print(out, "Warning: {}\n", w);
  std::vector<std::string> files;
  for (const auto& file : {o.output, o.plot_file, o.thickness_plot}) {
    if (file && answer) files.push_back(*file);
  }
  if (!files.empty()) fmt::print(out, "Wrote      {}\n", fmt::join(files, ", "));
}

}  // namespace

void SetupRetime(CLI::App* sub, RetimeCommandOptions& options) {
  sub->footer(std::string(kFooter));
  AddAuditInputOptions(*sub, options,
                       "with --thickness: add the per-link design (each link's thinnest catalog covering safe at full "
                       "speed) to the sweep");
  // --material is repeatable here (one sweep line per material; the first is the covering of every link).
  sub->remove_option(sub->get_option("--material"));
  sub->add_option("--material", options.materials,
                  "covering modulus and Poisson ratio from the material catalog; with --thickness repeat it for one "
                  "sweep line per material")
      ->type_name("NAME")
      ->group("Scene");
  constexpr const char* kRetime = "Re-timing";
  sub->add_option("--joint-accel-limit", options.joint_accel_limit,
                  "the joints' largest acceleration, rad/s² (m/s² prismatic): one value, or one per joint "
                  "comma-separated (required: a URDF gives none)")
      ->type_name("A[,A...]")
      ->group(kRetime);
  sub->add_option("--joint-speed-limit", options.joint_speed_limit,
                  "the joints' largest speed, rad/s (m/s prismatic): one value, or one per joint comma-separated; inf: "
                  "none (default: the URDF's <limit velocity>)")
      ->type_name("V[,V...]")
      ->group(kRetime);
  sub->add_option("--max-speed-scale", options.max_speed_scale,
                  "the largest speed relative to the program, in (0, 100] (default 1: never faster than programmed)")
      ->type_name("X")
      ->group(kRetime);
  sub->add_option("--thickness", options.thickness,
                  "the cycle time against the covering's thickness, e.g. 0..40mm:9 or 0,5mm,10mm (every link wears "
                  "it; per --material)")
      ->type_name("A..B:N")
      ->group(kRetime);
  AddJsonFlag(*sub, options.json);
  AddOutputFileOption(*sub, "--output", options.output, "write the re-timed trajectory (the same columns and joints)",
                      "FILE.csv");
  AddOutputFileOption(*sub, "--plot", options.plot_file, "chart of the speed scale over the program's time (gnuplot)",
                      "FILE.png|FILE.svg");
  AddOutputFileOption(*sub, "--thickness-plot", options.thickness_plot,
                      "chart of the cycle time against the covering's thickness (gnuplot; with --thickness)",
                      "FILE.png|FILE.svg");
  AddReportOption(*sub, options.report);
}

int RunRetime(const RetimeCommandOptions& o, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "retime");
  std::optional<RetimeRun> resolved;
  audit::RetimeResult result;
  try {
    resolved.emplace(Resolve(o));
    const audit::AssembledAudit& a = resolved->resolved.assembled;
    result = audit::Retime(a.setup, a.trajectory, resolved->options);
    if (resolved->sweep) {
      resolved->sweep->points = audit::CycleTimeAgainstThickness(a.setup, a.trajectory, resolved->options,
                                                                 resolved->sweep->designs, resolved->sweep->thicknesses_m);
    }
  } catch (const std::invalid_argument& e) {  // InputError and the library's own checks
    return errors.BadInput(e.what());
  }
  const RetimeRun& run = *resolved;
  const audit::AuditSetup& setup = run.resolved.assembled.setup;
  const bool answer = result.status == audit::RetimeStatus::kSafe || result.status == audit::RetimeStatus::kAtRest;
  try {
    if ((o.plot_file || o.thickness_plot || o.report.file) && !FindOnPath("gnuplot")) {
      return errors.Failed(kGnuplotMissing);
    }
    const std::string name = std::filesystem::path(*o.trajectory).filename().string();
    if (answer && o.output) {
      std::ostringstream csv;
      robot::WriteJointTrajectory(csv, result.trajectory, setup.chain.joint_names());
      WriteFileAtomically(*o.output, csv.str());
    }
    if (answer && o.plot_file) RunGnuplot(*o.plot_file, chart::RetimeSpeedChart(result, name));
    if (answer && o.thickness_plot) {
      RunGnuplot(*o.thickness_plot, chart::CycleTimeChart(*run.sweep, result.original_cycle_time_s));
    }
    if (o.json || o.report.file) {
      const std::string json = report::RetimeJson(setup, result, run.options, run.sweep ? &*run.sweep : nullptr,
                                                  run.resolved.assembled.input_warnings);
      PrintAndReport(out, o.json, json, o.run, o.report, run.resolved.inputs, report::ReportKind::kRetime, [&] {
        std::vector<chart::GnuplotChart> charts;
        if (!result.path_speed.empty()) charts.push_back(chart::RetimeSpeedChart(result, name));
        if (run.sweep && !run.sweep->points.empty()) {
          charts.push_back(chart::CycleTimeChart(*run.sweep, result.original_cycle_time_s));
        }
        return charts;
      });
    }
    if (!o.json) PrintText(out, o, run, result);
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace covopt::cli
