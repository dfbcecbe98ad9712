#include "sweep.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <thread>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <fmt/compile.h>
#include <fmt/format.h>
#include <fmt/ostream.h>
#include <fmt/ranges.h>

#include "covopt/report/csv.hpp"
#include "errors.hpp"
#include "sweep_axis_option.hpp"
#include "catalog_options.hpp"
#include "output.hpp"
#include "covopt/chart/sweep_charts.hpp"
#include "plot.hpp"
#include "progress.hpp"
#include "rule_options.hpp"
#include "covopt/report/sweep_csv.hpp"
#include "quantity.hpp"
#include "output_options.hpp"

namespace covopt::cli {
namespace {

using chart::ChartPoint;
using chart::ChartPointOf;
using chart::Display;
using report::FindResultColumn;
using chart::PlotInput;
using report::ResultColumn;
using report::SweepCsvWriter;
using chart::SweepFamiliesScript;
using chart::SweepMapScript;
using report::SweepResultColumns;

constexpr int kMaxThreads = 4096;

constexpr std::string_view kFooter = R"(An axis is NAME=LO..HI[:lin|:log][:N] (N values, default 50, linear unless
:log) or NAME=V1,V2,... (the values as listed; a mass may be 'fixed', the
robot radius 'flat'); a list may mix ranges and values, e.g.
robot-radius=2mm..500mm:log:10,flat (charts draw the values sorted). NAME is
a scene flag without its dashes: robot-mass, speed, robot-radius,
robot-modulus, robot-poisson, covering-modulus, covering-poisson,
covering-thickness, head-mass, head-radius, scalp-modulus, scalp-poisson,
scalp-thickness, skull-modulus, skull-poisson (or its scene-file name, e.g.
robot.speed). Values take units as the scene flags do; a bare number is SI,
so write 0..50mm or 1mm..50mm, not 1..50mm.

Every point is solved on the exact path (as 'covopt simulate'), on all cores;
a point whose scene has no energy integral (a braking robot, a neck) on the
time path (ARKODE ERK 5(4), rtol 1e-8), as 'simulate' chooses.
A point whose scene is outside the model's input range is 'invalid' in the CSV,
with the library's message; the others carry the numeric keys of 'simulate
--json'. Without --csv, stdout gets a summary; '--csv -' prints the CSV instead.

Exit codes: 0 done (also with invalid points); 1 an output could not be written
(e.g. gnuplot missing); 2 bad input.)";

/// "0.1 MPa .. 1 GPa, 200 values, log", "3 values: 1 kg, 5 kg, fixed" or, for a mixed
/// list, "11 values: 2 mm .. 500 mm (10, log), flat".
std::string DescribeAxis(const SweepAxisArgument& axis) {
  const auto& v = axis.values;
  const auto& parts = axis.parts;
  if (parts.size() == 1 && parts.front().range) {
    return fmt::format("{} .. {}, {} values{}", Display(axis, v.front()), Display(axis, v.back()),
                       v.size(), parts.front().log ? ", log" : "");
  }
  std::vector<std::string> shown;
  for (std::size_t i = 0; i < parts.size() && i < 6; ++i) {
    const SweepAxisPart& part = parts[i];
    shown.push_back(part.range ? fmt::format("{} .. {} ({}{})", Display(axis, part.low),
                                             Display(axis, part.high), part.count,
                                             part.log ? ", log" : "")
                               : Display(axis, part.low));
  }
  if (parts.size() > 6) shown.push_back("...");
  return fmt::format("{} value{}: {}", v.size(), v.size() == 1 ? "" : "s",
                     fmt::join(shown, ", "));
}

std::string PointName(const SweepAxisArgument& x, const SweepAxisArgument* y, std::size_t index) {
  const std::size_t ny = y ? y->values.size() : 1;
  std::string name = fmt::format("{} {}", x.name, Display(x, x.values[index / ny]));
  if (y) name += fmt::format(", {} {}", y->name, Display(*y, y->values[index % ny]));
  return name;
}

}  // namespace

covopt::SweepSpec MakeSweepSpec(const SweepAxisArgument& x, const SweepAxisArgument* y,
                                const SimulationPlan& plan) {
  covopt::SweepSpec spec;
  spec.scene = plan.scene;
  spec.x = {x.name, x.values};
  if (y) spec.y = covopt::SweepAxis{y->name, y->values};
  spec.limits = plan.limits;
  spec.safety_factor = plan.safety_factor;
  return spec;
}

std::size_t SweepBlockRows(std::size_t points, unsigned threads) {
  const std::size_t per_block = points / (8 * std::max(1u, threads)) + 1;
  return std::clamp<std::size_t>(per_block, 16, 1024);
}

void SetupSweep(CLI::App* sub, SweepCommandOptions& options) {
  sub->footer(std::string(kFooter));
  sub->add_option("--x", options.x, "first swept quantity, e.g. covering-modulus=0.1MPa..1GPa:log:200")
      ->type_name("NAME=SPEC")
      ->required()
      ->group("Sweep");
  sub->add_option("--y", options.y, "second swept quantity, e.g. covering-thickness=0..50mm:200")
      ->type_name("NAME=SPEC")
      ->group("Sweep");
  sub->add_option("--threads", options.threads,
                  "worker threads (default: all cores); results do not depend on it")
      ->type_name("N")
      ->group("Sweep");

  AddSceneOptions(*sub, options.scene);
  AddBodyRegionOptions(*sub, options.scene.body);
  AddRuleOptions(*sub, {.keep_travel = &options.scene.keep_travel});

  AddOutputFileOption(*sub, "--csv", options.csv_file, "write one row per point (SI units); '-' prints it on stdout instead of the "
                  "summary", "FILE.csv|-");
  AddOutputFileOption(*sub, "--plot", options.plot_file, "chart with gnuplot: worst-ratio map with both limit contours and the "
                  "full-compression boundary, or line families when an axis has at most 8 "
                  "values", "FILE.png|FILE.svg");
  sub->add_option("--plot-quantity", options.plot_quantity,
                  "what the chart shows instead of the injury ratios: a CSV result column, "
                  "e.g. max_compressive_stress_Pa, peak_force_N, contact_duration_s")
      ->type_name("COLUMN")
      ->group("Output");
  sub->add_flag("--no-progress", options.no_progress,
                "no progress bar (it is shown only on a terminal, for long sweeps)")
      ->group("Output");
}

/// What RunSweep reads from its options before any computation.
struct SweepRun {
  SweepAxisArgument x;
  std::optional<SweepAxisArgument> y;
  SimulationPlan plan;
  std::optional<PlotFormat> plot_format;
  unsigned threads = 0;  ///< 0 = all cores
  const ResultColumn* quantity = nullptr;
  const SweepAxisArgument* y_axis() const { return y ? &*y : nullptr; }
};

/// The axes, the scene and the outputs of a sweep, checked.
/// @throws InputError naming the flag, the value and what is allowed.
SweepRun ResolveSweep(const SweepCommandOptions& options) {
  SweepRun run;
  run.x = ParseSweepAxis(options.x, "--x");
  if (options.y) {
    run.y = ParseSweepAxis(*options.y, "--y");
    if (run.y->field == run.x.field) {
      throw InputError(fmt::format("--y: {} is already swept by --x (got '{}')", run.y->name,
                                   *options.y));
    }
  }
  CheckGridSize(run.x, run.y_axis());
  for (const SweepAxisArgument* axis : {static_cast<const SweepAxisArgument*>(&run.x), run.y_axis()}) {
    if (axis == nullptr) continue;
    const std::string key = axis->field->dotted_name();
    const auto typed = options.scene.scene_values.find(key);
    if (typed != options.scene.scene_values.end()) {
      throw InputError(fmt::format("--{} '{}' sets {}, which {} sweeps; give it one way",
                                   axis->field->name, typed->second, key,
                                   axis == &run.x ? "--x" : "--y"));
    }
    if (options.scene.material &&
        (key == "covering.modulus" || key == "covering.poisson")) {
      throw InputError(fmt::format("--material '{}' sets {}, which {} sweeps; give it one way",
                                   *options.scene.material, key, axis == &run.x ? "--x" : "--y"));
    }
  }
  run.plan = ResolveSimulation(options.scene);
  // A swept field is given (by its axis): e.g. the covering is not the assumed default.
  for (const SweepAxisArgument* axis : {static_cast<const SweepAxisArgument*>(&run.x), run.y_axis()}) {
    if (axis != nullptr) run.plan.sources[axis->field->dotted_name()] = axis == &run.x ? "--x" : "--y";
  }
  if (options.threads) {
    if (*options.threads < 0 || *options.threads > kMaxThreads) {  // 0 = all cores, as elsewhere
      throw InputError(
          fmt::format("--threads must be in 0..{}, 0 = all cores (got {})", kMaxThreads, *options.threads));
    }
    run.threads = static_cast<unsigned>(*options.threads);
  }
  if (options.csv_file && options.csv_file->empty()) throw InputError("--csv: empty file name");
  if (options.scene.keep_travel) {
    throw InputError("--keep-travel applies with --body-region: the head's sweep reports the covering's travel in its "
                     "own columns (fully compressed, admissible); drop it");
  }
  if (options.plot_quantity) {
    run.quantity = FindResultColumn(*options.plot_quantity);
    if (run.quantity == nullptr) {
      throw InputError(fmt::format("--plot-quantity: no result column '{}'; the columns are {}",
                                   *options.plot_quantity,
                                   fmt::join(SweepResultColumns(), ", ")));
    }
    if (!options.plot_file) throw InputError("--plot-quantity applies only with --plot FILE");
  }
  if (options.plot_file) {
    run.plot_format = PlotFormatFor(*options.plot_file);
    if (!run.plot_format) {
      throw InputError(fmt::format(
          "--plot: cannot tell the format of '{}'; name the file *.png or *.svg",
          *options.plot_file));
    }
  }
  return run;
}

/// The summary of a finished sweep, counted by the library on the stream.
void PrintSweepSummary(std::ostream& out, const SweepRun& run, const covopt::SweepResult& result,
                       const std::string& scene_line, const std::vector<std::string>& written) {
  const SweepAxisArgument& x = run.x;
  const SweepAxisArgument* y_axis = run.y_axis();
  const std::optional<SweepAxisArgument>& y = run.y;
  const SimulationPlan& plan = run.plan;
  const std::size_t valid = result.valid;
  const auto percent = [&](std::size_t n) {
    return valid == 0 ? 0.0 : 100.0 * static_cast<double>(n) / static_cast<double>(valid);
  };
  fmt::print(out, "Sweep   {}: {}\n", x.name, DescribeAxis(x));
  if (y) fmt::print(out, "        {}: {}\n", y->name, DescribeAxis(*y));
  fmt::print(out, "Scene   {}\n", scene_line);
  fmt::print(out, "Points  {} in {:.3g} s on {} thread{}: {} valid, {} invalid{}\n",
             result.rows, result.wall_time_s, result.threads, result.threads == 1 ? "" : "s",
             valid, result.rows - valid,
             result.time_path_rows == 0
                 ? std::string()
                 : fmt::format("; {} on the time path (no energy integral)", result.time_path_rows));
  if (valid > 0) {
    // The library's counts (core::Sweep judges each row under the safety factor).
    fmt::print(out, "Safe    {} ({:.1f} %); laceration over its {}limit at {} ({:.1f} %), "
                    "contusion over its {}limit at {} ({:.1f} %)\n",
               result.safe, percent(result.safe), plan.safety_factor > 1.0 ? "derated " : "",
               result.laceration_unsafe, percent(result.laceration_unsafe),
               plan.safety_factor > 1.0 ? "derated " : "", result.contusion_unsafe,
               percent(result.contusion_unsafe));
    // The design criterion: safe, and a covering not fully compressed (a bare robot has
    // no covering to bottom out, so safe is enough for it).
    if (result.covered > 0) {
      fmt::print(out, "Full    covering fully compressed at {} of {} covered points ({:.1f} %); "
                      "safe and not fully compressed at {} ({:.1f} %)\n",
                 result.fully_compressed, result.covered,
                 100.0 * static_cast<double>(result.fully_compressed) /
                     static_cast<double>(result.covered),
                 result.admissible, percent(result.admissible));
    }
    for (const auto& [label, extreme] :
         {std::pair{"Least", *result.least}, std::pair{"Most", *result.most}}) {
      fmt::print(out, "{:<7} worst ratio {:.4g} at {} (laceration {:.4g}, contusion {:.4g})\n",
                 label, extreme.worst_ratio, PointName(x, y_axis, extreme.index),
                 extreme.laceration_ratio, extreme.contusion_ratio);
    }
  }
  if (result.first_invalid) {
    const std::size_t invalid = result.rows - valid;
    fmt::print(out, "Invalid {} point{} outside the model's input range, e.g. at {}: {}\n",
               invalid, invalid == 1 ? "" : "s", PointName(x, y_axis, *result.first_invalid),
               result.first_invalid_error);
  }
  if (result.first_warned) {
    fmt::print(out, "Warned  {} point{} with validity warnings, e.g. at {}: {}\n",
               result.warned, result.warned == 1 ? "" : "s",
               PointName(x, y_axis, *result.first_warned), result.first_warning.message);
  }
  for (const std::string& warning : InputWarnings(plan)) {
    fmt::print(out, "Note    {}\n", warning);
  }
  if (!written.empty()) fmt::print(out, "Wrote   {}\n", fmt::join(written, ", "));
}

namespace {

/// The scene without the swept quantities, for the summary and the chart titles.
std::string SweptSceneLine(const SweepRun& run) {
  std::vector<std::string_view> swept_fields;
  std::vector<std::string> swept_names{run.x.field->dotted_name()};
  if (run.y) swept_names.push_back(run.y->field->dotted_name());
  for (const std::string& name : swept_names) swept_fields.push_back(name);
  std::string scene_line = SceneHeadline(run.plan.scene, swept_fields);
  if (const auto details = SceneDetailsBeyondHeadline(run.plan.scene, swept_fields); !details.empty()) {
    scene_line += fmt::format("; {}", fmt::join(details, ", "));
  }
  return scene_line;
}

/// Where the CSV streams: a file by the one file writer (output.hpp), or stdout ("--csv -").
struct SweepCsvOutput {
  std::optional<OutputFile> file;
  std::optional<SweepCsvWriter> writer;
};

/// Opens the CSV before the sweep (an unwritable file costs no computation). @throws OutputError.
void OpenSweepCsv(SweepCsvOutput& csv, const SweepCommandOptions& options, const SweepRun& run, std::ostream& out) {
  if (!options.csv_file) return;
  if (*options.csv_file != "-") {
    csv.file.emplace(*options.csv_file);
    csv.writer.emplace(run.x, run.y_axis(), [&file = csv.file](std::string_view text) { file->Write(text); });
  } else {
    csv.writer.emplace(run.x, run.y_axis(), [&out](std::string_view text) {
      out.write(text.data(), static_cast<std::streamsize>(text.size()));
      if (!out) throw OutputError("cannot write the results to standard output");
    });
  }
}

/// The map (two axes of more than kMaxFamilies values) or the families of lines into `path`.
/// @throws OutputError.
void DrawSweepChart(const std::string& path, const SweepRun& run, std::span<const ChartPoint> chart,
                    const std::string& scene_line) {
  PlotInput input;
  input.quantity = run.quantity;
  input.x = &run.x;
  input.y = run.y_axis();
  input.points = chart;
  input.limits = run.plan.limits;
  input.scene_line = scene_line;
  input.safety_factor = run.plan.safety_factor;
  input.format = *run.plot_format;
  const bool map = run.y && run.x.values.size() > kMaxFamilies && run.y->values.size() > kMaxFamilies;
  RunGnuplot(path, [&](const std::string& output_path) {
    return map ? SweepMapScript(input, output_path) : SweepFamiliesScript(input, output_path);
  });
}

}  // namespace

int RunSweep(const SweepCommandOptions& options, std::ostream& out, std::ostream& err) {
  const CommandErrors errors(err, "sweep");
  if (options.scene.body.any()) {  // ISO/TS 15066 body regions (sweep_body_region.cpp)
    return RunWithBodyRegions(options.scene.body, errors, [&](const BodyRegionPlan& regions) {
      return RunBodyRegionSweep(options, regions, out, err);
    });
  }

  SweepRun run;
  try {
    run = ResolveSweep(options);
  } catch (const InputError& e) {
    return errors.BadInput(e.what());
  }
  const SweepAxisArgument& x = run.x;
  const std::optional<SweepAxisArgument>& y = run.y;
  const SimulationPlan& plan = run.plan;
  const std::optional<PlotFormat>& plot_format = run.plot_format;
  const unsigned threads = run.threads;
  const ResultColumn* quantity = run.quantity;
  const SweepAxisArgument* y_axis = run.y_axis();

  const std::string scene_line = SweptSceneLine(run);

  // Outputs that can fail are checked or opened before the sweep: a missing gnuplot or an
  // unwritable CSV file costs no computation and leaves no file.
  const bool csv_to_stdout = options.csv_file && *options.csv_file == "-";
  std::vector<std::string> written;
  if (plot_format && !FindOnPath("gnuplot")) return errors.Failed(kGnuplotMissing);
  SweepCsvOutput csv_output;
  std::optional<OutputFile>& csv_file = csv_output.file;
  std::optional<SweepCsvWriter>& csv = csv_output.writer;
  try {
    OpenSweepCsv(csv_output, options, run, out);
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }

  // The sweep: rows stream into the CSV and, for a chart, into the few numbers it draws.
  const covopt::SweepSpec spec = MakeSweepSpec(x, y_axis, plan);
  const std::size_t points = x.values.size() * (y ? y->values.size() : 1);
  const unsigned wanted_threads =
      threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
  covopt::SweepOptions sweep;
  sweep.threads = wanted_threads;
  sweep.block_rows = SweepBlockRows(points, wanted_threads);
  // On a terminal only, once the sweep has run for a while.
  ProgressBar bar(err, "sweep",
                  ProgressBarOptions{.enabled = !options.no_progress, .delay = std::chrono::milliseconds(300)});
  sweep.progress = [&bar](std::size_t done, std::size_t total) { bar.Update(done, total); };
  std::vector<ChartPoint> chart;
  if (plot_format) chart.reserve(points);
  covopt::SweepResult result;
  try {
    result = covopt::Sweep(spec, sweep, [&](std::span<const SweepRow> rows) {
      if (csv) csv->Write(rows);
      if (plot_format) {
        for (const SweepRow& row : rows) chart.push_back(ChartPointOf(row, quantity));
      }
    });
    if (csv) csv->Finish();
    if (csv_file) {
      csv_file->Commit();
      written.push_back(*options.csv_file);
    }
  } catch (const OutputError& e) {
    bar.Finish();
    return errors.Failed(e);
  } catch (const std::invalid_argument& e) {  // the library refused the spec
    bar.Finish();
    return errors.BadInput(e.what());
  }
  bar.Finish();

  try {
    if (plot_format) {
      DrawSweepChart(*options.plot_file, run, chart, scene_line);
      written.push_back(*options.plot_file);
    }
  } catch (const OutputError& e) {
    return errors.Failed(e);
  }

  if (!csv_to_stdout) PrintSweepSummary(out, run, result, scene_line, written);
  out.flush();
  if (!out) return errors.Failed("cannot write the results to standard output");
  return 0;
}

}  // namespace covopt::cli
