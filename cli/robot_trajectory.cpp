#include "robot_trajectory.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ostream.h>

#include "body_region_options.hpp"
#include "body_region_output.hpp"
#include "covopt/optim/summaries.hpp"
#include "covopt/report/summary_json.hpp"
#include "covopt/chart/region_charts.hpp"
#include "covopt/optim/body_region_trajectory.hpp"
#include "covopt/optim/input_warnings.hpp"
#include "covopt/optim/trajectory_check.hpp"
#include "covopt/report/body_contact_json.hpp"
#include "covopt/report/csv.hpp"
#include "covopt/report/trajectory_json.hpp"
#include "covopt/report/trajectory_text.hpp"
#include "covopt/robot/trajectory.hpp"
#include "errors.hpp"
#include "output.hpp"
#include "plot.hpp"
#include "report_option.hpp"
#include "scene_fields.hpp"
#include "limit_search_output.hpp"
#include "rule_options.hpp"
#include "output_options.hpp"

namespace covopt::cli {
namespace {

/// Everything the check's outputs need.
struct TrajectoryRun {
  SimulationPlan scene;  ///< the covering, head and limits (robot mass and speed unused)
  optim::SpeedLimitOptions limit;
  std::string robot_line;  ///< "fr3: base -> fr3_link8, 7 movable joints; contact point ..."
  std::string tip_link;
  robot::ContactMotionResult motion;
  optim::TrajectoryCheck check;
  std::vector<std::string> input_warnings;
  std::optional<PlotFormat> plot_format;
};

std::string CsvText(const optim::TrajectoryCheck& check) {
  std::string text;
  report::AppendCsvRecord(text, report::TrajectorySampleColumns());
  for (const optim::SampleVerdict& sample : check.samples) {
    report::AppendCsvRecord(text, report::TrajectorySampleCsvCells(sample));
  }
  return text;
}

/// The chain and contact point of --urdf/--base/--tip/--point (the trajectory brings the joints).
RobotModelInput ResolveChainAndPoint(const RobotModelOptions& model) {
  if (!model.urdf) throw InputError("--urdf FILE is required with --trajectory");
  return ResolveRobotModelChain(model);
}

/// A library message about the trajectory's samples, or about the scene.
std::string Attribute(const std::string& message, const SimulationPlan& scene, const std::string& file) {
  if (message.starts_with("trajectory")) return fmt::format("--trajectory '{}': {}", file, message);
  return AttributeError(message, scene);
}

TrajectoryRun Resolve(const RobotModelOptions& model, const RobotTrajectoryOptions& options, bool json) {
  if (model.joints) {
    throw InputError(fmt::format("--joints '{}': not used with --trajectory (the file gives each sample's joint "
                                 "positions); drop --joints",
                                 *model.joints));
  }
  if (model.direction) {
    throw InputError(fmt::format("--direction '{}': not used with --trajectory (each impact is along the contact "
                                 "point's motion); drop --direction",
                                 *model.direction));
  }
  for (const auto& [key, flag] : {std::pair<std::string_view, std::string_view>{"robot.mass", "--robot-mass"},
                                  {"robot.speed", "--speed"}}) {
    if (const auto typed = options.scene.scene_values.find(key); typed != options.scene.scene_values.end()) {
      throw InputError(fmt::format("{} '{}': not used with --trajectory (each sample's {} comes from the robot "
                                   "model and the file); drop {}",
                                   flag, typed->second,
                                   key == "robot.mass" ? "reflected mass" : "contact-point speed", flag));
    }
  }
  if (options.file->empty()) throw InputError("--trajectory: empty file name");
  TrajectoryRun run;
  run.scene = ResolveSimulation(options.scene);
  run.limit.limits = run.scene.limits;
  run.limit.safety_factor = run.scene.safety_factor;
  run.limit.allow_full_compression = options.allow_full_compression;
  run.limit.keep_travel = run.scene.keep_travel;
  run.limit.covering_compressive_strength_Pa = CrushCheckOf(run.scene).compressive_strength_Pa;
  if (options.csv_file && options.csv_file->empty()) throw InputError("--csv: empty file name");
  if (json && options.csv_file && *options.csv_file == "-") {
    throw InputError("--json and --csv - both print to stdout; give --csv a file name");
  }
  if (options.plot_file) {
    run.plot_format = PlotFormatFor(*options.plot_file);
    if (!run.plot_format) {
      throw InputError(fmt::format("--plot: cannot tell the format of '{}'; name the file *.png or *.svg",
                                   *options.plot_file));
    }
  }
  for (const std::string_view key : {"robot.mass", "robot.speed"}) {
    if (const auto source = run.scene.sources.find(key); source != run.scene.sources.end()) {
      run.input_warnings.push_back(fmt::format("{} from {} is not used: each sample brings its own", key,
                                               source->second));
    }
  }
  for (std::string& w : InputWarnings(run.scene)) run.input_warnings.push_back(std::move(w));
  optim::AppendNewWarnings(run.input_warnings, CrushCheckOf(run.scene).notes);  // the default covering is in both

  const RobotModelInput robot_input = ResolveChainAndPoint(model);
  const robot::KinematicChain& chain = robot_input.chain;
  run.tip_link = chain.tip_link();
  const Eigen::Vector3d& p = robot_input.point_in_tip_m;
  run.robot_line = fmt::format("{}: {} -> {}, {} movable joint{}; contact point ({:.4g}, {:.4g}, {:.4g}) m in {}",
                               chain.robot_name(), chain.base_link(), chain.tip_link(), chain.joint_count(),
                               chain.joint_count() == 1 ? "" : "s", p[0], p[1], p[2], chain.tip_link());
  if (const robot::Payload& payload = chain.payload(); !payload.empty()) {  // counted in every sample's mass
    const Eigen::Vector3d& c = payload.center_of_mass_m;
    run.robot_line += fmt::format("; payload {:.6g} kg at ({:.4g}, {:.4g}, {:.4g}) m in {}", payload.mass_kg, c[0],
                                  c[1], c[2], chain.tip_link());
  }
  try {
    const robot::JointTrajectory trajectory = robot::ReadJointTrajectory(*options.file, chain.joint_count());
    robot::ContactMotionOptions motion_options;
    motion_options.reflected_mass = model.reflected_mass_options();
    run.motion = robot::ContactMotion(chain, trajectory, robot_input.point_in_tip_m, motion_options);
  } catch (const std::invalid_argument& e) {
    throw InputError(fmt::format("--trajectory: {}", e.what()));
  }
  try {
    run.check = optim::CheckTrajectory(run.scene.scene, optim::MotionSamples(run.motion.samples), {run.limit});
  } catch (const std::invalid_argument& e) {
    throw InputError(Attribute(e.what(), run.scene, *options.file));
  }
  return run;
}

/// --trajectory with --body-region: every sample against the ISO regions named
/// (optim::CheckTrajectoryForBodyRegions); the head, when named, by the head's own check.
int RunBodyRegionTrajectory(const TrajectoryRun& run, const RobotTrajectoryOptions& options,
                            const BodyRegionPlan& regions, bool json, const std::optional<RunContext>& context,
                            std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "robot");
  const std::vector<materials::BodyLimits> iso = regions.IsoLimits();
  const optim::BodyRegionOptions body_options = BodyRegionOptionsOf(run.scene, options.allow_full_compression, false);
  std::optional<optim::BodyRegionTrajectoryCheck> check;
  try {
    if (options.csv_file || options.plot_file) {
      throw InputError(fmt::format("{} with --body-region: the samples' table is printed (or --json); drop it",
                                   options.csv_file ? "--csv" : "--plot"));
    }
    CheckBodyRegionScene(regions, run.scene);
    if (!iso.empty()) {
      check = optim::CheckTrajectoryForBodyRegions(BodyContactSceneOf(run.scene.scene, regions), iso,
                                                   optim::MotionSamples(run.motion.samples), body_options);
    }
  } catch (const std::invalid_argument& e) {
    return errors.BadInput(e.what());
  }
  std::optional<report::HeadTrajectorySummary> head;
  if (regions.has_head()) {
    if (run.check.status == optim::TrajectoryCheckStatus::kEvaluationFailed) return errors.Failed(run.check.message);
    head = report::HeadTrajectorySummary{std::string(optim::ToString(run.check.status)), run.check.safe_speed_scale,
                                         run.check.message};
  }
  const std::string criterion = BodyCriterion(optim::JudgedRule(body_options), regions);
  std::vector<std::string> warnings = run.input_warnings;
  warnings.insert(warnings.end(), run.motion.warnings.begin(), run.motion.warnings.end());
  warnings.insert(warnings.end(), regions.notes.begin(), regions.notes.end());
  if (json || options.report.file) {
    const optim::BodyRegionTrajectoryCheck empty;
    try {
      PrintAndReport(out, json,
                     report::BodyRegionTrajectoryJson(check ? *check : empty, iso,
                                                      BodyContactSceneOf(run.scene.scene, regions), head, criterion,
                                                      optim::JudgedRule(body_options).safety_factor, warnings),
                     context, options.report, run.scene.inputs, report::ReportKind::kTrajectory, [&] {
                       return chart::BodyRegionTrajectoryCharts(check ? *check : empty, iso, body_options.rule.safety_factor);
                     });
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (!json) {
    fmt::print(out, "Robot      {}\n", run.robot_line);
    fmt::print(out, "Trajectory {}: {} samples\n", *options.file, run.motion.samples.size());
    fmt::print(out, "Contact    {} contact; bare robot's contact area {}\n", ToString(regions.contact),
               regions.contact_area_m2 > 0.0 ? FormatQuantity(regions.contact_area_m2, QuantityKind::kArea) : "not given");
    fmt::print(out, "Limits     {}\n", LimitTableText(regions));
    fmt::print(out, "Criterion  {}\n", criterion);
    if (check) {
      fmt::print(out, "Verdict    {}\n", check->message);
      report::PrintBodyRegionSamples(out, *check, iso);
      fmt::print(out, "\nScope\n");
      for (const materials::BodyLimits& limits : iso) fmt::print(out, "  {}\n", limits.Describe());
    }
    if (head) {
      fmt::print(out, "{}Head ({}): {}\n", check ? "" : "\n", HeadCriteriaName(), head->message);
    }
    for (const std::string& w : warnings) fmt::print(out, "Warning: {}\n", w);
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace

std::optional<std::string> RobotTrajectoryOptions::FirstCheckFlag() const {
  if (scene.scene_file) return "--scene";
  for (const SceneField& field : SceneFields()) {
    if (scene.scene_values.count(field.dotted_name()) != 0) return std::string(field.flag);
  }
  if (scene.choices.thresholds) return "--thresholds";
  if (scene.choices.head_area) return "--head-area";
  if (scene.choices.covering_law) return "--covering-law";
  if (scene.material) return "--material";
  if (scene.catalog.given()) return scene.catalog.files.empty() ? "--no-builtin" : "--catalog";
  if (scene.laceration_limit) return "--laceration-limit";
  if (scene.contusion_limit) return "--contusion-limit";
  if (scene.body.any()) return "--body-region";
  if (scene.safety_factor) return "--safety-factor";
  if (allow_full_compression) return "--allow-full-compression";
  if (csv_file) return "--csv";
  if (report.file) return "--report";
  if (plot_file) return "--plot";
  return std::nullopt;
}

void AddRobotTrajectoryOptions(CLI::App& sub, RobotTrajectoryOptions& options) {
  sub.add_option("--trajectory", options.file,
                 "check a joint trajectory (CSV: an optional header, then time [s], the n joint positions, the n "
                 "joint velocities per line) against the covering below")
      ->type_name("FILE.csv")
      ->group("Trajectory check");
  AddSceneOptions(sub, options.scene);
  AddBodyRegionOptions(sub, options.scene.body);
  // Each sample brings the robot's mass and speed: refused with a message, hidden from --help.
  sub.get_option("--robot-mass")->group("");
  sub.get_option("--speed")->group("");
  AddRuleOptions(sub, {.safety_factor = &options.scene.safety_factor,
                       .allow_full_compression = &options.allow_full_compression,
                       .keep_travel = &options.scene.keep_travel});
  AddOutputFileOption(sub, "--csv", options.csv_file, "write the trajectory's samples as CSV ('-': to stdout instead of the table)", "FILE.csv|-");
  AddOutputFileOption(sub, "--plot", options.plot_file, "chart with gnuplot: speed and max safe speed over time, and the speed scaled by the safe "
                 "speed scale", "FILE.png|FILE.svg");
  AddReportOption(sub, options.report);
}

int RunRobotTrajectory(const RobotModelOptions& model, const RobotTrajectoryOptions& options, bool json,
                       const std::optional<RunContext>& context, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "robot");
  TrajectoryRun run;
  try {
    run = Resolve(model, options, json);
  } catch (const std::invalid_argument& e) {  // InputError and the library's own checks
    return errors.BadInput(e.what());
  }
  if (options.scene.body.any()) {  // ISO/TS 15066 body regions
    return RunWithBodyRegions(options.scene.body, errors, [&](const BodyRegionPlan& regions) {
      return RunBodyRegionTrajectory(run, options, regions, json, context, out, err);
    });
  }
  const optim::TrajectoryCheck& check = run.check;
  // A failed evaluation leaves the trajectory without a verdict: no table, file or chart.
  if (check.status == optim::TrajectoryCheckStatus::kEvaluationFailed) return errors.Failed(check.message);
  try {
    if ((options.plot_file || options.report.file) && !FindOnPath("gnuplot")) return errors.Failed(kGnuplotMissing);
    if (options.csv_file && *options.csv_file != "-") WriteFileAtomically(*options.csv_file, CsvText(check));
    if (options.plot_file) {
      RunGnuplot(*options.plot_file,
                 chart::TrajectoryChart({check, run.scene.scene, run.limit, *options.file, run.tip_link}));
    }
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }

  if (json || options.report.file) {
    try {
      PrintAndReport(out, json,
                     report::TrajectoryCheckJson(check, run.motion, run.scene.scene,
                                                 run.scene.covering_material
                                                     ? std::optional<std::string>(run.scene.covering_material->name)
                                                     : std::nullopt,
                                                 run.limit, run.input_warnings),
                     context, options.report, run.scene.inputs, report::ReportKind::kTrajectory, [&] {
                       return std::vector{chart::TrajectoryChart({check, run.scene.scene, run.limit, *options.file, run.tip_link})};
                     });
    } catch (const OutputError& e) {
      return errors.Failed(e);
    }
  }
  if (!json && options.csv_file && *options.csv_file == "-") {
    out << CsvText(check);
  } else if (!json) {
    const Scene& scene = run.scene.scene;
    const std::array<std::string_view, 2> omitted{"robot.mass", "robot.speed"};
    const auto& samples = run.motion.samples;
    fmt::print(out, "Robot      {}\n", run.robot_line);
    const auto fastest = std::max_element(samples.begin(), samples.end(), [](const auto& a, const auto& b) {
      return a.speed_m_per_s < b.speed_m_per_s;
    });
    fmt::print(out, "Trajectory {}: {} samples, t = {:g} .. {:g} s, peak contact speed {:.4g} m/s at t = {:.4g} s\n",
               *options.file, samples.size(), samples.front().time_s, samples.back().time_s,
               fastest->speed_m_per_s, fastest->time_s);
    fmt::print(out, "Scene      {}\n", SceneHeadline(scene, omitted));
    if (run.scene.covering_material && scene.covering.thickness_m > 0.0) {
      fmt::print(out, "Material   {}\n", run.scene.covering_material->name);
    }
    PrintLimitsAndCriterion(out, run.limit, run.scene);
    fmt::print(out, "Verdict    {}\n{}", check.message,
               report::SummaryText(optim::SummarizeTrajectory(check, scene, body_text::MaterialName(run.scene).value_or("")), 11));
    report::PrintWorstSample(out, check);
    fmt::print(out, "\n");
    report::PrintTrajectorySamples(out, check);
    PrintHeadScope(out, run.limit, run.scene);
    std::vector<std::string> warnings = run.input_warnings;
    warnings.insert(warnings.end(), run.motion.warnings.begin(), run.motion.warnings.end());
    warnings.insert(warnings.end(), check.warnings.begin(), check.warnings.end());
    if (warnings.empty()) fmt::print(out, "\nWarnings: none\n");
    for (const std::string& w : warnings) fmt::print(out, "Warning: {}\n", w);
    if (options.csv_file || options.plot_file) {
      fmt::print(out, "Wrote      {}{}{}\n", options.csv_file.value_or(""),
                 options.csv_file && options.plot_file ? ", " : "", options.plot_file.value_or(""));
    }
  }
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace covopt::cli
